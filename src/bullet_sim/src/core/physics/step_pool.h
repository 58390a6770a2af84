#ifndef BULLET_SIM_CORE_STEP_POOL_H
#define BULLET_SIM_CORE_STEP_POOL_H

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "physics/helper_choice.h"

namespace bullet_sim {

/// Threads that share out independent pieces of work, such as the steps of worlds that
/// touch nothing of each other. Thread t (the caller is thread 0) first takes pieces t,
/// t + threads, ..., so that a world keeps to one core's cache from step to step, then any
/// piece not taken yet: a helper that the machine's other work keeps off its core delays
/// nothing but the piece it holds. Whether helpers are used at all is a HelperChoice.
/// Between jobs the helper threads look for the next one for a short while (a step's work
/// comes every few tens of microseconds when the simulation runs fast), yielding their core
/// to any other thread that wants it between looks, then sleep.
class StepPool {
 public:
  /// `threads` >= 1 counts the caller: threads - 1 helper threads are started.
  explicit StepPool(unsigned threads);
  ~StepPool();
  StepPool(const StepPool&) = delete;
  StepPool& operator=(const StepPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(helpers_.size()) + 1; }
  /// Calls work(i) once for each i in [0, n) and returns when all have returned; then
  /// rethrows the first exception a piece threw (the other pieces run all the same).
  /// `units` is the work in each piece (a world's steps, say), for the HelperChoice to
  /// compare jobs of different sizes. Jobs of another kind (scans, whose pieces cost
  /// otherwise) keep a `choice` of their own; null: the pool's.
  void run(size_t n, const std::function<void(size_t)>& work, size_t units = 1,
           HelperChoice* choice = nullptr);

 private:
  void helperLoop(unsigned thread);
  /// Waits until a job other than `seen` is open; false when the pool stops.
  bool waitForJob(uint64_t seen, uint64_t* job);
  void runWithHelpers(size_t n, const std::function<void(size_t)>& work);
  void runAlone(size_t n, const std::function<void(size_t)>& work);
  void runShare(unsigned thread);
  void runPiece(size_t i);

  std::vector<std::thread> helpers_;
  // The current job, written by the caller only while no helper is in it.
  const std::function<void(size_t)>* work_ = nullptr;
  size_t pieces_ = 0;
  std::vector<std::atomic<bool>> taken_;  ///< per piece: a thread has taken it
  std::exception_ptr error_;
  std::mutex error_mutex_;
  uint64_t jobs_ = 0;                     ///< jobs handed out so far
  HelperChoice choice_;
  std::atomic<uint64_t> open_{0};         ///< the job helpers may join; 0 = none
  std::atomic<size_t> finished_{0};       ///< pieces of the open job done
  std::atomic<unsigned> active_{0};       ///< helpers inside a job
  std::atomic<unsigned> sleepers_{0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_STEP_POOL_H
