// JWildfire's own variations that flame files in the wild use and the other families lack: dustpoint,
// its pre_-only pre_stabilize, its prepost_ pairs (the inverse map run as a pre_ term, the map as a
// post_ term, see below) and its cut_ shapes.
// Each variation is a kernel below and one row of the table at the end (see variations.h for the
// notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// JWildfire's Tools.FTOI: a parameter rounded half away from 0 (its int parameters are set so).
inline double jwfFtoi(double value) {
  return value > 0.0 ? std::trunc(value + 0.5) : (value < 0.0 ? std::trunc(value - 0.5) : 0.0);
}

// JWildfire's precalculated r = √(x² + y²) + MathLib.SMALL_EPSILON (1e-300).
constexpr double kJwfSmallEpsilon = 1e-300;

// dustpoint (Jesus Sosa after Roger Bagula's curved IFS): one of three maps picked by Ψ₂ — the unit
// vector of the point shifted left, its y negated when Ψ₁ < ½ (half the time), or the point scaled by
// ⅓ and perhaps shifted right by ⅔. JWildfire divides by r unguarded; 1e-300 keeps the origin finite.
VOXFLAME_VARIATION_2D(dustpoint, {
  const double sign = laneUniform(rnd[i]) < 0.5 ? 1.0 : -1.0;
  const double pick = laneUniform(rnd[i]);
  const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]) + kJwfSmallEpsilon;
  double px = x[i] / 3.0, py = y[i] / 3.0;
  if (pick < 0.5) {
    px = x[i] / r - 1.0;
    py = sign * y[i] / r;
  } else if (pick >= 0.75) {
    px += 2.0 / 3.0;
  }
  outX[i] += w * px;
  outY[i] += w * py;
})

// java.util.Random's 48-bit linear congruence (its setSeed, next(bits) and nextDouble), jumped ahead
// in O(log k) so that pre_stabilize's k-th point is found without drawing the ones before it.
constexpr std::uint64_t kJavaMultiplier = 0x5DEECE66DULL, kJavaIncrement = 0xBULL, kJavaMask = (1ULL << 48) - 1;

inline std::uint64_t javaRandomSkip(std::uint64_t state, std::uint64_t steps) {
  std::uint64_t mul = kJavaMultiplier, add = kJavaIncrement;  // one step: s → mul·s + add
  std::uint64_t accMul = 1, accAdd = 0;
  while (steps > 0) {
    if (steps & 1u) {
      accMul = (accMul * mul) & kJavaMask;
      accAdd = (accAdd * mul + add) & kJavaMask;
    }
    add = ((mul + 1) * add) & kJavaMask;
    mul = (mul * mul) & kJavaMask;
    steps >>= 1;
  }
  return (accMul * state + accAdd) & kJavaMask;
}

inline std::uint64_t javaRandomStep(std::uint64_t state) {
  return (state * kJavaMultiplier + kJavaIncrement) & kJavaMask;
}

// The nextDouble() drawn from `state` (two steps: 26 and 27 bits); `state` is advanced.
inline double javaNextDouble(std::uint64_t& state) {
  state = javaRandomStep(state);
  const std::uint64_t high = state >> (48 - 26);
  state = javaRandomStep(state);
  const std::uint64_t low = state >> (48 - 27);
  return static_cast<double>((high << 27) + low) * 0x1p-53;
}

// stabilize (Rick Sidwell's pre_stabilize, a "glitch repellent"): with probability p/1000 (Ψ₁) the
// point jumps to one of n fixed points (Ψ₂ picks which), z = 0; else it is kept. The n points are
// (2u − 1, 2v − 1) from java.util.Random seeded with `seed`, as JWildfire makes them. The weight is
// not applied (JWildfire ignores it). JWildfire also jumps on a thread's first iteration, which the
// chaos game's own start makes moot. With dc the jump also sets the colour index to point k's: ½, ¼, ¾,
// ⅛, ⅜, … (JWildfire's halving sequence: (2(k − 2^L + 1) + 1) / 2^(L+1), L = ⌊log₂(k + 1)⌋).
VOXFLAME_VARIATION_TARGETS void stabilize(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double count = std::max(1.0, std::min(jwfFtoi(P[0]), 2147483647.0));
  const double chance = P[2] / 1000.0;
  const bool dc = std::clamp(jwfFtoi(P[3]), 0.0, 1.0) != 0.0;
  const std::uint64_t seeded =
      (static_cast<std::uint64_t>(static_cast<std::int64_t>(javaInt(jwfFtoi(P[1])))) ^ kJavaMultiplier) & kJavaMask;
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i], pz = z[i];
    if (laneUniform(rnd[i]) < chance) {
      const double k = std::min(std::floor(laneUniform(rnd[i]) * count), count - 1.0);
      std::uint64_t state = javaRandomSkip(seeded, 4 * static_cast<std::uint64_t>(k));
      px = javaNextDouble(state) * 2.0 - 1.0;
      py = javaNextDouble(state) * 2.0 - 1.0;
      pz = 0.0;
      if (dc) {
        const double level = std::floor(std::log2(k + 1.0)), first = std::exp2(level) - 1.0;
        colour[i] = (2.0 * (k - first) + 1.0) / std::exp2(level + 1.0);
      }
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += pz;
  }
}

// ---- prepost_ pairs ----------------------------------------------------------------------------
// JWildfire runs a prepost_ variation twice in its transform: its inverse map on the affine point
// before the other variations (a pre_ term) and its map on their sum after them (a post_ term), so
// the transform's variations act in the map's coordinates. The importer writes such a term as
// pre_prepost_X (the inverse, an entry of its own) and post_prepost_X (the map, entry prepost_X).
// Both replace the point, as pre_/post_ terms do; the weight enters the maps as JWildfire has it.

// prepost_affine: the point scaled by w·scale (a scale of 0 is JWildfire's 1e-8), turned by yaw, pitch
// and roll (degrees), then moved by move; its inverse undoes that. Weight 0 leaves the point.
struct PrepostAffine {
  double sx, sy, sz, mx, my, mz;
  double m[9];  // the rotation, row-major
};

inline double jwfNonZero(double value) {
  return value == 0.0 ? kJwfEpsilon : value;
}

inline PrepostAffine prepostAffine(const double* P) {
  constexpr double kDegree = kPi / 180.0;
  const double sy = std::sin(P[3] * kDegree), cy = std::cos(P[3] * kDegree);
  const double sp = std::sin(P[4] * kDegree), cp = std::cos(P[4] * kDegree);
  const double sr = std::sin(P[5] * kDegree), cr = std::cos(P[5] * kDegree);
  return {jwfNonZero(P[0]),
          jwfNonZero(P[1]),
          jwfNonZero(P[2]),
          P[6],
          P[7],
          P[8],
          {cy * cr - sy * sp * sr, -sy * cr - cy * sp * sr, -cp * sr, sy * cp, cy * cp, -sp, cy * sr + sy * sp * cr,
           cy * sp * cr - sy * sr, cp * cr}};
}

VOXFLAME_VARIATION_TARGETS void prepostAffineForward(const VariationInput& in, double* __restrict ox,
                                                     double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const PrepostAffine a = prepostAffine(P);
  const bool on = w != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double px = w * a.sx * x[i], py = w * a.sy * y[i], pz = w * a.sz * z[i];
    outX[i] += on ? a.m[0] * px + a.m[1] * py + a.m[2] * pz + a.mx : x[i];
    outY[i] += on ? a.m[3] * px + a.m[4] * py + a.m[5] * pz + a.my : y[i];
    outZ[i] += on ? a.m[6] * px + a.m[7] * py + a.m[8] * pz + a.mz : z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void prepostAffineInverse(const VariationInput& in, double* __restrict ox,
                                                     double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const PrepostAffine a = prepostAffine(P);
  const bool on = w != 0.0;
  const double kx = on ? 1.0 / (w * a.sx) : 1.0, ky = on ? 1.0 / (w * a.sy) : 1.0, kz = on ? 1.0 / (w * a.sz) : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] - a.mx, py = y[i] - a.my, pz = z[i] - a.mz;
    // The transpose of the rotation turns it back.
    outX[i] += on ? (a.m[0] * px + a.m[3] * py + a.m[6] * pz) * kx : x[i];
    outY[i] += on ? (a.m[1] * px + a.m[4] * py + a.m[7] * pz) * ky : y[i];
    outZ[i] += on ? (a.m[2] * px + a.m[5] * py + a.m[8] * pz) * kz : z[i];
  }
}

// prepost_circlize: the regular n-gon (turned by `rotation` degrees) pushed onto its circumcircle
// (circlize: r / f) or the circle pulled onto the n-gon (uncirclize: r·f), f = cos(π/n) / cos(α − π/n
// (2⌊nα/2π⌋ + 1)), α = φ − rotation, each blended with the point by the weight (lerp(r, r', w)).
// The post_ map uncirclizes (circlizes when reverse = 1), the pre_ map does the opposite.
inline double circlizeRadius(double x, double y, double w, double sides, double rotation, bool circlize,
                             double& angle) {
  angle = std::atan2(y, x);
  const double r = std::sqrt(x * x + y * y) + kJwfSmallEpsilon;
  const double piN = kPi / sides, a = angle - rotation;
  const double factor = std::cos(piN) / std::cos(a - piN * (2.0 * std::floor(sides * a / kTwoPi) + 1.0));
  const double target = circlize ? r / factor : r * factor;
  return r + (target - r) * w;
}

void prepostCirclize(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz,
                     bool inverse) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = std::clamp(jwfFtoi(P[0]), 3.0, 50.0), rotation = P[1] * kPi / 180.0;
  const bool reverse = std::clamp(jwfFtoi(P[2]), 0.0, 1.0) == 1.0;
  const bool circlize = reverse != inverse;
  for (std::size_t i = 0; i < n; ++i) {
    double angle = 0.0;
    const double r = circlizeRadius(x[i], y[i], w, sides, rotation, circlize, angle);
    outX[i] += r * std::cos(angle);
    outY[i] += r * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void prepostCirclizeForward(const VariationInput& in, double* __restrict ox,
                                                       double* __restrict oy, double* __restrict oz) {
  prepostCirclize(in, ox, oy, oz, false);
}
VOXFLAME_VARIATION_TARGETS void prepostCirclizeInverse(const VariationInput& in, double* __restrict ox,
                                                       double* __restrict oy, double* __restrict oz) {
  prepostCirclize(in, ox, oy, oz, true);
}

// prepost_mobius: the Möbius map w (a ζ + b) / (c ζ + d) (complex a–d, ζ = x + iy); its inverse
// (d ζ − b) / (w (a − c ζ)). Weight 0, or a zero denominator, leaves the point.
VOXFLAME_VARIATION_TARGETS void prepostMobiusForward(const VariationInput& in, double* __restrict ox,
                                                     double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double ra = P[0], rb = P[1], rc = P[2], rd = P[3], ia = P[4], ib = P[5], ic = P[6], id = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double ru = ra * x[i] - ia * y[i] + rb, iu = ra * y[i] + ia * x[i] + ib;
    const double rv = rc * x[i] - ic * y[i] + rd, iv = rc * y[i] + ic * x[i] + id;
    const double d = rv * rv + iv * iv;
    const bool keep = w == 0.0 || d == 0.0;
    const double k = keep ? 0.0 : w / d;
    outX[i] += keep ? x[i] : k * (ru * rv + iu * iv);
    outY[i] += keep ? y[i] : k * (iu * rv - ru * iv);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void prepostMobiusInverse(const VariationInput& in, double* __restrict ox,
                                                     double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double ra = P[0], rb = P[1], rc = P[2], rd = P[3], ia = P[4], ib = P[5], ic = P[6], id = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double ru = rd * x[i] - id * y[i] - rb, iu = rd * y[i] + id * x[i] - ib;
    const double rv = -rc * x[i] + ic * y[i] + ra, iv = -rc * y[i] - ic * x[i] + ia;
    const double d = rv * rv + iv * iv;
    const bool keep = w == 0.0 || d == 0.0;
    const double k = keep ? 0.0 : 1.0 / (w * d);
    outX[i] += keep ? x[i] : k * (ru * rv + iu * iv);
    outY[i] += keep ? y[i] : k * (iu * rv - ru * iv);
    outZ[i] += w * z[i];
  }
}

// ---- JWildfire's cut_ shapes (Jesus Sosa's, after Shadertoy shaders) -----------------------------
// Each keeps the points of a pattern and drops the rest (NaN in x, y and z, the chaos game's escape:
// JWildfire hides them); invert keeps the
// others. In mode 1 (the default) the points are uniform in a square (a blur drawing the pattern), in
// mode 0 the transform's own points are cut. They assign x and y, discarding the terms before them; z is
// carried. The int parameters are clamped and truncated as JWildfire's (int) Tools.limitValue does.

inline double jwfIntParam(double value, double low, double high) {
  return std::trunc(std::clamp(value, low, high));
}
// GLSL's clamp and smoothstep as JWildfire's G writes them (a NaN passes through, as with Java's Math).
inline double jwfClamp(double x, double low, double high) {
  return std::isnan(x) ? x : std::min(std::max(x, low), high);
}
inline double jwfSmoothstep(double edge0, double edge1, double x) {
  const double t = jwfClamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
inline double jwfFract(double x) {
  return x - std::floor(x);
}
// JWildfire's G.atan2: a cheap approximation of atan2(y, x) (within about 0.07 rad), used by these shapes.
inline double jwfFastAtan2(double y, double x) {
  constexpr double kQuarter = kPi / 4.0, kThreeQuarters = 3.0 * kPi / 4.0;
  const double ay = std::abs(y);
  const double angle =
      x >= 0.0 ? kQuarter - kQuarter * ((x - ay) / (x + ay)) : kThreeQuarters - kQuarter * ((x + ay) / (ay - x));
  return y < 0.0 ? -angle : angle;
}

// The point a cut_ shape tests: the transform's (mode 0) or a uniform one in [lo, lo + 2·half)².
inline void cutPoint(bool random, double x, double y, std::uint32_t& state, double lo, double span, double& px,
                     double& py) {
  if (random) {
    px = span * laneUniform(state) + lo;
    py = span * laneUniform(state) + lo;
  } else {
    px = x;
    py = y;
  }
}

// cut_fractal: Kali's "abs(p)/dot(p, p) + c" fractal, iters times from (y, x)·zoom, c = 0.15 (cos(time +
// 1.5), sin(time + 1.8)) − 0.25; the point is dropped where 2 |p·p − 0.01| > ½. Points of mode 1 in
// [−½, ½)².
VOXFLAME_VARIATION_TARGETS void cutFractal(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const bool random = jwfIntParam(P[1], 0.0, 1.0) == 1.0;
  const double time = P[2], iters = jwfIntParam(P[3], 1.0, 100.0), zoom = P[4];
  const bool invert = jwfIntParam(P[5], 0.0, 1.0) == 1.0;
  const double cx = std::cos(time + 1.5) * 0.15 - 0.25, cy = std::sin(time + 1.8) * 0.15 - 0.25;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0;
    cutPoint(random, x[i], y[i], rnd[i], -0.5, 1.0, px, py);
    double ux = py * zoom, uy = px * zoom;
    for (double k = 0.0; k < iters; ++k) {
      const double s = 0.5 / (ux * ux + uy * uy);
      ux = std::abs(ux) * s + cx;
      uy = std::abs(uy) * s + cy;
    }
    const double pattern = std::abs(ux * ux + uy * uy - 0.01) * 2.0;
    const bool drop = invert ? pattern <= 0.5 : pattern > 0.5;
    outX[i] += drop ? kNaN : w * px;
    outY[i] += drop ? kNaN : w * py;
    outZ[i] += drop ? kNaN : w * z[i];
  }
}

// cut_glypho: 30 discs (radius f1·s at 0.4 (cos, sin)(j π/5 + s π/10), j = 0 … 9, of the point scaled by s =
// 1, 1.5, 2) summed as m = f3 Σ smoothstep(f1 s, 0, |p s + offset|) over the point·zoom; kept where
// fract(m f3) ≥ f2. Points of mode 1 in [−½, ½)².
VOXFLAME_VARIATION_TARGETS void cutGlypho(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const bool random = jwfIntParam(P[0], 0.0, 1.0) == 1.0;
  const double zoom = std::clamp(P[1], 0.1, 50.0);
  const bool invert = jwfIntParam(P[2], 0.0, 1.0) == 1.0;
  const double f1 = P[3], f2 = P[4], f3 = P[5];
  // The discs' scales and offsets, stepped as JWildfire steps them (its angle starts at 1e-4 and adds π/5
  // while below 2π).
  struct Disc {
    double scale, dx, dy;
  };
  std::array<Disc, 40> discs{};
  std::size_t count = 0;
  const double step = kPi / 5.0;
  for (double s = 1.0; s < 2.5; s += 0.5)
    for (double a = 0.0001; a < 2.0 * kPi && count < discs.size(); a += step)
      discs[count++] = {s, std::cos(a + s * step * 0.5) * 0.4, std::sin(a + s * step * 0.5) * 0.4};
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0;
    cutPoint(random, x[i], y[i], rnd[i], -0.5, 1.0, px, py);
    const double ux = px * zoom, uy = py * zoom;
    double m = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const double vx = ux * discs[k].scale + discs[k].dx, vy = uy * discs[k].scale + discs[k].dy;
      m += jwfSmoothstep(f1 * discs[k].scale, 0.0, std::sqrt(vx * vx + vy * vy)) * f3;
    }
    const bool on = !(jwfFract(m * f3) < f2);
    const bool drop = invert ? on : !on;
    outX[i] += drop ? kNaN : w * px;
    outY[i] += drop ? kNaN : w * py;
    outZ[i] += drop ? kNaN : w * z[i];
  }
}

// cut_triskel: a triskelion: three arms (the point·zoom + (0, 0.1) turned by 120° each time, shifted by
// (0.03, −0.577)) where 3|A| + fract(β/7 + 0.3) < 2, β the arm's angle (JWildfire's approximate atan2),
// shaded ½ + ½ sin(β + 6.24 · 3|A|); kept where smoothstep(0, 0.1, |shade − ½|) − smoothstep(0.8, 0.9, shade) ≤
// ½. Points of mode 1 in [−1, 1)².
VOXFLAME_VARIATION_TARGETS void cutTriskel(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const bool random = jwfIntParam(P[0], 0.0, 1.0) == 1.0;
  const double zoom = P[1];
  const bool invert = jwfIntParam(P[2], 0.0, 1.0) == 1.0;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0;
    cutPoint(random, x[i], y[i], rnd[i], -1.0, 2.0, px, py);
    double ux = px * zoom, uy = py * zoom + 0.1;
    double shade = 0.0;
    for (int arm = 0; arm < 3; ++arm) {
      const double tx = -0.5 * ux - 0.866 * uy, ty = 0.866 * ux - 0.5 * uy;
      ux = tx;
      uy = ty;
      const double ax = ux + 0.03, ay = uy - 0.577;
      const double l = 3.0 * std::sqrt(ax * ax + ay * ay), b = jwfFastAtan2(ay, ax);
      shade = std::max(shade, l + jwfFract(b / 7.0 + 0.3) < 2.0 ? 0.5 + 0.5 * std::sin(b + 6.24 * l) : 0.0);
    }
    const double pattern = jwfSmoothstep(0.0, 0.1, std::abs(shade - 0.5)) - jwfSmoothstep(0.8, 0.9, shade);
    const bool drop = invert ? pattern <= 0.5 : pattern > 0.5;
    outX[i] += drop ? kNaN : w * px;
    outY[i] += drop ? kNaN : w * py;
    outZ[i] += drop ? kNaN : w * z[i];
  }
}

// cut_web: a web of log-spiral threads: from the point·½, e = (log r, β) (β JWildfire's approximate atan2),
// e + 4 (−β, log r) scaled by 10/2π and shifted by time, each coordinate's distance |mod(·, 2) − 1| − thick
// smoothed over ±d/2, d = log r · 0.05 · 10/2π; the two summed. invert = 1 (the default) keeps the threads
// (sum > 0), 0 the rest. Points of mode 1 in [−1, 1)². seed only moved the time in JWildfire's editor.
VOXFLAME_VARIATION_TARGETS void cutWeb(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double time = P[1];
  const bool random = jwfIntParam(P[2], 0.0, 1.0) == 1.0;
  const double thick = std::clamp(P[3], 0.0, 0.9);
  const bool invert = jwfIntParam(P[4], 0.0, 1.0) == 1.0;
  constexpr double kFac = 10.0 / (2.0 * kPi);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const auto thread = [&](double v, double d) {
    const double m = v * kFac + time;
    return jwfSmoothstep(-0.5 * d, 0.5 * d, std::abs(m - 2.0 * std::floor(m / 2.0) - 1.0) - thick);
  };
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0;
    cutPoint(random, x[i], y[i], rnd[i], -1.0, 2.0, px, py);
    const double ux = px * 0.5, uy = py * 0.5;
    const double l = std::log(std::sqrt(ux * ux + uy * uy)), b = jwfFastAtan2(uy, ux);
    const double d = l * 0.05 * kFac;
    const double pattern = thread(l - 4.0 * b, d) + thread(b + 4.0 * l, d);
    const bool drop = invert ? pattern <= 0.0 : pattern > 0.0;
    outX[i] += drop ? kNaN : w * px;
    outY[i] += drop ? kNaN : w * py;
    outZ[i] += drop ? kNaN : w * z[i];
  }
}

}  // namespace

void variation_kernels::addJwildfireTailVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("dustpoint", "Ψ₂ < ½: (x/r − 1, ±y/r) (− when Ψ₁ ≥ ½); Ψ₂ < ¾: (x/3, y/3); else (x/3 + ⅔, y/3); z (JWildfire's)",
      k2D, kRandom, &dustpoint);
  add("stabilize",
      "the point, except when Ψ₁ < p/1000: point k = ⌊Ψ₂ n⌋ of n fixed points in [−1, 1]² (java.util.Random "
      "seeded with seed), z = 0, and with dc the colour index ½, ¼, ¾, ⅛, … of point k; the weight is not "
      "applied (JWildfire's pre_stabilize)",
      k3D, kRandom, &stabilize,
      {count("n", 4.0, 1.0, 100.0),
       count("seed", 0.0, 0.0, 100000.0),
       {"p", 0.1, 0.0, 10.0},
       count("dc", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  const std::vector<VariationParam> affineParams = {
      {"scale_x", 1.0, -2.0, 2.0}, {"scale_y", 1.0, -2.0, 2.0},   {"scale_z", 1.0, -2.0, 2.0},
      {"yaw", 0.0, -180.0, 180.0}, {"pitch", 0.0, -180.0, 180.0}, {"roll", 0.0, -180.0, 180.0},
      {"move_x", 0.0, -2.0, 2.0},  {"move_y", 0.0, -2.0, 2.0},    {"move_z", 0.0, -2.0, 2.0}};
  add("prepost_affine",
      "R (w sx x, w sy y, w sz z) + move: scaled, turned by yaw, pitch and roll (degrees), moved; the point where "
      "w = 0 (JWildfire's prepost_affine as its post_ half; the importer adds pre_prepost_affine before it)",
      k3D, kFixed, &prepostAffineForward, affineParams);
  add("pre_prepost_affine",
      "the inverse of prepost_affine: Rᵀ (p − move) / (w sx, w sy, w sz); the point where w = 0 (JWildfire's "
      "prepost_affine as its pre_ half)",
      k3D, kFixed, &prepostAffineInverse, affineParams);
  const std::vector<VariationParam> circlizeParams = {
      count("n", 4.0, 3.0, 50.0), {"rotation", 45.0, -180.0, 180.0}, count("reverse", 0.0, 0.0, 1.0)};
  add("prepost_circlize",
      "(lerp(r, r f, w) cos φ, lerp(r, r f, w) sin φ), z (r / f when reverse = 1): the circle onto the n-gon, f = "
      "cos(π/n) / cos(α − π/n (2⌊nα/2π⌋ + 1)), α = φ − rotation° (JWildfire's prepost_circlize as its post_ half; the "
      "importer adds pre_prepost_circlize before it)",
      k2D, kFixed, &prepostCirclizeForward, circlizeParams);
  add("pre_prepost_circlize",
      "(lerp(r, r / f, w) cos φ, lerp(r, r / f, w) sin φ), z (r f when reverse = 1): the n-gon onto the circle, f "
      "as in prepost_circlize (JWildfire's prepost_circlize as its pre_ half)",
      k2D, kFixed, &prepostCirclizeInverse, circlizeParams);
  const std::vector<VariationParam> mobiusParams = {
      {"re_a", 1.0, -2.0, 2.0}, {"re_b", 0.0, -2.0, 2.0}, {"re_c", 0.0, -2.0, 2.0}, {"re_d", 1.0, -2.0, 2.0},
      {"im_a", 0.0, -2.0, 2.0}, {"im_b", 0.0, -2.0, 2.0}, {"im_c", 0.0, -2.0, 2.0}, {"im_d", 0.0, -2.0, 2.0}};
  add("prepost_mobius",
      "w (a ζ + b) / (c ζ + d), z; ζ = x + iy, a = re_a + i im_a, …; the point where w = 0 or the denominator is 0 "
      "(JWildfire's prepost_mobius as its post_ half; the importer adds pre_prepost_mobius before it)",
      k2D, kFixed, &prepostMobiusForward, mobiusParams);
  add("pre_prepost_mobius",
      "(d ζ − b) / (w (a − c ζ)), z: the inverse of prepost_mobius; the point where w = 0 or the denominator is 0 "
      "(JWildfire's prepost_mobius as its pre_ half)",
      k2D, kFixed, &prepostMobiusInverse, mobiusParams);
  add("cut_fractal",
      "w p where Kali's fractal (p ← |p|/(p·p) + c, iters times from (y, x)·zoom, c = 0.15 (cos(time + 1.5), "
      "sin(time + 1.8)) − 0.25) has 2 |p·p − 0.01| ≤ ½ (> ½ when invert), else dropped; p uniform in [−½, ½)² "
      "in mode 1; z (JWildfire's; the terms before it are discarded)",
      k2D, kRandom, &cutFractal,
      {count("seed", 0.0, 0.0, 1000.0),
       count("mode", 1.0, 0.0, 1.0),
       {"time", 0.0, 0.0, 10.0},
       count("iters", 30.0, 1.0, 100.0),
       {"zoom", 1.0, 0.1, 5.0},
       count("invert", 0.0, 0.0, 1.0)});
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("cut_glypho",
      "w p where fract(m f3) ≥ f2 (< f2 when invert), m = f3 Σ smoothstep(f1 s, 0, |s·zoom p + 0.4 (cos, sin)(a + "
      "s π/10)|) over s = 1, 1.5, 2 and ten angles a, else dropped; p uniform in [−½, ½)² in mode 1; z "
      "(JWildfire's; the terms before it are discarded)",
      k2D, kRandom, &cutGlypho,
      {count("mode", 1.0, 0.0, 1.0),
       {"zoom", 1.0, 0.1, 50.0},
       count("invert", 0.0, 0.0, 1.0),
       {"f1", 0.115, 0.0, 1.0},
       {"f2", 0.75, 0.0, 1.0},
       {"f3", 1.5, 0.0, 5.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("cut_triskel",
      "w p where p·zoom is off the triskelion's shaded arms (on them when invert), else dropped; p uniform in "
      "[−1, 1)² in mode 1; z (JWildfire's, with its approximate atan2; the terms before it are discarded)",
      k2D, kRandom, &cutTriskel,
      {count("mode", 1.0, 0.0, 1.0), {"zoom", 1.0, 0.1, 5.0}, count("invert", 0.0, 0.0, 1.0)});
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("cut_web",
      "w p where p/2 is on the web of log-spiral threads (off it when invert = 0), threads of width thick around "
      "|mod(10/2π (e + 4 e⊥) + time, 2) − 1|, e = (log r, β); else dropped; p uniform in [−1, 1)² in mode 1; z "
      "(JWildfire's, with its approximate atan2; seed is not used; the terms before it are discarded)",
      k2D, kRandom, &cutWeb,
      {count("seed", 1000.0, 0.0, 10000.0),
       {"time", 0.0, 0.0, 10.0},
       count("mode", 1.0, 0.0, 1.0),
       {"thick", 0.05, 0.0, 0.9},
       count("invert", 1.0, 0.0, 1.0)});
  catalogue.back().replaces = VariationInfo::Replaces::XY;
}

}  // namespace voxflame::core
