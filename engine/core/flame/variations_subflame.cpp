// JWildfire's subflame variations: subflame_wf (SubFlameWFFunc) and glynns3subfl (GlynnS3SubflWFFunc,
// which draws a Glynn-like circle inversion or, at random, the subflame). Both carry a whole flame
// as text (JWildfire's "flame" resource) and add a point of that flame's attractor. See variations.h
// for the notation and variation_kernels.h for what the family files share.
//
// JWildfire keeps one orbit of the embedded flame per render thread and advances it one step per
// call. A variation here keeps nothing from one call to the next, so, as hopalong does, the
// embedded flame is imported (voxflame's own importer, readFlameXml) and iterated once per text to a
// cloud of kCloudPoints points with their colour indices, and each call draws one of them (Ψ picks
// which): the same attractor with the same density, the same for every lane, chunk and thread.
#include "core/flame/subflame.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "core/chaos_game.h"
#include "core/flame/variation_kernels.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

constexpr std::size_t kCloudPoints = std::size_t{1} << 20;
constexpr std::size_t kCloudLanes = 1024;
// JWildfire's prefuse: each orbit makes 42 steps before its first point is used.
constexpr std::size_t kTransient = 42;
// An embedded flame whose orbits keep escaping gets this many steps per lane at most (each escape
// costs its lane a new transient), so a flame that never settles costs bounded time.
constexpr std::size_t kMaxStepsPerLane = 8 * (kCloudPoints / kCloudLanes) + kTransient;

// What a term draws when its text is empty: a Sierpinski gasket in [−1, 1]², the colour index 0,
// ½, 1 by corner. (JWildfire's own default is a flame of waves2_wf and spherical3D; files always
// write the flame they embed, so the default only serves new terms.)
constexpr std::string_view kDefaultEmbeddedFlame =
    R"(<flame name="gasket"><xform weight="1" color="0" linear3D="1" coefs="0.5 0 0 0.5 -0.5 0.5"/>)"
    R"(<xform weight="1" color="0.5" linear3D="1" coefs="0.5 0 0 0.5 0.5 0.5"/>)"
    R"(<xform weight="1" color="1" linear3D="1" coefs="0.5 0 0 0.5 0 -0.5"/></flame>)";

struct EmbeddedCloud {
  std::string text;  // the term's text, as given (empty: the default)
  std::vector<double> x, y, z, colour;
  EmbeddedFlameCheck check;
};

// Leaves out the terms of variations that embed a flame themselves: an embedding then never
// recurses (each level would hold its own cloud of a flame inside the last).
bool dropNestedSubflames(FlameXform& xform) {
  const auto nested = [](const VariationTerm& term) {
    const VariationInfo* info = findVariation(term.name);
    return info && embedsFlame(*info);
  };
  const bool any = std::any_of(xform.variations.begin(), xform.variations.end(), nested);
  if (!any) return false;
  std::erase_if(xform.variations, nested);
  if (xform.variations.empty()) xform.variations = {{"linear", 1.0, {}}};
  return true;
}

// Imports and iterates one embedded flame. JWildfire starts its orbit at (Ψ − ½, Ψ − ½, 0) with a
// random colour, runs the first layer's transforms and final transforms (not the flame's
// symmetry), and skips the points a transform's opacity hides; so does this.
void buildCloud(EmbeddedCloud& cloud) {
  FlameImportOptions options;
  options.depth = 0.0;  // a flat embedded flame stays flat, as in JWildfire
  const std::string_view text = cloud.text.empty() ? kDefaultEmbeddedFlame : std::string_view(cloud.text);
  FlameFileContents contents = readFlameXml(text, "the embedded flame", options);
  cloud.check.leftOut = contents.flame.leftOut;
  FlameGenome& genome = contents.flame.genome;
  bool nested = false;
  for (FlameXform& xform : genome.xforms) nested = dropNestedSubflames(xform) || nested;
  if (genome.hasFinal) nested = dropNestedSubflames(genome.finalXform) || nested;
  for (FlameXform& xform : genome.chainedFinals) nested = dropNestedSubflames(xform) || nested;
  cloud.check.nested = nested;
  genome.symmetry = {};
  genome.postSymmetry = {};
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.flame = genome;
  const ChaosGame game(layer, "the embedded flame");

  ChaosLanes lanes;
  lanes.resize(kCloudLanes);
  SplitMix64 rng(0x5EB1F1A3Eu);
  std::vector<std::size_t> age(kCloudLanes, 0);
  const auto seed = [&](std::size_t i) {
    game.seedLane(lanes, i, rng);
    lanes.x[i] = rng.uniform() - 0.5;
    lanes.y[i] = rng.uniform() - 0.5;
    lanes.z[i] = 0.0;
    age[i] = 0;
  };
  for (std::size_t i = 0; i < kCloudLanes; ++i) seed(i);
  std::vector<double> ox(kCloudLanes), oy(kCloudLanes), oz(kCloudLanes), oc(kCloudLanes);
  for (auto* v : {&cloud.x, &cloud.y, &cloud.z, &cloud.colour}) v->reserve(kCloudPoints);
  for (std::size_t step = 0; step < kMaxStepsPerLane && cloud.x.size() < kCloudPoints; ++step) {
    game.step(lanes, ox.data(), oy.data(), oz.data(), oc.data(), kCloudLanes);
    for (std::size_t i = 0; i < kCloudLanes && cloud.x.size() < kCloudPoints; ++i) {
      if (!std::isfinite(ox[i]) || !std::isfinite(oy[i]) || !std::isfinite(oz[i])) {
        seed(i);
        continue;
      }
      if (++age[i] <= kTransient || !lanes.visible[i]) continue;
      cloud.x.push_back(ox[i]);
      cloud.y.push_back(oy[i]);
      cloud.z.push_back(oz[i]);
      cloud.colour.push_back(std::isfinite(oc[i]) ? std::clamp(oc[i], 0.0, 1.0) : 0.0);
    }
  }
  cloud.check.escapes = cloud.x.empty();
}

thread_local bool buildingCloud = false;  // this thread is importing or iterating an embedded flame

// The cloud of `text`, built once and shared: each thread keeps the last one it used, and a few
// recent ones are kept for all threads. nullptr while this thread builds one (an embedded flame's
// own import checking a flame nested in it), which draws nothing.
std::shared_ptr<const EmbeddedCloud> embeddedCloud(std::string_view text) {
  thread_local std::shared_ptr<const EmbeddedCloud> last;
  if (last && last->text == text) return last;
  if (buildingCloud) return nullptr;
  static RecentBuilds<EmbeddedCloud> clouds(2);
  return clouds.get(
      last, [&](const EmbeddedCloud& cloud) { return cloud.text == text; },
      [&] {
        auto cloud = std::make_shared<EmbeddedCloud>();
        cloud->text = text;
        buildingCloud = true;
        try {
          buildCloud(*cloud);
        } catch (const std::exception& e) {
          cloud->check.error = e.what();
        }
        buildingCloud = false;
        if (!cloud->check.error.empty()) {
          for (auto* v : {&cloud->x, &cloud->y, &cloud->z, &cloud->colour}) v->clear();
          cloud->check.escapes = false;
        }
        return std::shared_ptr<const EmbeddedCloud>(std::move(cloud));
      });
}

// JWildfire's colour modes: −2 the embedded point's true colour (voxflame has no true colour: its
// colour index stands in), −1 the colour left alone, 0 the embedded point's colour index, 1–4 a
// channel or the brightness of its true colour (likewise its colour index).
constexpr double kColourOff = -1.0;

// The subflame's own parameters at P[0 …]: scale, angle (degrees), offset_x, offset_y, offset_z,
// colorscale_z, color_mode, then JWildfire's flame-sequence settings (files from disk per frame,
// which voxflame does not read).
struct SubflameShape {
  double scale, cosA, sinA, offsetX, offsetY, offsetZ, colourScaleZ, colourMode;
  explicit SubflameShape(const double* P) {
    const double angle = P[1] * std::numbers::pi / 180.0;
    scale = P[0];
    cosA = std::cos(angle);
    sinA = std::sin(angle);
    offsetX = P[2];
    offsetY = P[3];
    offsetZ = P[4];
    colourScaleZ = P[5];
    // Tools.FTOI, then limitIntVal into [−2, 4]; a NaN is taken as off.
    colourMode = std::isnan(P[6]) ? kColourOff : std::clamp(std::round(P[6]), -2.0, 4.0);
  }
};

struct CloudPoint {
  double x, y, z, colour;
};

// Point k of the cloud through the variation's scale, turn and offsets, as JWildfire's subflameIter
// ends: (s x cos a − s y sin a + offset_x, s x sin a + s y cos a + offset_y, s z + offset_z +
// colorscale_z · colour).
inline CloudPoint shaped(const EmbeddedCloud& cloud, std::size_t k, const SubflameShape& s) {
  const double x = s.scale * cloud.x[k], y = s.scale * cloud.y[k], c = cloud.colour[k];
  return {x * s.cosA - y * s.sinA + s.offsetX, x * s.sinA + y * s.cosA + s.offsetY,
          s.scale * cloud.z[k] + s.offsetZ + s.colourScaleZ * c, c};
}

// Which point of the cloud Ψ picks.
inline std::size_t cloudIndex(double psi, std::size_t size) {
  return std::min(static_cast<std::size_t>(psi * static_cast<double>(size)), size - 1);
}

// subflame_wf: q, a point of the embedded flame's attractor (Ψ) shaped as above, added as it is:
// JWildfire's SubFlameWFFunc adds q without the term's weight. Colour mode ≠ −1: the colour index
// becomes the embedded point's. An embedded flame that cannot be read or never gives a finite point
// adds nothing.
VOXFLAME_VARIATION_TARGETS void subflameWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  (void)w;
  const std::shared_ptr<const EmbeddedCloud> cloud =
      embeddedCloud(in.texts ? std::string_view(in.texts[0]) : std::string_view());
  const std::size_t size = cloud ? cloud->x.size() : 0;
  const SubflameShape shape(P);
  for (std::size_t i = 0; i < n; ++i) {
    const double psi = laneUniform(rnd[i]);
    if (size == 0) continue;
    const CloudPoint q = shaped(*cloud, cloudIndex(psi, size), shape);
    outX[i] += q.x;
    outY[i] += q.y;
    outZ[i] += q.z;
    if (shape.colourMode != kColourOff && colour) colour[i] = q.colour;
  }
}

// glynns3subfl: with probability `probability` (JWildfire's glynns3subfl_weight) a point of Glynn's
// circle inversion replaces the running sum in x and y (JWildfire assigns it), z carried as by
// voxflame's 2D rule; otherwise w · q, q the subflame's point as in subflame_wf (here times the
// weight, as JWildfire's GlynnS3SubflWFFunc multiplies it), colour as subflame_wf's. The inversion,
// r = |(x, y)|, α = radius / r: type 0 (circle2): inside r₁ = radius + thickness, with show 1 a
// point of the circle of radius r₁ (chance γ = r₁ / (r₁ + r₂)) or r₂ = radius² / r₁ at angle 2πΨ,
// with show 0 (x, y); outside, (x, y) when Ψ > contrast α^|pow|, else α² (x, y). Type ≠ 0 (circle):
// inside radius, radius + thickness − γ' Ψ at angle φ₁ + (φ₂ − φ₁) Ψ (degrees), γ' = thickness (2
// radius + thickness) / (radius + thickness); outside as type 0. Draws in JWildfire's order: the
// inversion's, then the branch's, then the subflame's.
VOXFLAME_VARIATION_TARGETS void glynns3subfl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double probability = std::clamp(P[0], 0.0, 1.0);
  const bool show = std::trunc(std::clamp(P[1], 0.0, 1.0)) == 1.0;  // (int) limitVal(v, 0, 1)
  const double radius = P[2], thickness = std::clamp(P[3], 0.0, 1.0), contrast = std::clamp(P[4], 0.0, 1.0);
  const double absPow = std::abs(P[5]);
  const bool circle2 = std::trunc(P[6]) == 0.0 || std::isnan(P[6]);  // Java's (int) cast: NaN is 0
  const double radius1 = radius + thickness, radius2 = radius * radius / radius1;
  const double gamma2 = radius1 / (radius1 + radius2);
  const double phi10 = std::numbers::pi * P[7] / 180.0, delta = std::numbers::pi * P[8] / 180.0 - phi10;
  const double gamma1 = thickness * (2.0 * radius + thickness) / (radius + thickness);
  const double inner = circle2 ? radius1 : radius;
  const std::shared_ptr<const EmbeddedCloud> cloud =
      embeddedCloud(in.texts ? std::string_view(in.texts[0]) : std::string_view());
  const std::size_t size = cloud ? cloud->x.size() : 0;
  const SubflameShape shape(P + 9);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double alpha = radius / r;
    double px, py;
    if (r < inner) {
      if (show) {
        double rr, phi;
        if (circle2) {
          phi = 2.0 * std::numbers::pi * laneUniform(rnd[i]);
          rr = laneUniform(rnd[i]) < gamma2 ? radius1 : radius2;
        } else {
          rr = radius + thickness - gamma1 * laneUniform(rnd[i]);
          phi = phi10 + delta * laneUniform(rnd[i]);
        }
        px = rr * std::cos(phi);
        py = rr * std::sin(phi);
      } else {
        px = x[i];
        py = y[i];
      }
    } else if (laneUniform(rnd[i]) > contrast * std::pow(alpha, absPow)) {
      px = x[i];
      py = y[i];
    } else {
      px = alpha * alpha * x[i];
      py = alpha * alpha * y[i];
    }
    if (laneUniform(rnd[i]) < probability) {
      outX[i] = w * px;
      outY[i] = w * py;
      outZ[i] += w * z[i];
      continue;
    }
    const double psi = laneUniform(rnd[i]);
    if (size == 0) continue;
    const CloudPoint q = shaped(*cloud, cloudIndex(psi, size), shape);
    outX[i] += w * q.x;
    outY[i] += w * q.y;
    outZ[i] += w * q.z;
    if (shape.colourMode != kColourOff && colour) colour[i] = q.colour;
  }
}

// The cloud a term draws from, for the GPU's copy of the kernels: x, y, z and colour index per point.
std::vector<double> subflameTable(const double*, const std::string* texts) {
  const std::shared_ptr<const EmbeddedCloud> cloud =
      embeddedCloud(texts ? std::string_view(texts[0]) : std::string_view());
  std::vector<double> table;
  if (!cloud) return table;
  table.reserve(4 * cloud->x.size());
  for (std::size_t k = 0; k < cloud->x.size(); ++k)
    table.insert(table.end(), {cloud->x[k], cloud->y[k], cloud->z[k], cloud->colour[k]});
  return table;
}

// The subflame parameters both variations share, with JWildfire's defaults (`colourMode` differs).
std::vector<VariationParam> subflameParams(double colourMode) {
  const auto count = &CatalogueAdder::count;
  return {{"scale", 1.0, -2.5, 2.5},
          {"angle", 0.0, -180.0, 180.0},
          {"offset_x", 0.0, -2.5, 2.5},
          {"offset_y", 0.0, -2.5, 2.5},
          {"offset_z", 0.0, -2.5, 2.5},
          {"colorscale_z", 0.0, -2.5, 2.5},
          count("color_mode", colourMode, -2.0, 4.0),
          count("flame_is_sequence", 0.0, 0.0, 2.0),
          count("flame_sequence_start", 1.0, 1.0, 1000.0),
          count("flame_sequence_end", 0.0, 0.0, 1000.0),
          count("flame_sequence_repeat", 1.0, 1.0, 1000.0),
          count("flame_sequence_digits", 4.0, 1.0, 8.0)};
}

}  // namespace

EmbeddedFlameCheck checkEmbeddedFlame(std::string_view text) {
  if (buildingCloud) {
    EmbeddedFlameCheck skipped;
    skipped.skipped = true;
    return skipped;
  }
  const std::shared_ptr<const EmbeddedCloud> cloud = embeddedCloud(text);
  return cloud->check;
}

bool embedsFlame(const VariationInfo& info) {
  return !info.textParams.empty() && info.textParams.front().name == "flame";
}

std::optional<std::string> decodeJwildfireResource(std::string_view value) {
  if (value.size() % 2 != 0) return std::nullopt;
  const auto digit = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string decoded;
  decoded.reserve(value.size() / 2);
  for (std::size_t i = 0; i < value.size(); i += 2) {
    const int high = digit(value[i]), low = digit(value[i + 1]);
    if (high < 0 || low < 0) return std::nullopt;
    decoded.push_back(static_cast<char>(high * 16 + low));
  }
  return decoded;
}

void variation_kernels::addSubflameVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("subflame_wf",
      "q = (s x cos a − s y sin a + offset_x, s x sin a + s y cos a + offset_y, s z + offset_z + colorscale_z c) "
      "with s = scale, a = angle (degrees), (x, y, z) and colour index c a point of the embedded flame's attractor "
      "(`flame`: its XML; empty, a Sierpinski gasket) drawn by Ψ from 2²⁰ of its chaos game's points, the point "
      "itself not used and q added without the weight, as JWildfire does; color_mode ≠ −1: the colour index becomes "
      "c. The flame-sequence parameters (flame files per frame) are not used",
      k3D, kRandom, &subflameWf, subflameParams(-1.0));
  catalogue.back().textParams = {{"flame", ""}};
  catalogue.back().directColour = true;
  catalogue.back().additive = true;
  catalogue.back().table = &subflameTable;
  {
    std::vector<VariationParam> params = {
        {"probability", 0.5, 0.0, 1.0}, count("show", 1.0, 0.0, 1.0), {"radius", 1.0, 0.1, 2.1},
        {"thickness", 0.42, 0.0, 1.0},  {"contrast", 1.0, 0.0, 1.0},  {"pow", 1.5, 0.5, 1.5},
        count("type", 0.0, 0.0, 1.0),   {"phi1", 0.0, 0.0, 360.0},    {"phi2", 360.0, 0.0, 360.0}};
    for (VariationParam& p : subflameParams(0.0)) params.push_back(std::move(p));
    add("glynns3subfl",
        "with chance probability (Ψ after the inversion's draws) the x and y of the sum become w g, g Glynn's "
        "inversion of (x, y) in the circle of radius `radius` (type 0: inside radius + thickness, with show 1 a "
        "point at angle 2πΨ on the circle of radius r₁ = radius + thickness or r₂ = radius²/r₁, r₁ by chance r₁/(r₁ "
        "+ r₂); type 1: radius + thickness − γΨ at angle φ₁ + (φ₂ − φ₁)Ψ inside radius; outside, α² (x, y), α = "
        "radius/r, by chance contrast α^|pow|, else (x, y)), z carried; otherwise w q, q subflame_wf's point of the "
        "embedded flame, colour as subflame_wf's",
        k3D, kRandom, &glynns3subfl, std::move(params));
  }
  catalogue.back().textParams = {{"flame", ""}};
  catalogue.back().directColour = true;
  catalogue.back().readsSum = true;
  catalogue.back().table = &subflameTable;
}

}  // namespace voxflame::core
