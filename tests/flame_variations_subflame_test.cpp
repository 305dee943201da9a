// The subflame variations of core/flame/variations_subflame.cpp (subflame_wf, glynns3subfl): hand-checked points
// where the result does not depend on the embedded flame's cloud (worked out from JWildfire's SubFlameWFFunc and
// GlynnS3SubflWFFunc by a separate Python script in double precision, independently of the code under test; the
// point is (0.3, −0.7, 0.5) with weight 0.8 unless said, random draws replayed from the lane's seed: xorshift32 gives
// Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594 first from 0x9E3779B9), then the points of an embedded
// Sierpinski gasket, the import of flames that embed one, and embedded flames that are broken.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/flame/subflame.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

// glynns3subfl's parameters: probability, show, radius, thickness, contrast, pow, type, phi1, phi2, then the
// subflame's (scale, angle, offset_x, offset_y, offset_z, colorscale_z, color_mode, and five of JWildfire's flame
// sequence).
std::vector<double> glynnParams(std::array<double, 9> own, std::array<double, 7> sub = {1, 0, 0, 0, 0, 0, 0}) {
  std::vector<double> params(own.begin(), own.end());
  params.insert(params.end(), sub.begin(), sub.end());
  params.insert(params.end(), {0.0, 1.0, 0.0, 1.0, 4.0});
  return params;
}

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // subflame_wf with scale 0: q = (offset_x, offset_y, offset_z + colorscale_z c) = (0.3, −0.2, 0.7) whatever
      // point of the embedded flame is drawn, added without the weight as JWildfire does.
      {"subflame_wf",
       {0.0, 30.0, 0.3, -0.2, 0.7, 0.0, -1.0, 0.0, 1.0, 0.0, 1.0, 4.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3, -0.2, 0.7}},
      // glynns3subfl, defaults: r = 0.7616 < r₁ = 1.42, so a point of the circle of radius r₁ or r₂ at angle 2πΨ₁
      // (Ψ₂ picks r₁ by chance r₁/(r₁ + r₂)), and Ψ₃ < 0.5 keeps it: x and y assigned (the row's start
      // subtracted), z carried.
      {"glynns3subfl", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.7004965641840055, -0.5304174668217018, 0.4}},
      {"glynns3subfl", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.3539108646831455, 0.7647787464797641, 0.4}},
      // Type 1 inside radius 0.9: radius + thickness − γ'Ψ₁ at angle 30° + 170° Ψ₂.
      {"glynns3subfl",
       glynnParams({1.0, 1.0, 0.9, 0.3, 1.0, 1.5, 1.0, 30.0, 200.0}),
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.44412525977853856, 0.7469868238467496, 0.4}},
      // Outside (1.5, −1.2): α = 0.52, contrast α^1.2 = 0.32; Ψ₁ = 0.879 keeps (x, y), Ψ₁ = 0.317 inverts it (α²).
      {"glynns3subfl",
       glynnParams({1.0, 1.0, 1.0, 0.42, 0.7, 1.2, 0.0, 0.0, 360.0}),
       {1.5, -1.2, 0.5},
       0.8,
       kHighSeed,
       {1.0750000000000002, -0.71, 0.4}},
      {"glynns3subfl",
       glynnParams({1.0, 1.0, 1.0, 0.42, 0.7, 1.2, 0.0, 0.0, 360.0}),
       {1.5, -1.2, 0.5},
       0.8,
       kLowSeed,
       {0.20020325203252037, -0.010162601626016288, 0.4}},
      // show 0: the point itself inside.
      {"glynns3subfl",
       glynnParams({1.0, 0.0, 1.0, 0.42, 1.0, 1.5, 0.0, 0.0, 360.0}),
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.11499999999999999, -0.30999999999999994, 0.4}},
      // probability 0: always the subflame, here with scale 0, so w (offset_x, offset_y, offset_z) is added.
      {"glynns3subfl",
       glynnParams({0.0, 1.0, 1.0, 0.42, 1.0, 1.5, 0.0, 0.0, 360.0}, {0.0, 0.0, 0.3, -0.2, 0.7, 0.0, 0.0}),
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.16000000000000003, 0.5599999999999999}},
  };
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class SubflameVariationAtPoint : public testing::TestWithParam<PointCase> {};
TEST_P(SubflameVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Subflame, SubflameVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

// A Sierpinski gasket with corners (−2, −1), (2, −1), (0, 3): each transform halves towards one corner, whose
// colour it has (0, ½, 1).
const std::string kGasket =
    R"(<flame name="gasket" size="100 100"><xform weight="1" color="0" linear="1" coefs="0.5 0 0 0.5 -1 -0.5"/>)"
    R"(<xform weight="1" color="0.5" linear="1" coefs="0.5 0 0 0.5 1 -0.5"/>)"
    R"(<xform weight="1" color="1" linear="1" coefs="0.5 0 0 0.5 0 1.5"/></flame>)";
constexpr std::array<std::array<double, 2>, 3> kCorners = {{{-2.0, -1.0}, {2.0, -1.0}, {0.0, 3.0}}};

struct Drawn {
  std::vector<double> x, y, z, colour;
};

// `lanes` calls of one term, each lane with a seed of its own, at the origin; the outputs start at 0.
Drawn draw(const std::string& name, const std::vector<double>& params, const std::string& text, std::size_t lanes,
           double weight = 1.0) {
  const VariationInfo& info = variationOrThrow(name);
  std::vector<double> zeros(lanes, 0.0);
  Drawn out{zeros, zeros, zeros, std::vector<double>(lanes, 0.25)};
  std::vector<std::uint32_t> random(lanes);
  for (std::size_t i = 0; i < lanes; ++i) random[i] = static_cast<std::uint32_t>(0x9E3779B9u * (i + 1)) | 1u;
  VariationInput in;
  in.x = in.tx = zeros.data();
  in.y = in.ty = zeros.data();
  in.z = in.tz = zeros.data();
  in.random = random.data();
  in.count = lanes;
  in.weight = weight;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = out.colour.data();
  const std::string texts[1] = {std::string(text)};
  in.texts = texts;
  info.apply(in, out.x.data(), out.y.data(), out.z.data());
  return out;
}

std::vector<double> subflameParams(double scale, double angle, double ox, double oy, double oz, double colourZ,
                                   double colourMode) {
  return {scale, angle, ox, oy, oz, colourZ, colourMode, 0.0, 1.0, 0.0, 1.0, 4.0};
}

// Whether (x, y) is inside the triangle of the three corners (with a little slack for rounding).
bool insideTriangle(double x, double y) {
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& a = kCorners[k];
    const auto& b = kCorners[(k + 1) % 3];
    const auto& c = kCorners[(k + 2) % 3];
    const auto side = [&](double px, double py) { return (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]); };
    if (side(x, y) * side(c[0], c[1]) < -1e-9) return false;
  }
  return true;
}

TEST(FlameVariationSubflame, PointsLieOnTheEmbeddedGasket) {
  const Drawn d = draw("subflame_wf", subflameParams(1, 0, 0, 0, 0, 0, 0), kGasket, 20000);
  std::array<int, 3> nearCorner{};
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    ASSERT_TRUE(insideTriangle(d.x[i], d.y[i])) << d.x[i] << ", " << d.y[i];
    EXPECT_EQ(d.z[i], 0.0);
    // The gasket's biggest hole, the triangle of the sides' midpoints (−1, 1), (1, 1), (0, −1), holds no point:
    // a disc well inside it stays empty.
    EXPECT_GT(std::hypot(d.x[i], d.y[i] - 1.0 / 3.0), 0.5) << d.x[i] << ", " << d.y[i];
    for (std::size_t k = 0; k < 3; ++k)
      if (std::hypot(d.x[i] - kCorners[k][0], d.y[i] - kCorners[k][1]) < 0.25) {
        ++nearCorner[k];
        // Points near a corner came through its transform several times: their colour is near the corner's.
        EXPECT_NEAR(d.colour[i], 0.5 * static_cast<double>(k), 0.1);
      }
  }
  // Each corner region holds its share (the area within 0.25 of a corner is about 1/64 of the gasket's measure).
  for (std::size_t k = 0; k < 3; ++k) EXPECT_GT(nearCorner[k], 100) << "corner " << k;
}

TEST(FlameVariationSubflame, ScaleAngleAndOffsetsShapeTheDrawnPoint) {
  const Drawn plain = draw("subflame_wf", subflameParams(1, 0, 0, 0, 0, 0, -1), kGasket, 500);
  const Drawn shaped = draw("subflame_wf", subflameParams(2, 90, 0.5, -1, 3, 2, -1), kGasket, 500, 0.3);
  for (std::size_t i = 0; i < plain.x.size(); ++i) {
    // The same draw: 2 (x, y) turned by 90° and offset, z = 2 · 0 + 3 + 2 c; the weight is not applied.
    EXPECT_NEAR(shaped.x[i], -2.0 * plain.y[i] + 0.5, 1e-12);
    EXPECT_NEAR(shaped.y[i], 2.0 * plain.x[i] - 1.0, 1e-12);
    EXPECT_GE(shaped.z[i], 3.0);
    EXPECT_LE(shaped.z[i], 5.0);
    EXPECT_EQ(plain.colour[i], 0.25);  // colour mode −1 leaves the colour alone
  }
}

TEST(FlameVariationSubflame, EmptyTextDrawsTheDefaultGasket) {
  const Drawn d = draw("subflame_wf", subflameParams(1, 0, 0, 0, 0, 0, -1), "", 2000);
  double minY = 1e9, maxY = -1e9;
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    EXPECT_LE(std::abs(d.x[i]), 1.0 + 1e-12);
    minY = std::min(minY, d.y[i]);
    maxY = std::max(maxY, d.y[i]);
  }
  EXPECT_LT(minY, -0.8);
  EXPECT_GT(maxY, 0.8);
}

// The hex digits of the text's bytes, as JWildfire writes a resource.
std::string hex(const std::string& text) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : text) {
    out.push_back(kDigits[static_cast<unsigned char>(c) >> 4]);
    out.push_back(kDigits[static_cast<unsigned char>(c) & 15]);
  }
  return out;
}

// A JWildfire flame whose first transform holds a subflame term with the given extra attributes.
std::string outerFlame(const std::string& subflameAttributes) {
  return R"(<flame name="outer" size="64 64"><xform weight="1" color="0" subflame_wf="1.0" )"
         R"(subflame_wf_fx_priority="0" subflame_wf_scale="0.5" subflame_wf_angle="0.0" subflame_wf_offset_x="0.25" )"
         R"(subflame_wf_offset_y="0.0" subflame_wf_offset_z="0.0" subflame_wf_colorscale_z="0.0" )"
         R"(subflame_wf_color_mode="0" subflame_wf_flame_is_sequence="0" subflame_wf_flame_sequence_start="1" )"
         R"(subflame_wf_flame_sequence_end="0" subflame_wf_flame_sequence_repeat="1" )"
         R"(subflame_wf_flame_sequence_digits="4" subflame_wf_flame_filename="" )" +
         subflameAttributes + R"( coefs="1 0 0 1 0 0"/>)" +
         R"(<xform weight="1" color="1" linear3D="1" coefs="0.7 0.5 -0.5 0.7 1 0"/></flame>)";
}

const VariationTerm& subflameTerm(const FlameGenome& genome) {
  const std::vector<VariationTerm>& terms = genome.xforms.at(0).variations;
  const auto at =
      std::find_if(terms.begin(), terms.end(), [](const VariationTerm& t) { return t.name == "subflame_wf"; });
  if (at == terms.end()) throw Error("no subflame_wf term");
  return *at;
}

TEST(FlameVariationSubflame, ImportsTheEmbeddedFlameAndKeepsItInTheScene) {
  const FlameFileContents contents =
      readFlameXml(outerFlame("subflame_wf_flame=\"" + hex(kGasket) + "\""), "outer.flame");
  const ImportedFlame& flame = contents.flame;
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const VariationTerm& term = subflameTerm(flame.genome);
  EXPECT_EQ(term.texts.at(0), kGasket);
  const VariationInfo& info = variationOrThrow("subflame_wf");
  EXPECT_EQ(term.params.at(static_cast<std::size_t>(info.paramIndex("scale"))), 0.5);
  EXPECT_EQ(term.params.at(static_cast<std::size_t>(info.paramIndex("offset_x"))), 0.25);
  EXPECT_EQ(term.params.at(static_cast<std::size_t>(info.paramIndex("color_mode"))), 0.0);
  EXPECT_FALSE(isFlatFlame(flame.genome));  // a 3D variation: no depth is added

  // The scene keeps the embedded flame as text under the variation's `flame` key, and reads it back.
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  const std::string json = sceneToJson(scene);
  EXPECT_NE(json.find("\"flame\": \"<flame name=\\\"gasket\\\""), std::string::npos);
  const Scene back = sceneFromJson(json, "scene.json");
  EXPECT_EQ(back.layers.at(0).flame.xforms.at(0).variations, scene.layers.at(0).flame.xforms.at(0).variations);
  EXPECT_EQ(subflameTerm(back.layers.at(0).flame).texts.at(0), kGasket);
}

TEST(FlameVariationSubflame, ImportsGlynns3subflsParameterNames) {
  const std::string text = R"(<flame name="g" size="64 64"><xform weight="1" color="0" glynns3subfl="0.9" )"
                           R"(glynns3subfl_weight="0.25" glynns3subfl_show/hide(1/0)="0" glynns3subfl_radius="1.5" )"
                           R"(glynns3subfl_color_mode="0" glynns3subfl_flame=")" +
                           hex(kGasket) + R"(" glynns3subfl_flame_filename="" coefs="1 0 0 1 0 0"/></flame>)";
  const ImportedFlame flame = readFlameXml(text, "g.flame").flame;
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  ASSERT_EQ(term.name, "glynns3subfl");
  EXPECT_EQ(term.params.at(0), 0.25);  // probability
  EXPECT_EQ(term.params.at(1), 0.0);   // show
  EXPECT_EQ(term.params.at(2), 1.5);   // radius
  EXPECT_EQ(term.texts.at(0), kGasket);
}

// The import's warnings and losses for a subflame term with these attributes.
ImportedFlame importOuter(const std::string& attributes) {
  return readFlameXml(outerFlame(attributes), "outer.flame").flame;
}
bool lost(const ImportedFlame& flame, const std::string& what) {
  return std::find(flame.leftOut.begin(), flame.leftOut.end(), what) != flame.leftOut.end();
}
bool warned(const ImportedFlame& flame, const std::string& part) {
  return std::any_of(flame.warnings.begin(), flame.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

// Every drawn point of the term is finite, or the term adds nothing.
void expectFiniteOrNothing(const std::string& text) {
  const Drawn d = draw("subflame_wf", subflameParams(1, 0, 0, 0, 0, 0, 0), text, 64);
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    EXPECT_TRUE(std::isfinite(d.x[i]) && std::isfinite(d.y[i]) && std::isfinite(d.z[i]));
    EXPECT_TRUE(std::isfinite(d.colour[i]));
  }
}

TEST(FlameVariationSubflame, BrokenEmbeddedFlamesAreReportedAndAddNothing) {
  // Not XML at all (and not hex either: the text is taken as it is).
  const ImportedFlame garbage = importOuter(R"(subflame_wf_flame="not a flame")");
  EXPECT_TRUE(lost(garbage, "embedded flame of subflame_wf"));
  EXPECT_TRUE(warned(garbage, "embedded flame cannot be read"));
  const Drawn d = draw("subflame_wf", subflameParams(1, 0, 0.5, 0, 0, 0, 0), "not a flame", 16);
  for (std::size_t i = 0; i < d.x.size(); ++i) EXPECT_EQ(d.x[i], 0.0);

  // A flame without transforms.
  const ImportedFlame empty = importOuter("subflame_wf_flame=\"" + hex("<flame name=\"e\"></flame>") + "\"");
  EXPECT_TRUE(lost(empty, "embedded flame of subflame_wf"));

  // A flame every orbit of which escapes.
  const std::string escaping = R"(<flame name="far"><xform weight="1" color="0" linear="1" )"
                               R"(coefs="100000 0 0 100000 1 0"/></flame>)";
  const ImportedFlame far = importOuter("subflame_wf_flame=\"" + hex(escaping) + "\"");
  EXPECT_TRUE(lost(far, "embedded flame of subflame_wf"));
  EXPECT_TRUE(warned(far, "no finite point"));
  expectFiniteOrNothing(escaping);

  // No embedded flame: the default gasket stands in, which the import says.
  const ImportedFlame missing = importOuter("");
  EXPECT_TRUE(lost(missing, "embedded flame of subflame_wf"));
  const VariationTerm missingTerm = subflameTerm(missing.genome);
  EXPECT_TRUE(missingTerm.texts.empty() || missingTerm.texts.at(0).empty());

  // A flame file: not read, the embedded flame drawn.
  std::string withFile = outerFlame("subflame_wf_flame=\"" + hex(kGasket) + "\"");
  const std::string noFile = "subflame_wf_flame_filename=\"\"";
  withFile.replace(withFile.find(noFile), noFile.size(), "subflame_wf_flame_filename=\"x.flame\"");
  const ImportedFlame file = readFlameXml(withFile, "outer.flame").flame;
  EXPECT_TRUE(lost(file, "flame file of subflame_wf"));
}

TEST(FlameVariationSubflame, ANestedSubflameIsLeftOutOfTheEmbeddedFlame) {
  // The embedded gasket's first transform embeds another gasket.
  std::string inner = kGasket;
  inner.replace(inner.find("linear=\"1\""), 10,
                "linear=\"1\" subflame_wf=\"0.2\" subflame_wf_flame=\"" + hex(kGasket) + "\"");
  const ImportedFlame flame = importOuter("subflame_wf_flame=\"" + hex(inner) + "\"");
  EXPECT_TRUE(lost(flame, "subflame inside the flame subflame_wf embeds"));
  EXPECT_TRUE(warned(flame, "embeds a flame itself"));
  // Without the nested term the embedded flame is the gasket again.
  const Drawn d = draw("subflame_wf", subflameParams(1, 0, 0, 0, 0, 0, -1), inner, 2000);
  for (std::size_t i = 0; i < d.x.size(); ++i) EXPECT_TRUE(insideTriangle(d.x[i], d.y[i]));
}

// Embedded flames cut short and with bytes changed at random: each import finishes (with or without a warning), and
// each term draws finite points or nothing.
TEST(FlameVariationSubflame, MalformedEmbeddedXmlNeverCrashes) {
  std::uint32_t state = 0x1234567u;
  const auto next = [&] {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  };
  static constexpr char kNasty[] = "<>\"'&/= \0x9e-.";
  for (int round = 0; round < 24; ++round) {
    std::string text = kGasket;
    if (round % 3 == 0) {
      text.resize(next() % text.size());
    } else {
      for (int k = 0; k < 1 + round % 5; ++k) text[next() % text.size()] = kNasty[next() % (sizeof(kNasty) - 1)];
    }
    SCOPED_TRACE(text);
    ImportedFlame flame;
    EXPECT_NO_THROW(flame = importOuter("subflame_wf_flame=\"" + hex(text) + "\""));
    expectFiniteOrNothing(text);
  }
  // The resource's own hex cut short by one digit (not hex any more): read as text, not a flame.
  const std::string cut = hex(kGasket).substr(1);
  const ImportedFlame flame = importOuter("subflame_wf_flame=\"" + cut + "\"");
  EXPECT_TRUE(lost(flame, "embedded flame of subflame_wf"));
  EXPECT_FALSE(decodeJwildfireResource(cut).has_value());
  EXPECT_EQ(decodeJwildfireResource("3C2f3e"), "</>");
}

}  // namespace
