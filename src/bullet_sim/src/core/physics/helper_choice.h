#ifndef BULLET_SIM_CORE_HELPER_CHOICE_H
#define BULLET_SIM_CORE_HELPER_CHOICE_H

#include <chrono>
#include <cstddef>

namespace bullet_sim {

/// Whether a StepPool's jobs run on its helpers or on the caller alone, chosen window by
/// window (64 jobs): the way that took less wall time per piece when last tried; the other
/// is tried again every 16 windows, as the machine's other work comes and goes. On cores
/// busy with other work a helper put off its core holds up every job it has a piece of, and
/// the caller alone is then faster.
class HelperChoice {
 public:
  bool helpers() const { return helpers_now_; }
  /// A job of `pieces` took `took`, run the way helpers() said.
  void record(std::chrono::steady_clock::duration took, size_t pieces);

 private:
  bool helpers_now_ = true;
  double with_helpers_ = -1, alone_ = -1;  ///< seconds per piece when last tried; -1 never
  int jobs_ = 0, windows_ = 0;
  size_t pieces_ = 0;
  std::chrono::steady_clock::duration took_{};
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_HELPER_CHOICE_H
