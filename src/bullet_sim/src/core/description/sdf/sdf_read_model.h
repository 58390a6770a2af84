#ifndef BULLET_SIM_CORE_SDF_READ_MODEL_H
#define BULLET_SIM_CORE_SDF_READ_MODEL_H

#include <memory>
#include <optional>
#include <string>

#include <tinyxml2.h>

#include "description/sdf/sdf_dom.h"
#include "description/sdf/sdf_frames.h"
#include "description/sdf/sdf_read_context.h"

namespace bullet_sim {

/// What an <include> sets on the model it includes.
struct IncludeOverrides {
  std::optional<std::string> name;
  std::optional<RawPose> pose;
  std::optional<bool> is_static;
  std::vector<SdfPlugin> plugins;  ///< appended to the model's own
};

/// A <model> read, with its frames (for the scope that holds it) and its pose as written
/// (to be resolved in that scope).
struct ReadModel {
  SdfModel model;
  std::unique_ptr<FrameScope> frames;
  RawPose pose;
};

/// Reads <model> element `e` of the file of `values`. `file_top` says it is the file's
/// top model (a direct child of <world> or of <sdf>): SDF 1.4 puts the axes of only those
/// models' joints in the model frame (libsdformat's 1.4 to 1.5 conversion).
/// @throws LoadError naming the file, line and element.
ReadModel readSdfModel(const tinyxml2::XMLElement* e, const SdfValues& values, bool file_top,
                       const IncludeOverrides& overrides, SdfReadContext* context);

/// The overrides of an <include> element (<name>, <pose>, <static>, <plugin>s).
IncludeOverrides readIncludeOverrides(const tinyxml2::XMLElement* include,
                                      const SdfValues& values);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_READ_MODEL_H
