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
/// checked 20 times a second: what Gazebo's window would show of them. A topic nobody
/// listens to is not checked (the checks are made on the stepping thread): a listener
/// that connects gets the latched array at once, and the current one within the check
/// period if anything moved meanwhile.
class WorldMarkersIo {
 public:
  /// Advertises `world_markers` and `model_markers` in `nh` (the node uses /gazebo) and
  /// publishes the world.
  WorldMarkersIo(const bullet_sim::Simulation& sim, const ros::NodeHandle& nh);
  WorldMarkersIo(const WorldMarkersIo&) = delete;
  WorldMarkersIo& operator=(const WorldMarkersIo&) = delete;

  /// Draws the movable model `name` (a robot of the simulation) with the world from now on.
  void track(const std::string& name) { world_.set.track(name); }
  void update();

 private:
  /// One latched MarkerArray topic and the set it shows.
  struct Topic {
    Topic(bullet_sim::WorldMarkerSet set, std::chrono::milliseconds period);
    void advertise(ros::NodeHandle& nh, const std::string& name);
    /// Publishes the set when it changed, checked every `period` while someone listens.
    void update(const bullet_sim::Simulation& sim, std::chrono::steady_clock::time_point now);
    void publish(const std::vector<bullet_sim::MarkerShape>& markers) const;

    bullet_sim::WorldMarkerSet set;
    const std::chrono::milliseconds period;
    ros::Publisher pub;
    std::chrono::steady_clock::time_point last_check;
  };

  const bullet_sim::Simulation& sim_;
  Topic world_, models_;
};

}  // namespace bullet_sim_node
