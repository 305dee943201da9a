// The GPU backend's chaos game for one flame or quaternion Julia layer: GLSL generated per genome
// (the structure: which transforms, which variations in which stage, final and symmetry maps) and
// a block of numbers it reads (affine maps, weights, parameters, colours), so a slider that moves a
// number re-uploads the block and only a change of structure compiles a new program. The code
// follows core::ChaosGame step for step (core/chaos_game.cpp stays the reference): the same pick
// table, the same affine → pre_ → ordinary → post_ → post-affine order, flam3's colour blend, the
// opacity draw, the final transform and its chained ones, the symmetry maps. The variations it
// calls are shaders/flame_variations.glsl.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace voxflame::core {
struct PatternLayer;
struct FlameXform;
class ChaosGame;
}  // namespace voxflame::core

namespace voxflame::gl {

struct FlameKernel {
  // GLSL placed after flame_variations.glsl and before accumulate.comp.glsl: defines CHAOS_GAME,
  // CHAOS_STATE (vec4 for a flame, dvec4 for a quaternion Julia set, which needs double) and `bool
  // chaosStep(inout CHAOS_STATE state, inout float colour, inout uint previous, out vec3 drawn,
  // out float drawnColour)`.
  std::string source;
  std::vector<float> data;          // flame_variations.glsl's flameData
  std::vector<std::uint32_t> pick;  // flamePick: core::ChaosGame::pickTable, one transform index per entry
  // The V_ functions it calls, and the helpers of the variation files its own code calls
  // (weightFieldNoise): gpuVariationSource's argument.
  std::vector<std::string> variations;
  // Groups of orbits share each step's transform (accumulate.comp.glsl's GROUP_CHOICE): the
  // program's workgroups are then 256 orbits, not 64.
  bool groupChoice = false;
  // Doubles of memory per orbit its variations keep from step to step (VariationInfo::laneState):
  // flame_variations.glsl's gLane, LANE_MEMORY, which the program defines before the variations.
  std::size_t laneMemory = 0;
  // Floats of the largest term block a weighting field moves parameters of (flame_variations.glsl's
  // gFieldBlock, FIELD_BLOCK, which the program defines before the variations); 0: none.
  std::size_t fieldBlock = 0;
};

// Empty when the GPU's chaos game runs `layer` (a flame or quaternion Julia layer); else what it
// lacks, for a message ("variation 'falloff2'", "a weighting field on crackle's parameters").
std::string flameKernelUnsupported(const core::PatternLayer& layer);

// The kernel of `layer`, whose prepared game is `game` (the same pick table the CPU draws from).
// `groupChoice`: groups of orbits share each step's transform where the flame allows it (no xaos,
// two transforms or more). Call only when flameKernelUnsupported(layer) is empty.
FlameKernel makeFlameKernel(const core::PatternLayer& layer, const core::ChaosGame& game, bool groupChoice);

// The GLSL of the GPU's variations (shaders/flame_variations*.glsl, one file per family) a kernel
// needs: what every variation shares (buffers, constants, helpers), and the V_ functions of
// `variations` (or, for a name with no V_ function, the helper of that name) and those they call.
std::string gpuVariationSource(const std::vector<std::string>& variations);
// The variations it defines (as V_<name>), in the catalogue's spelling.
const std::vector<std::string>& gpuFlameVariations();

// The GLSL that defines parplotSurface (shaders/flame_variations_jwildfire.glsl) for parplot2d_wf's
// surfaces, each three formulas (x, y, z) as its term gives them, surface k at `which` k, with the
// functions the formulas call (shaders/parplot_functions.glsl). Throws core::Error for a formula
// flameKernelUnsupported refuses.
std::string gpuParplotSurfaces(const std::vector<std::array<std::string, 3>>& surfaces);
// Whether the GPU's variation `name` reads simplex noise (crackle): its term's parameters (all of
// them) are then followed in flameData by gpuNoiseExtras.
bool gpuVariationReadsNoise(std::string_view name);
// Whether the GPU's variation `name` reads its parameters in double as well, where float's rounding
// of one moves what it draws (dc_inversion's scales and time, dc_portal's time, waves and zoom, dc_tesla's,
// dc_warping's zoom and shifts, fract_mandelbrot_wf's and mandelbrot's bounds): each of its parameters then follows
// everything else of its term in flameData as its double's bits (low word, high word), gpuDoubleParams.
bool gpuVariationReadsDoubles(std::string_view name);
std::vector<float> gpuDoubleParams(const std::vector<double>& params);
// What crackle reads after its parameters `params`: its slice z in double (its bits in two floats)
// and `tables`, where gpuNoiseTables() lie in flameData (the kernel puts them in once).
std::vector<float> gpuNoiseExtras(const std::vector<double>& params, int tables);
// core::simplexNoiseTables() as flame_variations.glsl reads them: the hash (1024 entries), then the
// gradients (1024 × 3).
std::vector<float> gpuNoiseTables();
// The block shaders/weight_field.glsl's weightFieldNoise reads for `xform`'s weighting field (its
// kind, noise, octaves, frequency, seed...); `tables`: where gpuNoiseTables() lie in flameData,
// which its simplex noise reads.
std::vector<float> gpuWeightFieldBlock(const core::FlameXform& xform, int tables);

}  // namespace voxflame::gl
