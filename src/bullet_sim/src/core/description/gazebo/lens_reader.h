#ifndef BULLET_SIM_CORE_LENS_READER_H
#define BULLET_SIM_CORE_LENS_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads the <lens> of a wide-angle camera's <camera> element (SDF's defaults where an
/// element, or the whole <lens>, is left out) and checks that it maps `horizontal_fov_rad`.
/// @throws LoadError naming `camera_where` + the lens element and its value.
LensSpec readLens(const tinyxml2::XMLElement* camera, double horizontal_fov_rad,
                  const XmlValues& xml, const std::string& camera_where);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_LENS_READER_H
