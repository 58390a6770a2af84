#include "physics/step_pool.h"

#include <chrono>

namespace bullet_sim {
namespace {

/// How long a helper spins for the next job before it sleeps.
constexpr std::chrono::microseconds kSpin{200};
/// Every kWindowJobs jobs the caller compares how long it waited for the helpers with how
/// long it worked itself; when it waited more than half as long (helpers put off their cores
/// by the machine's other work, in the middle of a piece or of leaving a job), it runs the
/// next kAloneJobs jobs alone, then tries again.
constexpr int kWindowJobs = 64;
constexpr int kAloneJobs = 2000;

void pause() { __builtin_ia32_pause(); }

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

void StepPool::run(size_t n, const std::function<void(size_t)>& work) {
  if (helpers_.empty() || n < 2 || alone_ > 0) {
    if (n >= 2 && alone_ > 0) --alone_;
    for (size_t i = 0; i < n; ++i) work(i);
    return;
  }
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  // Helpers still leaving the last job read its pieces: wait for them before changing them.
  waitFor([this] { return active_.load() == 0; });
  if (taken_.size() < n) taken_ = std::vector<std::atomic<bool>>(n);
  for (size_t i = 0; i < n; ++i) taken_[i].store(false, std::memory_order_relaxed);
  work_ = &work;
  pieces_ = n;
  error_ = nullptr;
  finished_.store(0);
  open_.store(++jobs_);
  if (sleepers_.load() > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_all();
  }
  const Clock::time_point own_start = Clock::now();
  runShare(0);
  const Clock::time_point own_done = Clock::now();
  waitFor([this, n] { return finished_.load(std::memory_order_acquire) == n; });
  worked_ += own_done - own_start;
  waited_ += (Clock::now() - start) - (own_done - own_start);
  if (++window_jobs_ == kWindowJobs) {
    if (waited_ * 2 > worked_) alone_ = kAloneJobs;
    window_jobs_ = 0;
    worked_ = waited_ = Clock::duration::zero();
  }
  // No helper joins the job from here, and one still in it finds every piece taken (and
  // never calls `work`, which the caller may now destroy).
  open_.store(0);
  if (error_) std::rethrow_exception(error_);
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
      pause();
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
