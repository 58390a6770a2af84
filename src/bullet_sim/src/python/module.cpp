// bullet_sim._core: the ROS-free core (loaders, Simulation, camera renderer) as a Python
// module. Includes only the public headers (include/bullet_sim/), as the node does.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/sensors/sensor_data.h"
#include "bullet_sim/simulation.h"
#include "bullet_sim/types.h"

namespace py = pybind11;
using namespace bullet_sim;

namespace {

using Paths = std::optional<std::vector<std::string>>;

// ---------------------------------------------------------------- arrays ----

/// A NumPy array that owns `values` (moved to the heap and freed with the array): no copy
/// of the data, and nothing that points into the simulation.
template <class T>
py::array_t<T> ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape,
                          std::vector<py::ssize_t> strides = {}) {
  auto* heap = new std::vector<T>(std::move(values));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  if (strides.empty()) return py::array_t<T>(shape, heap->data(), owner);
  return py::array_t<T>(shape, strides, heap->data(), owner);
}

template <class T>
py::array_t<T> ownedArray(std::vector<T>&& values) {
  const auto n = static_cast<py::ssize_t>(values.size());
  return ownedArray(std::move(values), {n});
}

py::array_t<double> vec3(const Eigen::Vector3d& v) {
  return ownedArray(std::vector<double>{v.x(), v.y(), v.z()});
}

py::array_t<double> quatXyzw(const Eigen::Quaterniond& q) {
  return ownedArray(std::vector<double>{q.x(), q.y(), q.z(), q.w()});
}

double yawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()),
                    1 - 2 * (q.y() * q.y() + q.z() * q.z()));
}

// ----------------------------------------------------------- arguments ----

double finite(double value, const char* what) {
  if (!std::isfinite(value)) {
    std::ostringstream msg;
    msg << what << " must be finite, got " << value;
    throw std::invalid_argument(msg.str());
  }
  return value;
}

/// A pose given as (x, y, z, yaw), (x, y, z, qx, qy, qz, qw) or a Pose.
Pose3 poseArg(py::handle arg, const char* what) {
  if (py::isinstance<Pose3>(arg)) return arg.cast<Pose3>();
  std::vector<double> v;
  try {
    v = arg.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw std::invalid_argument(std::string(what) +
                                ": expected (x, y, z, yaw), (x, y, z, qx, qy, qz, qw) or a Pose");
  }
  if (v.size() != 4 && v.size() != 7) {
    throw std::invalid_argument(std::string(what) +
                                ": expected (x, y, z, yaw) or (x, y, z, qx, qy, qz, qw), got " +
                                std::to_string(v.size()) + " values");
  }
  for (double x : v) finite(x, what);
  Pose3 pose;
  pose.position = Eigen::Vector3d(v[0], v[1], v[2]);
  if (v.size() == 4) {
    pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitZ()));
  } else {
    Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
    if (!(q.norm() > 1e-9)) {
      throw std::invalid_argument(std::string(what) + ": the quaternion has zero length");
    }
    pose.orientation = q.normalized();
  }
  return pose;
}

/// A twist given as ((vx, vy, vz), (wx, wy, wz)), world axes, or a Twist.
Twist3 twistArg(py::handle arg) {
  if (arg.is_none()) return Twist3{};
  if (py::isinstance<Twist3>(arg)) return arg.cast<Twist3>();
  std::vector<std::vector<double>> v;
  try {
    v = arg.cast<std::vector<std::vector<double>>>();
  } catch (const py::cast_error&) {
    throw std::invalid_argument("twist: expected ((vx, vy, vz), (wx, wy, wz)) or a Twist");
  }
  if (v.size() != 2 || v[0].size() != 3 || v[1].size() != 3) {
    throw std::invalid_argument("twist: expected ((vx, vy, vz), (wx, wy, wz))");
  }
  for (const auto& part : v)
    for (double x : part) finite(x, "twist");
  Twist3 t;
  t.linear = Eigen::Vector3d(v[0][0], v[0][1], v[0][2]);
  t.angular = Eigen::Vector3d(v[1][0], v[1][1], v[1][2]);
  return t;
}

UriResolver resolverFor(const Paths& model_paths, const Paths& package_paths) {
  ResourcePaths paths = ResourcePaths::fromEnvironment();
  if (model_paths) {
    paths.model_paths = *model_paths;
    paths.later_model_paths = {};
  }
  if (package_paths) paths.package_paths = *package_paths;
  return UriResolver(std::move(paths));
}

/// Text when it starts (after white space) with '<', else a file path.
bool isXmlText(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t\r\n");
  return first != std::string::npos && s[first] == '<';
}

std::string readFile(const std::string& path, const char* what) {
  std::ifstream in(path);
  if (!in) throw LoadError(path + ": cannot read the " + what + " file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// ------------------------------------------------------------- results ----

/// A scan with its ranges and intensities as arrays that own their memory.
struct Scan {
  LaserScanData meta;  ///< ranges and intensities moved out
  py::array_t<float> ranges, intensities;
};

Scan toScan(LaserScanData&& data) {
  Scan scan;
  scan.ranges = ownedArray(std::move(data.ranges));
  scan.intensities = ownedArray(std::move(data.intensities));
  scan.meta = std::move(data);
  return scan;
}

struct JointStates {
  double time_s = 0;
  std::vector<std::string> names;
  py::array_t<double> positions, velocities, efforts;
};

py::array_t<double> covariance(const std::array<double, 36>& c) {
  return ownedArray(std::vector<double>(c.begin(), c.end()), {6, 6});
}

/// A camera image as an array: H x W x 3 for rgb8/bgr8 (uint8) and rgb16 (uint16), H x W for
/// mono8 and mono16; rows `step` bytes apart, as rendered.
py::array imageArray(ImageData&& image) {
  const py::ssize_t h = image.height, w = image.width, step = image.step;
  const std::string& enc = image.encoding;
  const bool color = enc == "rgb8" || enc == "bgr8" || enc == "rgb16";
  const bool wide = enc == "rgb16" || enc == "mono16";
  if (!color && enc != "mono8" && enc != "mono16") {
    throw std::invalid_argument("camera image encoding '" + enc + "' is not supported");
  }
  if (!wide) {
    if (color) return ownedArray(std::move(image.data), {h, w, 3}, {step, 3, 1});
    return ownedArray(std::move(image.data), {h, w}, {step, 1});
  }
  std::vector<uint16_t> words(image.data.size() / 2);
  std::memcpy(words.data(), image.data.data(), words.size() * 2);
  if (color) return ownedArray(std::move(words), {h, w, 3}, {step, 6, 2});
  return ownedArray(std::move(words), {h, w}, {step, 2});
}

// ---------------------------------------------------------- simulation ----

/// Throws std::out_of_range naming the robot and the sensors it has when `index` is not one
/// of its `count` sensors of kind `what` (the core's own message is the container's).
void checkIndex(const std::string& robot, const char* what, size_t count, size_t index) {
  if (index >= count) {
    throw std::out_of_range("robot '" + robot + "' has " + std::to_string(count) + " " + what +
                            " sensor(s): no index " + std::to_string(index));
  }
}


const char* kindName(SensorKind kind) {
  switch (kind) {
    case SensorKind::Ray: return "ray";
    case SensorKind::Imu: return "imu";
    case SensorKind::Camera: return "camera";
    case SensorKind::Odometry: return "odometry";
    case SensorKind::JointStates: return "joint_states";
    case SensorKind::GroundTruth: return "ground_truth";
    case SensorKind::Range: return "range";
    case SensorKind::BlockLaser: return "block_laser";
    case SensorKind::Bumper: return "bumper";
    case SensorKind::PlanarMoveOdometry: return "planar_move_odometry";
    case SensorKind::PluginJointStates: return "plugin_joint_states";
    case SensorKind::F3d: return "f3d";
    case SensorKind::ForceTorque: return "force_torque";
  }
  return "?";
}

/// A Simulation and its camera renderer (made with the first camera read). Every call
/// releases the GIL and takes the object's lock, so Python threads may step separate
/// simulations in parallel, and calls on one simulation from several threads take turns.
class PySimulation {
 public:
  PySimulation(std::shared_ptr<WorldSpec> world, double physics_step, uint64_t seed,
               unsigned threads, double cmd_vel_timeout)
      : world_(std::move(world)) {
    SimConfig cfg;
    cfg.physics_step_s = finite(physics_step, "physics_step");
    cfg.seed = seed;
    cfg.threads = threads;
    cfg.cmd_vel_timeout_s = finite(cmd_vel_timeout, "cmd_vel_timeout");
    if (cfg.cmd_vel_timeout_s < 0) {
      throw std::invalid_argument("cmd_vel_timeout must be >= 0, got " +
                                  std::to_string(cmd_vel_timeout));
    }
    py::gil_scoped_release nogil;
    sim_ = std::make_unique<Simulation>(*world_, cfg);
  }

  ~PySimulation() {
    renderer_.reset();  // it refers to the simulation
  }

  /// Runs `f(sim)` without the GIL, under the object's lock.
  template <class F>
  auto locked(F&& f) {
    py::gil_scoped_release nogil;
    std::lock_guard<std::mutex> lock(mutex_);
    return f(*sim_);
  }

  std::vector<DueSensor> step(long n) {
    if (n < 1) throw std::invalid_argument("step: n must be >= 1, got " + std::to_string(n));
    return locked([n](Simulation& sim) {
      std::vector<DueSensor> due;
      for (long i = 0; i < n; ++i) {
        std::vector<DueSensor> now = sim.step();
        due.insert(due.end(), std::make_move_iterator(now.begin()),
                   std::make_move_iterator(now.end()));
      }
      return due;
    });
  }

  py::array readCamera(const std::string& robot, size_t index) {
    ImageData image = locked([&](Simulation& sim) {
      checkIndex(robot, "camera", sim.robotSpec(robot).cameras.size(), index);
      if (!renderer_) renderer_ = std::make_unique<CameraRenderer>(sim);
      ImageData out;
      renderer_->render(robot, index, &out);
      return out;
    });
    return imageArray(std::move(image));
  }

  std::shared_ptr<WorldSpec> world() const { return world_; }

 private:
  std::shared_ptr<WorldSpec> world_;
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<CameraRenderer> renderer_;
  std::mutex mutex_;
};

}  // namespace

// ---------------------------------------------------------------- module ----

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "bullet_sim's ROS-free core: load SDF worlds and URDF/SDF robots, step the physics, "
      "read the sensors.";

  // Errors: LoadError for descriptions that cannot be loaded; std::out_of_range (unknown
  // robot, sensor index, link, joint) as NotFoundError, a KeyError and an IndexError;
  // std::invalid_argument as ValueError (pybind11's own translation).
  auto& load_error = py::register_exception<LoadError>(m, "LoadError", PyExc_Exception);
  load_error.doc() =
      "A robot description or world that cannot be loaded; the message names the file (or "
      "source), the element and the value.";
  py::object not_found;
  {
    py::tuple bases = py::make_tuple(py::handle(PyExc_KeyError), py::handle(PyExc_IndexError));
    py::dict body;
    body["__str__"] = py::handle(PyExc_Exception).attr("__str__");
    body["__module__"] = "bullet_sim";
    body["__doc__"] =
        "An unknown robot, sensor index, link or joint: a KeyError and an IndexError, with "
        "the core's message.";
    not_found = py::reinterpret_steal<py::object>(
        PyErr_NewException("bullet_sim.NotFoundError", bases.ptr(), body.ptr()));
    if (!not_found) throw py::error_already_set();
  }
  m.attr("NotFoundError") = not_found;
  static PyObject* not_found_ptr = not_found.inc_ref().ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::out_of_range& e) {
      PyErr_SetString(not_found_ptr, e.what());
    }
  });

  // -------------------------------------------------------------- values ----
  py::class_<Pose3>(m, "Pose", "A rigid transform: position (m) and unit quaternion.")
      .def(py::init([](py::object pose) { return poseArg(pose, "pose"); }), py::arg("pose"),
           "From (x, y, z, yaw) or (x, y, z, qx, qy, qz, qw).")
      .def_property_readonly("x", [](const Pose3& p) { return p.position.x(); })
      .def_property_readonly("y", [](const Pose3& p) { return p.position.y(); })
      .def_property_readonly("z", [](const Pose3& p) { return p.position.z(); })
      .def_property_readonly("yaw", [](const Pose3& p) { return yawOf(p.orientation); },
                             "Heading (rad) about the world's z axis.")
      .def_property_readonly("position", [](const Pose3& p) { return vec3(p.position); },
                             "float64 array (x, y, z).")
      .def_property_readonly("orientation", [](const Pose3& p) { return quatXyzw(p.orientation); },
                             "float64 array (qx, qy, qz, qw).")
      .def("to_tuple",
           [](const Pose3& p) {
             const auto& q = p.orientation;
             return py::make_tuple(p.position.x(), p.position.y(), p.position.z(), q.x(), q.y(),
                                   q.z(), q.w());
           },
           "(x, y, z, qx, qy, qz, qw).")
      .def("__repr__", [](const Pose3& p) {
        std::ostringstream s;
        s.precision(6);
        s << "Pose(x=" << p.position.x() << ", y=" << p.position.y() << ", z=" << p.position.z()
          << ", yaw=" << yawOf(p.orientation) << ")";
        return s.str();
      });

  py::class_<Twist3>(m, "Twist", "Linear (m/s) and angular (rad/s) velocity.")
      .def(py::init([](py::object linear, py::object angular) {
             return twistArg(py::make_tuple(linear, angular));
           }),
           py::arg("linear"), py::arg("angular"))
      .def_property_readonly("linear", [](const Twist3& t) { return vec3(t.linear); })
      .def_property_readonly("angular", [](const Twist3& t) { return vec3(t.angular); })
      .def("__repr__", [](const Twist3& t) {
        std::ostringstream s;
        s.precision(6);
        s << "Twist(linear=(" << t.linear.x() << ", " << t.linear.y() << ", " << t.linear.z()
          << "), angular=(" << t.angular.x() << ", " << t.angular.y() << ", " << t.angular.z()
          << "))";
        return s.str();
      });

  py::class_<ModelCondition>(m, "Condition", "How a model stands.")
      .def_readonly("tilt", &ModelCondition::tilt_rad,
                    "Angle (rad) between the root link's z axis and the world's.")
      .def_readonly("wall_penetration", &ModelCondition::wall_penetration_m,
                    "Deepest reach (m) of any of its bodies into a static body.")
      .def_property_readonly("tipped_over", &ModelCondition::tippedOver, "tilt beyond 45 degrees")
      .def_property_readonly("in_wall", &ModelCondition::inWall, "wall_penetration beyond 1 cm")
      .def("__repr__", [](const ModelCondition& c) {
        std::ostringstream s;
        s << "Condition(tilt=" << c.tilt_rad << ", wall_penetration=" << c.wall_penetration_m
          << ")";
        return s.str();
      });

  py::enum_<SensorKind>(m, "SensorKind", "The kind of a due sensor.")
      .value("RAY", SensorKind::Ray)
      .value("IMU", SensorKind::Imu)
      .value("CAMERA", SensorKind::Camera)
      .value("ODOMETRY", SensorKind::Odometry)
      .value("JOINT_STATES", SensorKind::JointStates)
      .value("GROUND_TRUTH", SensorKind::GroundTruth)
      .value("RANGE", SensorKind::Range)
      .value("BLOCK_LASER", SensorKind::BlockLaser)
      .value("BUMPER", SensorKind::Bumper)
      .value("PLANAR_MOVE_ODOMETRY", SensorKind::PlanarMoveOdometry)
      .value("PLUGIN_JOINT_STATES", SensorKind::PluginJointStates)
      .value("F3D", SensorKind::F3d)
      .value("FORCE_TORQUE", SensorKind::ForceTorque);

  py::class_<DueSensor>(m, "DueSensor",
                        "A sensor whose update period elapsed: read it with the read_* method "
                        "of its kind and index.")
      .def_readonly("robot", &DueSensor::robot)
      .def_readonly("kind", &DueSensor::kind)
      .def_readonly("index", &DueSensor::index)
      .def("__eq__", [](const DueSensor& a, const DueSensor& b) {
        return a.robot == b.robot && a.kind == b.kind && a.index == b.index;
      })
      .def("__hash__", [](const DueSensor& d) {
        return py::hash(py::make_tuple(d.robot, static_cast<int>(d.kind), d.index));
      })
      .def("__repr__", [](const DueSensor& d) {
        return "DueSensor(robot='" + d.robot + "', kind=" + kindName(d.kind) +
               ", index=" + std::to_string(d.index) + ")";
      });

  py::class_<Scan>(m, "Scan", "One planar scan, laid out as sensor_msgs/LaserScan.")
      .def_readonly("ranges", &Scan::ranges,
                    "float32 array (m), +inf where nothing is hit within range_max. Owns its "
                    "memory: it stays valid after the Simulation is gone.")
      .def_readonly("intensities", &Scan::intensities, "float32 array")
      .def_property_readonly("time", [](const Scan& s) { return s.meta.time_s; }, "sim time (s)")
      .def_property_readonly("frame_id", [](const Scan& s) { return s.meta.frame_id; })
      .def_property_readonly("angle_min", [](const Scan& s) { return s.meta.angle_min; })
      .def_property_readonly("angle_max", [](const Scan& s) { return s.meta.angle_max; })
      .def_property_readonly("angle_increment", [](const Scan& s) { return s.meta.angle_increment; })
      .def_property_readonly("time_increment", [](const Scan& s) { return s.meta.time_increment; })
      .def_property_readonly("scan_time", [](const Scan& s) { return s.meta.scan_time; })
      .def_property_readonly("range_min", [](const Scan& s) { return s.meta.range_min; })
      .def_property_readonly("range_max", [](const Scan& s) { return s.meta.range_max; });

  py::class_<OdometryData>(m, "Odometry",
                           "The diff drive's odometry, laid out as nav_msgs/Odometry.")
      .def_readonly("time", &OdometryData::time_s)
      .def_readonly("frame_id", &OdometryData::frame_id)
      .def_readonly("child_frame_id", &OdometryData::child_frame_id)
      .def_readonly("pose", &OdometryData::pose, "the robot base in the odometry frame")
      .def_readonly("twist", &OdometryData::twist_in_child, "in the robot base's axes")
      .def_property_readonly("pose_covariance",
                             [](const OdometryData& o) { return covariance(o.pose_covariance); },
                             "6 x 6 (x, y, z, roll, pitch, yaw)")
      .def_property_readonly("twist_covariance",
                             [](const OdometryData& o) { return covariance(o.twist_covariance); });

  py::class_<ImuData>(m, "Imu", "One IMU reading, in the IMU link's frame.")
      .def_readonly("time", &ImuData::time_s)
      .def_readonly("frame_id", &ImuData::frame_id)
      .def_property_readonly("orientation", [](const ImuData& d) { return quatXyzw(d.orientation); },
                             "(qx, qy, qz, qw): the link in the world")
      .def_property_readonly("angular_velocity",
                             [](const ImuData& d) { return vec3(d.angular_velocity); }, "rad/s")
      .def_property_readonly("linear_acceleration",
                             [](const ImuData& d) { return vec3(d.linear_acceleration); },
                             "m/s^2, proper acceleration (+9.8 on z at rest)")
      .def_readonly("orientation_covariance", &ImuData::orientation_cov)
      .def_readonly("angular_velocity_covariance", &ImuData::angular_velocity_cov)
      .def_readonly("linear_acceleration_covariance", &ImuData::linear_acceleration_cov);

  py::class_<JointStates>(m, "JointStates", "Every non-fixed joint, as sensor_msgs/JointState.")
      .def_readonly("time", &JointStates::time_s)
      .def_readonly("names", &JointStates::names)
      .def_readonly("positions", &JointStates::positions, "float64 array (rad)")
      .def_readonly("velocities", &JointStates::velocities, "float64 array (rad/s)")
      .def_readonly("efforts", &JointStates::efforts, "float64 array (N m)");

  // ------------------------------------------------------------- loaders ----
  py::class_<WorldSpec, std::shared_ptr<WorldSpec>>(m, "World", "A loaded SDF world.")
      .def_static(
          "from_file",
          [](const std::string& path, const Paths& model_paths, const Paths& package_paths) {
            UriResolver resolver = resolverFor(model_paths, package_paths);
            py::gil_scoped_release nogil;
            return std::make_shared<WorldSpec>(loadWorldFile(path, resolver));
          },
          py::arg("path"), py::kw_only(), py::arg("model_paths") = py::none(),
          py::arg("package_paths") = py::none(),
          "Loads an SDF world file. model:// and package:// URIs are looked up in "
          "`model_paths` and `package_paths` (default: GAZEBO_MODEL_PATH and "
          "ROS_PACKAGE_PATH); raises LoadError naming the file, element and value.")
      .def_static(
          "from_string",
          [](const std::string& sdf, const std::string& source_name, const Paths& model_paths,
             const Paths& package_paths) {
            UriResolver resolver = resolverFor(model_paths, package_paths);
            py::gil_scoped_release nogil;
            return std::make_shared<WorldSpec>(loadWorldString(sdf, source_name, resolver));
          },
          py::arg("sdf"), py::arg("source_name") = "world", py::kw_only(),
          py::arg("model_paths") = py::none(), py::arg("package_paths") = py::none(),
          "Loads an SDF world from its text; errors name `source_name`.")
      .def_readonly("name", &WorldSpec::name)
      .def_property_readonly("model_names",
                             [](const WorldSpec& w) {
                               std::vector<std::string> names;
                               for (const auto& model : w.models) names.push_back(model.name);
                               return names;
                             },
                             "The movable models, simulated as robots of these names.")
      .def_property_readonly("gravity", [](const WorldSpec& w) { return vec3(w.gravity); })
      .def_readonly("warnings", &WorldSpec::warnings)
      .def("__repr__", [](const WorldSpec& w) { return "World('" + w.name + "')"; });

  py::class_<RobotSpec, std::shared_ptr<RobotSpec>>(m, "Robot",
                                                    "A parsed robot description (URDF or SDF).")
      .def_static(
          "from_urdf",
          [](const std::string& path_or_text, std::optional<std::string> source_name,
             const Paths& model_paths, const Paths& package_paths) {
            UriResolver resolver = resolverFor(model_paths, package_paths);
            py::gil_scoped_release nogil;
            if (isXmlText(path_or_text)) {
              return std::make_shared<RobotSpec>(parseRobot(
                  path_or_text, source_name.value_or("robot_description"), resolver));
            }
            const std::string text = readFile(path_or_text, "robot");
            return std::make_shared<RobotSpec>(
                parseRobot(text, source_name.value_or(path_or_text), resolver));
          },
          py::arg("path_or_text"), py::arg("source_name") = py::none(), py::kw_only(),
          py::arg("model_paths") = py::none(), py::arg("package_paths") = py::none(),
          "Parses a URDF (with its Gazebo extensions) from a file path or from its text (a "
          "string that starts with '<', such as xacro's output). Errors name `source_name` "
          "(default: the path, or 'robot_description' for text).")
      .def_static(
          "from_sdf",
          [](const std::string& path_or_text, std::optional<std::string> source_name,
             const Paths& model_paths, const Paths& package_paths) {
            UriResolver resolver = resolverFor(model_paths, package_paths);
            py::gil_scoped_release nogil;
            const bool text = isXmlText(path_or_text);
            const std::string sdf = text ? path_or_text : readFile(path_or_text, "model");
            return std::make_shared<RobotSpec>(parseSdfModelString(
                sdf, source_name.value_or(text ? "model" : path_or_text), resolver));
          },
          py::arg("path_or_text"), py::arg("source_name") = py::none(), py::kw_only(),
          py::arg("model_paths") = py::none(), py::arg("package_paths") = py::none(),
          "Parses an SDF document holding one <model>, from a file path or its text.")
      .def_readonly("name", &RobotSpec::name)
      .def_property_readonly("num_rays", [](const RobotSpec& r) { return r.rays.size(); })
      .def_property_readonly("num_imus", [](const RobotSpec& r) { return r.imus.size(); })
      .def_property_readonly("num_cameras", [](const RobotSpec& r) { return r.cameras.size(); })
      .def_property_readonly("has_diff_drive",
                             [](const RobotSpec& r) { return r.diff_drive.has_value(); })
      .def_readonly("is_static", &RobotSpec::is_static)
      .def_readonly("warnings", &RobotSpec::warnings)
      .def("__repr__", [](const RobotSpec& r) { return "Robot('" + r.name + "')"; });

  // ---------------------------------------------------------- simulation ----
  py::class_<PySimulation>(
      m, "Simulation",
      "The simulated world with its robots, in sim time only (nothing reads a clock).\n\n"
      "Methods release the GIL: Python threads stepping separate Simulations run in "
      "parallel. Calls on one Simulation from several threads take turns (a lock); use one "
      "Simulation per thread for speed. Every robot-taking method raises NotFoundError (a "
      "KeyError) for an unknown robot.")
      .def(py::init([](std::shared_ptr<WorldSpec> world, double physics_step, uint64_t seed,
                       unsigned threads, double cmd_vel_timeout) {
             if (!world) throw std::invalid_argument("world must be a World, got None");
             return std::make_unique<PySimulation>(world, physics_step, seed, threads,
                                                   cmd_vel_timeout);
           }),
           py::arg("world"), py::arg("physics_step") = 0.001, py::arg("seed") = 1,
           py::arg("threads") = 0, py::arg("cmd_vel_timeout") = 0.0,
           "physics_step: seconds per step; seed: every sensor's noise is drawn from (seed, "
           "robot, sensor); threads: physics threads (0 = the machine's; results are the "
           "same to the bit whatever the number); cmd_vel_timeout: a robot whose last "
           "set_cmd_vel is older (sim s) gets zero (0 = never). The world's movable models "
           "are spawned as robots of their names.")
      .def(
          "spawn",
          [](PySimulation& s, const std::string& name, std::shared_ptr<RobotSpec> robot,
             py::object pose) {
            if (!robot) throw std::invalid_argument("robot must be a Robot, got None");
            const Pose3 p = poseArg(pose, "pose");
            s.locked([&](Simulation& sim) { sim.spawnRobot(name, *robot, p); });
          },
          py::arg("name"), py::arg("robot"), py::arg("pose") = py::make_tuple(0.0, 0.0, 0.0, 0.0),
          "Spawns `robot` as `name` with its model frame at `pose`: (x, y, z, yaw), (x, y, z, "
          "qx, qy, qz, qw) or a Pose. Raises LoadError on a name clash.")
      .def("delete",
           [](PySimulation& s, const std::string& name) {
             return s.locked([&](Simulation& sim) { return sim.deleteRobot(name); });
           },
           py::arg("name"), "Removes a robot; False when there is none of that name.")
      .def("robot_names",
           [](PySimulation& s) { return s.locked([](Simulation& sim) { return sim.robotNames(); }); },
           "Every robot (the world's movable models first), in spawn order.")
      .def("step", &PySimulation::step, py::arg("n") = 1,
           "Advances `n` physics steps; returns the sensors that fell due, in order.")
      .def(
          "step_to_next_reading",
          [](PySimulation& s, unsigned max_steps) {
            if (max_steps < 1) throw std::invalid_argument("max_steps must be >= 1");
            return s.locked(
                [&](Simulation& sim) { return sim.stepToNextReading(max_steps); });
          },
          py::arg("max_steps"),
          "Advances up to `max_steps` steps (at least one), stopping after the first at which "
          "a sensor is due; returns the sensors due then (empty when none fell due).")
      .def_property_readonly(
          "time", [](PySimulation& s) { return s.locked([](Simulation& sim) { return sim.timeS(); }); },
          "Sim time (s).")
      .def_property_readonly(
          "seed", [](PySimulation& s) { return s.locked([](Simulation& sim) { return sim.seed(); }); })
      .def_property_readonly(
          "threads",
          [](PySimulation& s) { return s.locked([](Simulation& sim) { return sim.threads(); }); })
      .def_property(
          "physics_step",
          [](PySimulation& s) { return s.locked([](Simulation& sim) { return sim.physicsStepS(); }); },
          [](PySimulation& s, double step) {
            s.locked([&](Simulation& sim) { sim.setPhysicsStep(step); });
          },
          "Seconds per step; settable (sim time runs on).")
      .def_property_readonly("world", &PySimulation::world, "The World it was made from.")
      .def("reset", [](PySimulation& s) { s.locked([](Simulation& sim) { sim.reset(); }); },
           "Sim time to 0, robots back to their spawn poses at rest, commands zero.")
      .def(
          "set_cmd_vel",
          [](PySimulation& s, const std::string& robot, double v, double w) {
            finite(v, "linear velocity");
            finite(w, "angular velocity");
            s.locked([&](Simulation& sim) { sim.setCmdVel(robot, v, w); });
          },
          py::arg("robot"), py::arg("linear"), py::arg("angular"),
          "The diff drive's command (m/s, rad/s), kept until the next one (or cmd_vel_timeout).")
      .def("model_pose",
           [](PySimulation& s, const std::string& robot) {
             return s.locked([&](Simulation& sim) { return sim.modelPose(robot); });
           },
           py::arg("robot"), "The model frame in the world.")
      .def("model_twist",
           [](PySimulation& s, const std::string& robot) {
             return s.locked([&](Simulation& sim) { return sim.modelTwist(robot); });
           },
           py::arg("robot"), "Velocity of the model, world axes.")
      .def("condition",
           [](PySimulation& s, const std::string& robot) {
             return s.locked([&](Simulation& sim) { return sim.condition(robot); });
           },
           py::arg("robot"), "Tilt and wall penetration (tipped_over, in_wall).")
      .def(
          "set_model_state",
          [](PySimulation& s, const std::string& robot, py::object pose, py::object twist) {
            const Pose3 p = poseArg(pose, "pose");
            const Twist3 t = twistArg(twist);
            s.locked([&](Simulation& sim) { sim.setModelState(robot, p, t); });
          },
          py::arg("robot"), py::arg("pose"), py::arg("twist") = py::none(),
          "Moves the model to `pose` with `twist` ((vx, vy, vz), (wx, wy, wz)) world axes; "
          "default at rest.")
      .def(
          "read_scan",
          [](PySimulation& s, const std::string& robot, size_t index) {
            LaserScanData data =
                s.locked([&](Simulation& sim) {
                  checkIndex(robot, "ray", sim.robotSpec(robot).rays.size(), index);
                  return sim.readRay(robot, index);
                });
            return toScan(std::move(data));
          },
          py::arg("robot"), py::arg("index") = 0, "Ray sensor `index` of `robot`, cast now.")
      .def("read_odometry",
           [](PySimulation& s, const std::string& robot) {
             return s.locked([&](Simulation& sim) { return sim.readOdometry(robot); });
           },
           py::arg("robot"), "The diff drive's odometry.")
      .def("read_imu",
           [](PySimulation& s, const std::string& robot, size_t index) {
             return s.locked([&](Simulation& sim) {
               checkIndex(robot, "IMU", sim.robotSpec(robot).imus.size(), index);
               return sim.readImu(robot, index);
             });
           },
           py::arg("robot"), py::arg("index") = 0, "IMU `index` of `robot`.")
      .def(
          "read_joint_states",
          [](PySimulation& s, const std::string& robot) {
            JointStateData data =
                s.locked([&](Simulation& sim) { return sim.readJointStates(robot); });
            JointStates out;
            out.time_s = data.time_s;
            out.names = std::move(data.names);
            out.positions = ownedArray(std::move(data.positions));
            out.velocities = ownedArray(std::move(data.velocities));
            out.efforts = ownedArray(std::move(data.efforts));
            return out;
          },
          py::arg("robot"), "Every non-fixed joint of `robot`.")
      .def("read_camera", &PySimulation::readCamera, py::arg("robot"), py::arg("index") = 0,
           "Renders camera `index` of `robot` as the world stands now: an H x W x 3 uint8 "
           "array (rgb8 or bgr8 as the camera's format says; H x W for mono8; uint16 for 16-bit "
           "formats). Raises LoadError for a camera that cannot be rendered.")
      .def(
          "cast_rays",
          [](PySimulation& s, py::array_t<double, py::array::c_style | py::array::forcecast> starts,
             py::array_t<double, py::array::c_style | py::array::forcecast> ends,
             const std::string& ignored_robot) {
            auto points = [](const py::array_t<double, py::array::c_style>& a, const char* what) {
              if (a.ndim() != 2 || a.shape(1) != 3) {
                std::ostringstream msg;
                msg << "cast_rays: " << what << " must be an N x 3 array of points, got shape (";
                for (py::ssize_t i = 0; i < a.ndim(); ++i) msg << (i ? ", " : "") << a.shape(i);
                msg << ")";
                throw std::invalid_argument(msg.str());
              }
              std::vector<Eigen::Vector3d> out(static_cast<size_t>(a.shape(0)));
              const double* d = a.data();
              for (size_t i = 0; i < out.size(); ++i) out[i] = {d[3 * i], d[3 * i + 1], d[3 * i + 2]};
              return out;
            };
            std::vector<Eigen::Vector3d> a = points(starts, "starts");
            std::vector<Eigen::Vector3d> b = points(ends, "ends");
            std::vector<double> d =
                s.locked([&](Simulation& sim) { return sim.castRays(a, b, ignored_robot); });
            return ownedArray(std::move(d));
          },
          py::arg("starts"), py::arg("ends"), py::arg("ignored_robot") = "",
          "Distances (m) from each starts[i] to the first thing the segment starts[i] -> ends[i] "
          "hits (the world's static shapes and every robot where it is now, as the ray "
          "sensors see them); inf where it hits nothing. `starts`, `ends`: N x 3 arrays; the "
          "collisions of robot `ignored_robot` are passed through.")
      .def("take_warnings",
           [](PySimulation& s) {
             return s.locked([](Simulation& sim) { return sim.takeWarnings(); });
           },
           "What the simulation noticed since the last call, each message once.");
}
