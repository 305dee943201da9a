// More of Fractorium's random 2D variations: shapes filled at random (discs in grid cells, hexagonal
// Truchet arcs, rings), depth blurs that grow with the distance from a centre, and random-branch
// powers. Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share). Fractorium writes z = 0 for these
// 2D variations; here z is carried (w z), voxflame's rule, except juliaNab, which keeps z as it is.
//
// Where Fractorium draws its random numbers in one branch only, every lane draws the most any branch
// needs and each branch uses them in Fractorium's order: the loops have fewer branches, the lanes'
// generators advance alike, and the distribution is Fractorium's.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/flame/variations_2d_shared.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// Hugo Elias' integer noise of a cell, in [0, 1]: Fractorium's DiscreteNoise2 (CircleRand's and
// CircleTrans1's), its int arithmetic wrapping around.
inline double cellNoise(std::int32_t x, std::int32_t y) {
  std::uint32_t k = static_cast<std::uint32_t>(wrapAdd(x, wrapMul(y, 57)));
  k = (k << 13) ^ k;
  const std::uint32_t v = k * (k * k * 15731u + 789221u) + 1376312589u;
  return static_cast<double>(v & 0x7fffffffu) * (1.0 / 2147483647.0);
}

// asteria: inside the unit disc (of w p) and outside the four unit discs about (±1, ±1) the point
// is bent (turned by πα, its x scaled by (1 − √(1 − (1 − |y|)²))/√(1 − y²), turned back); elsewhere
// it is kept. Where both discs hold it, it is bent with the chance 0.35. Fractorium's flam3-compatible
// branch (x turned as x cos − y sin) is followed.
VOXFLAME_VARIATION_TARGETS void asteria(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double alpha = fractoriumCyclic(P[0], 0.0, 1.0);
  const double s = std::sin(kPi * alpha), c = std::cos(kPi * alpha);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double x0 = w * x[i], y0 = w * y[i];
    const double r = x0 * x0 + y0 * y0;
    const double ax = std::abs(x0) - 1.0, ay = std::abs(y0) - 1.0;
    const bool inside = r < 1.0, nearCorner = std::sqrt(ax * ax + ay * ay) < 1.0;
    const bool keep = inside && nearCorner ? u > 0.35 : !inside;
    const double xx = x0 * c - y0 * s, yy = x0 * s + y0 * c;
    const double t = 1.0 - std::abs(yy);
    // |yy| < 1 wherever the point is bent (it lies in the unit disc); the guard is for the kept ones.
    const double nx = xx / std::sqrt(std::max(1.0 - yy * yy, kEpsilon)) * (1.0 - std::sqrt(std::max(1.0 - t * t, 0.0)));
    outX[i] += keep ? x0 : nx * c + yy * s;
    outY[i] += keep ? y0 : -nx * s + yy * c;
    outZ[i] += w * z[i];
  }
}

// Circle_Rand: a random cell (X, Y) of the lattice of even integers within ±X/2·2, ±Y/2·2; in the
// cells whose hash is below density, a disc of radius size · hash^power (a second hash) filled
// uniformly. Elsewhere nothing is added (Fractorium leaves the previous variation's output there).
VOXFLAME_VARIATION_TARGETS void circleRandCells(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                                double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sideX = P[0] * 0.5, sideY = P[1] * 0.5, size = std::max(P[2], 0.0), power = P[3];
  const double density = fractoriumClamp(P[4], 0.0, 1.0), seed = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    const double a = laneUniform(rnd[i]) * kTwoPi;
    const double r = std::sqrt(laneUniform(rnd[i]));
    const double cx = 2.0 * (std::floor(laneUniform(rnd[i]) * sideX * 2.0 + 0.5) - sideX);
    const double cy = 2.0 * (std::floor(laneUniform(rnd[i]) * sideY * 2.0 + 0.5) - sideY);
    const double ret = hashShadertoy(cy, cx, seed) < density
                           ? size * r * std::exp(std::log(hashShadertoy(cx, cy, seed)) * power)
                           : 0.0;
    const bool drawn = ret > 0.0;
    outX[i] += drawn ? w * (std::cos(a) * ret + cx) : 0.0;
    outY[i] += drawn ? w * (std::sin(a) * ret + cy) : 0.0;
    outZ[i] += w * z[i];
  }
}

// CircleRand: a random point of [−X, X] × [−Y, Y], redrawn (at most ten times) until it falls in a
// disc of its cell of side 2 Sc: cells whose noise is below Dens hold a disc of radius (0.3 + 0.7
// noise') Sc about their centre.
VOXFLAME_VARIATION_TARGETS void circleRand(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sc = fractoriumNonzero(P[0]), dens = P[1], spanX = P[2], spanY = P[3];
  const double seed = fractoriumInteger(P[4], -2147483647.0, 2147483647.0);
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0, m = 0.0, k = 0.0;
    for (int tries = 1;; ++tries) {
      px = spanX * (1.0 - 2.0 * laneUniform(rnd[i]));
      py = spanY * (1.0 - 2.0 * laneUniform(rnd[i]));
      m = std::floor(0.5 * px / sc);
      k = std::floor(0.5 * py / sc);
      px -= (m * 2.0 + 1.0) * sc;
      py -= (k * 2.0 + 1.0) * sc;
      if (tries > 10) break;
      const bool outside =
          cellNoise(javaInt(m + seed), javaInt(k)) > dens ||
          std::sqrt(px * px + py * py) > (0.3 + 0.7 * cellNoise(javaInt(m + 10.0), javaInt(k + 3.0))) * sc;
      if (!outside) break;
    }
    outX[i] += w * (px + (m * 2.0 + 1.0) * sc);
    outY[i] += w * (py + (k * 2.0 + 1.0) * sc);
    outZ[i] += w * z[i];
  }
}

// CircleTrans1: the point moved half way towards (X, Y); where it falls in one of CircleRand's discs
// (its cell's noise below Dens and within the disc's noisy radius), it is replaced by a random point
// of the circle of a random cell of [−|X|, |X|] × [−|Y|, |Y|] whose noise is below Dens (redrawn at
// most ten times). Every lane draws that point; those outside the discs keep theirs.
VOXFLAME_VARIATION_TARGETS void circleTrans1(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sc = fractoriumZeps(fractoriumNonzero(P[0])), dens = P[1], cx = P[2], cy = P[3];
  const double seed = fractoriumInteger(P[4], -2147483647.0, 2147483647.0);
  const double spanX = std::abs(cx), spanY = std::abs(cy);
  for (std::size_t i = 0; i < n; ++i) {
    double ux = (x[i] - cx) * 0.5 + cx, uy = (y[i] - cy) * 0.5 + cy;
    const double m = std::floor(0.5 * ux / sc), k = std::floor(0.5 * uy / sc);
    const double dx = ux - (m * 2.0 + 1.0) * sc, dy = uy - (k * 2.0 + 1.0) * sc;
    const bool keep = cellNoise(javaInt(m + seed), javaInt(k)) > dens ||
                      std::sqrt(dx * dx + dy * dy) > (0.3 + 0.7 * cellNoise(javaInt(m + 10.0), javaInt(k + 3.0))) * sc;
    // The random circle point (Fractorium's CircleR).
    double rx = 0.0, ry = 0.0, rm = 0.0, rk = 0.0;
    for (int tries = 1;; ++tries) {
      const double px = spanX * (1.0 - 2.0 * laneUniform(rnd[i]));
      const double py = spanY * (1.0 - 2.0 * laneUniform(rnd[i]));
      rm = std::floor(0.5 * px / sc);
      rk = std::floor(0.5 * py / sc);
      const double angle = kTwoPi * laneUniform(rnd[i]);
      const double u = 0.3 + 0.7 * cellNoise(javaInt(rm + 10.0), javaInt(rk + 3.0));
      rx = u * std::cos(angle);
      ry = u * std::sin(angle);
      if (tries > 10 || !(cellNoise(javaInt(rm + seed), javaInt(rk)) > dens)) break;
    }
    ux = keep ? ux : rx + (rm * 2.0 + 1.0) * sc;
    uy = keep ? uy : ry + (rk * 2.0 + 1.0) * sc;
    outX[i] += w * ux;
    outY[i] += w * uy;
    outZ[i] += w * z[i];
  }
}

// cpow2: the complex power p^(c + i d), c + i d = r e^(iπa/2)/divisor, on a random branch: the angle
// φ (in [0, 2π)) plus 2π k, k below ⌊spread⌋, less 2π spread when cos(α/(2 spread)) < 2Ψ − 1, and
// turned by 2π/divisor times a random integer below 32767 (Fractorium's C-rand emulation).
VOXFLAME_VARIATION_TARGETS void cpow2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double divisor = P[2], spread = fractoriumZeps(P[3]);
  const double ang = kTwoPi / divisor;
  const double c = P[0] * std::cos(kPi / 2.0 * P[1]) / divisor, d = P[0] * std::sin(kPi / 2.0 * P[1]) / divisor;
  const double halfC = c / 2.0, halfD = d / 2.0, invSpread = 0.5 / spread, fullSpread = kTwoPi * spread;
  // Fractorium draws k below uint(spread); below 1 that is 0, and its Rand(0) is then any 32-bit
  // integer taken as an int (here from the lane's 24 bits, spread over the same range).
  const double branches = spread >= 1.0 ? std::min(std::floor(spread), 4294967295.0) : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    double a = std::atan2(y[i], x[i]);
    double k = branches >= 1.0 ? std::floor(u * branches) : std::floor(u * 0x1p32) - 0x1p31;
    k += a < 0.0 ? 1.0 : 0.0;
    a += kTwoPi * k;
    if (std::cos(a * invSpread) < laneUniform(rnd[i]) * 2.0 - 1.0) a -= fullSpread;
    const double lnr2 = std::log(x[i] * x[i] + y[i] * y[i]);
    const double r = w * std::exp(halfC * lnr2 - d * a);
    const double t = c * a + halfD * lnr2 + ang * std::floor(laneUniform(rnd[i]) * 32767.0);
    outX[i] += r * std::cos(t);
    outY[i] += r * std::sin(t);
    outZ[i] += w * z[i];
  }
}

// The blur of depth_blur and depth_blur2: a random point of a star of `power` points (its outline
// between radius 1 and `range`), scaled by √Ψ; odd and even half-points are mirrored by `oddSign`
// (the two variations differ there). Returns the offset's length factor and sets its angle.
struct StarShape {
  double length, sinAlpha, cosAlpha, power2, step;
};
inline StarShape starShape(double power, double range) {
  const double alpha0 = kPi / fractoriumZeps(power);
  const double length = std::sqrt(1.0 + range * range - 2.0 * range * std::cos(alpha0));
  const double alpha = std::asin(std::sin(alpha0) * range / fractoriumZeps(length));
  return {length, std::sin(alpha), std::cos(alpha), power * 2.0, kTwoPi / fractoriumZeps(power)};
}
[[gnu::always_inline]] inline double starPoint(const StarShape& s, double oddSign, double u1, double u2,
                                               double& angle) {
  double f = u1 * s.power2;
  const double whole = std::trunc(f);
  f -= whole;
  const double t = f * s.length;
  const double zz = std::sqrt(1.0 + t * t - 2.0 * t * s.cosAlpha);
  const double turn = std::asin(s.sinAlpha * t / fractoriumZeps(zz));
  // C's iangle / 2 and iangle & 1 on the whole part (negative for a negative power).
  angle = s.step * std::trunc(whole / 2.0) + (isOddWhole(whole) ? oddSign : -oddSign) * turn - kPi / 2.0;
  return zz * std::sqrt(u2);
}

// depth_blur: w (p + b), b a random point of the star (starPoint) times blur/10 (r − radius) beyond
// the radius, 0 within.
VOXFLAME_VARIATION_TARGETS void depthBlur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const StarShape star = starShape(P[0], P[1]);
  const double blur = P[2] / 10.0, radius = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]);
    double angle = 0.0;
    const double len = starPoint(star, -1.0, u1, u2, angle);
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double aux = rad > radius ? len * blur * (rad - radius) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// depth_blur2: depth_blur about (x0, y0) with the axes divided by mulx, muly, the blur growing as
// (r − radius)^exp, and the star's half-points mirrored the other way round (Fractorium's).
VOXFLAME_VARIATION_TARGETS void depthBlur2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const StarShape star = starShape(P[0], P[1]);
  const double blur = P[2] / 10.0, radius = P[3], x0 = P[4], y0 = P[5];
  const double invMulX = 1.0 / fractoriumZeps(P[6]), invMulY = 1.0 / fractoriumZeps(P[7]), power = P[8];
  for (std::size_t i = 0; i < n; ++i) {
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]);
    double angle = 0.0;
    const double len = starPoint(star, 1.0, u1, u2, angle);
    const double dx = (x[i] - x0) * invMulX, dy = (y[i] - y0) * invMulY;
    const double rad = std::sqrt(dx * dx + dy * dy);
    const double aux = rad > radius ? len * blur * std::exp(std::log(rad - radius) * power) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// depth_gaussian2: depth_gaussian about (x0, y0), the distance's axes multiplied by mulx², muly² (as
// Fractorium has it: divided by 1/mulx²), the blur growing as (r − radius)^exp. ln(1 − Ψ₁) keeps
// the radius finite where Fractorium's ln Ψ₁ would not be.
VOXFLAME_VARIATION_TARGETS void depthGaussian2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double blur = P[0] / 10.0, radius = P[1], x0 = P[2], y0 = P[3];
  const double invMulX2 = 1.0 / fractoriumZeps(P[4] * P[4]), invMulY2 = 1.0 / fractoriumZeps(P[5] * P[5]);
  const double power = P[6];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(-2.0 * std::log(1.0 - laneUniform(rnd[i])));
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    const double dx = (x[i] - x0) / invMulX2, dy = (y[i] - y0) / invMulY2;
    const double rad = std::sqrt(dx * dx + dy * dy);
    const double aux = rad > radius ? r * blur * std::exp(std::log(rad - radius) * power) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// depth_sine2: depth_sine about (x0, y0) with the axes divided by mulx, muly (Fractorium's
// flam3-compatible form) and the blur growing as (r − radius)^exp.
VOXFLAME_VARIATION_TARGETS void depthSine2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = std::max(P[0], 0.0), blur = P[1] / 10.0, radius = P[2], x0 = P[3], y0 = P[4];
  const double mulX = fractoriumZeps(P[5]), mulY = fractoriumZeps(P[6]), grow = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    const double u = laneUniform(rnd[i]);
    const double r = power == 1.0 ? std::acos(u * 2.0 - 1.0) / kPi
                                  : std::acos(std::exp(std::log(1.0 - u) * power) * 2.0 - 1.0) / kPi;
    const double dx = (x[i] - x0) / mulX, dy = (y[i] - y0) / mulY;
    const double rad = std::sqrt(dx * dx + dy * dy);
    const double aux = rad > radius ? r * blur * std::exp(std::log(rad - radius) * grow) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// GlynnSim2: within radius, a random point of the ring from radius + thickness inwards by γ =
// thickness (2 radius + thickness)/(radius + thickness), between the angles Phi1 and Phi2 (degrees);
// beyond it, w p, or w α² p (α = radius/r) with the chance contrast α^|pow|.
VOXFLAME_VARIATION_TARGETS void glynnSim2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = std::max(P[0], 0.0), thickness = fractoriumClamp(P[1], 0.0, 1.0);
  const double contrast = fractoriumClamp(P[2], 0.0, 1.0), power = std::abs(P[3]);
  const double phi1 = kPi * P[4] / 180.0, delta = kPi * P[5] / 180.0 - phi1;
  const double gamma = thickness * (2.0 * radius + thickness) / fractoriumZeps(radius + thickness);
  for (std::size_t i = 0; i < n; ++i) {
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double ring = radius + thickness - gamma * u1, phi = phi1 + delta * u2;
    const double alpha = std::abs(radius / fractoriumZeps(r));
    const double f = u1 > contrast * std::pow(alpha, power) ? w : w * (alpha * alpha);
    const bool inner = r < radius;
    outX[i] += inner ? w * ring * std::cos(phi) : f * x[i];
    outY[i] += inner ? w * ring * std::sin(phi) : f * y[i];
    outZ[i] += w * z[i];
  }
}

// GlynnSim3: within radius + thickness, a random point of one of two circles, radius₁ = radius +
// thickness (chance γ = radius₁/(radius₁ + radius₂)) or radius₂ = radius²/radius₁; beyond it as
// GlynnSim2. thickness2 is read but not used, as in Fractorium.
VOXFLAME_VARIATION_TARGETS void glynnSim3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], radius1 = P[0] + P[1], contrast = fractoriumClamp(P[3], 0.0, 1.0), power = P[4];
  const double radius2 = radius * radius / fractoriumZeps(radius1);
  const double gamma = radius1 / fractoriumZeps(radius1 + radius2);
  for (std::size_t i = 0; i < n; ++i) {
    // Fractorium's first draw (a ring radius it then discards) is the contrast draw beyond.
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]), u3 = laneUniform(rnd[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double phi = kTwoPi * u2, ring = u3 < gamma ? radius1 : radius2;
    const double alpha = std::abs(radius / fractoriumZeps(r));
    const double f = u1 > contrast * std::pow(alpha, power) ? w : w * (alpha * alpha);
    const bool inner = r < radius1;
    outX[i] += inner ? w * ring * std::cos(phi) : f * x[i];
    outY[i] += inner ? w * ring * std::sin(phi) : f * y[i];
    outZ[i] += w * z[i];
  }
}

// hex_truchet: a random point of a random Truchet arc of a random hexagonal cell: the arc about one
// of the cell's three alternate corners (by the angle), its width set by size, the tile turned by
// 60° where the cell's hash is ½ or more. Fractorium's rounded constants (2.0943, 0.5773, …) kept.
VOXFLAME_VARIATION_TARGETS void hexTruchet(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double size = fractoriumClamp(P[0], -1.0, 1.0), side = P[1], seed = P[2];
  const double oneMinusSize = (1.0 - size) * 0.85;
  const double low = (0.15 + oneMinusSize * 0.5) * (0.15 + oneMinusSize * 0.5);
  const double span = (1.0 - oneMinusSize * 0.5) * (1.0 - oneMinusSize * 0.5) - low, cells = side * 2.0 + 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    const double r = std::sqrt(laneUniform(rnd[i]) * span + low);
    const double cornerX = angle < 2.0943 ? 1.0 : (angle < 4.1887 ? -1.0 : 0.0);
    const double cornerY = angle < 4.1887 ? 0.5773 : -1.1547;
    const double cx = 2.0 * (std::floor(laneUniform(rnd[i]) * cells) - side);
    const double cy = 2.0 * (std::floor(laneUniform(rnd[i]) * cells) - side);
    const double turn = hashShadertoy(cx, cy, seed) < 0.5 ? 0.0 : 1.0471;
    const double c = std::cos(turn), s = std::sin(turn), a = angle + 2.6179 - turn;
    outX[i] += (std::cos(a) * r + cornerX * c + cornerY * s + cx + 0.5 * cy) * w;
    outY[i] += (std::sin(a) * r - cornerX * s + cornerY * c + 0.866 * cy) * w;
    outZ[i] += w * z[i];
  }
}

// juliaNab: a Julia root with the angle atan2(y, |x|^separ) on a random one of |n| branches, the
// radius r^(a/|n|) and b added to both coordinates unweighted; z is kept as it is (an ordinary term
// discards the z of the terms before it, Replaces::Z).
VOXFLAME_VARIATION_TARGETS void juliaNab(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double root = fractoriumZeps(std::abs(P[0])), branches = std::abs(P[0]);
  const double exponent = 1.0 / root / 2.0 * P[1], b = P[2], separ = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double a =
        (std::atan2(y[i], std::pow(std::abs(x[i]), separ)) + kTwoPi * std::floor(laneUniform(rnd[i]) * branches)) /
        root;
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], exponent);
    outX[i] += r * std::cos(a) + b;
    outY[i] += r * std::sin(a) + b;
    outZ[i] += z[i];
  }
}

// crob's frame, from its parameters as Fractorium's Precalc derives it: the edges sorted (equal ones
// become ±1), the half sizes, the corner (x0c, y0c) of the square at the frame's right top, the
// chance of the top and bottom bands (by their share of the frame's size), and the inner borders the
// blur band starts at.
struct CropFrame {
  double top, bottom, left, right, ratio, power;
  bool blur;
  double halfX, halfY, minHalf, x0c, y0c, setProb, topBorder, bottomBorder, leftBorder, rightBorder;
};
inline CropFrame cropFrame(const double* P) {
  CropFrame f{};
  f.top = std::min(P[0], P[1]);
  f.bottom = std::max(P[0], P[1]);
  if (f.top == f.bottom) f.top = -1.0, f.bottom = 1.0;
  f.left = std::min(P[2], P[3]);
  f.right = std::max(P[2], P[3]);
  if (f.left == f.right) f.left = -1.0, f.right = 1.0;
  f.blur = fractoriumInteger(P[4], -2147483647.0, 2147483647.0) != 0.0;
  f.ratio = fractoriumClamp(P[5], 0.0, 1.0);
  f.power = std::max(P[6], 0.0);
  // Fractorium's intervals: |right| − left and |bottom| − top.
  const double intervalX = std::abs(f.right) - f.left, intervalY = std::abs(f.bottom) - f.top;
  f.halfX = intervalX / 2.0;
  f.halfY = intervalY / 2.0;
  f.minHalf = f.halfX > f.halfY ? f.halfY : f.halfX;
  const double x0 = f.right - f.halfX, y0 = f.top + f.halfY;
  f.x0c = f.halfX > f.halfY ? f.right - f.minHalf : x0;
  f.y0c = f.halfX < f.halfY ? f.top + f.minHalf : y0;
  f.setProb = intervalY / (intervalX + intervalY);
  const double inset = f.blur ? f.minHalf * f.ratio : 0.0;
  f.topBorder = f.top + inset;
  f.bottomBorder = f.bottom - inset;
  f.leftBorder = f.left + inset;
  f.rightBorder = f.right - inset;
  return f;
}

// crob: a crop to the frame [left, right] × [top, bottom]. Inside its inner borders the term adds
// nothing; outside them, with blur, a random point of the band between the borders and the frame (its
// depth drawn as Ψ^directBlur ratioBlur, the sides picked by their share of the frame, the corners
// cut along their diagonals), unweighted, and without blur the origin. As an ordinary term it also
// moves the transform's point there, so that the terms after it map the cropped point (linear after
// it gives the crop); a pre_ term sets the point to its result, inside points to the origin, as
// Fractorium's does. The rejection loops are cut at 64 tries (Fractorium's have no limit).
VOXFLAME_VARIATION_TARGETS void crob(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  // The point through plain pointers: in.movableX/Y (the same arrays) is written below.
  const double* px = in.x;
  const double* py = in.y;
  double* moveX = in.stage == VariationStage::Normal ? in.movableX : nullptr;
  double* moveY = in.stage == VariationStage::Normal ? in.movableY : nullptr;
  const CropFrame f = cropFrame(P);
  const double quarter = 0.25 * f.setProb, half = 0.5 * f.setProb, threeQuarters = 0.75 * f.setProb;
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = px[i], yi = py[i];
    const double section = laneUniform(rnd[i]);
    double cx = 0.0, cy = 0.0;
    if (f.blur) {
      if (section < f.setProb) {
        for (int tries = 0; tries < 64; ++tries) {
          cy = f.top + laneUniform(rnd[i]) * f.halfY;
          cx = f.right - std::pow(laneUniform(rnd[i]), f.power) * f.ratio * f.minHalf;
          if (!((cy - f.y0c) / fractoriumZeps(cx - f.x0c) < -1.0)) break;
        }
        cx = section < half ? f.left + f.right - cx : cx;
        cy = section > quarter && section < threeQuarters ? f.bottom + f.top - cy : cy;
      } else {
        for (int tries = 0; tries < 64; ++tries) {
          cx = f.right - laneUniform(rnd[i]) * f.halfX;
          cy = f.top + std::pow(laneUniform(rnd[i]), f.power) * f.ratio * f.minHalf;
          const double gradient = (cy - f.y0c) / fractoriumZeps(cx - f.x0c);
          if (!(gradient <= 0.0 && gradient > -1.0)) break;
        }
        // Fractorium compares with the top and bottom bands' chances here too.
        cy = section > half ? f.bottom + f.top - cy : cy;
        cx = section > quarter && section < threeQuarters ? f.left + f.right - cx : cx;
      }
    }
    const bool outside = xi < f.leftBorder || xi > f.rightBorder || yi < f.topBorder || yi > f.bottomBorder;
    cx = outside ? cx : 0.0;
    cy = outside ? cy : 0.0;
    if (outside && moveX) {
      moveX[i] = cx;
      moveY[i] = cy;
    }
    outX[i] += cx;
    outY[i] += cy;
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractoriumBlursMoreVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  add("asteria",
      "w p kept outside the unit disc (and with the chance 0.65 where it also lies within a unit disc about (±1, ±1)); "
      "otherwise turned by πα, x scaled by (1 − √(1 − (1 − |y|)²))/√(1 − y²), turned back (Fractorium's "
      "flam3-compatible form)",
      k2D, kRandom, &asteria, {{"alpha", 0.0, 0.0, 1.0}});
  add("Circle_Rand",
      "w (c + ρ √Ψ₂ (cos 2πΨ₁, sin 2πΨ₁)), c = 2 (⌊X Ψ₃ + ½⌋ − X/2, ⌊Y Ψ₄ + ½⌋ − Y/2) a random cell, ρ = size "
      "h(c)^power "
      "where the cell's hash h'(c) < density, else nothing (Fractorium's)",
      k2D, kRandom, &circleRandCells,
      {{"X", 10.0, 0.0, 50.0},
       {"Y", 10.0, 0.0, 50.0},
       {"size", 1.0, 0.0, 4.0},
       {"power", 1.0, 0.0, 4.0},
       {"density", 1.0, 0.0, 1.0},
       {"seed", 1.0, 0.0, 100.0}});
  add("CircleRand",
      "w q, q a random point of [−X, X] × [−Y, Y] redrawn (at most 10 times) until it lies in its cell's disc: cells "
      "of "
      "side 2 Sc with noise below Dens hold a disc of radius (0.3 + 0.7 noise') Sc (Fractorium's)",
      k2D, kRandom, &circleRand,
      {{"Sc", 1.0, 0.1, 4.0},
       {"Dens", 0.5, 0.0, 1.0},
       {"X", 10.0, 0.0, 50.0},
       {"Y", 10.0, 0.0, 50.0},
       CatalogueAdder::count("Seed", 0.0, 0.0, 100.0)});
  add("CircleTrans1",
      "w u, u = (p + (X, Y))/2; where u lies in one of CircleRand's discs (cells of side 2 Sc), a random point of the "
      "circle of a random such cell instead (Fractorium's)",
      k2D, kRandom, &circleTrans1,
      {{"Sc", 1.0, 0.1, 4.0},
       {"Dens", 0.5, 0.0, 1.0},
       {"X", 10.0, -50.0, 50.0},
       {"Y", 10.0, -50.0, 50.0},
       CatalogueAdder::count("Seed", 0.0, 0.0, 100.0)});
  add("cpow2",
      "w e^(c L/2 − d α) (cos β, sin β), L = ln r², α = φ + 2πk (k = ⌊Ψ₁ ⌊spread⌋⌋, +1 where φ < 0), less 2π spread "
      "when cos(α/(2 spread)) < 2Ψ₂ − 1, β = c α + d L/2 + 2π ⌊32767 Ψ₃⌋/divisor; c + i d = r e^(iπa/2)/divisor "
      "(Fractorium's)",
      k2D, kRandom, &cpow2,
      {{"r", 1.0, -4.0, 4.0}, {"a", 0.0, -4.0, 4.0}, {"divisor", 1.0, -10.0, 10.0}, {"spread", 1.0, 0.0, 10.0}});
  add("depth_blur",
      "w (p + b), b = blur/10 (r − radius) √Ψ₂ s(Ψ₁) beyond the radius, 0 within; s(Ψ₁) a point of the outline of a "
      "star of power points between the radii range and 1 (Fractorium's)",
      k2D, kRandom, &depthBlur,
      {{"power", 5.0, 1.0, 12.0}, {"range", 0.401623, 0.0, 2.0}, {"blur", 1.0, 0.0, 4.0}, {"radius", 1.0, 0.0, 4.0}});
  add("depth_blur2",
      "depth_blur about (x0, y0) with the axes divided by mulx, muly and the blur growing as (r − radius)^exp, the "
      "star's points mirrored (Fractorium's)",
      k2D, kRandom, &depthBlur2,
      {{"power", 5.0, 1.0, 12.0},
       {"range", 0.401623, 0.0, 2.0},
       {"blur", 1.0, 0.0, 4.0},
       {"radius", 1.0, 0.0, 4.0},
       {"x0", 0.0, -2.0, 2.0},
       {"y0", 0.0, -2.0, 2.0},
       {"mulx", 1.0, 0.0, 4.0},
       {"muly", 1.0, 0.0, 4.0},
       {"exp", 1.0, 0.0, 4.0}});
  add("depth_gaussian2",
      "w (p + b), b = √(−2 ln(1 − Ψ₁)) blur/10 (d − radius)^exp (cos 2πΨ₂, sin 2πΨ₂) beyond the radius, 0 within; d = "
      "|((x − x0) mulx², (y − y0) muly²)| (Fractorium's)",
      k2D, kRandom, &depthGaussian2,
      {{"blur", 1.0, 0.0, 4.0},
       {"radius", 1.0, 0.0, 4.0},
       {"x0", 0.0, -2.0, 2.0},
       {"y0", 0.0, -2.0, 2.0},
       {"mulx", 1.0, 0.0, 4.0},
       {"muly", 1.0, 0.0, 4.0},
       {"exp", 1.0, 0.0, 4.0}});
  add("depth_sine2",
      "w (p + b), b = acos(2u − 1)/π blur/10 (d − radius)^exp (cos 2πΨ₁, sin 2πΨ₁) beyond the radius; u = Ψ₂ for power "
      "1, else (1 − Ψ₂)^power; d = |((x − x0)/mulx, (y − y0)/muly)| (Fractorium's flam3-compatible form)",
      k2D, kRandom, &depthSine2,
      {{"power", 1.0, 0.0, 4.0},
       {"blur", 1.0, 0.0, 4.0},
       {"radius", 1.0, 0.0, 4.0},
       {"x0", 0.0, -2.0, 2.0},
       {"y0", 0.0, -2.0, 2.0},
       {"mulx", 1.0, 0.0, 4.0},
       {"muly", 1.0, 0.0, 4.0},
       {"exp", 1.0, 0.0, 4.0}});
  add("GlynnSim2",
      "within radius, w ρ (cos ψ, sin ψ), ρ = radius + thickness − γ Ψ₁, ψ = Phi1 + (Phi2 − Phi1) Ψ₂ (degrees), γ = "
      "thickness (2 radius + thickness)/(radius + thickness); beyond, w α² p (α = radius/r) when Ψ₁ ≤ contrast "
      "α^|pow|, else w p (Fractorium's)",
      k2D, kRandom, &glynnSim2,
      {{"radius", 1.0, 0.0, 4.0},
       {"thickness", 0.1, 0.0, 1.0},
       {"contrast", 0.5, 0.0, 1.0},
       {"pow", 1.5, 0.0, 4.0},
       {"Phi1", 0.0, -360.0, 360.0},
       {"Phi2", 360.0, -360.0, 360.0}});
  add("GlynnSim3",
      "within radius₁ = radius + thickness, w ρ (cos 2πΨ₂, sin 2πΨ₂), ρ = radius₁ when Ψ₃ < radius₁/(radius₁ + "
      "radius₂), else radius₂ = radius²/radius₁; beyond, w α² p (α = radius/r) when Ψ₁ ≤ contrast α^pow, else w p "
      "(Fractorium's)",
      k2D, kRandom, &glynnSim3,
      {{"radius", 1.0, 0.0, 4.0},
       {"thickness", 0.1, 0.0, 1.0},
       {"thickness2", 0.1, 0.0, 1.0},
       {"contrast", 0.5, 0.0, 1.0},
       {"pow", 1.5, 0.0, 4.0}});
  add("hex_truchet",
      "w (ρ (cos β, sin β) + k + c), a random point of a Truchet arc (ρ² = m + (M − m) Ψ₂ set by size) about the "
      "corner "
      "k of a random hexagonal cell c (Ψ₃, Ψ₄ within ±side) picked by 2πΨ₁, the tile turned by 60° by the cell's hash "
      "(Fractorium's)",
      k2D, kRandom, &hexTruchet, {{"size", 1.0, -1.0, 1.0}, {"side", 1.0, 0.0, 10.0}, {"seed", 1.0, 0.0, 100.0}});
  add("juliaNab",
      "(w r^(a/|n|) (cos β, sin β) + (b, b), z), β = (atan2(y, |x|^separ) + 2π ⌊Ψ |n|⌋)/|n|; z unweighted, replacing "
      "the z of the terms before it (Fractorium's)",
      k3D, kRandom, &juliaNab,
      {{"n", 1.0, -10.0, 10.0}, {"a", 1.0, -4.0, 4.0}, {"b", 1.0, -2.0, 2.0}, {"separ", 1.0, -4.0, 4.0}});
  catalogue.back().replaces = VariationInfo::Replaces::Z;
  add("crob",
      "0 inside the frame's inner borders (the frame [left, right] × [top, bottom] less ratioBlur of its smaller half "
      "size); outside them a random point of the band between, its depth Ψ^directBlur, unweighted (the origin without "
      "blur); an ordinary term also moves the transform's point there for the terms after it (Fractorium's)",
      k2D, kRandom, &crob,
      {{"top", -1.0, -4.0, 4.0},
       {"bottom", 1.0, -4.0, 4.0},
       {"left", -1.0, -4.0, 4.0},
       {"right", 1.0, -4.0, 4.0},
       CatalogueAdder::count("blur", 1.0, 0.0, 1.0),
       {"ratioBlur", 0.5, 0.0, 1.0},
       {"directBlur", 2.0, 0.0, 4.0}});
}

}  // namespace voxflame::core
