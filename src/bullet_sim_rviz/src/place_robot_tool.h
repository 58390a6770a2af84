// The Place robot tool: click and drag on the ground to put a robot there.
#pragma once

#ifndef Q_MOC_RUN
#include "sim_client.h"

#include <rviz/default_plugin/tools/pose_tool.h>
#endif

#include <memory>

namespace bullet_sim_rviz {

/// Like RViz's 2D Pose Estimate: press on the ground where the robot goes, drag towards
/// where it should face, release. The pose goes to /gazebo/set_model_state in frame world
/// for the robot chosen in the Simulation panel (or the only model there is). RViz's
/// PoseTool does the picking and draws the arrow; this class only sends the result.
class PlaceRobotTool : public rviz::PoseTool {
  Q_OBJECT
 public:
  PlaceRobotTool();
  void onInitialize() override;

 protected:
  void onPoseSet(double x, double y, double theta) override;

 private:
  void showResult(bool ok, const QString& text);

  std::shared_ptr<SimClient> client_;
};

}  // namespace bullet_sim_rviz
