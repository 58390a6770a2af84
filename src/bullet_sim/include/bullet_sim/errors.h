#ifndef BULLET_SIM_ERRORS_H
#define BULLET_SIM_ERRORS_H

#include <stdexcept>

namespace bullet_sim {

/// Thrown when a robot description or a world cannot be loaded. The message
/// names the source (file path or "robot_description"), the element and the
/// offending value, so that it can be shown to the user as it is.
class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_ERRORS_H
