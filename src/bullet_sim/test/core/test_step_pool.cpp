// StepPool: every piece of every job runs once, on any number of threads; HelperChoice.
#include <pthread.h>

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

TEST(StepPool, HelperChoiceTakesTheFasterWayAndTriesTheOtherAgain) {
  using std::chrono::microseconds;
  bullet_sim::HelperChoice choice;
  std::vector<bool> ways;
  // Helpers take 300 us a job of 10 pieces, the caller alone 100 us: 64 jobs a window.
  for (int job = 0; job < 64 * 40; ++job) {
    const bool helpers = choice.helpers();
    if (job % 64 == 0) ways.push_back(helpers);
    choice.record(microseconds(helpers ? 300 : 100), 10);
  }
  EXPECT_TRUE(ways[0]);   // helpers first
  EXPECT_FALSE(ways[1]);  // then alone, to compare
  int with_helpers = 0;
  for (size_t w = 2; w < ways.size(); ++w) with_helpers += ways[w];
  // Alone from then on, but for one window in 16 that tries the helpers again.
  EXPECT_EQ(with_helpers, 2);
}
