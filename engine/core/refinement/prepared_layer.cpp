#include "core/refinement/prepared_layer.h"

#include <algorithm>
#include <utility>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <optional>

#if defined(__linux__)
#endif

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

#include "core/color.h"
#include "core/error.h"
#include "core/order_statistics.h"
#include "core/random.h"

namespace voxflame::core {

namespace {

constexpr std::size_t kProbeOrbits = 64;  // the fit samples many orbits, not one: steadier bounds
constexpr int kProbeTransient = 2'000;
constexpr int kProbeSpacing = 250;  // steps between the probe orbits' seeds
constexpr int kProbeSamplesPerOrbit = 2'000;
constexpr std::size_t kSeedPoolSize = 1'024;
constexpr int kDeepSeedSteps = 32'768;  // the probe orbits' run for a deep seed pool (prepareLayers)
constexpr int kDeepSeedSpacing = 16;
constexpr double kProbeEscape = 1e8;

bool isFiniteAndNear(double x, double y, double z, double radius) {
  return std::abs(x) < radius && std::abs(y) < radius && std::abs(z) < radius;  // false for NaN
}

double percentile(const std::vector<double>& values, double fraction) {
  return percentiles(values, std::array<double, 1>{fraction})[0];
}

// Robust bounds and centre: the low and high percentiles ignore a fraction of outliers on each
// side, so a rare excursion does not shrink the whole pattern and a small parameter change moves
// the fit only a little; the median is the robust centre.
void robustBounds(const std::vector<glm::dvec3>& samples, double fraction, glm::dvec3& low, glm::dvec3& median,
                  glm::dvec3& high) {
  std::vector<double> axis(samples.size());
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < samples.size(); ++i) axis[i] = samples[i][a];
    const auto [lowValue, medianValue, highValue] = percentiles(axis, std::array{fraction, 0.5, 1.0 - fraction});
    low[a] = lowValue;
    median[a] = medianValue;
    high[a] = highValue;
  }
}

bool finiteVector(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dmat3 rotationFromDegrees(glm::dvec3 degrees) {
  const glm::dvec3 r = glm::radians(degrees);
  const double cx = std::cos(r.x), sx = std::sin(r.x), cy = std::cos(r.y), sy = std::sin(r.y);
  const double cz = std::cos(r.z), sz = std::sin(r.z);
  // Column-major (glm): rotate about x first, then y, then z.
  const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  return rz * ry * rx;
}

void validateAttractorLayer(const PatternLayer& layer, const AttractorInfo& info) {
  const std::string name = "attractor '" + info.id + "'";
  if (layer.params.size() != info.params.size())
    throw Error(name + " takes " + std::to_string(info.params.size()) + " parameters, got " +
                std::to_string(layer.params.size()));
  for (std::size_t i = 0; i < layer.params.size(); ++i)
    if (!std::isfinite(layer.params[i]))
      throw Error("parameter '" + info.params[i].name + "' of " + name + " is not a finite number");
  if (!std::isfinite(layer.step) || layer.step <= 0.0 || layer.step > 1.0)
    throw Error("the step of " + name + " must be in (0, 1]");
  if (layer.color.mode == ColorMode::Index)
    throw Error("the colour mode 'index' of " + name + " needs a flame or quaternion Julia layer");
}

// What every kind of layer must satisfy: weight, placement and colour.
void validateLayer(const PatternLayer& layer) {
  const std::string name = layer.kind == PatternKind::Attractor ? "attractor '" + layer.attractor + "'"
                                                                : std::string(toString(layer.kind)) + " layer";
  if (!std::isfinite(layer.weight) || layer.weight < 0.0 || layer.weight > 1000.0)
    throw Error("the weight of " + name + " must be in [0, 1000]");
  const LayerTransform& t = layer.transform;
  if (!std::isfinite(t.scale) || t.scale <= 1e-3 || t.scale > 1e3)
    throw Error("the transform scale of " + name + " must be in (0.001, 1000]");
  if (!finiteVector(t.rotationDeg) || !finiteVector(t.offset) ||
      glm::any(glm::greaterThan(glm::abs(t.offset), glm::dvec3(100.0))))
    throw Error("the transform rotation and offset of " + name + " must be finite (offset within ±100)");
  if (t.lockFit &&
      (!finiteVector(t.lockedCenter) || !std::isfinite(t.lockedScale) || t.lockedScale <= 0.0 ||
       !finiteVector(t.lockedAxisScale) || glm::any(glm::lessThanEqual(t.lockedAxisScale, glm::dvec3(0.0)))))
    throw Error("the locked fit of " + name + " needs a finite centre and positive scales");
  const ColorSettings& c = layer.color;
  if (!std::isfinite(c.period) || c.period < 1.0 || c.period > 1e9)
    throw Error("the colour period of " + name + " must be 1 to 1e9 steps");
  if (!finiteVector(c.axis) || glm::length(c.axis) < 1e-12)
    throw Error("the colour axis of " + name + " must be a finite, non-zero vector");
  if (!std::isfinite(c.scale) || c.scale <= 0.0 || c.scale > 1e6)
    throw Error("the colour scale of " + name + " must be in (0, 1e6]");
  if (c.gradient.empty()) throw Error("the colour gradient of " + name + " has no stops");
}

}  // namespace

InsideBox insideBox(const InsideMask& mask) {
  const GridGeometry& g = mask.geometry;
  glm::ivec3 lo = g.size, hi(-1);
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j) {
      // A row's first and last inside voxel: the box needs nothing in between.
      const std::uint8_t* row = &mask.inside[g.index(0, j, k)];
      const std::uint8_t* end = row + g.size.x;
      const std::uint8_t* first = std::find_if(row, end, [](std::uint8_t v) { return v != 0; });
      if (first == end) continue;
      const std::uint8_t* last = std::find_if(std::make_reverse_iterator(end), std::make_reverse_iterator(first),
                                              [](std::uint8_t v) { return v != 0; })
                                     .base() -
                                 1;
      lo = glm::min(lo, glm::ivec3(static_cast<int>(first - row), j, k));
      hi = glm::max(hi, glm::ivec3(static_cast<int>(last - row), j, k));
    }
  if (hi.x < 0) return {glm::dvec3(0.0), glm::dvec3(g.size)};
  return {glm::dvec3(lo), glm::dvec3(hi) + 1.0};
}

AutomaticFit automaticFit(const glm::dvec3& low, const glm::dvec3& median, const glm::dvec3& high,
                          const InsideBox& inside, FitMode mode) {
  // Scale from the percentile box, centre on the median: for lopsided attractors (Rössler's flat
  // disc with rare spikes) the dense part then sits in the middle of the shape, not at its edge.
  // (Both are smooth in the samples; a max() of the two half-boxes would jump between sides.)
  const glm::dvec3 extent = glm::max(high - low, glm::dvec3(1e-9));
  const glm::dvec3 ratiosVector = (inside.high - inside.low) / extent;
  std::array<double, 3> ratios{ratiosVector.x, ratiosVector.y, ratiosVector.z};
  std::sort(ratios.begin(), ratios.end());
  switch (mode) {
    case FitMode::Previous:  // prepareLayers puts the previous layer's fit in its place
    case FitMode::Contain:
      // Scale so the attractor covers the shape along its middle axis (at most 2.5× over along its
      // widest); what spills over the surface is cut away by the mask, which is what makes the
      // pattern take the mesh's form. The thinnest axis is ignored: for flat attractors its extent
      // is the least stable statistic (Rössler's z), and it would make the scale jump.
      return {median, std::min(ratios[1], 2.5 * ratios[0]), glm::dvec3(1.0)};
    case FitMode::Cover:
      // The largest ratio, so the robust box reaches the shape's box along every axis and the mask
      // carves the form out of it. A flat attractor's thin axis would ask for a huge blow-up that
      // shows only its middle, so the scale stops at 3× the middle axis's ratio.
      return {median, std::min(ratios[2], 3.0 * ratios[1]), glm::dvec3(1.0)};
    case FitMode::Stretch: {
      // One ratio per attractor axis; the uniform part is their geometric mean and the rest the
      // shape. Each axis stays within 8× of the mean so a flat attractor is thickened, not turned
      // into noise by an absurd stretch of its least stable extent.
      const double mean = std::cbrt(ratios[0] * ratios[1] * ratios[2]);
      const glm::dvec3 shape = glm::clamp(ratiosVector / mean, glm::dvec3(1.0 / 8.0), glm::dvec3(8.0));
      return {median, mean, shape};
    }
  }
  return {median, std::min(ratios[1], 2.5 * ratios[0]), glm::dvec3(1.0)};
}

std::vector<PatternLayer> expandCopies(const std::vector<PatternLayer>& layers) {
  std::vector<PatternLayer> expanded;
  for (const PatternLayer& layer : layers) {
    const double share = 1.0 / static_cast<double>(layer.transform.copies.size() + 1);
    PatternLayer original = layer;
    original.transform.copies.clear();
    original.weight = layer.weight * share;
    expanded.push_back(original);
    for (const glm::dvec3& angles : layer.transform.copies) {
      PatternLayer copy = original;
      copy.transform.rotationDeg = layer.transform.rotationDeg + angles;
      expanded.push_back(copy);
    }
  }
  return expanded;
}

namespace {

PreparedLayer finishPreparedLayer(PreparedLayer prepared, std::vector<glm::dvec3>& samples, std::vector<double>& speeds,
                                  std::vector<double>& turns, const InsideMask& mask, const InsideBox& inside,
                                  SplitMix64& rng);

constexpr std::size_t kChaosProbeLanes = 256;
constexpr int kChaosProbeTransient = 40;
constexpr int kChaosProbeSteps = 500;

// The probe of a chaos-game layer: lanes from random starts run through their transient, then
// every drawn point is a sample. Its points are not kept as seeds: a chaos-game lane restarts
// anywhere and finds the attractor within its transient.
// Returns how many lane steps survived their transient (drawn or hidden): the measure of whether
// the pattern stays finite at all, apart from how much of it a slice or an opacity shows.
std::size_t probeChaosGame(const ChaosGame& game, SplitMix64& rng, std::vector<glm::dvec3>& samples,
                           std::vector<double>& speeds, std::vector<double>& turns) {
  std::size_t settled = 0;
  ChaosLanes lanes;
  lanes.resize(kChaosProbeLanes);
  for (std::size_t i = 0; i < kChaosProbeLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> x(kChaosProbeLanes), y(kChaosProbeLanes), z(kChaosProbeLanes), color(kChaosProbeLanes);
  std::vector<glm::dvec3> previous(kChaosProbeLanes, glm::dvec3(0.0)), previousStep(kChaosProbeLanes, glm::dvec3(0.0));
  // Steps since each lane was (re)seeded: like the workers, a lane draws only once it has survived
  // its transient, so a pattern whose lanes all run away before that yields no samples at all.
  std::vector<int> age(kChaosProbeLanes, 0);
  samples.reserve(kChaosProbeLanes * kChaosProbeSteps);
  for (int step = 0; step < kChaosProbeTransient + kChaosProbeSteps; ++step) {
    game.step(lanes, x.data(), y.data(), z.data(), color.data(), kChaosProbeLanes);
    for (std::size_t i = 0; i < kChaosProbeLanes; ++i) {
      const glm::dvec3 p(x[i], y[i], z[i]);
      if (!isFiniteAndNear(p.x, p.y, p.z, kProbeEscape)) {
        game.seedLane(lanes, i, rng);  // as the workers do: an escaped lane starts again
        previous[i] = previousStep[i] = glm::dvec3(0.0);
        age[i] = 0;
        continue;
      }
      const glm::dvec3 d = p - previous[i];
      settled += ++age[i] > kChaosProbeTransient ? 1 : 0;
      if (age[i] > kChaosProbeTransient && lanes.visible[i]) {
        samples.push_back(p);
        speeds.push_back(glm::length(d));
        const double lengths = glm::length(d) * glm::length(previousStep[i]);
        if (lengths > 0.0) turns.push_back(glm::length(glm::cross(d, previousStep[i])) / lengths);
      }
      previous[i] = p;
      previousStep[i] = d;
    }
  }
  return settled;
}

}  // namespace

PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, std::uint64_t seed) {
  return prepareLayer(layer, mask, insideBox(mask), seed, false);
}

PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, const InsideBox& inside,
                           std::uint64_t seed, bool deepSeeds) {
  PreparedLayer prepared;
  prepared.layer = layer;
  validateLayer(layer);
  SplitMix64 rng(mixSeed(seed, 0x70726f6265ULL));
  std::vector<glm::dvec3> samples;
  std::vector<double> speeds, turns;
  if (layer.isChaosGame()) {
    prepared.game = std::make_shared<const ChaosGame>(layer, std::string(toString(layer.kind)) + " layer");
    const std::size_t settled = probeChaosGame(*prepared.game, rng, samples, speeds, turns);
    // A good share of the lanes must stay finite past their transient for the pattern to mean
    // anything, and enough of those must be drawn to fit it (a slice that misses the set shows none).
    if (settled < kChaosProbeLanes * kChaosProbeSteps / 20 || samples.size() < 500) {
      prepared.emptyView = settled >= kChaosProbeLanes * kChaosProbeSteps / 20;
      return prepared;  // bounded stays false
    }
    return finishPreparedLayer(std::move(prepared), samples, speeds, turns, mask, inside, rng);
  }
  prepared.info = &attractorOrThrow(layer.attractor);
  const AttractorInfo& info = *prepared.info;
  validateAttractorLayer(layer, info);

  // Probe: one orbit from the start runs through its transient, then drops a seed every
  // kProbeSpacing steps; the seeds (different phases of the attractor, not near-copies of one
  // orbit, which chaos would take long to pull apart) advance as one batch and are sampled. Many
  // decorrelated samples make the bounds — and so the fit — steady under small changes.
  const AdvanceFn advance = info.advance(layer.integrator);
  std::vector<double> x(kProbeOrbits), y(kProbeOrbits), z(kProbeOrbits);
  std::vector<std::uint8_t> alive(kProbeOrbits, 1);
  {
    double sx = info.start.x, sy = info.start.y, sz = info.start.z;
    // The seed shifts the phase at which sampling begins, so different seeds give independent
    // probes (which is how the tests measure the fit's sampling noise).
    const int transient = kProbeTransient + static_cast<int>(rng.next() % 1'000);
    for (int step = 0; step < transient + static_cast<int>(kProbeOrbits) * kProbeSpacing; ++step) {
      advance(layer.params.data(), layer.step, &sx, &sy, &sz, 1);
      if (!isFiniteAndNear(sx, sy, sz, kProbeEscape)) return prepared;  // escapes: bounded stays false
      const int sampled = step - transient;
      if (sampled >= 0 && sampled % kProbeSpacing == 0) {
        const auto orbit = static_cast<std::size_t>(sampled / kProbeSpacing);
        x[orbit] = sx;
        y[orbit] = sy;
        z[orbit] = sz;
      }
    }
  }
  samples.reserve(kProbeOrbits * kProbeSamplesPerOrbit);
  std::vector<glm::dvec3> previous(kProbeOrbits), previousStep(kProbeOrbits, glm::dvec3(0.0));
  for (int step = 0; step < kProbeSamplesPerOrbit; ++step) {
    for (std::size_t i = 0; i < kProbeOrbits; ++i) previous[i] = {x[i], y[i], z[i]};
    advance(layer.params.data(), layer.step, x.data(), y.data(), z.data(), kProbeOrbits);
    for (std::size_t i = 0; i < kProbeOrbits; ++i) {
      if (!alive[i]) continue;
      if (!isFiniteAndNear(x[i], y[i], z[i], kProbeEscape)) {
        alive[i] = 0;
        x[i] = y[i] = z[i] = 0.0;  // parked; never sampled again
        continue;
      }
      const glm::dvec3 p(x[i], y[i], z[i]);
      const glm::dvec3 d = p - previous[i];
      if (step > 0) {
        samples.push_back(p);
        speeds.push_back(glm::length(d));
        const double lengths = glm::length(d) * glm::length(previousStep[i]);
        if (lengths > 0.0) turns.push_back(glm::length(glm::cross(d, previousStep[i])) / lengths);
      }
      previousStep[i] = d;
    }
  }
  // A few probe orbits leaving (a basin boundary nearby) is tolerated as long as most stay.
  const auto survivors = static_cast<std::size_t>(std::count(alive.begin(), alive.end(), std::uint8_t{1}));
  if (survivors < kProbeOrbits / 2 || samples.empty()) return prepared;  // bounded stays false
  if (!deepSeeds) return finishPreparedLayer(std::move(prepared), samples, speeds, turns, mask, inside, rng);
  std::vector<glm::dvec3> deep;
  {
    // The probe's samples are 64 arcs of 2,000 steps: orbits started there and run long (a live
    // view, one still) soon spread over the attractor, but short ones (a still's 64 chunks each
    // start their own) stay near those arcs and thin out what the arcs miss, by up to a third of
    // a sparse print's coverage. So the probe orbits go on much longer and drop a seed every
    // kDeepSeedSpacing steps.
    deep.reserve(kProbeOrbits * (kDeepSeedSteps / kDeepSeedSpacing));
    for (int step = 1; step <= kDeepSeedSteps; ++step) {
      advance(layer.params.data(), layer.step, x.data(), y.data(), z.data(), kProbeOrbits);
      if (step % kDeepSeedSpacing != 0) continue;
      for (std::size_t i = 0; i < kProbeOrbits; ++i) {
        if (!alive[i]) continue;
        if (!isFiniteAndNear(x[i], y[i], z[i], kProbeEscape)) {
          alive[i] = 0;
          x[i] = y[i] = z[i] = 0.0;
          continue;
        }
        deep.emplace_back(x[i], y[i], z[i]);
      }
    }
  }
  PreparedLayer finished = finishPreparedLayer(std::move(prepared), samples, speeds, turns, mask, inside, rng);
  if (!deep.empty() && !finished.seeds.empty()) finished.seeds = std::move(deep);
  return finished;
}

namespace {

// The fit, the colour references and the palette, from a probe's samples (any kind of layer).
PreparedLayer finishPreparedLayer(PreparedLayer prepared, std::vector<glm::dvec3>& samples, std::vector<double>& speeds,
                                  std::vector<double>& turns, const InsideMask& mask, const InsideBox& inside,
                                  SplitMix64& rng) {
  const PatternLayer& layer = prepared.layer;
  glm::dvec3 low, median, high;
  // 5%..95%: the bulk of the density decides the fit, not rare excursions (Rössler's z spikes
  // would otherwise push its dense spiral out of the grid), and a small sample noise moves it little.
  robustBounds(samples, 0.05, low, median, high);
  const glm::dvec3 extent = high - low;
  if (std::max({extent.x, extent.y, extent.z}) < 1e-6) return prepared;  // collapsed to a point
  prepared.center = median;
  prepared.automaticFit = automaticFit(low, median, high, inside, layer.transform.fit);

  const LayerTransform& t = layer.transform;
  prepared.fit.attractorCenter = t.lockFit ? t.lockedCenter : prepared.automaticFit.center;
  prepared.fit.scale = (t.lockFit ? t.lockedScale : prepared.automaticFit.scale) * t.scale;
  prepared.fit.axisScale = t.lockFit ? t.lockedAxisScale : prepared.automaticFit.axisScale;
  prepared.fit.rotation = rotationFromDegrees(t.rotationDeg);
  const glm::dvec3 gridSize(mask.geometry.size);
  prepared.fit.gridCenter =
      0.5 * (inside.low + inside.high) + t.offset * std::max({gridSize.x, gridSize.y, gridSize.z});
  prepared.escapeRadius = 1e3 * (std::max({std::abs(low.x), std::abs(low.y), std::abs(low.z), std::abs(high.x),
                                           std::abs(high.y), std::abs(high.z)}) +
                                 1.0);

  // Attractor orbits restart from points on the attractor; a chaos-game lane restarts anywhere.
  // (A still split into chunks replaces these with a deeper pool: prepareLayer's deepSeeds.)
  if (!prepared.game) prepared.seeds.reserve(kSeedPoolSize);
  for (std::size_t i = 0; !prepared.game && i < kSeedPoolSize; ++i)
    prepared.seeds.push_back(samples[static_cast<std::size_t>(rng.uniform() * static_cast<double>(samples.size()))]);

  // References that map each colour mode's raw value onto the gradient, measured on the probe
  // so the gradient spans what this attractor actually does.
  prepared.speedReference = std::max(percentile(speeds, 0.95), 1e-12);
  std::vector<double> distances(samples.size()), along(samples.size());
  const glm::dvec3 axis = glm::normalize(layer.color.axis);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    distances[i] = glm::length(samples[i] - prepared.center);
    along[i] = glm::dot(samples[i], axis);
  }
  prepared.distanceReference = std::max(percentile(distances, 0.95), 1e-12);
  const auto [alongLow, alongHigh] = percentiles(along, std::array{0.01, 0.99});
  prepared.axisLow = alongLow;
  prepared.axisHigh = std::max(alongHigh, prepared.axisLow + 1e-12);
  prepared.curvatureReference = turns.empty() ? 1.0 : std::max(percentile(turns, 0.95), 1e-12);

  const Gradient gradient(layer.color.gradient);
  // flam3's colour index comes with flam3's palette: its colours are summed and shown as the file
  // writes them (display-encoded, as the flat view sums them), not as linear light. Summed as
  // linear light, a flame's palette showed darker and more saturated than flam3 and its flat view
  // show it (Ethereal passage's blues and pinks, near 0.3 to 0.6, fell to 0.07 to 0.3: a dark smudge).
  const bool flam3Palette = layer.color.mode == ColorMode::Index;
  prepared.palette.resize(256);
  for (int i = 0; i < 256; ++i) {
    const glm::vec3 linear = gradient.at(static_cast<float>(i) / 255.0f);
    const glm::vec3 c = glm::clamp(flam3Palette ? linearToSrgb(linear) : linear, 0.0f, 1.0f) * 255.0f + 0.5f;
    prepared.palette[static_cast<std::size_t>(i)] = glm::u8vec3(c);
  }
  prepared.bounded = true;
  return prepared;
}

}  // namespace

std::vector<PreparedLayer> prepareLayers(const std::vector<PatternLayer>& layers, const InsideMask& mask,
                                         std::uint64_t seed) {
  return prepareLayers(layers, mask, insideBox(mask), seed, false);
}

std::vector<PreparedLayer> prepareLayers(const std::vector<PatternLayer>& layers, const InsideMask& mask,
                                         const InsideBox& inside, std::uint64_t seed, bool deepSeeds) {
  std::vector<PreparedLayer> prepared;
  std::size_t source = 0;
  const std::vector<PatternLayer> expanded = expandCopies(layers);
  // The fit a `previous` layer takes: that of the last original before it, if that one is bounded.
  std::optional<AutomaticFit> previousFit;
  for (const PatternLayer& layer : layers) {
    // The probe and the automatic fit come before the rotation, so one probe serves the original
    // and all its copies: only the rotation differs.
    PreparedLayer original = prepareLayer(expanded[source++], mask, inside, seed, deepSeeds);
    if (layer.transform.fit == FitMode::Previous && previousFit && original.bounded) {
      const AutomaticFit& previous = *previousFit;
      const LayerTransform& t = original.layer.transform;
      original.automaticFit = previous;
      if (!t.lockFit) {
        original.fit.attractorCenter = previous.center;
        original.fit.scale = previous.scale * t.scale;
        original.fit.axisScale = previous.axisScale;
      }
    }
    // A locked layer passes on its locked fit: what places it is what places the next.
    const LayerTransform& placed = original.layer.transform;
    previousFit.reset();
    if (placed.lockFit)
      previousFit = AutomaticFit{placed.lockedCenter, placed.lockedScale, placed.lockedAxisScale};
    else if (original.bounded)
      previousFit = original.automaticFit;
    prepared.push_back(original);
    for (std::size_t c = 0; c < layer.transform.copies.size(); ++c) {
      PreparedLayer copy = original;
      copy.layer = expanded[source++];
      copy.fit.rotation = rotationFromDegrees(copy.layer.transform.rotationDeg);
      prepared.push_back(std::move(copy));
    }
  }
  return prepared;
}

bool runsBounded(const PatternLayer& layer, std::uint64_t seed) {
  InsideMask mask;
  mask.geometry.size = glm::ivec3(8);
  const InsideBox inside{glm::dvec3(0.0), glm::dvec3(8.0)};
  try {
    const std::vector<PreparedLayer> prepared = prepareLayers({layer}, mask, inside, seed);
    return std::all_of(prepared.begin(), prepared.end(), [](const PreparedLayer& l) { return l.bounded; });
  } catch (const Error&) {
    return false;
  }
}

std::string escapeProblem(const std::vector<PreparedLayer>& prepared) {
  std::string problem;
  for (const PreparedLayer& layer : prepared) {
    if (layer.bounded) continue;
    problem = layer.emptyView
                  ? "the quaternion slice (or the transforms' opacity) shows almost none of the set; move the "
                    "slice or thicken it"
              : layer.layer.kind == PatternKind::Attractor
                  ? "attractor '" + layer.layer.attractor + "' escapes to infinity (or collapses) with these parameters"
                  : std::string(toString(layer.layer.kind)) +
                        " layer escapes to infinity (or collapses) with these transforms";
  }
  return problem;
}

}  // namespace voxflame::core
