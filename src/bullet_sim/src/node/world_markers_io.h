// The world's shapes for RViz: a latched visualization_msgs/MarkerArray on world_markers.
#pragma once

#include <bullet_sim/simulation.h>
#include <bullet_sim/world_markers.h>

#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <chrono>
#include <set>
#include <string>
#include <vector>

namespace bullet_sim_node {

/// Publishes every world shape as a marker in frame "world", latched, once at start. Movable
/// world models handed to track() are drawn at their current link poses; update() sends the
/// whole array again (a latched topic keeps only its last message) when one of them has moved,
/// checked at most a few times a second of wall time.
class WorldMarkersIo {
 public:
  /// Advertises `world_markers` in `nh` (the node uses /gazebo) and publishes the static shapes.
  WorldMarkersIo(const bullet_sim::Simulation& sim, const ros::NodeHandle& nh);

  /// Draws the movable model `name` (a robot of the simulation) with the world from now on.
  void track(const std::string& name);
  /// Republishes when a tracked model has moved or disappeared since the last message.
  void update();

 private:
  std::vector<bullet_sim::MarkerShape> trackedMarkers() const;
  void publish(const std::vector<bullet_sim::MarkerShape>& moving);

  const bullet_sim::Simulation& sim_;
  ros::Publisher pub_;
  const std::vector<bullet_sim::MarkerShape> static_markers_;
  std::set<std::string> tracked_;
  bullet_sim::MarkerChanges changes_;
  std::chrono::steady_clock::time_point last_check_;
};

}  // namespace bullet_sim_node
