#ifndef BULLET_SIM_RVIZ_PHYSICS_RATE_H
#define BULLET_SIM_RVIZ_PHYSICS_RATE_H

namespace bullet_sim_rviz {

/// Gazebo sets the pace with get/set_physics_properties' max_update_rate (steps per wall
/// second) and time_step (sim seconds per step): their product is the real-time factor,
/// and a rate of 0 means as fast as possible.

/// The max_update_rate that runs at `factor` times real time (0 = as fast as possible).
/// @throws std::invalid_argument naming the value unless factor >= 0 and time_step_s > 0
double maxUpdateRateFor(double factor, double time_step_s);

/// The real-time factor a max_update_rate gives (0 = as fast as possible).
/// @throws std::invalid_argument naming the value unless both are valid
double realTimeFactorOf(double max_update_rate_hz, double time_step_s);

}  // namespace bullet_sim_rviz

#endif  // BULLET_SIM_RVIZ_PHYSICS_RATE_H
