// Exploring chaos-game patterns: random flame genomes, mutations of a genome, random or nudged
// quaternion Julia constants, and the test that decides whether a candidate is worth showing.
//
// Most random flames are not: a contractive set that collapses onto a few points (dust), a flat
// sheet, or maps that push points to infinity. The fill test runs a short chaos game (the same
// ChaosGame the accumulator runs) and measures what the accumulator's fit would see: the robust
// (5–95%) box of the drawn points, and how many cells of a coarse 16³ grid over that box the points
// reach. A candidate is kept when the box is a volume (no axis collapsed against the others), the
// points fill a fair share of it, and almost every draw is a finite point. The search draws or
// mutates candidates deterministically from a seed and returns the best scoring ones.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/flame.h"

namespace voxflame::core {

struct PatternLayer;

// What a candidate must reach to be kept. The defaults keep volumes with visible structure.
struct FillCriteria {
  double minOccupancy = 0.06;        // fraction of the 16³ cells over the robust box that points reach
  double minExtentRatio = 0.12;      // smallest robust box side over the largest: rejects sheets and lines
  double maxBadFraction = 0.05;      // draws that were not finite (escaped) over all draws
  double minVisibleFraction = 0.05;  // drawn points over steps taken (opacity 0, a slice that misses)
};

// What the fill test measured on one candidate.
struct FillReport {
  bool passes = false;
  std::string reason;        // why it failed, for messages ("collapses to a sheet", ...); empty when it passes
  double occupancy = 0.0;    // of the 16³ grid over the robust box
  double extentRatio = 0.0;  // smallest over largest side of the robust box
  double badFraction = 1.0;  // escaped draws over all draws
  double visibleFraction = 0.0;
  // How unevenly the points spread over the cells they reach (coefficient of variation of the
  // counts): filaments and dense cores against sparse veils score high, an even fog low.
  double contrast = 0.0;
  glm::dvec3 low{0.0}, high{0.0};  // the robust box (5% and 95% per axis)
  double score = 0.0;              // higher is better; 0 when it fails
};

// Runs a short chaos-game probe of a flame or quaternion Julia layer and measures its fill.
// Deterministic for a seed. Throws core::Error for an invalid layer (or an attractor layer).
FillReport measureFill(const PatternLayer& layer, std::uint64_t seed, const FillCriteria& criteria = {});
FillReport measureFlameFill(const FlameGenome& genome, std::uint64_t seed, const FillCriteria& criteria = {});
FillReport measureJuliaFill(const QuaternionJuliaSettings& julia, std::uint64_t seed,
                            const FillCriteria& criteria = {});

struct RandomFlameOptions {
  int minXforms = 2, maxXforms = 5;
  int minVariations = 1, maxVariations = 3;  // per transform
  double symmetryChance = 0.25;              // a rotational (sometimes mirrored) symmetry
  double finalChance = 0.15;                 // a final transform
};

// A random genome: 2–5 transforms, each a contractive 3D affine map (a random rotation times
// scales of 0.3–0.9 times a small shear, plus an offset) followed by 1–3 variations drawn from the
// whole catalogue, favouring those that make beautiful flames and never a noise-like one alone;
// colours spread over [0, 1]. Always passes validateFlame; deterministic for a seed.
FlameGenome randomFlame(std::uint64_t seed, const RandomFlameOptions& options = {});

// One random transform as randomFlame makes them (for the explorer's "Add transform").
FlameXform randomTransform(std::uint64_t seed, double color);

// A nearby genome: affine coefficients, weights, variation weights and parameters (by a share of
// their slider range) and colours move by amounts proportional to `strength` (0.1: a small step,
// 1: a large one); with a chance that grows with strength a variation is swapped, added or removed,
// or a transform added or removed. Strength 0 returns the genome unchanged. The result passes
// validateFlame when the input does; deterministic for a seed.
FlameGenome mutateFlame(const FlameGenome& genome, double strength, std::uint64_t seed);

// A Julia constant drawn in the ball of radius 1.1 (where connected quaternion Julia sets live);
// the other settings are `base`'s.
QuaternionJuliaSettings randomJulia(std::uint64_t seed, const QuaternionJuliaSettings& base = {});
// The constant moved by up to `strength` in a random direction of 4D (0 leaves it unchanged).
QuaternionJuliaSettings mutateJulia(const QuaternionJuliaSettings& julia, double strength, std::uint64_t seed);

struct FlameSearchOptions {
  std::uint64_t seed = 1;
  int count = 1;                      // the best candidates to return
  double strength = 0.1;              // with a base: how far mutations go
  int maxCandidates = 120;            // gives up after this many tries
  int poolPerResult = 3;              // candidates that pass, per result asked for, before the best are chosen
  RandomFlameOptions random;          // flames without a base
  QuaternionJuliaSettings juliaView;  // Julia sets without a base: the view, turn and slice kept
  FillCriteria fill;
  std::stop_token stop;  // a stop request ends the search early with what it found
  // When set, a candidate that passes the fill test is kept only if this says yes: the explorer
  // asks whether its live view runs it bounded (runsBounded, refinement/prepared_layer.h). Each search asks the
  // one of its kind.
  std::function<bool(const FlameGenome&)> acceptFlame;
  std::function<bool(const QuaternionJuliaSettings&)> acceptJulia;
};

struct FlameCandidate {
  FlameGenome genome;
  FillReport fill;
};
struct JuliaCandidate {
  QuaternionJuliaSettings julia;
  FillReport fill;
};

// Without a base: random genomes; with one: mutations of it. Returns up to `count` candidates that
// pass the fill test, best score first (fewer, possibly none, when the tries run out); a mutation
// identical to the base is never returned. Deterministic for a seed.
std::vector<FlameCandidate> searchFlames(const std::optional<FlameGenome>& base, const FlameSearchOptions& options);
std::vector<JuliaCandidate> searchQuaternionJulia(const std::optional<QuaternionJuliaSettings>& base,
                                                  const FlameSearchOptions& options);

}  // namespace voxflame::core
