// JWildfire's weighting fields beyond the variation weights: the noise families (FastNoise's
// character), and the colour, jitter and variation parameters a field drives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/chaos_game.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"
#include "core/scene_io.h"

using namespace voxflame::core;

namespace {

FlameXform fieldOf(WeightFieldNoise noise, WeightFieldKind kind = WeightFieldKind::Noise) {
  FlameXform x;
  x.fieldKind = kind;
  x.fieldNoise = noise;
  x.fieldSeed = 11;
  return x;
}

}  // namespace

// Each family as FastNoise makes it, told apart by what only it does.
TEST(WeightFieldNoise, FamiliesHaveTheirCharacter) {
  // Perlin: on the x axis only the two lattice gradients' x components (−1, 0 or 1) matter, so
  // halfway between lattice points the noise is ¼ (a − b): 0, ±¼ or ±½ (simplex noise is not).
  const FlameXform perlin = fieldOf(WeightFieldNoise::Perlin);
  std::set<double> halves;
  for (int i = -20; i < 20; ++i) {
    const double n = weightFieldNoise(perlin, i + 0.5, 0.0, 0.0);
    const double quarters = n * 4.0;
    EXPECT_NEAR(quarters, std::round(quarters), 1e-12) << i;
    halves.insert(std::round(quarters));
    EXPECT_NEAR(weightFieldNoise(perlin, i, 3.0, -2.0), 0.0, 1e-12);  // 0 at every lattice point
  }
  EXPECT_GE(halves.size(), 3u);
  // Value noise: the lattice points' own values, spread over [−1, 1], and smooth between them.
  const FlameXform value = fieldOf(WeightFieldNoise::Value);
  double low = 1.0, high = -1.0;
  for (int i = 0; i < 200; ++i) {
    const double n = weightFieldNoise(value, i, 2 * i, -i);
    low = std::min(low, n);
    high = std::max(high, n);
    EXPECT_NEAR(weightFieldNoise(value, i + 1e-7, 2 * i, -i), n, 1e-5);
  }
  EXPECT_LT(low, -0.8);
  EXPECT_GT(high, 0.8);
  // Cubic noise: the lattice value over 1.5³ at a lattice point.
  const FlameXform cubic = fieldOf(WeightFieldNoise::Cubic);
  double largest = 0.0;
  for (int i = 0; i < 200; ++i) largest = std::max(largest, std::abs(weightFieldNoise(cubic, i, -i, 3)));
  EXPECT_LE(largest, 1.0 / 3.375 + 1e-12);
  EXPECT_GT(largest, 0.2);
  // White noise: unrelated values a hair apart.
  const FlameXform white = fieldOf(WeightFieldNoise::White);
  int differ = 0;
  for (int i = 0; i < 100; ++i)
    differ +=
        std::abs(weightFieldNoise(white, 0.1 * i, 0.3, 0.2) - weightFieldNoise(white, 0.1 * i + 1e-4, 0.3, 0.2)) > 0.05;
  EXPECT_GT(differ, 80);
}

TEST(WeightFieldNoise, CellularIsWorleyNoise) {
  FlameXform cells = fieldOf(WeightFieldNoise::Cellular);
  cells.fieldCellReturn = CellReturn::Distance;
  // Squared distance to the nearest feature point, less 1: −1 at a feature point, never below, and
  // a feature point lies within 0.45 of each lattice point, so the field dips to about −1 there.
  double lowest = 0.0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) {
      const double n = weightFieldNoise(cells, i * 0.05, j * 0.05, 0.0);
      EXPECT_GE(n, -1.0);
      EXPECT_LE(n, 0.75 * 0.75 * 3 - 1.0);
      lowest = std::min(lowest, n);
    }
  EXPECT_LT(lowest, -0.9);
  // The cell's value is constant over the cell: few values, each over a patch.
  cells.fieldCellReturn = CellReturn::CellValue;
  std::set<double> values;
  int same = 0;
  for (int i = 0; i < 100; ++i) {
    const double n = weightFieldNoise(cells, 0.03 * i, 0.5, 0.5);
    values.insert(n);
    same += n == weightFieldNoise(cells, 0.03 * i + 0.01, 0.5, 0.5);
  }
  EXPECT_LE(values.size(), 8u);
  EXPECT_GE(values.size(), 2u);
  EXPECT_GT(same, 80);
  // The second-nearest distance is never below the nearest.
  FlameXform first = cells, second = cells;
  first.fieldCellReturn = CellReturn::Distance;
  second.fieldCellReturn = CellReturn::Distance2;
  for (int i = 0; i < 100; ++i)
    EXPECT_GE(weightFieldNoise(second, 0.07 * i, 0.2, -0.4), weightFieldNoise(first, 0.07 * i, 0.2, -0.4));
}

// FastNoise's rigid sum: 1 − |n₀| less gain · (1 − |n₁|), octave 1 at seed + 1 and lacunarity
// times the frequency, unscaled.
TEST(WeightFieldNoise, RigidSumIsFastNoises) {
  FlameXform rigid = fieldOf(WeightFieldNoise::Value, WeightFieldKind::Fractal);
  rigid.fieldFractal = WeightFieldFractal::Rigid;
  rigid.fieldOctaves = 2;
  rigid.fieldGain = 0.6;
  rigid.fieldLacunarity = 2.2;
  rigid.fieldFrequency = 1.3;
  FlameXform octave0 = fieldOf(WeightFieldNoise::Value), octave1 = octave0;
  octave0.fieldFrequency = 1.3;
  octave1.fieldFrequency = 1.3 * 2.2;
  octave1.fieldSeed = 12;
  for (int i = 0; i < 20; ++i) {
    const double x = 0.37 * i, y = -0.21 * i, z = 0.5;
    EXPECT_NEAR(weightFieldNoise(rigid, x, y, z),
                (1.0 - std::abs(weightFieldNoise(octave0, x, y, z))) -
                    0.6 * (1.0 - std::abs(weightFieldNoise(octave1, x, y, z))),
                1e-12);
  }
}

namespace {

constexpr std::size_t kLanes = 32;

struct Step {
  std::vector<double> px, py, pz;  // where each lane started
  std::vector<double> x, y, z, c;  // what it drew
};

// One step of one transform's layer from lanes seeded alike.
Step stepOnce(const FlameXform& x, std::uint64_t seed = 3) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.flame.xforms = {x};
  const ChaosGame game(layer, "field");
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(seed);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  Step s{lanes.x,
         lanes.y,
         lanes.z,
         std::vector<double>(kLanes),
         std::vector<double>(kLanes),
         std::vector<double>(kLanes),
         std::vector<double>(kLanes)};
  game.step(lanes, s.x.data(), s.y.data(), s.z.data(), s.c.data(), kLanes);
  return s;
}

FlameXform plainTransform() {
  FlameXform x;
  x.affine.m = {0.5, 0.1, 0, 0.2, -0.1, 0.5, 0, 0.1, 0, 0, 0.5, 0.3};
  x.variations = {{"linear", 1.0, {}}, {"spherical", 0.5, {}}};
  x.color = 0.7;
  x.colorSpeed = 0.4;
  return x;
}

}  // namespace

// The colour: after the blend, c · (1 + 0.1 · intensity · n), n read where the amount reads it;
// the position is the plain one (amount 0).
TEST(WeightFieldEffects, ColourScalesByTheNoise) {
  for (const WeightFieldNoise noise : {WeightFieldNoise::Simplex, WeightFieldNoise::Cellular}) {
    FlameXform x = plainTransform();
    const Step plain = stepOnce(x);
    x.fieldKind = WeightFieldKind::Noise;
    x.fieldNoise = noise;
    x.fieldFrequency = 1.7;
    x.fieldColor = 3.0;
    ASSERT_TRUE(x.hasWeightField());
    const Step field = stepOnce(x);
    double largest = 0.0;
    for (std::size_t i = 0; i < kLanes; ++i) {
      const glm::dvec3 t = x.affine.apply({plain.px[i], plain.py[i], plain.pz[i]});
      const double n = weightFieldNoise(x, t.x, t.y, t.z);
      EXPECT_NEAR(field.c[i], plain.c[i] * (1.0 + 0.3 * n), 1e-12) << i;
      EXPECT_EQ(field.x[i], plain.x[i]);
      largest = std::max(largest, std::abs(field.c[i] - plain.c[i]));
    }
    EXPECT_GT(largest, 0.02) << "the noise hardly moved the colour: the test shows nothing";
  }
}

// The jitter: after the post map, x += 0.1 · J · n(x, y, z), then y += … n(y, x, z), then
// z += … n(z, x, y), each read at the point as moved so far.
TEST(WeightFieldEffects, JitterMovesThePointByTheStatedAmount) {
  FlameXform x = plainTransform();
  x.hasPost = true;
  x.post.m = {1, 0, 0, 0.1, 0, 1, 0, 0, 0, 0, 1, 0};
  const Step plain = stepOnce(x);
  x.fieldKind = WeightFieldKind::Fractal;
  x.fieldNoise = WeightFieldNoise::Value;
  x.fieldFrequency = 2.0;
  x.fieldJitter = 2.5;
  const Step field = stepOnce(x);
  double moved = 0.0;
  for (std::size_t i = 0; i < kLanes; ++i) {
    double qx = plain.x[i], qy = plain.y[i], qz = plain.z[i];
    qx += 0.25 * weightFieldNoise(x, qx, qy, qz);
    qy += 0.25 * weightFieldNoise(x, qy, qx, qz);
    qz += 0.25 * weightFieldNoise(x, qz, qx, qy);
    EXPECT_NEAR(field.x[i], qx, 1e-12) << i;
    EXPECT_NEAR(field.y[i], qy, 1e-12) << i;
    EXPECT_NEAR(field.z[i], qz, 1e-12) << i;
    EXPECT_EQ(field.c[i], plain.c[i]);
    moved = std::max(moved, std::abs(field.x[i] - plain.x[i]));
  }
  EXPECT_GT(moved, 0.05) << "the jitter hardly moved a point: the test shows nothing";
}

// JWildfire's semantics: julian's power, an int in JWildfire, becomes FTOI(4 · (1 + I · n)) for
// that point, and `amount` scales its weight by 1 + I · n: the point is the one a plain transform
// with that power and weight makes (to rounding: the weight is folded in elsewhere).
TEST(WeightFieldEffects, ParametersScaleByTheNoisePerPoint) {
  FlameXform x = plainTransform();
  x.variations = {{"linear", 0.3, {}}, {"julian", 0.8, {4.0, 1.0}}};
  ASSERT_EQ(variationOrThrow("julian").params.at(0).name, "power");
  x.fieldKind = WeightFieldKind::Noise;
  x.fieldNoise = WeightFieldNoise::Perlin;
  x.fieldFrequency = 2.3;
  x.fieldParam1Variation = "julian";
  x.fieldParam1Name = "power";
  x.fieldParam1Intensity = 0.6;
  x.fieldParam2Variation = "julian";
  x.fieldParam2Name = "amount";
  x.fieldParam2Intensity = 0.5;
  const Step field = stepOnce(x);
  std::set<double> powers;
  for (std::size_t i = 0; i < kLanes; ++i) {
    const glm::dvec3 t = x.affine.apply({field.px[i], field.py[i], field.pz[i]});
    const double n = weightFieldNoise(x, t.x, t.y, t.z);
    FlameXform fixed = x;
    fixed.fieldKind = WeightFieldKind::None;
    fixed.variations[1].params[0] = std::round(4.0 * (1.0 + x.fieldParam1Intensity * n));
    fixed.variations[1].weight = 0.8 * (1.0 + 0.5 * n);
    powers.insert(fixed.variations[1].params[0]);
    const Step plain = stepOnce(fixed);  // the same lanes, the same random draws
    EXPECT_NEAR(field.x[i], plain.x[i], 1e-12) << i;
    EXPECT_NEAR(field.y[i], plain.y[i], 1e-12) << i;
  }
  EXPECT_GE(powers.size(), 2u) << "the field moved no lane's power: the test shows nothing";
}

namespace {

// A field transform and a plain one beside it, so that the field's group has lanes of no
// particular number (not a multiple of 4: the group's call is rounded up to whole vectors).
struct TwoTransforms {
  PatternLayer layer;
  TwoTransforms(const FlameXform& withField) {
    layer.kind = PatternKind::Flame;
    FlameXform other;
    other.weight = 0.7;
    other.affine.m = {0.4, 0, 0, -0.3, 0, 0.4, 0, 0.2, 0, 0, 0.4, 0};
    layer.flame.xforms = {withField, other};
  }
};

constexpr std::size_t kOddLanes = 37;

// lanes seeded as a layer's chaos game seeds them, and one step of them.
struct SeededStep {
  ChaosLanes before;
  std::vector<double> x, y, z, c;
};
SeededStep seededStep(const ChaosGame& game) {
  SeededStep s;
  s.before.resize(kOddLanes);
  SplitMix64 rng(5);
  for (std::size_t i = 0; i < kOddLanes; ++i) game.seedLane(s.before, i, rng);
  ChaosLanes lanes = s.before;
  for (auto* v : {&s.x, &s.y, &s.z, &s.c}) v->assign(kOddLanes, 0.0);
  game.step(lanes, s.x.data(), s.y.data(), s.z.data(), s.c.data(), kOddLanes);
  return s;
}

}  // namespace

// The per-point parameters exactly: lane for lane, the point is what linear and julian make when
// run by hand on that lane alone, julian with the lane's own scaled parameters and random state,
// each scaled by the lane's factors as the chaos game scales a term under a field (its weight
// times 1 + amount · n, julian's times 1 + I · n for its `amount` too). Once for the power (an
// int in JWildfire: rounded), once for dist (a real number).
TEST(WeightFieldEffects, ParametersScaleLaneByLaneExactly) {
  const VariationInfo& julian = variationOrThrow("julian");
  for (const std::string parameter : {"power", "dist"}) {
    SCOPED_TRACE(parameter);
    FlameXform x = plainTransform();
    x.variations = {{"linear", 0.3, {}}, {"julian", 0.8, {4.0, 1.0}}};
    x.fieldKind = WeightFieldKind::Noise;
    x.fieldNoise = WeightFieldNoise::Perlin;
    x.fieldFrequency = 2.3;
    x.fieldAmount = 0.4;
    x.fieldParam1Variation = "julian";
    x.fieldParam1Name = parameter;
    x.fieldParam1Intensity = 0.6;
    x.fieldParam2Variation = "julian";
    x.fieldParam2Name = "amount";
    x.fieldParam2Intensity = 0.5;
    const TwoTransforms two(x);
    const ChaosGame game(two.layer, "field");
    const SeededStep step = seededStep(game);
    std::size_t group = 0;
    std::set<double> values;
    for (std::size_t i = 0; i < kOddLanes; ++i) {
      // The transform the lane draws, as the chaos game draws it.
      std::uint32_t random = laneNext(step.before.random[i]);
      if (game.pickTable()[random >> (32 - ChaosGame::pickBits())] != 0) continue;
      ++group;
      const glm::dvec3 t = x.affine.apply({step.before.x[i], step.before.y[i], step.before.z[i]});
      const double n = weightFieldNoise(x, t.x, t.y, t.z);
      std::vector<double> params = x.variations[1].params;
      const std::size_t at = parameter == "power" ? 0 : 1;
      params[at] *= 1.0 + 0.6 * n;
      if (parameter == "power") params[at] = std::round(params[at]);
      values.insert(params[at]);
      double jx = 0.0, jy = 0.0, jz = 0.0;
      VariationInput in;
      in.x = in.tx = &t.x;
      in.y = in.ty = &t.y;
      in.z = in.tz = &t.z;
      in.random = &random;
      in.count = 1;
      in.weight = 0.8;
      in.params = params.data();
      in.affine = x.affine.m.data();
      double colour = 0.0;
      in.colour = &colour;
      julian.apply(in, &jx, &jy, &jz);
      const double field = 1.0 + 0.4 * n;
      const double julianFactor = field * (1.0 + n * 0.5);
      EXPECT_EQ(step.x[i], field * (0.3 * t.x) + julianFactor * jx) << i;
      EXPECT_EQ(step.y[i], field * (0.3 * t.y) + julianFactor * jy) << i;
      EXPECT_EQ(step.z[i], field * (0.3 * t.z) + julianFactor * jz) << i;
    }
    EXPECT_NE(group % 4, 0u) << "the field's group is whole vectors: pick another seed";
    EXPECT_GE(values.size(), 3u) << "the field hardly changed the parameter: the test shows nothing";
  }
}

// A parameter the field drives at intensity 0 is no field at all; at 1e-9 julian's power rounds
// to 4 on every lane, and the points are the plain transform's, bit for bit.
TEST(WeightFieldEffects, ParametersTheFieldLeavesAloneChangeNothing) {
  FlameXform plain = plainTransform();
  plain.variations = {{"linear", 0.3, {}}, {"julian", 0.8, {4.0, 1.0}}};
  const ChaosGame plainGame(TwoTransforms(plain).layer, "plain");
  const SeededStep expected = seededStep(plainGame);
  for (const double intensity : {0.0, 1e-9}) {
    SCOPED_TRACE(intensity);
    FlameXform x = plain;
    x.fieldKind = WeightFieldKind::Noise;
    x.fieldNoise = WeightFieldNoise::Perlin;
    x.fieldFrequency = 2.3;
    x.fieldParam1Variation = "julian";
    x.fieldParam1Name = "power";
    x.fieldParam1Intensity = intensity;
    EXPECT_EQ(x.hasWeightField(), intensity != 0.0);
    const ChaosGame game(TwoTransforms(x).layer, "field");
    const SeededStep step = seededStep(game);
    for (std::size_t i = 0; i < kOddLanes; ++i) {
      EXPECT_EQ(step.x[i], expected.x[i]) << i;
      EXPECT_EQ(step.y[i], expected.y[i]) << i;
      EXPECT_EQ(step.z[i], expected.z[i]) << i;
      EXPECT_EQ(step.c[i], expected.c[i]) << i;
    }
  }
}

namespace {

std::string flameFile(const std::string& xforms) {
  std::string palette = "<palette count=\"256\" format=\"RGB\">\n";
  char hex[8];
  for (int i = 0; i < 256; ++i) {
    std::snprintf(hex, sizeof hex, "%02X%02X%02X", i, 255 - i, 128);
    palette += hex;
  }
  return "<flames><flame name=\"t\">\n" + xforms + palette + "\n</palette>\n</flame></flames>\n";
}

}  // namespace

TEST(WeightFieldImport, EveryFamilyAndInputIsRead) {
  FlameImportOptions options;
  options.depth = 0.0;
  const ImportedFlame flame =
      readFlameXml(
          flameFile(
              "<xform weight=\"1\" linear=\"1\" polar2=\"0.4\" coefs=\"0.5 0 0 0.5 0 0\" "
              "wfield_type=\"CELLULAR_NOISE\" "
              "wfield_input=\"POSITION\" wfield_color_intensity=\"3.0\" wfield_var_amount_intensity=\"1.0\" "
              "wfield_noise_seed=\"42\" wfield_noise_frequency=\"3.0\" wfield_cell_noise_return_type=\"DISTANCE_SUB\" "
              "wfield_cell_noise_dist_function=\"MANHATTAN\"/>\n"
              "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" wfield_type=\"VALUE_FRACTAL_NOISE\" "
              "wfield_jitter_intensity=\"1.0\" wfield_fract_noise_fract_type=\"RIGID_MULTI\"/>\n"
              "<xform weight=\"1\" linear=\"1\" julian=\"1\" julian_power=\"3\" coefs=\"0.5 0 0 0.5 0 0.5\" "
              "wfield_type=\"SIMPLEX_FRACTAL_NOISE\" wfield_var_param1_var_name=\"julian\" "
              "wfield_var_param1_param_name=\"power\" wfield_var_param1_intensity=\"1.0\" "
              "wfield_var_param2_var_name=\"julian\" wfield_var_param2_param_name=\"amount\" "
              "wfield_var_param2_intensity=\"0.5\" wfield_var_param3_var_name=\"julian\" "
              "wfield_var_param3_param_name=\"no_such\" wfield_var_param3_intensity=\"0.5\"/>\n"
              "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0.5\" wfield_type=\"10\" "
              "wfield_cell_noise_ret_val=\"0\" wfield_jitter_amount=\"0.2\"/>\n"
              "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 -0.5 0\" wfield_type=\"CUBIC_NOISE\" "
              "wfield_color_intensity=\"1\" weightingFieldColorIntensityCurve_enabled=\"true\" "
              "weightingFieldColorIntensityCurve_point_count=\"2\" weightingFieldColorIntensityCurve_x0=\"1\" "
              "weightingFieldColorIntensityCurve_y0=\"1\" weightingFieldColorIntensityCurve_x1=\"31\" "
              "weightingFieldColorIntensityCurve_y1=\"4\" "
              "weightingFieldColorIntensityCurve_interpolation=\"LINEAR\"/>\n"),
          "t.flame", options)
          .flame;
  ASSERT_EQ(flame.genome.xforms.size(), 5u);
  const FlameXform& cell = flame.genome.xforms[0];
  EXPECT_EQ(cell.fieldKind, WeightFieldKind::Noise);
  EXPECT_EQ(cell.fieldNoise, WeightFieldNoise::Cellular);
  EXPECT_EQ(cell.fieldCellReturn, CellReturn::Distance2Sub);
  EXPECT_EQ(cell.fieldCellDistance, CellDistance::Manhattan);
  EXPECT_EQ(cell.fieldInput, WeightFieldInput::Position);
  EXPECT_DOUBLE_EQ(cell.fieldColor, 3.0);
  const FlameXform& value = flame.genome.xforms[1];
  EXPECT_EQ(value.fieldKind, WeightFieldKind::Fractal);
  EXPECT_EQ(value.fieldNoise, WeightFieldNoise::Value);
  EXPECT_EQ(value.fieldFractal, WeightFieldFractal::Rigid);
  EXPECT_DOUBLE_EQ(value.fieldJitter, 1.0);
  EXPECT_TRUE(value.hasWeightField());  // jitter alone makes the field active, as in JWildfire
  const FlameXform& params = flame.genome.xforms[2];
  EXPECT_EQ(params.fieldParam1Variation, "julian");
  EXPECT_EQ(params.fieldParam1Name, "power");
  EXPECT_DOUBLE_EQ(params.fieldParam1Intensity, 1.0);
  EXPECT_EQ(params.fieldParam2Name, "amount");
  EXPECT_DOUBLE_EQ(params.fieldParam2Intensity, 0.5);
  EXPECT_DOUBLE_EQ(params.fieldParam3Intensity, 0.0);  // a parameter julian does not have: named below
  EXPECT_EQ(flame.genome.xforms[3].fieldNoise, WeightFieldNoise::White);
  EXPECT_DOUBLE_EQ(flame.genome.xforms[3].fieldJitter, 0.2);
  EXPECT_EQ(flame.genome.xforms[4].fieldNoise, WeightFieldNoise::Cubic);
  EXPECT_EQ(flame.leftOut,
            (std::vector<std::string>{"JWildfire weighting field parameter no_such of julian (which voxflame's "
                                      "julian does not have)"}));
  // The colour-intensity curve is a keyframe track of the field's colour.
  bool keyed = false;
  for (const KeyframeTrack& track : flame.keyframes)
    keyed = keyed || track.path == "/layers/0/flame/xforms/4/field/color";
  EXPECT_TRUE(keyed);
  // The preset keeps all of it and loads it back.
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  const std::string saved = sceneToJson(scene);
  const Scene back = sceneFromJson(saved, "field.json");
  EXPECT_EQ(back.layers[0].flame.xforms, scene.layers[0].flame.xforms);
  const nlohmann::json document = nlohmann::json::parse(saved);
  EXPECT_EQ(document["layers"][0]["flame"]["xforms"][0]["field"]["noise"], "cellular");
  EXPECT_EQ(document["layers"][0]["flame"]["xforms"][0]["field"]["cell_return"], "distance2_sub");
  EXPECT_EQ(document["layers"][0]["flame"]["xforms"][2]["field"]["param1_variation"], "julian");
}
