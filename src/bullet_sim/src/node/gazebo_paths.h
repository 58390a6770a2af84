// The model folders that ROS packages export to Gazebo.
#pragma once

namespace bullet_sim_node {

/// Starts collecting, on a thread of its own, the `gazebo_model_path` exports of the
/// packages that depend on gazebo_ros (`rospack plugins --attrib=gazebo_model_path
/// gazebo_ros`, as gazebo_ros's paths plugin collects them inside gzserver), and has the
/// simulator's `model://` lookups search them after GAZEBO_MODEL_PATH. The world loads
/// meanwhile; only a lookup that needs them waits.
void collectExportedModelPaths();

}  // namespace bullet_sim_node
