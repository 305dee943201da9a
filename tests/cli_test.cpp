#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/image_io.h"
#include "core/scene.h"
#include "test_support.h"

using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

TEST(Cli, RenderWithoutPresetWritesPngCarryingTheDefaultPreset) {
  TemporaryFolder folder;
  const auto result = runVoxflame("render -o out.png --width 96 --height 64 --points 200000", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto png = voxflame::core::readPng(folder / "out.png");
  EXPECT_EQ(png.image.width, 96);
  EXPECT_EQ(png.image.height, 64);
  ASSERT_TRUE(png.text.count("voxflame:preset"));
  const auto scene = voxflame::core::sceneFromJson(png.text.at("voxflame:preset"), "png");
  EXPECT_EQ(scene.layers.at(0).attractor, "lorenz84");
}

TEST(Cli, RenderSixteenBit) {
  TemporaryFolder folder;
  const auto result =
      runVoxflame("render -o deep.png --width 32 --height 32 --points 50000 --bit-depth 16", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_EQ(voxflame::core::readPng(folder / "deep.png").bitDepth, 16);
}

TEST(Cli, MissingPresetIsNamedAndFails) {
  TemporaryFolder folder;
  const auto result = runVoxflame("render no-such-preset.json -o out.png", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("no-such-preset.json"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "out.png"));
}

TEST(Cli, MissingMeshIsNamedAndFails) {
  TemporaryFolder folder;
  std::ofstream(folder / "p.json") << R"({"mesh":{"path":"gone/teapot.obj"},"layers":[{"attractor":"lorenz84"}]})";
  const auto result = runVoxflame("render p.json -o out.png", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("teapot.obj"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "out.png"));
}

TEST(Cli, MalformedPresetAndBadOptionsGiveMessages) {
  TemporaryFolder folder;
  std::ofstream(folder / "bad.json") << "{\"mesh\": ";
  auto result = runVoxflame("render bad.json -o out.png", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("bad.json"), std::string::npos) << result.output;
  result = runVoxflame("render -o out.png --width banana", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("--width"), std::string::npos) << result.output;
  result = runVoxflame("render -o out.png --frobnicate 3", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("unknown option --frobnicate"), std::string::npos) << result.output;
  result = runVoxflame("render", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("-o"), std::string::npos) << result.output;
}

TEST(Cli, WithoutADisplayTheExplorerRendersAPngAndSaysSo) {
  TemporaryFolder folder;
  const auto result = runVoxflame("", folder.path(), "env -u DISPLAY -u WAYLAND_DISPLAY");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_NE(result.output.find("no display"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "voxflame-preview.png"));
}

TEST(Cli, HelpAndVersion) {
  EXPECT_EQ(runVoxflame("--help").exitStatus, 0);
  const auto version = runVoxflame("--version");
  EXPECT_EQ(version.exitStatus, 0);
  EXPECT_NE(version.output.find("voxflame"), std::string::npos);
}

TEST(Cli, MaskWritesNrrdAndStats) {
  TemporaryFolder folder;
  const std::string mesh = voxflame::test::meshPath("teapot.obj").string();
  auto result = runVoxflame("mask '" + mesh + "' --grid 48 -o teapot.nrrd --stats", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  for (const char* line : {"triangles: 992", "grid: 48 ", "inside fraction: 0.", "seconds: "})
    EXPECT_NE(result.output.find(line), std::string::npos) << line << "\n" << result.output;
  std::ifstream in(folder / "teapot.nrrd", std::ios::binary);
  std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(file.rfind("NRRD0004\n", 0), 0u);
  EXPECT_NE(file.find("type: uchar\n"), std::string::npos);

  result = runVoxflame("mask '" + mesh + "' --grid 16 -o t.nrrd", folder.path());
  EXPECT_EQ(result.exitStatus, 2);
  EXPECT_NE(result.output.find("--grid"), std::string::npos) << result.output;
  result = runVoxflame("mask '" + mesh + "' --grid 48", folder.path());
  EXPECT_EQ(result.exitStatus, 2);
  EXPECT_NE(result.output.find("-o OUT.nrrd"), std::string::npos) << result.output;
  result = runVoxflame("mask gone.obj -o t.nrrd", folder.path());
  EXPECT_EQ(result.exitStatus, 1);
  EXPECT_NE(result.output.find("gone.obj"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "t.nrrd"));
}
