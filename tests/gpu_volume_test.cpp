// The grid that stays on the GPU (gl/gpu_volume.h): a GPU backend sharing the renderer's context
// packs its grid there, and the renderer copies it on the GPU instead of uploading. The pack must
// be core::packVolume's, texel for texel, and what the renderer draws from it (shadows included)
// the picture an upload of the host pack draws.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/flame/image.h"
#include "core/image_metrics.h"
#include "core/mesh.h"
#include "core/packed_volume.h"
#include "core/scene_io.h"
#include "core/shadow_volume.h"
#include "gl/gpu_accumulator.h"
#include "gl/gpu_volume.h"
#include "gl/headless_context.h"
#include "gl/volume_renderer.h"
#include "pipeline.h"
#include "gl_test_support.h"

using namespace voxflame;

using test::bunnyMask;
using test::glAvailable;

namespace {

template <class T>
std::vector<T> readTexture(GLuint texture, GLenum format, GLenum type, std::size_t values) {
  std::vector<T> out(values);
  glBindTexture(GL_TEXTURE_3D, texture);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, format, type, out.data());
  return out;
}

// How many half floats differ by more than one unit in the last place (a GPU may round the
// conversion from float the other way).
std::size_t halvesApart(const std::vector<std::uint16_t>& a, const std::vector<std::uint16_t>& b) {
  std::size_t apart = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i])) > 1) ++apart;
  return apart;
}

gl::RenderSettings viewOf(const core::Scene& scene, const core::GridGeometry& grid, int width, int height) {
  gl::RenderSettings settings;
  settings.camera =
      core::orbitCamera(scene.camera, grid.box(), static_cast<double>(width) / static_cast<double>(height));
  settings.tone = scene.tone;
  settings.render = scene.render;
  return settings;
}

// The device path on every renderer, llvmpipe's included (it packs on the host there otherwise).
class GpuVolume : public ::testing::Test {
 protected:
  void SetUp() override { gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(true); }
  void TearDown() override { gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(false); }
};

// A backend sharing this thread's context, refined to `points` of the default preset's pattern.
struct SharedBackend {
  core::Scene scene = core::defaultScene();
  gl::GpuAccumulator backend;
  explicit SharedBackend(int resolution, std::uint64_t points = 600'000)
      : backend(bunnyMask(resolution), gl::currentShareGroup()) {
    backend.setTargetPoints(points);
    backend.setPattern(scene.layers, 5);
    EXPECT_TRUE(backend.waitUntilDone(120.0));
    backend.setHeld(true);
  }
};

}  // namespace

TEST_F(GpuVolume, APackOnTheGpuIsThePackOnTheHostTexelForTexel) {
  if (!glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  gl::HeadlessContext context;
  // 48³ keeps a colour cell per voxel; above 256³ a colour cell spans 2×2×2 voxels.
  for (const int resolution : {48, 258}) {
    SharedBackend refined(resolution, resolution > 256 ? 3'000'000 : 600'000);
    ASSERT_TRUE(refined.backend.sharesWithRenderer()) << "the backend's context could not share this one's";
    core::PackedVolume onHost, onDevice;
    ASSERT_TRUE(core::packVolumeOnHost(refined.backend, onHost));
    ASSERT_TRUE(core::packVolume(refined.backend, onDevice));
    ASSERT_TRUE(onDevice.onDevice());
    EXPECT_TRUE(onDevice.density.empty());
    EXPECT_EQ(onDevice.version, onHost.version);
    EXPECT_EQ(onDevice.points, onHost.points);
    EXPECT_DOUBLE_EQ(onDevice.referenceDensity, onHost.referenceDensity);
    EXPECT_EQ(onDevice.texelDensity, onHost.texelDensity);
    EXPECT_EQ(onDevice.brickCount, onHost.brickCount);
    EXPECT_EQ(onDevice.colour.size, onHost.colour.size);

    auto& device = dynamic_cast<gl::GpuVolume&>(*onDevice.device);
    glWaitSync(device.packed, 0, GL_TIMEOUT_IGNORED);
    const auto density =
        readTexture<std::uint16_t>(device.density, GL_RED, GL_HALF_FLOAT, onHost.geometry.voxelCount());
    const auto colours = readTexture<std::uint16_t>(device.colour, GL_RGBA, GL_HALF_FLOAT, onHost.colours.size());
    const auto distances =
        readTexture<std::uint8_t>(device.emptyDistance, GL_RED_INTEGER, GL_UNSIGNED_BYTE, onHost.emptyDistance.size());
    const auto occupied = static_cast<std::size_t>(
        std::count_if(onHost.density.begin(), onHost.density.end(), [](std::uint16_t half) { return half != 0; }));
    ASSERT_GT(occupied, onHost.density.size() / 50) << "the pattern barely fills the grid at " << resolution;
    EXPECT_EQ(halvesApart(density, onHost.density), 0u) << resolution;
    EXPECT_EQ(halvesApart(colours, onHost.colours), 0u) << resolution;
    EXPECT_EQ(distances, onHost.emptyDistance) << resolution;
    // Distances run from 0 (occupied) up, so the pattern leaves both kinds of brick.
    EXPECT_GT(*std::max_element(distances.begin(), distances.end()), 1);
  }
}

TEST_F(GpuVolume, TheRendererDrawsACopiedVolumeAsAnUploadedOneShadowsIncluded) {
  if (!glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  gl::HeadlessContext context;
  SharedBackend refined(64, 1'500'000);
  core::PackedVolume onHost, onDevice;
  ASSERT_TRUE(core::packVolumeOnHost(refined.backend, onHost));
  ASSERT_TRUE(core::packVolume(refined.backend, onDevice));
  ASSERT_TRUE(onDevice.onDevice());

  constexpr int kWidth = 160, kHeight = 120;
  core::Scene scene = refined.scene;
  scene.render.lighting = true;
  const gl::RenderSettings settings = viewOf(scene, onHost.geometry, kWidth, kHeight);
  const glm::dvec3 light = core::lightDirection(scene.render.lightAzimuthDeg, scene.render.lightElevationDeg);

  gl::VolumeRenderer uploaded;
  uploaded.upload(onHost);
  core::ShadowVolume shadow;
  ASSERT_TRUE(core::computeShadowVolume(onHost, light, core::kAbsorptionPerDensity, 2, shadow));
  uploaded.uploadShadow(shadow, 2);
  const core::ImageRGBA expected = gl::renderToImage(uploaded, settings, kWidth, kHeight);

  gl::VolumeRenderer copied;
  copied.upload(onDevice);
  EXPECT_EQ(copied.uploadedBytes(), 0u) << "nothing of a volume packed on the GPU goes through host memory";
  EXPECT_GT(copied.copiedBytes(), 0u);
  EXPECT_TRUE(copied.hasVolume());
  copied.computeShadow(gl::VolumeRenderer::Source::Main, light, core::kAbsorptionPerDensity, 2);
  EXPECT_TRUE(copied.hasShadow());
  const core::ImageRGBA drawn = gl::renderToImage(copied, settings, kWidth, kHeight);

  EXPECT_GT(core::ssimLuma(drawn, expected), 0.995);
  double difference = 0.0, total = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) {
        difference += std::abs(drawn.at(x, y)[c] - expected.at(x, y)[c]);
        total += expected.at(x, y)[c];
      }
  EXPECT_GT(total, 0.02 * kWidth * kHeight * 3) << "the picture is nearly black: the test shows nothing";
  EXPECT_LT(difference / total, 0.01);

  // The shadow matters: without it the picture is another.
  scene.render.lighting = false;
  const core::ImageRGBA unlit =
      gl::renderToImage(copied, viewOf(scene, onHost.geometry, kWidth, kHeight), kWidth, kHeight);
  double unlitDifference = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) unlitDifference += std::abs(unlit.at(x, y)[c] - drawn.at(x, y)[c]);
  EXPECT_GT(unlitDifference / total, 0.05);
}

TEST_F(GpuVolume, AVolumeWhoseBackendIsGoneIsNotDrawn) {
  if (!glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  gl::HeadlessContext context;
  core::PackedVolume onDevice;
  {
    SharedBackend refined(32, 100'000);
    ASSERT_TRUE(core::packVolume(refined.backend, onDevice));
    ASSERT_TRUE(onDevice.onDevice());
    gl::VolumeRenderer renderer;
    renderer.upload(onDevice);
    EXPECT_TRUE(renderer.hasVolume());
  }
  // The backend deleted its textures with its context; the volume still names them.
  EXPECT_FALSE(dynamic_cast<gl::GpuVolume&>(*onDevice.device).alive);
  gl::VolumeRenderer renderer;
  renderer.upload(onDevice);
  EXPECT_FALSE(renderer.hasVolume());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GpuVolume, ABackendWithoutTheRenderersContextPacksOnTheHost) {
  if (!glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  gl::GpuAccumulator backend(bunnyMask(32));
  const core::Scene scene = core::defaultScene();
  backend.setTargetPoints(50'000);
  backend.setPattern(scene.layers, 5);
  EXPECT_TRUE(backend.waitUntilDone(120.0));
  EXPECT_FALSE(backend.sharesWithRenderer());
  EXPECT_FALSE(backend.packsOnDevice());
  core::PackedVolume volume;
  ASSERT_TRUE(core::packVolume(backend, volume));
  EXPECT_FALSE(volume.onDevice());
  EXPECT_EQ(volume.density.size(), volume.geometry.voxelCount());
}

// A still under the GPU backend keeps its grid on the GPU from the backend to the renderer, and
// draws what the host path draws, shadows included.
TEST_F(GpuVolume, AStillOnTheGpuBackendKeepsItsGridOnTheGpu) {
  if (!glAvailable()) GTEST_SKIP() << "no headless OpenGL context here";
  core::Scene scene = core::defaultScene();
  scene.gridResolution = 64;
  scene.points = 1'500'000;
  scene.render.lighting = true;
  app::StillOptions options;
  options.width = 160;
  options.height = 120;
  options.backend = core::BackendKind::Gpu;
  const app::StillResult onDevice = app::renderStill(scene, options);
  EXPECT_TRUE(onDevice.gridOnDevice);
  gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(false);
  const app::StillResult onHost = app::renderStill(scene, options);
  EXPECT_FALSE(onHost.gridOnDevice);
  EXPECT_EQ(onDevice.stats.points, onHost.stats.points);
  EXPECT_GT(core::ssimLuma(onDevice.image, onHost.image), 0.99);
  double difference = 0.0, total = 0.0;
  for (std::size_t i = 0; i < onHost.image.pixels.size(); ++i) {
    difference += std::abs(onDevice.image.pixels[i] - onHost.image.pixels[i]);
    total += onHost.image.pixels[i];
  }
  EXPECT_GT(total, 0.0);
  EXPECT_LT(difference / total, 0.02);
}
