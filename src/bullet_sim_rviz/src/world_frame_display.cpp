#include "world_frame_display.h"

#include <geometry_msgs/TransformStamped.h>
#include <rviz/display_context.h>
#include <rviz/frame_manager.h>
#include <rviz/properties/status_property.h>
#include <rviz/properties/string_property.h>
#include <tf2/exceptions.h>

#include <pluginlib/class_list_macros.hpp>

namespace bullet_sim_rviz {

namespace {
/// The child of the given frame in the view's buffer (a transform needs two frames).
const char* const kViewFrame = "gzclient";
const char* const kAuthority = "bullet_sim_rviz/WorldFrame";
}  // namespace

WorldFrameDisplay::WorldFrameDisplay() {
  frame_property_ = new rviz::StringProperty(
      "Frame", "world", "The simulator's frame that this view gives itself, as Gazebo's "
      "window has it: its markers are stamped with it.", this, SLOT(giveFrame()));
}

void WorldFrameDisplay::onInitialize() { giveFrame(); }

void WorldFrameDisplay::onEnable() { giveFrame(); }

void WorldFrameDisplay::giveFrame() {
  if (!context_ || !isEnabled()) return;
  const std::string frame = frame_property_->getStdString();
  if (frame.empty() || frame == kViewFrame) {
    setStatusStd(rviz::StatusProperty::Error, "Frame",
                 "'" + frame + "' cannot be given: name the simulator's frame, e.g. world");
    return;
  }
  geometry_msgs::TransformStamped identity;
  identity.header.frame_id = frame;
  identity.child_frame_id = kViewFrame;
  identity.transform.rotation.w = 1.0;
  try {
    context_->getFrameManager()->getTF2BufferPtr()->setTransform(identity, kAuthority, true);
  } catch (const tf2::TransformException& e) {
    setStatusStd(rviz::StatusProperty::Error, "Frame", e.what());
    return;
  }
  setStatusStd(rviz::StatusProperty::Ok, "Frame",
               "[" + frame + "] exists in this view (static " + frame + " -> " + kViewFrame +
                   " in RViz's own tf buffer; nothing is published)");
}

}  // namespace bullet_sim_rviz

PLUGINLIB_EXPORT_CLASS(bullet_sim_rviz::WorldFrameDisplay, rviz::Display)
