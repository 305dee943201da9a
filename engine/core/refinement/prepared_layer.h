// What a refinement backend runs of a pattern: each layer prepared once per generation from a
// short probe orbit on the CPU (bounds, the fit into the mask's grid, a pool of seeds, colour
// references, the palette), whichever backend then iterates it. The CPU accumulator and the GPU
// backend share it, so both place, colour and judge a pattern (bounded or escaping) alike.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/attractor.h"
#include "core/chaos_game.h"
#include "core/inside_mask.h"
#include "core/scene.h"

namespace voxflame::core {

// Maps attractor coordinates into grid voxel coordinates: scale about a centre (uniform, times a
// per-axis factor for a stretch fit), then the user's rotation, then a move to the grid centre
// (plus the user's offset).
struct FitTransform {
  glm::dvec3 attractorCenter{0.0};
  double scale = 1.0;          // voxels per attractor unit
  glm::dvec3 axisScale{1.0};   // per attractor axis, times scale (1 unless the fit stretches)
  glm::dvec3 gridCenter{0.0};  // in voxel units
  glm::dmat3 rotation{1.0};
  glm::dvec3 apply(glm::dvec3 p) const { return rotation * ((p - attractorCenter) * axisScale * scale) + gridCenter; }
};

// The automatic part of the fit (before the user transform): robust bounds of a probe sample,
// so a 1% parameter change moves it by well under 2%. Exposed for tests and the UI's lock button.
struct AutomaticFit {
  glm::dvec3 center{0.0};
  double scale = 1.0;
  glm::dvec3 axisScale{1.0};  // a stretch fit's shape (geometric mean 1); 1 for contain and cover
};

// What one layer needs to run, prepared once per generation from a short probe orbit.
struct PreparedLayer {
  PatternLayer layer;
  const AttractorInfo* info = nullptr;    // attractor layers
  std::shared_ptr<const ChaosGame> game;  // flame and quaternion Julia layers (shared by copies)
  AutomaticFit automaticFit;
  FitTransform fit;                      // automatic fit (or the locked one) and the user transform
  std::vector<glm::dvec3> seeds;         // points known to lie on the attractor (attractor layers)
  double escapeRadius = 1e6;             // beyond this an orbit counts as escaped
  double speedReference = 1.0;           // speed mapped to the gradient's end
  double distanceReference = 1.0;        // distance from the centre mapped to the gradient's end
  double curvatureReference = 1.0;       // sine of the turning angle mapped to the gradient's end
  double axisLow = 0.0, axisHigh = 1.0;  // extent of the attractor along the colour axis
  glm::dvec3 center{0.0};                // robust centre of the attractor
  std::vector<glm::u8vec3> palette;      // 256 gradient entries, linear RGB
  bool bounded = false;                  // the probe orbit stayed finite and bounded
  bool emptyView = false;                // a chaos game stays finite but (almost) nothing of it is drawn
};

// The box of the voxels inside the mask, in voxel units; the whole grid when the mask is empty.
// What the automatic fit sizes the attractor's robust box against and centres it in.
struct InsideBox {
  glm::dvec3 low{0.0}, high{0.0};
};
// One pass over the mask (a tenth of a second at 512³): an Accumulator finds it once for its
// grid instead of once per pattern.
InsideBox insideBox(const InsideMask& mask);

// The automatic fit of robust bounds (low, median and high percentiles) into the mask's inside box,
// the way `mode` asks (scene.h's FitMode).
AutomaticFit automaticFit(const glm::dvec3& low, const glm::dvec3& median, const glm::dvec3& high,
                          const InsideBox& inside, FitMode mode = FitMode::Contain);

// Each layer followed by its copies (LayerTransform::copies) as layers of their own: turned by the
// copy's angles, the layer's weight shared among them, no copies left. What the Accumulator runs.
std::vector<PatternLayer> expandCopies(const std::vector<PatternLayer>& layers);

// prepareLayer for each layer and its copies (one probe for all copies of a layer), in
// expandCopies's order.
// `inside` is insideBox(mask), when the caller has it already.
// `deepSeeds`: attractor layers draw their orbits' starts from a pool of seeds spread over a long
// run of the probe (tens of milliseconds), not only its first samples: what many short orbits (a
// still's chunks) need to cover the attractor.
std::vector<PreparedLayer> prepareLayers(const std::vector<PatternLayer>& layers, const InsideMask& mask,
                                         const InsideBox& inside, std::uint64_t seed, bool deepSeeds = false);
std::vector<PreparedLayer> prepareLayers(const std::vector<PatternLayer>& layers, const InsideMask& mask,
                                         std::uint64_t seed);

// Samples the layer's attractor and fits it into the mask's grid. Deterministic for a seed.
// Throws core::Error on parameters that are not finite numbers, absurd steps or transforms.
PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, const InsideBox& inside,
                           std::uint64_t seed, bool deepSeeds = false);
PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, std::uint64_t seed);

// Whether an Accumulator runs `layer` (in a scene of `seed`) or counts it as escaping (or
// collapsing, or showing almost nothing): the probe setPattern makes, so the answer is the live
// view's, whose KeepLastBounded keeps the last pattern instead. The mask only places a bounded
// pattern, so a small box stands in for the mesh's. A search asks this of a candidate before it
// hands it back. An invalid layer does not run: false.
bool runsBounded(const PatternLayer& layer, std::uint64_t seed);

// What a backend's stats say of the layers that escape (or collapse, or show almost nothing): the
// last such layer's reason; empty when every layer stays bounded.
std::string escapeProblem(const std::vector<PreparedLayer>& prepared);

}  // namespace voxflame::core
