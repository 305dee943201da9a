// svg_wf (JWildfire's points of an SVG drawing: variations_svg.cpp, svg_raster.cpp) and the static
// and cropmode 2 forms of smartcrop (Fractorium's post_smartcrop, which keeps the last point it let
// through per lane).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/flame/flame.h"
#include "core/flame/svg_raster.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "variation_point_case.h"

namespace voxflame::test {
namespace {

using core::rasteriseSvg;
using core::SvgRaster;
using core::VariationInfo;
using core::VariationInput;

// A square outline: corners (10, 10) and (90, 90) of a 100 × 100 document, stroked 2 wide.
const std::string kSquare =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"100\">"
    "<path d=\"M 10 10 H 90 V 90 H 10 Z\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\"/></svg>";

// Runs svg_wf with `document` over `lanes` lanes from one seed each; returns (x, y) pairs.
std::vector<std::array<double, 2>> svgPoints(const std::string& document, const std::vector<double>& params,
                                             std::size_t lanes) {
  const VariationInfo& info = core::variationOrThrow("svg_wf");
  std::vector<double> xs(lanes, 0.3), ys(lanes, -0.2), zs(lanes, 0.5), ox(lanes, 0.0), oy(lanes, 0.0), oz(lanes, 0.0),
      colour(lanes, 0.5);
  std::vector<std::uint32_t> random(lanes);
  for (std::size_t i = 0; i < lanes; ++i) random[i] = 0x9E3779B9u * static_cast<std::uint32_t>(i + 1) | 1u;
  const std::vector<std::string> texts = {document};
  VariationInput in;
  in.x = xs.data();
  in.y = ys.data();
  in.z = zs.data();
  in.tx = xs.data();
  in.ty = ys.data();
  in.tz = zs.data();
  in.random = random.data();
  in.count = lanes;
  in.weight = 1.0;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = colour.data();
  in.texts = texts.data();
  info.apply(in, ox.data(), oy.data(), oz.data());
  std::vector<std::array<double, 2>> out;
  for (std::size_t i = 0; i < lanes; ++i) out.push_back({ox[i], oy[i]});
  return out;
}

std::vector<double> svgParams(double blurRadius, double resolution, double antialias) {
  std::vector<double> p = core::variationOrThrow("svg_wf").defaultParams();
  p[0] = blurRadius;
  p[1] = resolution;
  p[3] = antialias;
  return p;
}

TEST(SvgRaster, ASquarePathPaintsItsOutlineOnly) {
  const SvgRaster raster = rasteriseSvg(kSquare, 1.0, false);
  EXPECT_TRUE(raster.problems.empty());
  EXPECT_EQ(raster.width, 100);
  EXPECT_EQ(raster.height, 100);
  ASSERT_FALSE(raster.column.empty());
  for (std::size_t k = 0; k < raster.column.size(); ++k) {
    // Pixel centres within the stroke's half width (1) of the outline x or y = 10 or 90.
    const double x = raster.column[k] + 0.5, y = raster.row[k] + 0.5;
    const double toSide = std::min({std::abs(x - 10.0), std::abs(x - 90.0), std::abs(y - 10.0), std::abs(y - 90.0)});
    EXPECT_LE(toSide, 1.0 + 1e-9) << x << ", " << y;
    EXPECT_TRUE(x >= 9.0 && x <= 91.0 && y >= 9.0 && y <= 91.0) << x << ", " << y;
  }
  // 4 sides of 80 pixels, 2 rows thick (the corners shared): about 640 pixels.
  EXPECT_NEAR(static_cast<double>(raster.column.size()), 640.0, 24.0);
  // Antialiased, the pixels a slanted stroke only touches count too (the square's stroke covers
  // whole pixels, so antialiasing adds none to it).
  EXPECT_EQ(rasteriseSvg(kSquare, 1.0, true).column.size(), raster.column.size());
  const std::string slanted =
      "<svg width=\"60\" height=\"60\"><line x1=\"3\" y1=\"5\" x2=\"50\" y2=\"37\" stroke=\"#000\"/></svg>";
  EXPECT_GT(rasteriseSvg(slanted, 1.0, true).column.size(), rasteriseSvg(slanted, 1.0, false).column.size());
  // A filled square paints its inside.
  const SvgRaster filled = rasteriseSvg(
      "<svg width=\"20\" height=\"20\"><rect x=\"5\" y=\"5\" width=\"10\" height=\"10\"/></svg>", 1.0, false);
  EXPECT_EQ(filled.column.size(), 100u);
}

TEST(SvgRaster, ShapesTransformsAndViewBoxAreDrawn) {
  // A circle of radius 10 through a translate, in a viewBox twice the size: radius 20 pixels.
  const SvgRaster circle = rasteriseSvg(
      "<svg width=\"100\" height=\"100\" viewBox=\"0 0 50 50\"><g transform=\"translate(25 25)\">"
      "<circle r=\"10\" fill=\"red\"/></g></svg>",
      1.0, false);
  EXPECT_TRUE(circle.problems.empty());
  EXPECT_NEAR(static_cast<double>(circle.column.size()), std::numbers::pi * 400.0, 40.0);
  for (std::size_t k = 0; k < circle.column.size(); ++k)
    EXPECT_LE(std::hypot(circle.column[k] + 0.5 - 50.0, circle.row[k] + 0.5 - 50.0), 20.0 + 1e-9);
  // Hidden and unpainted shapes draw nothing; inherited fill="none" holds in the group.
  const SvgRaster none = rasteriseSvg(
      "<svg width=\"40\" height=\"40\"><g fill=\"none\"><rect width=\"10\" height=\"10\"/></g>"
      "<rect width=\"10\" height=\"10\" style=\"display:none\"/><rect width=\"10\" height=\"10\" opacity=\"0\"/>"
      "<defs><rect width=\"10\" height=\"10\"/></defs></svg>",
      1.0, true);
  EXPECT_TRUE(none.column.empty());
  // The resolution multiplier scales the image.
  EXPECT_EQ(rasteriseSvg(kSquare, 0.5, true).width, 50);
}

TEST(SvgWf, PointsOfASquareLieOnItsOutlineAndCoverAllFourSides) {
  const auto points = svgPoints(kSquare, svgParams(0.0, 1.0, 0.0), 4000);
  // Painted pixels 9…90 both ways: xSize = ySize = 81, centred: the outline at ±(80/81)/2 ± 1/81.
  int sides[4] = {0, 0, 0, 0};
  for (const auto& [x, y] : points) {
    const double edge = 40.0 / 81.0, slack = 1.01 / 81.0;
    const bool left = std::abs(x + edge) <= slack, right = std::abs(x - edge) <= slack;
    const bool top = std::abs(y + edge) <= slack, bottom = std::abs(y - edge) <= slack;
    EXPECT_TRUE(left || right || top || bottom) << x << ", " << y;
    EXPECT_LE(std::max(std::abs(x), std::abs(y)), edge + slack);
    sides[0] += left;
    sides[1] += right;
    sides[2] += top;
    sides[3] += bottom;
  }
  for (const int side : sides) EXPECT_GT(side, 800) << "a side of the square gets too few points";
  // scale and offset as JWildfire's: x s + o, and the weight does not scale them.
  std::vector<double> params = svgParams(0.0, 1.0, 0.0);
  params[4] = 2.0;
  params[7] = 0.5;
  const auto scaled = svgPoints(kSquare, params, 64);
  for (std::size_t i = 0; i < scaled.size(); ++i) {
    EXPECT_NEAR(scaled[i][0], 2.0 * points[i][0], 1e-12);
    EXPECT_NEAR(scaled[i][1], points[i][1] + 0.5, 1e-12);
  }
}

TEST(SvgWf, MalformedDocumentsWarnAndStayFinite) {
  const std::vector<std::string> bad = {
      "<svg width=\"10\" height=\"10\"><path d=\"M 1 1 L 5",                                   // not XML
      "<svg width=\"10\" height=\"10\"><path d=\"M 1 1 L 5 5 L 7\"/></svg>",                   // truncated data
      "<svg width=\"10\" height=\"10\"><path d=\"M 1e400 1 L 5 -1e999 L 2 2 Z\"/></svg>",      // huge numbers
      "<svg width=\"10\" height=\"10\"><path d=\"M NaN 1 L 5 5\"/></svg>",                     // NaN
      "<svg width=\"10\" height=\"10\"><path d=\"M 1 1 X 5 5\"/></svg>",                       // unknown command
      "<svg width=\"1e300\" height=\"1e300\"><rect width=\"1e300\" height=\"1e300\"/></svg>",  // huge image
      "<html/>",
      "",
  };
  for (const std::string& document : bad) {
    SCOPED_TRACE(document);
    const auto start = std::chrono::steady_clock::now();
    const SvgRaster raster = rasteriseSvg(document, 100.0, true);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
    // Numbers past the double's range are drawn as very far off (finite); the others are reported.
    if (document.find("1e400") == std::string::npos) {
      EXPECT_FALSE(raster.problems.empty());
    }
    for (const auto& [x, y] : svgPoints(document, svgParams(0.5, 100.0, 1.0), 37)) {
      EXPECT_TRUE(std::isfinite(x) && std::isfinite(y)) << x << ", " << y;
    }
  }
  // What comes before an error is drawn (SVG's rule): the truncated path's first segment.
  EXPECT_FALSE(rasteriseSvg(bad[1], 1.0, true).column.empty());
  // With no picture, JWildfire's fallback: (Ψ, Ψ) in the unit square.
  for (const auto& [x, y] : svgPoints("<html/>", svgParams(0.5, 1.0, 1.0), 37)) {
    EXPECT_TRUE(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0);
  }
}

// The hex of a text's bytes, as JWildfire writes a resource.
std::string hexOf(const std::string& text) {
  std::string out;
  char two[3];
  for (const char c : text) {
    std::snprintf(two, sizeof two, "%02X", static_cast<unsigned char>(c));
    out += two;
  }
  return out;
}

TEST(SvgWf, AFlameWithSvgWfImportsItsDocumentAndKeepsItInTheScene) {
  const std::string xforms =
      "<xform weight=\"1\" color=\"0\" svg_wf=\"1\" svg_wf_antialias_radius=\"0.25\" "
      "svg_wf_resolution_multiplier=\"0.5\" svg_wf_pre_antialias=\"0\" svg_wf_scale_x=\"1.5\" "
      "svg_wf_svg=\"" +
      hexOf(kSquare) +
      "\" svg_wf_svg_enabled=\"false\" coefs=\"1 0 0 1 0 0\"/>"
      "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>";
  const std::string text = "<flames><flame name=\"svg\" version=\"JWildfire V6.50\">" + xforms + "</flame></flames>";
  const core::ImportedFlame flame = core::readFlameXml(text, "svg.flame").flame;
  ASSERT_EQ(flame.genome.xforms.size(), 2u);
  const core::VariationTerm& term = flame.genome.xforms[0].variations.at(0);
  EXPECT_EQ(term.name, "svg_wf");
  ASSERT_EQ(term.texts.size(), 1u);
  EXPECT_EQ(term.texts[0], kSquare);
  EXPECT_DOUBLE_EQ(term.params[0], 0.25);
  EXPECT_DOUBLE_EQ(term.params[1], 0.5);
  EXPECT_DOUBLE_EQ(term.params[3], 0.0);
  EXPECT_DOUBLE_EQ(term.params[4], 1.5);
  // Only the colouring by the SVG's colours is left out.
  EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"colour of svg_wf"}));
  // The scene keeps the document: written as text and read back equal.
  const core::Scene scene = core::sceneFromImportedFlame(flame, core::defaultScene());
  const core::Scene back = core::sceneFromJson(core::sceneToJson(scene), "svg.json");
  EXPECT_EQ(back.layers.at(0).flame.xforms.at(0).variations.at(0).texts, term.texts);

  // A resource that is not hex is reported, and the default drawing stands in.
  const std::string odd =
      "<flames><flame name=\"svg\"><xform weight=\"1\" svg_wf=\"1\" svg_wf_svg=\"<svg/>\" "
      "coefs=\"1 0 0 1 0 0\"/></flame></flames>";
  const core::ImportedFlame oddFlame = core::readFlameXml(odd, "odd.flame").flame;
  EXPECT_NE(std::find(oddFlame.leftOut.begin(), oddFlame.leftOut.end(), "svg_wf_svg"), oddFlame.leftOut.end());
  // Bytes that are not UTF-8 (a Latin-1 é in a comment) are read as Latin-1, so the scene can be saved.
  const std::string latin1 = "<flames><flame name=\"svg\"><xform weight=\"1\" svg_wf=\"1\" svg_wf_svg=\"" +
                             hexOf("<!-- caf\xE9 -->" + kSquare) + "\" coefs=\"1 0 0 1 0 0\"/></flame></flames>";
  const core::ImportedFlame latin1Flame = core::readFlameXml(latin1, "latin1.flame").flame;
  EXPECT_EQ(latin1Flame.genome.xforms.at(0).variations.at(0).texts.at(0), "<!-- caf\u00E9 -->" + kSquare);
  EXPECT_NO_THROW(core::sceneToJson(core::sceneFromImportedFlame(latin1Flame, core::defaultScene())));
  // A document that paints nothing is reported too.
  const std::string empty = "<flames><flame name=\"svg\"><xform weight=\"1\" svg_wf=\"1\" svg_wf_svg=\"" +
                            hexOf("<svg width=\"10\" height=\"10\"/>") + "\" coefs=\"1 0 0 1 0 0\"/></flame></flames>";
  const core::ImportedFlame emptyFlame = core::readFlameXml(empty, "empty.flame").flame;
  EXPECT_NE(std::find(emptyFlame.leftOut.begin(), emptyFlame.leftOut.end(), "picture of svg_wf"),
            emptyFlame.leftOut.end());
}

// ---- smartcrop's static modes and cropmode 2 ----------------------------------------------------

// One lane's call of smartcrop with memory `state`: the point p (x, y, z), the transform's point t,
// the colour index; returns (result, colour after).
struct CropResult {
  double x, y, z, colour;
};
CropResult smartcropOnce(const std::vector<double>& params, double weight, std::array<double, 3> p,
                         std::array<double, 3> t, double colour, std::uint32_t seed, double* state,
                         const std::uint32_t* lane = nullptr) {
  const VariationInfo& info = core::variationOrThrow("smartcrop");
  double ox = 0.0, oy = 0.0, oz = 0.0;
  VariationInput in;
  in.x = &p[0];
  in.y = &p[1];
  in.z = &p[2];
  in.tx = &t[0];
  in.ty = &t[1];
  in.tz = &t[2];
  in.random = &seed;
  in.count = 1;
  in.weight = weight;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = &colour;
  in.stage = core::VariationStage::Post;
  in.state = state;
  in.lanes = lane;
  info.apply(in, &ox, &oy, &oz);
  return {ox, oy, oz, colour};
}

void expectCrop(const CropResult& got, std::array<double, 4> expected) {
  EXPECT_NEAR(got.x, expected[0], 1e-12);
  EXPECT_NEAR(got.y, expected[1], 1e-12);
  EXPECT_NEAR(got.z, expected[2], 1e-12);
  EXPECT_NEAR(got.colour, expected[3], 1e-12);
}

// Parameters: power, radius, roundstr, roundwidth, distortion, edge, scatter, offset, rotation,
// cropmode, static. Expected values from Fractorium's PostSmartcropVariation::Func transcribed into
// a separate Python script (lane generator as variation_point_case.h's; first draws of seed
// 0x2545F491: 0.879466, 0.545326, 0.394069).
TEST(SmartcropState, Cropmode2ReplacesACroppedPointByTheLastOneLetThroughAndItsColour) {
  const std::vector<double> params = {4, 1, 0, 1, 1, 0, 0, 0, 0, 2, 2};  // static 2: p itself
  double state[4] = {0, 0, 0, 0};
  const std::array<double, 3> far = {9, 9, 9};
  expectCrop(smartcropOnce(params, 0.8, {0.3, -0.2, 0.5}, far, 0.25, 0x2545F491u, state), {0.24, -0.16, 0.4, 0.25});
  expectCrop(smartcropOnce(params, 0.8, {1.7, 0.4, -0.3}, far, 0.6, 0x2545F491u, state), {0.24, -0.16, 0.4, 0.25});
  expectCrop(smartcropOnce(params, 0.8, {-0.1, 0.6, 0.2}, far, 0.9, 0x2545F491u, state), {-0.08, 0.48, 0.16, 0.9});
  expectCrop(smartcropOnce(params, 0.8, {0.2, -3.0, 0.1}, far, 0.1, 0x2545F491u, state), {-0.08, 0.48, 0.16, 0.9});
  // Without memory (a single evaluation) a cropped point goes to Fractorium's initial zeros.
  expectCrop(smartcropOnce(params, 0.8, {1.7, 0.4, -0.3}, far, 0.6, 0x2545F491u, nullptr), {0, 0, 0, 0});
}

TEST(SmartcropState, StaticModesReadAndReturnWhatFractoriumDoes) {
  const std::array<double, 3> p = {0.3, -0.2, 0.5};
  {  // static 0, cropmode 1 (scatter 0.2, offset 0.05, rotation 0.25): t is cropped, p + w q returned.
    const std::vector<double> params = {4, 1, 0, 1, 1, 0, 0.2, 0.05, 0.25, 1, 0};
    double state[4] = {0, 0, 0, 0};
    expectCrop(smartcropOnce(params, 0.8, p, {0.1, 0.4, -0.6}, 0.5, 0x2545F491u, state), {0.38, 0.12, 0.02, 0.5});
    expectCrop(smartcropOnce(params, 0.8, p, {1.4, -0.9, 0.7}, 0.5, 0x2545F491u, state),
               {1.447328538649376, -0.4071652988006892, 1.06, 0.5});
  }
  {  // static 3, cropmode 2: a kept point returns and keeps w t; a cropped one the kept w t.
    const std::vector<double> params = {4, 1, 0, 1, 1, 0, 0, 0, 0, 2, 3};
    double state[4] = {0, 0, 0, 0};
    expectCrop(smartcropOnce(params, 0.8, p, {0.1, 0.4, -0.6}, 0.3, 0x2545F491u, state), {0.08, 0.32, -0.48, 0.3});
    expectCrop(smartcropOnce(params, 0.8, {2.5, 0.1, 0.5}, {0.2, 0.1, 0.3}, 0.7, 0x2545F491u, state),
               {0.08, 0.32, -0.48, 0.3});
  }
  {  // static −1, cropmode −1: kept p + w t; cropped w |t| along t's angle, w t_z, alone.
    const std::vector<double> params = {4, 1, 0, 1, 1, 0, 0, 0, 0, -1, -1};
    double state[4] = {0, 0, 0, 0};
    expectCrop(smartcropOnce(params, 0.8, p, {0.1, 0.4, -0.6}, 0.5, 0x2545F491u, state), {0.38, 0.12, 0.02, 0.5});
    expectCrop(smartcropOnce(params, 0.8, p, {1.4, -0.9, 0.7}, 0.5, 0x2545F491u, state), {1.12, -0.72, 0.56, 0.5});
  }
  {  // static 1, cropmode 2, a sector of 1.5π: kept w t alone; cropped p + the kept w t, its colour.
    const std::vector<double> params = {1.5, 1, 0, 1, 1, 0, 0, 0, 0, 2, 1};
    double state[4] = {0, 0, 0, 0};
    expectCrop(smartcropOnce(params, 0.8, p, {0.5, 0.5, 0.25}, 0.4, 0x2545F491u, state), {0.4, 0.4, 0.2, 0.4});
    expectCrop(smartcropOnce(params, 0.8, p, {0.3, -0.7, 0.1}, 0.8, 0x2545F491u, state), {0.7, 0.2, 0.7, 0.4});
  }
}

TEST(SmartcropState, EachLaneKeepsItsOwnMemory) {
  const std::vector<double> params = {4, 1, 0, 1, 1, 0, 0, 0, 0, 2, 2};
  std::vector<double> state(4 * 3, 0.0);
  const std::uint32_t lane0 = 0, lane2 = 2;
  smartcropOnce(params, 1.0, {0.5, 0.25, 0.0}, {0, 0, 0}, 0.2, 1u, state.data(), &lane0);
  smartcropOnce(params, 1.0, {-0.5, 0.125, 0.0}, {0, 0, 0}, 0.7, 1u, state.data(), &lane2);
  expectCrop(smartcropOnce(params, 1.0, {5, 5, 5}, {0, 0, 0}, 0.0, 1u, state.data(), &lane0), {0.5, 0.25, 0.0, 0.2});
  expectCrop(smartcropOnce(params, 1.0, {5, 5, 5}, {0, 0, 0}, 0.0, 1u, state.data(), &lane2), {-0.5, 0.125, 0.0, 0.7});
  EXPECT_EQ(state[4], 0.0);  // lane 1 untouched
}

// The catalogue's own check rows. svg_wf with its default drawing (a square outline 80 wide at
// (10, 10), stroke 2, drawn at twice its size, antialiased): a separate Python script lists the pixels
// whose centres lie within 2 + 7/16 of the outline (svg_raster.cpp's model of an antialiased
// stroke), takes JWildfire's extent and centring, the pixel ⌊Ψ₁ · 2560⌋ and the blur by Ψ₂, Ψ₃.
// smartcrop's rows from the Python transcription of Fractorium's Func named above.
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // svg_wf: pixel (37, 180) for seed 0x2545F491, (19, 18) for 0x0BADF00D.
      {"svg_wf", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.3838750849559821, 0.49421008055938487, 0.4}},
      {"svg_wf", {}, {0.3, -0.7, 0.5}, 0.8, 0x0BADF00Du, {-0.4933066829386309, -0.5010376247715891, 0.4}},
      // smartcrop, static 2, cropmode 2, a point outside the unit square: Fractorium's initial zeros.
      {"smartcrop", {4, 1, 0, 1, 1, 0, 0, 0, 0, 2, 2}, {1.7, 0.4, -0.3}, 0.8, 0x2545F491u, {0.0, 0.0, 0.0}},
      // smartcrop, static 0, cropmode 1, kept (t = p in this harness): p + w p.
      {"smartcrop", {4, 1, 0, 1, 1, 0, 0, 0, 0, 1, 0}, {0.3, -0.2, 0.5}, 0.8, 0x2545F491u, {0.54, -0.36, 0.9}},
  };
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class FlameVariationSvg : public testing::TestWithParam<PointCase> {};
TEST_P(FlameVariationSvg, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Cases, FlameVariationSvg, testing::ValuesIn(pointCases()), caseLabel);

}  // namespace
}  // namespace voxflame::test
