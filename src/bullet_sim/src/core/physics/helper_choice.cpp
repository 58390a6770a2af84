#include "physics/helper_choice.h"

#include <algorithm>

namespace bullet_sim {
namespace {

/// Jobs in a window, and the windows from one try of the way not chosen to the next.
constexpr int kWindowJobs = 64;
constexpr int kFirstGap = 16;
constexpr int kLongestGap = 128;

}  // namespace

HelperChoice::HelperChoice() : gap_(kFirstGap) {}

void HelperChoice::record(std::chrono::steady_clock::duration took, size_t pieces) {
  took_ += took;
  pieces_ += pieces;
  if (++jobs_ < kWindowJobs) return;
  const double per_piece = std::chrono::duration<double>(took_).count() / pieces_;
  (helpers_now_ ? with_helpers_ : alone_) = per_piece;
  jobs_ = 0;
  pieces_ = 0;
  took_ = std::chrono::steady_clock::duration::zero();
  const bool better_with_helpers = alone_ < 0 || (with_helpers_ >= 0 && with_helpers_ < alone_);
  if (trying_) {  // the way tried won: tried again soon; it lost: later
    gap_ = helpers_now_ == better_with_helpers ? kFirstGap : std::min(2 * gap_, kLongestGap);
  }
  // The way never tried yet is tried at once.
  trying_ = alone_ < 0 || ++since_try_ >= gap_;
  if (trying_) since_try_ = 0;
  helpers_now_ = trying_ ? !better_with_helpers : better_with_helpers;
}

}  // namespace bullet_sim
