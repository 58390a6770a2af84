// Simulation: the model plugins of gazebo_plugins that read or push one link (p3d, force).
#include "bullet_sim/simulation.h"

#include "bullet_sim/errors.h"
#include "sensors/ground_truth.h"
#include "simulation_impl.h"

namespace bullet_sim {
namespace {

bool isWorldFrame(const std::string& frame) {
  return frame == "world" || frame == "/world" || frame == "map" || frame == "/map";
}

void requirePluginLink(const PhysicsRobot& robot, const std::string& robot_name,
                       const std::string& plugin, const std::string& tag,
                       const std::string& link) {
  if (!robot.hasLink(link)) {
    throw LoadError("robot '" + robot_name + "': " + plugin + " <" + tag + "> names link '" +
                    link + "' that does not exist");
  }
}

LinkMotion motion(const PhysicsRobot& robot, const std::string& link) {
  return {robot.linkPose(link), robot.linkTwist(link)};
}

}  // namespace

void Simulation::Impl::equipModelPlugins(const std::string& name, Robot* r) {
  for (const P3dSpec& s : r->spec.p3ds) {
    requirePluginLink(*r->physics, name, "libgazebo_ros_p3d.so", "bodyName", s.body);
    if (!isWorldFrame(s.frame)) {
      requirePluginLink(*r->physics, name, "libgazebo_ros_p3d.so", "frameName", s.frame);
    }
  }
  for (const ForceSpec& s : r->spec.forces) {
    requirePluginLink(*r->physics, name, "libgazebo_ros_force.so", "bodyName", s.body);
  }
  r->plugin_wrenches.assign(r->spec.forces.size(), Wrench());
}

OdometryData Simulation::readGroundTruth(const std::string& robot, size_t index) {
  Impl::Robot& r = impl_->robot(robot);
  const P3dSpec& spec = r.spec.p3ds.at(index);
  const LinkMotion body = motion(*r.physics, spec.body);
  if (isWorldFrame(spec.frame)) {
    return bullet_sim::readGroundTruth(spec, body, nullptr, timeS(), &r.p3d_rngs[index]);
  }
  const LinkMotion frame = motion(*r.physics, spec.frame);
  return bullet_sim::readGroundTruth(spec, body, &frame, timeS(), &r.p3d_rngs[index]);
}

void Simulation::setPluginWrench(const std::string& robot, size_t index, const Wrench& wrench) {
  impl_->robot(robot).plugin_wrenches.at(index) = wrench;
}

}  // namespace bullet_sim
