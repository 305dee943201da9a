// Fractorium's blurs and random-drawing 2D variations: shapes filled at random (squares, discs,
// hearts, pixels), random choices between maps, and Julia-like maps with a random branch. Each
// variation is a kernel below and one row of the table at the end (see variations.h for the
// notation and variation_kernels.h for what the files share). Fractorium writes z = 0 for these
// 2D variations; here z is carried (w z), voxflame's rule.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// Fractorium's HashShadertoy (after Chaotica): fract(sin(12.9898 a + 78.233 b + seed) 43758.5453).
inline double shadertoyHash(double a, double b, double seed) {
  const double v = std::sin(a * 12.9898 + b * 78.233 + seed) * 43758.5453;
  return v - std::floor(v);
}

// gaussian: the point plus a Gaussian-like blur of radius w (Ψ₁ + Ψ₂ + Ψ₃ + Ψ₄ − 2) in the
// direction 2πΨ; unlike flam3's gaussian_blur the point itself is added, without the weight
// (Fractorium's).
VOXFLAME_VARIATION_2D(gaussian, {
  const double angle = laneUniform(rnd[i]) * kTwoPi;
  const double r = w * laneGauss(rnd[i]);
  outX[i] += r * std::cos(angle) + x[i];
  outY[i] += r * std::sin(angle) + y[i];
})

// blur_square: a uniform point of the square of side 2w about the origin.
VOXFLAME_VARIATION_2D(blurSquare, {
  outX[i] += 2.0 * w * (laneUniform(rnd[i]) - 0.5);
  outY[i] += 2.0 * w * (laneUniform(rnd[i]) - 0.5);
})

// circleblur: a uniform point of the disc of radius w (radius √Ψ₁, angle 2πΨ₂).
VOXFLAME_VARIATION_2D(circleblur, {
  const double rad = std::sqrt(laneUniform(rnd[i]));
  const double angle = laneUniform(rnd[i]) * kTwoPi;
  outX[i] += w * std::cos(angle) * rad;
  outY[i] += w * std::sin(angle) * rad;
})

// blur_pixelize: the point's cell of a grid of side `size`, filled with a random point of a square
// `scale` cells wide about its centre.
VOXFLAME_VARIATION_TARGETS void blurPixelize(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  // Fractorium keeps size ≥ its machine epsilon.
  const double size = std::max(P[0], kFractoriumEps), inverse = 1.0 / size, v = w * size, scale = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double cx = std::floor(x[i] * inverse), cy = std::floor(y[i] * inverse);
    outX[i] += v * (cx + scale * (laneUniform(rnd[i]) - 0.5) + 0.5);
    outY[i] += v * (cy + scale * (laneUniform(rnd[i]) - 0.5) + 0.5);
    outZ[i] += w * z[i];
  }
}

// blur_heart: a uniform point (u, v) of [−1, 1]², v cut at the heart's outline
// (a |u|^p ± b √|1 − u²| − a) / (|a| + |b|) (± by v's sign), so the cut-off density piles up on it.
VOXFLAME_VARIATION_TARGETS void blurHeart(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = P[0], a = P[1], b = P[2], scale = fractoriumZeps(std::abs(a) + std::abs(b));
  for (std::size_t i = 0; i < n; ++i) {
    const double u = (laneUniform(rnd[i]) - 0.5) * 2.0;
    double v = (laneUniform(rnd[i]) - 0.5) * 2.0;
    const double k = v < 0.0 ? -1.0 : 1.0;
    const double limit = (a * std::pow(std::abs(u), p) + k * b * std::sqrt(std::abs(1.0 - u * u)) - a) / scale;
    v = k > 0.0 ? std::min(v, limit) : std::max(v, limit);
    outX[i] += w * u;
    outY[i] += w * v;
    outZ[i] += w * z[i];
  }
}

// d_spherical: spherical with the chance spherical_weight, linear otherwise. Fractorium calls the
// parameter d_spherical_weight, which the importer reads (a preset's "weight" is the term's own).
VOXFLAME_VARIATION_TARGETS void dSpherical(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double chance = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double f = laneUniform(rnd[i]) < chance ? w / fractoriumZeps(r2) : w;
    outX[i] += f * x[i];
    outY[i] += f * y[i];
    outZ[i] += w * z[i];
  }
}

// juliaq: r^(divisor/power) at the angle (φ divisor + 2πk)/power, k a random integer below 32767
// (Fractorium's C-rand emulation), so every branch of the root is taken.
VOXFLAME_VARIATION_TARGETS void juliaq(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = fractoriumZeps(P[0]), divisor = P[1];
  const double inverse = divisor / power, halfInverse = 0.5 * inverse, branch = kTwoPi / power;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::floor(laneUniform(rnd[i]) * 32767.0);
    const double a = std::atan2(y[i], x[i]) * inverse + k * branch;
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], halfInverse);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// Juliac: the complex power z^(1/re + i im/100) with the modulus's logarithm scaled by dist, on a
// random branch: the angle φ + 2π (k mod re), k a random integer (Fractorium's 32-bit draw; here 24
// bits, the same spread of branches).
VOXFLAME_VARIATION_TARGETS void juliac(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double reInverse = 1.0 / fractoriumZeps(P[0]), re = 1.0 / reInverse;
  const double im = 0.01 * P[1], halfDist = 0.5 * P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::floor(laneUniform(rnd[i]) * 0x1p24);
    const double arg = std::atan2(y[i], x[i]) + std::fmod(k, re) * kTwoPi;
    const double lnmod = halfDist * std::log(x[i] * x[i] + y[i] * y[i]);
    const double angle = arg * reInverse + lnmod * im;
    const double mod = std::exp(lnmod * reInverse - arg * im);
    outX[i] += w * mod * std::cos(angle);
    outY[i] += w * mod * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

// coth_spiral: a random point t of the curve (−sinh t, sin(a t)) / (cos(a t) − cosh t),
// t = 2π (Ψ − ½): the spiral of coth's poles.
VOXFLAME_VARIATION_TARGETS void cothSpiral(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (laneUniform(rnd[i]) - 0.5) * kTwoPi;
    const double aux = fractoriumZeps(std::cos(a * t) - std::cosh(t));
    outX[i] += w * (-std::sinh(t) / aux);
    outY[i] += w * (std::sin(a * t) / aux);
    outZ[i] += w * z[i];
  }
}

// depth_gaussian: w (p + b), b a Gaussian blur (Box–Muller radius √(−2 ln Ψ₁), angle 2πΨ₂) times
// blur/10 and the distance beyond `radius`, so points inside the radius stay sharp. Fractorium
// draws only outside; here every lane draws (with ln(1 − Ψ₁), finite), so the loop has no branch.
VOXFLAME_VARIATION_TARGETS void depthGaussian(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double blur = P[0] / 10.0, radius = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(-2.0 * std::log(1.0 - laneUniform(rnd[i])));
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double aux = rad > radius ? r * blur * (rad - radius) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// depth_ngon: depth_gaussian's blur (beyond `radius`, growing with the distance) shaped as a regular
// polygon of `power` sides: the radius 1/cos of the angle from the nearest side's middle. Every lane
// draws its Ψ, as in depth_gaussian.
VOXFLAME_VARIATION_TARGETS void depthNgon(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double side = kTwoPi / fractoriumZeps(P[0]), halfSide = side / 2.0, blur = P[1] / 10.0, radius = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    double phi = angle - side * std::floor(angle / fractoriumZeps(side));
    phi = phi > halfSide ? phi - side : phi;
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double stretch = 1.0 / fractoriumZeps(std::cos(phi));
    const double aux = rad > radius ? stretch * blur * (rad - radius) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// depth_sine: depth_gaussian's blur with the radius acos(2u − 1)/π, u = (1 − Ψ)^power (Ψ itself
// for power 1, as Fractorium has it).
VOXFLAME_VARIATION_TARGETS void depthSine(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = std::max(P[0], 0.0), blur = P[1] / 10.0, radius = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    const double u = laneUniform(rnd[i]);
    const double r = power == 1.0 ? std::acos(u * 2.0 - 1.0) / kPi
                                  : std::acos(std::exp(std::log(1.0 - u) * power) * 2.0 - 1.0) / kPi;
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double aux = rad > radius ? r * blur * (rad - radius) : 0.0;
    outX[i] += w * (x[i] + aux * std::cos(angle));
    outY[i] += w * (y[i] + aux * std::sin(angle));
    outZ[i] += w * z[i];
  }
}

// bTransform: bipolar coordinates (τ, σ) of p about the foci ±1, τ divided by power and moved by
// move, σ turned by rotate, divided by power and put on a random one of the power branches
// (⌊Ψ power⌋), τ pushed apart by split on the two half-planes, and mapped back.
VOXFLAME_VARIATION_TARGETS void bTransform(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  // Fractorium keeps power in [1, 2³¹ − 1] (its default 0 becomes 1).
  const double rotate = P[0], power = std::clamp(P[1], 1.0, 2147483647.0), move = P[2], split = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double xp1 = x[i] + 1.0, y2 = y[i] * y[i];
    double tau = 0.5 * (std::log(xp1 * xp1 + y2) - std::log((x[i] - 1.0) * (x[i] - 1.0) + y2)) / power + move;
    double sigma = kPi - std::atan2(y[i], xp1) - std::atan2(y[i], 1.0 - x[i]) + rotate;
    sigma = sigma / power + kTwoPi / power * std::floor(laneUniform(rnd[i]) * power);
    tau += x[i] >= 0.0 ? split : -split;
    const double d = fractoriumZeps(std::cosh(tau) - std::cos(sigma));
    outX[i] += w * std::sinh(tau) / d;
    outY[i] += w * std::sin(sigma) / d;
    outZ[i] += w * z[i];
  }
}

// boarders2: the point's offset from its rounded (unit) cell centre scaled by |c|; with the chance
// |c| (1 + |right|) (Ψ below it) pushed out by |c| |left| towards the cell's border along the larger
// offset. The ratio of the offsets is guarded where both are 0 (Fractorium's 0/0).
VOXFLAME_VARIATION_TARGETS void boarders2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c = fractoriumZeps(std::abs(P[0])), cl = c * fractoriumZeps(std::abs(P[1]));
  const double cr = c + c * fractoriumZeps(std::abs(P[2]));
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = apophysisRound(x[i]), ry = apophysisRound(y[i]);
    const double dx = x[i] - rx, dy = y[i] - ry;
    double px = dx * c + rx, py = dy * c + ry;
    if (laneUniform(rnd[i]) < cr) {
      if (std::abs(dx) >= std::abs(dy)) {
        const double side = dx >= 0.0 ? cl : -cl;
        px += side;
        py += side * dy / fractoriumZeps(dx);
      } else {
        const double side = dy >= 0.0 ? cl : -cl;
        py += side;
        px += dx / dy * side;
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// cpow3: the complex power z^(c + i d') of cpow's kind on a random branch: the angle taken in
// [0, 2π), moved down a turn with the chance (1 − cos(φ/2))/2, then by ±2π round(spread-scaled
// ln Ψ) turns, and the result turned by 2πk/divisor (k = ⌊32767 Ψ⌋). c and d' come from r and
// d: the exponent's angle atan2(r ln d, 2π) (ln of |d| negated for d < 0).
VOXFLAME_VARIATION_TARGETS void cpow3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double r = P[0], d = fractoriumZeps(P[1]), divisor = fractoriumZeps(P[2]), spread = P[3];
  const double turn = kTwoPi / divisor;
  const double a0 = std::atan2((d < 0.0 ? -std::log(-d) : std::log(d)) * r, kTwoPi);
  const double c = std::cos(a0) * r * std::cos(a0) / divisor, e = std::cos(a0) * r * std::sin(a0) / divisor;
  const double halfC = c / 2.0, halfE = e / 2.0, coeff = e == 0.0 ? 0.0 : -0.095 * spread / e;
  for (std::size_t i = 0; i < n; ++i) {
    double a = std::atan2(y[i], x[i]);
    a = a < 0.0 ? a + kTwoPi : a;
    a = std::cos(a / 2.0) < 2.0 * laneUniform(rnd[i]) - 1.0 ? a - kTwoPi : a;
    const double sign = laneUniform(rnd[i]) < 0.5 ? kTwoPi : -kTwoPi;
    // ln(1 − Ψ): Ψ = 0 would make it −∞ (and 0 · −∞ NaN).
    a += sign * std::round(std::log(1.0 - laneUniform(rnd[i])) * coeff);
    const double k = std::floor(laneUniform(rnd[i]) * 32767.0);
    const double lnr2 = std::log(x[i] * x[i] + y[i] * y[i]);
    const double m = w * std::exp(halfC * lnr2 - e * a);
    const double angle = c * a + halfE * lnr2 + turn * k;
    outX[i] += m * std::cos(angle);
    outY[i] += m * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

// GlynnSim5: the origin within radius + thickness; beyond it, with the chance contrast ·
// (radius/r)^pow, the point (w α², w α²), α = radius/r, else w p (Fractorium's, as it has it).
// Every lane draws its Ψ, so the loop has no branch on the draw.
VOXFLAME_VARIATION_TARGETS void glynnSim5(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], inner = P[0] + P[1], contrast = std::clamp(P[2], 0.0, 1.0), power = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double alpha = std::abs(radius / fractoriumZeps(r));
    double px = 0.0, py = 0.0;
    if (!(r < inner)) {
      const bool keep = u > contrast * std::pow(alpha, power);
      px = keep ? w * x[i] : w * alpha * alpha;
      py = keep ? w * y[i] : w * alpha * alpha;
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// GlynnSim4: w (X, Y) within radius; beyond it w p, or w α² p (α = radius/r) with the chance
// contrast α^pow. Every lane draws its Ψ.
VOXFLAME_VARIATION_TARGETS void glynnSim4(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], contrast = std::clamp(P[1], 0.0, 1.0), power = P[2], cx = P[3], cy = P[4];
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double alpha = std::abs(radius / fractoriumZeps(r));
    const double f = u > contrast * std::pow(alpha, power) ? w : w * (alpha * alpha);
    const bool inside = r < radius;
    outX[i] += inside ? w * cx : f * x[i];
    outY[i] += inside ? w * cy : f * y[i];
    outZ[i] += w * z[i];
  }
}

// hex_rand: a random point of a random hexagon of a hexagonal lattice (2x by 2y cells about the
// origin), shown with the chance `density` (hashed per hexagon) and sized by size/2 times a hashed
// number to the power `power` (Fractorium's).
VOXFLAME_VARIATION_TARGETS void hexRand(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  constexpr double kSqrt3Half = 0.86602540378443864676, kTwoOverSqrt3 = 1.1547005383792515290;
  constexpr double kThirdTurn = 2.0943951023931954923;
  const double cellsX = P[0], cellsY = P[1], halfSize = P[2] * 0.5, power = P[3];
  const double density = std::clamp(P[4], 0.0, 1.0), seed = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    // The angle within the hexagon's six triangles, and the distance to its edge in that direction.
    const double k = laneUniform(rnd[i]) * 6.0;
    const double sector = std::floor(k), t = k - sector;
    const double edge = std::sqrt(1.0 + t * t - t);
    const double sign = sector - std::floor(k / 2.0) * 2.0 == 1.0 ? 1.0 : -1.0;
    // Fractorium halves the sector in integers: ⌊sector/2⌋.
    const double angle = kThirdTurn * std::floor(sector / 2.0) + sign * std::asin(kSqrt3Half * t / edge) - kPi / 2.0;
    const double cx = std::floor(laneUniform(rnd[i]) * cellsX * 2.0) - cellsX;
    const double cy = std::floor(laneUniform(rnd[i]) * cellsY * 2.0) - cellsY;
    const double hx = cx + 0.5 * cy, hy = cy * kSqrt3Half;
    const double spread = std::sqrt(laneUniform(rnd[i]));
    double px = 0.0, py = 0.0;
    if (shadertoyHash(hy, hx, seed) < density) {
      const double scaled = edge * spread * kTwoOverSqrt3;
      const double r = halfSize * scaled * std::pow(shadertoyHash(hx, hy, seed), power);
      px = (std::cos(angle) * r + hx) * w;
      py = (std::sin(angle) * r + hy) * w;
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// checks: a checkerboard of cells of side `size`: the point moved by (−x, −y) on the odd cells
// and by (x, y) on the even ones, with a random spread rnd Ψ along x on the odd, along y on the
// even ones; the cells' parity is that of the sum of the rounded (Apophysis' rounding) cell
// coordinates.
VOXFLAME_VARIATION_TARGETS void checks(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1], cells = 1.0 / fractoriumZeps(P[2]), spread = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = spread * laneUniform(rnd[i]), ry = spread * laneUniform(rnd[i]);
    const double sum = apophysisRound(x[i] * cells) + apophysisRound(y[i] * cells);
    const bool odd = std::abs(std::fmod(sum, 2.0)) == 1.0;
    outX[i] += w * (x[i] + (odd ? rx - cx : cx));
    outY[i] += w * (y[i] + (odd ? -cy : cy + ry));
    outZ[i] += w * z[i];
  }
}

// glynnia2: Glynnia's two square-root branches, one chosen at random (Ψ > ½), mirrored in x for
// points on or below the x axis.
VOXFLAME_VARIATION_TARGETS void glynnia2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double v2 = w * std::sqrt(2.0) / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool root = laneUniform(rnd[i]) > 0.5;
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const bool upper = r > 0.0 && y[i] > 0.0;
    // Fractorium guards the divisors only below the axis, where they can be 0.
    const auto guard = [upper](double v) { return upper ? v : fractoriumZeps(v); };
    const double sign = upper ? 1.0 : -1.0;
    double px, py;
    if (root) {
      const double d = guard(std::sqrt(r + x[i]));
      px = sign * v2 * d;
      py = -(v2 / d * y[i]);
    } else {
      const double d = r + x[i];
      const double f = w / guard(std::sqrt(r * (y[i] * y[i] + d * d)));
      px = sign * f * d;
      py = f * y[i];
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// crackle2: cracks between jittered cell points: the point's unit cell and a random neighbour (up,
// down, right or left), each with a point hashed from its indices, and a random point of the
// segment between them, times cellsize. Fractorium applies no weight to it (x, y); z is carried.
VOXFLAME_VARIATION_TARGETS void crackle2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = std::max(P[0], 0.0001), jitter = 1.0 / fractoriumZeps(cellsize);
  constexpr double kSeed = 34554.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double cx = std::floor(x[i]), cy = std::floor(y[i]);
    const double x0 = cx + jitter * shadertoyHash(cx, cy, kSeed);
    const double y0 = cy + jitter * shadertoyHash(cy, cx * 3.0, kSeed + 7.0);
    const bool vertical = laneUniform(rnd[i]) < 0.5;
    const double step = laneUniform(rnd[i]) < 0.5 ? 1.0 : -1.0;
    const double nx = vertical ? cx : cx + step, ny = vertical ? cy + step : cy;
    const double x1 = nx + jitter * shadertoyHash(nx, ny, kSeed);
    const double y1 = ny + jitter * shadertoyHash(ny, nx * 3.0, kSeed + 7.0);
    const double t = laneUniform(rnd[i]);
    outX[i] += (x0 + (x1 - x0) * t) * cellsize;
    outY[i] += (y0 + (y1 - y0) * t) * cellsize;
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addBlurVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;

  add("gaussian",
      "p + w (Ψ₂ + Ψ₃ + Ψ₄ + Ψ₅ − 2)(cos 2πΨ₁, sin 2πΨ₁), the point itself not weighted (Fractorium's; flam3's "
      "gaussian_blur leaves the point out)",
      k2D, kRandom, &gaussian);
  add("blur_square", "2w (Ψ₁ − ½, Ψ₂ − ½): the square of side 2w (Fractorium's)", k2D, kRandom, &blurSquare);
  add("circleblur", "w √Ψ₁ (cos 2πΨ₂, sin 2πΨ₂): the disc of radius w (Fractorium's)", k2D, kRandom, &circleblur);
  add("blur_pixelize",
      "w size (⌊x/size⌋ + scale (Ψ₁ − ½) + ½, ⌊y/size⌋ + scale (Ψ₂ − ½) + ½): the point's grid cell filled at random "
      "(Fractorium's)",
      k2D, kRandom, &blurPixelize, {{"size", 0.1, 0.01, 1.0}, {"scale", 1.0, 0.0, 2.0}});
  add("blur_heart",
      "w (u, v), u, v = 2Ψ − 1, v cut at (a |u|^p ± b √|1 − u²| − a)/(|a| + |b|) (± as v's sign) (Fractorium's)", k2D,
      kRandom, &blurHeart, {{"p", 0.5, 0.0, 2.0}, {"a", -0.6, -2.0, 2.0}, {"b", 0.7, -2.0, 2.0}});
  add("d_spherical", "w p / r² when Ψ < spherical_weight, else w p (Fractorium's, whose files call it weight)", k2D,
      kRandom, &dSpherical, {{"spherical_weight", 0.5, 0.0, 1.0}});
  add("juliaq", "w r^(divisor/power) (cos α, sin α), α = (φ divisor + 2πk)/power, k = ⌊32767 Ψ⌋ (Fractorium's)", k2D,
      kRandom, &juliaq, {{"power", 3.0, -10.0, 10.0}, {"divisor", 2.0, -10.0, 10.0}});
  add("Juliac",
      "w e^(L/re − α im/100) (cos β, sin β), L = dist ln r, α = φ + 2π (k mod re), k a random integer, β = α/re + "
      "L im/100 (Fractorium's)",
      k2D, kRandom, &juliac, {{"re", 2.0, -10.0, 10.0}, {"im", 1.0, -100.0, 100.0}, {"dist", 1.0, -4.0, 4.0}});
  add("coth_spiral", "w (−sinh t, sin(a t)) / (cos(a t) − cosh t), t = 2π (Ψ − ½) (Fractorium's)", k2D, kRandom,
      &cothSpiral, {{"a", 4.0, -10.0, 10.0}});
  add("depth_gaussian",
      "w (p + b), b = √(−2 ln(1 − Ψ₁)) blur/10 (r − radius) (cos 2πΨ₂, sin 2πΨ₂) beyond the radius, 0 within "
      "(Fractorium's)",
      k2D, kRandom, &depthGaussian, {{"blur", 1.0, 0.0, 4.0}, {"radius", 1.0, 0.0, 4.0}});
  add("depth_ngon",
      "w (p + b), b = blur/10 (r − radius) / cos(φ') (cos 2πΨ, sin 2πΨ) beyond the radius, 0 within; φ' the angle "
      "2πΨ from the middle of its side of a regular power-gon (Fractorium's)",
      k2D, kRandom, &depthNgon, {{"power", 5.0, 1.0, 12.0}, {"blur", 1.0, 0.0, 4.0}, {"radius", 1.0, 0.0, 4.0}});
  // depth_ngon2 in Fractorium's flam3-compatible form is depth_ngon: its x0, y0, mulx, muly and exp
  // only act in the other form.
  add("depth_ngon2",
      "depth_ngon: w (p + b), b = blur/10 (r − radius)/cos φ' (cos 2πΨ, sin 2πΨ) beyond the radius (Fractorium's "
      "flam3-compatible form, in which x0, y0, mulx, muly and exp do nothing)",
      k2D, kRandom, &depthNgon,
      {{"power", 5.0, 1.0, 12.0},
       {"blur", 1.0, 0.0, 4.0},
       {"radius", 1.0, 0.0, 4.0},
       {"x0", 0.0, -2.0, 2.0},
       {"y0", 0.0, -2.0, 2.0},
       {"mulx", 1.0, 0.0, 4.0},
       {"muly", 1.0, 0.0, 4.0},
       {"exp", 1.0, 0.0, 4.0}});
  add("depth_sine",
      "w (p + b), b = acos(2u − 1)/π blur/10 (r − radius) (cos 2πΨ₁, sin 2πΨ₁) beyond the radius, 0 within; u = Ψ₂ "
      "for power 1, else (1 − Ψ₂)^power (Fractorium's)",
      k2D, kRandom, &depthSine, {{"power", 1.0, 0.0, 4.0}, {"blur", 1.0, 0.0, 4.0}, {"radius", 1.0, 0.0, 4.0}});
  add("bTransform",
      "bipolar coordinates of p (foci ±1): τ/power + move ± split (by x's sign), (σ + rotate)/power + 2π ⌊Ψ "
      "power⌋/power, "
      "back to the plane: w (sinh τ, sin σ)/(cosh τ − cos σ) (Fractorium's)",
      k2D, kRandom, &bTransform,
      {{"rotate", 0.0, -kPi, kPi}, {"power", 1.0, 1.0, 10.0}, {"move", 0.0, -2.0, 2.0}, {"split", 0.0, -2.0, 2.0}});
  add("boarders2",
      "w (o |c| + k), k = p rounded, o = p − k; when Ψ < |c| (1 + |right|) moved by |c| |left| towards the cell's "
      "border along o's larger coordinate (Fractorium's)",
      k2D, kRandom, &boarders2, {{"c", 0.5, -2.0, 2.0}, {"left", 0.5, -2.0, 2.0}, {"right", 0.5, -2.0, 2.0}});
  add("cpow3",
      "w e^(c L/2 − d' α) (cos β, sin β), L = ln r², β = c α + d' L/2 + 2πk/divisor, k = ⌊32767 Ψ₄⌋; α = φ in [0, 2π), "
      "less 2π when cos(α/2) < 2Ψ₁ − 1, plus ±2π round(−0.095 spread ln(1 − Ψ₃)/d') (± by Ψ₂); c = r cos² t/divisor, "
      "d' = r cos t sin t/divisor, t = atan2(r ln d, 2π) (Fractorium's)",
      k2D, kRandom, &cpow3,
      {{"r", 1.0, -4.0, 4.0}, {"d", 1.0, -4.0, 4.0}, {"divisor", 1.0, -10.0, 10.0}, {"spread", 1.0, -4.0, 4.0}});
  add("GlynnSim5",
      "0 within radius + thickness; beyond, w (α², α²) with α = radius/r when Ψ ≤ contrast α^pow, else w p "
      "(Fractorium's)",
      k2D, kRandom, &glynnSim5,
      {{"radius", 1.0, 0.0, 4.0}, {"thickness", 0.1, 0.0, 1.0}, {"contrast", 0.5, 0.0, 1.0}, {"pow", 1.5, 0.0, 4.0}});
  add("GlynnSim4",
      "w (X, Y) within radius; beyond, w α² p (α = radius/r) when Ψ ≤ contrast α^pow, else w p (Fractorium's)", k2D,
      kRandom, &glynnSim4,
      {{"radius", 1.0, 0.0, 4.0},
       {"contrast", 0.5, 0.0, 1.0},
       {"pow", 1.5, 0.0, 4.0},
       {"X", 0.0, -2.0, 2.0},
       {"Y", 0.0, -2.0, 2.0}});
  add("hex_rand",
      "w (c + R (cos β, sin β)): c a random centre (i + j/2, j √3/2) of the hexagonal lattice, i ∈ [−x, x), j ∈ [−y, "
      "y), kept when its hash is below density (else 0); β a random direction, R = size/2 · (distance to the "
      "hexagon's edge) √Ψ · 2/√3 · h^power, h another hash of c (Fractorium's)",
      k2D, kRandom, &hexRand,
      {{"x", 10.0, 0.0, 50.0},
       {"y", 10.0, 0.0, 50.0},
       {"size", 1.0, 0.0, 2.0},
       {"power", 1.0, 0.0, 4.0},
       {"density", 1.0, 0.0, 1.0},
       {"seed", 1.0, 0.0, 100.0}});
  add("checks",
      "w (p + d): on the cells of side size where ⌊x/size⌉ + ⌊y/size⌉ is odd d = (rnd Ψ₁ − x, −y), else d = (x, y + "
      "rnd "
      "Ψ₂), ⌊⌉ Apophysis' rounding (Fractorium's)",
      k2D, kRandom, &checks,
      {{"x", 0.5, -2.0, 2.0}, {"y", 0.5, -2.0, 2.0}, {"size", 0.5, 0.01, 2.0}, {"rnd", 0.0, 0.0, 1.0}});
  add("glynnia2",
      "for y > 0: (w/√2) (d, −y/d), d = √(r + x), when Ψ > ½, else w (d, y)/√(r (y² + d²)), d = r + x; on or below the "
      "x axis the same with x negated (Fractorium's)",
      k2D, kRandom, &glynnia2);
  add("crackle2",
      "cellsize (q₀ + (q₁ − q₀) Ψ₃): q₀ the jittered point of p's unit cell c = (⌊x⌋, ⌊y⌋), q₁ that of its neighbour "
      "c ± (0, 1) (Ψ₁ < ½) or c ± (1, 0) (± by Ψ₂), a cell's point c + (h(cx, cy), h(cy, 3cx)) / cellsize, h "
      "Chaotica's sine hash; no weight on x, y (Fractorium's)",
      k2D, kRandom, &crackle2, {{"cellsize", 1.0, 0.0001, 4.0}});
}

}  // namespace voxflame::core
