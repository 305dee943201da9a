// Chaos diagnostics for one attractor and one parameter set: the full Lyapunov spectrum (three
// exponents) from the orbit and its tangent space, re-orthonormalised by Gram–Schmidt every step
// so the three directions neither blow up nor collapse onto the most unstable one; the box the
// orbit fills; and a verdict (escapes, settles on a point or a cycle, chaotic). Exponents are per
// unit time for flows and per iteration for maps. The chaos search mutates parameters and keeps
// the sets this verdict calls chaotic and volume-filling, as Sprott's and Chaoscope's searches do.
#pragma once

#include <atomic>

#include <array>
#include <cstdint>
#include <functional>
#include <stop_token>
#include <vector>

#include <glm/vec3.hpp>

#include "attractor.h"
#include "progress_signal.h"
#include "scene.h"

namespace voxflame::core {

// What to analyse: an attractor, its parameters, how it is stepped and where the orbit starts.
struct OrbitSpec {
  const AttractorInfo* info = nullptr;
  std::vector<double> params;
  Integrator integrator = Integrator::Euler;
  double step = 0.01;  // flows only
  glm::dvec3 start{0.1, 0.1, 0.1};
};

// The spec of an attractor's defaults (its own integrator, step and start).
OrbitSpec defaultOrbitSpec(const AttractorInfo& info);
// An attractor layer's orbit: its attractor's default start, its parameters, integrator and step.
OrbitSpec orbitSpecOf(const PatternLayer& layer);

// Refuses (core::Error) parameters of the wrong count, NaN or infinite values, and steps that are
// not finite or outside (0, 1].
void validateOrbitSpec(const OrbitSpec& spec);

struct LyapunovOptions {
  int transientSteps = 5'000;
  int steps = 100'000;
  double escapeRadius = 1e6;  // |coordinate| beyond this counts as escaped
};

enum class OrbitVerdict { Escapes, FixedPoint, Periodic, Chaotic };
std::string_view toString(OrbitVerdict verdict);

struct OrbitAnalysis {
  bool bounded = false;              // stayed finite and inside the escape radius
  std::array<double, 3> lyapunov{};  // largest first; per unit time (flows) or iteration (maps)
  glm::dvec3 low{0.0}, high{0.0};    // the box the orbit filled after the transient
  double kaplanYorkeDimension = 0.0;
  OrbitVerdict verdict = OrbitVerdict::Escapes;
  int stepsTaken = 0;
  double largestExtent() const;
  double smallestExtent() const;
};

// Deterministic: no randomness involved. Throws core::Error on invalid specs.
OrbitAnalysis analyseOrbit(const OrbitSpec& spec, const LyapunovOptions& options = {});

// The threshold above which the largest exponent counts as clearly positive, in the analysis's
// own units (per unit time for flows, per iteration for maps).
double chaosThreshold(const AttractorInfo& info);

// The explorer's search (and `bench search`'s): a few hundred tries at each strength, doubled
// while nothing is found, up to this.
inline constexpr double kSearchWidenTo = 0.8;
inline constexpr int kSearchTriesPerStrength = 100;

struct SearchOptions {
  std::uint64_t seed = 1;
  int count = 5;                                // parameter sets to find
  double strength = 0.1;                        // mutation size as a fraction of each parameter's slider range
  int maxCandidates = 2'000;                    // gives up after this many tries
  LyapunovOptions screen{1'000, 4'000, 1e4};    // cheap first look at every candidate
  LyapunovOptions confirm{5'000, 40'000, 1e4};  // the full check a found set must pass
  double minExtentRatio = 0.05;                 // smallest box side over largest: rejects flat or thin sets
  std::stop_token stop;                         // a stop request ends the search early with what it found
  // > strength: while nothing is found, the search starts over at twice the strength (a new
  // seed), up to this, `maxCandidates` tries at each strength, before it gives up.
  double widenTo = 0.0;
  std::atomic<int>* tried = nullptr;           // counts the candidates as they are tried (progress), if set
  ProgressSignal* triedSignal = nullptr;       // notified after each count of `tried`, if set (its waiters)
  std::atomic<double>* strengthNow = nullptr;  // the strength being tried now, if set
  // Half the candidates start from a point near the base's start (basins move with the
  // parameters), and a result says where. A caller whose orbits always start at the base's start
  // (the explorer's layers hold no start) turns this off, so every analysis is of its own orbit.
  bool jitterStart = true;
  // When set, a candidate that passed the analysis is kept only if this says yes: the explorer
  // asks whether its live view runs the parameters bounded (runsBounded, refinement/prepared_layer.h).
  std::function<bool(const std::vector<double>& params)> accept;
};

struct SearchResult {
  std::vector<double> params;
  glm::dvec3 start{0.0};
  OrbitAnalysis analysis;
};

// Mutates `base` (each parameter by up to strength × its slider range) and keeps sets that are
// bounded, chaotic and fill a volume. Deterministic for a seed; may return fewer than asked.
std::vector<SearchResult> searchChaos(const OrbitSpec& base, const SearchOptions& options);

}  // namespace voxflame::core
