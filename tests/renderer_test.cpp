// The ray-marcher and tone mapping against analytic expectations, headless through EGL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/camera.h"
#include "core/color.h"
#include "core/error.h"
#include "core/flame/image.h"
#include "core/packed_volume.h"
#include "gl/canvas.h"
#include "gl/headless_context.h"
#include "gl/read_back.h"
#include "gl/shader_program.h"
#include "gl/volume_renderer.h"
#include "test_shapes.h"

using namespace voxflame;

namespace {

constexpr int kCube = 32;

// A grid of kCube³ unit voxels, every one holding the same density and colour.
core::PackedVolume uniformCube(std::uint8_t red = 255, std::uint8_t green = 255, std::uint8_t blue = 255) {
  core::VolumeSnapshot snapshot;
  snapshot.geometry.size = glm::ivec3(kCube);
  snapshot.geometry.origin = glm::dvec3(0.0);
  snapshot.geometry.voxelSize = 1.0;
  const std::size_t voxels = snapshot.geometry.voxelCount();
  snapshot.density.assign(voxels, 10.0f);
  snapshot.rgba.resize(4 * voxels);
  for (std::size_t v = 0; v < voxels; ++v) {
    snapshot.rgba[4 * v] = red;
    snapshot.rgba[4 * v + 1] = green;
    snapshot.rgba[4 * v + 2] = blue;
    snapshot.rgba[4 * v + 3] = 255;
  }
  snapshot.maxDensity = 10.0f;
  snapshot.version = 1;
  core::PackedVolume volume;
  core::packVolume(snapshot, volume);
  return volume;
}

// Tone mapping without gamma, threshold or density estimation: pixel = brightness · log(1 + k2 D).
core::ToneMapSettings neutralTone(double brightness) {
  core::ToneMapSettings tone;
  tone.brightness = brightness;
  tone.gamma = 1.0;
  tone.gammaThreshold = 0.0;
  tone.vibrancy = 1.0;
  tone.highlightPower = -1.0;
  tone.contrast = 1.0;
  tone.exposure = 0.0;
  tone.opacity = 1.0;
  tone.background = glm::vec3(0.0f);
  tone.estimatorRadius = 0.0;
  return tone;
}

// The marched column density D at the image's centre (flame/image.h).
double centreDensity(gl::VolumeRenderer& renderer, const gl::RenderSettings& settings, int size = 16) {
  const gl::MarchedImage marched = gl::marchImage(renderer, settings, size, size);
  return marched.density.at(size / 2, size / 2)[3];
}

gl::RenderSettings frontView(const core::GridGeometry& grid, core::ToneMapSettings tone) {
  core::CameraSettings camera;
  camera.azimuthDeg = 0.0;  // eye on +z looking down −z, straight through the cube
  camera.elevationDeg = 0.0;
  camera.projection = core::Projection::Orthographic;
  camera.orthoHeight = 0.5;  // only the cube's middle
  gl::RenderSettings settings;
  settings.camera = core::orbitCamera(camera, grid.box(), 1.0);
  settings.tone = tone;
  settings.render.stepVoxels = 0.25;
  return settings;
}

float centre(const core::ImageRGBA& image, int channel = 0) {
  return image.at(image.width / 2, image.height / 2)[channel];
}

float luminance(const float* p) {
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// Settings that look at `box` from azimuth and elevation (degrees) at `distance` radii, with a
// neutral tone of `brightness`.
gl::RenderSettings orbitView(const core::Box& box, double azimuthDeg, double elevationDeg, double aspect,
                             double brightness = 0.5, double distance = core::CameraSettings{}.distance) {
  core::CameraSettings camera;
  camera.azimuthDeg = azimuthDeg;
  camera.elevationDeg = elevationDeg;
  camera.distance = distance;
  gl::RenderSettings settings;
  settings.camera = core::orbitCamera(camera, box, aspect);
  settings.tone = neutralTone(brightness);
  return settings;
}

class Renderer : public ::testing::Test {
 protected:
  void marchInBandsOfRows();
  // Uploads a tinted uniform cube and returns settings that look at it from above and aside
  // (35°, 20°) with a neutral tone: rays of every length cross it.
  gl::RenderSettings uploadObliqueCube() {
    const core::PackedVolume cube = uniformCube(200, 120, 255);
    renderer.upload(cube);
    return orbitView(cube.geometry.box(), 35.0, 20.0, 1.5);
  }

  gl::HeadlessContext context;
  gl::VolumeRenderer renderer;
};

}  // namespace

TEST_F(Renderer, UniformCubeMatchesAnalyticColumnDensity) {
  // A uniform cube: density relative to the mean is 1 everywhere and the ray crosses one grid
  // side, so D = ∫ T dD = (1 − e^(−a)) / a with absorption a, and exactly 1 with none.
  const core::PackedVolume cube = uniformCube();
  renderer.upload(cube);
  for (double opacity : {0.0, 0.25, 1.0}) {
    auto tone = neutralTone(1.0);
    tone.opacity = opacity;
    const double a = opacity * core::kAbsorptionPerDensity;
    const double expected = a > 0.0 ? (1.0 - std::exp(-a)) / a : 1.0;
    EXPECT_NEAR(centreDensity(renderer, frontView(cube.geometry, tone)), expected, 0.01 * expected)
        << "opacity " << opacity;
  }
}

TEST_F(Renderer, FinishedPixelIsTheLogOfTheColumnDensity) {
  const core::PackedVolume cube = uniformCube();
  renderer.upload(cube);
  auto tone = neutralTone(0.2);
  tone.opacity = 0.0;
  const core::ImageRGBA image = gl::renderToImage(renderer, frontView(cube.geometry, tone), 16, 16, true);
  EXPECT_NEAR(centre(image), core::logDensity(1.0, tone), 0.01 * core::logDensity(1.0, tone));
}

TEST_F(Renderer, NearPlaneCutsThroughTheVolume) {
  const core::PackedVolume cube = uniformCube();
  renderer.upload(cube);
  auto tone = neutralTone(1.0);
  tone.opacity = 0.0;
  auto settings = frontView(cube.geometry, tone);
  const double whole = centreDensity(renderer, settings);
  // Put the near plane through the cube's centre: rays see only its far half.
  core::CameraSettings camera;
  camera.azimuthDeg = 0.0;
  camera.elevationDeg = 0.0;
  camera.projection = core::Projection::Orthographic;
  camera.orthoHeight = 0.5;
  camera.nearClip = camera.distance;
  settings.camera = core::orbitCamera(camera, cube.geometry.box(), 1.0);
  const double half = centreDensity(renderer, settings);
  EXPECT_NEAR(whole, 1.0, 0.01);
  EXPECT_NEAR(half, 0.5, 0.01);
}

TEST_F(Renderer, LookingStraightUpAndDownSeesTheVolume) {
  const core::PackedVolume cube = uniformCube();
  renderer.upload(cube);
  for (double elevation : {90.0, -90.0}) {
    core::CameraSettings camera;
    camera.elevationDeg = elevation;
    gl::RenderSettings settings;
    settings.camera = core::orbitCamera(camera, cube.geometry.box(), 1.0);
    settings.tone = neutralTone(3.0);
    EXPECT_GT(centre(gl::renderToImage(renderer, settings, 16, 16)), 0.5) << "elevation " << elevation;
  }
}

TEST_F(Renderer, ToneParametersMovePixelsTheExpectedWay) {
  const core::PackedVolume cube = uniformCube(255, 80, 40);
  renderer.upload(cube);
  const auto base = neutralTone(2.0);
  auto value = [&](const core::ToneMapSettings& tone) {
    return luminance(gl::renderToImage(renderer, frontView(cube.geometry, tone), 8, 8).at(4, 4));
  };
  const float reference = value(base);
  ASSERT_GT(reference, 0.05f);
  ASSERT_LT(reference, 0.9f);
  auto with = [&](auto change) {
    core::ToneMapSettings tone = base;
    change(tone);
    return value(tone);
  };
  EXPECT_GT(with([](auto& t) { t.brightness = 4.0; }), reference);
  EXPECT_GT(with([](auto& t) { t.exposure = 1.0; }), reference);
  EXPECT_LT(with([](auto& t) { t.exposure = -1.0; }), reference);
  EXPECT_GT(with([](auto& t) { t.gamma = 2.2; }), reference);     // gamma lifts partial opacity
  EXPECT_LT(with([](auto& t) { t.contrast = 2.0; }), reference);  // below mid grey goes darker
  EXPECT_GT(with([](auto& t) { t.background = glm::vec3(1.0f); }), reference);
  // Vibrancy 0 applies gamma per channel instead of to opacity.
  EXPECT_NE(with([](auto& t) {
              t.gamma = 2.2;
              t.vibrancy = 0.0;
            }),
            with([](auto& t) { t.gamma = 2.2; }));
}

TEST_F(Renderer, HighlightPowerDesaturatesOverexposedColour) {
  const core::PackedVolume cube = uniformCube(255, 80, 40);
  renderer.upload(cube);
  auto tone = neutralTone(3.0);
  tone.exposure = 1.0;  // red overexposed, green and blue not
  tone.highlightPower = -1.0;
  const core::ImageRGBA clipped = gl::renderToImage(renderer, frontView(cube.geometry, tone), 8, 8);
  tone.highlightPower = 1.0;
  const core::ImageRGBA faded = gl::renderToImage(renderer, frontView(cube.geometry, tone), 8, 8);
  // Clipping keeps the hue saturated; highlight power ≥ 0 moves it toward white.
  EXPECT_LT(clipped.at(4, 4)[2], faded.at(4, 4)[2]);
  EXPECT_NEAR(faded.at(4, 4)[0], 1.0f, 0.01f);
}

TEST_F(Renderer, TiledAndSampledRendersMatchOneTile) {
  gl::RenderSettings settings = uploadObliqueCube();
  settings.tone.gamma = 2.2;
  settings.tone.estimatorRadius = 9.0;  // density estimation must not see tile seams either
  settings.render.samples = 3;
  const core::ImageRGBA whole = gl::renderToImage(renderer, settings, 60, 40, false, 2048);
  const core::ImageRGBA tiled = gl::renderToImage(renderer, settings, 60, 40, false, 16);
  ASSERT_EQ(whole.pixels.size(), tiled.pixels.size());
  double maxDifference = 0.0;
  for (std::size_t i = 0; i < whole.pixels.size(); ++i)
    maxDifference = std::max(maxDifference, static_cast<double>(std::abs(whole.pixels[i] - tiled.pixels[i])));
  EXPECT_LT(maxDifference, 0.02);
  // Rendering twice gives the same image, bit for bit.
  const core::ImageRGBA again = gl::renderToImage(renderer, settings, 60, 40, false, 2048);
  EXPECT_EQ(whole.pixels, again.pixels);
}

TEST_F(Renderer, EmptyBricksAreSkippedWithoutChangingTheImage) {
  // A single dense voxel in an otherwise empty grid: brick skipping must still find it.
  core::VolumeSnapshot snapshot;
  snapshot.geometry.size = glm::ivec3(64);
  snapshot.geometry.voxelSize = 1.0;
  snapshot.density.assign(snapshot.geometry.voxelCount(), 0.0f);
  snapshot.rgba.assign(4 * snapshot.geometry.voxelCount(), 255);
  snapshot.density[snapshot.geometry.index(40, 32, 32)] = 50.0f;
  snapshot.maxDensity = 50.0f;
  snapshot.version = 1;
  core::PackedVolume volume;
  core::packVolume(snapshot, volume);
  EXPECT_LT(std::count(volume.occupancy.begin(), volume.occupancy.end(), 1), 10);
  renderer.upload(volume);
  core::CameraSettings camera;
  camera.azimuthDeg = 0.0;
  camera.elevationDeg = 0.0;
  camera.projection = core::Projection::Orthographic;
  camera.orthoHeight = 1.0;
  gl::RenderSettings settings;
  settings.camera = core::orbitCamera(camera, snapshot.geometry.box(), 1.0);
  settings.tone = neutralTone(40.0);
  const core::ImageRGBA image = gl::renderToImage(renderer, settings, 110, 110);
  float brightest = 0.0f;
  for (int y = 0; y < 110; ++y)
    for (int x = 0; x < 110; ++x) brightest = std::max(brightest, image.at(x, y)[0]);
  EXPECT_GT(brightest, 0.3f);
}

// Knots of density scattered through a grid whose sides are not multiples of a brick, with
// colours that vary, marched from an oblique eye: rays cross wide empty stretches and graze bricks.
// With `corners`, dense voxels at the grid's eight corners too, which reach its outline on screen.
core::PackedVolume scatteredKnots(bool corners = false) {
  core::VolumeSnapshot snapshot;
  snapshot.geometry.size = {70, 57, 63};
  snapshot.geometry.voxelSize = 1.0;
  const core::GridGeometry& g = snapshot.geometry;
  snapshot.density.assign(g.voxelCount(), 0.0f);
  snapshot.rgba.assign(4 * g.voxelCount(), 255);
  std::uint32_t state = 12345u;
  auto next = [&state](int below) {
    state = state * 1664525u + 1013904223u;
    return static_cast<int>((state >> 8) % static_cast<std::uint32_t>(below));
  };
  for (int knot = 0; knot < 40; ++knot) {
    const glm::ivec3 centre(next(g.size.x), next(g.size.y), next(g.size.z));
    for (int voxel = 0; voxel < 30; ++voxel) {
      const glm::ivec3 v =
          glm::clamp(centre + glm::ivec3(next(5) - 2, next(5) - 2, next(5) - 2), glm::ivec3(0), g.size - 1);
      const std::size_t i = g.index(v.x, v.y, v.z);
      snapshot.density[i] += static_cast<float>(1 + next(40));
      snapshot.rgba[4 * i] = static_cast<std::uint8_t>(next(256));
      snapshot.rgba[4 * i + 1] = static_cast<std::uint8_t>(next(256));
    }
  }
  if (corners)
    for (int corner = 0; corner < 8; ++corner)
      snapshot.density[g.index((corner & 1) ? g.size.x - 1 : 0, (corner & 2) ? g.size.y - 1 : 0,
                               (corner & 4) ? g.size.z - 1 : 0)] = 200.0f;
  snapshot.maxDensity = *std::max_element(snapshot.density.begin(), snapshot.density.end());
  snapshot.points = 40 * 30 * 20;
  snapshot.version = 1;
  core::PackedVolume volume;
  core::packVolume(snapshot, volume);
  return volume;
}

core::DensityImage marchScattered(gl::VolumeRenderer& renderer, const core::PackedVolume& volume) {
  renderer.upload(volume);
  const gl::RenderSettings settings = orbitView(volume.geometry.box(), 28.0, 17.0, 1.3);
  gl::FrameTarget target;
  target.resize(96, 80);
  for (int s = 0; s < 3; ++s) renderer.march(target, settings, s);
  return target.readDensity();
}

double worstRelativeDifference(const core::DensityImage& a, const core::DensityImage& b, double* total) {
  double worst = 0.0;
  *total = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    worst = std::max(worst, std::abs(a.values[i] - b.values[i]) / std::max(1e-3, std::abs(double(b.values[i]))));
    *total += b.values[i];
  }
  return worst;
}

// The march leaps whole cubes of empty bricks (core::PackedVolume::emptyDistance) on the step
// lattice: it must see every step with density that a march without leaps sees.
TEST_F(Renderer, EmptySpaceLeapsMissNoDensity) {
  const core::PackedVolume knots = scatteredKnots();
  ASSERT_GT(*std::max_element(knots.emptyDistance.begin(), knots.emptyDistance.end()), 3)
      << "some leaps cross several bricks";
  const core::DensityImage leaping = marchScattered(renderer, knots);
  core::PackedVolume everyStep = knots;
  std::fill(everyStep.emptyDistance.begin(), everyStep.emptyDistance.end(), std::uint8_t{0});
  const core::DensityImage stepping = marchScattered(renderer, everyStep);
  ASSERT_EQ(leaping.values.size(), stepping.values.size());
  double total = 0.0;
  EXPECT_LE(worstRelativeDifference(leaping, stepping, &total), 1e-4);
  EXPECT_GT(total, 0.0);
}

// Where colour cells are voxels the density can come from the colour texel's alpha (one fetch a
// step) or from the density texture first: both give the same sums.
TEST_F(Renderer, DensityFromColourGivesTheSumsOfDensityFirst) {
  const core::PackedVolume knots = scatteredKnots();
  ASSERT_EQ(knots.colour.shift, 0);
  renderer.setDensityFetch(gl::VolumeRenderer::DensityFetch::FromColour);
  const core::DensityImage fromColour = marchScattered(renderer, knots);
  renderer.setDensityFetch(gl::VolumeRenderer::DensityFetch::DensityFirst);
  const core::DensityImage densityFirst = marchScattered(renderer, knots);
  double total = 0.0;
  EXPECT_LE(worstRelativeDifference(fromColour, densityFirst, &total), 1e-5);
  EXPECT_GT(total, 0.0);
}

// A volume whose draws read the density from the colour texels is uploaded without its density
// texture, a fifth fewer bytes; marched after the fetch order changes to density-first, it still
// gives the same sums (from its colour).
TEST_F(Renderer, AVolumeMarchedFromItsColourGoesUpWithoutItsDensity) {
  const core::PackedVolume knots = scatteredKnots();
  ASSERT_EQ(knots.colour.shift, 0);
  const std::uint64_t colourAndDistances = knots.colours.size() * sizeof(std::uint16_t) + knots.emptyDistance.size();
  const std::uint64_t density = knots.density.size() * sizeof(std::uint16_t);

  renderer.setDensityFetch(gl::VolumeRenderer::DensityFetch::DensityFirst);
  std::uint64_t before = renderer.uploadedBytes();
  const core::DensityImage densityFirst = marchScattered(renderer, knots);
  EXPECT_EQ(renderer.uploadedBytes() - before, colourAndDistances + density);

  renderer.setDensityFetch(gl::VolumeRenderer::DensityFetch::FromColour);
  before = renderer.uploadedBytes();
  const core::DensityImage fromColour = marchScattered(renderer, knots);
  EXPECT_EQ(renderer.uploadedBytes() - before, colourAndDistances);

  renderer.setDensityFetch(gl::VolumeRenderer::DensityFetch::DensityFirst);
  const gl::RenderSettings settings = orbitView(knots.geometry.box(), 28.0, 17.0, 1.3);
  gl::FrameTarget target;
  target.resize(96, 80);
  for (int s = 0; s < 3; ++s) renderer.march(target, settings, s);  // the volume uploaded without density
  const core::DensityImage afterChange = target.readDensity();
  double total = 0.0;
  EXPECT_LE(worstRelativeDifference(fromColour, densityFirst, &total), 1e-5);
  EXPECT_LE(worstRelativeDifference(afterChange, densityFirst, &total), 1e-5);
  EXPECT_GT(total, 0.0);
}

// A live frame finishes only around the grid box's outline on the screen and fills the rest with
// the empty pixel's colour (FinishSource::content): the picture must be the one a still of the
// same view makes, which finishes every pixel, background, contrast and edges included.
TEST_F(Renderer, ALiveFrameFinishedAroundTheBoxIsTheStillOfTheView) {
  const core::PackedVolume knots = scatteredKnots(true);
  renderer.upload(knots);
  // A mesh inside the grid, as a pattern's mesh always is, for the overlays.
  const core::Box box = knots.geometry.box();
  renderer.setMesh(test::uvSphere(glm::vec3(box.center()), 0.45f * static_cast<float>(box.extent().y), 24, 12));
  // The box far from the eye (4 radii): most of the picture lies outside its outline.
  gl::RenderSettings settings = orbitView(box, 28.0, 17.0, 160.0 / 90.0, 20.0, 4.0);
  settings.tone.background = glm::vec3(0.3f, 0.05f, 0.1f);
  settings.tone.contrast = 1.3;
  settings.render.samples = 1;
  settings.render.meshColor = glm::vec3(0.9f, 0.9f, 0.2f);
  constexpr int kWidth = 160, kHeight = 90;
  for (const core::MeshDisplay display :
       {core::MeshDisplay::Off, core::MeshDisplay::Ghost, core::MeshDisplay::Silhouette}) {
    SCOPED_TRACE(static_cast<int>(display));
    settings.render.meshDisplay = display;
    const core::ImageRGBA still = gl::renderToImage(renderer, settings, kWidth, kHeight);

    gl::FrameTarget target;
    target.resize(kWidth, kHeight);
    renderer.march(target, settings, 0);
    renderer.drawMesh(target, settings);
    const gl::Canvas canvas(kWidth, kHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, canvas.framebuffer());
    renderer.resolve(target, settings, glm::ivec4(0, 0, kWidth, kHeight), false);
    const std::vector<std::uint8_t> live = canvas.pixels();

    int close = 0, lit = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const float* expected = still.at(x, y);
        const std::uint8_t* got = &live[4 * (static_cast<std::size_t>(y) * kWidth + x)];
        float worst = 0.0f;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] / 255.0f - expected[c]));
        close += worst <= 1.5f / 255.0f;
        lit += std::abs(expected[0] - still.at(0, 0)[0]) > 0.02f;
      }
    EXPECT_GE(close, kWidth * kHeight - 4);  // all but a few pixels rounded the other way
    EXPECT_GT(lit, 50) << "the knots show";
    EXPECT_LT(lit, kWidth * kHeight / 3) << "most of the picture is outside the box";
    // The corner is the background as chosen (sRGB), the contrast being the pattern's.
    EXPECT_NEAR(live[0] / 255.0f, core::linearToSrgb(settings.tone.background).r, 1.0f / 255.0f);
  }
}

TEST(PackedVolume, HalfFloatConversionRoundTrips) {
  for (float value : {0.0f, 1.0f, -2.5f, 0.333f, 1e-5f, 6.1e-5f, 65504.0f, 1e-7f})
    EXPECT_NEAR(core::halfToFloat(core::floatToHalf(value)), value, std::abs(value) * 1e-3f + 6e-8f) << value;
  EXPECT_TRUE(std::isinf(core::halfToFloat(core::floatToHalf(1e6f))));
}

TEST(PackedVolume, HalfFloatRoundsToNearestEven) {
  // The bits the hand-written converter gave before Imath::half replaced it.
  EXPECT_EQ(core::floatToHalf(1.0f), 0x3c00);
  EXPECT_EQ(core::floatToHalf(1.0f + 0x1p-11f), 0x3c00);             // a tie: down to the even mantissa
  EXPECT_EQ(core::floatToHalf(1.0f + 3 * 0x1p-11f), 0x3c02);         // a tie: up to the even mantissa
  EXPECT_EQ(core::floatToHalf(1.0f + 0x1p-11f + 0x1p-20f), 0x3c01);  // past the tie
  EXPECT_EQ(core::floatToHalf(65519.0f), 0x7bff);
  EXPECT_EQ(core::floatToHalf(65520.0f), 0x7c00);  // overflows to infinity
  EXPECT_EQ(core::floatToHalf(-0.0f), 0x8000);
  EXPECT_EQ(core::floatToHalf(0x1p-24f), 0x0001);  // smallest subnormal
  EXPECT_EQ(core::floatToHalf(0x1p-25f), 0x0000);  // half of it: a tie, to even zero
  EXPECT_EQ(core::floatToHalf(0x1.8p-24f), 0x0002);
  EXPECT_EQ(core::halfToFloat(0x3555), 0.333251953125f);
  EXPECT_EQ(core::halfToFloat(0x0001), 0x1p-24f);
  EXPECT_TRUE(std::isnan(core::halfToFloat(core::floatToHalf(std::nanf("")))));
}

namespace {

// A framebuffer object of one colour texture, bound for drawing while it lives.
struct TestFramebuffer {
  GLuint framebuffer = 0, texture = 0;
  TestFramebuffer(int width, int height, GLenum format) {
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(format), width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("incomplete");
    glViewport(0, 0, width, height);
  }
  ~TestFramebuffer() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
  }
  // Fills the rectangle with lower-left corner (x, y) in GL's coordinates.
  static void fill(int x, int y, int width, int height, float r, float g, float b, float a) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, width, height);
    glClearColor(r, g, b, a);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }
};

}  // namespace

TEST_F(Renderer, ReadBackReturnsRowsTopToBottom) {
  constexpr int kWidth = 5, kHeight = 4;
  TestFramebuffer target(kWidth, kHeight, GL_RGBA8);
  TestFramebuffer::fill(0, 0, kWidth, kHeight, 0.0f, 0.0f, 1.0f, 0.5f);      // blue, half alpha
  TestFramebuffer::fill(0, kHeight - 1, kWidth, 1, 1.0f, 0.0f, 0.0f, 0.5f);  // the top row red
  TestFramebuffer::fill(kWidth - 1, 0, 1, 1, 0.0f, 1.0f, 0.0f, 0.5f);        // the bottom-right pixel green
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);

  const std::vector<std::uint8_t> bytes = gl::readRgba8(target.framebuffer, {0, 0, kWidth, kHeight});
  ASSERT_EQ(bytes.size(), 4u * kWidth * kHeight);
  const auto byte = [&](int x, int y, int c) { return bytes[4 * static_cast<std::size_t>(y * kWidth + x) + c]; };
  for (int x = 0; x < kWidth; ++x) EXPECT_EQ(byte(x, 0, 0), 255) << x;  // first row returned: the top
  EXPECT_EQ(byte(0, kHeight - 1, 2), 255);
  EXPECT_EQ(byte(kWidth - 1, kHeight - 1, 1), 255);  // the last row: the bottom
  EXPECT_EQ(byte(kWidth - 1, kHeight - 1, 0), 0);
  EXPECT_EQ(byte(2, 2, 3), 128);  // alpha kept

  const std::vector<float> floats =
      gl::readRgbaFloat(target.framebuffer, {0, 0, kWidth, kHeight}, gl::ReadAlpha::Opaque);
  ASSERT_EQ(floats.size(), bytes.size());
  for (std::size_t i = 0; i < floats.size(); ++i)
    EXPECT_FLOAT_EQ(floats[i], i % 4 == 3 ? 1.0f : static_cast<float>(bytes[i]) / 255.0f) << i;

  // A region: its own top row first (GL's y = 0 is the image's bottom row).
  const std::vector<std::uint8_t> corner = gl::readRgba8(target.framebuffer, {kWidth - 2, 0, 2, 2});
  ASSERT_EQ(corner.size(), 4u * 2 * 2);
  EXPECT_EQ(corner[4 * 3 + 1], 255);  // bottom-right green, last in the region
  EXPECT_EQ(corner[4 * 2 + 2], 255);  // bottom-left of the region: blue
  EXPECT_EQ(corner[0 + 2], 255);      // top-left of the region: blue

  // State left as found.
  GLint binding = -1, alignment = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &binding);
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  EXPECT_EQ(binding, 0);
  EXPECT_EQ(alignment, 8);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  EXPECT_TRUE(gl::readRgba8(target.framebuffer, {0, 0, 0, 3}).empty());
}

TEST_F(Renderer, ShadersComeFromEmbeddedFilesAndErrorsNameTheFile) {
  const gl::ShaderSource march = gl::embeddedShader("march.frag.glsl");
  EXPECT_EQ(march.file, "engine/gl/shaders/march.frag.glsl");
  EXPECT_NE(march.text.find("marchRay("), std::string::npos);  // the stage; the body is march_common.glsl
  EXPECT_EQ(gl::embeddedShader("blit.frag.glsl").text.rfind("#version 430 core\n", 0), 0u);
  EXPECT_THROW(gl::embeddedShader("no-such.frag.glsl"), core::Error);
  try {
    gl::ShaderProgram program(gl::embeddedShader("fullscreen.vert.glsl"),
                              {"engine/gl/shaders/broken.frag.glsl", "#version 430 core\nvoid main() { oops }\n"});
    FAIL() << "compiled";
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.frag.glsl"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fragment shader"), std::string::npos) << e.what();
  }
  try {
    gl::ShaderProgram program(
        gl::ShaderSource{"engine/gl/shaders/broken.comp.glsl",
                         "#version 430 core\nlayout(local_size_x = 1) in;\nvoid main() { oops }\n"});
    FAIL() << "compiled";
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.comp.glsl"), std::string::npos) << e.what();
  }
}

TEST_F(Renderer, ComputeAndFragmentMarchesGiveTheSameSums) {
  // Both stages run the same body (march_common.glsl) and keep the same running average, the
  // fragment stage by blending and the compute stage in the shader.
  gl::RenderSettings settings = uploadObliqueCube();
  constexpr int kWidth = 45, kHeight = 31, kSamples = 4;
  core::DensityImage sums[2];
  for (int i = 0; i < 2; ++i) {
    renderer.setMarchStage(i == 0 ? gl::VolumeRenderer::MarchStage::Compute : gl::VolumeRenderer::MarchStage::Fragment);
    gl::FrameTarget target;
    target.resize(kWidth, kHeight);
    for (int s = 0; s < kSamples; ++s) renderer.march(target, settings, 3 + s);
    sums[i] = target.readDensity();
  }
  ASSERT_EQ(sums[0].values.size(), sums[1].values.size());
  double worst = 0.0, column = 0.0;
  for (std::size_t i = 0; i < sums[0].values.size(); ++i) {
    const double a = sums[0].values[i], b = sums[1].values[i];
    worst = std::max(worst, std::abs(a - b) / std::max(1e-3, std::abs(b)));
    column += b;
  }
  EXPECT_LE(worst, 1e-5);
  EXPECT_GT(column, 0.0);
}

TEST_F(Renderer, MarchingInBandsOfRowsConvergesToTheUntiledMarch) {
  for (const auto stage : {gl::VolumeRenderer::MarchStage::Compute, gl::VolumeRenderer::MarchStage::Fragment}) {
    SCOPED_TRACE(stage == gl::VolumeRenderer::MarchStage::Compute ? "compute" : "fragment");
    renderer.setMarchStage(stage);
    marchInBandsOfRows();
  }
}

void Renderer::marchInBandsOfRows() {
  // The explorer's still view refines in bands of rows (app::RefineBands), each band keeping its
  // own sample count: once every band has its samples each pixel must hold exactly what an
  // untiled march gives it, whatever the bands and the order passes reach them in.
  gl::RenderSettings settings = uploadObliqueCube();
  constexpr int kWidth = 45, kHeight = 31, kSamples = 5, kFirstIndex = 17;
  gl::FrameTarget whole;
  whole.resize(kWidth, kHeight);
  for (int s = 0; s < kSamples; ++s) renderer.march(whole, settings, kFirstIndex + s);
  EXPECT_EQ(whole.samples, kSamples);

  gl::FrameTarget banded;
  banded.resize(kWidth, kHeight);
  const int bands[] = {0, 7, 8, 20, 31};  // uneven bands, the last one short
  for (int s = 0; s < kSamples; ++s) {
    // A later pass runs through the bands in another grouping, as the budget may change it.
    if (s % 2 == 0) {
      for (int b = 0; b + 1 < static_cast<int>(std::size(bands)); ++b)
        renderer.marchRows(banded, settings, kFirstIndex + s, bands[b], bands[b + 1] - bands[b], s);
    } else {
      renderer.marchRows(banded, settings, kFirstIndex + s, 0, 12, s);
      renderer.marchRows(banded, settings, kFirstIndex + s, 12, kHeight - 12, s);
    }
    EXPECT_EQ(banded.samples, 0) << "the caller counts samples per band";
  }
  const core::DensityImage expected = whole.readDensity();
  const core::DensityImage actual = banded.readDensity();
  ASSERT_EQ(expected.values.size(), actual.values.size());
  EXPECT_EQ(expected.values, actual.values) << "bit for bit";
  EXPECT_EQ(expected.hitsPerUnitDensity, actual.hitsPerUnitDensity);

  // A band marched alone writes its rows and no others.
  gl::FrameTarget one;
  one.resize(kWidth, kHeight);
  renderer.marchRows(one, settings, kFirstIndex, 8, 12, 0);
  const core::DensityImage band = one.readDensity();  // rows top to bottom
  double outside = 0.0, inside = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    const int glRow = kHeight - 1 - y;
    for (int x = 0; x < kWidth; ++x) (glRow >= 8 && glRow < 20 ? inside : outside) += band.at(x, y)[3];
  }
  EXPECT_GT(inside, 0.0);
  EXPECT_EQ(outside, 0.0);

  // A copy shows the same sums.
  gl::FrameTarget shown;
  shown.copyFrom(whole);
  EXPECT_EQ(shown.samples, kSamples);
  EXPECT_EQ(shown.readDensity().values, expected.values);
}
