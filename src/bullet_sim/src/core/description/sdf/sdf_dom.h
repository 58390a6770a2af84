#ifndef BULLET_SIM_CORE_SDF_DOM_H
#define BULLET_SIM_CORE_SDF_DOM_H

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// What the simulator takes from an SDF file (SDF 1.4 to 1.9, as Gazebo classic reads it),
/// with the spec's default for every element that is absent, <include>s expanded and every
/// pose resolved into the frame named in its comment: version differences (a 1.4 joint
/// axis in the model frame, <pose frame> of 1.5/1.6, relative_to, <frame> and expressed_in
/// of 1.7) are settled by the reader, so users of these structs never see them.

/// Where an element was read: the file (or the source name of text from elsewhere) and
/// its line, for messages and for URIs relative to that file.
struct SdfOrigin {
  std::string file;
  int line = 0;
};

/// A <plugin>: its attributes and its children as written (XML text), for emulations.
struct SdfPlugin {
  std::string name, filename;
  std::string xml;  ///< the <plugin> element itself, printed
};

/// A <geometry>. `shape` holds the kinds the simulator has (box, cylinder, sphere, plane,
/// mesh) with their sizes as written or the spec's defaults; `type` names any kind.
struct SdfGeometry {
  std::string type = "empty";  ///< "box", "mesh", "heightmap", ... ("empty" when none)
  std::optional<Geometry> shape;
  std::string submesh;  ///< mesh only: <submesh><name>, "" when none
};

/// A visual's <material>. Colours are set only where the file gives them (Gazebo applies
/// only those); `script_name` is "" without a script, or for the script shorthand that
/// Gazebo reads as its default name (see sdf_material.cpp).
struct SdfMaterial {
  std::optional<Eigen::Vector4f> ambient, diffuse, specular, emissive;
  std::string script_name;
  std::vector<std::string> script_uris;  ///< as written
  bool lighting = true;
};

struct SdfVisual {
  std::string name;
  SdfOrigin origin;
  Eigen::Isometry3d T_link_visual = Eigen::Isometry3d::Identity();
  SdfGeometry geometry;
  std::optional<SdfMaterial> material;
  double transparency = 0;
  bool cast_shadows = true;
};

/// <surface><friction><ode> of a collision: set only where the file gives them, as written
/// (a negative or nan coefficient is refused by the builder, naming it).
struct SdfFriction {
  std::optional<double> mu, mu2;
};

struct SdfCollision {
  std::string name;
  SdfOrigin origin;
  Eigen::Isometry3d T_link_collision = Eigen::Isometry3d::Identity();
  SdfGeometry geometry;
  std::optional<SdfFriction> ode_friction;  ///< present when <surface><friction><ode> is
};

struct SdfSensor {
  std::string name, type;
  SdfOrigin origin;
  Eigen::Isometry3d T_link_sensor = Eigen::Isometry3d::Identity();
  double update_rate_hz = 0;
  bool always_on = false, visualize = false;
  std::string topic;  ///< <topic>, "" when absent
  std::vector<SdfPlugin> plugins;
  std::string xml;  ///< the <sensor> element itself, printed, for the sensor readers
};

/// <inertial>: mass and moments about the centre of mass, in the frame T_link_inertial.
struct SdfInertial {
  double mass = 1;
  double ixx = 1, iyy = 1, izz = 1, ixy = 0, ixz = 0, iyz = 0;
  Eigen::Isometry3d T_link_inertial = Eigen::Isometry3d::Identity();
};

struct SdfLink {
  std::string name;
  SdfOrigin origin;
  Eigen::Isometry3d T_model_link = Eigen::Isometry3d::Identity();
  SdfInertial inertial;
  bool gravity = true, kinematic = false, self_collide = false;
  std::vector<SdfCollision> collisions;
  std::vector<SdfVisual> visuals;
  std::vector<SdfSensor> sensors;
};

/// The first <axis> of a joint.
struct SdfJointAxis {
  Eigen::Vector3d xyz_in_model{0, 0, 1};  ///< unit vector, in the model frame
  double lower = -1e16, upper = 1e16, effort = -1, velocity = -1;
  double damping = 0, friction = 0, spring_reference = 0, spring_stiffness = 0;
};

struct SdfJoint {
  std::string name, type;  ///< type as written: revolute, prismatic, fixed, ...
  SdfOrigin origin;
  /// Parent and child link names as written, in this model's scope ("world", a link, or
  /// "nested::link").
  std::string parent, child;
  Eigen::Isometry3d T_model_joint = Eigen::Isometry3d::Identity();
  std::optional<SdfJointAxis> axis;  ///< absent for joints without one (fixed, ball)
};

struct SdfModel {
  std::string name;
  SdfOrigin origin;
  /// In the parent model's frame (the world frame for a model of the world).
  Eigen::Isometry3d T_parent_model = Eigen::Isometry3d::Identity();
  bool is_static = false;
  /// <model canonical_link> (1.7+) or "": the first link, else the first nested model's.
  std::string canonical_link;
  std::vector<SdfLink> links;
  std::vector<SdfJoint> joints;
  std::vector<SdfModel> models;  ///< nested models (and included ones)
  std::vector<SdfPlugin> plugins;

  /// The canonical link's scoped name ("nested::link") and pose in this model's frame, as
  /// libsdformat and Gazebo pick it; nullopt without any link.
  std::optional<std::pair<std::string, Eigen::Isometry3d>> canonicalLink() const;
};

/// A <light> of the world, posed in the world frame.
struct SdfLight {
  std::string name, type = "point";  ///< "point", "directional" or "spot"
  SdfOrigin origin;
  Eigen::Isometry3d T_world_light = Eigen::Isometry3d::Identity();
  Eigen::Vector4f diffuse{1, 1, 1, 1}, specular{0.1f, 0.1f, 0.1f, 1};
  double range_m = 10, constant = 1, linear = 1, quadratic = 0;
  Eigen::Vector3d direction{0, 0, -1};  ///< in the light's frame
  double spot_inner_rad = 0, spot_outer_rad = 0, spot_falloff = 0;
  bool cast_shadows = false;
};

struct SdfWorld {
  std::string name;
  SdfOrigin origin;
  Eigen::Vector3d gravity{0, 0, -9.8};
  double max_step_size_s = 0.001;
  double real_time_update_rate_hz = 1000, real_time_factor = 1;
  Eigen::Vector4f ambient{0.4f, 0.4f, 0.4f, 1.0f};
  Eigen::Vector4f background{0.7f, 0.7f, 0.7f, 1.0f};
  std::vector<SdfLight> lights;
  std::vector<SdfModel> models;
  std::vector<SdfPlugin> plugins;
};

/// A whole SDF document: a world, or a model (a file given to spawn_sdf_model or
/// included), or a light (model://sun is one).
struct SdfDocument {
  std::string version;  ///< of the top file's <sdf version>
  std::optional<SdfWorld> world;
  std::optional<SdfModel> model;
  std::optional<SdfLight> light;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_DOM_H
