// Values shared by the oracle's converters: ignition types to Eigen, where an element was
// read, libsdformat's errors as text, resolved poses, plugins from the element tree.
#include <tinyxml2.h>

#include "oracle_parts.h"

namespace bullet_sim_test {
namespace oracle {

Eigen::Isometry3d toIsometry(const ignition::math::Pose3d& pose) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(pose.Pos().X(), pose.Pos().Y(), pose.Pos().Z());
  const ignition::math::Quaterniond& q = pose.Rot();
  T.linear() = Eigen::Quaterniond(q.W(), q.X(), q.Y(), q.Z()).toRotationMatrix();
  return T;
}

Eigen::Vector3d toVector(const ignition::math::Vector3d& v) { return {v.X(), v.Y(), v.Z()}; }

Eigen::Vector4f toColour(const ignition::math::Color& c) { return {c.R(), c.G(), c.B(), c.A()}; }

bullet_sim::SdfOrigin originOf(const sdf::ElementPtr& element) {
  bullet_sim::SdfOrigin origin;
  if (!element) return origin;
  origin.file = element->FilePath();
  origin.line = element->LineNumber().value_or(0);
  return origin;
}

std::string formatError(const sdf::Error& error, const std::string& what) {
  std::string where = error.FilePath().value_or("");
  if (error.LineNumber()) where += ":" + std::to_string(*error.LineNumber());
  if (where.empty()) where = what;
  return (where.empty() ? "" : where + ": ") + error.Message();
}

void appendErrors(const sdf::Errors& errors, const std::string& what, Problems* problems) {
  for (const sdf::Error& e : errors) problems->push_back(formatError(e, what));
}

Eigen::Isometry3d resolvedPose(const sdf::SemanticPose& pose, const std::string& resolve_to,
                               const std::string& what, Problems* problems) {
  ignition::math::Pose3d resolved;
  const sdf::Errors errors = pose.Resolve(resolved, resolve_to);
  if (!errors.empty()) {
    appendErrors(errors, what + " pose", problems);
    return Eigen::Isometry3d::Identity();
  }
  return toIsometry(resolved);
}

bool hasChild(const sdf::ElementPtr& parent, const std::string& name) {
  return parent && parent->HasElement(name);
}

namespace {

/// `element` as XML, from libsdformat's tree: its attributes that are set, its value, its
/// children (a plugin's children are kept as libsdformat copied them).
void printElement(const sdf::ElementPtr& element, tinyxml2::XMLPrinter* out) {
  out->OpenElement(element->GetName().c_str());
  for (size_t i = 0; i < element->GetAttributeCount(); ++i) {
    const sdf::ParamPtr attribute = element->GetAttribute(static_cast<unsigned>(i));
    if (attribute->GetSet()) {
      out->PushAttribute(attribute->GetKey().c_str(), attribute->GetAsString().c_str());
    }
  }
  if (element->GetValue()) out->PushText(element->GetValue()->GetAsString().c_str());
  for (sdf::ElementPtr child = element->GetFirstElement(); child;
       child = child->GetNextElement()) {
    printElement(child, out);
  }
  out->CloseElement();
}

}  // namespace

std::vector<bullet_sim::SdfPlugin> pluginsOf(const sdf::ElementPtr& parent) {
  std::vector<bullet_sim::SdfPlugin> plugins;
  if (!hasChild(parent, "plugin")) return plugins;
  for (sdf::ElementPtr e = parent->GetElement("plugin"); e; e = e->GetNextElement("plugin")) {
    bullet_sim::SdfPlugin plugin;
    plugin.name = e->Get<std::string>("name");
    plugin.filename = e->Get<std::string>("filename");
    tinyxml2::XMLPrinter printer;
    printElement(e, &printer);
    plugin.xml = printer.CStr();
    plugins.push_back(plugin);
  }
  return plugins;
}

}  // namespace oracle
}  // namespace bullet_sim_test
