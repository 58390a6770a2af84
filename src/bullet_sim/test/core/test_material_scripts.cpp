// OGRE material scripts as Gazebo Classic reads them: the parser (values, inheritance,
// skipped blocks, syntax errors) and the lookup of a named material and its texture through
// the <uri> paths and GAZEBO_RESOURCE_PATH, on scripts the tests write in a temp dir.
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "description/material/material_scripts.h"
#include "description/material/ogre_material.h"
#include "load_errors.h"
#include "temp_dir.h"

using bullet_sim::findScriptMaterial;
using bullet_sim::OgreMaterial;
using bullet_sim::parseOgreMaterials;
using bullet_sim_test::loadErrorOf;
using bullet_sim_test::TempDir;

namespace {

// Two materials (the second derived from the first), comments of both kinds, a program
// block, an import line, a second technique and pass, a second texture unit.
const char* kFullScript = R"(// a line comment
import * from "other.material"
vertex_program shiny_vp glsl
{
  source shiny.vert
}

/* a block comment
   over two lines { with a brace */
material base_paint
{
  receive_shadows on
  technique first
  {
    pass one
    {
      ambient 0.1 0.2 0.3
      diffuse 0.4 0.5 0.6 0.7   // trailing comment
      specular 1 1 1 1 12.5
      vertex_program_ref shiny_vp
      {
        param_named_auto worldViewProj worldviewproj_matrix
      }
      texture_unit
      {
        texture paint.png 2d
        scale 0.5 0.25
        scroll 0.1 -0.2
        filtering anisotropic
      }
      texture_unit detail
      {
        texture detail.png
      }
    }
    pass two
    {
      diffuse 0 0 0 1
    }
  }
  technique fallback
  {
    pass
    {
      ambient 1 1 1
    }
  }
}

material "road/lines" : base_paint
{
  technique
  {
    pass
    {
      diffuse vertexcolour
      texture_unit
      {
        texture lines.png
      }
    }
  }
}

material plain_red
{ technique { pass { diffuse 1 0 0 } } }
)";

std::vector<OgreMaterial> parse(const std::string& text) {
  return parseOgreMaterials(text, "/s/x.material");
}

void expectVector(const Eigen::VectorXf& actual, const Eigen::VectorXf& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (int i = 0; i < actual.size(); ++i) EXPECT_FLOAT_EQ(actual[i], expected[i]) << "index " << i;
}

/// Writes a script at `script_relative` defining material `name` as one texture unit
/// naming `texture` (the form of the autorace scripts); returns its path.
std::string writeMaterial(const TempDir& dir, const std::string& script_relative,
                          const std::string& name, const std::string& texture) {
  return dir.write(script_relative, "material " + name +
                                        "\n{\n  technique\n  {\n    pass\n    {\n"
                                        "      texture_unit\n      {\n        texture " +
                                        texture + "\n      }\n    }\n  }\n}\n");
}

}  // namespace

TEST(OgreMaterial, FullScriptKeepsTheFirstPassOfTheFirstTechnique) {
  const std::vector<OgreMaterial> materials = parse(kFullScript);
  ASSERT_EQ(materials.size(), 3u);

  const OgreMaterial& base = materials[0];
  EXPECT_EQ(base.name, "base_paint");
  EXPECT_EQ(base.script_path, "/s/x.material");
  ASSERT_TRUE(base.ambient && base.diffuse && base.texture_unit);
  expectVector(*base.ambient, Eigen::Vector4f(0.1f, 0.2f, 0.3f, 1.0f));
  expectVector(*base.diffuse, Eigen::Vector4f(0.4f, 0.5f, 0.6f, 0.7f));
  EXPECT_EQ(base.texture_unit->texture, "paint.png");
  EXPECT_EQ(base.texture_unit->scale, Eigen::Vector2d(0.5, 0.25));
  EXPECT_EQ(base.texture_unit->scroll, Eigen::Vector2d(0.1, -0.2));

  // Inherits the ambient and the unit's scale and scroll; its own texture; vertexcolour
  // diffuse is no diffuse.
  const OgreMaterial& lines = materials[1];
  EXPECT_EQ(lines.name, "road/lines");
  ASSERT_TRUE(lines.ambient && lines.texture_unit);
  EXPECT_FALSE(lines.diffuse);
  expectVector(*lines.ambient, Eigen::Vector4f(0.1f, 0.2f, 0.3f, 1.0f));
  EXPECT_EQ(lines.texture_unit->texture, "lines.png");
  EXPECT_EQ(lines.texture_unit->scale, Eigen::Vector2d(0.5, 0.25));
  EXPECT_EQ(lines.texture_unit->scroll, Eigen::Vector2d(0.1, -0.2));

  const OgreMaterial& red = materials[2];
  EXPECT_EQ(red.name, "plain_red");
  EXPECT_FALSE(red.ambient);
  EXPECT_FALSE(red.texture_unit);
  ASSERT_TRUE(red.diffuse);
  expectVector(*red.diffuse, Eigen::Vector4f(1, 0, 0, 1));
}

TEST(OgreMaterial, TextureUnitDefaultsAndUnknownParent) {
  const std::vector<OgreMaterial> materials = parse(
      "material a : not_here\n{\n technique\n {\n  pass\n  {\n   texture_unit\n   {\n"
      "    texture a.png\n   }\n  }\n }\n}\n"
      "material b\n{\n technique\n {\n  pass\n  {\n   texture_unit\n   {\n"
      "    colour_op replace\n   }\n  }\n }\n}\n");
  ASSERT_EQ(materials.size(), 2u);
  ASSERT_TRUE(materials[0].texture_unit);
  EXPECT_EQ(materials[0].texture_unit->scale, Eigen::Vector2d(1, 1));
  EXPECT_EQ(materials[0].texture_unit->scroll, Eigen::Vector2d(0, 0));
  EXPECT_FALSE(materials[0].diffuse);
  EXPECT_FALSE(materials[1].texture_unit);  // a unit without a texture file
}

TEST(OgreMaterial, AbstractMaterialsAreSkipped) {
  const std::vector<OgreMaterial> materials =
      parse("abstract material template\n{\n technique\n {\n  pass\n  {\n   diffuse 1 1 1\n"
            "  }\n }\n}\nmaterial real\n{\n}\n");
  ASSERT_EQ(materials.size(), 1u);
  EXPECT_EQ(materials[0].name, "real");
}

TEST(OgreMaterial, SyntaxErrorsNameFileLineAndText) {
  const auto error = [](const std::string& text) { return loadErrorOf([&] { parse(text); }); };
  EXPECT_EQ(error("material a\n{\n  technique\n  {\n  }\n"),
            "/s/x.material:1: 'material a {' is never closed");
  EXPECT_EQ(error("material a\n{\n}\n}\n"), "/s/x.material:4: '}' closes no block");
  EXPECT_EQ(error("material a\n{\n technique\n {\n  pass\n  {\n   diffuse 1 O.5 0\n  }\n }\n}\n"),
            "/s/x.material:7: diffuse: 'O.5' is not a number");
  EXPECT_EQ(error("material a { technique { pass { ambient 1 1 } } }"),
            "/s/x.material:1: ambient: expected r g b [a] or vertexcolour, got '1 1'");
  EXPECT_EQ(error("material a {\n technique {\n pass {\n texture_unit {\n scale 2 x2\n } } } }"),
            "/s/x.material:5: scale: 'x2' is not a number");
  EXPECT_EQ(error("material a {\n technique {\n pass {\n texture_unit {\n scroll 1\n } } } }"),
            "/s/x.material:5: scroll: expected two numbers, got '1'");
  EXPECT_EQ(error("material a {\n technique {\n pass {\n texture_unit {\n texture\n } } } }"),
            "/s/x.material:5: texture: expected a file name, got ''");
  EXPECT_EQ(error("material a b\n{\n}\n"),
            "/s/x.material:1: material: expected 'material NAME [: PARENT]', got 'material a b'");
  EXPECT_EQ(error("\n\n{\n}\n"), "/s/x.material:3: '{' without a block name");
  EXPECT_EQ(error("material a\n/* open\n\n{\n}\n"), "/s/x.material:2: '/*' comment is never closed");
  EXPECT_EQ(error("material \"a\n{\n}\n"), "/s/x.material:1: quote is never closed: '\"a'");
}

TEST(MaterialScripts, AutoraceLayoutScriptsAndTexturesFolders) {
  TempDir dir;
  writeMaterial(dir, "course/materials/scripts/course.material", "course", "course.png");
  const std::string png = dir.write("course/materials/textures/course.png", "png");
  const std::string scripts = dir.sub("course/materials/scripts");
  const std::string textures = dir.sub("course/materials/textures");
  std::vector<std::string> warnings;
  const auto found = findScriptMaterial("course", {scripts, textures}, {}, &warnings);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->material.name, "course");
  EXPECT_EQ(found->material.script_path, scripts + "/course.material");
  EXPECT_EQ(found->texture_path, png);
  EXPECT_TRUE(warnings.empty());
}

TEST(MaterialScripts, TextureInTheUriFolderWinsOverTheSiblingTexturesFolder) {
  TempDir dir;
  writeMaterial(dir, "m/scripts/a.material", "a", "a.png");
  dir.write("m/textures/a.png", "sibling");
  const std::string in_uri = dir.write("elsewhere/a.png", "uri");
  const auto found =
      findScriptMaterial("a", {dir.sub("m/scripts"), dir.sub("elsewhere")}, {}, nullptr);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->texture_path, in_uri);
}

TEST(MaterialScripts, TextureBesideTheScriptFoundThroughAFileUri) {
  TempDir dir;
  const std::string script = writeMaterial(dir, "flat/a.material", "a", "a.png");
  const std::string png = dir.write("flat/a.png", "png");
  const auto found = findScriptMaterial("a", {script}, {}, nullptr);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->material.script_path, script);
  EXPECT_EQ(found->texture_path, png);
}

TEST(MaterialScripts, TextureInTheScriptsSiblingTexturesFolder) {
  TempDir dir;
  writeMaterial(dir, "m/materials/scripts/a.material", "a", "a.png");
  const std::string png = dir.write("m/materials/textures/a.png", "png");
  const auto found = findScriptMaterial("a", {dir.sub("m/materials/scripts")}, {}, nullptr);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->texture_path, png);
}

TEST(MaterialScripts, ScriptAndTextureFromGazeboResourcePath) {
  TempDir dir;
  writeMaterial(dir, "gazebo/media/materials/scripts/stock.material", "Stock/Tiles", "tiles.jpg");
  const std::string jpg = dir.write("other/media/materials/textures/tiles.jpg", "jpg");
  const auto found =
      findScriptMaterial("Stock/Tiles", {}, {dir.sub("none"), dir.sub("gazebo"), dir.sub("other")},
                         nullptr);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->material.script_path, dir.sub("gazebo/media/materials/scripts/stock.material"));
  EXPECT_EQ(found->texture_path, jpg);
}

TEST(MaterialScripts, ResourcePathEntryItselfHoldsScriptAndTexture) {
  TempDir dir;
  writeMaterial(dir, "res/a.material", "a", "a.png");
  const std::string png = dir.write("res/a.png", "png");
  const auto found = findScriptMaterial("a", {}, {dir.sub("res")}, nullptr);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->texture_path, png);
}

TEST(MaterialScripts, UriScriptsComeBeforeResourcePathScripts) {
  TempDir dir;
  writeMaterial(dir, "res/media/materials/scripts/a.material", "a", "from_resource.png");
  writeMaterial(dir, "uri/b.material", "a", "from_uri.png");
  const auto found = findScriptMaterial("a", {dir.sub("uri")}, {dir.sub("res")}, nullptr);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->material.texture_unit->texture, "from_uri.png");
}

TEST(MaterialScripts, MissingTextureWarnsOnceAndLeavesThePathEmpty) {
  TempDir dir;
  const std::string script = writeMaterial(dir, "m/scripts/a.material", "lane", "lane.png");
  std::vector<std::string> warnings;
  const auto found = findScriptMaterial("lane", {dir.sub("m/scripts")}, {}, &warnings);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->texture_path, "");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'lane.png'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("material 'lane'"), std::string::npos) << warnings[0];
  EXPECT_EQ(warnings[0].rfind(script + ":", 0), 0u) << warnings[0];
}

TEST(MaterialScripts, ColourOnlyMaterialHasNoTexturePathAndNoWarning) {
  TempDir dir;
  dir.write("s/c.material", "material c { technique { pass { diffuse 0 1 0 } } }\n");
  std::vector<std::string> warnings;
  const auto found = findScriptMaterial("c", {dir.sub("s")}, {}, &warnings);
  ASSERT_TRUE(found && found->material.diffuse);
  EXPECT_EQ(*found->material.diffuse, Eigen::Vector4f(0, 1, 0, 1));
  EXPECT_EQ(found->texture_path, "");
  EXPECT_TRUE(warnings.empty());
}

TEST(MaterialScripts, UnknownNameGivesNothing) {
  TempDir dir;
  writeMaterial(dir, "s/a.material", "a", "a.png");
  std::vector<std::string> warnings;
  EXPECT_FALSE(findScriptMaterial("b", {dir.sub("s")}, {dir.sub("s")}, &warnings));
  EXPECT_FALSE(findScriptMaterial("a", {dir.sub("missing")}, {}, &warnings));
  EXPECT_TRUE(warnings.empty());
}

TEST(MaterialScripts, BrokenScriptIsALoadErrorNamingIt) {
  TempDir dir;
  const std::string script = dir.write("s/bad.material", "material a\n{\n");
  EXPECT_EQ(loadErrorOf([&] { findScriptMaterial("a", {dir.sub("s")}, {}, nullptr); }),
            script + ":1: 'material a {' is never closed");
}

TEST(MaterialScripts, AChangedScriptIsReadAgain) {
  TempDir dir;
  writeMaterial(dir, "s/a.material", "a", "first.png");
  ASSERT_EQ(findScriptMaterial("a", {dir.sub("s")}, {}, nullptr)->material.texture_unit->texture,
            "first.png");
  writeMaterial(dir, "s/a.material", "a", "second_one.png");
  EXPECT_EQ(findScriptMaterial("a", {dir.sub("s")}, {}, nullptr)->material.texture_unit->texture,
            "second_one.png");
}

TEST(MaterialScripts, LookupsFromSeveralThreadsAgree) {
  TempDir dir;
  for (int i = 0; i < 20; ++i)
    writeMaterial(dir, "s/m" + std::to_string(i) + ".material", "m" + std::to_string(i),
                  "t" + std::to_string(i) + ".png");
  std::vector<std::thread> threads;
  std::vector<int> found(4, 0);
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 20; ++i) {
        const auto m = findScriptMaterial("m" + std::to_string(i), {dir.sub("s")}, {}, nullptr);
        found[t] += m && m->material.texture_unit->texture == "t" + std::to_string(i) + ".png";
      }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(found, std::vector<int>(4, 20));
}

TEST(MaterialScripts, GazeboResourcePathSkipsEmptyEntries) {
  setenv("GAZEBO_RESOURCE_PATH", ":/a::/b/c:", 1);
  EXPECT_EQ(bullet_sim::gazeboResourcePaths(), (std::vector<std::string>{"/a", "/b/c"}));
  unsetenv("GAZEBO_RESOURCE_PATH");
  EXPECT_TRUE(bullet_sim::gazeboResourcePaths().empty());
}
