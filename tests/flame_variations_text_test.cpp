// text_wf (JWildfire's points of a line of text: variations_text.cpp, text_raster.cpp). The text is
// drawn by FreeType in DejaVu Sans (the project's setup installs it; fontconfig offers it for any
// family that is not installed), so the tests check the picture's layout and the kernel's use of it,
// not one font's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/flame/flame.h"
#include "core/flame/text_raster.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

namespace voxflame::test {
namespace {

using core::rasteriseText;
using core::TextRaster;
using core::VariationInfo;

// A family no machine has: fontconfig offers its default sans-serif instead.
constexpr const char* kMissingFont = "Zz No Such Family";

// text_wf once at the point (0.3, −0.7, 0.5), weight 0.8, with these parameters and texts (text, font_name).
glm::dvec3 runTextWf(const std::vector<double>& params, const std::vector<std::string>& texts, std::uint32_t seed) {
  const VariationInfo& info = core::variationOrThrow("text_wf");
  double x = 0.3, y = -0.7, z = 0.5, ox = 0.0, oy = 0.0, oz = 0.0, colour = 0.375;
  std::uint32_t random = seed;
  core::VariationInput in;
  in.x = in.tx = &x;
  in.y = in.ty = &y;
  in.z = in.tz = &z;
  in.random = &random;
  in.count = 1;
  in.weight = 0.8;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = &colour;
  in.texts = texts.data();
  info.apply(in, &ox, &oy, &oz);
  return {ox, oy, oz};
}

// At font size 0 nothing is painted (Java draws nothing): JWildfire then adds a unit square's random point (Ψ₁, Ψ₂),
// unweighted; z carried.
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      {"text_wf",
       {0, 0.5, 1, 1, 0, 0, 0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.8794664144515991, 0.545325517654419, 0.4}},
  };
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class FlameVariationTextAtPoint : public testing::TestWithParam<PointCase> {};
TEST_P(FlameVariationTextAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Cases, FlameVariationTextAtPoint, testing::ValuesIn(pointCases()), caseLabel);

// The same with a text that is empty.
TEST(FlameVariationText, EmptyTextAddsAUnitSquaresRandomPoint) {
  const glm::dvec3 out = runTextWf({320, 0.5, 1, 1, 0, 0, 0}, {"", "Arial"}, kHighSeed);
  EXPECT_DOUBLE_EQ(out.x, 0.8794664144515991);
  EXPECT_DOUBLE_EQ(out.y, 0.545325517654419);
  EXPECT_DOUBLE_EQ(out.z, 0.4);
}

// The picture's layout is JWildfire's TextTransformer's: the text's size plus the font size on every
// side, the text centred in it, not antialiased.
TEST(FlameVariationText, TheTextIsCentredInAnImageOfItsSizePlusTheFontSizeOnEverySide) {
  const TextRaster raster = rasteriseText("IIII", kMissingFont, 100, 0);
  ASSERT_TRUE(raster.problem.empty()) << raster.problem;
  ASSERT_GT(raster.column.size(), 100u);
  int left = raster.width, right = 0, top = raster.height, bottom = 0;
  for (std::size_t k = 0; k < raster.column.size(); ++k) {
    left = std::min(left, raster.column[k]);
    right = std::max(right, raster.column[k]);
    top = std::min(top, raster.row[k]);
    bottom = std::max(bottom, raster.row[k]);
  }
  // A margin of the font size (100) and more round the painted area, the text centred across.
  EXPECT_GE(left, 100);
  EXPECT_GE(top, 100);
  EXPECT_LE(right, raster.width - 100);
  EXPECT_LE(bottom, raster.height - 100);
  EXPECT_LE(std::abs((left + right) - raster.width), 12) << left << " " << right << " of " << raster.width;
  // Four capital I's: taller than wide, and about 0.7 of the 100-pixel size tall.
  EXPECT_GT(bottom - top, 60);
  EXPECT_LT(bottom - top, 90);
  // In row order, as JWildfire lists them.
  for (std::size_t k = 1; k < raster.row.size(); ++k)
    ASSERT_TRUE(raster.row[k] > raster.row[k - 1] ||
                (raster.row[k] == raster.row[k - 1] && raster.column[k] > raster.column[k - 1]));
  // A baseline offset moves the text down by that many pixels (half of it, as the picture grows too).
  const TextRaster lower = rasteriseText("IIII", kMissingFont, 100, 40);
  int lowerTop = lower.height;
  for (const int row : lower.row) lowerTop = std::min(lowerTop, row);
  EXPECT_EQ(lower.height, raster.height + 40);
  EXPECT_EQ(lowerTop - top, 40);
}

// text_wf adds 3 (scale X + offset) of the pixel Ψ₁ picks, (X, Y) its place in the picture over the picture's width
// and height; the weight does not scale it.
TEST(FlameVariationText, TheKernelAddsThePickedPixelScaledAndMoved) {
  const std::vector<std::string> texts = {"Hello", kMissingFont};
  const TextRaster raster = rasteriseText(texts[0], texts[1], 64, 0);
  ASSERT_GT(raster.column.size(), 1u);
  const std::vector<double> params = {64, 0.0, 1.5, -0.5, 0.25, 0.125, 0};  // antialias 0: no blur
  for (const std::uint32_t seed : {kHighSeed, kLowSeed}) {
    const glm::dvec3 out = runTextWf(params, texts, seed);
    std::uint32_t replay = seed;
    const double psi = core::laneUniform(replay);
    const auto k = static_cast<std::size_t>(psi * static_cast<double>(raster.column.size()));
    const double px = (raster.column[k] - raster.width / 2.0) / raster.width;
    const double py = (raster.row[k] - raster.height / 2.0) / raster.height;
    EXPECT_NEAR(out.x, 3.0 * (1.5 * px + 0.25), 1e-12);
    EXPECT_NEAR(out.y, 3.0 * (-0.5 * py + 0.125), 1e-12);
    EXPECT_NEAR(out.z, 0.4, 1e-12);
  }
}

// Odd sizes never hang or take unbounded memory: a huge font size is drawn smaller, a NaN or zero one
// draws nothing and the kernel falls back to the unit square; a long text is cut.
TEST(FlameVariationText, OddSizesAndLongTextsStayBounded) {
  const TextRaster huge = rasteriseText("Wide text", kMissingFont, 1000000, 0);
  EXPECT_LE(huge.width, 2 * core::kTextRasterMaxSide);
  EXPECT_LE(huge.height, 2 * core::kTextRasterMaxSide);
  EXPECT_GT(huge.column.size(), 1u);
  const TextRaster none = rasteriseText("", kMissingFont, 100, 0);
  EXPECT_TRUE(none.column.empty());
  const TextRaster longText = rasteriseText(std::string(100000, 'x'), kMissingFont, 50, 0);
  EXPECT_LE(longText.width, 2 * core::kTextRasterMaxSide);
  const std::vector<std::string> texts = {"Hi", kMissingFont};
  for (const double size : {std::nan(""), 0.0, -5.0, 1e300}) {
    const glm::dvec3 out = runTextWf({size, 0.5, 1, 1, 0, 0, 0}, texts, kLowSeed);
    EXPECT_TRUE(std::isfinite(out.x) && std::isfinite(out.y)) << size;
  }
}

std::string hexOf(const std::string& text) {
  std::string hex;
  char byte[3];
  for (const unsigned char c : text) {
    std::snprintf(byte, sizeof(byte), "%02X", c);
    hex += byte;
  }
  return hex;
}

// A file's text and font (JWildfire's hex resources) are read; a font that is not installed is named with the
// family that stands in, which is no loss; a text that paints nothing is.
TEST(FlameVariationText, ImportReadsTheTextAndNamesAFontThatStandsIn) {
  const auto flameWith = [](const std::string& text, const std::string& font) {
    return "<flames><flame name=\"t\" size=\"64 64\" version=\"JWildfire V7.50\"><xform weight=\"1\" color=\"0\" "
           "text_wf=\"1\" text_wf_font_size=\"120\" text_wf_scale_x=\"1.333\" text_wf_text=\"" +
           hexOf(text) + "\" text_wf_font_name=\"" + hexOf(font) +
           "\" coefs=\"1 0 0 1 0 0\"/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  };
  const core::ImportedFlame flame = core::readFlameXml(flameWith("Generative art.", kMissingFont), "t.flame").flame;
  const core::VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "text_wf");
  ASSERT_EQ(term.texts.size(), 2u);
  EXPECT_EQ(term.texts[0], "Generative art.");
  EXPECT_EQ(term.texts[1], kMissingFont);
  EXPECT_DOUBLE_EQ(term.params.at(0), 120.0);
  EXPECT_DOUBLE_EQ(term.params.at(2), 1.333);
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const bool named = std::any_of(flame.warnings.begin(), flame.warnings.end(), [](const std::string& w) {
    return w.find("in the font 'Zz No Such Family', which is not installed here;") != std::string::npos &&
           w.find("draws its text") != std::string::npos;
  });
  EXPECT_TRUE(named) << (flame.warnings.empty() ? std::string("no warning") : flame.warnings.front());
  const core::ImportedFlame blank = core::readFlameXml(flameWith("   ", kMissingFont), "blank.flame").flame;
  EXPECT_EQ(blank.leftOut, (std::vector<std::string>{"text of text_wf"}));
}

}  // namespace
}  // namespace voxflame::test
