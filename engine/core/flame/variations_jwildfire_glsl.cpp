// JWildfire's pattern and escape-time variations that published JWildfire flames use: glsl_apollonian
// (Jesus Sosa's shader port), dc_crackle_wf (crackle coloured by its Voronoi distance) and
// fract_mandelbrot_wf (the escape-time Mandelbrot set of JWildfire's AbstractFractWFFunc).
// Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/flame/noise.h"
#include "core/flame/glsl_pixel.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// JWildfire's Tools.FTOI (rounds half away from 0) of a value its setParameter keeps as an int,
// clamped into [low, high] so that no count can make a loop run for ever; NaN (Java's (int) makes
// it 0) is taken as `nan`.
inline int jwfCount(double value, double low, double high, double nan) {
  return static_cast<int>(std::isnan(value) ? nan : std::clamp(std::round(value), low, high));
}

// ---- glsl_apollonian -----------------------------------------------------------------------------

struct Vec3 {
  double x, y, z;
};
// js.glsl.mat3: built from its three columns, M v = c₀ v_x + c₁ v_y + c₂ v_z, summed as Java does.
struct Mat3 {
  Vec3 c0, c1, c2;
  Vec3 times(const Vec3& v) const {
    return {c0.x * v.x + c1.x * v.y + c2.x * v.z, c0.y * v.x + c1.y * v.y + c2.y * v.z,
            c0.z * v.x + c1.z * v.y + c2.z * v.z};
  }
  Mat3 scaled(double f) const {
    return {{c0.x * f, c0.y * f, c0.z * f}, {c1.x * f, c1.y * f, c1.z * f}, {c2.x * f, c2.y * f, c2.z * f}};
  }
};

// G.rot(s): the rotation by the angles s (x, then y, then z), as the shader builds it.
Mat3 glslRotation(double a, double b, double c) {
  const double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b), sc = std::sin(c),
               cc = std::cos(c);
  return {{cb * cc, -cb * sc, sb},
          {sa * sb * cc + ca * sc, -sa * sb * sc + ca * cc, -sa * cb},
          {-ca * sb * cc + sa * sc, ca * sb * sc + sa * cc, ca * cb}};
}

// What the Apollonian pattern is made of at one time: m = G.rot(t + (1, 2, 3)) with t = time/20, the
// fold's scale k = 1.2 + 0.1 sin(time/10) (kept as the matrix k m that G.app builds) and the zoom f =
// 2 + 0.25 sin(0.3 time) (as the matrix f m).
struct Apollonian {
  Mat3 folded, zoomed;
  explicit Apollonian(double time) {
    const double t = 0.05 * time;
    const Mat3 m = glslRotation(t + 1.0, t + 2.0, t + 3.0);
    folded = m.scaled(1.2 + 0.1 * std::sin(0.1 * time));
    zoomed = m.scaled(2.0 + 0.25 * std::sin(0.3 * time));
  }
  // The colour at uv ∈ [−1, 1]²: v = f m (2 uv, 0) folded 50 times by G.app, v → |k m v / (v·v) · ½ − ½| ·
  // 2 − 1, then 0.6 sin v + 0.5 per channel. A v of length 0 or ∞ makes NaN, which the caller catches.
  Vec3 colour(double u, double v) const {
    Vec3 p = zoomed.times({2.0 * u, 2.0 * v, 0.0});
    for (int k = 0; k < 50; ++k) {
      const double d = p.x * p.x + p.y * p.y + p.z * p.z;
      const Vec3 q = folded.times(p);
      p = {std::abs(q.x / d * 0.5 - 0.5) * 2.0 - 1.0, std::abs(q.y / d * 0.5 - 0.5) * 2.0 - 1.0,
           std::abs(q.z / d * 0.5 - 0.5) * 2.0 - 1.0};
    }
    return {std::sin(p.x) * 0.6 + 0.5, std::sin(p.y) * 0.6 + 0.5, std::sin(p.z) * 0.6 + 0.5};
  }
};

// glsl_apollonian: pixel (i, j) of a resolution × 10⁶ grid drawn at random, the point w (i/resolution −
// ½, j/10⁶ − ½); the pattern's colour at the pixel's centre. JWildfire sets its grid's height from its
// width once, when the variation is made, so a file's "Density Pixels" changes the width alone; so here.
// Gradient 1 makes the colour index r·g (JWildfire leaves it unclamped; the palette lookup clamps);
// Gradient 0 paints the point the RGB colour itself (VariationInput::rgb; JWildfire's dbl2int bytes) and
// leaves the index. A NaN colour (a pixel where the fold divides by 0) leaves the index, and paints black.
VOXFLAME_VARIATION_TARGETS void glslApollonian(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double width = glslPixelColumns(P[0]);
  const bool index = jwfCount(P[3], 0.0, 1.0, 0.0) == 1;
  std::uint32_t* __restrict rgb = index ? nullptr : in.rgb;
  const Apollonian pattern(std::isfinite(P[2]) ? P[2] : 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [pi, pj] = addGlslPixel(rnd[i], width, w, z[i], outX[i], outY[i], outZ[i]);
    if (!index && !rgb) continue;
    const Vec3 c = pattern.colour(2.0 * (pi + 0.5) / width - 1.0, 2.0 * (pj + 0.5) / kGlslPixelRows - 1.0);
    if (rgb) {
      rgb[i] = paintedRgb(static_cast<std::uint32_t>(rgbByte(c.x)), static_cast<std::uint32_t>(rgbByte(c.y)),
                          static_cast<std::uint32_t>(rgbByte(c.z)));
      continue;
    }
    const double grey = c.x * c.y;
    if (grey == grey) colour[i] = grey;
  }
}

// ---- dc_crackle_wf -------------------------------------------------------------------------------

// dc_crackle_wf: crackle (variations_plugins.cpp) whose colour index is its Voronoi distance L · color_scale
// + color_offset, clamped into [0, 1] (NaN, from NaN parameters, taken as 0). With weight 0 JWildfire
// colours by the point itself instead of a random one, and draws nothing; so here.
VOXFLAME_VARIATION_TARGETS void dcCrackleWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = P[0], power = P[1], distort = P[2], scale = P[3], slice = P[4];
  const double colourScale = P[5], colourOffset = P[6];
  for (std::size_t i = 0; i < n; ++i) {
    outZ[i] += w * z[i];
    if (cellsize == 0.0) continue;  // crackle's guard: no cells, nothing drawn or coloured
    double ux = x[i], uy = y[i];
    if (w != 0.0) {
      const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]), c = laneUniform(rnd[i]);
      const double blurred = (a + b) / 2.0 + (c - 0.5) / 4.0;
      const double theta = kTwoPi * laneUniform(rnd[i]);
      ux = blurred * std::sin(theta);
      uy = blurred * std::cos(theta);
    }
    const CrackleStep step = crackleStep(ux, uy, cellsize / 2.0, distort, slice, power, scale);
    const double c = step.distance * colourScale + colourOffset;
    colour[i] = c > 1.0 ? 1.0 : (c >= 0.0 ? c : 0.0);
    outX[i] += w * step.x;
    outY[i] += w * step.y;
  }
}

// ---- fract_mandelbrot_wf -------------------------------------------------------------------------

// The orbit of c = start under z → z^power + c, with JWildfire's bookkeeping: xs and ys are the squares
// of the point before the last step (its bailout test reads them), count the steps taken.
struct MandelbrotOrbit {
  int power = 2;
  double startX = 0.0, startY = 0.0, x = 0.0, y = 0.0, xs = 0.0, ys = 0.0, count = 0.0;

  void start(double x0, double y0) {
    xs = ys = 0.0;
    startX = x = x0;
    startY = y = y0;
    count = 0.0;
  }
  bool escaped() const { return xs + ys >= 4.0; }
  // One step, expanded as JWildfire's iterators expand z² , z³, z⁴ and z⁵ · zⁿ⁻⁵.
  void step() {
    xs = x * x;
    ys = y * y;
    double nx, ny;
    if (power == 2) {
      ny = 2.0 * x * y + startY;
      nx = (xs - ys) + startX;
    } else if (power == 3) {
      nx = xs * x - 3.0 * x * ys + startX;
      ny = 3.0 * xs * y - ys * y + startY;
    } else if (power == 4) {
      nx = xs * xs + ys * ys - 6.0 * xs * ys + startX;
      ny = 4.0 * x * y * (xs - ys) + startY;
    } else {
      double px = x * (xs * xs - 10.0 * xs * ys + 5.0 * ys * ys);
      double py = y * (ys * ys - 10.0 * xs * ys + 5.0 * xs * xs);
      for (int k = 5; k < power; ++k) {
        const double ax = x * px - y * py, ay = x * py + px * y;
        px = ax;
        py = ay;
      }
      nx = px + startX;
      ny = py + startY;
    }
    x = nx;
    y = ny;
    count += 1.0;
  }
  // JWildfire's iterate: steps until the point escapes or maxIter tests have passed; returns the number
  // of tests made (one more than the steps).
  int iterate(double x0, double y0, int maxIter) {
    start(x0, y0);
    int tests = 0;
    while (tests++ < maxIter && !escaped()) step();
    return tests;
  }
};

// The buddhabrot mode's memory per lane: whether an orbit is being drawn, its start, its point, the
// squares, the steps taken and the length of the orbit.
constexpr std::size_t kBuddhabrotState = 9;

struct FractParams {
  int maxIter, power, clipIterMin, clipIterMax, maxClipIter, buddhabrotMinIter;
  double xmin, xmax, ymin, ymax, scalez, scale, offsetx, offsety, offsetz, zFill;
  bool buddhabrot, directColour, logZ, colourOnly;

  explicit FractParams(const double* P)
      : maxIter(jwfCount(P[0], 1.0, 10000.0, 1.0)),
        // z^power costs power − 4 products a step; beyond 64 the set is a blurred disc anyway.
        power(jwfCount(P[6], 2.0, 64.0, 2.0)),
        clipIterMin(jwfCount(P[9], -1e9, 1e9, 0.0)),
        clipIterMax(jwfCount(P[10], -1e9, 1e9, 0.0)),
        maxClipIter(jwfCount(P[11], -1.0, 100.0, 0.0)),
        buddhabrotMinIter(jwfCount(P[12], -1.0, 1e9, 0.0)),
        xmin(P[1]),
        xmax(P[2]),
        ymin(P[3]),
        ymax(P[4]),
        scalez(P[8]),
        scale(P[13]),
        offsetx(P[14]),
        offsety(P[15]),
        offsetz(P[16]),
        zFill(std::clamp(P[17], 0.0, 1.0)),
        buddhabrot(jwfCount(P[5], -1.0, 1.0, 0.0) > 0),
        directColour(jwfCount(P[7], -1.0, 1.0, 0.0) != 0),
        logZ(jwfCount(P[18], 0.0, 1.0, 0.0) == 1),
        colourOnly(jwfCount(P[19], 0.0, 1.0, 0.0) == 1) {}
  double height(double count) const {
    const double t = count / maxIter;
    return scalez / 10.0 * (logZ ? std::log10(1.0 + t) : t) + offsetz;
  }
};

// transformIterate: up to max_clip_iter random starts c in [xmin, xmax] × [ymin, ymax] (or the point
// itself with color_only), the first whose test count n is neither ≥ max_iter + clip_iter_max (for a
// negative clip_iter_max: inside the set) nor ≤ clip_iter_min (for a positive one: far outside) kept;
// none kept: the point is dropped (NaN, the chaos game's escape, where JWildfire hides it).
void fractIterate(const FractParams& f, double px, double py, std::uint32_t& rnd, double w, double& outX, double& outY,
                  double& outZ, double& colour) {
  MandelbrotOrbit orbit;
  orbit.power = f.power;
  double x0 = 0.0, y0 = 0.0;
  int count = 0;
  for (int k = 0; k < f.maxClipIter; ++k) {
    if (f.colourOnly) {
      x0 = px;
      y0 = py;
    } else {
      x0 = (f.xmax - f.xmin) * laneUniform(rnd) + f.xmin;
      y0 = (f.ymax - f.ymin) * laneUniform(rnd) + f.ymin;
    }
    count = orbit.iterate(x0, y0, f.maxIter);
    const bool clipped =
        (f.clipIterMax < 0 && count >= f.maxIter + f.clipIterMax) || (f.clipIterMin > 0 && count <= f.clipIterMin);
    if (!clipped) break;
    if (k == f.maxClipIter - 1) {
      outX = outY = outZ = kNaN;
      return;
    }
  }
  if (!f.colourOnly) {
    outX += f.scale * w * (x0 + f.offsetx);
    outY += f.scale * w * (y0 + f.offsety);
  }
  double height = f.scale * w * f.height(count);
  if (f.zFill > 1e-8 && laneUniform(rnd) < f.zFill) {
    const double below = f.scale * w * f.height(count - 1);
    height = (below - height) * laneUniform(rnd) + height;
  }
  outZ += height;
  if (f.directColour) {
    double c = colour + static_cast<double>(count) / f.maxIter;
    if (c > 1.0) c -= 1.0;
    colour = c < 0.0 ? 0.0 : (c > 1.0 ? 1.0 : c);
  }
}

// transformBuddhabrot: each lane draws an orbit that escapes after more than buddhabrot_min_iter tests
// (up to 250 tries, else the point is dropped), skips its first buddhabrot_min_iter points, and then
// gives one point of it per call until its length is reached; the colour index grows along the orbit.
// JWildfire keeps the orbit in the variation (one per render thread); here each lane keeps its own.
void fractBuddhabrot(const FractParams& f, double* memory, std::uint32_t& rnd, double w, double& outX, double& outY,
                     double& outZ, double& colour) {
  MandelbrotOrbit orbit;
  orbit.power = f.power;
  double length = memory[8];
  if (memory[0] == 0.0) {
    double x0 = 0.0, y0 = 0.0;
    for (int k = 0;; ++k) {
      x0 = (f.xmax - f.xmin) * laneUniform(rnd) + f.xmin;
      y0 = (f.ymax - f.ymin) * laneUniform(rnd) + f.ymin;
      const int tests = orbit.iterate(x0, y0, f.maxIter);
      if (orbit.escaped() && tests > f.buddhabrotMinIter) {
        length = tests;
        break;
      }
      if (k == 249) {
        outX = outY = outZ = kNaN;
        return;
      }
    }
    orbit.start(x0, y0);
    for (int skip = 0; skip < f.buddhabrotMinIter; ++skip) orbit.step();
  } else {
    orbit.startX = memory[1], orbit.startY = memory[2], orbit.x = memory[3], orbit.y = memory[4];
    orbit.xs = memory[5], orbit.ys = memory[6], orbit.count = memory[7];
  }
  orbit.step();
  const bool more = !(orbit.count >= length);
  const double kept[kBuddhabrotState] = {more ? 1.0 : 0.0, orbit.startX, orbit.startY, orbit.x, orbit.y,
                                         orbit.xs,         orbit.ys,     orbit.count,  length};
  std::copy(kept, kept + kBuddhabrotState, memory);
  outX += f.scale * w * (orbit.x + f.offsetx);
  outY += f.scale * w * (orbit.y + f.offsety);
  const double c = colour + orbit.count / length;
  colour = c < 0.0 ? 0.0 : (c > 1.0 ? 1.0 : c);
}

VOXFLAME_VARIATION_TARGETS void fractMandelbrotWf(const VariationInput& in, double* __restrict ox,
                                                  double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const FractParams f(P);
  for (std::size_t i = 0; i < n; ++i) {
    if (f.buddhabrot) {
      double scratch[kBuddhabrotState] = {};
      double* memory = in.state ? in.state + kBuddhabrotState * (in.lanes ? in.lanes[i] : i) : scratch;
      fractBuddhabrot(f, memory, rnd[i], w, outX[i], outY[i], outZ[i], colour[i]);
    } else {
      fractIterate(f, x[i], y[i], rnd[i], w, outX[i], outY[i], outZ[i], colour[i]);
    }
  }
}

}  // namespace

void variation_kernels::addJwildfireGlslVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("glsl_apollonian",
      "w (i/Density Pixels − ½, j/10⁶ − ½), z: pixel i = ⌊Ψ₁ Density Pixels⌋, j = ⌊Ψ₂ 10⁶⌋; Gradient 1: colour index "
      "r·g of Sosa's Apollonian pattern at the pixel (v = f m (2 uv, 0) folded 50 times v → |k m v/(v·v)/2 − ½|·2 − "
      "1, colour 0.6 sin v + ½; m the rotation by time/20 + (1, 2, 3), k = 1.2 + 0.1 sin(time/10), f = 2 + 0.25 "
      "sin(0.3 time)); Gradient 0 paints the point that RGB colour and leaves the index; seed is JWildfire's random "
      "time, which time overrides",
      k2D, kRandom, &glslApollonian,
      {count("Density Pixels", 1000000.0, 100.0, 1000000.0),
       count("seed", 10000.0, 0.0, 10000.0),
       {"time", 0.0, 0.0, 5000.0},
       count("Gradient", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().paintsRgb = true;
  add("dc_crackle_wf",
      "crackle's C + (U − C) L^power·scale / L, z (U random on the blurred disc; with weight 0 the point itself); "
      "colour index L color_scale + color_offset clamped into [0, 1] (JWildfire's)",
      k2D, kRandom, &dcCrackleWf,
      {{"cellsize", 1.0, 0.0, 5.0},
       {"power", 0.2, -2.0, 2.0},
       {"distort", 0.0, -2.0, 2.0},
       {"scale", 1.0, -2.0, 2.0},
       {"z", 0.0, -5.0, 5.0},
       {"color_scale", 0.5, -2.0, 2.0},
       {"color_offset", 0.0, -1.0, 1.0}});
  catalogue.back().directColour = true;
  add("fract_mandelbrot_wf",
      "w scale (c + (offsetx, offsety)), z += w scale (scalez/10 · t + offsetz), t = n/max_iter (log₁₀(1 + t) with "
      "z_logscale; z_fill blends towards n − 1): c = Ψ-uniform in [xmin, xmax] × [ymin, ymax] (color_only: the point, "
      "not moved), redrawn up to max_clip_iter times while its escape count n under z → z^power + c is ≥ max_iter + "
      "clip_iter_max (< 0) or ≤ clip_iter_min (> 0), else dropped; direct_color adds t to the colour index (less 1 "
      "above 1); buddhabrot_mode: each lane walks one escaping orbit, a point a call (JWildfire's)",
      k3D, kRandom, &fractMandelbrotWf,
      {count("max_iter", 100.0, 1.0, 10000.0),
       {"xmin", -2.35, -3.0, 3.0},
       {"xmax", 0.75, -3.0, 3.0},
       {"ymin", -1.2, -3.0, 3.0},
       {"ymax", 1.2, -3.0, 3.0},
       count("buddhabrot_mode", 0.0, 0.0, 1.0),
       count("power", 2.0, 2.0, 64.0),
       count("direct_color", 1.0, 0.0, 1.0),
       {"scalez", 1.0, -10.0, 10.0},
       count("clip_iter_min", 3.0, 0.0, 100.0),
       count("clip_iter_max", -5.0, -100.0, 0.0),
       count("max_clip_iter", 3.0, 0.0, 100.0),
       count("buddhabrot_min_iter", 7.0, 0.0, 100.0),
       {"scale", 4.0, -10.0, 10.0},
       {"offsetx", 0.55, -2.0, 2.0},
       {"offsety", 0.0, -2.0, 2.0},
       {"offsetz", 0.0, -2.0, 2.0},
       {"z_fill", 0.0, 0.0, 1.0},
       count("z_logscale", 0.0, 0.0, 1.0),
       count("color_only", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().laneState = kBuddhabrotState;
}

}  // namespace voxflame::core
