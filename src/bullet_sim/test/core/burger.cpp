#include "burger.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace bullet_sim_test {

const std::string& burgerUrdf() {
  static const std::string urdf = [] {
    const std::string ws = BULLET_SIM_WORKSPACE;
    const std::string cmd = "ROS_PACKAGE_PATH=" + ws + " /usr/bin/python3 " + ws +
                            "/src/xacro/xacro " + ws +
                            "/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    if (!pipe) throw std::runtime_error("cannot run: " + cmd);
    std::string out;
    char buf[4096];
    size_t n = 0;
    while ((n = fread(buf, 1, sizeof(buf), pipe.get())) > 0) out.append(buf, n);
    if (out.find("<robot") == std::string::npos) throw std::runtime_error("xacro failed: " + cmd);
    return out;
  }();
  return urdf;
}

bullet_sim::RobotSpec burgerSpec() { return bullet_sim::parseRobot(burgerUrdf(), "burger"); }

bullet_sim::WorldSpec flatWorld() {
  return bullet_sim::loadWorldString(
      "<sdf version='1.6'><world name='flat'><model name='ground'><static>true</static>"
      "<link name='link'><collision name='c'><geometry><plane><normal>0 0 1</normal>"
      "<size>100 100</size></plane></geometry></collision></link></model></world></sdf>",
      "flat world");
}

std::string roundTrackPath() {
  return std::string(BULLET_SIM_WORKSPACE) + "/src/turtlebot3_gazebo/worlds/roundTrack.world";
}

double yawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
}

double turnFor(bullet_sim::Simulation* sim, const std::string& robot, double seconds) {
  constexpr double kStepS = 0.001;
  double heading = 0, last = yawOf(sim->modelPose(robot).orientation);
  const long steps = std::lround(seconds / kStepS);
  for (long i = 0; i < steps; ++i) {
    sim->step();
    const double now = yawOf(sim->modelPose(robot).orientation);
    heading += std::remainder(now - last, 2 * M_PI);
    last = now;
  }
  return heading;
}

}  // namespace bullet_sim_test
