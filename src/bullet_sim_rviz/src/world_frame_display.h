// The World frame display: the simulator's `world` frame in the view, with or without TF.
#pragma once

#ifndef Q_MOC_RUN
#include <rviz/display.h>
#endif

namespace rviz {
class StringProperty;
}

namespace bullet_sim_rviz {

/// Gazebo's window draws the world and every model at the simulator's pose, without TF, so
/// it always has its world frame. RViz, in its place, needs the fixed frame in TF, and on
/// launches without a robot_state_publisher or a `world` -> `odom` (the TurtleBot3
/// simulations) nothing publishes `world`: RViz shows "Fixed Frame [world] does not
/// exist" though the simulator's markers, stamped `world`, are drawn. This display adds
/// the static transform `world` -> `gzclient` (identity) to this view's own tf buffer:
/// `world` exists for this RViz only, nothing is published, and a `world` that TF has too
/// (a parent `map`, children `odom`) keeps its links.
class WorldFrameDisplay : public rviz::Display {
  Q_OBJECT
 public:
  WorldFrameDisplay();

 protected:
  void onInitialize() override;
  void onEnable() override;

 private Q_SLOTS:
  void giveFrame();

 private:
  rviz::StringProperty* frame_property_;
};

}  // namespace bullet_sim_rviz
