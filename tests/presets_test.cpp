// The shipped preset library (presets/*.json): found on disk when the tests run (CTest runs this
// executable as one test), so a preset added to the folder is covered without touching this file
// or rebuilding. Each one must load, cover the
// catalogue's seed attractors as a set, and render a small image that is neither empty nor
// blown out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/color.h"
#include "core/scene.h"
#include "pipeline.h"
#include "test_support.h"

using namespace voxflame;

namespace {

std::vector<std::filesystem::path> shippedPresets() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("presets")))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// gtest parameter names allow only letters, digits and underscores.
std::string testName(const std::filesystem::path& file) {
  std::string name = file.stem().string();
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

}  // namespace

TEST(ShippedPresets, AtLeastEighteenWithEverySeedAttractorAndUniqueNames) {
  const std::vector<std::filesystem::path> files = shippedPresets();
  EXPECT_GE(files.size(), 18u);
  std::set<std::string> attractors;
  std::map<std::string, std::string> fileOfName;
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const core::Scene scene = core::loadScene(file);
    EXPECT_NE(scene.name, "untitled") << "a preset needs a name a user would like to see";
    const auto [previous, inserted] = fileOfName.emplace(scene.name, file.filename().string());
    EXPECT_TRUE(inserted) << "name '" << scene.name << "' is also used by " << previous->second;
    EXPECT_TRUE(std::filesystem::is_regular_file(scene.resolvedMeshPath())) << scene.resolvedMeshPath();
    for (const auto& layer : scene.layers) attractors.insert(layer.attractor);
  }
  for (const char* seed : {"lorenz", "lorenz84", "pickover", "polynomial_a", "polynomial_b", "polynomial_c"})
    EXPECT_TRUE(attractors.count(seed)) << "no shipped preset uses the seed attractor " << seed;
}

TEST(ShippedPresets, TenChaosGamePresetsWithFlamesJuliaSetsAndIfsFractalsThreeAnimated) {
  int chaos = 0, flames = 0, julia = 0, animated = 0, affineOnly = 0;
  for (const auto& file : shippedPresets()) {
    const core::Scene scene = core::loadScene(file);
    bool isChaos = false;
    for (const auto& layer : scene.layers) {
      if (!layer.isChaosGame()) continue;
      isChaos = true;
      flames += layer.kind == core::PatternKind::Flame ? 1 : 0;
      julia += layer.kind == core::PatternKind::QuaternionJulia ? 1 : 0;
      // A classic IFS: every transform an affine map alone (linear variation).
      bool onlyAffine = layer.kind == core::PatternKind::Flame;
      for (const auto& xform : layer.flame.xforms)
        for (const auto& term : xform.variations) onlyAffine = onlyAffine && term.name == "linear";
      affineOnly += onlyAffine ? 1 : 0;
    }
    chaos += isChaos ? 1 : 0;
    animated += isChaos && !scene.keyframes.empty() ? 1 : 0;
  }
  EXPECT_GE(chaos, 10);
  EXPECT_GE(flames, 5);
  EXPECT_GE(julia, 2);
  EXPECT_GE(affineOnly, 3);  // Menger sponge, Sierpiński tetrahedron, fern
  EXPECT_GE(animated, 3);
}

namespace {

// What a small still shows: pixels that differ from the background, and pixels blown out to white.
struct PixelCounts {
  int pixels = 0;
  int lit = 0;
  int white = 0;
};

// A still at a size the suite can afford (64×48, a 48-voxel grid, 300,000 points) with the mesh
// display off, so that what lights up is the pattern itself.
PixelCounts renderSmall(core::Scene scene, std::string* warning = nullptr) {
  scene.gridResolution = 48;
  scene.render.meshDisplay = core::MeshDisplay::Off;
  scene.render.samples = 1;
  app::StillOptions options;
  options.width = 64;
  options.height = 48;
  options.points = 300'000;
  const app::StillResult result = app::renderStill(scene, options);
  if (warning) *warning = result.warning;
  const glm::vec3 background = core::linearToSrgb(scene.tone.background);
  PixelCounts counts;
  for (int y = 0; y < result.image.height; ++y)
    for (int x = 0; x < result.image.width; ++x) {
      const float* p = result.image.at(x, y);
      const float difference =
          std::max({std::abs(p[0] - background.x), std::abs(p[1] - background.y), std::abs(p[2] - background.z)});
      ++counts.pixels;
      counts.lit += difference > 0.1f;
      counts.white += std::min({p[0], p[1], p[2]}) > 0.95f;
    }
  return counts;
}

bool blownOut(const PixelCounts& counts) {
  return counts.white >= std::max(1, counts.lit / 10);
}

}  // namespace

TEST(ShippedPresets, TheBlownOutCheckCatchesAnOverexposedRender) {
  core::Scene scene = core::loadScene(test::sourcePath("presets/default.json"));
  scene.tone.exposure = 12.0;
  scene.tone.highlightPower = 1.0;
  EXPECT_TRUE(blownOut(renderSmall(scene)));
}

class ShippedPreset : public testing::TestWithParam<std::filesystem::path> {};

TEST_P(ShippedPreset, RendersSmallNeitherEmptyNorBlownOut) {
  std::string warning;
  const PixelCounts counts = renderSmall(core::loadScene(GetParam()), &warning);
  ASSERT_EQ(counts.pixels, 64 * 48);
  EXPECT_EQ(warning, "") << "the pattern should land inside the mesh";
  EXPECT_GT(counts.lit, counts.pixels / 50) << "too few pixels differ from the background";
  EXPECT_FALSE(blownOut(counts)) << counts.white << " of " << counts.lit << " lit pixels are blown out to white";
}

INSTANTIATE_TEST_SUITE_P(Library, ShippedPreset, testing::ValuesIn(shippedPresets()),
                         [](const testing::TestParamInfo<std::filesystem::path>& param) {
                           return testName(param.param);
                         });
