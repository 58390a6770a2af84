#include "place_robot_tool.h"

#include "bullet_sim_rviz/planar_pose.h"

#include <rviz/display_context.h>
#include <rviz/frame_manager.h>

#include <QApplication>
#include <QPointer>

#include <OgreQuaternion.h>
#include <OgreVector3.h>
#include <pluginlib/class_list_macros.hpp>

namespace bullet_sim_rviz {
namespace {

const char* const kWorldFrame = "world";

}  // namespace

PlaceRobotTool::PlaceRobotTool() : client_(SimClient::shared()) { shortcut_key_ = 'r'; }

void PlaceRobotTool::onInitialize() {
  rviz::PoseTool::onInitialize();
  setName("Place robot");
}

void PlaceRobotTool::onPoseSet(double x, double y, double theta) {
  const std::string model = client_->targetModel();
  if (model.empty()) {
    showResult(false, "Place robot: choose the robot in the Simulation panel");
    return;
  }
  const std::string fixed = context_->getFixedFrame().toStdString();
  Eigen::Isometry3d T_fixed_world = Eigen::Isometry3d::Identity();
  if (fixed != kWorldFrame) {
    Ogre::Vector3 p;
    Ogre::Quaternion q;
    if (!context_->getFrameManager()->getTransform(kWorldFrame, ros::Time(), p, q)) {
      showResult(false, QString("Place robot: no transform from %1 to world")
                            .arg(QString::fromStdString(fixed)));
      return;
    }
    T_fixed_world.translate(Eigen::Vector3d(p.x, p.y, p.z));
    T_fixed_world.rotate(Eigen::Quaterniond(q.w, q.x, q.y, q.z));
  }
  const PlanarPose pose = toWorld({x, y, theta}, T_fixed_world);
  QPointer<PlaceRobotTool> self(this);
  client_->place(model, pose.x_m, pose.y_m, pose.yaw_rad,
                 [self](bool ok, const std::string& text) {
                   const QString line = QString::fromStdString(text);
                   QMetaObject::invokeMethod(
                       qApp, [self, ok, line] { if (self) self->showResult(ok, line); },
                       Qt::QueuedConnection);
                 });
}

void PlaceRobotTool::showResult(bool ok, const QString& text) {
  setStatus(text);
  if (ok)
    ROS_INFO("%s", text.toStdString().c_str());
  else
    ROS_WARN("%s", text.toStdString().c_str());
}

}  // namespace bullet_sim_rviz

PLUGINLIB_EXPORT_CLASS(bullet_sim_rviz::PlaceRobotTool, rviz::Tool)
