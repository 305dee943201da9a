// flam3 itself as the oracle of the variation formulas (issue 25): every variation of flam3's 99
// that draws no random number is run by libflam3 (apply_xform, on a one-transform genome parsed
// from XML with an identity affine map) and by voxflame's catalogue at four points, with every
// parameter set away from its default, and the two must agree to 1e-9. Built only where
// libflam3-dev is installed (a test-only dependency, scripts/packages.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

extern "C" {
#include <flam3.h>
// Exported by libflam3 but not declared in its public header.
int apply_xform(flam3_genome* cp, int fn, double* p, double* q, randctx* rc);
void xform_precalc(flam3_genome* cp, int xi);
int prepare_precalc_flags(flam3_genome* cp);
}

#include "core/flame/variations.h"

using namespace voxflame::core;

namespace {

// flam3_free releases the genome alone; its transforms (and their xaos rows) are released by
// clear_cp, which the leak checker otherwise reports as ours.
void freeGenome(flam3_genome* genome) {
  clear_cp(genome, flam3_defaults_on);
  flam3_free(genome);
}

// The parameter as a flame file names it (flam3's auger_weight is the catalogue's strength).
std::string fileParamName(const VariationInfo& info, const VariationParam& param) {
  if (info.name == "auger" && param.name == "strength") return "weight";
  return param.name;
}

// A value 37% of the way along the slider: away from the default, inside the range.
double probeValue(const VariationParam& p) {
  double v = p.sliderMin + 0.37 * (p.sliderMax - p.sliderMin);
  if (p.integer) v = std::round(v) == 0.0 ? 2.0 : std::round(v);
  return v;
}

}  // namespace

TEST(Flam3Oracle, DeterministicVariationsMatchLibflam3) {
  std::set<std::string> flam3Names;
  for (int i = 0; i < flam3_nvariations; ++i) flam3Names.insert(flam3_variation_names[i]);
  ASSERT_EQ(flam3Names.size(), 99u);
  const double points[][2] = {{0.3, -0.7}, {-0.45, 0.2}, {1.3, 0.9}, {-0.2, -1.6}};
  const double identity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  std::size_t compared = 0;
  for (const VariationInfo& info : variationCatalogue()) {
    if (!flam3Names.contains(info.name) || info.random) continue;
    SCOPED_TRACE(info.name);
    std::vector<double> params = info.defaultParams();
    std::string attributes = info.name + "=\"0.8\"";
    for (std::size_t i = 0; i < info.params.size(); ++i) {
      // log's base is JWildfire's; flam3's log is the natural one.
      if (info.name == "log") break;
      // waves2's z part (freqz, scalez) is Apophysis'; flam3 has no such parameters.
      if (info.name == "waves2" && i >= 4) continue;
      // splits' shears are JWildfire's; flam3's splits has x and y only.
      if (info.name == "splits" && i >= 2) continue;
      // elliptic's mode is JWildfire's; flam3's elliptic is mode 0.
      if (info.name == "elliptic") continue;
      params[i] = probeValue(info.params[i]);
      char number[40];
      std::snprintf(number, sizeof number, "%.17g", params[i]);
      attributes += " " + info.name + "_" + fileParamName(info, info.params[i]) + "=\"" + number + "\"";
    }
    std::string xml = "<flame size=\"10 10\"><xform weight=\"1\" coefs=\"1 0 0 1 0 0\" " + attributes + "/></flame>";
    int count = 0;
    flam3_genome* genome = flam3_parse_xml2(xml.data(), const_cast<char*>("oracle"), flam3_defaults_on, &count);
    ASSERT_NE(genome, nullptr) << xml;
    ASSERT_EQ(count, 1);
    prepare_precalc_flags(genome);
    xform_precalc(genome, 0);
    randctx rc{};
    irandinit(&rc, 1);
    for (const auto& point : points) {
      double p[4] = {point[0], point[1], 0.5, 1.0}, q[4] = {0.0, 0.0, 0.0, 0.0};
      apply_xform(genome, 0, p, q, &rc);
      double x = point[0], y = point[1], z = 0.0, outX = 0.0, outY = 0.0, outZ = 0.0;
      std::uint32_t random = 1;
      VariationInput in;
      in.x = &x;
      in.y = &y;
      in.z = &z;
      in.random = &random;
      in.count = 1;
      in.weight = 0.8;
      in.params = params.data();
      in.affine = identity;
      in.tx = &x;
      in.ty = &y;
      in.tz = &z;
      double colour = 0.5;
      in.colour = &colour;
      info.apply(in, &outX, &outY, &outZ);
      const double tolerance = 1e-9 * std::max(1.0, std::abs(q[0]) + std::abs(q[1]));
      EXPECT_NEAR(outX, q[0], tolerance) << "at (" << point[0] << ", " << point[1] << ")";
      EXPECT_NEAR(outY, q[1], tolerance) << "at (" << point[0] << ", " << point[1] << ")";
      ++compared;
    }
    freeGenome(genome);
  }
  // flam3's 99 less the random ones (julia, blur, noise, pie, arch, ...): about 80 variations.
  EXPECT_GE(compared, 4u * 75u);
}

// Xaos as flam3 means it: row i of `chaos` scales the weights of the transform chosen right after
// transform i. Each transform here sends every point to its own spot (x = 1, 2, 3), so the
// sequence flam3_iterate draws is read off its points; the shares of each transition are those
// voxflame's chaos game is tested for (chaos_game_test.cpp, ChaosGame.XaosForbids...).
TEST(Flam3Oracle, XaosRowsScaleTheNextTransformsWeight) {
  std::string xml = "<flame size=\"10 10\">";
  const char* chaos[] = {"0 1 1", "1 1 3", "2 1 1"};
  for (int k = 0; k < 3; ++k)
    xml += "<xform weight=\"1\" coefs=\"0 0 0 0 " + std::to_string(k + 1) + " 0\" linear=\"1\" chaos=\"" + chaos[k] +
           "\"/>";
  xml += "</flame>";
  int count = 0;
  flam3_genome* genome = flam3_parse_xml2(xml.data(), const_cast<char*>("xaos"), flam3_defaults_on, &count);
  ASSERT_NE(genome, nullptr);
  prepare_precalc_flags(genome);
  for (int k = 0; k < genome->num_xforms; ++k) xform_precalc(genome, k);
  genome->chaos_enable = !flam3_check_unity_chaos(genome);
  ASSERT_TRUE(genome->chaos_enable);
  unsigned short* distrib = flam3_create_xform_distrib(genome);
  ASSERT_NE(distrib, nullptr);
  randctx rc{};
  irandinit(&rc, 1);
  constexpr int kSamples = 60000;
  std::vector<double> samples(4 * kSamples, 0.0);
  flam3_iterate(genome, kSamples, 0, samples.data(), distrib, &rc);
  double transitions[3][3] = {};
  for (int i = 1; i < kSamples; ++i) {
    const auto from = static_cast<int>(std::lround(samples[4 * (i - 1)])) - 1;
    const auto to = static_cast<int>(std::lround(samples[4 * i])) - 1;
    ASSERT_TRUE(from >= 0 && from < 3 && to >= 0 && to < 3);
    transitions[from][to] += 1.0;
  }
  const auto share = [&](int from, int to) {
    return transitions[from][to] / (transitions[from][0] + transitions[from][1] + transitions[from][2]);
  };
  EXPECT_EQ(transitions[0][0], 0.0);
  EXPECT_NEAR(share(0, 1), 0.5, 0.02);
  EXPECT_NEAR(share(1, 2), 0.6, 0.02);
  EXPECT_NEAR(share(1, 0), 0.2, 0.02);
  EXPECT_NEAR(share(2, 0), 0.5, 0.02);
  EXPECT_NEAR(share(2, 1), 0.25, 0.02);
  flam3_free(distrib);
  freeGenome(genome);
}
