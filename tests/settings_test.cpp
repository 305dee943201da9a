#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "core/error.h"
#include "settings.h"
#include "test_support.h"

using voxflame::app::loadSettings;
using voxflame::app::RecentKind;
using voxflame::app::saveSettings;
using voxflame::app::Settings;
using voxflame::test::TemporaryFolder;

namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void touch(const std::filesystem::path& path) {
  std::ofstream(path) << "x";
}

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      setenv(name, value->c_str(), 1);
    else
      unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

}  // namespace

TEST(Settings, MissingFileGivesDefaultsSilently) {
  TemporaryFolder folder;
  const auto loaded = loadSettings(folder / "voxflame" / "settings.json");
  EXPECT_TRUE(loaded.message.empty());
  EXPECT_EQ(loaded.settings.window.width, Settings{}.window.width);
  EXPECT_TRUE(loaded.settings.recent.empty());
}

TEST(Settings, RoundTripKeepsEverything) {
  TemporaryFolder folder;
  touch(folder / "a.json");
  touch(folder / "bunny.obj");
  Settings settings;
  settings.window.width = 1234;
  settings.window.height = 777;
  settings.window.x = -40;
  settings.window.y = 25;
  settings.window.maximized = true;
  settings.lastPreset = folder / "a.json";
  settings.userPresetFolder = folder / "mine";
  settings.addRecent(RecentKind::Preset, folder / "a.json");
  settings.addRecent(RecentKind::Mesh, folder / "bunny.obj");
  settings.lastExport.width = 3840;
  settings.lastExport.height = 2160;
  settings.lastExport.samples = 16;
  settings.lastExport.points = 123'456'789;
  settings.lastExport.format = voxflame::app::ExportFormat::Exr;
  settings.lastExportFolder = folder / "renders";
  settings.refinementBackend = voxflame::app::BackendChoice::Gpu;
  const auto file = folder / "config" / "voxflame" / "settings.json";
  saveSettings(settings, file);
  // Atomic: nothing but the file is left in its folder.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(file.parent_path()), {}), 1);

  const auto loaded = loadSettings(file);
  EXPECT_TRUE(loaded.message.empty()) << loaded.message;
  const Settings& s = loaded.settings;
  EXPECT_EQ(s.window.width, 1234);
  EXPECT_EQ(s.window.height, 777);
  EXPECT_EQ(s.window.x, -40);
  EXPECT_EQ(s.window.y, 25);
  EXPECT_TRUE(s.window.maximized);
  EXPECT_EQ(s.lastPreset, folder / "a.json");
  EXPECT_EQ(s.userPresetFolder, folder / "mine");
  EXPECT_EQ(s.presetFolder(), folder / "mine");
  EXPECT_EQ(s.recentOf(RecentKind::Preset), std::vector<std::filesystem::path>{folder / "a.json"});
  EXPECT_EQ(s.recentOf(RecentKind::Mesh), std::vector<std::filesystem::path>{folder / "bunny.obj"});
  EXPECT_EQ(s.lastExport.width, 3840);
  EXPECT_EQ(s.lastExport.height, 2160);
  EXPECT_EQ(s.lastExport.samples, 16);
  EXPECT_EQ(s.lastExport.points, 123'456'789u);
  EXPECT_EQ(s.lastExport.format, voxflame::app::ExportFormat::Exr);
  EXPECT_EQ(s.lastExportFolder, folder / "renders");
  EXPECT_EQ(s.refinementBackend, voxflame::app::BackendChoice::Gpu);
}

TEST(Settings, AnUnknownRefinementBackendIsNamedAndLeftAtTheCpu) {
  TemporaryFolder folder;
  const auto file = folder / "settings.json";
  std::ofstream(file) << R"({"refinement_backend": "metal", "refine_until_noise_percent": 2})";
  const auto loaded = loadSettings(file);
  EXPECT_EQ(loaded.settings.refinementBackend, voxflame::app::BackendChoice::Cpu);
  EXPECT_EQ(loaded.settings.refineUntilNoisePercent, 2.0);
  EXPECT_NE(loaded.message.find("unknown refinement backend 'metal'"), std::string::npos) << loaded.message;
}

TEST(Settings, RecentFilesAreNewestFirstDeduplicatedCappedAndPruned) {
  TemporaryFolder folder;
  Settings settings;
  for (int i = 0; i < 12; ++i) {
    touch(folder / ("p" + std::to_string(i) + ".json"));
    settings.addRecent(RecentKind::Preset, folder / ("p" + std::to_string(i) + ".json"));
  }
  touch(folder / "m.obj");
  settings.addRecent(RecentKind::Mesh, folder / "m.obj");
  // The same file by another spelling moves to the front instead of appearing twice.
  settings.addRecent(RecentKind::Preset, folder / "sub" / ".." / "p5.json");
  auto presets = settings.recentOf(RecentKind::Preset);
  ASSERT_EQ(presets.size(), voxflame::app::kMaxRecentFiles);
  EXPECT_EQ(presets[0], folder / "p5.json");
  EXPECT_EQ(presets[1], folder / "p11.json");
  EXPECT_EQ(std::count(presets.begin(), presets.end(), folder / "p5.json"), 1);
  EXPECT_EQ(std::count(presets.begin(), presets.end(), folder / "p0.json"), 0);  // the oldest went
  EXPECT_EQ(settings.recentOf(RecentKind::Mesh).size(), 1u);

  saveSettings(settings, folder / "settings.json");
  std::filesystem::remove(folder / "p11.json");
  const auto loaded = loadSettings(folder / "settings.json");
  EXPECT_TRUE(loaded.message.empty()) << loaded.message;
  presets = loaded.settings.recentOf(RecentKind::Preset);
  ASSERT_EQ(presets.size(), voxflame::app::kMaxRecentFiles - 1);
  EXPECT_EQ(presets[0], folder / "p5.json");
  EXPECT_EQ(presets[1], folder / "p10.json");
  EXPECT_EQ(loaded.settings.recentOf(RecentKind::Mesh).size(), 1u);
}

TEST(Settings, MalformedFileGivesDefaultsAMessageAndIsKeptAside) {
  TemporaryFolder folder;
  const auto file = folder / "settings.json";
  std::ofstream(file) << "{\"window\": {\"width\": 1300,";
  const auto loaded = loadSettings(file);
  EXPECT_NE(loaded.message.find(file.string()), std::string::npos) << loaded.message;
  EXPECT_NE(loaded.message.find("settings.json.bad"), std::string::npos) << loaded.message;
  EXPECT_EQ(loaded.settings.window.width, Settings{}.window.width);
  EXPECT_EQ(readText(folder / "settings.json.bad"), "{\"window\": {\"width\": 1300,");
  // Saving afterwards replaces the bad file; the copy stays.
  saveSettings(loaded.settings, file);
  EXPECT_TRUE(loadSettings(file).message.empty());
  EXPECT_TRUE(std::filesystem::exists(folder / "settings.json.bad"));
}

TEST(Settings, BadValuesCostOnlyTheirKey) {
  TemporaryFolder folder;
  const auto file = folder / "settings.json";
  std::ofstream(file) << R"({"window": {"width": "banana", "height": 800, "x": 1e300, "y": 3},
    "recent": [{"path": 7}, 3, {"path": "/", "kind": "teapot"}],
    "last_export": {"samples": -2, "format": "gif", "width": 640, "points": 18446744073709551615},
    "last_preset": ["not", "a", "string"], "future_key": {"is": "ignored"}})";
  const auto loaded = loadSettings(file);
  const Settings& s = loaded.settings;
  EXPECT_EQ(s.window.width, Settings{}.window.width);
  EXPECT_EQ(s.window.height, 800);
  EXPECT_FALSE(s.window.x.has_value());  // a position needs both coordinates
  EXPECT_EQ(s.lastExport.width, 640);
  EXPECT_EQ(s.lastExport.samples, Settings{}.lastExport.samples);
  EXPECT_EQ(s.lastExport.points, 0u);
  EXPECT_EQ(s.lastExport.format, voxflame::app::ExportFormat::Png8);
  EXPECT_TRUE(s.lastPreset.empty());
  EXPECT_TRUE(s.recent.empty());
  EXPECT_NE(loaded.message.find("'window.width' must be a whole number from 200 to 32768"), std::string::npos)
      << loaded.message;
  EXPECT_NE(loaded.message.find("more"), std::string::npos) << loaded.message;
  EXPECT_TRUE(std::filesystem::exists(folder / "settings.json.bad"));
}

TEST(Settings, HostileFilesNeverCrash) {
  TemporaryFolder folder;
  const auto file = folder / "settings.json";
  const std::vector<std::string> hostile = {
      std::string(200000, '[') + std::string(200000, ']'),
      "[1, 2, 3]",
      "\"just a string\"",
      "null",
      std::string("{\"last_preset\": \"\xff\xfe\"}"),
      std::string("{\"window\": {\"width\": 1\0, \"height\": 2}}", 34),
      "{\"recent\": " + std::string(1000, '[') + std::string(1000, ']') + "}",
      "{\"window\": null, \"recent\": null, \"last_export\": 5}",
  };
  for (const auto& text : hostile) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    const auto loaded = loadSettings(file);
    EXPECT_EQ(loaded.settings.window.width, Settings{}.window.width) << text.substr(0, 40);
  }
  // Too large to be ours.
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "{\"x\": \"" << std::string(2 << 20, 'a') << "\"}";
  EXPECT_NE(loadSettings(file).message.find("too large"), std::string::npos);
  // A folder where the file should be.
  std::filesystem::remove(file);
  std::filesystem::create_directories(file);
  EXPECT_FALSE(loadSettings(file).message.empty());
}

TEST(Settings, SaveFailureNamesTheFile) {
  TemporaryFolder folder;
  touch(folder / "plain-file");
  try {
    saveSettings(Settings{}, folder / "plain-file" / "settings.json");
    FAIL() << "saving under a plain file must fail";
  } catch (const voxflame::core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("plain-file"), std::string::npos) << e.what();
  }
}

TEST(Settings, XdgFolders) {
  TemporaryFolder folder;
  {
    const ScopedEnv config("XDG_CONFIG_HOME", (folder / "config").string());
    const ScopedEnv data("XDG_DATA_HOME", (folder / "data").string());
    EXPECT_EQ(voxflame::app::defaultSettingsPath(), folder / "config" / "voxflame" / "settings.json");
    EXPECT_EQ(voxflame::app::defaultUserPresetFolder(), folder / "data" / "voxflame" / "presets");
    EXPECT_EQ(Settings{}.presetFolder(), folder / "data" / "voxflame" / "presets");
  }
  {
    // Unset or relative: the specification's fallbacks under $HOME.
    const ScopedEnv home("HOME", folder.path().string());
    const ScopedEnv config("XDG_CONFIG_HOME", std::string("relative/config"));
    const ScopedEnv data("XDG_DATA_HOME", std::nullopt);
    EXPECT_EQ(voxflame::app::defaultSettingsPath(), folder / ".config" / "voxflame" / "settings.json");
    EXPECT_EQ(voxflame::app::defaultUserPresetFolder(), folder / ".local" / "share" / "voxflame" / "presets");
  }
}
