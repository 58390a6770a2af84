// The world's shapes for RViz: a latched visualization_msgs/MarkerArray on world_markers.
#pragma once

#include <bullet_sim/simulation.h>
#include <bullet_sim/render/world_marker_set.h>

#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <chrono>
#include <string>
#include <vector>

namespace bullet_sim_node {

/// Publishes the world's markers (bullet_sim::WorldMarkerSet) in frame "world", latched:
/// once at start, and again from update() when a tracked movable model has moved, checked
/// at most a few times a second of wall time. The spawned models (robots), which a
/// robot_state_publisher may draw instead, go to a topic of their own, `model_markers`,
/// checked 20 times a second: what Gazebo's window would show of them.
class WorldMarkersIo {
 public:
  /// Advertises `world_markers` and `model_markers` in `nh` (the node uses /gazebo) and
  /// publishes the world.
  WorldMarkersIo(const bullet_sim::Simulation& sim, const ros::NodeHandle& nh);

  /// Draws the movable model `name` (a robot of the simulation) with the world from now on.
  void track(const std::string& name) { markers_.track(name); }
  void update();

 private:
  static void publish(const ros::Publisher& pub,
                      const std::vector<bullet_sim::MarkerShape>& markers);

  const bullet_sim::Simulation& sim_;
  ros::Publisher pub_, model_pub_;
  bullet_sim::WorldMarkerSet markers_, model_markers_;
  std::chrono::steady_clock::time_point last_check_, last_model_check_;
};

}  // namespace bullet_sim_node
