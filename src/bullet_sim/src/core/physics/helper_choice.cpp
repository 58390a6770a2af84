#include "physics/helper_choice.h"

namespace bullet_sim {
namespace {

/// Jobs in a window, and how often the way not chosen is tried again.
constexpr int kWindowJobs = 64;
constexpr int kProbeEvery = 16;

}  // namespace

void HelperChoice::record(std::chrono::steady_clock::duration took, size_t pieces) {
  took_ += took;
  pieces_ += pieces;
  if (++jobs_ < kWindowJobs) return;
  const double per_piece = std::chrono::duration<double>(took_).count() / pieces_;
  (helpers_now_ ? with_helpers_ : alone_) = per_piece;
  jobs_ = 0;
  pieces_ = 0;
  took_ = std::chrono::steady_clock::duration::zero();
  ++windows_;
  const bool better_with_helpers = alone_ < 0 || (with_helpers_ >= 0 && with_helpers_ < alone_);
  helpers_now_ = (windows_ % kProbeEvery == 1) ? !better_with_helpers : better_with_helpers;
}

}  // namespace bullet_sim
