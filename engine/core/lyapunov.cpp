#include "lyapunov.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "error.h"
#include "random.h"

namespace voxflame::core {

OrbitSpec defaultOrbitSpec(const AttractorInfo& info) {
  return {&info, info.defaultParams(), info.defaultIntegrator, info.defaultStep, info.start};
}

OrbitSpec orbitSpecOf(const PatternLayer& layer) {
  OrbitSpec spec = defaultOrbitSpec(attractorOrThrow(layer.attractor));
  spec.params = layer.params;
  spec.integrator = layer.integrator;
  spec.step = layer.step;
  return spec;
}

void validateOrbitSpec(const OrbitSpec& spec) {
  if (!spec.info) throw Error("no attractor given");
  const AttractorInfo& info = *spec.info;
  if (spec.params.size() != info.params.size())
    throw Error("attractor '" + info.id + "' takes " + std::to_string(info.params.size()) + " parameters, got " +
                std::to_string(spec.params.size()));
  for (std::size_t i = 0; i < spec.params.size(); ++i)
    if (!std::isfinite(spec.params[i]))
      throw Error("parameter '" + info.params[i].name + "' of attractor '" + info.id + "' is not a finite number");
  if (info.kind == AttractorKind::Flow && (!std::isfinite(spec.step) || spec.step <= 0.0 || spec.step > 1.0))
    throw Error("the step of attractor '" + info.id + "' must be a number in (0, 1]");
  if (!std::isfinite(spec.start.x) || !std::isfinite(spec.start.y) || !std::isfinite(spec.start.z))
    throw Error("the start point of attractor '" + info.id + "' is not finite");
}

std::string_view toString(OrbitVerdict verdict) {
  switch (verdict) {
    case OrbitVerdict::Escapes:
      return "escapes";
    case OrbitVerdict::FixedPoint:
      return "fixed point";
    case OrbitVerdict::Periodic:
      return "periodic";
    case OrbitVerdict::Chaotic:
      return "chaotic";
  }
  return "?";
}

double OrbitAnalysis::largestExtent() const {
  const glm::dvec3 e = high - low;
  return std::max({e.x, e.y, e.z});
}
double OrbitAnalysis::smallestExtent() const {
  const glm::dvec3 e = high - low;
  return std::min({e.x, e.y, e.z});
}

double chaosThreshold(const AttractorInfo& info) {
  // Flows: a zero exponent is always present and the numerical estimate of it wobbles by ~1e-3,
  // so "clearly positive" must be well above that. Maps have no zero exponent, and over the
  // 1e5 iterations analysed the estimate of a map exponent settles to ~1e-4.
  return info.kind == AttractorKind::Flow ? 0.01 : 0.005;
}

namespace {

// Columns of the 3×3 tangent matrix, kept orthonormal.
using Basis = std::array<std::array<double, 3>, 3>;

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

OrbitAnalysis analyseOrbit(const OrbitSpec& spec, const LyapunovOptions& options) {
  validateOrbitSpec(spec);
  if (options.steps < 1 || options.transientSteps < 0) throw Error("the Lyapunov estimate needs at least one step");
  const AttractorInfo& info = *spec.info;
  const StepJacobianFn stepJacobian = info.stepJacobian(spec.integrator);
  const double* p = spec.params.data();
  const double h = info.kind == AttractorKind::Flow ? spec.step : 1.0;

  OrbitAnalysis result;
  double state[3] = {spec.start.x, spec.start.y, spec.start.z};
  double jacobian[9];
  const auto escaped = [&] {
    for (double v : state)
      if (!(std::abs(v) < options.escapeRadius)) return true;  // also true for NaN
    return false;
  };
  for (int i = 0; i < options.transientSteps; ++i) {
    stepJacobian(p, h, state, jacobian);
    if (escaped()) return result;
  }

  Basis basis{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
  std::array<double, 3> logSums{0.0, 0.0, 0.0};
  result.low = result.high = glm::dvec3(state[0], state[1], state[2]);
  for (int i = 0; i < options.steps; ++i) {
    stepJacobian(p, h, state, jacobian);
    if (escaped()) return result;
    result.low = glm::min(result.low, glm::dvec3(state[0], state[1], state[2]));
    result.high = glm::max(result.high, glm::dvec3(state[0], state[1], state[2]));
    // Push every tangent direction through the step's Jacobian, then modified Gram–Schmidt: the
    // norms removed are the local stretch factors whose log-averages are the exponents.
    for (auto& v : basis) {
      const std::array<double, 3> u = v;
      for (int r = 0; r < 3; ++r)
        v[r] = jacobian[3 * r] * u[0] + jacobian[3 * r + 1] * u[1] + jacobian[3 * r + 2] * u[2];
    }
    for (int k = 0; k < 3; ++k) {
      for (int j = 0; j < k; ++j) {
        const double projection = dot(basis[k], basis[j]);
        for (int r = 0; r < 3; ++r) basis[k][r] -= projection * basis[j][r];
      }
      const double norm = std::sqrt(dot(basis[k], basis[k]));
      // A singular step (a map with zero Jacobian somewhere) would give log 0: count it as a huge
      // contraction and pick a fresh orthogonal direction so the estimate stays finite.
      logSums[k] += std::log(std::max(norm, 1e-300));
      if (norm > 1e-300) {
        for (int r = 0; r < 3; ++r) basis[k][r] /= norm;
      } else {
        basis[k] = {0.0, 0.0, 0.0};
        basis[k][k] = 1.0;
      }
    }
    ++result.stepsTaken;
  }
  result.bounded = true;
  const double time = static_cast<double>(options.steps) * h;
  for (int k = 0; k < 3; ++k) result.lyapunov[k] = logSums[k] / time;
  std::sort(result.lyapunov.begin(), result.lyapunov.end(), std::greater<>());

  // Kaplan–Yorke dimension: j + (λ1 + … + λj) / |λ(j+1)| for the largest j with a non-negative sum.
  double sum = 0.0;
  int j = 0;
  while (j < 3 && sum + result.lyapunov[j] >= 0.0) sum += result.lyapunov[j++];
  result.kaplanYorkeDimension = j == 3 ? 3.0 : static_cast<double>(j) + sum / std::abs(result.lyapunov[j]);

  const double scale = std::max(result.largestExtent(), 1e-300);
  if (result.largestExtent() < 1e-9 * std::max(1.0, glm::length(result.high)))
    result.verdict = OrbitVerdict::FixedPoint;
  else if (result.lyapunov[0] > chaosThreshold(info))
    result.verdict = OrbitVerdict::Chaotic;
  else
    result.verdict = scale > 0.0 ? OrbitVerdict::Periodic : OrbitVerdict::FixedPoint;
  return result;
}

std::vector<SearchResult> searchChaos(const OrbitSpec& base, const SearchOptions& options) {
  validateOrbitSpec(base);
  if (!(options.strength > 0.0) || options.strength > 10.0) throw Error("the mutation strength must be in (0, 10]");
  if (options.count < 1 || options.count > 10'000) throw Error("the search count must be 1 to 10000");
  const AttractorInfo& info = *base.info;
  if (options.strengthNow) options.strengthNow->store(options.strength);
  SplitMix64 rng(mixSeed(options.seed, 0x736561726368ULL));
  std::vector<SearchResult> found;
  for (int candidate = 0; candidate < options.maxCandidates && static_cast<int>(found.size()) < options.count &&
                          !options.stop.stop_requested();
       ++candidate) {
    OrbitSpec spec = base;
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
      const double range = info.params[i].sliderMax - info.params[i].sliderMin;
      spec.params[i] += options.strength * range * rng.symmetric();
    }
    // Half the candidates start from the base start, half from a jittered one: basins move with
    // the parameters, and a nearby start often lands in the new one.
    const double jitter = (candidate % 2 == 0 || !options.jitterStart) ? 0.0 : 0.5;
    spec.start += jitter * glm::dvec3(rng.symmetric(), rng.symmetric(), rng.symmetric());
    if (options.tried) options.tried->fetch_add(1, std::memory_order_relaxed);
    if (options.triedSignal) options.triedSignal->notify();
    const OrbitAnalysis screen = analyseOrbit(spec, options.screen);
    if (screen.verdict != OrbitVerdict::Chaotic) continue;
    if (screen.smallestExtent() < options.minExtentRatio * screen.largestExtent()) continue;
    const OrbitAnalysis confirm = analyseOrbit(spec, options.confirm);
    if (confirm.verdict != OrbitVerdict::Chaotic) continue;
    if (confirm.smallestExtent() < options.minExtentRatio * confirm.largestExtent()) continue;
    if (options.accept && !options.accept(spec.params)) continue;
    found.push_back({spec.params, spec.start, confirm});
  }
  if (found.empty() && options.widenTo > options.strength && !options.stop.stop_requested()) {
    // Nothing this close: look further away.
    SearchOptions wider = options;
    wider.strength = std::min(options.widenTo, 2.0 * options.strength);
    wider.seed = options.seed + 1;
    return searchChaos(base, wider);
  }
  return found;
}

}  // namespace voxflame::core
