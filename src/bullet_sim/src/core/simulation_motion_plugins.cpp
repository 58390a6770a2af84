// Simulation: gazebo_plugins' libgazebo_ros_planar_move.so (the model's planar velocity at
// every step, its odometry) and libgazebo_ros_joint_state_publisher.so (chosen joints).
#include "bullet_sim/simulation.h"

#include <cmath>
#include <stdexcept>

#include "bullet_sim/errors.h"
#include "description/robot_plan.h"
#include "simulation_impl.h"

namespace bullet_sim {
namespace {

const char* const kJointStatePlugin = "libgazebo_ros_joint_state_publisher.so";

double yawOf(const Eigen::Isometry3d& T) { return std::atan2(T.linear()(1, 0), T.linear()(0, 0)); }

}  // namespace

Eigen::Isometry3d Simulation::Impl::modelFrame(const Robot& r) {
  return r.physics->linkPose(r.physics->plan().bodies[0].root_link) *
         toIsometry(r.spec.root_link_in_model).inverse();
}

void Simulation::Impl::equipMotionPlugins(const std::string& name, Robot* r) {
  r->joint_state_plugin_joints.clear();
  for (const JointStatePublisherSpec& s : r->spec.joint_state_publishers) {
    std::vector<size_t> joints;
    for (const std::string& joint : s.joints) {
      const int index = r->physics->jointIndex(joint);
      if (index < 0) {
        throw LoadError("robot '" + name + "': " + kJointStatePlugin + " <jointName> names joint '" +
                        joint + "' that does not move here (only revolute and continuous "
                        "joints of a movable model do)");
      }
      joints.push_back(static_cast<size_t>(index));
    }
    r->joint_state_plugin_joints.push_back(std::move(joints));
  }
  r->planar_move.reset();
  if (r->spec.planar_move) {
    r->planar_move.emplace(r->spec.planar_move->cmd_timeout_s);
    r->planar_odometry.start(modelFrame(*r), timeAtStep(steps));
  }
}

void Simulation::Impl::resetMotionPlugins(Robot* r) const {
  if (!r->planar_move) return;
  r->planar_move->reset();
  r->planar_odometry.start(modelFrame(*r), 0.0);
}

void Simulation::Impl::planarMoveBeforeStep(Robot& r, uint64_t k) const {
  // Gazebo's SetLinearVel and SetAngularVel move no link of a static model.
  if (!r.planar_move || r.spec.is_static) return;
  r.planar_move->update(r.physics.get(), yawOf(modelFrame(r)), timeAtStep(k - 1));
}

void Simulation::setPlanarMoveCommand(const std::string& robot, double x_mps, double y_mps,
                                      double yaw_radps) {
  Impl::Robot& r = impl_->robot(robot);
  if (!r.planar_move) {
    throw std::out_of_range("robot '" + robot + "' has no libgazebo_ros_planar_move.so");
  }
  r.planar_move->setCommand(x_mps, y_mps, yaw_radps, timeS());
}

OdometryData Simulation::readPlanarMoveOdometry(const std::string& robot) {
  Impl::Robot& r = impl_->robot(robot);
  if (!r.planar_move) {
    throw std::out_of_range("robot '" + robot + "' has no libgazebo_ros_planar_move.so");
  }
  return r.planar_odometry.read(*r.spec.planar_move, Impl::modelFrame(r),
                                r.planar_move->yawRateRadps(), timeS());
}

JointStateData Simulation::readPluginJointStates(const std::string& robot, size_t index) const {
  const Impl::Robot& r = impl_->robot(robot);
  const std::vector<size_t>& joints = r.joint_state_plugin_joints.at(index);
  JointStateData js;
  js.time_s = timeS();
  for (const size_t j : joints) {
    js.names.push_back(r.physics->plan().joints[j].name);
    js.positions.push_back(r.physics->jointPosition(j));
    js.velocities.push_back(r.physics->jointVelocity(j));
  }
  return js;
}

}  // namespace bullet_sim
