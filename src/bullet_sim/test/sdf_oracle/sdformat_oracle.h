#ifndef BULLET_SIM_TEST_SDFORMAT_ORACLE_H
#define BULLET_SIM_TEST_SDFORMAT_ORACLE_H

#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bullet_sim/description/resource_paths.h"
#include "description/sdf/sdf_dom.h"
#include "field_paths.h"

namespace bullet_sim_test {

/// The canonical link libsdformat picks for a model: its name relative to the model
/// ("link" or "nested::link") and its pose in the model's frame.
struct OracleCanonicalLink {
  std::string scoped_name;
  Eigen::Isometry3d T_model_link = Eigen::Isometry3d::Identity();
};

/// What libsdformat 12 makes of an SDF file, in the simulator's own structs.
struct OracleResult {
  bullet_sim::SdfDocument document;
  /// libsdformat's errors, each "FILE:LINE: message" (empty: the file is valid to it).
  std::vector<std::string> errors;
  /// Its errors that Gazebo classic does not have, each "why: error": checks of its DOM
  /// classes, which Gazebo classic never builds (it reads the element tree): a link's
  /// inertia, a <script> without <uri> or <name> (the tree has "__default__" for them, as
  /// in sdformat 9), a camera pixel format sdf::Camera does not list. Root::Load fills the
  /// DOM all the same, so the file is compared.
  std::vector<std::string> set_aside;
  /// Per model, keyed by its field path (modelFieldPath: "world.models[a]", "model"), the
  /// canonical link libsdformat picks; models without any link have no entry.
  std::map<std::string, OracleCanonicalLink> canonical_links;
};

/// Reads `path` with libsdformat 12 (sdf::Root::Load). <include> URIs are found through
/// `resolver`: model://NAME in its model folders, else the built-in sun and ground_plane
/// of `builtin_models_dir`; relative and file:// URIs against the folder of `path`.
/// libsdformat itself picks a model folder's SDF file from its model.config. Every field
/// comes from libsdformat's DOM (poses through SemanticPose::Resolve, axes through
/// JointAxis::ResolveXyz) or, where the DOM has no accessor, its element tree.
OracleResult readWithLibsdformat(const std::string& path, const bullet_sim::UriResolver& resolver,
                                 const std::string& builtin_models_dir);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_SDFORMAT_ORACLE_H
