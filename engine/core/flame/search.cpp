#include "core/flame/search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include <glm/geometric.hpp>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame/variations.h"
#include "core/random.h"
#include "core/scene.h"

namespace voxflame::core {

namespace {

// The probe: enough lanes and steps for ~50 000 points, a few milliseconds for a small genome.
constexpr std::size_t kProbeLanes = 256;
constexpr int kProbeTransient = 30;
constexpr int kProbeSteps = 200;
constexpr double kProbeEscape = 1e8;  // as the accumulator's probe: beyond it a draw has escaped
constexpr int kFillCells = 16;        // per axis of the occupancy grid
constexpr double kRobustLow = 0.05, kRobustHigh = 0.95;

// Variations that make the classic flame looks; the random genome draws them more often. Names
// the catalogue does not (yet) hold are simply never drawn.
constexpr std::array<std::string_view, 40> kFavourites = {
    "linear",  "spherical", "julia",     "julian",  "juliascope",   "swirl",       "sinusoidal", "spherical3D",
    "julia3D", "julia3Dz",  "curl",      "curl3D",  "rings2",       "fan2",        "pdj",        "blob",
    "disc",    "spiral",    "horseshoe", "polar",   "handkerchief", "heart",       "hyperbolic", "diamond",
    "ex",      "bubble",    "eyefish",   "fisheye", "ngon",         "perspective", "rectangles", "pie",
    "popcorn", "waves",     "power",     "cosine",  "exponential",  "bent",        "cylinder",   "linear3D"};
// Variations that smear points (noise, blurs), only act on depth, only turn the point (rotate_*,
// whose weight is an angle) or only crop it: fine as a second term, but alone they make a formless
// cloud, flatten the pattern or leave the affine map bare, so they are never a transform's only term.
// Besides these names, every variation whose result ignores the point (VariationInfo::additive:
// the blurs) or that acts on depth alone (mapsXY false) is never alone either (neverAlone below).
constexpr std::array<std::string_view, 34> kNeverAlone = {
    "noise",       "blur",          "gaussian_blur",     "pre_blur",   "square",      "blur3D",
    "radial_blur", "zscale",        "ztranslate",        "zcone",      "zblur",       "blur_circle",
    "blur_zoom",   "blur_pixelize", "crackle",           "pre_zscale", "blur_linear", "exblur",
    "inflateZ_3",  "rotate_x",      "rotate_y",          "rotate_z",   "smartcrop",   "circlecrop",
    "cropn",       "hexcrop",       "circlecrop2",       "vignette",   "plane_wf",    "triangle",
    "zscale_wf",   "mirror_wf",     "point_symmetry_wf", "chunk"};

bool contains(const auto& list, std::string_view name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

bool neverAlone(const VariationInfo& info) {
  return contains(kNeverAlone, info.name) || info.additive || !info.mapsXY;
}

double uniformIn(SplitMix64& rng, double low, double high) {
  return low + (high - low) * rng.uniform();
}

int integerIn(SplitMix64& rng, int low, int high) {  // inclusive
  return low + static_cast<int>(rng.next() % static_cast<std::uint64_t>(high - low + 1));
}

double drawWeight(const VariationInfo& info) {
  if (neverAlone(info)) return 0.4;
  return contains(kFavourites, info.name) ? 3.0 : 1.0;
}

// One catalogue entry drawn with drawWeight, skipping `exclude` and, when `alone`, the never-alone ones.
const VariationInfo* drawVariation(SplitMix64& rng, bool alone, const std::vector<VariationTerm>& exclude) {
  const auto& catalogue = variationCatalogue();
  const auto usable = [&](const VariationInfo& info) {
    if (alone && neverAlone(info)) return false;
    return std::none_of(exclude.begin(), exclude.end(), [&](const VariationTerm& t) { return t.name == info.name; });
  };
  double total = 0.0;
  for (const VariationInfo& info : catalogue)
    if (usable(info)) total += drawWeight(info);
  if (total <= 0.0) return nullptr;
  double pick = rng.uniform() * total;
  const VariationInfo* last = nullptr;
  for (const VariationInfo& info : catalogue) {
    if (!usable(info)) continue;
    last = &info;
    pick -= drawWeight(info);
    if (pick < 0.0) return &info;
  }
  return last;
}

// Half the time the default (what the variation's author found pretty), else anywhere on its slider.
std::vector<double> drawParams(SplitMix64& rng, const VariationInfo& info) {
  std::vector<double> values = info.defaultParams();
  for (std::size_t i = 0; i < info.params.size(); ++i) {
    const VariationParam& p = info.params[i];
    if (rng.uniform() < 0.5) continue;
    double v = uniformIn(rng, p.sliderMin, p.sliderMax);
    if (p.integer) {
      v = std::round(v);
      if (v == 0.0 && p.defaultValue != 0.0) v = p.defaultValue;  // a count of 0 (sides, power) is degenerate
    }
    values[i] = v;
  }
  return values;
}

VariationTerm drawTerm(SplitMix64& rng, bool alone, const std::vector<VariationTerm>& exclude) {
  const VariationInfo* info = drawVariation(rng, alone, exclude);
  if (!info) info = &variationOrThrow("linear");
  return {info->name, 1.0, drawParams(rng, *info)};
}

// A uniformly random rotation (a unit quaternion drawn uniformly from the 3-sphere).
std::array<double, 9> randomRotation(SplitMix64& rng) {
  double q[4];
  double length2 = 0.0;
  do {
    for (double& v : q) v = rng.symmetric();
    length2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  } while (length2 > 1.0 || length2 < 1e-6);
  const double s = 1.0 / std::sqrt(length2);
  const double w = q[0] * s, x = q[1] * s, y = q[2] * s, z = q[3] * s;
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),  //
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),  //
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

// rotation × diag(scales) × (identity + small upper shear), plus an offset in [-1, 1]³.
Affine3 randomContraction(SplitMix64& rng, double minScale, double maxScale, double offset) {
  const std::array<double, 9> r = randomRotation(rng);
  const double s[3] = {uniformIn(rng, minScale, maxScale), uniformIn(rng, minScale, maxScale),
                       uniformIn(rng, minScale, maxScale)};
  double h[9] = {1, 0.15 * rng.symmetric(), 0.15 * rng.symmetric(), 0, 1, 0.15 * rng.symmetric(), 0, 0, 1};
  Affine3 a;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k) sum += r[static_cast<std::size_t>(row * 3 + k)] * s[k] * h[k * 3 + col];
      a.m[static_cast<std::size_t>(row * 4 + col)] = sum;
    }
  for (int row = 0; row < 3; ++row) a.m[static_cast<std::size_t>(row * 4 + 3)] = offset * rng.symmetric();
  return a;
}

// 1–3 terms (within the options): the first may stand alone; weights sum to 1, the first largest.
std::vector<VariationTerm> randomTerms(SplitMix64& rng, const RandomFlameOptions& options) {
  const int count = integerIn(rng, std::max(1, options.minVariations),
                              std::max(std::max(1, options.minVariations), options.maxVariations));
  std::vector<VariationTerm> terms;
  for (int i = 0; i < count && terms.size() < kMaxXformVariations; ++i) {
    VariationTerm term = drawTerm(rng, i == 0, terms);
    term.weight = i == 0 ? uniformIn(rng, 0.5, 1.0) : uniformIn(rng, 0.1, 0.5);
    terms.push_back(std::move(term));
  }
  double total = 0.0;
  for (const VariationTerm& t : terms) total += t.weight;
  for (VariationTerm& t : terms) t.weight /= total;
  return terms;
}

FlameXform randomXform(SplitMix64& rng, const RandomFlameOptions& options, double color) {
  FlameXform x;
  x.weight = uniformIn(rng, 0.2, 1.0);
  x.affine = randomContraction(rng, 0.3, 0.9, 1.0);
  x.variations = randomTerms(rng, options);
  x.color = color;
  x.colorSpeed = uniformIn(rng, 0.3, 0.7);
  return x;
}

glm::dvec3 randomAxis(SplitMix64& rng) {
  const double pick = rng.uniform();
  if (pick < 0.5) return {0.0, 0.0, 1.0};
  if (pick < 0.65) return {0.0, 1.0, 0.0};
  if (pick < 0.8) return {1.0, 0.0, 0.0};
  glm::dvec3 v;
  do v = {rng.symmetric(), rng.symmetric(), rng.symmetric()};
  while (glm::length(v) > 1.0 || glm::length(v) < 0.1);
  return glm::normalize(v);
}

// Robust bounds: the low and high quantiles of one coordinate.
void quantiles(std::vector<double>& values, double& low, double& high) {
  const auto at = [&](double q) {
    const auto index = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + index, values.end());
    return values[static_cast<std::size_t>(index)];
  };
  low = at(kRobustLow);
  high = at(kRobustHigh);
}

FillReport fail(FillReport report, std::string reason) {
  report.passes = false;
  report.score = 0.0;
  report.reason = std::move(reason);
  return report;
}

double clamp01(double v) {
  return std::clamp(v, 0.0, 1.0);
}

void nudgeAffine(Affine3& affine, SplitMix64& rng, double strength) {
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col)
      affine.m[static_cast<std::size_t>(row * 4 + col)] += 0.3 * strength * rng.symmetric();
    affine.m[static_cast<std::size_t>(row * 4 + 3)] += 0.5 * strength * rng.symmetric();
  }
}

void nudgeTerms(std::vector<VariationTerm>& terms, SplitMix64& rng, double strength) {
  for (VariationTerm& term : terms) {
    term.weight += 0.3 * strength * rng.symmetric();
    const VariationInfo* info = findVariation(term.name);
    if (!info || term.params.size() != info->params.size()) continue;
    for (std::size_t i = 0; i < term.params.size(); ++i) {
      const VariationParam& p = info->params[i];
      const double old = term.params[i];
      double v = old + 0.5 * strength * (p.sliderMax - p.sliderMin) * rng.symmetric();
      // Stay on the slider (or where the user typed beyond it).
      v = std::clamp(v, std::min(p.sliderMin, old), std::max(p.sliderMax, old));
      if (p.integer) {
        v = std::round(v);
        if (v == 0.0 && old != 0.0) v = old;
      }
      term.params[i] = v;
    }
  }
}

void nudgeXform(FlameXform& x, SplitMix64& rng, double strength, bool isFinal) {
  nudgeAffine(x.affine, rng, strength);
  if (x.hasPost) nudgeAffine(x.post, rng, 0.5 * strength);
  if (!isFinal) x.weight = std::clamp(x.weight * std::exp(strength * rng.symmetric()), 1e-3, 1e3);
  nudgeTerms(x.variations, rng, strength);
  x.color = clamp01(x.color + 0.25 * strength * rng.symmetric());
}

// One structural change: swap, add or remove a variation, or add or remove a transform.
void structuralChange(FlameGenome& g, SplitMix64& rng, const RandomFlameOptions& options) {
  const int kind = integerIn(rng, 0, 4);
  FlameXform& x = g.xforms[rng.next() % g.xforms.size()];
  switch (kind) {
    case 0: {  // swap one variation for a new one, keeping its weight
      if (x.variations.empty()) break;
      const std::size_t i = rng.next() % x.variations.size();
      const double weight = x.variations[i].weight;
      x.variations[i] = drawTerm(rng, x.variations.size() == 1, x.variations);
      x.variations[i].weight = weight;
      break;
    }
    case 1:
      if (x.variations.size() < 3) {
        VariationTerm term = drawTerm(rng, x.variations.empty(), x.variations);
        term.weight = uniformIn(rng, 0.1, 0.4);
        x.variations.push_back(std::move(term));
      }
      break;
    case 2:
      if (x.variations.size() > 1) {
        x.variations.erase(x.variations.begin() + static_cast<std::ptrdiff_t>(rng.next() % x.variations.size()));
        // What is left must be able to stand alone.
        const VariationInfo* left = findVariation(x.variations.front().name);
        if (x.variations.size() == 1 && left && neverAlone(*left))
          x.variations.push_back(drawTerm(rng, true, x.variations));
      }
      break;
    case 3:
      if (g.xforms.size() < std::min<std::size_t>(kMaxFlameXforms, 6))
        g.xforms.push_back(randomXform(rng, options, rng.uniform()));
      break;
    default:
      if (g.xforms.size() > 2) {
        const std::size_t k = rng.next() % g.xforms.size();
        g.xforms.erase(g.xforms.begin() + static_cast<std::ptrdiff_t>(k));
        // Xaos columns follow the transforms.
        for (FlameXform& other : g.xforms)
          if (other.xaos.size() > k) other.xaos.erase(other.xaos.begin() + static_cast<std::ptrdiff_t>(k));
      }
      break;
  }
}

// A flame that already has xaos keeps exploring it: each factor moves by up to e^±strength (a
// forbidden step stays forbidden), and sometimes one step is forbidden or allowed again. A flame
// without xaos is not given any, so its mutations are what they were before xaos existed.
void nudgeXaos(FlameGenome& g, SplitMix64& rng, double strength) {
  if (!hasXaos(g)) return;
  for (FlameXform& x : g.xforms)
    for (double& factor : x.xaos) factor = std::clamp(factor * std::exp(strength * rng.symmetric()), 0.0, 1e3);
  if (rng.uniform() < std::min(0.5, strength)) {
    FlameXform& x = g.xforms[rng.next() % g.xforms.size()];
    const std::size_t j = rng.next() % g.xforms.size();
    if (x.xaos.size() <= j) x.xaos.resize(j + 1, 1.0);
    x.xaos[j] = x.xaos[j] == 0.0 ? 1.0 : 0.0;
  }
}

template <class Candidate, class Make, class Measure, class Accept>
std::vector<Candidate> runSearch(const FlameSearchOptions& options, Make make, Measure measure, Accept accept) {
  std::vector<Candidate> pool;
  const auto wanted = static_cast<std::size_t>(std::max(1, options.count) * std::max(1, options.poolPerResult));
  for (int i = 0; i < options.maxCandidates && pool.size() < wanted && !options.stop.stop_requested(); ++i) {
    const std::uint64_t seed = mixSeed(options.seed, static_cast<std::uint64_t>(i));
    std::optional<Candidate> candidate = make(seed);
    if (!candidate) continue;
    try {
      candidate->fill = measure(*candidate, mixSeed(seed, 0x66696c6cULL));
    } catch (const Error&) {
      continue;  // an invalid candidate (cannot happen for valid inputs) is simply not kept
    }
    if (candidate->fill.passes && accept(*candidate)) pool.push_back(std::move(*candidate));
  }
  std::stable_sort(pool.begin(), pool.end(),
                   [](const Candidate& a, const Candidate& b) { return a.fill.score > b.fill.score; });
  if (pool.size() > static_cast<std::size_t>(std::max(1, options.count)))
    pool.resize(static_cast<std::size_t>(std::max(1, options.count)));
  return pool;
}

}  // namespace

FillReport measureFill(const PatternLayer& layer, std::uint64_t seed, const FillCriteria& criteria) {
  if (!layer.isChaosGame()) throw Error("the fill test measures flame and quaternion Julia layers, not attractors");
  const ChaosGame game(layer, "candidate");
  SplitMix64 rng(seed);
  ChaosLanes lanes;
  lanes.resize(kProbeLanes);
  for (std::size_t i = 0; i < kProbeLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> x(kProbeLanes), y(kProbeLanes), z(kProbeLanes), color(kProbeLanes);
  std::vector<glm::dvec3> samples;
  samples.reserve(kProbeLanes * kProbeSteps);
  std::size_t bad = 0;
  for (int step = 0; step < kProbeTransient + kProbeSteps; ++step) {
    game.step(lanes, x.data(), y.data(), z.data(), color.data(), kProbeLanes);
    for (std::size_t i = 0; i < kProbeLanes; ++i) {
      const glm::dvec3 p(x[i], y[i], z[i]);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || std::abs(p.x) > kProbeEscape ||
          std::abs(p.y) > kProbeEscape || std::abs(p.z) > kProbeEscape) {
        ++bad;
        game.seedLane(lanes, i, rng);  // as the accumulator does: an escaped lane starts again
        continue;
      }
      if (step >= kProbeTransient && lanes.visible[i]) samples.push_back(p);
    }
  }
  FillReport report;
  report.badFraction = static_cast<double>(bad) / static_cast<double>(kProbeLanes * (kProbeTransient + kProbeSteps));
  report.visibleFraction = static_cast<double>(samples.size()) / static_cast<double>(kProbeLanes * kProbeSteps);
  if (report.badFraction > criteria.maxBadFraction) return fail(report, "escapes: its points run off to infinity");
  if (report.visibleFraction < criteria.minVisibleFraction || samples.size() < 64)
    return fail(report, "draws almost no points (empty)");

  std::vector<double> coordinate(samples.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t i = 0; i < samples.size(); ++i) coordinate[i] = samples[i][axis];
    quantiles(coordinate, report.low[axis], report.high[axis]);
  }
  const glm::dvec3 extent = report.high - report.low;
  const double largest = std::max({extent.x, extent.y, extent.z});
  const double smallest = std::min({extent.x, extent.y, extent.z});
  if (!(largest > 1e-9)) return fail(report, "collapses to a point");
  report.extentRatio = smallest / largest;
  if (report.extentRatio < criteria.minExtentRatio) return fail(report, "is flat (a sheet or a line), not a volume");

  // Occupancy of the coarse grid over the robust box; the points' spread over the cells they reach
  // (coefficient of variation) tells a structured flame from an even fog.
  std::vector<std::uint32_t> cells(static_cast<std::size_t>(kFillCells * kFillCells * kFillCells), 0);
  const glm::dvec3 perCell = glm::dvec3(kFillCells) / glm::max(extent, glm::dvec3(1e-300));
  for (const glm::dvec3& p : samples) {
    const glm::dvec3 c = (p - report.low) * perCell;
    if (c.x < 0.0 || c.y < 0.0 || c.z < 0.0 || c.x >= kFillCells || c.y >= kFillCells || c.z >= kFillCells) continue;
    const auto index = (static_cast<std::size_t>(c.z) * kFillCells + static_cast<std::size_t>(c.y)) * kFillCells +
                       static_cast<std::size_t>(c.x);
    ++cells[index];
  }
  std::size_t occupied = 0;
  double sum = 0.0, sumSquares = 0.0;
  for (const std::uint32_t count : cells)
    if (count > 0) {
      ++occupied;
      sum += count;
      sumSquares += static_cast<double>(count) * count;
    }
  report.occupancy = static_cast<double>(occupied) / static_cast<double>(cells.size());
  if (report.occupancy < criteria.minOccupancy) return fail(report, "is dust: its points fill little of their box");
  const double mean = sum / static_cast<double>(occupied);
  report.contrast = std::sqrt(std::max(0.0, sumSquares / static_cast<double>(occupied) - mean * mean)) / mean;
  report.passes = true;
  // Past a third of its box a pattern reads as a volume, so more fill earns nothing; what tells a
  // flame from an even fog is its dynamic range, the contrast between dense and sparse cells.
  report.score = std::min(report.occupancy, 0.35) / 0.35 * std::sqrt(report.extentRatio) *
                 std::min(report.contrast, 4.0) / 4.0 * (1.0 - report.badFraction);
  return report;
}

FillReport measureFlameFill(const FlameGenome& genome, std::uint64_t seed, const FillCriteria& criteria) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = genome;
  return measureFill(layer, seed, criteria);
}

FillReport measureJuliaFill(const QuaternionJuliaSettings& julia, std::uint64_t seed, const FillCriteria& criteria) {
  PatternLayer layer;
  layer.kind = PatternKind::QuaternionJulia;
  layer.attractor.clear();
  layer.julia = julia;
  return measureFill(layer, seed, criteria);
}

FlameGenome randomFlame(std::uint64_t seed, const RandomFlameOptions& options) {
  SplitMix64 rng(mixSeed(seed, 0x666c616d65ULL));
  FlameGenome g;
  const int minX = std::clamp(options.minXforms, 1, static_cast<int>(kMaxFlameXforms));
  const int count = integerIn(rng, minX, std::clamp(options.maxXforms, minX, static_cast<int>(kMaxFlameXforms)));
  // Colours spread evenly over [0, 1] (a little jittered), handed out in random order.
  std::vector<double> colors;
  for (int i = 0; i < count; ++i)
    colors.push_back(clamp01((count == 1 ? 0.5 : static_cast<double>(i) / (count - 1)) + 0.05 * rng.symmetric()));
  for (int i = count - 1; i > 0; --i)
    std::swap(colors[static_cast<std::size_t>(i)], colors[rng.next() % static_cast<std::uint64_t>(i + 1)]);
  for (int i = 0; i < count; ++i) g.xforms.push_back(randomXform(rng, options, colors[static_cast<std::size_t>(i)]));
  if (rng.uniform() < options.symmetryChance) {
    g.symmetry.rotational = integerIn(rng, 1, 6);
    g.symmetry.axis = randomAxis(rng);
    g.symmetry.mirror = g.symmetry.rotational == 1 || rng.uniform() < 0.3;
  }
  if (rng.uniform() < options.finalChance) {
    // A gentle bend of the whole picture: near-identity map, one variation that can stand alone.
    FlameXform& f = g.finalXform;
    g.hasFinal = true;
    f.affine = randomContraction(rng, 0.8, 1.2, 0.2);
    f.variations = {drawTerm(rng, true, {})};
    f.colorSpeed = 0.0;  // the final transform bends, it does not recolour
    f.color = 0.5;
  }
  return g;
}

FlameXform randomTransform(std::uint64_t seed, double color) {
  SplitMix64 rng(mixSeed(seed, 0x78666f726dULL));
  return randomXform(rng, RandomFlameOptions{}, clamp01(color));
}

FlameGenome mutateFlame(const FlameGenome& genome, double strength, std::uint64_t seed) {
  if (!(strength > 0.0) || genome.xforms.empty()) return genome;
  SplitMix64 rng(mixSeed(seed, 0x6d757461ULL));
  FlameGenome g = genome;
  for (FlameXform& x : g.xforms) nudgeXform(x, rng, strength, false);
  if (g.hasFinal) nudgeXform(g.finalXform, rng, 0.5 * strength, true);
  if (rng.uniform() < std::min(0.9, strength)) structuralChange(g, rng, RandomFlameOptions{});
  nudgeXaos(g, rng, strength);
  return g;
}

QuaternionJuliaSettings randomJulia(std::uint64_t seed, const QuaternionJuliaSettings& base) {
  SplitMix64 rng(mixSeed(seed, 0x6a756c6961ULL));
  QuaternionJuliaSettings q = base;
  glm::dvec4 c;
  do c = {rng.symmetric(), rng.symmetric(), rng.symmetric(), rng.symmetric()};
  while (glm::length(c) > 1.0);
  // The classic pictures have most of c in its first two components; the other two shape it.
  q.c = 1.1 * glm::dvec4(c.x, c.y, 0.5 * c.z, 0.5 * c.w);
  return q;
}

QuaternionJuliaSettings mutateJulia(const QuaternionJuliaSettings& julia, double strength, std::uint64_t seed) {
  if (!(strength > 0.0)) return julia;
  SplitMix64 rng(mixSeed(seed, 0x6a6d7574ULL));
  glm::dvec4 d;
  do d = {rng.symmetric(), rng.symmetric(), rng.symmetric(), rng.symmetric()};
  while (glm::length(d) > 1.0);
  QuaternionJuliaSettings q = julia;
  q.c = glm::clamp(q.c + strength * d, glm::dvec4(-10.0), glm::dvec4(10.0));
  return q;
}

std::vector<FlameCandidate> searchFlames(const std::optional<FlameGenome>& base, const FlameSearchOptions& options) {
  if (base) validateFlame(*base, "the flame to mutate");
  return runSearch<FlameCandidate>(
      options,
      [&](std::uint64_t seed) -> std::optional<FlameCandidate> {
        FlameCandidate c;
        c.genome = base ? mutateFlame(*base, options.strength, seed) : randomFlame(seed, options.random);
        if (base && c.genome == *base) return std::nullopt;
        return c;
      },
      [&](const FlameCandidate& c, std::uint64_t seed) {
        validateFlame(c.genome, "candidate");
        return measureFlameFill(c.genome, seed, options.fill);
      },
      [&](const FlameCandidate& c) { return !options.acceptFlame || options.acceptFlame(c.genome); });
}

std::vector<JuliaCandidate> searchQuaternionJulia(const std::optional<QuaternionJuliaSettings>& base,
                                                  const FlameSearchOptions& options) {
  if (base) validateQuaternionJulia(*base, "the Julia set to mutate");
  return runSearch<JuliaCandidate>(
      options,
      [&](std::uint64_t seed) -> std::optional<JuliaCandidate> {
        JuliaCandidate c;
        c.julia = base ? mutateJulia(*base, options.strength, seed) : randomJulia(seed, options.juliaView);
        if (base && c.julia == *base) return std::nullopt;
        return c;
      },
      [&](const JuliaCandidate& c, std::uint64_t seed) {
        validateQuaternionJulia(c.julia, "candidate");
        return measureJuliaFill(c.julia, seed, options.fill);
      },
      [&](const JuliaCandidate& c) { return !options.acceptJulia || options.acceptJulia(c.julia); });
}

}  // namespace voxflame::core
