// The model text spawn_model sends: read, checked, rewritten.
#pragma once

#include <stdexcept>
#include <string>

namespace gazebo_ros_spawn {

/// A model that cannot be read or is not XML; the message names its source.
class ModelError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The text of the file at `path`. Throws ModelError "specified file PATH does not exist"
/// or "... is not a file".
std::string readModelFile(const std::string& path);

/// Throws ModelError "SOURCE is empty" or "SOURCE is not valid XML: REASON".
void checkXml(const std::string& text, const std::string& source);

/// package://PKG/... -> model://PKG/..., for models whose packages are on the model path.
std::string packageToModel(const std::string& text);

}  // namespace gazebo_ros_spawn
