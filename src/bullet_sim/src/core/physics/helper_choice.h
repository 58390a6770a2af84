#ifndef BULLET_SIM_CORE_HELPER_CHOICE_H
#define BULLET_SIM_CORE_HELPER_CHOICE_H

#include <chrono>
#include <cstddef>

namespace bullet_sim {

/// Whether a StepPool's jobs run on its helpers or on the caller alone, chosen window by
/// window (64 jobs): the way that took less wall time per piece when last tried; the other
/// is tried again for a window now and then, as the machine's other work comes and goes. On
/// cores busy with other work a helper put off its core holds up every job it has a piece
/// of, and the caller alone is then faster. A try costs what the slower way loses, so the
/// windows between tries double, from 16 up to 128, while the way tried keeps losing, and
/// are 16 again once it wins.
class HelperChoice {
 public:
  HelperChoice();
  bool helpers() const { return helpers_now_; }
  /// A job of `pieces` took `took`, run the way helpers() said.
  void record(std::chrono::steady_clock::duration took, size_t pieces);

 private:
  bool helpers_now_ = true;
  bool trying_ = false;  ///< this window tries the way that was slower
  double with_helpers_ = -1, alone_ = -1;  ///< seconds per piece when last tried; -1 never
  int jobs_ = 0;
  int gap_;              ///< windows from one try to the next
  int since_try_ = 0;    ///< windows since the last try
  size_t pieces_ = 0;
  std::chrono::steady_clock::duration took_{};
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_HELPER_CHOICE_H
