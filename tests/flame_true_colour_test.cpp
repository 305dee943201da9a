// JWildfire's true colour per point (XYZPoint.rgbColor): variations that paint a point an RGB colour
// instead of a colour index (dc_quadtree's, dc_ducks' and dc_booleans' Gradient 0, the palette's
// nearest colour with Gradient 1), the chaos game that keeps what the last transform painted, and the
// flat view that draws it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/chaos_game.h"
#include "core/flame/flat_render.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"
#include "variation_point_case.h"

using namespace voxflame::core;
using namespace voxflame::test;

namespace {

struct Painted {
  std::vector<std::uint32_t> rgb;
  std::vector<double> colour;
};

// The variation over `lanes` lanes at one point with a true-colour array (0 before) and, when given, a palette.
Painted paint(const VariationInfo& info, const std::vector<double>& params, std::uint32_t seed, std::size_t lanes,
              const std::uint32_t* palette) {
  std::vector<double> xs(lanes, 0.3), ys(lanes, -0.7), zs(lanes, 0.5), ox(lanes, 0.0), oy(lanes, 0.0), oz(lanes, 0.0);
  std::vector<std::uint32_t> random(lanes, seed);
  Painted out{std::vector<std::uint32_t>(lanes, 0u), std::vector<double>(lanes, kStartColour)};
  VariationInput in;
  in.x = in.tx = xs.data();
  in.y = in.ty = ys.data();
  in.z = in.tz = zs.data();
  in.random = random.data();
  in.count = lanes;
  in.weight = 0.8;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = out.colour.data();
  in.rgb = out.rgb.data();
  in.palette = palette;
  info.apply(in, ox.data(), oy.data(), oz.data());
  return out;
}

std::uint32_t packed(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return r | g << 8 | b << 16;
}

// A palette of navy (0, 0, 200) below entry 128 and near-white (250, 250, 250) from it.
std::vector<std::uint32_t> navyAndWhite() {
  std::vector<std::uint32_t> palette(256);
  for (std::size_t k = 0; k < palette.size(); ++k) palette[k] = k < 128 ? packed(0, 0, 200) : packed(250, 250, 250);
  return palette;
}

// The pattern colours of these cases are the hand-computed ones of the holdout variations' tests: dc_quadtree's
// (255, 255, 255) and dc_ducks' (0, 0, 232) at the first draw of kHighSeed.
const std::vector<double> kQuadtree = {1.0, 10000.0, 0.0, 1000.0, 30.0, 0.0, 0.0, 0.0, 0.0, 1.0};
const std::vector<double> kDucks = {10000.0, 10.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0};

TEST(FlameTrueColour, DcBaseGradientZeroPaintsThePatternsColourAndLeavesTheIndex) {
  const VariationInfo& quadtree = variationOrThrow("dc_quadtree");
  const VariationInfo& ducks = variationOrThrow("dc_ducks");
  EXPECT_TRUE(quadtree.paintsRgb);
  EXPECT_TRUE(ducks.paintsRgb);
  EXPECT_FALSE(variationOrThrow("linear").paintsRgb);
  // 37 lanes: the vectorised body and the scalar tail agree.
  const Painted q = paint(quadtree, kQuadtree, kHighSeed, 37, nullptr);
  const Painted d = paint(ducks, kDucks, kHighSeed, 37, nullptr);
  for (std::size_t lane = 0; lane < 37; ++lane) {
    EXPECT_EQ(q.rgb[lane], paintedRgb(255, 255, 255)) << lane;
    EXPECT_EQ(d.rgb[lane], paintedRgb(0, 0, 232)) << lane;
    EXPECT_EQ(q.colour[lane], kStartColour);
    EXPECT_EQ(d.colour[lane], kStartColour);
  }
}

// Gradient 1: the palette's entry nearest to the pattern's colour (JWildfire's findKey), painted; without a
// palette at hand nothing is painted. Gradient 2 paints nothing and sets the index to the grey level.
TEST(FlameTrueColour, DcBaseGradientOnePaintsThePalettesNearestEntry) {
  const std::vector<std::uint32_t> palette = navyAndWhite();
  std::vector<double> quadtree = kQuadtree, ducks = kDucks;
  quadtree[6] = 1.0;
  ducks[4] = 1.0;
  const Painted q = paint(variationOrThrow("dc_quadtree"), quadtree, kHighSeed, 5, palette.data());
  const Painted d = paint(variationOrThrow("dc_ducks"), ducks, kHighSeed, 5, palette.data());
  EXPECT_EQ(q.rgb[0], paintedRgb(250, 250, 250));
  EXPECT_EQ(d.rgb[0], paintedRgb(0, 0, 200));
  EXPECT_EQ(q.colour[0], kStartColour);
  EXPECT_EQ(paint(variationOrThrow("dc_quadtree"), quadtree, kHighSeed, 5, nullptr).rgb[0], 0u);
  quadtree[6] = 2.0;
  const Painted grey = paint(variationOrThrow("dc_quadtree"), quadtree, kHighSeed, 5, palette.data());
  EXPECT_EQ(grey.rgb[0], 0u);
  EXPECT_DOUBLE_EQ(grey.colour[0], 254.0 / 255.0);  // white's grey level: (76 + 149 + 29) / 255
  EXPECT_EQ(nearestPaletteEntry(palette.data(), 10, 10, 10), 0u);
  EXPECT_EQ(nearestPaletteEntry(palette.data(), 200, 200, 200), 128u);
}

// dc_booleans paints its hsv colour with Gradient 0 (whose luminance is the index Gradient 2 sets: 34/255 for
// these parameters and draw), leaving the index; without a true-colour array the luminance stands in.
TEST(FlameTrueColour, DcBooleansPaintsItsColour) {
  const VariationInfo& info = variationOrThrow("dc_booleans");
  EXPECT_TRUE(info.paintsRgb);
  const Painted p = paint(info, info.defaultParams(), kHighSeed, 3, nullptr);
  ASSERT_TRUE(p.rgb[0] & kRgbPainted);
  EXPECT_EQ(p.colour[0], kStartColour);
  const double r = p.rgb[0] & 255u, g = p.rgb[0] >> 8 & 255u, b = p.rgb[0] >> 16 & 255u;
  EXPECT_EQ(static_cast<int>(r * 0.299) + static_cast<int>(g * 0.587) + static_cast<int>(b * 0.114), 34);
  EXPECT_DOUBLE_EQ(run(info, info.defaultParams(), {0.3, -0.7, 0.5}, 0.8, kHighSeed, 3).colour[0], 34.0 / 255.0);
}

// A flame for the tests below: JWildfire's XML with a uniform palette of (r, g, b), or two halves.
std::string paletteXml(std::uint32_t low, std::uint32_t high) {
  std::string text;
  for (int k = 0; k < 256; ++k) {
    const std::uint32_t c = k < 128 ? low : high;
    text += "<color index=\"" + std::to_string(k) + "\" rgb=\"" + std::to_string(c & 255u) + " " +
            std::to_string(c >> 8 & 255u) + " " + std::to_string(c >> 16 & 255u) + "\"/>";
  }
  return text;
}

// dc_quadtree with one level at time 0 paints one colour, (33, 33, 255), but in a hair's width at the square's
// border (black).
std::string quadtreeXform(int gradient, const std::string& colour) {
  return "<xform weight=\"1\" color=\"" + colour +
         "\" dc_quadtree=\"1\" dc_quadtree_zoom=\"1\" dc_quadtree_time=\"0\" dc_quadtree_width=\"1000\" "
         "dc_quadtree_levels=\"1\" dc_quadtree_ColorOnly=\"0\" dc_quadtree_Gradient=\"" +
         std::to_string(gradient) +
         "\" dc_quadtree_scale_z=\"0\" dc_quadtree_offset_z=\"0\" dc_quadtree_reset_z=\"1\" coefs=\"1 0 0 1 0 0\"/>";
}

ImportedFlame importFlame(const std::string& body, const std::string& palette) {
  const std::string text =
      "<flames><flame name=\"t\" version=\"JWildfire V8.00\" size=\"48 48\" center=\"0 0\" "
      "scale=\"40\" estimator_radius=\"0\">" +
      body + palette + "</flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

PatternLayer layerOf(const ImportedFlame& flame) {
  return sceneFromImportedFlame(flame, Scene{}).layers.at(0);
}

// The chaos game keeps what the last transform painted: a transform without a painting term leaves the point to
// its colour index (JWildfire clears rgbColor as each transform starts and its colour step then takes the
// palette's colour), while a final transform without one keeps the point's colour (JWildfire's final transforms
// have no colour step unless the file gives them a colour type).
TEST(FlameTrueColour, TheChaosGameKeepsWhatTheLastTransformPainted) {
  const std::string red = paletteXml(packed(255, 0, 0), packed(255, 0, 0));
  const std::string linear = "<xform weight=\"1\" color=\"0.5\" linear=\"0.5\" coefs=\"1 0 0 1 0.2 0\"/>";
  const auto run = [](const ImportedFlame& flame, std::size_t steps) {
    const ChaosGame game(layerOf(flame), "the test flame");
    ChaosLanes lanes;
    lanes.resize(64);
    SplitMix64 rng(7);
    for (std::size_t i = 0; i < 64; ++i) game.seedLane(lanes, i, rng);
    std::vector<double> x(64), y(64), z(64), c(64);
    for (std::size_t s = 0; s < steps; ++s) game.step(lanes, x.data(), y.data(), z.data(), c.data(), 64);
    return std::make_pair(game.paintsRgb(), lanes);
  };
  const auto isQuadtreeColour = [](std::uint32_t rgb) {
    return rgb == paintedRgb(33, 33, 255) || rgb == paintedRgb(0, 0, 0);
  };
  EXPECT_FALSE(run(importFlame(linear, red), 3).first);

  const auto [paints, lanes] = run(importFlame(quadtreeXform(0, "0") + linear, red), 5);
  ASSERT_TRUE(paints);
  int painted = 0, plain = 0;
  for (std::size_t i = 0; i < 64; ++i) {
    if (lanes.choice[i] == 0) {
      EXPECT_TRUE(isQuadtreeColour(lanes.rgb[i])) << std::hex << lanes.rgb[i];
      ++painted;
    } else {
      EXPECT_EQ(lanes.rgb[i], 0u);
      ++plain;
    }
  }
  EXPECT_GT(painted, 10);
  EXPECT_GT(plain, 10);

  // A final transform that paints nothing keeps what the transform before it painted, or did not paint.
  const std::string plainFinal = "<finalxform color=\"0\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>";
  const auto [finalPaints, finalLanes] = run(importFlame(quadtreeXform(0, "0") + linear + plainFinal, red), 5);
  ASSERT_TRUE(finalPaints);
  for (std::size_t i = 0; i < 64; ++i) {
    if (finalLanes.choice[i] == 0)
      EXPECT_TRUE(isQuadtreeColour(finalLanes.rgb[i])) << std::hex << finalLanes.rgb[i];
    else
      EXPECT_EQ(finalLanes.rgb[i], 0u);
  }
  const std::string paintingFinal =
      "<finalxform color=\"0\" dc_quadtree=\"1\" dc_quadtree_levels=\"1\" "
      "dc_quadtree_time=\"0\" dc_quadtree_Gradient=\"0\" coefs=\"1 0 0 1 0 0\"/>";
  for (std::uint32_t rgb : run(importFlame(linear + paintingFinal, red), 5).second.rgb)
    EXPECT_TRUE(isQuadtreeColour(rgb)) << std::hex << rgb;
}

ImageRGBA renderFlame(const ImportedFlame& flame) {
  FlatRenderOptions options;
  options.quality = 20.0;
  return renderFlat(sceneFromImportedFlame(flame, Scene{}), options).image;
}

// The share of the channel values of two images that differ by more than 2/255 (the picture's levels differ by
// one step where the painted colour's bytes and the palette's float entry fall either side of one).
double differingShare(const ImageRGBA& a, const ImageRGBA& b) {
  std::size_t differing = 0;
  for (std::size_t k = 0; k < a.pixels.size(); ++k) differing += std::abs(a.pixels[k] - b.pixels[k]) > 2.0f / 255.0f;
  return static_cast<double>(differing) / static_cast<double>(a.pixels.size());
}

// The flat view draws the painted colours: dc_quadtree's Gradient 0 over a red palette draws as its Gradient 2
// (the same points, coloured by the index) over a palette of the painted (33, 33, 255) does; Gradient 1 over a
// half-navy, half-red palette, with the transform's colour index in the red half, draws as over all navy, the
// entry nearest to (33, 33, 255).
TEST(FlameTrueColour, TheFlatViewDrawsThePaintedColours) {
  const ImportedFlame trueColour = importFlame(quadtreeXform(0, "0"), paletteXml(packed(255, 0, 0), packed(255, 0, 0)));
  EXPECT_TRUE(trueColour.leftOut.empty()) << trueColour.leftOut.front();
  const ImportedFlame blue = importFlame(quadtreeXform(2, "0"), paletteXml(packed(33, 33, 255), packed(33, 33, 255)));
  const ImportedFlame redIndex = importFlame(quadtreeXform(2, "0"), paletteXml(packed(255, 0, 0), packed(255, 0, 0)));
  const ImageRGBA painted = renderFlame(trueColour);
  EXPECT_LT(differingShare(painted, renderFlame(blue)), 0.01);
  EXPECT_GT(differingShare(painted, renderFlame(redIndex)), 0.3);
  double red = 0.0, bluePart = 0.0;
  for (std::size_t k = 0; k < painted.pixels.size(); k += 4) {
    red += painted.pixels[k];
    bluePart += painted.pixels[k + 2];
  }
  EXPECT_GT(bluePart, 4.0 * red);  // blue, with a little red (33 of 255)
  EXPECT_GT(red, 0.05 * bluePart);

  const ImportedFlame nearest = importFlame(quadtreeXform(1, "1"), paletteXml(packed(0, 0, 200), packed(255, 0, 0)));
  EXPECT_TRUE(nearest.leftOut.empty()) << nearest.leftOut.front();
  const ImportedFlame navy = importFlame(quadtreeXform(2, "1"), paletteXml(packed(0, 0, 200), packed(0, 0, 200)));
  EXPECT_LT(differingShare(renderFlame(nearest), renderFlame(navy)), 0.01);
}

}  // namespace
