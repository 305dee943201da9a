// One variation at one point, against a value worked out by hand: the table row the catalogue's
// test files (flame_variations_test.cpp, flame_variations_more_test.cpp and one per family of
// variations) are made of, and the check they run on each row.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/variations.h"

namespace voxflame::test {

// Lane states for the tables' random variations, named by where their first draw lands.
constexpr std::uint32_t kHighSeed = 0x2545F491u;  // first Ψ = 0.879466
constexpr std::uint32_t kLowSeed = 0x9E3779B9u;   // first Ψ = 0.316594, then 0.875707

// Row-major 3×4: a = 0.9, b = 0.2, c = 0.3 / d = −0.1, e = 0.8, f = −0.4.
inline constexpr double kAffine[12] = {0.9, 0.2, 0.0, 0.3, -0.1, 0.8, 0.0, -0.4, 0.0, 0.0, 1.0, 0.0};

struct PointCase {
  std::string name;
  std::vector<double> params;  // empty: the catalogue's defaults
  glm::dvec3 point;
  double weight;
  std::uint32_t seed;
  glm::dvec3 expected;  // weight · V(point)
};

// Every test file's table of rows registers itself (`const PointCaseTable registered(&pointCases);`), so
// that one test can check that every entry of the catalogue has a hand-checked row somewhere.
using PointCaseTable = const std::vector<PointCase>& (*)();
inline std::vector<PointCaseTable>& registeredPointCaseTables() {
  static std::vector<PointCaseTable> tables;
  return tables;
}
struct PointCaseTableRegistration {
  explicit PointCaseTableRegistration(PointCaseTable table) { registeredPointCaseTables().push_back(table); }
};

[[maybe_unused]] inline void PrintTo(const PointCase& c, std::ostream* os) {
  *os << c.name;
}

inline std::string caseLabel(const testing::TestParamInfo<PointCase>& info) {
  return info.param.name + "_" + std::to_string(info.index);
}

// Runs `info` over `lanes` copies of one point, each lane seeded alike, adding to a non-zero start
// so that a variation that assigns instead of adding is caught; returns the outputs.
struct Outputs {
  std::vector<double> x, y, z;
  std::vector<std::uint32_t> random;
  std::vector<double> colour;  // each lane's colour index, kStartColour before (direct-colour variations set it)
};
inline constexpr double kStartX = 0.125, kStartY = -0.25, kStartZ = 0.5, kStartColour = 0.375;

inline Outputs run(const core::VariationInfo& info, const std::vector<double>& params, glm::dvec3 p, double weight,
                   std::uint32_t seed, std::size_t lanes) {
  std::vector<double> xs(lanes, p.x), ys(lanes, p.y), zs(lanes, p.z);
  Outputs out{std::vector<double>(lanes, kStartX), std::vector<double>(lanes, kStartY),
              std::vector<double>(lanes, kStartZ), std::vector<std::uint32_t>(lanes, seed),
              std::vector<double>(lanes, kStartColour)};
  core::VariationInput in;
  in.x = xs.data();
  in.y = ys.data();
  in.z = zs.data();
  in.random = out.random.data();
  in.count = lanes;
  in.weight = weight;
  in.params = params.data();
  in.affine = kAffine;
  in.tx = xs.data();
  in.ty = ys.data();
  in.tz = zs.data();
  in.colour = out.colour.data();
  info.apply(in, out.x.data(), out.y.data(), out.z.data());
  return out;
}

// The row's variation over 37 lanes (a vectorised body and a scalar remainder must agree lane for
// lane) matches its hand-computed value in every lane.
inline void expectMatchesTheHandComputedValue(const PointCase& c) {
  const core::VariationInfo& info = core::variationOrThrow(c.name);
  const std::vector<double> params = c.params.empty() ? info.defaultParams() : c.params;
  ASSERT_EQ(params.size(), info.params.size());
  const Outputs out = run(info, params, c.point, c.weight, c.seed, 37);
  const auto near = [](double expected) { return 1e-12 * std::max(1.0, std::abs(expected)); };
  for (std::size_t lane = 0; lane < out.x.size(); ++lane) {
    SCOPED_TRACE("lane " + std::to_string(lane));
    EXPECT_NEAR(out.x[lane] - kStartX, c.expected.x, near(c.expected.x));
    EXPECT_NEAR(out.y[lane] - kStartY, c.expected.y, near(c.expected.y));
    EXPECT_NEAR(out.z[lane] - kStartZ, c.expected.z, near(c.expected.z));
  }
}

// One direct-colour variation at one point: the colour index it leaves in every one of 37 lanes (the harness starts
// each at kStartColour, weight 0.8), against a value worked out by hand.
struct ColourCase {
  std::string name;
  std::vector<double> params;  // empty: the catalogue's defaults
  glm::dvec3 point;
  std::uint32_t seed;
  double colour;
};

[[maybe_unused]] inline void PrintTo(const ColourCase& c, std::ostream* os) {
  *os << c.name;
}

inline std::string colourCaseLabel(const testing::TestParamInfo<ColourCase>& info) {
  return info.param.name + "_" + std::to_string(info.index);
}

inline void expectSetsTheHandComputedColour(const ColourCase& c) {
  const core::VariationInfo& info = core::variationOrThrow(c.name);
  EXPECT_TRUE(info.directColour);
  const Outputs out = run(info, c.params.empty() ? info.defaultParams() : c.params, c.point, 0.8, c.seed, 37);
  for (std::size_t lane = 0; lane < out.colour.size(); ++lane)
    EXPECT_NEAR(out.colour[lane], c.colour, 1e-12) << "lane " << lane;
}

}  // namespace voxflame::test
