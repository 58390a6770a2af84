// Simulation: the model plugins of gazebo_plugins that publish a wrench (f3d, ft_sensor).
#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "sensors/wrench_readings.h"
#include "simulation_impl.h"

namespace bullet_sim {

void Simulation::Impl::equipWrenchPlugins(const std::string& name, Robot* r) {
  for (const F3dSpec& s : r->spec.f3ds) {
    if (!r->physics->hasLink(s.body)) {
      throw LoadError("robot '" + name + "': libgazebo_ros_f3d.so <bodyName> names link '" +
                      s.body + "' that does not exist");
    }
  }
  r->ft_joints.clear();
  for (const FtSensorSpec& s : r->spec.ft_sensors) {
    const int joint = r->physics->jointIndex(s.joint);
    if (joint < 0) {
      throw LoadError("robot '" + name + "': libgazebo_ros_ft_sensor.so <jointName> names joint '" +
                      s.joint + "' that does not exist (or is not revolute/continuous: a fixed " +
                      "joint's links are one body, as Gazebo lumps them)");
    }
    r->ft_joints.push_back(static_cast<size_t>(joint));
  }
}

WrenchData Simulation::readF3d(const std::string& robot, size_t index) const {
  const Impl::Robot& r = impl_->robot(robot);
  const F3dSpec& spec = r.spec.f3ds.at(index);
  const Wrench applied = r.physics->appliedWrench(r.physics->bodyOfLink(spec.body));
  WrenchData reading;
  reading.time_s = timeS();
  reading.frame_id = spec.frame;
  reading.force_n = applied.force_n;
  reading.torque_nm = applied.torque_nm;
  return reading;
}

WrenchData Simulation::readForceTorque(const std::string& robot, size_t index) {
  Impl::Robot& r = impl_->robot(robot);
  const size_t joint = r.ft_joints.at(index);
  const PhysicsRobot& physics = *r.physics;
  const size_t child = physics.plan().joints[joint].child_body;
  const std::string& child_link = physics.plan().bodies[child].root_link;
  const Wrench on_child = physics.jointWrenchOnChild(joint);
  const WorldWrench at_com{on_child.force_n, on_child.torque_nm, physics.bodyCentreOfMass(child)};
  return bullet_sim::readForceTorque(r.spec.ft_sensors[index], at_com,
                                     physics.linkPose(child_link), child_link, timeS(),
                                     &r.ft_rngs.at(index));
}

}  // namespace bullet_sim
