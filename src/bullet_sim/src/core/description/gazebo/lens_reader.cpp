#include "description/gazebo/lens_reader.h"

#include <cmath>
#include <stdexcept>

#include "description/gazebo/camera_lens.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// A number of `parent`'s child `name` that must satisfy `ok`, else a LoadError saying `rule`.
template <typename Ok>
double checked(const XMLElement* parent, const char* name, double fallback, Ok ok,
               const std::string& rule, const XmlValues& xml, const std::string& where) {
  const double v = xml.number(parent, name, fallback, where);
  if (!ok(v)) {
    xml.fail(where + " <" + name + ">", "'" + xml.text(parent, name, "") + "' " + rule);
  }
  return v;
}

void readCustomFunction(const XMLElement* lens, const XmlValues& xml, const std::string& where,
                        LensSpec* spec) {
  const XMLElement* custom = lens->FirstChildElement("custom_function");
  if (!custom) return;  // SDF's defaults: c1 = c2 = f = 1, c3 = 0, tan
  const std::string cw = where + " <custom_function>";
  const auto non_zero = [](double v) { return std::isfinite(v) && v != 0; };
  const std::string rule = "must be finite and not 0";
  spec->c1 = checked(custom, "c1", spec->c1, non_zero, rule, xml, cw);
  spec->c2 = checked(custom, "c2", spec->c2, non_zero, rule, xml, cw);
  spec->f = checked(custom, "f", spec->f, non_zero, rule, xml, cw);
  spec->c3 = checked(custom, "c3", spec->c3, [](double v) { return std::isfinite(v); },
                     "is not finite", xml, cw);
  spec->fun = xml.text(custom, "fun", spec->fun);
  if (spec->fun != "sin" && spec->fun != "tan" && spec->fun != "id") {
    xml.fail(cw + " <fun>", "'" + spec->fun + "' is not sin, tan or id");
  }
}

}  // namespace

LensSpec readLens(const XMLElement* camera, double horizontal_fov_rad, const XmlValues& xml,
                  const std::string& camera_where) {
  LensSpec spec;
  const XMLElement* lens = camera->FirstChildElement("lens");
  const std::string where = camera_where + " <lens>";
  if (lens) {
    spec.type = xml.text(lens, "type", spec.type);
    if (spec.type == "custom") readCustomFunction(lens, xml, where, &spec);
    spec.scale_to_hfov = xml.boolean(lens, "scale_to_hfov", spec.scale_to_hfov, where);
    spec.cutoff_angle_rad = checked(
        lens, "cutoff_angle", spec.cutoff_angle_rad, [](double v) { return v > 0 && v <= M_PI; },
        "must be in (0, pi] radians", xml, where);
    spec.env_texture_size = static_cast<int>(checked(
        lens, "env_texture_size", spec.env_texture_size,
        [](double v) { return v >= 4 && v <= 2048 && v == std::floor(v); },
        "is not a pixel count in 4..2048", xml, where));
  }
  try {
    CameraLens(spec, horizontal_fov_rad);
  } catch (const std::invalid_argument& e) {
    xml.fail(where, e.what());
  }
  return spec;
}

}  // namespace bullet_sim
