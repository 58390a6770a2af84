#ifndef BULLET_SIM_ROBOT_SPEC_H
#define BULLET_SIM_ROBOT_SPEC_H

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <urdf_model/model.h>
#include <urdf_world/types.h>

#include <sim_render/geometry.h>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// The geometry description shared with the renderer (sim_render/geometry.h).
using Geometry = sim_render::Geometry;

/// A friction coefficient as Gazebo keeps it (FrictionPyramid::SetMu): a negative one
/// becomes FLT_MAX, friction without a limit (a contact then takes the other surface's).
inline double frictionCoefficient(double mu) {
  return mu < 0 ? static_cast<double>(std::numeric_limits<float>::max()) : mu;
}

/// Gazebo surface parameters of one link (<gazebo reference="link"><mu1>...).
struct SurfaceParams {
  double mu1 = 1.0, mu2 = 1.0, kp = 1e12, kd = 1.0;
  /// The one friction coefficient the link's contacts are given: friction is isotropic
  /// here, the mean of the two directions' (Gazebo's ODE applies mu1 along fdir1, mu2
  /// across it).
  double isotropicMu() const { return 0.5 * (mu1 + mu2); }
};

/// A <sensor type="ray"> (planar lidar) and its libgazebo_ros_laser.so plugin.
struct RaySpec {
  std::string name, link, topic = "scan", frame_id;
  Pose3 pose_in_link;
  double update_rate_hz = 5, min_angle_rad = 0, max_angle_rad = 0, range_min_m = 0.1,
         range_max_m = 10, range_resolution_m = 0, noise_mean_m = 0, noise_stddev_m = 0;
  int samples = 1;
};

/// The rays of a <sensor type="ray"> as Gazebo's MultiRayShape casts them: `samples`
/// horizontal angles from min to max (yaw 0 alone when there is one) for each of
/// `vertical_samples` vertical angles (pitch 0 alone when there is one; up is positive),
/// each ray from range_min to range_max along the sensor's x axis turned by yaw and pitch.
struct RayConeSpec {
  int samples = 1, vertical_samples = 1;
  double resolution = 1, vertical_resolution = 1;  ///< ranges per ray (<scan> <resolution>)
  double min_angle_rad = 0, max_angle_rad = 0, vertical_min_angle_rad = 0,
         vertical_max_angle_rad = 0, range_min_m = 0, range_max_m = 0;
};

/// A <sensor type="ray"> with libgazebo_ros_range.so: a sensor_msgs/Range of the nearest
/// of its rays. Defaults are the plugin's.
struct RangeSpec {
  std::string name, link, topic = "/range", frame_id = "/world";
  Pose3 pose_in_link;
  RayConeSpec rays;
  double update_rate_hz = 0;  ///< the sensor's <update_rate>, throttled by <updateRate>
  double gaussian_noise = 0, fov_rad = 0.05;
  bool infrared = false;  ///< <radiation>: "ultrasound" (the default) or anything else
};

/// A <sensor type="ray"> with libgazebo_ros_block_laser.so: a sensor_msgs/PointCloud of
/// every ray's end point. Defaults are the plugin's.
struct BlockLaserSpec {
  std::string name, link, topic = "/world", frame_id = "/world";
  Pose3 pose_in_link;
  RayConeSpec rays;
  double update_rate_hz = 0;  ///< the sensor's <update_rate> (the plugin's is not used)
  double gaussian_noise = 0;
};

/// A <sensor type="contact"> with libgazebo_ros_bumper.so: the contacts of one collision of
/// the sensor's link, as gazebo_msgs/ContactsState. Defaults are the plugin's.
struct BumperSpec {
  std::string name, link, collision, topic = "bumper_states", frame_id = "world";
  double update_rate_hz = 0;  ///< the sensor's <update_rate>
};

/// An IMU: a <sensor type="imu"> or a libgazebo_ros_imu(_sensor).so plugin.
struct ImuSpec {
  std::string name, link, topic = "imu", frame_id;
  double update_rate_hz = 0, gaussian_noise = 0;
};

/// The depth part of a <sensor type="depth"> with libgazebo_ros_openni_kinect.so or
/// libgazebo_ros_depth_camera.so: topics under the camera's <cameraName>, and the range
/// (cutoff_m, cutoff_max_m), both exclusive, outside which depth and points are NaN.
struct DepthSpec {
  std::string plugin;  ///< the plugin's file name, as written
  std::string depth_image_topic = "depth/image_raw", depth_info_topic = "depth/camera_info",
              point_cloud_topic = "points";
  double cutoff_m = 0.4;
  /// <pointCloudCutoffMax> (openni_kinect only; the depth_camera plugin has no upper cutoff)
  double cutoff_max_m = 5.0;
};

/// The <lens> of a <sensor type="wideanglecamera"> (SDF's defaults): the image radius r of a
/// ray at angle theta from the optical axis is r = c1 * f * fun(theta / c2 + c3), r in units
/// of the image's half width. A named `type` fixes c1, c2, c3 and fun (see camera_lens.h);
/// "custom" takes them from <custom_function>.
struct LensSpec {
  std::string type = "stereographic";
  double c1 = 1, c2 = 1, c3 = 0, f = 1;
  std::string fun = "tan";  ///< "sin", "tan" or "id"
  bool scale_to_hfov = true;  ///< f chosen so that r = 1 at theta = hfov / 2
  double cutoff_angle_rad = 1.5707;  ///< rays further from the axis are black
  int env_texture_size = 256;  ///< pixels along each side of a cube-map face
};

/// A camera's <noise> of type gaussian: per pixel and frame one sample of N(mean, stddev),
/// added to each colour channel in [0, 1] (Gazebo's image noise).
struct ImageNoiseSpec {
  double mean = 0, stddev = 0;
};

/// A camera's <distortion>: Brown's model (radial k1 k2 k3, tangential p1 p2) about
/// <center>, in units of the image size (0.5 0.5 is the principal point).
struct DistortionSpec {
  double k1 = 0, k2 = 0, k3 = 0, p1 = 0, p2 = 0, center_x = 0.5, center_y = 0.5;
};

/// A <sensor type="camera"> and its libgazebo_ros_camera.so plugin (or
/// libgazebo_ros_triggered_camera.so), one <camera> of a <sensor type="multicamera">, or a
/// <sensor type="depth">, whose colour image and camera_info are those of a camera (under
/// Gazebo's depth plugins' defaults ir/image_raw and ir/camera_info) and `depth` the rest.
struct CameraSpec {
  std::string name, link, camera_name = "camera", image_topic = "image_raw",
                          info_topic = "camera_info", frame_id;
  Pose3 pose_in_link;
  double update_rate_hz = 0, horizontal_fov_rad = 1.047, clip_near_m = 0.1, clip_far_m = 100;
  int width = 320, height = 240;
  std::string format = "R8G8B8";
  std::optional<DepthSpec> depth;  ///< set for a depth camera
  std::optional<LensSpec> lens;    ///< set for a wide-angle camera (hfov up to 2 pi)
  std::optional<ImageNoiseSpec> noise;      ///< <noise type="gaussian">
  std::optional<DistortionSpec> distortion;  ///< <distortion>, applied to the image
  /// camera_info's D (k1 k2 t1 t2 k3): the plugin's <distortionK1>.. or, with
  /// <autoDistortion>, the <distortion>'s coefficients
  std::array<double, 5> info_distortion{};
  double hack_baseline_m = 0;  ///< <hackBaseline>: camera_info P[3] = -fx * baseline
  /// A triggered camera's trigger topic (<triggerTopicName>, under the camera name): it
  /// renders one frame per message received, and nothing else. Empty for other cameras.
  std::string trigger_topic;
};

/// Where the diff drive's odometry comes from (<odometrySource>).
enum class OdomSource { World, Encoder };

/// The parameters of a wheeled drive plugin: libgazebo_ros_diff_drive.so, or
/// libgazebo_ros_skid_steer_drive.so, whose front wheels are `left_joint` and `right_joint`
/// and whose rear wheels (`left_rear_joint`, `right_rear_joint`) turn as the front wheel of
/// their side. Defaults are the diff drive's; the skid steer's reader sets its own.
struct DiffDriveSpec {
  std::string plugin = "libgazebo_ros_diff_drive.so";  ///< the plugin file, for messages
  std::string left_joint, right_joint, command_topic = "cmd_vel", odometry_topic = "odom",
                                        odometry_frame = "odom",
                                        robot_base_frame = "base_footprint";
  std::string left_rear_joint, right_rear_joint;  ///< skid steer only; empty otherwise
  double wheel_separation_m = 0.34, wheel_diameter_m = 0.15, wheel_torque_nm = 5,
         wheel_acceleration = 0, update_rate_hz = 100;
  OdomSource odometry_source = OdomSource::World;
  bool publish_odom_tf = true, publish_wheel_tf = false, publish_wheel_joint_state = false;
  /// The odometry's covariance diagonal (x, y, yaw; z, roll and pitch get 1e12), as the
  /// skid steer's <covariance_x>, <covariance_y>, <covariance_yaw>; unset: all zero.
  std::optional<Eigen::Vector3d> odometry_covariance_xy_yaw;
};

/// A libgazebo_ros_p3d.so plugin: the ground truth of one link as nav_msgs/Odometry.
struct P3dSpec {
  std::string name;   ///< the <plugin name>: seeds its noise
  std::string body;   ///< <bodyName>, a link of the robot
  std::string topic;  ///< <topicName>
  std::string frame = "world";  ///< <frameName>: world, map, or a link of the robot
  Pose3 offset;       ///< <xyzOffset> and <rpyOffset>
  double gaussian_noise = 0, update_rate_hz = 0;  ///< rate 0: every step
};

/// A libgazebo_ros_force.so plugin: the wrench of a geometry_msgs/Wrench topic applied to
/// one link (world axes, at its centre of mass) at every step until the next message.
struct ForceSpec {
  std::string body;   ///< <bodyName>
  std::string topic;  ///< <topicName>
};

/// A libgazebo_ros_planar_move.so plugin: the model is given the commanded planar velocity
/// at every step (linear x, y in its yaw frame, angular z; its z velocity and roll and pitch
/// rates set to 0), and its world pose is published as odometry with the odom tf.
/// Defaults are the plugin's (Noetic's gazebo_plugins).
struct PlanarMoveSpec {
  std::string command_topic = "cmd_vel", odometry_topic = "odom", odometry_frame = "odom",
              robot_base_frame = "base_footprint";
  double odometry_rate_hz = 20;  ///< <odometryRate>: 0 publishes no odometry and no tf
  double cmd_timeout_s = -1;     ///< <cmdTimeout>: a command older than this stops; < 0 never
};

/// A libgazebo_ros_joint_state_publisher.so plugin: sensor_msgs/JointState of the joints it
/// names, on `joint_states`, at its rate.
struct JointStatePublisherSpec {
  std::vector<std::string> joints;  ///< <jointName>, split at commas, in the order given
  double update_rate_hz = 100;      ///< <updateRate>; 0: every step
};

/// A libgazebo_ros_f3d.so plugin: the wrench applied to one link (the forces and torques
/// pushed on it from outside: force plugins, apply_body_wrench, joint efforts; not gravity,
/// contacts or joint constraints), world axes, torque about its centre of mass, as
/// geometry_msgs/WrenchStamped at every step.
struct F3dSpec {
  std::string body;   ///< <bodyName>
  std::string topic;  ///< <topicName>
  /// <frameName>: only the messages' frame_id (Gazebo's plugin never turns the wrench).
  std::string frame = "world";
};

/// A libgazebo_ros_ft_sensor.so plugin: the wrench one joint passes between its links, as
/// the child exerts it on the joint, in the child link's frame, torque about the joint.
struct FtSensorSpec {
  std::string name;   ///< the <plugin name>: seeds its noise
  std::string joint;  ///< <jointName>, a movable joint of the robot
  std::string topic;  ///< <topicName>
  double gaussian_noise = 0;  ///< <gaussianNoise>: sd of the noise on each of the six values
  double update_rate_hz = 0;  ///< <updateRate>; 0: every step
};

/// One URDF <visual>, in its link's frame (for the camera renderer): its geometry (a mesh's
/// `mesh_uri` is the <mesh filename> as written), link, pose and colour.
struct VisualSpec : Geometry {
  std::string link;
  Pose3 pose_in_link;
  /// The URDF <material> colour; a mesh part with a colour of its own keeps that (as RViz).
  Eigen::Vector4f rgba{0.7f, 0.7f, 0.7f, 1.0f};
  TextureRef texture;  ///< a Gazebo material script's texture (mesh files carry their own)
  std::shared_ptr<const TriangleMesh> mesh;   ///< Mesh: null when it could not be read
};

/// Everything the simulator needs from a robot description.
struct RobotSpec {
  std::string name;
  urdf::ModelInterfaceSharedPtr urdf;
  std::map<std::string, SurfaceParams> surfaces;  ///< by link name
  std::vector<RaySpec> rays;
  std::vector<ImuSpec> imus;
  std::vector<CameraSpec> cameras;
  std::vector<RangeSpec> ranges;
  std::vector<BlockLaserSpec> block_lasers;
  std::vector<BumperSpec> bumpers;
  std::optional<DiffDriveSpec> diff_drive;
  std::vector<P3dSpec> p3ds;
  std::vector<ForceSpec> forces;
  std::optional<PlanarMoveSpec> planar_move;
  /// Set: joint_states carries these plugins' joints at their rates, and no longer every
  /// movable joint at the drive's (or 30 Hz).
  std::vector<JointStatePublisherSpec> joint_state_publishers;
  std::vector<F3dSpec> f3ds;
  std::vector<FtSensorSpec> ft_sensors;
  std::vector<VisualSpec> visuals;
  /// The collision meshes, by <mesh filename> as written in the URDF.
  std::map<std::string, std::shared_ptr<const TriangleMesh>> collision_meshes;
  /// Where the URDF root link sits in the model frame: identity for URDF robots; for an
  /// SDF model the pose of its root link (the canonical link) in the <model> frame. Spawn
  /// and model poses are poses of the model frame, as in Gazebo.
  Pose3 root_link_in_model;
  /// A static model: a <static> SDF model (spawned, or in a world file with sensors or
  /// plugins) or one anchored to the world. Every link is fixed to the root link, and the
  /// robot is immovable Bullet bodies (mass 0) that robots collide with and rays and
  /// cameras see; it stays where it is put (set_model_state still moves it).
  bool is_static = false;
  /// Unsupported plugins/sensors, links with collision but no inertial, ...
  std::vector<std::string> warnings;
};

/// Parses a URDF document with urdfdom plus its Gazebo extension tags.
/// @param source_name used in error messages ("robot_description" or a path).
/// URIs in it (meshes) are looked up through `resolver` (see loadRobotMeshes; relative ones
/// from the folder of `source_name` when that is a file, else from the current folder).
/// @throws LoadError naming the source, element and bad value.
RobotSpec parseRobot(const std::string& urdf_xml, const std::string& source_name,
                     const UriResolver& resolver);
/// As above, with the resource paths of the environment (ROS_PACKAGE_PATH, GAZEBO_MODEL_PATH).
RobotSpec parseRobot(const std::string& urdf_xml, const std::string& source_name);

/// Reads the meshes `spec`'s URDF names (through MeshCache::shared()): every collision
/// <mesh> into spec->collision_meshes, every visual one into its VisualSpec. URIs resolve
/// through `resolver`, relative ones from `base_dir`.
/// @throws LoadError naming `source`, the link and the URI (and the path or folders
/// searched) for a collision mesh that is missing or unreadable, or a scale that is not
/// finite and non-zero; a visual mesh in that state becomes a warning and is not drawn.
void loadRobotMeshes(const UriResolver& resolver, const std::string& base_dir,
                     const std::string& source, RobotSpec* spec);

/// Reads a URDF file and parses it as parseRobot does (the path names the source; relative
/// mesh names resolve from the file's folder).
/// @throws LoadError when the file cannot be read or parsed.
RobotSpec parseRobotFile(const std::string& path);

/// Converts an SDF document holding one <model> into a RobotSpec, as a movable model of a
/// world is simulated (Gazebo's spawn_sdf_model): its links with inertial, collision and
/// visual geometry (material scripts give Gazebo's colours), its revolute, continuous,
/// prismatic and fixed joints, nested models with `::`-scoped link names; the tree is
/// rooted at the canonical link. <include>s are resolved through `resolver`.
/// Its links' <sensor>s and its <plugin>s are read as a URDF's <gazebo> blocks are (the
/// same readers; unsupported ones a warning each). A <static> model gives a static spec.
/// @throws LoadError naming the source, element and value.
RobotSpec parseSdfModelString(const std::string& sdf_xml, const std::string& source_name,
                              const UriResolver& resolver);
/// As above, with the resource paths of the environment (GAZEBO_MODEL_PATH, ROS_PACKAGE_PATH).
RobotSpec parseSdfModelString(const std::string& sdf_xml, const std::string& source_name);

}  // namespace bullet_sim

#endif  // BULLET_SIM_ROBOT_SPEC_H
