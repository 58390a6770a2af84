#include "description/material/gazebo_materials.h"

#include <map>

namespace bullet_sim {
namespace {

/// Diffuse colours of the materials in Gazebo Classic's media/materials/scripts/
/// gazebo.material. Those defined by a texture (Wood, WoodFloor, WoodPallet, Bricks,
/// PaintedWall, CeilingTiled) have a white or no diffuse there: for them the table holds
/// an estimate of the texture's mean colour, since the renderer draws flat colours.
/// The Glow variants share their base colour (emission is not rendered).
const std::map<std::string, Eigen::Vector4f>& table() {
  static const std::map<std::string, Eigen::Vector4f> colours = {
      {"Gazebo/Grey", {0.7f, 0.7f, 0.7f, 1.0f}},
      {"Gazebo/DarkGrey", {0.175f, 0.175f, 0.175f, 1.0f}},
      {"Gazebo/White", {1.0f, 1.0f, 1.0f, 1.0f}},
      {"Gazebo/FlatBlack", {0.1f, 0.1f, 0.1f, 1.0f}},
      {"Gazebo/Black", {0.0f, 0.0f, 0.0f, 1.0f}},
      {"Gazebo/Red", {1.0f, 0.0f, 0.0f, 1.0f}},
      {"Gazebo/RedBright", {0.87f, 0.26f, 0.07f, 1.0f}},
      {"Gazebo/Green", {0.0f, 1.0f, 0.0f, 1.0f}},
      {"Gazebo/Blue", {0.0f, 0.0f, 1.0f, 1.0f}},
      {"Gazebo/SkyBlue", {0.0f, 0.0f, 1.0f, 1.0f}},
      {"Gazebo/Yellow", {1.0f, 1.0f, 0.0f, 1.0f}},
      {"Gazebo/ZincYellow", {0.9725f, 0.9529f, 0.2078f, 1.0f}},
      {"Gazebo/Purple", {1.0f, 0.0f, 1.0f, 1.0f}},
      {"Gazebo/Turquoise", {0.0f, 1.0f, 1.0f, 1.0f}},
      {"Gazebo/Orange", {1.0f, 0.5088f, 0.0468f, 1.0f}},
      {"Gazebo/Gold", {0.8f, 0.64869f, 0.120759f, 1.0f}},
      {"Gazebo/Pioneer2Body", {0.681193f, 0.000923f, 0.000923f, 1.0f}},
      {"Gazebo/WhiteGlow", {1.0f, 1.0f, 1.0f, 1.0f}},
      {"Gazebo/RedGlow", {1.0f, 0.0f, 0.0f, 1.0f}},
      {"Gazebo/GreenGlow", {0.0f, 1.0f, 0.0f, 1.0f}},
      {"Gazebo/BlueGlow", {0.0f, 0.0f, 1.0f, 1.0f}},
      {"Gazebo/YellowGlow", {1.0f, 1.0f, 0.0f, 1.0f}},
      {"Gazebo/PurpleGlow", {1.0f, 0.0f, 1.0f, 1.0f}},
      {"Gazebo/TurquoiseGlow", {0.0f, 1.0f, 1.0f, 1.0f}},
      {"Gazebo/GreenTransparent", {0.0f, 1.0f, 0.0f, 0.5f}},
      {"Gazebo/BlueTransparent", {0.0f, 0.0f, 1.0f, 0.5f}},
      {"Gazebo/GreyTransparent", {0.5f, 0.5f, 0.5f, 0.5f}},
      {"Gazebo/YellowTransparent", {1.0f, 1.0f, 0.0f, 0.5f}},
      {"Gazebo/OrangeTransparent", {1.0f, 0.44f, 0.0f, 0.4f}},
      {"Gazebo/Road", {0.8f, 0.8f, 0.8f, 1.0f}},
      // Textured: estimated mean colours of the textures.
      {"Gazebo/Wood", {0.66f, 0.47f, 0.30f, 1.0f}},
      {"Gazebo/WoodFloor", {0.55f, 0.38f, 0.22f, 1.0f}},
      {"Gazebo/WoodPallet", {0.72f, 0.58f, 0.42f, 1.0f}},
      {"Gazebo/Bricks", {0.60f, 0.32f, 0.24f, 1.0f}},
      {"Gazebo/PaintedWall", {0.90f, 0.88f, 0.82f, 1.0f}},
      {"Gazebo/CeilingTiled", {0.85f, 0.85f, 0.83f, 1.0f}},
  };
  return colours;
}

}  // namespace

std::optional<Eigen::Vector4f> gazeboMaterialColour(const std::string& script_name) {
  const auto it = table().find(script_name);
  if (it == table().end()) return std::nullopt;
  return it->second;
}

Eigen::Vector4f unknownMaterialColour() { return table().at("Gazebo/Grey"); }

}  // namespace bullet_sim
