// `voxflame import` (issue 12): flame files become presets that `voxflame render` renders; bad
// files fail with the file named and leave nothing behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/image_io.h"
#include "core/scene.h"
#include "test_support.h"

using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

namespace {

const std::filesystem::path kTestFlam3 = "/usr/share/flam3/test.flam3";

const char* kHandFlame = R"(<flame name="spiral" brightness="6" gamma="3">
  <xform weight="0.7" color="0" swirl="0.6" linear="0.4" coefs="0.6 -0.3 0.3 0.6 0.2 0"/>
  <xform weight="0.3" color="1" julia="1" nosuchvariation="0.5" coefs="0.5 0 0 0.5 -0.4 0.1"/>
  <symmetry kind="3"/>
  <color index="0" rgb="255 120 20"/><color index="255" rgb="40 90 255"/>
</flame>
)";

// Pixels clearly brighter than black: the flame drew something.
std::size_t litPixels(const std::filesystem::path& png) {
  const auto image = voxflame::core::readPng(png).image;
  std::size_t lit = 0;
  for (std::size_t i = 0; i + 3 < image.pixels.size(); i += 4)
    lit += image.pixels[i] + image.pixels[i + 1] + image.pixels[i + 2] > 0.1f;
  return lit;
}

// Renders the preset small, without the mesh's outline, so only the flame can light pixels. The
// copy sits beside the preset: a mesh path in it is relative to the preset's folder.
std::size_t renderLitPixels(const TemporaryFolder& folder, const std::string& preset) {
  nlohmann::json document;
  std::ifstream(folder / preset) >> document;
  document["render"]["mesh"] = "off";
  const std::filesystem::path bare = (folder / preset).parent_path() / "bare.json";
  std::ofstream(bare) << document.dump();
  const auto result =
      runVoxflame("render '" + bare.string() + "' -o bare.png --width 96 --height 64 --points 400000", folder.path());
  EXPECT_EQ(result.exitStatus, 0) << result.output;
  return litPixels(folder / "bare.png");
}

}  // namespace

TEST(ImportCli, Flam3SampleBecomesAPresetThatRenders) {
  if (!std::filesystem::exists(kTestFlam3)) GTEST_SKIP() << "flam3-utils is not installed";
  TemporaryFolder folder;
  auto result = runVoxflame("import " + kTestFlam3.string() + " -o first.json", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_NE(result.output.find("2 flames"), std::string::npos) << result.output;
  const auto scene = voxflame::core::loadScene(folder / "first.json");
  ASSERT_EQ(scene.layers.size(), 1u);
  EXPECT_EQ(scene.layers[0].kind, voxflame::core::PatternKind::Flame);
  EXPECT_EQ(scene.layers[0].flame.xforms.size(), 4u);
  EXPECT_EQ(scene.layers[0].color.mode, voxflame::core::ColorMode::Index);
  EXPECT_EQ(scene.layers[0].color.gradient.size(), 256u);
  EXPECT_EQ(scene.meshPath, "meshes/bunny.obj");
  EXPECT_TRUE(scene.embedded);
  EXPECT_GT(renderLitPixels(folder, "first.json"), 200u);

  // The second flame, by index and by its generated name; a flat import at depth 0.
  result = runVoxflame("import " + kTestFlam3.string() + " --index 2 --depth 0 -o second.json", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto second = voxflame::core::loadScene(folder / "second.json");
  EXPECT_EQ(second.name, "test 2");
  EXPECT_NE(second.layers[0].flame.xforms[0].affine, scene.layers[0].flame.xforms[0].affine);
  EXPECT_EQ(second.layers[0].flame.xforms[0].affine.m[11], 0.0);
}

TEST(ImportCli, HandWrittenFlameInAnotherMeshWithAWarningForTheUnknownVariation) {
  TemporaryFolder folder;
  std::ofstream(folder / "spiral.flame") << kHandFlame;
  const std::string teapot = voxflame::test::meshPath("teapot.obj").string();
  std::filesystem::create_directories(folder / "presets");
  const auto result =
      runVoxflame("import spiral.flame --mesh '" + teapot + "' -o presets/spiral.json --depth 1", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_NE(result.output.find("warning"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("nosuchvariation"), std::string::npos) << result.output;
  const auto scene = voxflame::core::loadScene(folder / "presets" / "spiral.json");
  EXPECT_EQ(scene.name, "spiral");
  EXPECT_EQ(scene.layers[0].flame.symmetry.rotational, 3);
  EXPECT_DOUBLE_EQ(scene.tone.brightness, 6.0);
  EXPECT_EQ(std::filesystem::weakly_canonical(scene.resolvedMeshPath()), std::filesystem::weakly_canonical(teapot));
  EXPECT_GT(renderLitPixels(folder, "presets/spiral.json"), 200u);
}

TEST(ImportCli, RenderAndOpenTakeAFlameFileDirectly) {
  TemporaryFolder folder;
  std::ofstream(folder / "spiral.flame") << kHandFlame;
  const auto result =
      runVoxflame("render spiral.flame -o direct.png --width 64 --height 48 --points 200000", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_NE(result.output.find("nosuchvariation"), std::string::npos) << result.output;
  const auto png = voxflame::core::readPng(folder / "direct.png");
  const auto scene = voxflame::core::sceneFromJson(png.text.at("voxflame:preset"), "direct.png");
  EXPECT_EQ(scene.layers.at(0).kind, voxflame::core::PatternKind::Flame);
}

TEST(ImportCli, BadFlameFilesFailNamingTheFile) {
  TemporaryFolder folder;
  std::ofstream(folder / "notes.flame") << "these are not the flames you are looking for";
  std::ofstream(folder / "image.flame") << "<svg><circle r=\"3\"/></svg>";
  std::ofstream(folder / "nan.flame") << "<flame><xform weight=\"1\" linear=\"1\" coefs=\"nan 0 0 1 0 0\"/></flame>";
  std::ofstream(folder / "zero.flame") << "<flame><xform weight=\"0\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/></flame>";
  std::ofstream(folder / "empty.flame") << "<flame brightness=\"4\"></flame>";
  for (const char* name : {"notes.flame", "image.flame", "nan.flame", "zero.flame", "empty.flame"}) {
    const auto result = runVoxflame(std::string("import ") + name + " -o out.json", folder.path());
    EXPECT_EQ(result.exitStatus, 1) << name << ": " << result.output;
    EXPECT_NE(result.output.find(name), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(folder / "out.json")) << name;
  }
  std::ofstream(folder / "ok.flame") << kHandFlame;
  auto result = runVoxflame("import ok.flame -o out.json --index 2", folder.path());
  EXPECT_EQ(result.exitStatus, 1);
  EXPECT_NE(result.output.find("ok.flame"), std::string::npos) << result.output;
  result = runVoxflame("import ok.flame -o out.json --index 1 --name spiral", folder.path());
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  result = runVoxflame("import ok.flame -o out.png", folder.path());
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  result = runVoxflame("import ok.flame -o out.json --depth -1", folder.path());
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  result = runVoxflame("import missing.flame -o out.json", folder.path());
  EXPECT_EQ(result.exitStatus, 1);
  EXPECT_NE(result.output.find("missing.flame"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "out.json"));
}

// `render --flat` (issue 25): the flame in 2D at the flame's own framing, from a flame file or the
// preset an import wrote; what it cannot do is a clear error.
TEST(ImportCli, RenderFlatDrawsTheFlameAtItsOwnFraming) {
  TemporaryFolder folder;
  std::ofstream(folder / "hand.flame") << R"(<flame name="framed" size="120 80" scale="30" quality="5">)" +
                                              std::string(kHandFlame).substr(std::string(kHandFlame).find('\n'));
  auto result = runVoxflame("render hand.flame --flat -o flat.png", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  auto image = voxflame::core::readPng(folder / "flat.png").image;
  EXPECT_EQ(image.width, 120);
  EXPECT_EQ(image.height, 80);
  EXPECT_GT(litPixels(folder / "flat.png"), 500u);

  result = runVoxflame("import hand.flame -o hand.json", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  result = runVoxflame("render hand.json --flat -o half.png --width 60 --quality 2 --seed 3", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  image = voxflame::core::readPng(folder / "half.png").image;
  EXPECT_EQ(image.width, 60);
  EXPECT_EQ(image.height, 40);

  result = runVoxflame("render hand.flame --flat -o flat.exr", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("PNG"), std::string::npos) << result.output;
  result = runVoxflame("render --flat -o none.png", folder.path());  // the built-in preset: attractors
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("no flame layer"), std::string::npos) << result.output;
  result = runVoxflame("render hand.flame --flat -o flat.png --quality 0", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  result = runVoxflame("render hand.flame -o still.png --quality 10", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("--flat"), std::string::npos) << result.output;
}
