#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "preset_library.h"
#include "test_support.h"

using voxflame::app::PresetEntry;
using voxflame::app::PresetLibrary;
using voxflame::app::PresetSource;
using voxflame::app::sanitizePresetName;
using voxflame::app::Thumbnail;
using voxflame::app::ThumbnailState;
using voxflame::test::TemporaryFolder;

namespace {

// A width×height image: left half red, right half blue (8 or 16 bits per channel).
void writeTwoColourPng(const std::filesystem::path& path, int width, int height, int bitDepth = 8) {
  voxflame::core::ImageRGBA image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = image.at(x, y);
      p[0] = x < width / 2 ? 1.0f : 0.0f;
      p[1] = 0.0f;
      p[2] = x < width / 2 ? 0.0f : 1.0f;
      p[3] = 1.0f;
    }
  voxflame::core::writePng(path, image, bitDepth, {});
}

void writePreset(const std::filesystem::path& path, const std::string& name, const std::string& attractor) {
  std::ofstream(path) << R"({"name": ")" << name << R"(", "mesh": {"path": "meshes/bunny.obj"},
      "layers": [{"attractor": ")"
                      << attractor << R"("}]})";
}

const PresetEntry* findEntry(const std::vector<PresetEntry>& entries, const std::string& filename) {
  for (const auto& entry : entries)
    if (entry.path.filename() == filename) return &entry;
  return nullptr;
}

Thumbnail solidThumbnail(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Thumbnail thumbnail;
  thumbnail.width = width;
  thumbnail.height = height;
  for (int i = 0; i < width * height; ++i) thumbnail.rgba.insert(thumbnail.rgba.end(), {r, g, b, 255});
  return thumbnail;
}

}  // namespace

TEST(PresetLibrary, ListsShippedAndUserPresetsBrokenOnesWithTheirError) {
  TemporaryFolder folder;
  const auto shipped = folder / "presets";
  const auto user = folder / "mine";
  std::filesystem::create_directories(shipped / "gallery");
  std::filesystem::create_directories(shipped / "meshes");
  std::filesystem::create_directories(user);
  writePreset(shipped / "alpha.json", "Alpha", "lorenz84");
  writeTwoColourPng(shipped / "gallery" / "alpha.png", 40, 20);
  writePreset(shipped / "zeta.json", "zeta", "no-such-attractor");
  std::ofstream(shipped / "truncated.json") << "{\"name\": \"cut";
  std::ofstream(shipped / "readme.txt") << "not a preset";
  writePreset(shipped / ".hidden.json", "Hidden", "lorenz84");
  writePreset(shipped / "meshes" / "nested.json", "Nested", "lorenz84");
  writePreset(user / "mine.json", "Beta mine", "lorenz84");
  writeTwoColourPng(user / "mine.png", 30, 30);

  const auto entries = voxflame::app::listPresets(shipped, user);
  ASSERT_EQ(entries.size(), 4u);
  // Shipped first, by display name; then the user's.
  EXPECT_EQ(entries[0].displayName, "Alpha");
  EXPECT_EQ(entries[1].displayName, "truncated");
  EXPECT_EQ(entries[2].displayName, "zeta");
  EXPECT_EQ(entries[3].displayName, "Beta mine");
  EXPECT_EQ(entries[3].source, PresetSource::User);

  const PresetEntry* alpha = findEntry(entries, "alpha.json");
  ASSERT_TRUE(alpha);
  EXPECT_TRUE(alpha->loads);
  EXPECT_EQ(alpha->attractor, "lorenz84");
  EXPECT_EQ(alpha->source, PresetSource::Shipped);
  EXPECT_EQ(alpha->thumbnailPath, shipped / "gallery" / "alpha.png");
  EXPECT_EQ(alpha->thumbnailState, ThumbnailState::Pending);

  const PresetEntry* zeta = findEntry(entries, "zeta.json");
  ASSERT_TRUE(zeta);
  EXPECT_FALSE(zeta->loads);
  EXPECT_NE(zeta->error.find("no-such-attractor"), std::string::npos) << zeta->error;
  EXPECT_NE(zeta->error.find("zeta.json"), std::string::npos) << zeta->error;
  EXPECT_EQ(zeta->thumbnailState, ThumbnailState::Missing);

  const PresetEntry* truncated = findEntry(entries, "truncated.json");
  ASSERT_TRUE(truncated);
  EXPECT_FALSE(truncated->loads);
  EXPECT_NE(truncated->error.find("not valid JSON"), std::string::npos) << truncated->error;

  EXPECT_EQ(findEntry(entries, "mine.json")->thumbnailPath, user / "mine.png");
  // Missing folders are simply empty.
  EXPECT_TRUE(voxflame::app::listPresets(folder / "nothing", {}).empty());
}

TEST(PresetLibrary, ChaosGamePresetsAreListedByTheirKind) {
  TemporaryFolder folder;
  const auto shipped = folder / "presets";
  std::filesystem::create_directories(shipped);
  std::ofstream(shipped / "flame.json") << R"({"name": "Flame", "mesh": {"path": "meshes/bunny.obj"},
      "layers": [{"kind": "flame", "flame": {"xforms": [{"weight": 1, "affine": [0.5, 0, 0, 0.3, 0, 0.5, 0, 0.1,
      0, 0, 0.5, 0], "variations": [{"name": "spherical", "weight": 1}]}]}}]})";
  std::ofstream(shipped / "julia.json") << R"({"name": "Julia", "mesh": {"path": "meshes/bunny.obj"},
      "layers": [{"kind": "quaternion_julia", "julia": {"c": [-0.2, 0.8, 0, 0]}}]})";
  const auto entries = voxflame::app::listPresets(shipped, {});
  ASSERT_EQ(entries.size(), 2u);
  const PresetEntry* flame = findEntry(entries, "flame.json");
  ASSERT_TRUE(flame);
  EXPECT_TRUE(flame->loads) << flame->error;
  EXPECT_EQ(flame->attractor, "flame");
  const PresetEntry* julia = findEntry(entries, "julia.json");
  ASSERT_TRUE(julia);
  EXPECT_TRUE(julia->loads) << julia->error;
  EXPECT_EQ(julia->attractor, "quaternion_julia");
}

TEST(PresetLibrary, HostilePresetFilesAreListedNotFatal) {
  TemporaryFolder folder;
  std::ofstream(folder / "deep.json") << std::string(100000, '[') << std::string(100000, ']');
  std::ofstream(folder / "huge.json") << "{\"name\": \"" << std::string(5 << 20, 'a') << "\"}";
  std::ofstream(folder / "binary.json") << std::string("\x89PNG\r\n\x1a\n\0\0\xff", 11);
  std::filesystem::create_directories(folder / "folder.json");
  const auto entries = voxflame::app::listPresets(folder.path(), {});
  ASSERT_EQ(entries.size(), 3u);
  for (const auto& entry : entries) {
    EXPECT_FALSE(entry.loads);
    EXPECT_FALSE(entry.error.empty());
  }
}

TEST(PresetLibrary, ShippedFolderLookupOrder) {
  TemporaryFolder folder;
  const auto exe = folder / "prefix" / "bin" / "voxflame";
  const auto candidates = voxflame::app::shippedPresetFolderCandidates(exe);
  ASSERT_GE(candidates.size(), 3u);
  EXPECT_EQ(candidates[0], folder / "prefix" / "share" / "voxflame" / "presets");
  EXPECT_EQ(candidates[1], folder / "prefix" / "bin" / "presets");
  EXPECT_EQ(candidates[2], voxflame::test::sourcePath("presets"));
  // Nothing installed: the developer build's source folder.
  EXPECT_EQ(voxflame::app::findShippedPresetFolder(exe), voxflame::test::sourcePath("presets"));
  std::filesystem::create_directories(folder / "prefix" / "bin" / "presets");
  EXPECT_EQ(voxflame::app::findShippedPresetFolder(exe), folder / "prefix" / "bin" / "presets");
  std::filesystem::create_directories(folder / "prefix" / "share" / "voxflame" / "presets");
  EXPECT_EQ(voxflame::app::findShippedPresetFolder(exe), folder / "prefix" / "share" / "voxflame" / "presets");
  // This test binary's own lookup finds the source tree.
  EXPECT_FALSE(voxflame::app::findShippedPresetFolder().empty());
}

TEST(PresetLibrary, TheRealShippedPresetsLoadWithTheirGalleryThumbnail) {
  const auto entries = voxflame::app::listPresets(voxflame::test::sourcePath("presets"), {});
  const PresetEntry* fallback = findEntry(entries, "default.json");
  ASSERT_TRUE(fallback);
  EXPECT_TRUE(fallback->loads) << fallback->error;
  EXPECT_EQ(fallback->displayName, voxflame::core::defaultScene().name);
  EXPECT_EQ(fallback->thumbnailState, ThumbnailState::Pending);
  const Thumbnail thumbnail = voxflame::app::decodeThumbnail(fallback->thumbnailPath);
  const auto gallery = voxflame::core::readPng(fallback->thumbnailPath);
  EXPECT_EQ(thumbnail.width, voxflame::app::kThumbnailWidth);
  EXPECT_EQ(thumbnail.height, gallery.image.height * voxflame::app::kThumbnailWidth / gallery.image.width);
  for (const auto& entry : entries) EXPECT_TRUE(entry.loads) << entry.error;
}

TEST(PresetLibrary, ThumbnailsAreDecodedDownscaledToRgba8) {
  TemporaryFolder folder;
  writeTwoColourPng(folder / "wide.png", 640, 360);
  Thumbnail t = voxflame::app::decodeThumbnail(folder / "wide.png");
  EXPECT_EQ(t.width, 160);
  EXPECT_EQ(t.height, 90);
  ASSERT_EQ(t.rgba.size(), 4u * 160 * 90);
  const auto pixel = [&](int x, int y) { return &t.rgba[4 * (static_cast<std::size_t>(y) * t.width + x)]; };
  EXPECT_EQ(pixel(10, 45)[0], 255);  // left: red
  EXPECT_EQ(pixel(10, 45)[2], 0);
  EXPECT_EQ(pixel(150, 45)[0], 0);  // right: blue
  EXPECT_EQ(pixel(150, 45)[2], 255);
  EXPECT_EQ(pixel(150, 45)[3], 255);

  writeTwoColourPng(folder / "deep.png", 333, 100, 16);
  t = voxflame::app::decodeThumbnail(folder / "deep.png");
  EXPECT_EQ(t.width, 160);
  EXPECT_EQ(t.height, 48);

  writeTwoColourPng(folder / "small.png", 64, 32);  // never enlarged
  t = voxflame::app::decodeThumbnail(folder / "small.png");
  EXPECT_EQ(t.width, 64);
  EXPECT_EQ(t.height, 32);

  writeTwoColourPng(folder / "strip.png", 4000, 1);  // never zero rows
  t = voxflame::app::decodeThumbnail(folder / "strip.png", 100);
  EXPECT_EQ(t.width, 100);
  EXPECT_EQ(t.height, 1);

  std::ofstream(folder / "fake.png") << "not a png at all";
  EXPECT_THROW(voxflame::app::decodeThumbnail(folder / "fake.png"), voxflame::core::Error);
  // Cut short after the header: an error, not a crash.
  std::filesystem::resize_file(folder / "wide.png", 200);
  EXPECT_THROW(voxflame::app::decodeThumbnail(folder / "wide.png"), voxflame::core::Error);
  EXPECT_THROW(voxflame::app::decodeThumbnail(folder / "missing.png"), voxflame::core::Error);
}

TEST(PresetLibrary, SanitizesNames) {
  EXPECT_EQ(sanitizePresetName("Lorenz bunny"), "Lorenz-bunny");
  EXPECT_EQ(sanitizePresetName("  My  Preset! (v2)  "), "My-Preset-v2");
  EXPECT_EQ(sanitizePresetName("../../etc/passwd"), "etc-passwd");
  EXPECT_EQ(sanitizePresetName(".hidden"), "hidden");
  EXPECT_EQ(sanitizePresetName("a/b\\c:d*e?f\"g<h>i|j"), "a-b-c-d-e-f-g-h-i-j");
  EXPECT_EQ(sanitizePresetName("snake_case-and-dash"), "snake_case-and-dash");
  EXPECT_EQ(sanitizePresetName("tab\there\nnewline"), "tab-here-newline");
  EXPECT_EQ(sanitizePresetName("Café ☕"), "Café-☕");
  EXPECT_EQ(sanitizePresetName("bad\xff\xfe utf8"), "bad-utf8");
  EXPECT_EQ(sanitizePresetName(""), "preset");
  EXPECT_EQ(sanitizePresetName("..."), "preset");
  EXPECT_EQ(sanitizePresetName("///"), "preset");
  const std::string longName = sanitizePresetName(std::string(200, 'x'));
  EXPECT_EQ(longName.size(), 80u);
  // A multi-byte character is never cut in half at the limit.
  const std::string accents = sanitizePresetName(std::string(79, 'x') + "éé");
  EXPECT_EQ(accents, std::string(79, 'x'));
}

TEST(PresetLibrary, SaveAsRoundTrip) {
  TemporaryFolder folder;
  std::filesystem::create_directories(folder / "project" / "meshes");
  std::filesystem::copy_file(voxflame::test::meshPath("bunny.obj"), folder / "project" / "meshes" / "bunny.obj");
  writePreset(folder / "project" / "p.json", "original", "lorenz84");
  voxflame::core::Scene scene = voxflame::core::loadScene(folder / "project" / "p.json");
  scene.tone.brightness = 6.5;
  const auto user = folder / "user" / "presets";  // created on demand

  const auto path = voxflame::app::savePresetAs(scene, "My Bunny: v1", solidThumbnail(640, 320, 10, 200, 30), user);
  EXPECT_EQ(path, user / "My-Bunny-v1.json");
  const voxflame::core::Scene loaded = voxflame::core::loadScene(path);
  EXPECT_EQ(loaded.name, "My Bunny: v1");
  EXPECT_DOUBLE_EQ(loaded.tone.brightness, 6.5);
  // The relative mesh path still finds the mesh from the user's folder.
  EXPECT_EQ(loaded.resolvedMeshPath(), folder / "project" / "meshes" / "bunny.obj");
  const auto png = voxflame::core::readPng(user / "My-Bunny-v1.png");
  EXPECT_EQ(png.image.width, voxflame::app::kSavedThumbnailWidth);
  EXPECT_EQ(png.image.height, 160);
  EXPECT_NEAR(png.image.pixels[1], 200.0f / 255.0f, 1e-6);
  ASSERT_TRUE(png.text.count("voxflame:preset"));
  EXPECT_EQ(voxflame::core::sceneFromJson(png.text.at("voxflame:preset"), "png").name, "My Bunny: v1");

  // Not replaced unless asked.
  EXPECT_THROW(voxflame::app::savePresetAs(scene, "My Bunny: v1", {}, user), voxflame::core::Error);
  scene.tone.brightness = 2.0;
  voxflame::app::savePresetAs(scene, "My Bunny: v1", {}, user, /*overwrite=*/true);
  EXPECT_DOUBLE_EQ(voxflame::core::loadScene(path).tone.brightness, 2.0);
  EXPECT_FALSE(std::filesystem::exists(user / "My-Bunny-v1.png"));  // the old picture is gone

  // The embedded default stays embedded.
  const auto builtin = voxflame::app::savePresetAs(voxflame::core::defaultScene(), "builtin", {}, user);
  EXPECT_TRUE(voxflame::core::loadScene(builtin).embedded);

  Thumbnail wrong = solidThumbnail(4, 4, 0, 0, 0);
  wrong.rgba.pop_back();
  EXPECT_THROW(voxflame::app::savePresetAs(scene, "wrong", wrong, user), voxflame::core::Error);
  // Nothing but the presets and the thumbnail: no temporaries left.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(user), {}), 2);
}

TEST(PresetLibrary, BackgroundScanDecodesThumbnailsAndSeesNewPresets) {
  TemporaryFolder folder;
  const auto shipped = folder / "presets";
  const auto user = folder / "mine";
  std::filesystem::create_directories(shipped / "gallery");
  writePreset(shipped / "alpha.json", "Alpha", "lorenz84");
  writeTwoColourPng(shipped / "gallery" / "alpha.png", 480, 240);
  writePreset(shipped / "beta.json", "Beta", "lorenz84");
  std::ofstream(shipped / "gallery" / "beta.png") << "broken picture";

  PresetLibrary library(shipped, user);
  const auto waitIdle = [&] { return library.waitUntilIdle(60.0); };
  ASSERT_TRUE(waitIdle());
  auto entries = library.entries();
  ASSERT_EQ(entries->size(), 2u);
  EXPECT_EQ((*entries)[0].thumbnailState, ThumbnailState::Ready);
  ASSERT_TRUE((*entries)[0].thumbnail);
  EXPECT_EQ((*entries)[0].thumbnail->width, 160);
  EXPECT_EQ((*entries)[0].thumbnail->height, 80);
  EXPECT_EQ((*entries)[1].thumbnailState, ThumbnailState::Failed);
  EXPECT_NE((*entries)[1].thumbnailError.find("beta.png"), std::string::npos) << (*entries)[1].thumbnailError;

  const auto version = library.version();
  const auto saved = library.saveAs(voxflame::core::defaultScene(), "Gamma", solidThumbnail(200, 100, 1, 2, 3));
  EXPECT_EQ(saved, user / "Gamma.json");
  ASSERT_TRUE(waitIdle());
  EXPECT_GT(library.version(), version);
  entries = library.entries();
  ASSERT_EQ(entries->size(), 3u);
  EXPECT_EQ((*entries)[2].source, PresetSource::User);
  EXPECT_EQ((*entries)[2].displayName, "Gamma");
  EXPECT_EQ((*entries)[2].thumbnailState, ThumbnailState::Ready);
  EXPECT_EQ((*entries)[2].thumbnail->width, 160);
  // Entries handed out stay valid while the library rescans.
  library.refresh();
  EXPECT_EQ(entries->size(), 3u);
}
