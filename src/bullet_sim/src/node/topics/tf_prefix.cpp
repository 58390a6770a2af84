#include "topics/tf_prefix.h"

namespace bullet_sim_node {
namespace {

std::string withoutLeadingSlash(const std::string& name) {
  return !name.empty() && name[0] == '/' ? name.substr(1) : name;
}

}  // namespace

std::string resolveFrame(const std::string& prefix, const std::string& frame) {
  if (!frame.empty() && frame[0] == '/') return withoutLeadingSlash(frame);
  const std::string stripped = withoutLeadingSlash(prefix);
  return stripped.empty() ? frame : stripped + "/" + frame;
}

std::string findTfPrefix(const ros::NodeHandle& robot_nh) {
  std::string key, prefix;
  if (robot_nh.searchParam("tf_prefix", key)) robot_nh.getParam(key, prefix);
  return prefix;
}

}  // namespace bullet_sim_node
