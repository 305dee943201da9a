// Golden images: shipped presets (attractors, a flame, an IFS, a quaternion Julia set) rendered small, compared with
// reference PNGs in tests/golden that were looked at and judged good. When a change to the picture is intended,
// scripts/update_golden.sh renders them again (VOXFLAME_UPDATE_GOLDEN=1); look at the new ones before committing them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "core/image_io.h"
#include "core/scene.h"
#include "pipeline.h"

using namespace voxflame;

namespace {

// Mean absolute difference per channel (display-encoded, 0–1) allowed, and the share of pixels
// that may differ by more than 0.1: covers driver and rounding differences, not a changed look.
// A render matches its reference within about 0.0005; the points and the volume render of the
// same preset differ by 0.0038 (the flame) to 0.013, so the mean alone tells the methods apart.
constexpr double kMeanTolerance = 0.002;
constexpr double kOutlierShare = 0.01;

struct Golden {
  const char* preset;
  core::RenderMethod method;
};

class GoldenImage : public ::testing::TestWithParam<Golden> {};

}  // namespace

TEST_P(GoldenImage, MatchesTheReference) {
  const Golden golden = GetParam();
  const std::filesystem::path source(VOXFLAME_SOURCE_DIR);
  core::Scene scene = core::loadScene(source / "presets" / (std::string(golden.preset) + ".json"));
  scene.render.method = golden.method;
  scene.render.samples = 1;
  scene.render.oversample = 1;
  scene.gridResolution = std::min(scene.gridResolution, 128);
  app::StillOptions options;
  options.width = 200;
  options.height = 125;
  options.points = 3'000'000;
  options.threads = 2;
  options.chunks = app::ChunkPlan{};  // as `voxflame render` splits every still
  const core::ImageRGBA image = app::renderStill(scene, options).image;
  const std::filesystem::path reference =
      source / "tests" / "golden" /
      (std::string(golden.preset) + "-" + std::string(core::toString(golden.method)) + ".png");
  if (std::getenv("VOXFLAME_UPDATE_GOLDEN")) {
    core::writePng(reference, image, 8, {});
    GTEST_SKIP() << "wrote " << reference;
  }
  ASSERT_TRUE(std::filesystem::exists(reference)) << reference << " is missing: run scripts/update_golden.sh";
  const core::ImageRGBA expected = core::readPng(reference).image;
  ASSERT_EQ(expected.width, image.width);
  ASSERT_EQ(expected.height, image.height);
  double sum = 0.0;
  std::size_t outliers = 0, pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(static_cast<double>(image.pixels[4 * p + c]) - expected.pixels[4 * p + c]);
      sum += d;
      worst = std::max(worst, d);
    }
    outliers += worst > 0.1 ? 1 : 0;
  }
  EXPECT_LT(sum / (3.0 * static_cast<double>(pixels)), kMeanTolerance) << reference;
  EXPECT_LT(static_cast<double>(outliers) / static_cast<double>(pixels), kOutlierShare) << reference;
}

INSTANTIATE_TEST_SUITE_P(
    Presets, GoldenImage,
    ::testing::Values(
        Golden{"default", core::RenderMethod::Volume}, Golden{"default", core::RenderMethod::Points},
        Golden{"thomas-pinwheel", core::RenderMethod::Volume}, Golden{"thomas-pinwheel", core::RenderMethod::Points},
        Golden{"lorenz-heart", core::RenderMethod::Volume}, Golden{"lorenz-heart", core::RenderMethod::Points},
        Golden{"flame-silk-bunny", core::RenderMethod::Volume}, Golden{"flame-silk-bunny", core::RenderMethod::Points},
        Golden{"sierpinski-orb", core::RenderMethod::Volume}, Golden{"qjulia-cage-orb", core::RenderMethod::Volume}),
    [](const auto& param) {
      std::string name = std::string(param.param.preset) + "_" + std::string(core::toString(param.param.method));
      for (char& c : name)
        if (c == '-') c = '_';
      return name;
    });
