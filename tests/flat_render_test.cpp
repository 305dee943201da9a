// The flat view (core/flame/flat_render.h): flam3's framing kept on import and through presets, the
// image metrics it is judged with, and a golden image made by flam3-render itself.
#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/flame/xml.h"
#include "core/flame/flat_render.h"
#include "core/image_io.h"
#include "core/image_metrics.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "test_support.h"

using namespace voxflame;

namespace {

const std::filesystem::path kTestFlame = std::filesystem::path(VOXFLAME_TEST_FLAMES) / "scottdraves__flam3__test.flam3";

core::ImageRGBA pattern(int width, int height, double phase) {
  core::ImageRGBA image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float v = static_cast<float>(0.5 + 0.4 * std::sin(0.3 * x + phase) * std::cos(0.2 * y));
      float* p = image.at(x, y);
      p[0] = p[1] = p[2] = v;
      p[3] = 1.0f;
    }
  return image;
}

// Imported as `voxflame import` does, with the depth it adds: the flat view must not see it.
core::Scene importedTestFlame() {
  return core::sceneFromImportedFlame(core::loadFlameFile(kTestFlame).flame, core::Scene{});
}

}  // namespace

TEST(ImageMetrics, SsimIsOneForIdenticalImagesAndFallsWithDifferences) {
  const core::ImageRGBA a = pattern(64, 48, 0.0);
  EXPECT_NEAR(core::ssimLuma(a, a), 1.0, 1e-12);
  const double shifted = core::ssimLuma(a, pattern(64, 48, 1.5));
  EXPECT_LT(shifted, 0.8);
  core::ImageRGBA flat = a;
  for (std::size_t p = 0; p < flat.pixels.size(); p += 4)
    flat.pixels[p] = flat.pixels[p + 1] = flat.pixels[p + 2] = 0.5f;
  EXPECT_LT(core::ssimLuma(a, flat), 0.2);
  EXPECT_THROW(core::ssimLuma(a, pattern(32, 48, 0.0)), core::Error);
  EXPECT_THROW(core::ssimLuma(core::ImageRGBA{}, core::ImageRGBA{}), core::Error);
  // An image smaller than the window still compares.
  EXPECT_NEAR(core::ssimLuma(pattern(4, 4, 0.0), pattern(4, 4, 0.0)), 1.0, 1e-12);
}

TEST(ImageMetrics, MeanLuminanceAndColour) {
  core::ImageRGBA image = pattern(8, 8, 0.0);
  for (std::size_t p = 0; p < image.pixels.size(); p += 4) {
    image.pixels[p] = 1.0f;
    image.pixels[p + 1] = 0.0f;
    image.pixels[p + 2] = 0.5f;
  }
  const glm::dvec3 mean = core::meanColor(image);
  EXPECT_NEAR(mean.r, 1.0, 1e-6);
  EXPECT_NEAR(mean.g, 0.0, 1e-6);
  EXPECT_NEAR(mean.b, 0.5, 1e-6);
  EXPECT_NEAR(core::meanLinearLuminance(image), 0.2126 + 0.0722 * 0.214, 1e-3);
}

TEST(FlatView, ImportKeepsFlam3sFraming) {
  const core::Scene scene = importedTestFlame();
  EXPECT_EQ(scene.flat.width, 640);
  EXPECT_EQ(scene.flat.height, 480);
  EXPECT_EQ(scene.flat.scale, 240.0);
  EXPECT_EQ(scene.flat.quality, 10.0);
  EXPECT_EQ(scene.flat.filterRadius, 1.0);
  EXPECT_EQ(scene.flat.oversample, 1);
  EXPECT_EQ(scene.tone.gamma, 4.0);

  const char* xml = R"(<flame size="300 200" center="0.5 -1" scale="80" zoom="1.5" rotate="30" supersample="2"
      filter="0.8" quality="50" estimator_radius="5" palette="0">
    <xform weight="1" color="0" linear="1" coefs="0.5 0 0 0.5 0 0"/></flame>)";
  const core::ImportedFlame flame = core::readFlameXml(xml, "framing.flame").flame;
  EXPECT_EQ(flame.flat.width, 300);
  EXPECT_EQ(flame.flat.height, 200);
  EXPECT_EQ(flame.flat.centerX, 0.5);
  EXPECT_EQ(flame.flat.centerY, -1.0);
  EXPECT_EQ(flame.flat.scale, 80.0);
  EXPECT_EQ(flame.flat.zoom, 1.5);
  EXPECT_EQ(flame.flat.rotateDeg, 30.0);
  EXPECT_EQ(flame.flat.oversample, 2);
  EXPECT_EQ(flame.flat.filterRadius, 0.8);
  EXPECT_EQ(flame.flat.quality, 50.0);
  EXPECT_EQ(flame.tone.estimatorRadius, 5.0);
  EXPECT_EQ(flame.flat.paletteMode, core::PaletteMode::Step) << "flam3's default";
  const auto paletteModeOf = [](const std::string& mode) {
    const std::string text =
        "<flame palette_mode=\"" + mode + "\"><xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/></flame>";
    return core::readFlameXml(text, "mode.flame").flame;
  };
  EXPECT_EQ(paletteModeOf("linear").flat.paletteMode, core::PaletteMode::Linear);
  EXPECT_EQ(paletteModeOf("step").flat.paletteMode, core::PaletteMode::Step);
  const core::ImportedFlame unknownMode = paletteModeOf("cubic");
  EXPECT_EQ(unknownMode.flat.paletteMode, core::PaletteMode::Step);
  EXPECT_TRUE(std::any_of(unknownMode.warnings.begin(), unknownMode.warnings.end(),
                          [](const std::string& w) { return w.find("palette_mode 'cubic'") != w.npos; }));
  // Framing that is not numbers (real files have center="nan nan") keeps flam3's defaults.
  const core::ImportedFlame odd =
      core::readFlameXml(
          R"(<flame size="big" center="nan nan" scale="inf"><xform weight="1" linear="1" coefs="1 0 0 1 0 0"/></flame>)",
          "odd.flame")
          .flame;
  EXPECT_EQ(odd.flat, core::FlatViewSettings{});
  EXPECT_EQ(std::count_if(odd.warnings.begin(), odd.warnings.end(),
                          [](const std::string& w) { return w.find("the flat view uses flam3's default") != w.npos; }),
            3);
}

TEST(FlatView, FramingRoundTripsThroughPresetsAndDefaultsToFlam3s) {
  core::Scene scene = core::defaultScene();
  EXPECT_EQ(scene.flat, core::FlatViewSettings{});
  EXPECT_EQ(core::sceneToJson(scene).find("\"flat\""), std::string::npos) << "presets without framing leave it out";
  scene.flat.width = 320;
  scene.flat.centerX = -0.25;
  scene.flat.zoom = 2.0;
  scene.flat.quality = 123.0;
  scene.flat.paletteMode = core::PaletteMode::Linear;
  EXPECT_NE(core::sceneToJson(scene).find("\"palette_mode\": \"linear\""), std::string::npos);
  const core::Scene loaded = core::sceneFromJson(core::sceneToJson(scene), "round trip");
  EXPECT_EQ(loaded.flat, scene.flat);
  // JWildfire's camera keys.
  scene.flat.cameraModel = core::FlatCameraModel::Jwildfire;
  scene.flat.cameraPitchDeg = 30.0;
  scene.flat.cameraBankDeg = -20.0;
  scene.flat.cameraPosition = {0.5, -0.25, 1.0};
  scene.flat.cameraDof = 0.3;
  scene.flat.cameraDofScale = 2.0;
  scene.flat.cameraDofFade = 0.25;
  const std::string json = core::sceneToJson(scene);
  EXPECT_NE(json.find("\"camera_model\": \"jwildfire\""), std::string::npos);
  EXPECT_EQ(core::sceneFromJson(json, "round trip").flat, scene.flat);
  const core::FlatViewSettings flam3;
  EXPECT_EQ(flam3.width, 100);
  EXPECT_EQ(flam3.scale, 50.0);
  EXPECT_EQ(flam3.filterRadius, 0.5);
  EXPECT_NE(voxflame::test::presetErrorOf(R"({"mesh": {"path": "m.obj"}, "layers": [{"attractor": "lorenz"}],
      "flat": {"width": 0}})"),
            "");
}

// flam3's lookup (rect.c): step takes entry ⌊index · 256⌋; linear blends entries i and i + 1 by
// the fraction of index · 256, and both clamp at the ends.
TEST(FlatView, PaletteModesLookUpAsFlam3Does) {
  std::array<glm::vec3, 256> palette{};
  for (std::size_t i = 0; i < palette.size(); ++i) palette[i] = glm::vec3(static_cast<float>(i) / 255.0f, 0.0f, 1.0f);
  using core::PaletteMode;
  const auto red = [&](double index, PaletteMode mode) { return core::flatPaletteColour(palette, index, mode).r; };
  const double between = (100.0 + 0.25) / 256.0;  // a quarter of the way from entry 100 to 101
  EXPECT_FLOAT_EQ(red(between, PaletteMode::Step), 100.0f / 255.0f);
  EXPECT_FLOAT_EQ(red(between, PaletteMode::Linear), (100.0f + 0.25f) / 255.0f);
  EXPECT_FLOAT_EQ(core::flatPaletteColour(palette, between, PaletteMode::Linear).b, 1.0f);
  for (const PaletteMode mode : {PaletteMode::Step, PaletteMode::Linear}) {
    EXPECT_EQ(red(-0.5, mode), 0.0f);
    EXPECT_EQ(red(std::nan(""), mode), 0.0f);
    EXPECT_EQ(red(255.5 / 256.0, mode), 1.0f);
    EXPECT_EQ(red(1.0, mode), 1.0f);
    EXPECT_EQ(red(7.0, mode), 1.0f);
  }
}

// flam3 writes ⌊min(256 v, 255)⌋ (rect.c), not a rounded 255 v: the flat view's pixels are on
// those levels, so a PNG writer's rounding keeps them.
TEST(FlatView, PixelsTakeFlam3sTruncatedLevels) {
  EXPECT_EQ(core::flatPixelLevel(5.9f / 256.0f, 8), 5.0f / 255.0f);
  EXPECT_EQ(core::flatPixelLevel(6.0f / 256.0f, 8), 6.0f / 255.0f);
  EXPECT_EQ(core::flatPixelLevel(0.999f, 8), 255.0f / 255.0f);
  EXPECT_EQ(core::flatPixelLevel(3.0f, 8), 1.0f);
  EXPECT_EQ(core::flatPixelLevel(-0.5f, 8), 0.0f);
  EXPECT_EQ(core::flatPixelLevel(std::nanf(""), 8), 0.0f);
  EXPECT_EQ(core::flatPixelLevel(5.9f / 256.0f, 16), std::floor(5.9f * 256.0f) / 65535.0f);
  EXPECT_EQ(core::flatPixelLevel(1.0f, 16), 65280.0f / 65535.0f);
  for (float v = 0.0f; v < 1.0f; v += 0.0137f)
    EXPECT_EQ(std::lround(core::flatPixelLevel(v, 8) * 255.0f), static_cast<long>(std::min(255.0f, v * 256.0f)));
}

TEST(FlatView, RefusesWhatItCannotDraw) {
  core::Scene scene = core::defaultScene();  // attractor layers only
  EXPECT_THROW(core::renderFlat(scene), core::Error);
  scene = importedTestFlame();
  core::FlatRenderOptions options;
  options.width = -3;
  EXPECT_THROW(core::renderFlat(scene, options), core::Error);
  options.width = 16;
  options.quality = std::nan("");
  EXPECT_THROW(core::renderFlat(scene, options), core::Error);
  options.quality = 1.0;
  const core::FlatRenderResult small = core::renderFlat(scene, options);
  EXPECT_EQ(small.image.width, 16);
  EXPECT_EQ(small.image.height, 12);  // the flame's 4:3
}

// The golden image is flam3-render's own render of the first flame of flam3's test.flam3, made with
//   prefix=tests/golden/flat-flam3-test- format=png ss=0.25 qs=20 isaac_seed=1 in=test.flam3 flam3-render
// (Debian's flam3-utils 3.1.1; it writes flat-flam3-test-00000.png for the first flame, renamed to
// flat-flam3-test.png): 160×120 pixels at quality 200. The tolerance is what voxflame's flat view
// and flam3 reach with different random numbers and a margin; a wrong palette, a wrong variation
// or a wrong brightness is far outside it (the tests below check that).
namespace {

struct Comparison {
  double ssim = 0.0, luminanceRatio = 0.0, colorDistance = 0.0;
};

Comparison compareWithGolden(const core::Scene& scene) {
  core::FlatRenderOptions options;
  options.width = 160;
  options.height = 120;
  options.quality = 200.0;
  const core::ImageRGBA image = core::renderFlat(scene, options).image;
  const core::ImageRGBA golden = core::readPng(voxflame::test::sourcePath("tests/golden/flat-flam3-test.png")).image;
  Comparison c;
  c.ssim = core::ssimLuma(image, golden);
  c.luminanceRatio = core::meanLinearLuminance(image) / core::meanLinearLuminance(golden);
  const glm::dvec3 d = core::meanColor(image) - core::meanColor(golden);
  c.colorDistance = std::max({std::abs(d.r), std::abs(d.g), std::abs(d.b)});
  return c;
}

constexpr double kMinSsim = 0.90;
constexpr double kLuminanceTolerance = 0.02;  // the goal of `bench fidelity`
constexpr double kColorTolerance = 0.008;

bool matches(const Comparison& c) {
  return c.ssim >= kMinSsim && std::abs(c.luminanceRatio - 1.0) <= kLuminanceTolerance &&
         c.colorDistance <= kColorTolerance;
}

}  // namespace

TEST(FlatView, MatchesFlam3RendersOwnImage) {
  ASSERT_TRUE(std::filesystem::exists(kTestFlame)) << kTestFlame << " is missing";
  const Comparison c = compareWithGolden(importedTestFlame());
  std::printf("flat view vs flam3-render: SSIM %.4f, luminance ratio %.4f, colour distance %.4f\n", c.ssim,
              c.luminanceRatio, c.colorDistance);
  EXPECT_GE(c.ssim, kMinSsim);
  EXPECT_NEAR(c.luminanceRatio, 1.0, kLuminanceTolerance);
  EXPECT_LE(c.colorDistance, kColorTolerance);
}

TEST(FlatView, TheGoldenComparisonCatchesAWrongPaletteOrVariation) {
  ASSERT_TRUE(std::filesystem::exists(kTestFlame)) << kTestFlame << " is missing";
  core::Scene palette = importedTestFlame();
  std::vector<core::GradientStop>& stops = palette.layers[0].color.gradient;
  std::reverse(stops.begin(), stops.end());
  for (std::size_t i = 0; i < stops.size(); ++i)
    stops[i].position = static_cast<float>(i) / static_cast<float>(stops.size() - 1);
  const Comparison wrongPalette = compareWithGolden(palette);
  EXPECT_FALSE(matches(wrongPalette)) << "ssim " << wrongPalette.ssim << ", colour " << wrongPalette.colorDistance;

  core::Scene variation = importedTestFlame();
  variation.layers[0].flame.xforms[1].variations = {{"linear", 1.0, {}}};
  const Comparison wrongVariation = compareWithGolden(variation);
  EXPECT_FALSE(matches(wrongVariation)) << "ssim " << wrongVariation.ssim;

  core::Scene brightness = importedTestFlame();
  brightness.tone.brightness *= 2.0;
  const Comparison tooBright = compareWithGolden(brightness);
  EXPECT_FALSE(matches(tooBright)) << "luminance ratio " << tooBright.luminanceRatio;
}

// The 3D camera of Apophysis 3D and Fractorium, at points worked out by hand from Fractorium's
// Ember::ProjectPitchYaw: yaw turns (x, y) by −yaw, pitch tilts y into depth (y cos p − z sin p),
// and perspective divides by 1 − perspective · depth (depth = y sin p + z cos p after the yaw).
TEST(FlatView, TheCameraProjectsAsFractoriumDoes) {
  core::FlatViewSettings flat;
  EXPECT_FALSE(flat.hasCamera());
  flat.cameraPitchDeg = 60.0;
  const core::FlatCamera pitch(flat);
  glm::dvec2 p = pitch.project(0.3, 0.8, 0.0, 0.0, 0.0);
  EXPECT_NEAR(p.x, 0.3, 1e-12);
  EXPECT_NEAR(p.y, 0.4, 1e-12);  // 0.8 cos 60°
  p = pitch.project(0.0, 0.0, 1.0, 0.0, 0.0);
  EXPECT_NEAR(p.y, -std::sqrt(3.0) / 2.0, 1e-12);  // −sin 60°
  flat.cameraPitchDeg = 0.0;
  flat.cameraYawDeg = 90.0;
  p = core::FlatCamera(flat).project(1.0, 0.0, 0.0, 0.0, 0.0);
  EXPECT_NEAR(p.x, 0.0, 1e-12);  // (cos 90°, −sin 90°)·x in Fractorium's matrix: (0, −1)
  EXPECT_NEAR(p.y, -1.0, 1e-12);
  flat.cameraYawDeg = 0.0;
  flat.cameraPitchDeg = 30.0;
  flat.cameraPerspective = 0.5;
  flat.cameraZ = 0.2;
  // dz = −0.2; y' = 0.8 cos 30° + 0.2 sin 30° = 0.79282; depth = 0.8 sin 30° − 0.2 cos 30° = 0.22679;
  // zr = 1 − 0.5 · 0.22679 = 0.88660.
  p = core::FlatCamera(flat).project(0.3, 0.8, 0.0, 0.0, 0.0);
  const double depth = 0.8 * 0.5 - 0.2 * std::sqrt(3.0) / 2.0, zr = 1.0 - 0.5 * depth;
  EXPECT_NEAR(p.x, 0.3 / zr, 1e-12);
  EXPECT_NEAR(p.y, (0.8 * std::sqrt(3.0) / 2.0 + 0.2 * 0.5) / zr, 1e-12);
  // Depth of field moves the point by blur · 0.1 dof · depth towards the angle, before the division.
  flat.cameraDof = 2.0;
  p = core::FlatCamera(flat).project(0.3, 0.8, 0.0, 0.25, 0.5);
  EXPECT_NEAR(p.x, 0.3 / zr, 1e-12);
  EXPECT_NEAR(p.y, (0.8 * std::sqrt(3.0) / 2.0 + 0.2 * 0.5 + 0.5 * 0.2 * depth) / zr, 1e-12);
}

// JWildfire's camera, at points worked out from its FlameRendererView (camera matrix and project)
// by hand and with a separate script: the turn is R_z(rotate) R_x(pitch) R_y(bank) R_z(−yaw), the
// camera position is added after it, and zr = 1 − perspective · depth + position_z.
TEST(FlatView, TheCameraProjectsAsJwildfireDoes) {
  core::FlatViewSettings flat;
  flat.cameraModel = core::FlatCameraModel::Jwildfire;
  EXPECT_FALSE(flat.hasCamera());
  flat.cameraZ = 0.5;  // JWildfire's depth in focus: alone it is no 3D camera
  EXPECT_FALSE(flat.hasCamera());
  flat.cameraZ = 0.0;
  const auto project = [&](double x, double y, double z) { return core::FlatCamera(flat).project(x, y, z, 0.0, 0.0); };
  flat.cameraPitchDeg = 60.0;
  EXPECT_TRUE(flat.hasCamera());
  glm::dvec2 p = project(0.0, 1.0, 0.0);
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, 0.5, 1e-12);  // cos 60°
  flat.cameraPitchDeg = 30.0;
  p = project(0.0, 1.0, 0.5);
  EXPECT_NEAR(p.y, 0.6160254037844387, 1e-12);  // cos 30° − 0.5 sin 30°
  flat.cameraPitchDeg = 0.0;
  flat.cameraYawDeg = 90.0;
  p = project(1.0, 0.0, 0.0);
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, -1.0, 1e-12);
  flat.cameraYawDeg = 0.0;
  // Bank turns about the vertical axis: x takes cos bank of itself and sin bank of the depth.
  flat.cameraBankDeg = 90.0;
  p = project(1.0, 0.0, 0.0);
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, 0.0, 1e-12);
  flat.cameraBankDeg = 40.0;
  p = project(1.0, 0.5, 0.25);
  EXPECT_NEAR(p.x, 0.9267413455406128, 1e-12);  // cos 40° + 0.25 sin 40°
  EXPECT_NEAR(p.y, 0.5, 1e-12);
  flat.cameraBankDeg = 0.0;
  // With the camera, `rotate` turns about the origin.
  flat.cameraPerspective = 1e-3;
  flat.rotateDeg = 90.0;
  flat.centerX = 5.0;
  p = core::FlatCamera(flat).project(0.0, 1.0, 0.0, 0.0, 0.0);
  EXPECT_NEAR(p.x, -1.0, 1e-12);
  EXPECT_NEAR(p.y, 0.0, 1e-12);
  flat.rotateDeg = 0.0;
  flat.centerX = 0.0;
  flat.cameraPerspective = 0.5;
  p = project(0.0, 1.0, 1.0);
  EXPECT_NEAR(p.y, 2.0, 1e-12);  // zr = 1 − 0.5 · 1
  // All at once, and with the camera moved.
  flat.cameraPitchDeg = 25.0;
  flat.cameraYawDeg = -40.0;
  flat.cameraBankDeg = 15.0;
  flat.rotateDeg = 10.0;
  flat.cameraPerspective = 0.3;
  p = project(0.3, -0.7, 0.4);
  EXPECT_NEAR(p.x, 0.8294126268011645, 1e-12);
  EXPECT_NEAR(p.y, -0.26571481040893774, 1e-12);
  flat.cameraPosition = {0.2, -0.1, 0.3};
  p = project(0.3, -0.7, 0.4);
  EXPECT_NEAR(p.x, 0.8509982435727739, 1e-12);
  EXPECT_NEAR(p.y, -0.30266129268303965, 1e-12);
  // A point behind the eye (zr ≤ 0) is not drawn.
  flat = {};
  flat.cameraModel = core::FlatCameraModel::Jwildfire;
  flat.cameraPerspective = 2.0;
  EXPECT_TRUE(std::isnan(project(0.0, 0.0, 0.6).x));
  EXPECT_FALSE(std::isnan(project(0.0, 0.0, 0.4).x));

  // Depth of field (its bubble blur): a point in front of the depth in focus moves by
  // f · 0.1 dof · scale · (focus − depth) towards the drawn angle.
  flat = {};
  flat.cameraModel = core::FlatCameraModel::Jwildfire;
  flat.cameraPitchDeg = 30.0;  // (0.3, 0.8, 0) is at depth 0.4
  flat.cameraDof = 2.0;
  flat.cameraDofScale = 1.5;
  flat.cameraZ = 1.0;
  const double y = 0.8 * std::sqrt(3.0) / 2.0;
  p = core::FlatCamera(flat).project(0.3, 0.8, 0.0, 0.25, 0.5);  // f = 0.5: 0.09 up
  EXPECT_NEAR(p.x, 0.3, 1e-12);
  EXPECT_NEAR(p.y, 0.782820323027551, 1e-12);
  flat.cameraDofFade = 0.5;
  p = core::FlatCamera(flat).project(0.3, 0.8, 0.0, 0.0, 0.25);  // f = 0.25 / 0.5: 0.09 right
  EXPECT_NEAR(p.x, 0.39, 1e-12);
  EXPECT_NEAR(p.y, y, 1e-12);
  p = core::FlatCamera(flat).project(0.3, 0.8, 0.0, 0.0, 0.75);  // past the fade: f = 1
  EXPECT_NEAR(p.x, 0.48, 1e-12);
  flat.cameraZ = 0.2;  // behind the depth in focus: sharp
  p = core::FlatCamera(flat).project(0.3, 0.8, 0.0, 0.25, 0.5);
  EXPECT_NEAR(p.x, 0.3, 1e-12);
  EXPECT_NEAR(p.y, y, 1e-12);
}

// A file's camera reaches the flat view and tilts the picture: Sierpinski's triangle (framed about
// its middle, flat, on black), pitched by 60° (cam_pitch in radians, as Apophysis 3D and Fractorium
// write it), is drawn half as tall and as wide; turned by yaw 90°, its height and width swap.
TEST(FlatView, AFilesCameraTiltsThePicture) {
  const auto sierpinski = [](const std::string& camera) {
    const std::string xml = "<flame size=\"200 200\" center=\"0 0\" scale=\"70\" estimator_radius=\"0\" " + camera +
                            ">\n<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 -0.5 -0.4\"/>\n"
                            "<xform weight=\"1\" color=\"0.5\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 -0.4\"/>\n"
                            "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0.6\"/>\n</flame>\n";
    return core::sceneFromImportedFlame(core::readFlameXml(xml, "sierpinski.flame").flame, core::Scene{});
  };
  // The extent of the lit pixels: width, height.
  const auto extent = [](const core::Scene& scene) {
    core::FlatRenderOptions options;
    options.quality = 20.0;
    const core::ImageRGBA image = core::renderFlat(scene, options).image;
    int left = image.width, right = -1, top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const float* p = image.at(x, y);
        if (p[0] + p[1] + p[2] < 0.2f) continue;
        left = std::min(left, x);
        right = std::max(right, x);
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    return std::array<double, 2>{static_cast<double>(right - left), static_cast<double>(bottom - top)};
  };
  const core::Scene straight = sierpinski("");
  EXPECT_FALSE(straight.flat.hasCamera());
  const core::Scene pitched = sierpinski("cam_pitch=\"1.0471975511965976\"");
  EXPECT_NEAR(pitched.flat.cameraPitchDeg, 60.0, 1e-9);
  const auto [width, height] = extent(straight);
  const auto [pitchedWidth, pitchedHeight] = extent(pitched);
  EXPECT_GT(height, 100.0);
  EXPECT_NEAR(pitchedWidth / width, 1.0, 0.05);
  EXPECT_NEAR(pitchedHeight / height, 0.5, 0.05);
  const auto [turnedWidth, turnedHeight] = extent(sierpinski("cam_yaw=\"1.5707963267948966\""));
  EXPECT_NEAR(turnedWidth / height, 1.0, 0.05);
  EXPECT_NEAR(turnedHeight / width, 1.0, 0.05);

  // JWildfire's camera: pitched by 60°, the triangle is half as tall; banked by 60°, half as wide;
  // cam_zoom 0.5 draws it half as large.
  const std::string jwildfire = "version=\"JWildfire V8.00\" ";
  const core::Scene jwfPitched = sierpinski(jwildfire + "cam_pitch=\"1.0471975511965976\"");
  EXPECT_EQ(jwfPitched.flat.cameraModel, core::FlatCameraModel::Jwildfire);
  const auto [jwfPitchedWidth, jwfPitchedHeight] = extent(jwfPitched);
  EXPECT_NEAR(jwfPitchedWidth / width, 1.0, 0.05);
  EXPECT_NEAR(jwfPitchedHeight / height, 0.5, 0.05);
  const auto [bankedWidth, bankedHeight] = extent(sierpinski(jwildfire + "cam_roll=\"1.0471975511965976\""));
  EXPECT_NEAR(bankedWidth / width, 0.5, 0.05);
  EXPECT_NEAR(bankedHeight / height, 1.0, 0.05);
  const auto [zoomedWidth, zoomedHeight] = extent(sierpinski(jwildfire + "cam_zoom=\"0.5\""));
  EXPECT_NEAR(zoomedWidth / width, 0.5, 0.05);
  EXPECT_NEAR(zoomedHeight / height, 0.5, 0.05);
}

// JWildfire's post symmetry in the flat view: Sierpinski's triangle off the centre, with a 3-fold
// point symmetry about the centre, looks the same turned by 120° (within the noise, after a small
// blur); with an x_axis symmetry it looks the same mirrored left to right. Without either it does not.
TEST(FlatView, PostSymmetryCopiesThePictureAsJwildfireDoes) {
  const auto render = [](const std::string& symmetry) {
    const std::string xml =
        "<flame version=\"JWildfire V8.00\" size=\"200 200\" center=\"0 0\" scale=\"50\" estimator_radius=\"0\" " +
        symmetry +
        ">\n<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.1 -0.3\"/>\n"
        "<xform weight=\"1\" color=\"0.5\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.7 -0.3\"/>\n"
        "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.4 0.3\"/>\n</flame>\n";
    const core::ImportedFlame flame = core::readFlameXml(xml, "sierpinski.flame").flame;
    EXPECT_TRUE(flame.leftOut.empty());
    core::FlatRenderOptions options;
    options.quality = 40.0;
    const core::ImageRGBA image = core::renderFlat(core::sceneFromImportedFlame(flame, core::Scene{}), options).image;
    // Luminance, blurred over 5 × 5 pixels.
    std::vector<double> lit(static_cast<std::size_t>(image.width * image.height)), blurred(lit.size());
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const float* p = image.at(x, y);
        lit[static_cast<std::size_t>(y * image.width + x)] = p[0] + p[1] + p[2];
      }
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        double sum = 0.0;
        for (int v = std::max(0, y - 2); v <= std::min(image.height - 1, y + 2); ++v)
          for (int u = std::max(0, x - 2); u <= std::min(image.width - 1, x + 2); ++u)
            sum += lit[static_cast<std::size_t>(v * image.width + u)];
        blurred[static_cast<std::size_t>(y * image.width + x)] = sum / 25.0;
      }
    return blurred;
  };
  constexpr int kSide = 200;
  // The mean difference between the picture and itself moved by `move` (a pixel centre's offset
  // from the image centre to the offset it is compared with), over the mean brightness.
  const auto difference = [&](const std::vector<double>& image, const auto& move) {
    double diff = 0.0, sum = 0.0;
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const glm::dvec2 to = move(glm::dvec2(x + 0.5 - kSide / 2.0, y + 0.5 - kSide / 2.0));
        const int u = static_cast<int>(std::floor(to.x + kSide / 2.0)),
                  v = static_cast<int>(std::floor(to.y + kSide / 2.0));
        const double a = image[static_cast<std::size_t>(y * kSide + x)];
        const double b =
            u >= 0 && v >= 0 && u < kSide && v < kSide ? image[static_cast<std::size_t>(v * kSide + u)] : 0.0;
        diff += std::abs(a - b);
        sum += a;
      }
    return diff / sum;
  };
  const double third = 2.0 * std::numbers::pi / 3.0;
  const auto turned = [&](glm::dvec2 d) {
    return glm::dvec2(d.x * std::cos(third) - d.y * std::sin(third), d.x * std::sin(third) + d.y * std::cos(third));
  };
  const auto mirrored = [](glm::dvec2 d) { return glm::dvec2(-d.x, d.y); };
  const std::vector<double> plain = render("");
  const std::vector<double> point = render("post_symmetry_type=\"POINT\" post_symmetry_order=\"3\"");
  const std::vector<double> axis =
      render("post_symmetry_type=\"X_AXIS\" post_symmetry_distance=\"0.4\" post_symmetry_rotation=\"20\"");
  const double plainTurned = difference(plain, turned), plainMirrored = difference(plain, mirrored);
  const double pointTurned = difference(point, turned), axisMirrored = difference(axis, mirrored);
  std::printf("post symmetry: turned by 120° %.3f (plain %.3f), mirrored %.3f (plain %.3f)\n", pointTurned, plainTurned,
              axisMirrored, plainMirrored);
  EXPECT_GT(plainTurned, 1.0);
  EXPECT_GT(plainMirrored, 1.0);
  EXPECT_LT(pointTurned, 0.25);
  EXPECT_LT(axisMirrored, 0.25);
  EXPECT_GT(difference(point, mirrored), 0.5);  // a turn is not a mirror
}
