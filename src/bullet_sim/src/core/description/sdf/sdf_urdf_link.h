#ifndef BULLET_SIM_CORE_SDF_URDF_LINK_H
#define BULLET_SIM_CORE_SDF_URDF_LINK_H

#include <map>
#include <string>

#include <urdf_model/model.h>

#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_extensions.h"
#include "description/sdf/sdf_model_entries.h"

namespace bullet_sim {

/// Turns the links of one SDF model into URDF links, collecting what URDF has no place for
/// in the model's RobotSpec and beside it.
class SdfLinkConverter {
 public:
  /// `where` names the model in messages; warnings and surfaces go to `spec`, which must
  /// outlive the converter.
  /// The links of a static model (`is_static`) never move: their inertia is not used (and
  /// not checked: Gazebo saves static links with mass 0 and nan moments).
  SdfLinkConverter(std::string where, const UriResolver& resolver, RobotSpec* spec,
                   bool is_static = false)
      : where_(std::move(where)), resolver_(resolver), spec_(spec), is_static_(is_static) {}

  /// The URDF link of `entry`: inertial (checked), collisions (their friction into
  /// spec->surfaces), visuals in their material's colour; its sensors are kept in sensors().
  /// @throws LoadError for a bad inertia or geometry a movable body cannot have.
  urdf::LinkSharedPtr convert(const LinkEntry& entry);

  /// The <sensor>s of the links converted, each posed in its link, for the sensor readers.
  const std::vector<SdfSensorText>& sensors() const { return sensors_; }

  /// Material script textures of the visuals converted, until the specs of the visuals exist.
  const std::map<const urdf::Visual*, TextureRef>& textures() const { return textures_; }

 private:
  void addCollisions(const SdfLink& l, const std::string& link, const std::string& where,
                     urdf::Link* out);
  void addVisuals(const SdfLink& l, const std::string& where, urdf::Link* out);
  /// A mesh's file is resolved here, from the folder of the SDF file that names it: the
  /// URDF model carries the path.
  urdf::GeometrySharedPtr geometry(const SdfGeometry& g, const SdfOrigin& origin,
                                   const std::string& where) const;
  /// <surface><friction><ode><mu>/<mu2> of a collision, as the URDF <gazebo> tags give them.
  void readFriction(const SdfCollision& c, const std::string& link, const std::string& where);

  std::string where_;
  const UriResolver& resolver_;
  RobotSpec* spec_;
  bool is_static_;
  std::map<const urdf::Visual*, TextureRef> textures_;
  std::vector<SdfSensorText> sensors_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_URDF_LINK_H
