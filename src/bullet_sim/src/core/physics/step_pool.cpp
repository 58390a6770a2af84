#include "physics/step_pool.h"

#include <pthread.h>

#include <chrono>
#include <string>
#include <utility>

namespace bullet_sim {
namespace {

/// How long a helper looks for the next job before it sleeps.
constexpr std::chrono::microseconds kSpin{200};

/// A spin-wait hint to the processor (x86's PAUSE, ARM's YIELD; nothing elsewhere).
void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__) || defined(__arm__)
  __asm__ __volatile__("yield");
#endif
}

/// Waits for `done()`, spinning first, then giving the core away between looks: a thread
/// it waits for may have been put off the core by the machine's other work.
template <class Done>
void waitFor(Done&& done) {
  for (int spins = 0; !done(); ++spins) {
    if (spins < 4096) {
      pause();
    } else {
      std::this_thread::yield();
    }
  }
}

}  // namespace

StepPool::StepPool(unsigned threads) {
  for (unsigned t = 1; t < threads; ++t) helpers_.emplace_back([this, t] { helperLoop(t); });
}

StepPool::~StepPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

void StepPool::run(size_t n, const std::function<void(size_t)>& work, size_t units,
                   HelperChoice* choice) {
  error_ = nullptr;
  if (!choice) choice = &choice_;
  if (helpers_.empty() || n < 2) {
    runAlone(n, work);
  } else {
    const auto start = std::chrono::steady_clock::now();
    if (choice->helpers()) {
      runWithHelpers(n, work);
    } else {
      runAlone(n, work);
    }
    choice->record(std::chrono::steady_clock::now() - start, n * units);
  }
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void StepPool::runAlone(size_t n, const std::function<void(size_t)>& work) {
  for (size_t i = 0; i < n; ++i) {
    try {
      work(i);
    } catch (...) {
      if (!error_) error_ = std::current_exception();
    }
  }
}

void StepPool::runWithHelpers(size_t n, const std::function<void(size_t)>& work) {
  // Helpers still leaving the last job read its pieces: wait for them before changing them.
  waitFor([this] { return active_.load() == 0; });
  if (taken_.size() < n) taken_ = std::vector<std::atomic<bool>>(n);
  for (size_t i = 0; i < n; ++i) taken_[i].store(false, std::memory_order_relaxed);
  work_ = &work;
  pieces_ = n;
  finished_.store(0);
  open_.store(++jobs_);
  if (sleepers_.load() > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_all();
  }
  runShare(0);
  waitFor([this, n] { return finished_.load(std::memory_order_acquire) == n; });
  // No helper joins the job from here, and one still in it finds every piece taken (and
  // never calls `work`, which the caller may now destroy).
  open_.store(0);
}

void StepPool::runPiece(size_t i) {
  if (taken_[i].exchange(true, std::memory_order_acq_rel)) return;
  try {
    (*work_)(i);
  } catch (...) {
    std::lock_guard<std::mutex> lock(error_mutex_);
    if (!error_) error_ = std::current_exception();
  }
  finished_.fetch_add(1, std::memory_order_release);
}

void StepPool::runShare(unsigned thread) {
  for (size_t i = thread; i < pieces_; i += threads()) runPiece(i);
  for (size_t i = 0; i < pieces_; ++i) runPiece(i);
}

bool StepPool::waitForJob(uint64_t seen, uint64_t* job) {
  const auto fresh = [&] {
    *job = open_.load();
    return *job != 0 && *job != seen;
  };
  const auto spin_until = std::chrono::steady_clock::now() + kSpin;
  while (!stop_.load()) {
    if (fresh()) return true;
    if (std::chrono::steady_clock::now() < spin_until) {
      // Other threads that want the core get it meanwhile (the node's publishing and
      // network threads, a subscriber on the same machine); with none, this returns at once.
      std::this_thread::yield();
      continue;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    sleepers_.fetch_add(1);
    wake_.wait(lock, [&] { return stop_.load() || fresh(); });
    sleepers_.fetch_sub(1);
  }
  return false;
}

void StepPool::helperLoop(unsigned thread) {
  // Named so that top -H, perf and /proc tell the helpers from the node's other threads.
  pthread_setname_np(pthread_self(), ("sim_step_" + std::to_string(thread)).c_str());
  uint64_t seen = 0, job = 0;
  while (waitForJob(seen, &job)) {
    seen = job;
    active_.fetch_add(1);
    // The caller closes a job before it waits for the helpers in it: one that comes later
    // stays out.
    if (open_.load() == job) runShare(thread);
    active_.fetch_sub(1);
  }
}

}  // namespace bullet_sim
