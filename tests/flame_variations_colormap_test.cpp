// JWildfire's colormap_wf (its default picture, the four-corner gradient) and dc_inversion, against values
// worked out by hand: the gradient's pixels and dc_inversion's colours were computed apart from this code,
// following GradientCreator's fixed-point steps and DC_InversionFunc's loop.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "core/chaos_game.h"
#include "core/flame/variations.h"
#include "core/flame/variations_colormap.h"
#include "core/flame/xml.h"
#include "core/image_io.h"
#include "core/random.h"
#include "core/scene.h"
#include "variation_point_case.h"

using namespace voxflame::core;
using namespace voxflame::test;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// colormap_wf's parameters: scale_x, scale_y, scale_z, offset_x, offset_y, offset_z, tile_x, tile_y, reset_z,
// dc_color, blend_colormap, with_alpha, is_sequence, sequence_start, sequence_digits.
std::vector<double> colormap(double scaleZ, double offsetZ, double tile, double resetZ, double dcColor, double blend) {
  return {1.0, 1.0, scaleZ, 0.0, 0.0, offsetZ, tile, tile, resetZ, dcColor, blend, 0.0, 0.0, 1.0, 4.0};
}

// At (0.3, −0.7) colormap_wf reads pixel (u, v) = (0.8 · 254, −0.2 · 254) = (203.2, −50.8), rounded to (203, −51)
// and tiled to (203, 205): the gradient's row 205 runs from (50, 205, 205) to (50, 50, 205) (the edges' steps of
// −1024/1024 per row in 1/1024), and column 203 of it is (50, 205 + ⌊203 · ⌊−155 · 1024 / 255⌋ / 1024⌋, 205) =
// (50, 81, 205). Blended, it reads (203, −50) tiled to (203, 206) and its neighbours (49, 81, 206), (49, 80, 206),
// (48, 80, 207), (48, 79, 207) by the fractions 0.2 and −0.8 (JWildfire's, negative below 0): (49.8, 81.6, 205.2).
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // The point is not moved; z is replaced by dz = 0 (reset_z, scale_z 0, offset_z 0).
      {"colormap_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, -0.5}},
      // dz = 0.1 + 0.3 (0.299 · 50 + 0.588 · 81 + 0.113 · 205)/255, added to z (reset_z 0); unweighted.
      {"colormap_wf",
       colormap(0.3, 0.1, 1.0, 0.0, 1.0, 0.0),
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.0, 0.0, 0.20087411764705881}},
      // Blended: dz = 0.25 (0.299 · 49.8 + 0.588 · 81.6 + 0.113 · 205.2)/255, replacing z.
      {"colormap_wf",
       colormap(0.25, 0.0, 1.0, 1.0, 1.0, 1.0),
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.0, 0.0, 0.08437117647058821 - 0.5}},
      // The origin reads pixel (127, 127) = (128, 127, 127).
      {"colormap_wf",
       colormap(0.3, 0.0, 1.0, 1.0, 1.0, 0.0),
       {0.0, 0.0, 0.5},
       0.8,
       kHighSeed,
       {0.0, 0.0, -0.35023647058823526}},
      // NaN rounds to pixel (0, 0), the red corner: dz = 0.3 · 0.299.
      {"colormap_wf", colormap(0.3, 0.0, 1.0, 1.0, 1.0, 0.0), {kNaN, kNaN, 0.5}, 0.8, kHighSeed, {0.0, 0.0, -0.4103}},
      // +∞ and huge values saturate at Java's int limit, which tiles to 255: the blue corner (0.3 · 0.113) ...
      {"colormap_wf", colormap(0.3, 0.0, 1.0, 1.0, 1.0, 0.0), {1e300, kInf, 0.5}, 0.8, kHighSeed, {0.0, 0.0, -0.4661}},
      // ... while −∞ tiles (with Java's int wrapping) to 256, outside the picture: black, dz = 0.
      {"colormap_wf", colormap(0.3, 0.0, 1.0, 1.0, 1.0, 0.0), {0.3, -kInf, 0.5}, 0.8, kHighSeed, {0.0, 0.0, -0.5}},
      // Untiled, x = 2 reads column 635, outside: black.
      {"colormap_wf", colormap(0.3, 0.0, 0.0, 1.0, 1.0, 0.0), {2.0, 0.0, 0.5}, 0.8, kHighSeed, {0.0, 0.0, -0.5}},
      // dc_inversion with ColorOnly: w · the point; its colour at (0.2, −0.3) is (106, 208, 227), grey level
      // (31 + 122 + 25)/255; z = grey · 0.5 + 0.1 replaces z.
      {"dc_inversion",
       {10000.0, 0.0, 50.0, 1.5, 1.5, 1.0, 2.0, 0.5, 0.1, 1.0},
       {0.2, -0.3, 0.5},
       0.8,
       kHighSeed,
       {0.16000000000000003, -0.24, -0.050980392156862786}},
      // Two steps at (0.3, −0.7): (0, 2, 3), grey 1/255; z + w z + 2 · grey (reset_z 0).
      {"dc_inversion",
       {10000.0, 0.0, 2.0, 1.5, 1.5, 1.0, 2.0, 2.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.40784313725490196}},
  };
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class ColormapVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(ColormapVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Colormap, ColormapVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

// dc_inversion's Gradient 2 sets the colour index to the grey level: (106, 208, 227) at (0.2, −0.3), and the
// same at (−0.2, −0.3), since each step starts from |v_x|.
const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      {"dc_inversion",
       {10000.0, 0.0, 50.0, 1.5, 1.5, 1.0, 2.0, 0.0, 0.0, 1.0},
       {0.2, -0.3, 0.5},
       kHighSeed,
       178.0 / 255.0},
      {"dc_inversion",
       {10000.0, 0.0, 50.0, 1.5, 1.5, 1.0, 2.0, 0.0, 0.0, 1.0},
       {-0.2, -0.3, 0.5},
       kLowSeed,
       178.0 / 255.0},
      // Without a palette at hand (a single evaluation) colormap_wf's dc_color 1 leaves the index alone.
      {"colormap_wf", {}, {0.3, -0.7, 0.5}, kHighSeed, kStartColour},
  };
  return cases;
}

class ColormapVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(ColormapVariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Colormap, ColormapVariationSetsColour, testing::ValuesIn(colourCases()), colourCaseLabel);

struct Painted {
  std::vector<std::uint32_t> rgb;
  std::vector<double> colour, x, y, z;
  std::vector<std::uint8_t> hidden;  // the doHide flags, where texts were given (0 before)
};

// colormap_wf over 9 lanes at one point, with a true-colour array and, when given, a palette.
Painted paint(const std::vector<double>& params, double px, double py, const std::uint32_t* palette,
              VariationStage stage = VariationStage::Normal, const std::vector<std::string>* texts = nullptr) {
  constexpr std::size_t kLanes = 9;
  std::vector<double> xs(kLanes, px), ys(kLanes, py), zs(kLanes, 0.5);
  std::vector<std::uint32_t> random(kLanes, kHighSeed);
  Painted out{std::vector<std::uint32_t>(kLanes, 0u), std::vector<double>(kLanes, kStartColour),
              std::vector<double>(kLanes, 0.0),       std::vector<double>(kLanes, 0.0),
              std::vector<double>(kLanes, 0.0),       std::vector<std::uint8_t>(kLanes, 0u)};
  VariationInput in;
  in.x = in.tx = xs.data();
  in.y = in.ty = ys.data();
  in.z = in.tz = zs.data();
  in.random = random.data();
  in.count = kLanes;
  in.weight = 0.8;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = out.colour.data();
  in.rgb = out.rgb.data();
  in.palette = palette;
  in.stage = stage;
  in.texts = texts ? texts->data() : nullptr;
  out.hidden.assign(kLanes, 0u);
  in.hidden = texts ? out.hidden.data() : nullptr;
  variationOrThrow("colormap_wf").apply(in, out.x.data(), out.y.data(), out.z.data());
  return out;
}

constexpr std::uint32_t packed(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return r | g << 8 | b << 16;
}

TEST(FlameVariationColormap, DcColorZeroPaintsThePicturesColour) {
  EXPECT_TRUE(variationOrThrow("colormap_wf").paintsRgb);
  EXPECT_TRUE(variationOrThrow("colormap_wf").directColour);
  const Painted p = paint(colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0), 0.3, -0.7, nullptr);
  for (std::size_t lane = 0; lane < p.rgb.size(); ++lane) {
    EXPECT_EQ(p.rgb[lane], paintedRgb(50, 81, 205)) << lane;
    EXPECT_EQ(p.colour[lane], kStartColour);
  }
  // Blended: (49.8, 81.6, 205.2) rounded.
  EXPECT_EQ(paint(colormap(0.0, 0.0, 1.0, 1.0, 0.0, 1.0), 0.3, -0.7, nullptr).rgb[0], paintedRgb(50, 82, 205));
  // The corners: NaN reads the red one, huge values the blue one; −∞ and an untiled x = 2 fall outside (black).
  EXPECT_EQ(paint(colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0), kNaN, kNaN, nullptr).rgb[0], paintedRgb(255, 0, 0));
  EXPECT_EQ(paint(colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0), 1e300, kInf, nullptr).rgb[0], paintedRgb(0, 0, 255));
  EXPECT_EQ(paint(colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0), -kInf, 0.0, nullptr).rgb[0], paintedRgb(0, 0, 0));
  EXPECT_EQ(paint(colormap(0.0, 0.0, 0.0, 1.0, 0.0, 0.0), 2.0, 0.0, nullptr).rgb[0], paintedRgb(0, 0, 0));
  // Offset and scale move the picture: offset_x 0.5 and scale_x 2 read column (0.3 − 1 + 1)/2 · 254 = 38.1 → 38
  // of row 205, (50, 205 + ⌊38 · −622 / 1024⌋, 205) = (50, 181, 205).
  std::vector<double> moved = colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0);
  moved[0] = 2.0;
  moved[3] = 0.5;
  EXPECT_EQ(paint(moved, 0.3, -0.7, nullptr).rgb[0], paintedRgb(50, 181, 205));
}

// dc_color 1: the colour index of the palette entry nearest to the pixel's colour, the palette scaled by 200/256
// as JWildfire's render palette is: entry 77 of (64, 104, 255) is (50, 81.25, 199.2) there, nearest to (50, 81,
// 205), although unscaled a grey entry 200 of (60, 90, 210) would be nearer. dc_color −1 sets neither.
TEST(FlameVariationColormap, DcColorOneTakesTheNearestEntryOfTheRenderPalette) {
  std::vector<std::uint32_t> palette(256, packed(0, 0, 0));
  palette[77] = packed(64, 104, 255);
  palette[200] = packed(60, 90, 210);
  const Painted p = paint(colormap(0.0, 0.0, 1.0, 1.0, 1.0, 0.0), 0.3, -0.7, palette.data());
  for (std::size_t lane = 0; lane < p.rgb.size(); ++lane) {
    EXPECT_DOUBLE_EQ(p.colour[lane], 77.0 / 255.0) << lane;
    EXPECT_EQ(p.rgb[lane], 0u);
  }
  const Painted none = paint(colormap(0.0, 0.0, 1.0, 1.0, -1.0, 0.0), 0.3, -0.7, palette.data());
  EXPECT_EQ(none.colour[0], kStartColour);
  EXPECT_EQ(none.rgb[0], 0u);
}

// As a pre_ or post_ term JWildfire changes the point in place: x and y are kept, z replaced by dz (reset_z) or
// moved by it; an ordinary term adds nothing to x and y.
TEST(FlameVariationColormap, PreAndPostTermsKeepThePoint) {
  const Painted post = paint(colormap(0.3, 0.1, 1.0, 0.0, 1.0, 0.0), 0.3, -0.7, nullptr, VariationStage::Post);
  EXPECT_DOUBLE_EQ(post.x[0], 0.3);
  EXPECT_DOUBLE_EQ(post.y[0], -0.7);
  EXPECT_NEAR(post.z[0], 0.5 + 0.20087411764705881, 1e-12);
  const Painted ordinary = paint(colormap(0.3, 0.1, 1.0, 1.0, 1.0, 0.0), 0.3, -0.7, nullptr);
  EXPECT_EQ(ordinary.x[0], 0.0);
  EXPECT_EQ(ordinary.y[0], 0.0);
  EXPECT_NEAR(ordinary.z[0], 0.20087411764705881, 1e-12);
}

// with_alpha: a point on a transparent pixel (outside the untiled picture, x > 0.506 here) is hidden, and stays
// hidden through transforms without colormap_wf (JWildfire's doHide lasts from point to point) until a colormap_wf
// term shows it again. Both transforms are the identity, so every lane keeps its x: a lane at x = 0.9 is drawn
// until it first takes transform 0, and never after; one at x = 0.1 always. Without with_alpha nothing is hidden.
TEST(FlameVariationColormap, WithAlphaHidesPointsOnTransparentPixelsUntilShown) {
  std::string palette;
  for (int k = 0; k < 256; ++k) palette += "<color index=\"" + std::to_string(k) + "\" rgb=\"200 100 50\"/>";
  const auto flame = [&](int withAlpha) {
    const std::string text =
        "<flames><flame name=\"t\" version=\"JWildfire V8.00\" size=\"48 48\" center=\"0 0\" scale=\"40\">"
        "<xform weight=\"1\" color=\"0\" linear=\"1\" colormap_wf=\"1\" colormap_wf_tile_x=\"0\" "
        "colormap_wf_tile_y=\"0\" colormap_wf_with_alpha=\"" +
        std::to_string(withAlpha) +
        "\" coefs=\"1 0 0 1 0 0\"/><xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>" + palette +
        "</flame></flames>";
    const ImportedFlame imported = readFlameXml(text, "t.flame").flame;
    EXPECT_TRUE(imported.leftOut.empty());
    return sceneFromImportedFlame(imported, Scene{}).layers.at(0);
  };
  for (const int withAlpha : {1, 0}) {
    const ChaosGame game(flame(withAlpha), "the test flame");
    EXPECT_TRUE(game.hidesPoints());
    constexpr std::size_t kLanes = 64;
    ChaosLanes lanes;
    lanes.resize(kLanes);
    SplitMix64 rng(11);
    for (std::size_t i = 0; i < kLanes; ++i) {
      game.seedLane(lanes, i, rng);
      lanes.x[i] = i % 2 ? 0.9 : 0.1;
      lanes.y[i] = 0.0;
    }
    std::vector<double> x(kLanes), y(kLanes), z(kLanes), c(kLanes);
    std::vector<bool> tookFirst(kLanes, false);
    std::size_t hidden = 0;
    for (int step = 0; step < 12; ++step) {
      game.step(lanes, x.data(), y.data(), z.data(), c.data(), kLanes);
      for (std::size_t i = 0; i < kLanes; ++i) {
        tookFirst[i] = tookFirst[i] || lanes.choice[i] == 0;
        const bool shown = withAlpha == 0 || i % 2 == 0 || !tookFirst[i];
        EXPECT_EQ(lanes.visible[i] != 0, shown) << "lane " << i << ", step " << step;
        hidden += lanes.visible[i] == 0;
      }
    }
    EXPECT_EQ(hidden > 100u, withAlpha == 1);
  }
}

// A 4 × 3 PNG of distinct opaque colours (pixel (i, j) = (60 i, 80 j, 200)) but for a transparent bottom-right
// pixel, as JWildfire inlines a picture: the hex of the file's bytes.
std::string inlinedPicture() {
  ImageRGBA image;
  image.width = 4;
  image.height = 3;
  image.pixels.resize(4 * 12);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      float* p = image.at(i, j);
      p[0] = static_cast<float>(60 * i) / 255.0f;
      p[1] = static_cast<float>(80 * j) / 255.0f;
      p[2] = 200.0f / 255.0f;
      p[3] = i == 3 && j == 2 ? 0.0f : 1.0f;
    }
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "voxflame_colormap_inlined.png";
  writePng(path, image, 8, {});
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  std::string hex;
  for (const char c : bytes) {
    constexpr const char* kDigits = "0123456789abcdef";
    hex += kDigits[static_cast<unsigned char>(c) >> 4];
    hex += kDigits[static_cast<unsigned char>(c) & 15u];
  }
  return hex;
}

// An inlined picture replaces the default one, scaled by its size − 2: (0.3, 0.2) reads pixel (⌊1.6⌉, ⌊0.7⌉) =
// (2, 1) = (120, 80, 200), (0.6, −0.1) pixel (2, 0); the transparent pixel (3, 2), reached from (1, 1.5), keeps
// its colour (180, 160, 200), as JWildfire's pixel does, and with_alpha hides a point there (or outside).
TEST(FlameVariationColormap, AnInlinedPngIsThePicture) {
  const std::vector<std::string> texts = {"", inlinedPicture(), "", ""};
  std::vector<double> params = colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0);
  EXPECT_EQ(paint(params, 0.3, 0.2, nullptr, VariationStage::Normal, &texts).rgb[0], paintedRgb(120, 80, 200));
  EXPECT_EQ(paint(params, 0.6, -0.1, nullptr, VariationStage::Normal, &texts).rgb[0], paintedRgb(120, 0, 200));
  const Painted transparent = paint(params, 1.0, 1.5, nullptr, VariationStage::Normal, &texts);
  EXPECT_EQ(transparent.rgb[0], paintedRgb(180, 160, 200));
  EXPECT_EQ(transparent.hidden[0], 0u);  // without with_alpha
  params[11] = 1.0;
  EXPECT_EQ(paint(params, 1.0, 1.5, nullptr, VariationStage::Normal, &texts).hidden[0], 1u);
  EXPECT_EQ(paint(params, 0.3, 0.2, nullptr, VariationStage::Normal, &texts).hidden[0], 0u);
  params[6] = params[7] = 0.0;  // untiled: outside the picture is transparent black
  EXPECT_EQ(paint(params, 5.0, 0.2, nullptr, VariationStage::Normal, &texts).hidden[0], 1u);
  params = colormap(0.0, 0.0, 1.0, 1.0, 0.0, 0.0);
  EXPECT_TRUE(colormapPictureProblem(texts[1]).empty());
  // Garbage in the text draws the default picture, and says why.
  const std::vector<std::string> garbage = {"", "6e6f742061207069637475726521", "", ""};
  EXPECT_EQ(paint(params, 0.3, -0.7, nullptr, VariationStage::Normal, &garbage).rgb[0], paintedRgb(50, 81, 205));
  EXPECT_NE(colormapPictureProblem(garbage[1]).find("PNG"), std::string::npos);
  EXPECT_FALSE(colormapPictureProblem("zz").empty());
}

// The importer keeps an inlined PNG (as its hex) and names a picture it cannot draw: a file the flame only names,
// or an inlined picture that is not a PNG.
TEST(FlameVariationColormap, TheImportKeepsAnInlinedPngAndNamesAPictureItCannotDraw) {
  const auto import = [](const std::string& resources) {
    return readFlameXml(
               "<flames><flame name=\"t\" version=\"JWildfire V8.00\" size=\"48 48\" center=\"0 0\" "
               "scale=\"40\"><xform weight=\"1\" color=\"0\" colormap_wf=\"1\" " +
                   resources + " coefs=\"1 0 0 1 0 0\"/></flame></flames>",
               "t.flame")
        .flame;
  };
  const std::string png = inlinedPicture();
  const ImportedFlame inlined = import("colormap_wf_image_filename=\"\" colormap_wf_inlined_image=\"" + png + "\"");
  EXPECT_TRUE(inlined.leftOut.empty());
  EXPECT_EQ(inlined.genome.xforms.at(0).variations.at(0).texts.at(1), png);
  const ImportedFlame file = import("colormap_wf_image_filename=\"2f746d702f612e706e67\"");  // "/tmp/a.png"
  EXPECT_EQ(file.leftOut, (std::vector<std::string>{"picture of colormap_wf"}));
  const ImportedFlame jpeg = import("colormap_wf_inlined_image=\"ffd8ffe000104a464946\"");
  EXPECT_EQ(jpeg.leftOut, (std::vector<std::string>{"picture of colormap_wf"}));
}

}  // namespace
