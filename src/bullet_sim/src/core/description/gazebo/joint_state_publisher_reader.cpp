#include "description/gazebo/joint_state_publisher_reader.h"

#include <algorithm>
#include <cctype>

#include "description/gazebo/gazebo_values.h"

namespace bullet_sim {
namespace {

/// The names of a <jointName> list: white space dropped, split at each comma.
std::vector<std::string> splitJointNames(std::string text) {
  text.erase(std::remove_if(text.begin(), text.end(),
                            [](unsigned char c) { return std::isspace(c) != 0; }),
             text.end());
  // As boost::split: "" is one empty name, "a,b," ends with one.
  std::vector<std::string> names(1);
  for (const char c : text) {
    if (c == ',') {
      names.emplace_back();
    } else {
      names.back() += c;
    }
  }
  return names;
}

}  // namespace

void readJointStatePublisherPlugin(const tinyxml2::XMLElement* p, const std::string& where,
                                   const XmlValues& xml, RobotSpec* spec) {
  JointStatePublisherSpec s;
  s.update_rate_hz = readRate(xml, p, "updateRate", s.update_rate_hz, where);
  if (!p->FirstChildElement("jointName")) {
    spec->warnings.push_back(where + ": no <jointName>: as in Gazebo, joint_states carries "
                             "no joints");
  } else {
    const std::string text = xml.text(p, "jointName", "");
    s.joints = splitJointNames(text);
    for (const std::string& joint : s.joints) {
      if (joint.empty()) xml.fail(where + " <jointName>", "'" + text + "' has an empty name");
      if (!spec->urdf || !spec->urdf->getJoint(joint)) {
        // Gazebo logs FATAL and crashes at its first update on the missing joint.
        xml.fail(where + " <jointName>", "the model has no joint '" + joint + "'");
      }
    }
  }
  spec->joint_state_publishers.push_back(s);
}

}  // namespace bullet_sim
