#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/attractor.h"
#include "core/flame/flame.h"
#include "core/flame/variations.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_io.h"
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
  // The explorer opened on a preset of a million points: the built-in default's 150 million took
  // most of this test's time (several times as long under a sanitizer) and tested nothing more.
  std::ofstream(folder / "small.json") << R"({"schema_version":2,"name":"small",
    "mesh":{"path":"builtin:meshes/bunny.obj"},"grid":{"resolution":64},
    "layers":[{"attractor":"lorenz84"}],"points":1000000})";
  const auto result = runVoxflame("small.json", folder.path(), "env -u DISPLAY -u WAYLAND_DISPLAY");
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

TEST(Cli, RenderingThePngAgainReproducesIt) {
  TemporaryFolder folder;
  const std::string size = " --width 48 --height 32 --points 100000 --samples 2 --grid 48";
  auto result = runVoxflame("render -o first.png --camera-azimuth 70 --camera-elevation -20" + size, folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  // A different number of threads must not change a single pixel.
  result = runVoxflame("render first.png -o second.png --threads 1 --width 48 --height 32", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto first = voxflame::core::readPng(folder / "first.png");
  const auto second = voxflame::core::readPng(folder / "second.png");
  EXPECT_EQ(first.image.pixels, second.image.pixels);
  const auto scene = voxflame::core::sceneFromJson(first.text.at("voxflame:preset"), "first.png");
  EXPECT_DOUBLE_EQ(scene.camera.azimuthDeg, 70.0);
  EXPECT_DOUBLE_EQ(scene.camera.elevationDeg, -20.0);
  EXPECT_EQ(scene.render.samples, 2);
  EXPECT_EQ(scene.gridResolution, 48);
  EXPECT_EQ(voxflame::core::sceneToJson(scene), voxflame::core::sceneToJson(voxflame::core::sceneFromJson(
                                                    second.text.at("voxflame:preset"), "second.png")));
  EXPECT_NE(first.text.at("voxflame:stats").find("\"points\""), std::string::npos);
}

// The preset names its mesh relative to its own folder, and is rendered from the folder above: the
// mesh is found beside the preset, not in the working directory. The PNG then carries a path that
// still finds the mesh from another folder.
TEST(Cli, PresetWithAMeshOnDiskTravelsInsideThePng) {
  TemporaryFolder folder;
  std::filesystem::create_directories(folder / "work" / "meshes");
  std::filesystem::copy_file(voxflame::test::meshPath("teapot.obj"), folder / "work" / "meshes" / "teapot.obj");
  std::ofstream(folder / "work" / "p.json")
      << R"({"mesh":{"path":"meshes/teapot.obj"},"grid":{"resolution":32},"layers":[{"attractor":"lorenz84"}]})";
  auto result = runVoxflame("render work/p.json -o out.png --width 32 --height 32 --points 50000", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  std::filesystem::create_directories(folder / "elsewhere");
  std::filesystem::rename(folder / "out.png", folder / "elsewhere" / "moved.png");
  result = runVoxflame("render moved.png -o again.png --width 32 --height 32 --points 50000", folder / "elsewhere");
  EXPECT_EQ(result.exitStatus, 0) << result.output;
}

TEST(Cli, ExrOutputIsLinearFloat) {
  TemporaryFolder folder;
  const auto result = runVoxflame("render -o out.exr --width 40 --height 30 --points 100000", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto image = voxflame::core::readExr(folder / "out.exr");
  EXPECT_EQ(image.width, 40);
  EXPECT_EQ(image.height, 30);
  float brightest = 0.0f;
  for (float v : image.pixels) brightest = std::max(brightest, v);
  EXPECT_GT(brightest, 0.05f);
}

TEST(Cli, PngWithoutPresetAndBadRenderOptionsAreRefused) {
  TemporaryFolder folder;
  voxflame::core::ImageRGBA plain;
  plain.width = plain.height = 4;
  plain.pixels.assign(64, 0.5f);
  voxflame::core::writePng(folder / "plain.png", plain, 8, {});
  auto result = runVoxflame("render plain.png -o out.png", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("carries no voxflame preset"), std::string::npos) << result.output;
  result = runVoxflame("render -o out.tiff", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find(".png or .exr"), std::string::npos) << result.output;
  result = runVoxflame("render -o out.png --samples 0", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  result = runVoxflame("render -o out.png --grid 4096", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  result = runVoxflame("render -o out.png --camera-elevation nan", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_FALSE(std::filesystem::exists(folder / "out.png"));
}

TEST(Cli, InterruptedRenderLeavesNoFile) {
  TemporaryFolder folder;
  // A render far too long to finish, stopped by SIGINT after a moment.
  const auto result = runVoxflame(
      "render -o never.png --points 100000000000 2>&1 & pid=$!; sleep 2; kill -INT $pid; wait $pid", folder.path());
  EXPECT_EQ(result.exitStatus, 130) << result.output;
  EXPECT_NE(result.output.find("interrupted"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "never.png"));
  EXPECT_TRUE(voxflame::test::filesStartingWith(folder.path(), "never.png").empty());  // no temporary either
}

TEST(Cli, ListJsonIsTheCatalogue) {
  const auto result = runVoxflame("list --json");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto list = nlohmann::json::parse(result.output);
  ASSERT_TRUE(list.is_array());
  EXPECT_EQ(list.size(), voxflame::core::attractorCatalogue().size());
  bool sawPickover = false;
  for (const auto& entry : list) {
    EXPECT_TRUE(entry.contains("id") && entry.contains("name") && entry.contains("kind")) << entry.dump();
    EXPECT_TRUE(entry["parameters"].is_array());
    if (entry["id"] == "pickover") {
      sawPickover = true;
      EXPECT_EQ(entry["kind"], "map");
      EXPECT_EQ(entry["parameters"][0]["name"], "a");
      EXPECT_DOUBLE_EQ(entry["parameters"][0]["default"].get<double>(), -0.759494);
    }
  }
  EXPECT_TRUE(sawPickover);
  const auto table = runVoxflame("list");
  ASSERT_EQ(table.exitStatus, 0);
  EXPECT_NE(table.output.find("lorenz84"), std::string::npos);
  // Every row's parameters start in the same column as the header's, counted in characters (not
  // bytes), names with letters outside ASCII (Lü–Chen, Rössler, Nosé–Hoover) included.
  std::istringstream rows(table.output);
  std::string row;
  int checked = 0, nonAscii = 0;
  constexpr std::size_t kParametersColumn = 23 + 6 + 33;
  while (std::getline(rows, row)) {
    std::vector<std::string> characters;  // one UTF-8 sequence each
    for (const char c : row) {
      if ((static_cast<unsigned char>(c) & 0xC0u) == 0x80u && !characters.empty())
        characters.back() += c;
      else
        characters.emplace_back(1, c);
    }
    ASSERT_GT(characters.size(), kParametersColumn) << row;
    EXPECT_EQ(characters[kParametersColumn - 1], " ") << row;
    EXPECT_NE(characters[kParametersColumn], " ") << row;
    if (std::any_of(row.begin(), row.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80u; })) ++nonAscii;
    ++checked;
  }
  EXPECT_GT(checked, 10);
  EXPECT_GE(nonAscii, 3) << "the catalogue's names with accents and dashes are among the rows";
  EXPECT_NE(runVoxflame("list --frobnicate").exitStatus, 0);
}

TEST(Cli, ListVariationsGivesTheFlameCatalogueAsTextJsonAndMarkdown) {
  const auto result = runVoxflame("list --variations --json");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto list = nlohmann::json::parse(result.output);
  ASSERT_TRUE(list.is_array());
  EXPECT_EQ(list.size(), voxflame::core::variationCatalogue().size());
  EXPECT_GE(list.size(), 40u);
  bool sawJulian = false, sawCurl3D = false;
  for (const auto& entry : list) {
    EXPECT_TRUE(entry.contains("name") && entry.contains("dimensions") && entry.contains("formula") &&
                entry.contains("random") && entry["parameters"].is_array())
        << entry.dump();
    if (entry["name"] == "julian") {
      sawJulian = true;
      EXPECT_EQ(entry["dimensions"], "2D");
      EXPECT_EQ(entry["random"], true);
      EXPECT_EQ(entry["parameters"][0]["name"], "power");
      EXPECT_EQ(entry["parameters"][0]["integer"], false) << "a real number, as flam3 has it";
      EXPECT_EQ(entry["parameters"][1]["name"], "dist");
    }
    if (entry["name"] == "julia3D") {
      EXPECT_EQ(entry["parameters"][0]["integer"], true);
    }
    if (entry["name"] == "curl3D") {
      sawCurl3D = true;
      EXPECT_EQ(entry["dimensions"], "3D");
      EXPECT_EQ(entry["parameters"].size(), 3u);
    }
  }
  EXPECT_TRUE(sawJulian);
  EXPECT_TRUE(sawCurl3D);

  const auto table = runVoxflame("list --variations");
  ASSERT_EQ(table.exitStatus, 0) << table.output;
  EXPECT_NE(table.output.find("julian"), std::string::npos);
  EXPECT_NE(table.output.find("power=4 dist=1"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("(x sin r² − y cos r², x cos r² + y sin r², z)"), std::string::npos);

  const auto markdown = runVoxflame("list --variations --markdown");
  ASSERT_EQ(markdown.exitStatus, 0) << markdown.output;
  EXPECT_EQ(markdown.output, voxflame::core::variationsMarkdown());

  const auto misused = runVoxflame("list --markdown");
  EXPECT_NE(misused.exitStatus, 0);
  EXPECT_NE(misused.output.find("--variations"), std::string::npos) << misused.output;
}

TEST(Cli, InfoJsonGivesBoundednessAndLyapunovLargestFirst) {
  auto result = runVoxflame(
      "info --attractor lorenz --param a=10 --param b=28 --param c=2.6666666667 "
      "--integrator rk4 --json");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  auto info = nlohmann::json::parse(result.output);
  EXPECT_EQ(info["attractor"], "lorenz");
  EXPECT_DOUBLE_EQ(info["params"]["a"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(info["params"]["b"].get<double>(), 28.0);
  EXPECT_EQ(info["bounded"], true);
  ASSERT_EQ(info["lyapunov"].size(), 3u);
  EXPECT_NEAR(info["lyapunov"][0].get<double>(), 0.906, 0.05);
  EXPECT_NEAR(info["lyapunov"][2].get<double>(), -14.57, 0.1);
  EXPECT_GE(info["lyapunov"][0].get<double>(), info["lyapunov"][1].get<double>());

  // A preset's first layer; the seed's escaping polynomial_b set.
  result = runVoxflame("info " + voxflame::test::sourcePath("presets/default.json").string() + " --json");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_EQ(nlohmann::json::parse(result.output)["attractor"], "lorenz84");
  result = runVoxflame("info --attractor polynomial_b --set seed --json");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_EQ(nlohmann::json::parse(result.output)["bounded"], false);
}

TEST(Cli, InfoRefusesBadValuesWithMessages) {
  auto result = runVoxflame("info --attractor lorenz --param a=nan");
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("finite number"), std::string::npos) << result.output;
  result = runVoxflame("info --attractor lorenz --param q=1");
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("no parameter 'q'"), std::string::npos) << result.output;
  result = runVoxflame("info --attractor lorenz --step 1e9");
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("step"), std::string::npos) << result.output;
  result = runVoxflame("info --attractor nope");
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("unknown attractor 'nope'"), std::string::npos) << result.output;
  result = runVoxflame("info --attractor lorenz --integrator leapfrog");
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find("leapfrog"), std::string::npos) << result.output;
}

TEST(Cli, SearchPrintsKDeterministicSets) {
  const auto first = runVoxflame("search --attractor polynomial_b --set seed --seed 7 --count 2 --strength 0.3 --json");
  ASSERT_EQ(first.exitStatus, 0) << first.output;
  const auto sets = nlohmann::json::parse(first.output);
  ASSERT_EQ(sets.size(), 2u);
  for (const auto& set : sets) {
    EXPECT_GT(set["lyapunov"][0].get<double>(), 0.0);
    EXPECT_EQ(set["params"].size(), 6u);
  }
  EXPECT_EQ(runVoxflame("search --attractor polynomial_b --set seed --seed 7 --count 2 --strength 0.3 --json").output,
            first.output);
  const auto text = runVoxflame("search --attractor lorenz84 --count 3");
  ASSERT_EQ(text.exitStatus, 0) << text.output;
  EXPECT_NE(text.output.find("3. a="), std::string::npos) << text.output;
  EXPECT_NE(runVoxflame("search --attractor lorenz84 --count 0").exitStatus, 0);
}

// A flame or quaternion Julia preset gets the fill test (info) and the flame search (search).
TEST(Cli, InfoAndSearchOnChaosGamePresetsUseTheFlameSearch) {
  TemporaryFolder folder;
  voxflame::core::Scene scene = voxflame::core::defaultScene();
  voxflame::core::PatternLayer& layer = scene.layers[0];
  layer.kind = voxflame::core::PatternKind::Flame;
  layer.attractor.clear();
  layer.params.clear();
  layer.flame = voxflame::core::defaultFlame();
  layer.color.mode = voxflame::core::ColorMode::Index;
  std::ofstream(folder.path() / "flame.json") << voxflame::core::sceneToJson(scene);
  layer.kind = voxflame::core::PatternKind::QuaternionJulia;
  layer.flame = {};
  std::ofstream(folder.path() / "julia.json") << voxflame::core::sceneToJson(scene);

  auto info = runVoxflame("info flame.json", folder.path());
  ASSERT_EQ(info.exitStatus, 0) << info.output;
  EXPECT_NE(info.output.find("fills a volume"), std::string::npos) << info.output;

  const auto first = runVoxflame("search flame.json --seed 3 --count 2 --json", folder.path());
  ASSERT_EQ(first.exitStatus, 0) << first.output;
  const auto found = nlohmann::json::parse(first.output);
  ASSERT_EQ(found.size(), 2u);
  for (const auto& entry : found) {
    EXPECT_EQ(entry["kind"], "flame");
    EXPECT_TRUE(entry["fill"]["passes"].get<bool>());
    EXPECT_FALSE(entry["flame"]["xforms"].empty());
  }
  EXPECT_GE(found[0]["fill"]["score"].get<double>(), found[1]["fill"]["score"].get<double>()) << "best first";
  EXPECT_EQ(runVoxflame("search flame.json --seed 3 --count 2 --json", folder.path()).output, first.output);

  // -o writes the best as a preset that loads and renders as a flame.
  const auto written = runVoxflame("search flame.json --random --seed 4 --count 1 -o best.json", folder.path());
  ASSERT_EQ(written.exitStatus, 0) << written.output;
  EXPECT_NE(written.output.find("1. score"), std::string::npos) << written.output;
  const voxflame::core::Scene best = voxflame::core::loadScene(folder.path() / "best.json");
  EXPECT_EQ(best.layers[0].kind, voxflame::core::PatternKind::Flame);
  EXPECT_NE(best.layers[0].flame, voxflame::core::defaultFlame());

  const auto julia = runVoxflame("search julia.json --count 1 --json", folder.path());
  ASSERT_EQ(julia.exitStatus, 0) << julia.output;
  EXPECT_EQ(nlohmann::json::parse(julia.output)[0]["julia"]["c"].size(), 4u);

  // Attractor options on a flame preset say why they do not apply.
  const auto wrong = runVoxflame("search flame.json --param a=1", folder.path());
  EXPECT_NE(wrong.exitStatus, 0);
  EXPECT_NE(wrong.output.find("applies to attractors"), std::string::npos) << wrong.output;
  EXPECT_NE(runVoxflame("search --attractor lorenz84 --random").exitStatus, 0);
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

// `render --until-noise` stops at a noise estimate instead of a point count: a looser target
// stops sooner, each meets its target, --points still caps it, and --stats prints the estimate.
TEST(Cli, RenderUntilNoiseStopsAtTheNoiseAndStatsReportIt) {
  TemporaryFolder folder;
  auto statsOf = [&](const std::string& options) {
    const auto result =
        runVoxflame("render -o out.png --width 64 --height 48 --grid 96 --stats " + options, folder.path());
    EXPECT_EQ(result.exitStatus, 0) << result.output;
    const auto at = result.output.find("stats {");
    if (at == std::string::npos) return nlohmann::json::object();
    return nlohmann::json::parse(result.output.substr(at + 6, result.output.find('\n', at) - at - 6));
  };
  const auto loose = statsOf("--until-noise 8");
  const auto tight = statsOf("--until-noise 3");
  ASSERT_TRUE(loose.contains("noise") && tight.contains("noise") && loose.contains("points")) << loose.dump() << "\n"
                                                                                              << tight.dump();
  EXPECT_LE(loose["noise"].get<double>(), 0.08);
  EXPECT_LE(tight["noise"].get<double>(), 0.03);
  EXPECT_LT(loose["points"].get<std::uint64_t>(), tight["points"].get<std::uint64_t>())
      << "a lower noise takes more points";
  // The preset in the image holds the count the target came to, so it renders the same again.
  const auto png = voxflame::core::readPng(folder / "out.png");
  EXPECT_EQ(voxflame::core::sceneFromJson(png.text.at("voxflame:preset"), "png").points,
            tight["points"].get<std::uint64_t>());

  const auto withCount = statsOf("--until-noise 8 --points 50000000");
  EXPECT_LT(withCount["points"].get<std::uint64_t>(), 10'000'000u)
      << "a noise target reached first stops the render, however far the count";
  EXPECT_LE(withCount["noise"].get<double>(), 0.08);

  const auto capped = statsOf("--until-noise 0.01 --points 2000000");
  EXPECT_LT(capped["points"].get<std::uint64_t>(), 3'000'000u) << "--points caps an unreachable noise target";
  ASSERT_TRUE(capped.contains("noise")) << capped.dump();
  EXPECT_GT(capped["noise"].get<double>(), 0.0001);

  const auto plain = statsOf("--points 2000000");
  EXPECT_TRUE(plain.contains("noise")) << "a plain render reports its noise too: " << plain.dump();

  const auto refused = runVoxflame("render -o p.png --method points --until-noise 1", folder.path());
  EXPECT_EQ(refused.exitStatus, 2) << refused.output;
  EXPECT_NE(refused.output.find("--until-noise"), std::string::npos) << refused.output;
  EXPECT_EQ(runVoxflame("render -o q.png --until-noise 0", folder.path()).exitStatus, 2) << "0 is not a noise";
}
