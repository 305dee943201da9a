#include "core/refinement/accumulator.h"

#include <pthread.h>
#include <algorithm>
#include <utility>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <glm/geometric.hpp>

#include "core/cpu_features.h"
#include "core/error.h"
#include "core/random.h"

namespace voxflame::core {

namespace {

constexpr std::size_t kOrbitsPerBatch = 256;  // independent orbits advanced together per layer
// A chaos game's orbits: four times as many, for as many samples a batch in a quarter of the steps. A
// step of a flame works transform by transform on the orbits that drew each (chaos_game.h), and with
// 20 transforms 256 orbits leave about a dozen to a group, where each group's and each variation
// call's fixed cost weighed as much as the variations themselves.
constexpr std::size_t kChaosOrbitsPerBatch = 1024;
constexpr std::size_t kMaxOrbitsPerBatch = std::max(kOrbitsPerBatch, kChaosOrbitsPerBatch);
constexpr int kStepsPerBatch = 128;           // steps per batch before checking for a new generation (with 256 orbits)
constexpr std::int32_t kTransientSteps = 32;  // steps an orbit takes before it may splat
constexpr std::int32_t kAgeLimit = 1 << 30;   // ages saturate here (time colouring then freezes)
constexpr int kMaxSlabs = 64;                 // grid slabs, each with its own mutex
constexpr std::size_t kFlushThreshold = 8'192;  // splats a thread collects before adding them to the grid
using detail::kColourCountLimit;
using detail::kOutsideBit;

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

// Per-thread state of one layer's orbits, structure of arrays so the advance and classify loops
// vectorise across orbits.
struct OrbitBatch {
  std::vector<double> x, y, z, px, py, pz, sx, sy, sz;  // position, previous position, previous step
  std::vector<std::int32_t> age;                        // steps since (re)seeding, saturating
  std::vector<std::int32_t> voxel;                      // this step's voxel, -1 when none
  std::vector<std::int32_t> colorIndex;                 // this step's palette entry (0..255)
  std::vector<std::int32_t> escaped;
  std::vector<std::int32_t> brick;   // this step's 4×4×4 brick of the grid, 0 when none (32-bit like voxel)
  std::vector<std::int32_t> cell;    // this step's colour cell, 0 when none
  std::vector<std::int32_t> slab;    // the grid slab of that cell (what the flush sorts by)
  std::vector<std::uint32_t> noise;  // xorshift32 state per orbit for the deposit jitter (never 0)
  std::vector<float> gx, gy, gz;     // this step's exact grid position (point sink only)
  std::vector<double> colorCoord;    // chaos games: this step's colour index (ColorMode::Index)
  ChaosLanes chaos;                  // chaos games: the iterated state behind x, y, z
  std::uint64_t epoch = 0;           // Accumulator::orbitEpoch_ when the orbits were seeded
  double pointsPerStep = 0.0;        // points a step of the stream's last batch yielded, past the transient
  SplitMix64 rng{0};
  std::uint64_t generation = ~std::uint64_t{0};
};

// One point for the grid: its voxel, its colour cell, and its packed RGB with the slab in the top byte.
struct Splat {
  std::uint32_t voxel;
  std::uint32_t cell;
  std::uint32_t rgbSlab;
};

// Each thread's splats: appended in orbit order, then sorted by grid slab (a counting sort) and
// added slab by slab under that slab's mutex.
struct SplatBuffer {
  std::vector<Splat> entries;  // kFlushThreshold plus room for one more step of every orbit
  std::vector<Splat> sorted;
  std::vector<std::size_t> slabStart;
  std::size_t count = 0;
  // With a point sink: accepted points collected for the next consume call (allocated on first use).
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> rgb;
  std::size_t pointCount = 0;
  void reset(std::size_t slabs) {
    entries.assign(kFlushThreshold + kMaxOrbitsPerBatch, Splat{});
    sorted.assign(entries.size(), Splat{});
    slabStart.assign(slabs + 1, 0);
    count = 0;
  }
  void reservePoints() {
    if (!x.empty()) return;
    for (auto* v : {&x, &y, &z}) v->assign(kFlushThreshold + kMaxOrbitsPerBatch, 0.0f);
    rgb.assign(kFlushThreshold + kMaxOrbitsPerBatch, 0);
  }
};

namespace {

// What the classify pass produces besides the colour: the voxel of the point (Nearest), of the
// point moved by a random offset in [-0.5, 0.5) per axis (Jittered: a stochastic trilinear
// deposit), or the exact voxel plus the continuous position for a point sink (Points).
enum class Output { Nearest, Jittered, Points };

// One xorshift32 step (Marsaglia 2003): shifts and xors only, so it vectorises across orbits
// alongside the 32-bit voxel arrays; for a jitter its quality is ample.
[[gnu::always_inline]] inline std::uint32_t xorshift32(std::uint32_t r) {
  r ^= r << 13;
  r ^= r >> 17;
  r ^= r << 5;
  return r;
}

// The top 24 bits as a uniform offset in [-0.5, 0.5): through int32 (not uint32) so the
// conversion to double is one vector instruction.
[[gnu::always_inline]] inline double jitterOffset(std::uint32_t r) {
  return static_cast<double>(static_cast<std::int32_t>(r >> 8)) * 0x1p-24 - 0.5;
}

// What the classify pass needs of a layer, flattened into plain numbers.
struct LayerKernel {
  double m[9];  // attractor → voxel: row-major 3×3
  double o[3];
  double gridSize[3];
  std::int32_t sizeX, sizeXY;
  std::int32_t bricksX, bricksXY;
  std::int32_t colourShift, cellsX, cellsXY, slabShift;
  double escapeRadius;
  // 1 for flows, 0 for maps: a flow's point is placed at a uniformly random spot of its last step,
  // so the orbit is drawn as the continuous curve it samples instead of a dotted stroboscope.
  double alongStep;
  double colorScale;   // mode value × colorScale = gradient position (before clamping to [0, 1])
  double indexDither;  // 1: a colour index takes the next palette entry with the fraction's chance (linear)
  double inversePeriod;
  double axis[3];
  double axisOffset;
  double center[3];
};

LayerKernel makeKernel(const PreparedLayer& layer, const GridGeometry& grid, const ColourLayout& colour, int slabShift,
                       PaletteMode paletteMode) {
  LayerKernel k{};
  k.indexDither = paletteMode == PaletteMode::Linear ? 1.0 : 0.0;
  const glm::dvec3 axisScale = layer.fit.axisScale * layer.fit.scale;
  const glm::dmat3 m =
      layer.fit.rotation * glm::dmat3(glm::dvec3(axisScale.x, 0.0, 0.0), glm::dvec3(0.0, axisScale.y, 0.0),
                                      glm::dvec3(0.0, 0.0, axisScale.z));
  const glm::dvec3 o = layer.fit.gridCenter - m * layer.fit.attractorCenter;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) k.m[3 * r + c] = m[c][r];
    k.o[r] = o[r];
    k.gridSize[r] = static_cast<double>(grid.size[r]);
  }
  k.sizeX = grid.size.x;
  k.sizeXY = grid.size.x * grid.size.y;
  k.bricksX = (grid.size.x + 3) / 4;
  k.bricksXY = k.bricksX * ((grid.size.y + 3) / 4);
  k.colourShift = colour.shift;
  k.cellsX = colour.size.x;
  k.cellsXY = colour.size.x * colour.size.y;
  k.slabShift = slabShift;
  k.escapeRadius = layer.escapeRadius;
  k.alongStep = layer.info && layer.info->kind == AttractorKind::Flow ? 1.0 : 0.0;
  const ColorSettings& color = layer.layer.color;
  const glm::dvec3 axis = glm::normalize(color.axis);
  for (int r = 0; r < 3; ++r) {
    k.axis[r] = axis[r];
    k.center[r] = layer.center[r];
  }
  switch (color.mode) {
    case ColorMode::Speed:
      k.colorScale = color.scale / layer.speedReference;
      break;
    case ColorMode::Curvature:
      k.colorScale = color.scale / layer.curvatureReference;
      break;
    case ColorMode::Time:
      k.colorScale = color.scale;
      break;
    case ColorMode::Axis:
      k.colorScale = color.scale / (layer.axisHigh - layer.axisLow);
      break;
    case ColorMode::Distance:
      k.colorScale = color.scale / layer.distanceReference;
      break;
    case ColorMode::Index:
      // flam3's palette lookup: a colour index c takes entry ⌊256 c⌋ (the last one from 255/256
      // on), not ⌊255 c⌋. Flames put their transforms' colours on entries (c = k/255) of
      // palettes that change from one entry to the next, so the lower entry would give them
      // other colours than the flat view and flam3 show.
      k.colorScale = color.scale * 256.0 / 255.0;
      break;
  }
  k.axisOffset = layer.axisLow;
  k.inversePeriod = 1.0 / color.period;
  return k;
}

// One pass over a batch after it advanced: escape test, colour value, voxel index. Branch-free
// (selects, not jumps), so GCC vectorises it across orbits; the colour mode is a template
// argument so the per-point work has no switch.
// The arrays of an OrbitBatch as __restrict function parameters: GCC honours restrict reliably
// on parameters (not on locals loaded from a struct), and without it the loop does not vectorise.
#define VOXFLAME_CLASSIFY_PARAMS                                                                                      \
  const LayerKernel &kernel, const double *__restrict x, const double *__restrict y, const double *__restrict z,      \
      double *__restrict px, double *__restrict py, double *__restrict pz, double *__restrict sx,                     \
      double *__restrict sy, double *__restrict sz, std::int32_t *__restrict age, std::int32_t *__restrict voxel,     \
      std::int32_t *__restrict colorIndex, std::int32_t *__restrict escaped, std::int32_t *__restrict brick,          \
      std::int32_t *__restrict cell, std::int32_t *__restrict slab, std::uint32_t *__restrict noise,                  \
      float *__restrict gxOut, float *__restrict gyOut, float *__restrict gzOut, const double *__restrict colorCoord, \
      std::size_t count
#define VOXFLAME_CLASSIFY_ARGS                                                                                      \
  kernel, x, y, z, px, py, pz, sx, sy, sz, age, voxel, colorIndex, escaped, brick, cell, slab, noise, gxOut, gyOut, \
      gzOut, colorCoord, count

// One pass over a batch after it advanced: escape test, colour value, voxel index. Bitwise &
// (not &&) and selects keep the body one basic block so it vectorises across orbits; the colour
// mode is a template argument so the per-point work has no switch.
// kTracksStep false: the point's last step (p and s) is neither read nor kept, for a layer that
// never needs it: a chaos game (no flow to draw along its step) coloured by its colour index.
template <ColorMode kMode, Output kOut, bool kTracksStep = true>
[[gnu::always_inline]] inline void classifyBody(VOXFLAME_CLASSIFY_PARAMS) {
  static_assert(kTracksStep || kMode == ColorMode::Index);
  const LayerKernel k = kernel;  // a local copy cannot alias the arrays written below
  for (std::size_t i = 0; i < count; ++i) {
    const double xi = x[i], yi = y[i], zi = z[i];
    const bool finite =
        (std::abs(xi) < k.escapeRadius) & (std::abs(yi) < k.escapeRadius) & (std::abs(zi) < k.escapeRadius);
    const double dx = kTracksStep ? xi - px[i] : 0.0, dy = kTracksStep ? yi - py[i] : 0.0,
                 dz = kTracksStep ? zi - pz[i] : 0.0;
    double value;
    if constexpr (kMode == ColorMode::Speed) {
      value = std::sqrt(dx * dx + dy * dy + dz * dz);
    } else if constexpr (kMode == ColorMode::Curvature) {
      const double cx = dy * sz[i] - dz * sy[i], cy = dz * sx[i] - dx * sz[i], cz = dx * sy[i] - dy * sx[i];
      const double lengths = std::sqrt((dx * dx + dy * dy + dz * dz) * (sx[i] * sx[i] + sy[i] * sy[i] + sz[i] * sz[i]));
      value = std::sqrt(cx * cx + cy * cy + cz * cz) / (lengths + 1e-300);
    } else if constexpr (kMode == ColorMode::Time) {
      const double cycles = static_cast<double>(age[i]) * k.inversePeriod;
      value = cycles - std::floor(cycles);
    } else if constexpr (kMode == ColorMode::Axis) {
      value = xi * k.axis[0] + yi * k.axis[1] + zi * k.axis[2] - k.axisOffset;
    } else if constexpr (kMode == ColorMode::Index) {
      value = colorCoord[i];
    } else {
      const double ex = xi - k.center[0], ey = yi - k.center[1], ez = zi - k.center[2];
      value = std::sqrt(ex * ex + ey * ey + ez * ez);
    }
    double t = value * k.colorScale * 255.0;
    if constexpr (kMode == ColorMode::Index) {
      // flam3's linear palette mode: the entry above with the chance of the fraction. The draw
      // is kept only then, so a step-mode render's jitters stay what they were (a select, no branch).
      const std::uint32_t r = xorshift32(noise[i]);
      noise[i] = k.indexDither > 0.0 ? r : noise[i];
      t += k.indexDither * (jitterOffset(r) + 0.5);
    }
    t = finite ? t : 0.0;
    t = std::min(std::max(t, 0.0), 255.0);
    colorIndex[i] = static_cast<std::int32_t>(t);

    // Where on its last step the point is drawn (flows; 0 for maps and the nearest deposit): a
    // stroboscopic sample of a flow locks onto fixed phases and shows as dots; a uniform spot
    // along each step draws the trajectory itself, with density proportional to time spent.
    double along = 0.0;
    if constexpr (kOut != Output::Nearest) {
      const std::uint32_t r = xorshift32(noise[i]);
      noise[i] = r;
      // Without the step (a chaos game's, alongStep 0) the draw is still taken, so the jitters
      // below stay the same, but nothing is made of it.
      if constexpr (kTracksStep) along = k.alongStep * (jitterOffset(r) + 0.5);
    }
    const double qx = kTracksStep ? xi - along * dx : xi, qy = kTracksStep ? yi - along * dy : yi,
                 qz = kTracksStep ? zi - along * dz : zi;
    const double gx = k.m[0] * qx + k.m[1] * qy + k.m[2] * qz + k.o[0];
    const double gy = k.m[3] * qx + k.m[4] * qy + k.m[5] * qz + k.o[1];
    const double gz = k.m[6] * qx + k.m[7] * qy + k.m[8] * qz + k.o[2];
    double jx = gx, jy = gy, jz = gz;
    if constexpr (kOut == Output::Jittered) {
      // Flooring x + u with u uniform in [-0.5, 0.5) lands in voxel i with probability equal to
      // the tent weight max(0, 1 - |x - (i + 0.5)|): on average the trilinear splat, at the cost
      // of one voxel add. A point that jitters out of the grid counts as outside.
      std::uint32_t r = xorshift32(noise[i]);
      jx += jitterOffset(r);
      r = xorshift32(r);
      jy += jitterOffset(r);
      r = xorshift32(r);
      jz += jitterOffset(r);
      noise[i] = r;
    }
    const bool inGrid = finite & (jx >= 0.0) & (jy >= 0.0) & (jz >= 0.0) & (jx < k.gridSize[0]) & (jy < k.gridSize[1]) &
                        (jz < k.gridSize[2]);
    // Converting only in-range values keeps the float→int conversion defined for NaN and huge ones.
    const auto vi = static_cast<std::int32_t>(inGrid ? jx : 0.0);
    const auto vj = static_cast<std::int32_t>(inGrid ? jy : 0.0);
    const auto vk = static_cast<std::int32_t>(inGrid ? jz : 0.0);
    if constexpr (kOut == Output::Points) {
      // Rounding to float may carry a point just below a voxel's upper face onto it; keep it in
      // [i, i + 1) so the position agrees with the voxel whose mask flag accepted it.
      const float fx = static_cast<float>(inGrid ? gx : 0.0), fy = static_cast<float>(inGrid ? gy : 0.0),
                  fz = static_cast<float>(inGrid ? gz : 0.0);
      const auto ux = static_cast<float>(vi + 1), uy = static_cast<float>(vj + 1), uz = static_cast<float>(vk + 1);
      constexpr float kBelow = 1.0f - 0x1p-24f;
      gxOut[i] = fx < ux ? fx : ux * kBelow;
      gyOut[i] = fy < uy ? fy : uy * kBelow;
      gzOut[i] = fz < uz ? fz : uz * kBelow;
    }
    const bool settled = finite & (age[i] > kTransientSteps);
    if constexpr (kTracksStep) {
      // -1: outside the grid (counted as outside); -2: not a point yet (transient or escaped).
      voxel[i] = settled ? (inGrid ? vi + k.sizeX * vj + k.sizeXY * vk : -1) : -2;
      brick[i] = (vi >> 2) + k.bricksX * (vj >> 2) + k.bricksXY * (vk >> 2);
      const std::int32_t ck = vk >> k.colourShift;
      cell[i] = (vi >> k.colourShift) + k.cellsX * (vj >> k.colourShift) + k.cellsXY * ck;
      slab[i] = ck >> k.slabShift;
    } else {
      // The voxel's coordinates and what the point is, for the integer pass below (in the arrays
      // that pass fills): 2 when settled, plus 1 when in the grid.
      brick[i] = vi;
      cell[i] = vj;
      slab[i] = vk;
      voxel[i] = (settled ? 2 : 0) | (inGrid ? 1 : 0);
    }
    escaped[i] = finite ? 0 : 1;
    if constexpr (kTracksStep) {
      sx[i] = dx;
      sy[i] = dy;
      sz[i] = dz;
      px[i] = xi;
      py[i] = yi;
      pz[i] = zi;
    }
    age[i] += age[i] < kAgeLimit ? 1 : 0;
  }
  // A chaos game's integer indices in a pass of their own: in the loop above, with its doubles, the
  // vectoriser ran out of registers and spilled. An attractor's stay in the loop above, where they
  // cost less than a second pass over the batch (bench accumulate: lorenz 11% fewer points a
  // second split in two).
  if constexpr (kTracksStep) return;
  for (std::size_t i = 0; i < count; ++i) {
    const std::int32_t vi = brick[i], vj = cell[i], vk = slab[i], what = voxel[i];
    // -1: outside the grid (counted as outside); -2: not a point yet (transient or escaped).
    voxel[i] = (what & 2) ? ((what & 1) ? vi + k.sizeX * vj + k.sizeXY * vk : -1) : -2;
    brick[i] = (vi >> 2) + k.bricksX * (vj >> 2) + k.bricksXY * (vk >> 2);
    const std::int32_t ck = vk >> k.colourShift;
    cell[i] = (vi >> k.colourShift) + k.cellsX * (vj >> k.colourShift) + k.cellsXY * ck;
    slab[i] = ck >> k.slabShift;
  }
}

// Built twice: for any x86-64 and for AVX2, picked at run time, so the binary still runs on CPUs
// without AVX2.
template <ColorMode kMode, Output kOut, bool kTracksStep = true>
[[gnu::noinline]] void classifyBaseline(VOXFLAME_CLASSIFY_PARAMS) {
  classifyBody<kMode, kOut, kTracksStep>(VOXFLAME_CLASSIFY_ARGS);
}
#if defined(__x86_64__) && !defined(__AVX2__)
template <ColorMode kMode, Output kOut, bool kTracksStep = true>
[[gnu::target("avx2"), gnu::noinline]] void classifyAvx2(VOXFLAME_CLASSIFY_PARAMS) {
  classifyBody<kMode, kOut, kTracksStep>(VOXFLAME_CLASSIFY_ARGS);
}
#endif

using ClassifyFn = void (*)(VOXFLAME_CLASSIFY_PARAMS);
#undef VOXFLAME_CLASSIFY_PARAMS
#undef VOXFLAME_CLASSIFY_ARGS

void classifyBatch(ClassifyFn classify, const LayerKernel& kernel, OrbitBatch& b) {
  classify(kernel, b.x.data(), b.y.data(), b.z.data(), b.px.data(), b.py.data(), b.pz.data(), b.sx.data(), b.sy.data(),
           b.sz.data(), b.age.data(), b.voxel.data(), b.colorIndex.data(), b.escaped.data(), b.brick.data(),
           b.cell.data(), b.slab.data(), b.noise.data(), b.gx.data(), b.gy.data(), b.gz.data(), b.colorCoord.data(),
           b.x.size());
}

template <Output kOut>
ClassifyFn classifierFor(ColorMode mode, bool chaosGame) {
#if defined(__x86_64__) && !defined(__AVX2__)
  if (cpuHasAvx2()) {
    if (chaosGame && mode == ColorMode::Index) return &classifyAvx2<ColorMode::Index, kOut, false>;
    switch (mode) {
      case ColorMode::Speed:
        return &classifyAvx2<ColorMode::Speed, kOut>;
      case ColorMode::Curvature:
        return &classifyAvx2<ColorMode::Curvature, kOut>;
      case ColorMode::Time:
        return &classifyAvx2<ColorMode::Time, kOut>;
      case ColorMode::Axis:
        return &classifyAvx2<ColorMode::Axis, kOut>;
      case ColorMode::Distance:
        return &classifyAvx2<ColorMode::Distance, kOut>;
      case ColorMode::Index:
        return &classifyAvx2<ColorMode::Index, kOut>;
    }
  }
#endif
  if (chaosGame && mode == ColorMode::Index) return &classifyBaseline<ColorMode::Index, kOut, false>;
  switch (mode) {
    case ColorMode::Speed:
      return &classifyBaseline<ColorMode::Speed, kOut>;
    case ColorMode::Curvature:
      return &classifyBaseline<ColorMode::Curvature, kOut>;
    case ColorMode::Time:
      return &classifyBaseline<ColorMode::Time, kOut>;
    case ColorMode::Axis:
      return &classifyBaseline<ColorMode::Axis, kOut>;
    case ColorMode::Distance:
      return &classifyBaseline<ColorMode::Distance, kOut>;
    case ColorMode::Index:
      return &classifyBaseline<ColorMode::Index, kOut>;
  }
  return &classifyBaseline<ColorMode::Speed, kOut>;
}

// chaosGame: the layer is a chaos game's (whose points are not drawn along their step).
ClassifyFn classifier(ColorMode mode, Output output, bool chaosGame) {
  switch (output) {
    case Output::Nearest:
      return classifierFor<Output::Nearest>(mode, chaosGame);
    case Output::Jittered:
      return classifierFor<Output::Jittered>(mode, chaosGame);
    case Output::Points:
      return classifierFor<Output::Points>(mode, chaosGame);
  }
  return classifierFor<Output::Jittered>(mode, chaosGame);
}

// Branch-free append of every settled point of a step in a brick that touches the mask (a
// 4×4×4-voxel bitmap small enough to stay in L1/L2 drops most outside points here) to out from
// entry n on; the exact test happens at the flush, where the voxel's cell (which carries the
// inside flag) is fetched anyway. Returns the new end; adds the settled points it dropped to
// outside and the escaped orbits to escapes. A function of restrict-qualified arrays, so the
// loop keeps them in registers (the same loop over a batch's vectors reloaded them every point).
// kPainted: a point's colour is its painted true colour where it has one (painted non-null).
// kPrefetch: ask for each kept point's colour cell ahead of the flush (see below): for a chaos game,
// whose points land anywhere in the grid; an attractor's next point lands beside its last, where
// the asking costs more than it saves (bench accumulate: lorenz 11% fewer points a second).
template <bool kPainted, bool kPrefetch>
std::size_t appendSplatsOf(const std::int32_t* __restrict voxel, const std::int32_t* __restrict cell,
                           const std::int32_t* __restrict slab, const std::int32_t* __restrict brick,
                           const std::int32_t* __restrict colorIndex, const std::int32_t* __restrict escaped,
                           const std::uint32_t* __restrict painted, const std::uint32_t* __restrict palette,
                           const std::uint64_t* __restrict bricks, const detail::ColourCell* cells,
                           const std::uint32_t* hits, std::size_t count, Splat* __restrict out, std::size_t n,
                           std::uint64_t& outside, std::int32_t& escapes) {
  std::uint64_t dropped = 0;
  std::int32_t escapedHere = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::int32_t v = voxel[i];
    std::uint32_t rgb = palette[static_cast<std::uint8_t>(colorIndex[i])];
    if constexpr (kPainted) rgb = painted[i] & kRgbPainted ? painted[i] & 0xffffffu : rgb;
    out[n] = Splat{static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(cell[i]),
                   rgb | static_cast<std::uint32_t>(slab[i]) << 24};
    const auto brickIndex = static_cast<std::uint32_t>(brick[i]);
    // Integer arithmetic, not bools: GCC turned the bool form into a bit-test branch, which
    // mispredicts about every other point of a pattern spread over the grid (a flame).
    const std::uint64_t inBrick = (bricks[brickIndex >> 6] >> (brickIndex & 63u)) & 1u;
    const std::uint64_t valid = (static_cast<std::uint32_t>(v) >> 31) ^ 1u;        // v >= 0
    const std::uint64_t settled = (static_cast<std::uint32_t>(v + 1) >> 31) ^ 1u;  // v >= -1
    const std::uint64_t keep = inBrick & valid;
    // The flush adds the point to its colour cell (and its voxel's hits, where they are apart), an
    // access to anywhere in the grid: asked for now, the line comes while the orbits step on, and
    // the flush finds it in the cache. A point not kept asks for the first cell, once.
    if constexpr (kPrefetch) {
      __builtin_prefetch(cells + static_cast<std::uint32_t>(cell[i]) * keep, 1, 3);
      if (hits) __builtin_prefetch(hits + static_cast<std::uint32_t>(v) * keep, 1, 3);
    }
    n += keep;
    dropped += settled & (keep ^ 1u);
    escapedHere += escaped[i];
  }
  outside += dropped;
  escapes += escapedHere;
  return n;
}

}  // namespace

std::size_t accumulatorBytes(const GridGeometry& grid) {
  const ColourLayout colour = ColourLayout::of(grid);
  const std::size_t bricks =
      static_cast<std::size_t>((grid.size.x + 3) / 4) * ((grid.size.y + 3) / 4) * ((grid.size.z + 3) / 4);
  const std::size_t hits = colour.shift == 0 ? 0 : grid.voxelCount() * sizeof(std::uint32_t);
  return hits + colour.cellCount() * sizeof(detail::ColourCell) + bricks / 8;
}

namespace detail {

void FreeHugePages::operator()(void* p) const {
  std::free(p);
}

void* allocateHugePages(std::size_t bytes) {
  constexpr std::size_t kHugePage = std::size_t{2} << 20;
  bytes = std::max<std::size_t>(1, (bytes + kHugePage - 1) / kHugePage) * kHugePage;
  void* memory = std::aligned_alloc(kHugePage, bytes);
  if (!memory) throw std::bad_alloc();
#if defined(__linux__)
  madvise(memory, bytes, MADV_HUGEPAGE);  // a hint: without it (or if refused) 4 KiB pages still work
#endif
  std::memset(memory, 0, bytes);
  return memory;
}

}  // namespace detail

Accumulator::Accumulator(std::shared_ptr<const InsideMask> mask, int threads, std::shared_ptr<CoreBudget> cores)
    : mask_(std::move(mask)), cores_(std::move(cores)) {
  if (!mask_) throw Error("the accumulator needs an inside mask");
  const GridGeometry& g = mask_->geometry;
  const std::size_t voxels = g.voxelCount();
  if (voxels == 0 || voxels >= (std::size_t{1} << 31)) throw Error("the accumulation grid must have 1 to 2^31 voxels");
  colour_ = ColourLayout::of(g);
  gridId_ = nextGridId();
  rowInside_.assign(static_cast<std::size_t>(g.size.y) * g.size.z, 0);
  if (colour_.shift > 0) hits_.allocate(voxels);
  colours_.allocate(colour_.cellCount());
  std::uint32_t* hits = hitsData();
  const auto stride = static_cast<std::size_t>(hitsStride());
  {
    const int bx = (g.size.x + 3) / 4, by = (g.size.y + 3) / 4, bz = (g.size.z + 3) / 4;
    brickBits_.assign((static_cast<std::size_t>(bx) * by * bz + 63) / 64 + 1, 0);
    for (int k = 0; k < g.size.z; ++k)
      for (int j = 0; j < g.size.y; ++j)
        for (int i = 0; i < g.size.x; ++i) {
          const std::size_t v = g.index(i, j, k);
          if (mask_->inside[v]) {
            const auto brick = static_cast<std::size_t>((i / 4) + bx * ((j / 4) + by * (k / 4)));
            brickBits_[brick / 64] |= std::uint64_t{1} << (brick % 64);
            ++insideVoxels_;
            rowInside_[static_cast<std::size_t>(j) + static_cast<std::size_t>(g.size.y) * k] = 1;
          } else {
            hits[v * stride] = kOutsideBit;  // the flag stays for the grid's life; clears keep it
          }
        }
  }
  insideBox_ = insideBox(*mask_);
  while (((colour_.size.z - 1) >> slabShift_) + 1 > kMaxSlabs) ++slabShift_;
  slabCount_ = static_cast<std::size_t>(((colour_.size.z - 1) >> slabShift_) + 1);
  slabMutexes_ = std::make_unique<std::mutex[]>(slabCount_);
  slabGeneration_ = std::make_unique<std::uint64_t[]>(slabCount_);  // generation 0: freshly zeroed
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threadCount_ = threads;
  workerWake_ = std::make_unique<std::condition_variable_any[]>(static_cast<std::size_t>(threads));
  wakeAsked_ = std::make_unique<std::atomic<bool>[]>(static_cast<std::size_t>(threads));
  threads_.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) threads_.emplace_back([this, t](std::stop_token stop) { workerLoop(stop, t); });
}

std::size_t Accumulator::gridBytes() const {
  return accumulatorBytes(mask_->geometry);
}

Accumulator::~Accumulator() {
  // Each worker's wait takes its stop token, and the stop request wakes it.
  for (auto& thread : threads_) thread.request_stop();
  threads_.clear();  // joins
}

void Accumulator::setPattern(const std::vector<PatternLayer>& layers, std::uint64_t seed, WhenEscaping whenEscaping) {
  // Probe outside the lock so running batches are not held up by it.
  std::vector<PreparedLayer> prepared;
  // The probe is this pattern's first work, and tens of milliseconds of it: it takes a core of the
  // shared budget like the workers' batches, ahead of them, instead of adding a runnable thread
  // beside theirs. Let go before the grid lock, so the workers it waits for there can pass on.
  std::vector<PreparedLayer> probed;
  {
    const HeldCore core(cores_.get(), true);
    probed = prepareLayers(layers, *mask_, insideBox_, seed, deepSeeds_.load());
  }
  const std::string problem = escapeProblem(probed);
  prepared = std::move(probed);
  {
    // Readers (batches, snapshots) hold the lock shared almost without pause, and a shared_mutex
    // may let them starve a writer; announcing the change makes them stand aside until it is done.
    patternWriters_.fetch_add(1, std::memory_order_acq_rel);
    std::unique_lock lock(gridMutex_);  // no batch runs and no snapshot copies while we clear
    patternWriters_.fetch_sub(1, std::memory_order_acq_rel);
    patternWriters_.notify_all();  // readers standing aside (waitForPatternChange) take their turn
    const auto anyLayerBounded = [](const std::vector<PreparedLayer>& set) {
      return std::any_of(set.begin(), set.end(), [](const PreparedLayer& l) { return l.bounded; });
    };
    if (whenEscaping == WhenEscaping::KeepLastBounded && !anyLayerBounded(prepared) && anyLayerBounded(layers_) &&
        points_.load() > 0) {
      // The grid, its counts and its layers stay the last bounded pattern's; only the workers stop
      // (a later bounded pattern starts afresh). Nothing new is published, so a view keeps its picture.
      {
        std::lock_guard problemLock(problemMutex_);
        problem_ = problem;
        showingLastBounded_ = true;
      }
      active_ = false;
      lock.unlock();
      notifyWorkChanged();
      return;
    }
    layers_ = std::move(prepared);
    seed_ = seed;
    deposit_ = requestedDeposit_.load();
    paletteMode_ = requestedPaletteMode_.load();
    sink_ = requestedSink_.load();
    {
      std::lock_guard problemLock(problemMutex_);
      problem_ = problem;
      showingLastBounded_ = false;
    }
    iterations_ = 0;  // the cells are cleared slab by slab as they are next touched (makeSlabCurrent)
    points_ = 0;
    for (auto& streamPoints : streamPoints_) streamPoints = 0;
    outside_ = 0;
    escapes_ = 0;
    generationStart_ = nowSeconds();
    active_ = anyLayerBounded(layers_);
    generation_.fetch_add(1, std::memory_order_acq_rel);
    version_.fetch_add(1, std::memory_order_acq_rel);
  }
  notifyWorkChanged();
}

void Accumulator::setChunk(std::uint64_t chunk, bool clearGrid) {
  {
    patternWriters_.fetch_add(1, std::memory_order_acq_rel);
    std::unique_lock lock(gridMutex_);  // no batch runs while the streams change
    patternWriters_.fetch_sub(1, std::memory_order_acq_rel);
    patternWriters_.notify_all();
    chunk_ = chunk;
    for (auto& streamPoints : streamPoints_) streamPoints = 0;
    orbitEpoch_.fetch_add(1, std::memory_order_relaxed);
    if (clearGrid) {
      iterations_ = 0;  // the cells are cleared slab by slab as they are next touched
      points_ = 0;
      outside_ = 0;
      escapes_ = 0;
      generationStart_ = nowSeconds();
      generation_.fetch_add(1, std::memory_order_acq_rel);
    }
    version_.fetch_add(1, std::memory_order_acq_rel);
  }
  notifyWorkChanged();
}

void Accumulator::notifyWorkChanged() {
  // Under the mutex the sleepers check their conditions with: a worker that has just found
  // nothing to do is either not yet waiting (and will see the change) or already asleep (and
  // gets this notification). No wake-up is lost, so nobody needs to poll.
  {
    std::lock_guard lock(wakeMutex_);
    wakeAsked_[0] = true;
    workerWake_[0].notify_one();
    doneSignal_.notify_all();
  }
  progress_.notify();
}

std::uint32_t* Accumulator::hitsData() const {
  return colour_.shift == 0 ? &colours_.data()->count : hits_.data();
}

int Accumulator::slabFirstZ(std::size_t slab) const {
  return std::min(mask_->geometry.size.z, static_cast<int>(slab << slabShift_) << colour_.shift);
}

int Accumulator::slabEndZ(std::size_t slab) const {
  return slabFirstZ(slab + 1);
}

void Accumulator::clearCells() {
  for (std::size_t slab = 0; slab < slabCount_; ++slab) {
    clearSlab(slab);
    slabGeneration_[slab] = generation_.load(std::memory_order_relaxed);
  }
}

void Accumulator::clearSlab(std::size_t slab) {
  const GridGeometry& g = mask_->geometry;
  const std::size_t first = g.index(0, 0, slabFirstZ(slab));
  const std::size_t end = slab + 1 < slabCount_ ? g.index(0, 0, slabEndZ(slab)) : g.voxelCount();
  const std::size_t sliceCells = static_cast<std::size_t>(colour_.size.x) * colour_.size.y;
  const std::size_t firstCell = (slab << slabShift_) * sliceCells;
  const std::size_t endCell = std::min(colours_.size(), ((slab + 1) << slabShift_) * sliceCells);
  detail::ColourCell* colours = colours_.data();
  if (colour_.shift == 0) {
    // The hits are the cells' counts: zeroed with the inside flag kept.
    for (std::size_t c = firstCell; c < endCell; ++c) colours[c] = {0, 0, 0, colours[c].count & kOutsideBit};
    return;
  }
  std::uint32_t* hits = hits_.data();
  for (std::size_t v = first; v < end; ++v) hits[v] &= kOutsideBit;  // zero hits, the inside flag kept
  std::fill(colours + firstCell, colours + endCell, detail::ColourCell{});
}

void Accumulator::makeSlabCurrent(std::size_t slab) {
  // A new generation leaves the old sums in place (setPattern holds the exclusive lock only for
  // a moment, not for a clear of gigabytes); the first writer or snapshot to reach a slab clears
  // it. Called under the slab's mutex and the shared grid lock, so the generation cannot move.
  const std::uint64_t generation = generation_.load(std::memory_order_relaxed);
  if (slabGeneration_[slab] == generation) return;
  clearSlab(slab);
  slabGeneration_[slab] = generation;
}

void Accumulator::setDeposit(Deposit deposit) {
  requestedDeposit_ = deposit;
}

void Accumulator::setPaletteMode(PaletteMode mode) {
  requestedPaletteMode_ = mode;
}

void Accumulator::setPointSink(PointSink* sink) {
  requestedSink_ = sink;
}

void Accumulator::setHeld(bool held) {
  if (held_.exchange(held) != held) notifyWorkChanged();  // steer() repeats it every few frames
}

void Accumulator::setTargetPoints(std::uint64_t target) {
  // The explorer repeats its targets every time it steers; only a change has workers to wake.
  if (targetPoints_.exchange(target) == target) return;
  notifyWorkChanged();
}

bool Accumulator::waitUntilDone(double timeoutSeconds) {
  std::unique_lock lock(wakeMutex_);
  return doneSignal_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds),
                              [&] { return !active_.load() || allStreamsDone(targetPoints_.load()); });
}

bool Accumulator::waitUntilIdle(double timeoutSeconds) {
  std::unique_lock lock(wakeMutex_);
  return doneSignal_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds),
                              [&] { return sleepingWorkers_ == threadCount(); });
}

bool Accumulator::idle() const {
  std::lock_guard lock(wakeMutex_);
  if (sleepingWorkers_ != threadCount()) return false;
  // A worker asked to wake (a change of work) is not asleep for want of work any more.
  for (int thread = 0; thread < threadCount(); ++thread)
    if (wakeAsked_[static_cast<std::size_t>(thread)].load()) return false;
  return true;
}

bool Accumulator::streamDone(int stream, std::uint64_t target) const {
  const std::uint64_t quota = (target + kStreams - 1) / kStreams;
  return target > 0 && streamPoints_[static_cast<std::size_t>(stream)].load() >= quota;
}

bool Accumulator::allStreamsDone(std::uint64_t target) const {
  for (int stream = 0; stream < kStreams; ++stream)
    if (!streamDone(stream, target)) return false;
  return true;
}

AccumulatorStats Accumulator::stats() const {
  AccumulatorStats s;
  s.generation = generation_.load();
  s.iterations = iterations_.load();
  s.points = points_.load();
  s.outside = outside_.load();
  s.escapes = escapes_.load();
  const double elapsed = nowSeconds() - generationStart_.load();
  s.pointsPerSecond = elapsed > 0.0 ? static_cast<double>(s.iterations) / elapsed : 0.0;
  const auto target = targetPoints_.load();
  // A pattern that cannot accumulate is as done as it will get: the explorer may rest on it.
  s.done = !active_.load() || allStreamsDone(target);
  std::lock_guard lock(problemMutex_);
  s.problem = problem_;
  s.showingLastBounded = showingLastBounded_;
  return s;
}

void Accumulator::readSlabsImpl(GridReading& reading, void (*visit)(const GridSlabView&, void*), void* context) const {
  waitForPatternChange();
  std::shared_lock lock(gridMutex_);
  const GridGeometry& g = mask_->geometry;
  reading.geometry = g;
  reading.colour = colour_;
  reading.version = version_.load(std::memory_order_acquire);
  reading.generation = generation_.load(std::memory_order_acquire);
  reading.points = points_.load();
  reading.insideVoxels = insideVoxels_;
  reading.gridId = gridId_;
  const std::size_t sliceCells = static_cast<std::size_t>(colour_.size.x) * colour_.size.y;
  for (std::size_t slab = 0; slab < slabCount_; ++slab) {
    // Workers add into a slab only under its mutex, so each slab is seen consistently.
    std::lock_guard slabLock(slabMutexes_[slab]);
    GridSlabView view;
    view.firstZ = slabFirstZ(slab);
    view.endZ = slabEndZ(slab);
    view.firstColourZ = static_cast<int>(slab << slabShift_);
    view.endColourZ = std::min(colour_.size.z, static_cast<int>((slab + 1) << slabShift_));
    view.hitsStride = hitsStride();
    view.hits = hitsData() + g.index(0, 0, view.firstZ) * static_cast<std::size_t>(view.hitsStride);
    view.colours = colours_.data() + static_cast<std::size_t>(view.firstColourZ) * sliceCells;
    // A slab nobody has written since the pattern changed still holds the old sums: it is empty.
    view.empty = slabGeneration_[slab] != reading.generation;
    view.rowInside = rowInside_.data() + static_cast<std::size_t>(g.size.y) * view.firstZ;
    visit(view, context);
  }
}

void Accumulator::snapshot(VolumeSnapshot& out) const {
  const GridGeometry& g = mask_->geometry;
  out.density.resize(g.voxelCount());
  out.rgba.resize(4 * g.voxelCount());
  float maxDensity = 0.0f;
  const ColourLayout colour = colour_;
  GridReading reading;
  readSlabs(reading, [&](const GridSlabView& slab) {
    for (int k = slab.firstZ; k < slab.endZ; ++k)
      for (int j = 0; j < g.size.y; ++j) {
        const std::uint32_t* hits = slab.hits + g.index(0, j, k - slab.firstZ) * slab.hitsStride;
        const detail::ColourCell* cells =
            slab.colours + static_cast<std::size_t>(colour.size.x) *
                               ((j >> colour.shift) +
                                static_cast<std::size_t>(colour.size.y) * ((k >> colour.shift) - slab.firstColourZ));
        float* density = &out.density[g.index(0, j, k)];
        std::uint8_t* rgba = &out.rgba[4 * g.index(0, j, k)];
        for (int i = 0; i < g.size.x; ++i, rgba += 4) {
          const std::uint32_t count = slab.empty ? 0u : hits[i * slab.hitsStride] & ~kOutsideBit;
          density[i] = static_cast<float>(count);
          maxDensity = std::max(maxDensity, density[i]);
          const detail::ColourCell& cell = cells[i >> colour.shift];
          const std::uint32_t colourPoints = detail::colourPoints(cell);
          if (count == 0 || colourPoints == 0) {
            rgba[0] = rgba[1] = rgba[2] = 0;
          } else {
            rgba[0] = static_cast<std::uint8_t>(std::min<std::uint32_t>(255u, cell.red / colourPoints));
            rgba[1] = static_cast<std::uint8_t>(std::min<std::uint32_t>(255u, cell.green / colourPoints));
            rgba[2] = static_cast<std::uint8_t>(std::min<std::uint32_t>(255u, cell.blue / colourPoints));
          }
          rgba[3] = 255;
        }
      }
  });
  out.geometry = reading.geometry;
  out.version = reading.version;
  out.generation = reading.generation;
  out.points = reading.points;
  out.insideVoxels = reading.insideVoxels;
  out.maxDensity = maxDensity;
}

void Accumulator::sampleDensity(DensitySample& out) const {
  waitForPatternChange();
  std::shared_lock lock(gridMutex_);
  const GridGeometry& g = mask_->geometry;
  const std::size_t voxels = g.voxelCount();
  const std::size_t stride = convergenceSampleStride(voxels);
  const std::uint32_t* hits = hitsData();
  const auto hitsStride = static_cast<std::size_t>(this->hitsStride());
  out.generation = generation_.load(std::memory_order_acquire);
  out.points = points_.load();
  out.hits.clear();
  out.hits.reserve(voxels / stride + 1);
  std::size_t v = 0;
  for (std::size_t slab = 0; slab < slabCount_ && v < voxels; ++slab) {
    const std::size_t end = slab + 1 < slabCount_ ? g.index(0, 0, slabEndZ(slab)) : voxels;
    if (v >= end) continue;
    std::lock_guard slabLock(slabMutexes_[slab]);
    // A slab not yet written in this generation holds an older pattern's hits: it is empty.
    const std::uint32_t keep = slabGeneration_[slab] == out.generation ? ~kOutsideBit : 0u;
    for (; v < end; v += stride) out.hits.push_back(hits[v * hitsStride] & keep);
  }
}

void Accumulator::workerLoop(std::stop_token stop, int threadIndex) {
  // Named for top, perf and the runnable-thread count of `bench explorer`.
  pthread_setname_np(pthread_self(), "vf-accumulate");
  markBatchThread();
  const int threadCount = threadCount_;
  std::vector<int> owned;
  for (int stream = threadIndex; stream < kStreams; stream += threadCount) owned.push_back(stream);
  std::vector<std::vector<OrbitBatch>> batches(kStreams);
  SplatBuffer splats;
  splats.reset(slabCount_);
  std::size_t turn = 0;
  auto nextStream = [&](std::uint64_t target) {
    // Round robin over this thread's streams that still have work.
    for (std::size_t k = 0; k < owned.size(); ++k) {
      const int stream = owned[(turn + k) % owned.size()];
      if (!streamDone(stream, target)) {
        turn = (turn + k + 1) % owned.size();
        return stream;
      }
    }
    return -1;
  };
  // A core of the shared budget is held from one batch to the next while this thread has work, and
  // passed on between batches only to a waiter that goes before it: releasing and taking it again
  // each batch woke a waiter that then found it taken again.
  bool holdingCore = false;
  auto letGoOfCore = [&] {
    if (holdingCore) cores_->release();
    holdingCore = false;
  };
  // A wake-up for the workers after this one, passed on once this one holds a core or has found
  // nothing to do (see workerWake_).
  bool passWakeUp = false;
  auto passWakeUpOn = [&] {
    if (!std::exchange(passWakeUp, false) || threadIndex + 1 >= threadCount) return;
    std::lock_guard lock(wakeMutex_);
    wakeAsked_[threadIndex + 1] = true;
    workerWake_[threadIndex + 1].notify_one();
  };
  while (!stop.stop_requested()) {
    if (wakeAsked_[threadIndex].exchange(false)) passWakeUp = true;
    const int stream = active_.load() && !held_.load() && !owned.empty() ? nextStream(targetPoints_.load()) : -1;
    if (stream < 0) {
      letGoOfCore();
      passWakeUpOn();
      // Nothing left for this thread: say so to waitUntilDone, then sleep until setPattern,
      // setTargetPoints or the stop request wakes it (all notify under wakeMutex_).
      std::unique_lock lock(wakeMutex_);
      ++sleepingWorkers_;  // seen by waitUntilIdle only once the wait below lets go of the lock
      doneSignal_.notify_all();
      workerWake_[threadIndex].wait(lock, stop, [&] {
        if (wakeAsked_[threadIndex].load()) return true;
        if (!active_.load() || held_.load() || owned.empty()) return false;
        const auto target = targetPoints_.load();
        return std::any_of(owned.begin(), owned.end(), [&](int s) { return !streamDone(s, target); });
      });
      --sleepingWorkers_;
      continue;
    }
    if (cores_) {
      // The other accumulator's threads get their turn between batches, when they go first.
      const bool first = coresFirst_.load(std::memory_order_relaxed);
      if (holdingCore)
        cores_->passOn(first);
      else
        cores_->acquire(first);
      holdingCore = true;
    }
    passWakeUpOn();
    runBatch(threadIndex, stream, generation_.load(), batches[static_cast<std::size_t>(stream)], splats);
  }
  letGoOfCore();
}

std::uint64_t Accumulator::flushSplats(SplatBuffer& splats) {
  // Counting sort by slab, so each slab's mutex is taken once per flush.
  const std::size_t count = splats.count;
  const Splat* entries = splats.entries.data();
  std::size_t* start = splats.slabStart.data();
  std::fill(splats.slabStart.begin(), splats.slabStart.end(), 0);
  for (std::size_t e = 0; e < count; ++e) ++start[(entries[e].rgbSlab >> 24) + 1];
  for (std::size_t slab = 0; slab < slabCount_; ++slab) start[slab + 1] += start[slab];
  Splat* sorted = splats.sorted.data();
  for (std::size_t e = 0; e < count; ++e) sorted[start[entries[e].rgbSlab >> 24]++] = entries[e];
  // start[slab] is now the end of that slab's run (and the beginning of the next one's).

  return colour_.shift == 0 ? addSplats<true>(sorted, start) : addSplats<false>(sorted, start);
}

template <bool kHitsInCells>
std::uint64_t Accumulator::addSplats(const Splat* sorted, const std::size_t* slabEnd) {
  constexpr std::size_t kPrefetchDistance = 32;
  std::uint32_t* hits = hits_.data();
  detail::ColourCell* colours = colours_.data();
  std::uint64_t inside = 0;
  std::size_t begin = 0;
  for (std::size_t slab = 0; slab < slabCount_; ++slab) {
    const std::size_t end = slabEnd[slab];
    if (end == begin) continue;
    std::lock_guard lock(slabMutexes_[slab]);
    makeSlabCurrent(slab);
    for (std::size_t e = begin; e < end; ++e) {
      // The adds are independent plain stores, so the CPU overlaps their cache misses;
      // prefetching a few entries ahead hides most of the rest.
      if (e + kPrefetchDistance < end) {
        __builtin_prefetch(&colours[sorted[e + kPrefetchDistance].cell], 1);
        if constexpr (!kHitsInCells) __builtin_prefetch(&hits[sorted[e + kPrefetchDistance].voxel], 1);
      }
      const Splat splat = sorted[e];
      detail::ColourCell& cell = colours[splat.cell];
      std::uint32_t& voxelHits = kHitsInCells ? cell.count : hits[splat.voxel];
      // Branch-free: a voxel outside the mask (flag set) gets zero added, and a colour cell that
      // holds kColourCountLimit points keeps its (long converged) mean.
      const std::uint32_t in = (~voxelHits) >> 31;
      const std::uint32_t colourPoints = kHitsInCells ? voxelHits & ~kOutsideBit : cell.count;
      const std::uint32_t room = in & ((colourPoints - kColourCountLimit) >> 31);
      voxelHits += in;
      cell.red += room * (splat.rgbSlab & 0xffu);
      cell.green += room * ((splat.rgbSlab >> 8) & 0xffu);
      cell.blue += room * ((splat.rgbSlab >> 16) & 0xffu);
      if constexpr (!kHitsInCells) cell.count += room;
      inside += in;
    }
    begin = end;
  }
  return inside;
}

std::uint64_t Accumulator::flushPoints(int threadIndex, std::uint64_t streamId, SplatBuffer& splats) {
  AcceptedPoints points;
  points.stream = streamId;
  points.x = splats.x.data();
  points.y = splats.y.data();
  points.z = splats.z.data();
  points.rgb = splats.rgb.data();
  points.count = splats.pointCount;
  sink_->consume(threadIndex, points);
  splats.pointCount = 0;
  return points.count;
}

void Accumulator::waitForPatternChange() const {
  // Blocks (futex) while a setPattern is waiting for or holding the exclusive lock.
  for (int writers = patternWriters_.load(std::memory_order_acquire); writers > 0;
       writers = patternWriters_.load(std::memory_order_acquire))
    patternWriters_.wait(writers, std::memory_order_acquire);
}

void Accumulator::runBatch(int threadIndex, int stream, std::uint64_t generation, std::vector<OrbitBatch>& batches,
                           SplatBuffer& splats) {
  waitForPatternChange();
  std::shared_lock lock(gridMutex_);
  if (generation != generation_.load()) return;  // a new pattern arrived; pick it up next time
  const GridGeometry& grid = mask_->geometry;
  // The stream's identity across chunks (setChunk): chunk 0's streams are 0..kStreams-1.
  const std::uint64_t streamId = chunk_ * kStreams + static_cast<std::uint64_t>(stream);

  batches.resize(layers_.size());

  double maxWeight = 0.0;
  for (const auto& l : layers_) maxWeight = std::max(maxWeight, l.layer.weight);
  const auto drawn = [&](const PreparedLayer& l) { return l.bounded && l.layer.weight > 0.0 && maxWeight > 0.0; };
  const auto orbitsOf = [](const PreparedLayer& l) { return l.game ? kChaosOrbitsPerBatch : kOrbitsPerBatch; };
  // A batch is as many samples of each layer whatever its orbits: with a chaos game among the
  // layers, every layer takes that many fewer steps (a batch stays as short, for a new pattern to
  // wait on), and the stream's step counts below are in those steps.
  std::size_t mostOrbits = kOrbitsPerBatch;
  for (const auto& l : layers_)
    if (drawn(l)) mostOrbits = std::max(mostOrbits, orbitsOf(l));
  const int stepsPerBatch = static_cast<int>(kStepsPerBatch * kOrbitsPerBatch / mostOrbits);

  std::uint64_t iterations = 0, points = 0, outside = 0, escapes = 0;
  const Output output = sink_ ? Output::Points : deposit_ == Deposit::Nearest ? Output::Nearest : Output::Jittered;
  if (sink_) splats.reservePoints();

  // The last batch a stream needs is cut short in proportion, so a chunk's points overshoot its
  // target by little: a full batch yields up to 32 K points, more than a small chunk's share of a
  // stream. Every layer is cut alike (their weights hold), and the cut depends only on the
  // stream's own history, so the points stay the same whatever the threads.
  double stepFraction = 1.0;
  {
    const std::uint64_t target = targetPoints_.load();
    const std::uint64_t quota = (target + kStreams - 1) / kStreams;
    const std::uint64_t done = streamPoints_[static_cast<std::size_t>(stream)].load();
    const double yield = batches.empty() ? 0.0 : batches.front().pointsPerStep * stepsPerBatch;
    const bool history = yield > 0.0 && batches.front().epoch == orbitEpoch_.load(std::memory_order_relaxed) &&
                         batches.front().generation == generation;
    if (target > 0 && quota > done) {
      const auto remaining = static_cast<double>(quota - done);
      // Without a batch of this chunk behind it, the stream's orbits are fresh: they take their
      // transient first, then yield at most one point a step each.
      // Every layer's orbits add points, each in proportion to its steps.
      double orbitShare = 0.0;
      for (const auto& l : layers_)
        if (drawn(l)) orbitShare += static_cast<double>(orbitsOf(l)) * l.layer.weight / maxWeight;
      orbitShare = std::max(orbitShare, static_cast<double>(kOrbitsPerBatch));
      stepFraction = history
                         ? 1.1 * remaining / yield
                         : (kTransientSteps + 1.1 * remaining / orbitShare + 1.0) / static_cast<double>(stepsPerBatch);
      stepFraction = std::clamp(stepFraction, 1.0 / stepsPerBatch, 1.0);
    }
  }
  bool freshOrbits = false;  // the orbits were (re)seeded this batch: their transient came first
  for (std::size_t li = 0; li < layers_.size(); ++li) {
    const PreparedLayer& layer = layers_[li];
    if (!drawn(layer)) continue;
    OrbitBatch& b = batches[li];
    const std::size_t orbits = orbitsOf(layer);
    const std::uint64_t epoch = orbitEpoch_.load(std::memory_order_relaxed);
    if (b.generation != generation || b.epoch != epoch) {
      // New generation or chunk: restart this thread's orbits from the seed pool, reproducibly.
      freshOrbits = true;
      b.generation = generation;
      b.epoch = epoch;
      b.rng = SplitMix64(mixSeed(seed_, (streamId << 8) + li));
      for (auto* v : {&b.x, &b.y, &b.z, &b.px, &b.py, &b.pz, &b.sx, &b.sy, &b.sz}) v->assign(orbits, 0.0);
      b.age.assign(orbits, 0);
      b.voxel.assign(orbits, -1);
      b.colorIndex.assign(orbits, 0);
      b.escaped.assign(orbits, 0);
      b.brick.assign(orbits, 0);
      b.cell.assign(orbits, 0);
      b.slab.assign(orbits, 0);
      // The jitter has its own random numbers, so the orbits are the same whatever the deposit.
      SplitMix64 noiseSeeds(mixSeed(mixSeed(seed_, 0x6a6974746572ULL), (streamId << 8) + li));
      b.noise.resize(orbits);
      for (auto& n : b.noise) n = static_cast<std::uint32_t>(noiseSeeds.next() >> 32) | 1u;
      for (auto* v : {&b.gx, &b.gy, &b.gz}) v->assign(orbits, 0.0f);
      b.colorCoord.assign(orbits, 0.0);
      if (layer.game) {
        // A chaos game's lanes start anywhere; their transient (kTransientSteps) finds the attractor.
        b.chaos.resize(orbits);
        for (std::size_t i = 0; i < orbits; ++i) layer.game->seedLane(b.chaos, i, b.rng);
      } else {
        // Each orbit starts a hair off its seed: seeds lie along a few probe orbits, and a flow's
        // orbits started on one trajectory would retrace it, phase-shifted, instead of filling the
        // attractor (chaos pulls the hair apart in a few hundred steps). A map needs one too:
        // started on the probe's own points, its orbits retraced the probe's orbits step for step
        // (the same arithmetic), so a render held only the probe's distinct points however many it
        // counted. Against the GPU backend, whose float orbits part, polynomial-b-fan's density
        // differed by 0.18 (relative RMS) at 1.5 M and at 15 M points; with the hair, by 0.05. A map
        // pulls even a hair this fine apart within tens of steps, and a point on a voxel centre
        // keeps to its voxel.
        const double hair = layer.info->kind == AttractorKind::Flow ? 1e-5 : 1e-9;
        for (std::size_t i = 0; i < orbits; ++i) {
          const glm::dvec3 s = layer.seeds[b.rng.next() % layer.seeds.size()];
          b.x[i] = b.px[i] = s.x + hair * (1.0 + std::abs(s.x)) * b.rng.symmetric();
          b.y[i] = b.py[i] = s.y + hair * (1.0 + std::abs(s.y)) * b.rng.symmetric();
          b.z[i] = b.pz[i] = s.z + hair * (1.0 + std::abs(s.z)) * b.rng.symmetric();
        }
      }
    }
    const ChaosGame* game = layer.game.get();
    const AdvanceFn advance = game ? nullptr : layer.info->advance(layer.layer.integrator);
    const double* params = layer.layer.params.data();
    const double h = layer.layer.step;
    // A layer's weight is its share of the iterations, hence of the density it adds.
    const int fullSteps = std::max(1, static_cast<int>(std::lround(stepsPerBatch * layer.layer.weight / maxWeight)));
    const int steps = std::max(1, static_cast<int>(std::ceil(fullSteps * stepFraction)));
    const LayerKernel kernel = makeKernel(layer, grid, colour_, slabShift_, paletteMode_);
    const ClassifyFn classify = classifier(layer.layer.color.mode, output, game != nullptr);
    std::uint32_t packedPalette[256];
    for (std::size_t c = 0; c < 256; ++c)
      packedPalette[c] = std::uint32_t{layer.palette[c].r} | std::uint32_t{layer.palette[c].g} << 8 |
                         std::uint32_t{layer.palette[c].b} << 16;
    // A point's packed colour: its palette entry, or for a flame whose variations paint true colours
    // (coloured by its own colours, ColorMode::Index) the colour painted, when one was. The loops
    // below are built once for each, so a flame without true colours runs the plain lookup.
    const auto paletteColour = [&](std::size_t i) { return packedPalette[static_cast<std::uint8_t>(b.colorIndex[i])]; };
    const std::uint32_t* painted = b.chaos.rgb.data();
    const auto paintedColour = [&](std::size_t i) {
      const std::uint32_t rgb = painted[i];
      return rgb & kRgbPainted ? rgb & 0xffffffu : packedPalette[static_cast<std::uint8_t>(b.colorIndex[i])];
    };
    const bool trueColours = game && game->paintsRgb() && layer.layer.color.mode == ColorMode::Index;
    for (int s = 0; s < steps; ++s) {
      if (game) {
        game->step(b.chaos, b.x.data(), b.y.data(), b.z.data(), b.colorCoord.data(), orbits);
      } else {
        advance(params, h, b.x.data(), b.y.data(), b.z.data(), orbits);
      }
      classifyBatch(classify, kernel, b);
      if (game && game->hidesPoints()) {
        // A point its transform's opacity (or a quaternion slice) hides is not a point at all.
        const std::int32_t* visible = b.chaos.visible.data();
        std::int32_t* voxel = b.voxel.data();
        for (std::size_t i = 0; i < orbits; ++i) voxel[i] = visible[i] ? voxel[i] : -2;
      }
      iterations += orbits;
      std::int32_t escapedHere = 0;
      const auto appendPoints = [&](const auto& colourOf) {
        // Points for the sink: the exact test (the voxel's mask flag) here, since no grid cell is
        // fetched later; branch-free like the grid's append below.
        const std::uint8_t* inside = mask_->inside.data();
        float* outX = splats.x.data();
        float* outY = splats.y.data();
        float* outZ = splats.z.data();
        std::uint32_t* outRgb = splats.rgb.data();
        std::size_t n = splats.pointCount;
        for (std::size_t i = 0; i < orbits; ++i) {
          const std::int32_t v = b.voxel[i];
          outX[n] = b.gx[i];
          outY[n] = b.gy[i];
          outZ[n] = b.gz[i];
          outRgb[n] = colourOf(i);
          // Integer arithmetic for the same reason as the grid's append below: no branch to mispredict.
          const std::uint64_t valid = (static_cast<std::uint32_t>(v) >> 31) ^ 1u;        // v >= 0
          const std::uint64_t settled = (static_cast<std::uint32_t>(v + 1) >> 31) ^ 1u;  // v >= -1
          const std::uint64_t keep = valid & static_cast<std::uint64_t>(inside[v >= 0 ? v : 0] != 0);
          n += keep;
          outside += settled & (keep ^ 1u);
          escapedHere += b.escaped[i];
        }
        splats.pointCount = n;
      };
      if (sink_) {
        if (trueColours)
          appendPoints(paintedColour);
        else
          appendPoints(paletteColour);
        if (splats.pointCount >= kFlushThreshold) points += flushPoints(threadIndex, streamId, splats);
      } else {
        const auto append = trueColours ? &appendSplatsOf<true, true>
                            : game      ? &appendSplatsOf<false, true>
                                        : &appendSplatsOf<false, false>;
        splats.count = append(b.voxel.data(), b.cell.data(), b.slab.data(), b.brick.data(), b.colorIndex.data(),
                              b.escaped.data(), painted, packedPalette, brickBits_.data(), colours_.data(),
                              colour_.shift == 0 ? nullptr : hits_.data(), orbits, splats.entries.data(), splats.count,
                              outside, escapedHere);
      }
      if (escapedHere > 0) [[unlikely]] {
        escapes += static_cast<std::uint64_t>(escapedHere);
        for (std::size_t i = 0; i < orbits; ++i) {
          if (!b.escaped[i]) continue;
          if (game) {
            game->seedLane(b.chaos, i, b.rng);
            b.px[i] = b.chaos.x[i];
            b.py[i] = b.chaos.y[i];
            b.pz[i] = b.chaos.z[i];
            b.sx[i] = b.sy[i] = b.sz[i] = 0.0;
            b.age[i] = 0;
            b.escaped[i] = 0;
            continue;
          }
          const glm::dvec3 seedPoint = layer.seeds[b.rng.next() % layer.seeds.size()];
          const double jitter = 1e-7 * (1.0 + std::abs(seedPoint.x));
          b.x[i] = b.px[i] = seedPoint.x + jitter * b.rng.symmetric();
          b.y[i] = b.py[i] = seedPoint.y;
          b.z[i] = b.pz[i] = seedPoint.z;
          b.sx[i] = b.sy[i] = b.sz[i] = 0.0;
          b.age[i] = 0;
          b.escaped[i] = 0;
        }
      }
      if (splats.count >= kFlushThreshold) {
        const std::uint64_t inside = flushSplats(splats);
        points += inside;
        outside += splats.count - inside;
        splats.count = 0;
      }
    }
  }
  if (splats.pointCount > 0) points += flushPoints(threadIndex, streamId, splats);
  if (splats.count > 0) {
    const std::uint64_t inside = flushSplats(splats);
    points += inside;
    outside += splats.count - inside;
    splats.count = 0;
  }
  // What a step of this stream yields now, its orbits past their transient.
  if (!batches.empty()) {
    const double steps = std::ceil(stepsPerBatch * stepFraction) - (freshOrbits ? kTransientSteps : 0);
    batches.front().pointsPerStep = steps > 0.0 ? static_cast<double>(points) / steps : 0.0;
  }
  iterations_.fetch_add(iterations, std::memory_order_relaxed);
  points_.fetch_add(points, std::memory_order_relaxed);
  streamPoints_[static_cast<std::size_t>(stream)].fetch_add(points, std::memory_order_relaxed);
  outside_.fetch_add(outside, std::memory_order_relaxed);
  escapes_.fetch_add(escapes, std::memory_order_relaxed);
  version_.fetch_add(1, std::memory_order_release);
  progress_.notify();  // once a batch, not a point: nearly free while nobody waits
}

}  // namespace voxflame::core
