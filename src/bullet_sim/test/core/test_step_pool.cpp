// StepPool: every piece of every job runs once, on any number of threads; HelperChoice.
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "physics/helper_choice.h"
#include "physics/step_pool.h"

using bullet_sim::StepPool;

TEST(StepPool, RunsEveryPieceOnceInEveryJob) {
  for (unsigned threads : {1u, 2u, 3u}) {
    StepPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (size_t n : {0u, 1u, 2u, 5u, 16u}) {
      for (int job = 0; job < 200; ++job) {
        std::vector<std::atomic<int>> runs(n);
        pool.run(n, [&runs](size_t i) { runs[i].fetch_add(1); });
        for (size_t i = 0; i < n; ++i) {
          ASSERT_EQ(runs[i].load(), 1) << threads << " threads, " << n << " pieces, piece " << i;
        }
      }
    }
  }
}

TEST(StepPool, RethrowsWhatAPieceThrewAfterTheOthersRan) {
  StepPool pool(2);
  std::vector<std::atomic<int>> runs(8);
  EXPECT_THROW(pool.run(8,
                        [&runs](size_t i) {
                          runs[i].fetch_add(1);
                          if (i == 5) throw std::runtime_error("piece 5");
                        }),
               std::runtime_error);
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "piece " << i;
  std::atomic<int> after{0};
  pool.run(4, [&after](size_t) { after.fetch_add(1); });
  EXPECT_EQ(after.load(), 4);
}

TEST(StepPool, HelpersAreNamedByTheirIndex) {
  StepPool pool(3);
  const pthread_t caller = pthread_self();
  std::vector<std::string> names(6);
  std::atomic<int> by_helpers{0};
  pool.run(names.size(), [&](size_t i) {
    if (pthread_equal(pthread_self(), caller)) {
      // The caller holds its first piece until a helper has run one (the helpers' own
      // pieces are 1, 2, 4, 5), so that a helper's name is seen.
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (by_helpers.load() == 0 && std::chrono::steady_clock::now() < deadline) {
      }
      names[i] = "caller";
      return;
    }
    char name[16] = {};
    pthread_getname_np(pthread_self(), name, sizeof(name));
    names[i] = name;
    by_helpers.fetch_add(1);
  });
  ASSERT_GT(by_helpers.load(), 0);
  for (const std::string& name : names) {
    EXPECT_TRUE(name == "caller" || name == "sim_step_1" || name == "sim_step_2") << name;
  }
}

namespace {

/// The windows (64 jobs each) that `choice` ran with helpers, of `windows` in which a job
/// of 10 pieces takes `helpers_us` on the helpers and `alone_us` on the caller alone.
std::vector<int> windowsWithHelpers(bullet_sim::HelperChoice* choice, int windows,
                                    int helpers_us, int alone_us, int first_window = 0) {
  std::vector<int> with;
  for (int window = first_window; window < first_window + windows; ++window) {
    const bool helpers = choice->helpers();
    if (helpers) with.push_back(window);
    for (int job = 0; job < 64; ++job) {
      EXPECT_EQ(choice->helpers(), helpers) << "a way is kept for a whole window";
      choice->record(std::chrono::microseconds(helpers ? helpers_us : alone_us), 10);
    }
  }
  return with;
}

}  // namespace

TEST(StepPool, HelperChoiceTakesTheFasterWayAndTriesTheOtherLessOftenWhileItLoses) {
  bullet_sim::HelperChoice choice;
  // Helpers first (window 0), then alone to compare (1), which is faster: alone from then
  // on, but for a window that tries the helpers again 16 windows after the last try, then
  // 32, 64, and at most 128 while they keep losing.
  EXPECT_EQ(windowsWithHelpers(&choice, 400, 300, 100),
            (std::vector<int>{0, 17, 49, 113, 241, 369}));
}

TEST(StepPool, HelperChoiceTurnsToTheWayThatWinsItsTryAndTriesTheOtherSoon) {
  bullet_sim::HelperChoice choice;
  windowsWithHelpers(&choice, 400, 300, 100);  // alone chosen, the next try at window 497
  // The helpers become the faster way: they win their next try and are kept; alone is
  // tried 16 windows later, loses, and is tried again 32 windows after that.
  std::vector<int> alone;
  const std::vector<int> with = windowsWithHelpers(&choice, 200, 50, 100, 400);
  for (int window = 400, k = 0; window < 600; ++window) {
    if (k < static_cast<int>(with.size()) && with[k] == window) {
      ++k;
    } else {
      alone.push_back(window);
    }
  }
  ASSERT_FALSE(alone.empty());
  EXPECT_EQ(alone.back(), 497 + 16 + 32);
  EXPECT_EQ(with.front(), 497);
  EXPECT_EQ(std::count(alone.begin(), alone.end(), 497 + 16), 1);
  EXPECT_EQ(static_cast<int>(alone.size()), 497 - 400 + 2);
}
