// The GPU's finish (gl/flame_finisher.h) held to core::finishImage, the reference: on the golden
// scenes' own sums (both methods; oversample 2, density estimation on and off, mesh ghost and
// silhouette, linear output) and on synthetic images finished in tiles, with the quad fallback.
// Within 1/255 per channel on 99.9% of the pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "core/flame/image.h"
#include "core/packed_volume.h"
#include "gl/canvas.h"
#include "gl/flame_finisher.h"
#include "gl/headless_context.h"
#include "gl/volume_renderer.h"
#include "pipeline.h"

using namespace voxflame;

namespace {

constexpr double kChannelTolerance = 1.0 / 255.0;
constexpr double kShareWithin = 0.999;

// The share of pixels whose channels (and opacity) all lie within 1/255 of the reference's
// (relative to the value where linear light exceeds 1).
double shareWithin(const core::FinishedImage& gpu, const core::FinishedImage& cpu, double* worst = nullptr) {
  EXPECT_EQ(gpu.image.width, cpu.image.width);
  EXPECT_EQ(gpu.image.height, cpu.image.height);
  const std::size_t pixels = static_cast<std::size_t>(cpu.image.width) * cpu.image.height;
  if (gpu.image.pixels.size() != cpu.image.pixels.size() || pixels == 0) return 0.0;
  std::size_t within = 0;
  double most = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    double pixelWorst = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double reference = cpu.image.pixels[4 * p + c];
      const double d = std::abs(gpu.image.pixels[4 * p + c] - reference) / std::max(1.0, std::abs(reference));
      pixelWorst = std::max(pixelWorst, d);
    }
    pixelWorst = std::max(pixelWorst, static_cast<double>(std::abs(gpu.alpha[p] - cpu.alpha[p])));
    most = std::max(most, pixelWorst);
    within += pixelWorst <= kChannelTolerance ? 1 : 0;
  }
  if (worst) *worst = most;
  return static_cast<double>(within) / static_cast<double>(pixels);
}

struct Variant {
  const char* name;
  int oversample;
  bool estimator;
  core::MeshDisplay mesh;
  bool linear;
};

constexpr Variant kVariants[] = {
    {"plain", 1, true, core::MeshDisplay::Off, false},
    {"no-estimator", 1, false, core::MeshDisplay::Off, false},
    {"oversample-2", 2, true, core::MeshDisplay::Off, false},
    {"oversample-2-no-estimator", 2, false, core::MeshDisplay::Ghost, false},
    {"ghost", 1, true, core::MeshDisplay::Ghost, false},
    {"silhouette", 2, true, core::MeshDisplay::Silhouette, false},
    {"linear", 1, true, core::MeshDisplay::Off, true},
};

struct GoldenScene {
  const char* preset;
  core::RenderMethod method;
};

class GpuFinishGolden : public ::testing::TestWithParam<GoldenScene> {};

// A synthetic supersampled density image: sparse specks (wide kernels) over a dense blob (narrow
// ones), some at the edges so weight piles there.
core::DensityImage syntheticDensity(int width, int height, double hitsPerUnit) {
  core::DensityImage density;
  density.resize(width, height);
  density.hitsPerUnitDensity = hitsPerUnit;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double dx = (x - 0.4 * width) / (0.25 * width), dy = (y - 0.6 * height) / (0.3 * height);
      float d = static_cast<float>(2.0 * std::exp(-(dx * dx + dy * dy)));
      if (d < 0.05f) d = unit(random) < 0.03f ? 0.02f * unit(random) : 0.0f;
      if (x == 0 || y == height - 1) d = unit(random) < 0.2f ? 0.01f : d;
      float* v = density.at(x, y);
      v[0] = d * unit(random);
      v[1] = d * 0.5f;
      v[2] = d * (1.0f - 0.5f * unit(random));
      v[3] = d;
    }
  return density;
}

}  // namespace

TEST(GpuFinishStrips, APictureFinishedInStripsIsThePictureFinishedWhole) {
  // The live view finishes a points picture a strip at a time (VolumeRenderer::finishStrip) while
  // the last whole one stays up; the strips, each with its apron, make the same pixels as one
  // finish of the whole (the sums supersampled, as the points method makes them).
  gl::HeadlessContext context;
  gl::VolumeRenderer renderer;
  constexpr int kOversample = 2, kOutWidth = 90, kOutHeight = 70;
  const core::DensityImage density = syntheticDensity(kOutWidth * kOversample, kOutHeight * kOversample, 40.0);
  gl::RenderSettings settings;
  settings.tone.estimatorRadius = 6.0;
  settings.tone.estimatorMinimum = 0.0;
  settings.tone.background = glm::vec3(0.05f, 0.0f, 0.1f);
  settings.render.filterRadius = 0.8;
  gl::Canvas whole(kOutWidth, kOutHeight), strips(kOutWidth, kOutHeight);
  ASSERT_TRUE(whole.complete() && strips.complete());
  gl::FrameTarget wholeTarget, stripTarget;
  wholeTarget.setSums(density, kOversample);
  EXPECT_EQ(wholeTarget.width(), kOutWidth);
  EXPECT_EQ(wholeTarget.height(), kOutHeight);
  glBindFramebuffer(GL_FRAMEBUFFER, whole.framebuffer());
  renderer.resolve(wholeTarget, settings, glm::ivec4(0, 0, kOutWidth, kOutHeight), false);

  stripTarget.setSums(density, kOversample);
  EXPECT_FALSE(renderer.drawFinished(stripTarget, glm::ivec4(0, 0, kOutWidth, kOutHeight)))
      << "nothing is whole before the last strip";
  int calls = 1;
  while (!renderer.finishStrip(stripTarget, settings, 8)) ++calls;
  EXPECT_EQ(calls, (kOutHeight + 7) / 8) << "one strip of 8 rows a call";
  EXPECT_TRUE(renderer.finishStrip(stripTarget, settings, 8)) << "a finished picture is not finished again";
  glBindFramebuffer(GL_FRAMEBUFFER, strips.framebuffer());
  ASSERT_TRUE(renderer.drawFinished(stripTarget, glm::ivec4(0, 0, kOutWidth, kOutHeight)));

  const std::vector<std::uint8_t> a = whole.pixels(), b = strips.pixels();
  ASSERT_EQ(a.size(), b.size());
  std::size_t differing = 0, lit = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    differing += std::abs(int(a[i]) - int(b[i])) > 1 ? 1 : 0;
    lit += a[i] > 40 ? 1 : 0;
  }
  EXPECT_GT(lit, a.size() / 20) << "the picture shows the density";
  EXPECT_LE(differing, a.size() / 1000) << "the strips' seams show";

  // New sums: the old whole picture stays drawn until the new one is whole.
  core::DensityImage brighter = density;
  for (float& value : brighter.values) value *= 4.0f;
  stripTarget.setSums(brighter, kOversample);
  EXPECT_FALSE(renderer.finishStrip(stripTarget, settings, 8));
  glBindFramebuffer(GL_FRAMEBUFFER, strips.framebuffer());
  ASSERT_TRUE(renderer.drawFinished(stripTarget, glm::ivec4(0, 0, kOutWidth, kOutHeight)));
  EXPECT_EQ(strips.pixels(), b) << "a half-finished picture was drawn";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_P(GpuFinishGolden, AgreesWithTheCpuReference) {
  const GoldenScene golden = GetParam();
  const std::filesystem::path source(VOXFLAME_SOURCE_DIR);
  core::Scene scene = core::loadScene(source / "presets" / (std::string(golden.preset) + ".json"));
  scene.render.method = golden.method;
  scene.render.samples = 1;
  scene.gridResolution = std::min(scene.gridResolution, 128);
  app::StillOptions options;
  options.width = 200;
  options.height = 125;
  options.points = 3'000'000;
  options.threads = 2;
  const app::SceneShape shape = app::buildSceneShape(scene);
  core::PackedVolume volume;
  {
    const app::AccumulatedVolume accumulated = app::accumulateVolume(scene, shape, options);
    core::packVolume(accumulated.snapshot, volume);
  }
  app::FrameRenderer renderer;
  renderer.setVolume(volume, shape);
  renderer.setPointsPass(1'000'000, 2);
  renderer.keepSums(true);
  for (const Variant& variant : kVariants) {
    SCOPED_TRACE(variant.name);
    core::Scene look = scene;
    look.render.oversample = variant.oversample;
    look.render.meshDisplay = variant.mesh;
    if (!variant.estimator) look.tone.estimatorRadius = 0.0;
    const app::FrameRenderer::Rendered rendered =
        renderer.renderWithStats(look, options.width, options.height, variant.linear);
    core::FinishSettings finish;
    finish.tone = look.tone;
    finish.oversample = variant.oversample;
    finish.filterRadius = look.render.filterRadius;
    finish.linearOutput = variant.linear;
    const core::FinishedImage reference = core::finishImage(rendered.density, finish, &rendered.mesh);
    core::FinishedImage gpu;
    gpu.image = rendered.image;
    // The pipeline keeps only the picture; the opacity is checked by the synthetic tests.
    gpu.alpha = reference.alpha;
    double worst = 0.0;
    EXPECT_GE(shareWithin(gpu, reference, &worst), kShareWithin) << "worst difference " << worst;
    double opacity = 0.0;
    for (float a : reference.alpha) opacity += a;
    EXPECT_GT(opacity, 0.01 * static_cast<double>(reference.alpha.size())) << "the pattern shows";
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, GpuFinishGolden,
                         ::testing::Values(GoldenScene{"default", core::RenderMethod::Volume},
                                           GoldenScene{"default", core::RenderMethod::Points},
                                           GoldenScene{"thomas-pinwheel", core::RenderMethod::Volume},
                                           GoldenScene{"thomas-pinwheel", core::RenderMethod::Points},
                                           GoldenScene{"lorenz-heart", core::RenderMethod::Volume},
                                           GoldenScene{"lorenz-heart", core::RenderMethod::Points},
                                           GoldenScene{"flame-silk-bunny", core::RenderMethod::Volume},
                                           GoldenScene{"flame-silk-bunny", core::RenderMethod::Points},
                                           GoldenScene{"sierpinski-orb", core::RenderMethod::Volume},
                                           GoldenScene{"qjulia-cage-orb", core::RenderMethod::Volume}),
                         [](const auto& param) {
                           std::string name =
                               std::string(param.param.preset) + "_" + std::string(core::toString(param.param.method));
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

class GpuFinish : public ::testing::Test {
 protected:
  gl::HeadlessContext context;
  gl::FlameFinisher finisher;
};

constexpr gl::FlameFinisher::Estimation kEstimations[] = {gl::FlameFinisher::Estimation::Scatter,
                                                          gl::FlameFinisher::Estimation::Gather};

TEST_F(GpuFinish, TilesWithApronsAndTheQuadFallbackMatchTheReference) {
  for (int oversample : {1, 3})
    for (const auto estimation : kEstimations) {
      SCOPED_TRACE(oversample);
      SCOPED_TRACE(estimation == gl::FlameFinisher::Estimation::Gather ? "gather, compute passes" : "scatter, drawn");
      // The GPU's way (gathered, compute passes) and the software rasteriser's (sprites, drawn).
      finisher.setEstimation(estimation);
      finisher.setComputePasses(estimation == gl::FlameFinisher::Estimation::Gather);
      const core::DensityImage density = syntheticDensity(90 * oversample, 70 * oversample, 40.0);
      core::FinishSettings finish;
      finish.tone.estimatorRadius = 6.0;
      finish.tone.estimatorMinimum = 0.0;
      finish.tone.background = glm::vec3(0.05f, 0.0f, 0.1f);
      finish.tone.highlightPower = 0.5;
      finish.tone.vibrancy = 0.8;
      finish.oversample = oversample;
      finish.filterRadius = 0.8;
      core::MeshOverlay overlay;
      overlay.mode = core::MeshDisplay::Silhouette;
      overlay.color = glm::vec3(0.2f, 0.9f, 0.4f);
      overlay.width = 90;
      overlay.height = 70;
      overlay.rgba.assign(4 * 90 * 70, 0);
      for (int y = 20; y < 50; ++y)
        for (int x = 10; x < 60; ++x) overlay.rgba[4 * (static_cast<std::size_t>(y) * 90 + x) + 3] = 255;
      const core::FinishedImage reference = core::finishImage(density, finish, &overlay);
      // One tile, then tiles much smaller than the aprons, then quads instead of point sprites.
      for (int maxTile : {4096, 16}) {
        SCOPED_TRACE(maxTile);
        EXPECT_GE(shareWithin(gl::finishImageOnGpu(finisher, density, finish, &overlay, maxTile), reference),
                  kShareWithin);
      }
      finisher.forceQuads(true);
      EXPECT_GE(shareWithin(gl::finishImageOnGpu(finisher, density, finish, &overlay, 40), reference), kShareWithin);
      finisher.forceQuads(false);
    }
}

TEST_F(GpuFinish, WideKernelsPileTheirWeightOnTheEdges) {
  // The estimator's widest setting at oversample 4: kernels far wider than the image's border
  // (a radius of 81 supersampled pixels at the faintest pixels, in an image of 80 × 48). The GPU's
  // cost grows with the pixels times the kernel's area, so the image is kept small (half the
  // 160 × 96 it was, a fifth of the time): the widest kernels still cross the whole of it, and a
  // 99.9% share of 240 output pixels still leaves no pixel out.
  const core::DensityImage density = syntheticDensity(20 * 4, 12 * 4, 0.5);
  core::FinishSettings finish;
  finish.tone.estimatorRadius = 20.0;
  finish.tone.estimatorMinimum = 2.0;
  finish.tone.estimatorCurve = 0.6;
  finish.oversample = 4;
  finish.filterRadius = 1.5;
  finish.linearOutput = true;
  const core::FinishedImage reference = core::finishImage(density, finish);
  for (const auto estimation : kEstimations) {
    SCOPED_TRACE(estimation == gl::FlameFinisher::Estimation::Gather ? "gather" : "scatter");
    finisher.setEstimation(estimation);
    finisher.setComputePasses(estimation == gl::FlameFinisher::Estimation::Scatter);  // the other pairing
    double worst = 0.0;
    EXPECT_GE(shareWithin(gl::finishImageOnGpu(finisher, density, finish, nullptr), reference, &worst), kShareWithin)
        << worst;
    EXPECT_GE(shareWithin(gl::finishImageOnGpu(finisher, density, finish, nullptr, 64), reference, &worst),
              kShareWithin)
        << worst;
  }
}

TEST_F(GpuFinish, GatheringGivesTheFloatsScatteringGives) {
  // The gather adds each pixel's shares in the order the sprites' blending adds them and computes
  // each share alike, so the two estimations agree to the float's last bits, or very nearly
  // where a driver contracts a multiply-add differently in the two stages; and so do the fold
  // and the tone as compute passes and drawn.
  const core::DensityImage density = syntheticDensity(2 * 120, 2 * 80, 25.0);
  core::FinishSettings finish;
  finish.tone.estimatorRadius = 9.0;
  finish.tone.estimatorMinimum = 0.0;
  finish.oversample = 2;
  finish.filterRadius = 1.0;
  finish.linearOutput = true;
  finisher.setEstimation(gl::FlameFinisher::Estimation::Scatter);
  finisher.setComputePasses(false);
  const core::FinishedImage scattered = gl::finishImageOnGpu(finisher, density, finish, nullptr);
  finisher.setEstimation(gl::FlameFinisher::Estimation::Gather);
  finisher.setComputePasses(true);
  const core::FinishedImage gathered = gl::finishImageOnGpu(finisher, density, finish, nullptr);
  ASSERT_EQ(scattered.image.pixels.size(), gathered.image.pixels.size());
  double worst = 0.0, lit = 0.0;
  for (std::size_t i = 0; i < scattered.image.pixels.size(); ++i) {
    const double a = scattered.image.pixels[i], b = gathered.image.pixels[i];
    worst = std::max(worst, std::abs(a - b) / std::max(1e-3, std::abs(a)));
    lit += a;
  }
  EXPECT_LE(worst, 1e-5);
  EXPECT_GT(lit, 0.0) << "the picture is not empty";
}
