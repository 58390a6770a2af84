#include "description/material/ogre_material.h"

#include <algorithm>
#include <charconv>

#include "bullet_sim/errors.h"
#include "description/material/ogre_script.h"

namespace bullet_sim {
namespace {

/// Reads the values of one statement, failing with the script's file and line.
class Values {
 public:
  Values(const OgreScriptNode& node, const std::string& source) : node_(node), source_(source) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw LoadError(ogreScriptError(source_, node_.line, node_.words[0] + ": " + what));
  }

  double number(std::size_t index) const {
    const std::string& text = node_.words[index];
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      fail("'" + text + "' is not a number");
    return value;
  }

  /// Needs between `least` and `most` values after the attribute's name.
  void expectCount(std::size_t least, std::size_t most, const std::string& what) const {
    const std::size_t count = node_.words.size() - 1;
    if (count < least || count > most) fail("expected " + what + ", got '" + text() + "'");
  }

  std::string text() const {
    std::string out;
    for (std::size_t i = 1; i < node_.words.size(); ++i) out += (i > 1 ? " " : "") + node_.words[i];
    return out;
  }

 private:
  const OgreScriptNode& node_;
  const std::string& source_;
};

std::optional<Eigen::Vector4f> colour(const OgreScriptNode& node, const std::string& source) {
  const Values values(node, source);
  if (node.words.size() == 2 && node.words[1] == "vertexcolour") return std::nullopt;
  values.expectCount(3, 4, "r g b [a] or vertexcolour");
  Eigen::Vector4f rgba(0, 0, 0, 1);
  for (std::size_t i = 1; i < node.words.size(); ++i)
    rgba[i - 1] = static_cast<float>(values.number(i));
  return rgba;
}

Eigen::Vector2d pair(const OgreScriptNode& node, const std::string& source) {
  const Values values(node, source);
  values.expectCount(2, 2, "two numbers");
  return {values.number(1), values.number(2)};
}

void readTextureUnit(const OgreScriptNode& unit, const std::string& source,
                     OgreTextureUnit* out) {
  for (const OgreScriptNode& node : unit.children) {
    if (node.is_block) continue;
    const std::string& key = node.words[0];
    if (key == "texture") {
      Values(node, source).expectCount(1, 100, "a file name");
      out->texture = node.words[1];
    } else if (key == "scale") {
      out->scale = pair(node, source);
    } else if (key == "scroll") {
      out->scroll = pair(node, source);
    }
  }
}

void readPass(const OgreScriptNode& pass, const std::string& source, OgreMaterial* material) {
  bool first_unit = true;
  for (const OgreScriptNode& node : pass.children) {
    const std::string& key = node.words[0];
    if (!node.is_block && key == "ambient") {
      material->ambient = colour(node, source);
    } else if (!node.is_block && key == "diffuse") {
      material->diffuse = colour(node, source);
    } else if (node.is_block && key == "texture_unit" && first_unit) {
      first_unit = false;
      OgreTextureUnit unit = material->texture_unit.value_or(OgreTextureUnit{});
      readTextureUnit(node, source, &unit);
      if (!unit.texture.empty()) material->texture_unit = unit;
    }
  }
}

/// The first child block of `parent` whose first word is `key`, or nullptr.
const OgreScriptNode* firstBlock(const OgreScriptNode& parent, const std::string& key) {
  const auto it = std::find_if(parent.children.begin(), parent.children.end(),
                               [&](const OgreScriptNode& n) { return n.is_block && n.words[0] == key; });
  return it == parent.children.end() ? nullptr : &*it;
}

OgreMaterial readMaterial(const OgreScriptNode& block, const std::string& source,
                          const std::vector<OgreMaterial>& earlier) {
  const std::vector<std::string>& header = block.words;
  const bool plain = header.size() == 2;
  const bool derived = header.size() == 4 && header[2] == ":";
  if (!plain && !derived)
    Values(block, source).fail("expected 'material NAME [: PARENT]', got 'material " +
                               Values(block, source).text() + "'");
  OgreMaterial material;
  if (derived) {
    const auto parent = std::find_if(earlier.begin(), earlier.end(),
                                     [&](const OgreMaterial& m) { return m.name == header[3]; });
    if (parent != earlier.end()) material = *parent;
  }
  material.name = header[1];
  material.script_path = source;
  if (const OgreScriptNode* technique = firstBlock(block, "technique"))
    if (const OgreScriptNode* pass = firstBlock(*technique, "pass"))
      readPass(*pass, source, &material);
  return material;
}

}  // namespace

std::vector<OgreMaterial> parseOgreMaterials(const std::string& text,
                                             const std::string& source_path) {
  std::vector<OgreMaterial> materials;
  for (const OgreScriptNode& node : parseOgreScript(text, source_path))
    if (node.is_block && node.words[0] == "material")
      materials.push_back(readMaterial(node, source_path, materials));
  return materials;
}

}  // namespace bullet_sim
