#ifndef BULLET_SIM_TEST_ORACLE_PARTS_H
#define BULLET_SIM_TEST_ORACLE_PARTS_H

// The oracle's converters, one per kind of libsdformat object, each filling the simulator's
// struct of that kind from libsdformat's DOM alone.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <ignition/math/Color.hh>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>
#include <sdf/sdf.hh>

#include "description/sdf/sdf_dom.h"
#include "sdformat_oracle.h"

namespace bullet_sim_test {
namespace oracle {

/// What went wrong while converting, worded as "FILE:LINE: message".
using Problems = std::vector<std::string>;

Eigen::Isometry3d toIsometry(const ignition::math::Pose3d& pose);
Eigen::Vector3d toVector(const ignition::math::Vector3d& v);
Eigen::Vector4f toColour(const ignition::math::Color& c);

/// The file and line libsdformat recorded for `element` (line 0 when it has none, as for
/// elements a version conversion added).
bullet_sim::SdfOrigin originOf(const sdf::ElementPtr& element);

/// "FILE:LINE: message" of one libsdformat error; `what` is put before the message when
/// the error names no file.
std::string formatError(const sdf::Error& error, const std::string& what = "");
void appendErrors(const sdf::Errors& errors, const std::string& what, Problems* problems);

/// `pose` resolved by libsdformat relative to `resolve_to` ("" = its default frame); a
/// resolution error is appended to `problems` naming `what`, and identity returned.
Eigen::Isometry3d resolvedPose(const sdf::SemanticPose& pose, const std::string& resolve_to,
                               const std::string& what, Problems* problems);

/// The <plugin> children of `parent` as libsdformat's element tree holds them.
std::vector<bullet_sim::SdfPlugin> pluginsOf(const sdf::ElementPtr& parent);

/// True when `parent` has a child element `name` in libsdformat's tree (written in the
/// file, or added by a version conversion or as a required element).
bool hasChild(const sdf::ElementPtr& parent, const std::string& name);

bullet_sim::SdfGeometry geometryOf(const sdf::Geometry* geometry);
bullet_sim::SdfMaterial materialOf(const sdf::Material& material);
bullet_sim::SdfVisual visualOf(const sdf::Visual& visual, Problems* problems);
bullet_sim::SdfCollision collisionOf(const sdf::Collision& collision, Problems* problems);
bullet_sim::SdfSensor sensorOf(const sdf::Sensor& sensor, Problems* problems);
bullet_sim::SdfLink linkOf(const sdf::Link& link, Problems* problems);
bullet_sim::SdfJoint jointOf(const sdf::Joint& joint, Problems* problems);
/// `in_world`: posed in a world's frame graph; else a document of its own.
bullet_sim::SdfLight lightOf(const sdf::Light& light, bool in_world, Problems* problems);

/// A model and everything in it; its canonical link (and its nested models') goes into
/// result->canonical_links under `field_path`, resolution errors into result->errors.
bullet_sim::SdfModel modelOf(const sdf::Model& model, const std::string& field_path,
                             OracleResult* result);
bullet_sim::SdfWorld worldOf(const sdf::World& world, OracleResult* result);

/// True for the versions whose "::" names libsdformat 12 turns into nested models (those
/// before 1.8, which it converts up).
bool unflattensNames(const std::string& version);
/// The nested models that conversion made, in `model` and below, put back as Gazebo
/// classic reads the file: links and joints named "inner::name" of the outer model.
void flattenConverted(bullet_sim::SdfModel* model);

}  // namespace oracle
}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_ORACLE_PARTS_H
