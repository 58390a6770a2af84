#include "plugin_robots.h"

#include <cmath>
#include <sstream>

#include "burger.h"

namespace bullet_sim_test {
namespace {

std::string wheel(const std::string& name, double x, double y) {
  std::ostringstream s;
  s << "<joint name='" << name << "_joint' type='continuous'><parent link='base_link'/>"
    << "<child link='" << name << "_link'/><origin xyz='" << x << " " << y << " 0'/>"
    << "<axis xyz='0 1 0'/></joint>"
    << "<link name='" << name << "_link'>"
    << "<inertial><mass value='0.3'/>"
    << "<inertia ixx='0.0002275' ixy='0' ixz='0' iyy='0.000375' iyz='0' izz='0.0002275'/>"
    << "</inertial><collision><origin rpy='1.5707963267948966 0 0'/>"
    << "<geometry><cylinder radius='0.05' length='0.04'/></geometry></collision>"
    << "<visual><origin rpy='1.5707963267948966 0 0'/>"
    << "<geometry><cylinder radius='0.05' length='0.04'/></geometry></visual></link>";
  return s.str();
}

}  // namespace

std::string fourWheelerUrdf(const std::string& gazebo) {
  return "<?xml version='1.0'?><robot name='four_wheeler'>"
         "<link name='base_link'><inertial><origin xyz='0 0 0.03'/><mass value='4'/>"
         "<inertia ixx='0.03333' ixy='0' ixz='0' iyy='0.05667' iyz='0' izz='0.08333'/>"
         "</inertial><collision><origin xyz='0 0 0.03'/><geometry><box size='0.4 0.3 0.1'/>"
         "</geometry></collision><visual><origin xyz='0 0 0.03'/><geometry>"
         "<box size='0.4 0.3 0.1'/></geometry></visual></link>" +
         wheel("left_front", 0.12, 0.175) + wheel("right_front", 0.12, -0.175) +
         wheel("left_rear", -0.12, 0.175) + wheel("right_rear", -0.12, -0.175) + gazebo +
         "</robot>";
}

std::string boxUrdf(double mass_kg, const std::string& gazebo) {
  const double i = mass_kg * (0.04 + 0.04) / 12.0;  // a cube of side 0.2 m
  std::ostringstream s;
  s << "<?xml version='1.0'?><robot name='box'><link name='body'><inertial><mass value='"
    << mass_kg << "'/><inertia ixx='" << i << "' ixy='0' ixz='0' iyy='" << i
    << "' iyz='0' izz='" << i << "'/></inertial><collision><geometry>"
    << "<box size='0.2 0.2 0.2'/></geometry></collision></link>" << gazebo << "</robot>";
  return s.str();
}

std::string hangingLinkUrdf(const std::string& rpy, const std::string& com,
                            const std::string& gazebo) {
  return "<?xml version='1.0'?><robot name='pendulum'>"
         "<link name='base'><inertial><mass value='50'/>"
         "<inertia ixx='4.2083' ixy='0' ixz='0' iyy='4.2083' iyz='0' izz='8.3333'/>"
         "</inertial><collision><geometry><box size='1 1 0.1'/></geometry></collision>"
         "</link><joint name='hinge' type='continuous'><parent link='base'/>"
         "<child link='bob'/><origin xyz='0 0 1' rpy='" + rpy + "'/><axis xyz='1 0 0'/>"
         "</joint><link name='bob'><inertial><origin xyz='" + com + "'/><mass value='2'/>"
         "<inertia ixx='0.01' ixy='0' ixz='0' iyy='0.01' iyz='0' izz='0.01'/></inertial>"
         "</link>" + gazebo + "</robot>";
}

void runFor(bullet_sim::Simulation* sim, double seconds) {
  const long steps = std::lround(seconds / 0.001);
  for (long k = 0; k < steps; ++k) sim->step();
}

bullet_sim::WorldSpec flatWorldWithGravity(double gravity_z) {
  bullet_sim::WorldSpec world = flatWorld();
  world.gravity = Eigen::Vector3d(0, 0, gravity_z);
  return world;
}

}  // namespace bullet_sim_test
