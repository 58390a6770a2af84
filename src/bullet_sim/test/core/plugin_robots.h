#ifndef BULLET_SIM_TEST_PLUGIN_ROBOTS_H
#define BULLET_SIM_TEST_PLUGIN_ROBOTS_H

// Robots written for the model-plugin tests, with figures simple enough to work out by
// hand what each plugin should give.

#include <string>

#include "bullet_sim/simulation.h"

namespace bullet_sim_test {

/// A four-wheeler: chassis `base_link` a box 0.4 x 0.3 x 0.1 m, 4 kg, its centre 0.03 m
/// above base_link; four wheels (cylinders r 0.05 m, 0.04 m wide, 0.3 kg) on continuous
/// joints about y, left_front_joint / right_front_joint / left_rear_joint /
/// right_rear_joint at x +-0.12, y +-0.175, z 0 (base_link at axle height: spawn it at
/// z 0.05). Total mass 5.2 kg. `gazebo` is put inside <robot> after the links.
std::string fourWheelerUrdf(const std::string& gazebo);

/// A box `body` 0.2 x 0.2 x 0.2 m of `mass_kg`, its centre at the link origin, as the
/// only link; `gazebo` is put inside <robot> after it.
std::string boxUrdf(double mass_kg, const std::string& gazebo);

/// A stand and a pendulum, for the wrench plugins: `base` a slab 1 x 1 x 0.1 m of 50 kg
/// lying on the ground (spawn it at z 0.05), and `bob` (2 kg, no collision, inertia 0.01
/// kg m^2 about each axis) hanging from continuous joint `hinge` about x, whose origin is
/// 1 m above base's and turned by `rpy` ("r p y"); bob's centre of mass at `com` ("x y z")
/// in its frame. `gazebo` is put inside <robot> after them.
std::string hangingLinkUrdf(const std::string& rpy, const std::string& com,
                            const std::string& gazebo);

/// Steps `sim` for `seconds` of 1 ms steps.
void runFor(bullet_sim::Simulation* sim, double seconds);

/// A flat world (ground plane) with gravity `gravity_z` along z.
bullet_sim::WorldSpec flatWorldWithGravity(double gravity_z);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_PLUGIN_ROBOTS_H
