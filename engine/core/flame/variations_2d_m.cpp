// Fractorium's smaller 2D variations, l to r: lenses, carpets, rays, moduli, projective and rational maps. Each is a
// kernel below and one row of the table at the end (see variations.h for the notation and variation_kernels.h for what
// the files share). They follow Fractorium's formulas (Source/Ember/Variations0*.h), including where Fractorium applies
// the weight twice or outside a term; z is carried as w·z (voxflame's rule for 2D variations, where Fractorium writes
// 0).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// (2/π)², which Fractorium writes SQR(M_2_PI) in rays1 and roundspher.
constexpr double kTwoOverPiSquared = (2.0 / kPi) * (2.0 / kPi);

// ---- polynomial maps -------------------------------------------------------------------------

VOXFLAME_VARIATION_2D(lens, {
  outX[i] += w * 0.5 * (x[i] * x[i] - y[i] * y[i]);
  outY[i] += w * x[i] * y[i];
})

// Each coordinate's magnitude to its own power, its sign kept (0 counted as positive, as Fractorium's SignNz).
VOXFLAME_VARIATION_TARGETS void linearT(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powX = P[0], powY = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = x[i] < 0.0 ? -1.0 : 1.0, sy = y[i] < 0.0 ? -1.0 : 1.0;
    outX[i] += w * sx * std::pow(std::abs(x[i]), powX);
    outY[i] += w * sy * std::pow(std::abs(y[i]), powY);
    outZ[i] += w * z[i];
  }
}

// The Lozi map, a piecewise-linear Hénon map.
VOXFLAME_VARIATION_TARGETS void lozi(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (1.0 - a * std::abs(x[i]) + y[i]);
    outY[i] += w * b * x[i];
    outZ[i] += w * z[i];
  }
}

// Fractorium's polynomial: the weight goes inside the powers, and the linear and constant terms are added without
// it. Fractorium takes |x| where the original plugin did not (a negative base would give NaN).
VOXFLAME_VARIATION_TARGETS void polynomial(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powX = P[0], powY = P[1], lcx = P[2], lcy = P[3], scx = P[4], scy = P[5];
  const double aw = std::abs(w);
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = x[i] < 0.0 ? -1.0 : (x[i] > 0.0 ? 1.0 : 0.0);
    const double sy = y[i] < 0.0 ? -1.0 : (y[i] > 0.0 ? 1.0 : 0.0);
    outX[i] += std::pow(aw * std::abs(x[i]), powX) * sx + lcx * x[i] + scx;
    outY[i] += std::pow(aw * std::abs(y[i]), powY) * sy + lcy * y[i] + scy;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void projective(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1], c = P[2], a1 = P[3], b1 = P[4], c1 = P[5], a2 = P[6], b2 = P[7], c2 = P[8];
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / fractoriumZeps(a * x[i] + b * y[i] + c);
    outX[i] += (a1 * x[i] + b1 * y[i] + c1) * s;
    outY[i] += (a2 * x[i] + b2 * y[i] + c2) * s;
    outZ[i] += w * z[i];
  }
}

// The quotient of two complex cubics in x + iy.
VOXFLAME_VARIATION_TARGETS void rational3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double t3 = P[0], t2 = P[1], t1 = P[2], tc = P[3], b3 = P[4], b2 = P[5], b1 = P[6], bc = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double x2 = x[i] * x[i], y2 = y[i] * y[i];
    const double cubeRe = x2 * x[i] - 3.0 * x[i] * y2, cubeIm = 3.0 * x2 * y[i] - y2 * y[i];
    const double sqRe = x2 - y2, sqIm = 2.0 * x[i] * y[i];
    const double tr = t3 * cubeRe + t2 * sqRe + t1 * x[i] + tc, ti = t3 * cubeIm + t2 * sqIm + t1 * y[i];
    const double br = b3 * cubeRe + b2 * sqRe + b1 * x[i] + bc, bi = b3 * cubeIm + b2 * sqIm + b1 * y[i];
    const double den = 1.0 / fractoriumZeps(br * br + bi * bi);
    outX[i] += w * (tr * br + ti * bi) * den;
    outY[i] += w * (ti * br - tr * bi) * den;
    outZ[i] += w * z[i];
  }
}

// Fractorium's q_ode: one Euler-like step of a quadratic ODE, (q01 + w q02 x + q03 x² + q04 x y + q05 y + q06 y², q07 +
// q08 x + q09 x² + q10 x y + w q11 y + q12 y²): the weight multiplies only q02 and q11, as Fractorium has it.
VOXFLAME_VARIATION_TARGETS void qOde(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double q01 = P[0], q02 = P[1], q03 = P[2], q04 = P[3], q05 = P[4], q06 = P[5];
  const double q07 = P[6], q08 = P[7], q09 = P[8], q10 = P[9], q11 = P[10], q12 = P[11];
  for (std::size_t i = 0; i < n; ++i) {
    const double x2 = x[i] * x[i], y2 = y[i] * y[i], xy = x[i] * y[i];
    outX[i] += (q01 + w * q02 * x[i] + q03 * x2) + (q04 * xy + q05 * y[i] + q06 * y2);
    outY[i] += (q07 + q08 * x[i] + q09 * x2) + (q10 * xy + w * q11 * y[i] + q12 * y2);
    outZ[i] += w * z[i];
  }
}

// ---- shapes ----------------------------------------------------------------------------------

// Fractorium's lazyjess: inside a regular n-gon of circumradius √2·w-ish (the weight sizes it), the point is spun by
// `spin`; where that carries it past the polygon's edge it is spun back, mirrored in y and turned by (corner − 1)
// slices; outside the polygon it is pushed out by space/r. n = 2 is Fractorium's special case, the strip |x| < w.
VOXFLAME_VARIATION_TARGETS void lazyjess(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = std::max(P[0], 2.0), spin = P[1], space = P[2], corner = P[3];
  const double vertex = kPi * (sides - 2.0) / fractoriumZeps(2.0 * sides), sinVertex = std::sin(vertex);
  const double slice = kTwoPi / fractoriumZeps(sides), halfSlice = slice / 2.0;
  const double cornerRotation = (corner - 1.0) * slice;
  const bool strip = sides == 2.0;
  // The polygon's radius at angle a (Fractorium's, with a shifted by 2π so that fmod sees a positive angle).
  const auto edge = [&](double a) {
    return w * std::numbers::sqrt2 * sinVertex /
           fractoriumZeps(std::sin(kPi - std::fmod(a + halfSlice, slice) - vertex));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double modulus = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double phi = std::atan2(y[i], x[i]);
    const bool inside = strip ? std::abs(x[i]) < w : modulus < edge(phi + kTwoPi);
    double px = 0.0, py = 0.0;
    if (inside) {
      const double a = phi + spin + (strip ? 0.0 : kTwoPi);
      const double sx = w * modulus * std::cos(a), sy = w * modulus * std::sin(a);
      const double spunModulus = strip ? modulus : std::hypot(sx, sy);
      const bool stays = strip ? std::abs(sx) < w : spunModulus < edge(a);
      if (stays) {
        px = sx;
        py = sy;
      } else {
        const double back = std::atan2(sy, sx) - spin + cornerRotation + (strip ? 0.0 : kTwoPi);
        px = w * spunModulus * std::cos(back);
        py = -(w * spunModulus * std::sin(back));
      }
    } else {
      const double push = 1.0 + space / fractoriumZeps(modulus);
      px = w * push * x[i];
      py = w * push * y[i];
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// Fractorium's loonie2 in its flam3-compatible form (Compat on, as flam3 and Apophysis draw it): loonie's inversion
// inside the rounded star r₂ < w², r₂ the squared largest of the point's projections on the sides' normals (blended
// with the circle by circle, the normals tilted by star); where r₂ < 0 the point is pulled in instead. power is used
// only by Fractorium's other (Chaotica) form, which is not ported.
VOXFLAME_VARIATION_TARGETS void loonie2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = fractoriumInteger(P[0], 1.0, 50.0);
  const double a = kTwoPi / sides, st = -kPi / 2.0 * std::clamp(P[1], -1.0, 1.0);
  const double c = kPi / 2.0 * std::clamp(P[2], -1.0, 1.0);
  const double sina = std::sin(a), cosa = std::cos(a), sins = std::sin(st), coss = std::cos(st);
  const double sinc = std::sin(c), cosc = std::cos(c);
  const double w2 = w * w;
  const int turns = sides >= 2.0 ? static_cast<int>(sides) - 1 : 0;  // 0 for a NaN parameter too
  for (std::size_t i = 0; i < n; ++i) {
    double xr = x[i], yr = y[i];
    double r2 = xr * coss + std::abs(yr) * sins;
    for (int k = 0; k < turns; ++k) {
      const double swap = xr * cosa - yr * sina;
      yr = xr * sina + yr * cosa;
      xr = swap;
      r2 = std::max(r2, xr * coss + std::abs(yr) * sins);
    }
    r2 = r2 * cosc + std::sqrt(x[i] * x[i] + y[i] * y[i]) * sinc;
    r2 = turns > 1 ? r2 * r2 : std::abs(r2) * r2;
    double scale = w;
    if (r2 > 0.0 && r2 < w2) {
      scale = w * std::sqrt(std::abs(w2 / r2 - 1.0));
    } else if (r2 < 0.0) {
      scale = w / std::sqrt(std::abs(w2 / r2) - 1.0);
    }
    outX[i] += scale * x[i];
    outY[i] += scale * y[i];
    outZ[i] += w * z[i];
  }
}

// Fractorium's loonie3: inside the curve (r²/x)² < w² (x > ε only) the point scaled by w √(w²/(r²/x)² − 1), elsewhere
// w p. The weight is part of the shape, as in loonie.
VOXFLAME_VARIATION_TARGETS void loonie3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double w2 = w * w;
  for (std::size_t i = 0; i < n; ++i) {
    const double q = (x[i] * x[i] + y[i] * y[i]) / x[i];
    const double r2 = x[i] > kFractoriumEps ? q * q : 2.0 * w2;
    const double scale = r2 < w2 ? w * std::sqrt(w2 / r2 - 1.0) : w;
    outX[i] += scale * x[i];
    outY[i] += scale * y[i];
    outZ[i] += w * z[i];
  }
}

// JWildfire's mask has five parameters more: X = xscale·x + xshift and Y = yscale·y + yshift in place of
// x and y, and ushift in place of the 1; their defaults give Fractorium's. (JWildfire hides the point at
// the origin where Fractorium divides by ε; Fractorium's way is kept.)
VOXFLAME_VARIATION_TARGETS void mask(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double xshift = P[0], yshift = P[1], ushift = P[2], xscale = P[3], yscale = P[4];
  for (std::size_t i = 0; i < n; ++i) {
    const double d = w / fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
    const double u = xscale * x[i] + xshift, v = yscale * y[i] + yshift;
    const double s = std::sin(u), c = std::cos(u), k = std::cosh(v) + ushift;
    outX[i] += d * s * k * s * s;
    outY[i] += d * c * k * s * s;
    outZ[i] += w * z[i];
  }
}

// Fractorium's mcarpet: an ovoid-like scaling by w/(r²/4 + 1) plus a Lozi-like term.
VOXFLAME_VARIATION_TARGETS void mcarpet(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], twist = P[2], tilt = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w / ((x[i] * x[i] + y[i] * y[i]) * 0.25 + 1.0);
    outX[i] += x[i] * r * sx + w * (1.0 - twist * x[i] * x[i] + y[i]);
    outY[i] += y[i] * r * sy + w * tilt * x[i];
    outZ[i] += w * z[i];
  }
}

// Fractorium's oscilloscope2: the point negated inside the band |y| ≤ t around a perturbed (and optionally damped)
// cosine trace t = amplitude e^(−damping |x|) cos(2π frequencyx x + perturbation sin(2π frequencyy y)) + separation.
VOXFLAME_VARIATION_TARGETS void oscilloscope2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double separation = std::max(P[0], 0.0), tpf = kTwoPi * P[1], tpf2 = kTwoPi * P[2];
  const double amplitude = P[3], perturbation = P[4], damping = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    const double pt = perturbation * std::sin(tpf2 * y[i]);
    const double damp = damping == 0.0 ? 1.0 : std::exp(-std::abs(x[i]) * damping);
    const double t = amplitude * damp * std::cos(tpf * x[i] + pt) + separation;
    const double sign = std::abs(y[i]) <= t ? -1.0 : 1.0;
    outX[i] += sign * w * x[i];
    outY[i] += sign * w * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void ovoid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w / fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
    outX[i] += x[i] * r * sx;
    outY[i] += y[i] * r * sy;
    outZ[i] += w * z[i];
  }
}

// panorama1/2: the point pulled into the unit disc (by 1/√(r² + 1) or 1/(r + 1)), then unrolled into (angle/π,
// radius − ½). Fractorium reads the transform's affine point here; it is the point itself for an ordinary term.
VOXFLAME_VARIATION_2D(panorama1, {
  const double aux = 1.0 / std::sqrt(x[i] * x[i] + y[i] * y[i] + 1.0);
  const double x1 = x[i] * aux, y1 = y[i] * aux;
  outX[i] += w * std::atan2(x1, y1) / kPi;
  outY[i] += w * (std::sqrt(x1 * x1 + y1 * y1) - 0.5);
})

VOXFLAME_VARIATION_2D(panorama2, {
  const double aux = 1.0 / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1.0);
  const double x1 = x[i] * aux, y1 = y[i] * aux;
  outX[i] += w * std::atan2(x1, y1) / kPi;
  outY[i] += w * (std::sqrt(x1 * x1 + y1 * y1) - 0.5);
})

VOXFLAME_VARIATION_2D(petal, {
  const double s = std::sin(x[i]), c = std::cos(x[i]), cy = std::cos(y[i]);
  const double bx = c * cy, by = s * cy;
  outX[i] += w * c * bx * bx * bx;
  outY[i] += w * c * by * by * by;
})

// ---- Möbius-like maps ------------------------------------------------------------------------

// murl: p / (1 + c' ζ^power) (ζ = x + iy, c' = c/(power − 1)), scaled by w (c' + 1); power at least 2 as Fractorium
// clamps it.
VOXFLAME_VARIATION_TARGETS void murl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = std::max(P[1], 2.0);
  const double cp = P[0] / (power - 1.0), half = power / 2.0, vp = w * (cp + 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = std::atan2(y[i], x[i]) * power;
    const double r = cp * std::pow(x[i] * x[i] + y[i] * y[i], half);
    const double re = r * std::cos(angle) + 1.0, im = r * std::sin(angle);
    const double r1 = vp / (re * re + im * im);
    outX[i] += r1 * (x[i] * re + y[i] * im);
    outY[i] += r1 * (y[i] * re - x[i] * im);
    outZ[i] += w * z[i];
  }
}

// murl2: p divided by the power-th root (taken twice over, as Fractorium does) of 1 + c ζ^power, scaled by
// w (c + 1)^(2/power); c clamped to [−1, 1], and 0 at c = −1.
VOXFLAME_VARIATION_TARGETS void murl2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c = std::clamp(P[0], -1.0, 1.0), power = P[1];
  const double half = power / 2.0, invP = 1.0 / power, invP2 = 2.0 / power;
  const double vp = c == -1.0 ? 0.0 : w * std::pow(c + 1.0, 2.0 / power);
  for (std::size_t i = 0; i < n; ++i) {
    double angle = std::atan2(y[i], x[i]) * power;
    double r = c * std::pow(x[i] * x[i] + y[i] * y[i], half);
    double re = r * std::cos(angle) + 1.0, im = r * std::sin(angle);
    r = std::pow(re * re + im * im, invP);
    angle = std::atan2(im, re) * invP2;
    re = r * std::cos(angle);
    im = r * std::sin(angle);
    const double r1 = vp / (r * r);
    outX[i] += r1 * (x[i] * re + y[i] * im);
    outY[i] += r1 * (y[i] * re - x[i] * im);
    outZ[i] += w * z[i];
  }
}

// Fractorium's wrap of a cyclic parameter into [−π, π] when it is set.
double wrapToPi(double value) {
  if (value > kPi) return -kPi + std::fmod(value + kPi, kTwoPi);
  if (value < -kPi) return kPi - std::fmod(kPi - value, kTwoPi);
  return value;
}

// Fractorium's poincare: inversions in two circles orthogonal to the unit circle, of radii c1r and c2r at angles c1a
// and c2a (taken mod π after the wrap into [−π, π], as Fractorium does). Fractorium applies no weight here.
VOXFLAME_VARIATION_TARGETS void poincare(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c1r = P[0], c2r = P[2];
  const double a1 = std::fmod(wrapToPi(P[1]), kPi), a2 = std::fmod(wrapToPi(P[3]), kPi);
  const double c1d = std::sqrt(1.0 + c1r * c1r), c2d = std::sqrt(1.0 + c2r * c2r);
  const double c1x = c1d * std::cos(a1), c1y = c1d * std::sin(a1), c2x = c2d * std::cos(a2), c2y = c2d * std::sin(a2);
  const double c1r2 = c1r * c1r, c2r2 = c2r * c2r;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx1 = x[i] - c1x, dy1 = y[i] - c1y;
    const double d1 = fractoriumZeps(dx1 * dx1 + dy1 * dy1);
    const double dx2 = c1x + c1r2 * dx1 / d1 - c2x, dy2 = c1y + c1r2 * dy1 / d1 - c2y;
    const double d2 = fractoriumZeps(dx2 * dx2 + dy2 * dy2);
    outX[i] += c2x + c2r2 * dx2 / d2;
    outY[i] += c2y + c2r2 * dy2 / d2;
    outZ[i] += w * z[i];
  }
}

// poincare2: the disc automorphism ζ ↦ (ζ − c)/(1 − c̄ ζ) that moves c, the centre of a neighbouring cell of the
// hyperbolic {p, q} tiling, to the origin (c = 0 where 1/p + 1/q ≥ ½, no such tiling).
VOXFLAME_VARIATION_TARGETS void poincare2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = P[0], q = P[1];
  const double a0 = kTwoPi / p;
  const double dist2 = 1.0 - (std::cos(a0) - 1.0) / (std::cos(a0) + std::cos(kTwoPi / q));
  const double dist = dist2 > 0.0 ? 1.0 / std::sqrt(dist2) : 1.0;
  const bool hyperbolic = 1.0 / p + 1.0 / q < 0.5;
  const double cx = hyperbolic ? std::cos(a0) * dist : 0.0, cy = hyperbolic ? std::sin(a0) * dist : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = x[i] - cx, b = y[i] - cy;
    const double c = 1.0 - cx * x[i] - cy * y[i], d = cy * x[i] - cx * y[i];
    const double num = w / fractoriumZeps(c * c + d * d);
    outX[i] += (a * c + b * d) * num;
    outY[i] += (b * c - a * d) * num;
    outZ[i] += w * z[i];
  }
}

// Fractorium's mobius_strip: the rectangle [−rect_x, rect_x] × [−rect_y, rect_y] (repeated) wrapped onto a Möbius strip
// of the given radius and half-width, turned by rotate_y then rotate_x turns (about the x and y axes), and seen from
// above: its x and y (Fractorium drops the strip's own z, and so does this 2D variation).
VOXFLAME_VARIATION_TARGETS void mobiusStrip(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], width = P[1], rectX = P[2], rectY = P[3];
  const double sinX = std::sin(P[4] * kTwoPi), cosX = std::cos(P[4] * kTwoPi);
  const double sinY = std::sin(P[5] * kTwoPi), cosY = std::cos(P[5] * kTwoPi);
  for (std::size_t i = 0; i < n; ++i) {
    double t = 0.0, s = 0.0;
    if (rectX != 0.0) {
      const double d = (x[i] + rectX) / (2.0 * rectX);
      t = kTwoPi * (d - std::floor(d));
    }
    if (rectY != 0.0) {
      const double d = (y[i] + rectY) / (2.0 * rectY);
      s = 2.0 * width * (d - std::floor(d)) - width;
    }
    const double band = radius + s * std::cos(t / 2.0);
    const double mx = band * std::cos(t), my = band * std::sin(t), mz = s * std::sin(t / 2.0);
    const double ry = my * cosY + mz * sinY, rz = mz * cosY - my * sinY;
    outX[i] += w * (mx * cosX - rz * sinX);
    outY[i] += w * ry;
    outZ[i] += w * z[i];
  }
}

// One half of Fractorium's ortho: the point q (x ≥ 0 side, or mirrored to it) moved along the circle through it
// orthogonal to the unit circle, by `turn` (in, or out) times that circle's half-angle θ, its position wrapped into
// [−θ, θ). Returns the new point through (ox, oy), on the side q was on.
[[gnu::always_inline]] inline void orthoArc(double qx, double qy, double r2, double turn, double& resultX,
                                            double& resultY) {
  const double side = qx >= 0.0 ? 1.0 : -1.0;
  const double ax = side * qx;
  // Fractorium guards the divisor with Zeps only on the x ≥ 0 side.
  const double xo = (r2 + 1.0) / (side > 0.0 ? fractoriumZeps(2.0 * ax) : 2.0 * ax);
  const double ro = std::sqrt((ax - xo) * (ax - xo) + qy * qy);
  const double theta = std::atan2(1.0, ro);
  const double a = std::fmod(turn * theta + std::atan2(qy, xo - ax) + theta, 2.0 * theta) - theta;
  resultX = side * (xo - std::cos(a) * ro);
  resultY = std::sin(a) * ro;
}

// Fractorium's ortho: inside the unit circle the point moves along its orthogonal circle by `in`; outside, its
// inversion in the unit circle moves by `out` and is inverted back. in and out are wrapped into [−π, π] as Fractorium
// does when they are set.
VOXFLAME_VARIATION_TARGETS void ortho(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double turnIn = wrapToPi(P[0]), turnOut = wrapToPi(P[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    double px = 0.0, py = 0.0;
    if (r2 < 1.0) {
      orthoArc(x[i], y[i], r2, turnIn, px, py);
    } else {
      // The inversion 1/r (cos, sin), with Fractorium's precalculated sin and cos (divided by Zeps(r)).
      const double r = std::sqrt(r2), inv = 1.0 / r;
      const double ix = inv * (x[i] / fractoriumZeps(r)), iy = inv * (y[i] / fractoriumZeps(r));
      double qx = 0.0, qy = 0.0;
      orthoArc(ix, iy, ix * ix + iy * iy, turnOut, qx, qy);
      // orthoArc mirrored qx back to the inverted point's side; Fractorium inverts the unmirrored point and mirrors
      // after, which is the same point.
      const double angle = std::atan2(qy, ix >= 0.0 ? qx : -qx);
      const double back = 1.0 / std::sqrt(qx * qx + qy * qy);
      px = (ix >= 0.0 ? 1.0 : -1.0) * back * std::cos(angle);
      py = back * std::sin(angle);
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// ---- rays (Fractorium's rays1/2/3 assign x and y: the terms summed before them are discarded) --------

VOXFLAME_VARIATION_2D(rays1, {
  const double r2 = x[i] * x[i] + y[i] * y[i];
  const double u = 1.0 / fractoriumZeps(std::tan(std::sqrt(r2))) + w * kTwoOverPiSquared;
  outX[i] += w * u * r2 / fractoriumZeps(x[i]);
  outY[i] += w * u * r2 / fractoriumZeps(y[i]);
})

VOXFLAME_VARIATION_2D(rays2, {
  const double r2 = x[i] * x[i] + y[i] * y[i];
  const double u = 1.0 / std::cos(r2 * std::tan(1.0 / fractoriumZeps(r2)));
  outX[i] += w / 10.0 * u * r2 / fractoriumZeps(x[i]);
  outY[i] += w / 10.0 * u * r2 / fractoriumZeps(y[i]);
})

VOXFLAME_VARIATION_2D(rays3, {
  const double r2 = x[i] * x[i] + y[i] * y[i];
  const double r4 = r2 * r2;
  const double u = 1.0 / std::sqrt(std::cos(std::sin(r4) * std::sin(1.0 / fractoriumZeps(r4))));
  outX[i] += w / 10.0 * u * std::cos(r2) * r2 / fractoriumZeps(x[i]);
  outY[i] += w / 10.0 * u * std::tan(r2) * r2 / fractoriumZeps(y[i]);
})

// ---- waves and moduli ------------------------------------------------------------------------

// x wrapped into [−size, size) after a shift (Fractorium's modulusx/modulusy, with fmod's sign rule: a negative
// remainder is moved up by size, a positive one down).
VOXFLAME_VARIATION_TARGETS void modulusx(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double size = P[0], shift = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double f = laneFmod(x[i] + size + shift, 2.0 * size);
    outX[i] += w * (f >= 0.0 ? f - size : f + size);
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void modulusy(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double size = P[0], shift = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double f = laneFmod(y[i] + size + shift, 2.0 * size);
    outX[i] += w * x[i];
    outY[i] += w * (f >= 0.0 ? f - size : f + size);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void pressureWave(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double fx = P[0] * kTwoPi, fy = P[1] * kTwoPi;
  const double ix = 1.0 / fractoriumZeps(fx), iy = 1.0 / fractoriumZeps(fy);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + ix * std::sin(fx * x[i]));
    outY[i] += w * (y[i] + iy * std::sin(fy * y[i]));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void pulse(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freqX = P[0], freqY = P[1], scaleX = P[2], scaleY = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + scaleX * std::sin(x[i] * freqX));
    outY[i] += w * (y[i] + scaleY * std::sin(y[i] * freqY));
    outZ[i] += w * z[i];
  }
}

// Fractorium's ripple: the point moved along its direction from the centre by a cosine wave of its distance, two
// such offsets blended by the phase. The distance is Fractorium's √(x² y²) (a product, not a sum), at least ε.
VOXFLAME_VARIATION_TARGETS void ripple(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double f = P[0] * 5.0, a = P[2] * 0.01, cx = P[3], cy = P[4], p = P[5] * kTwoPi - kPi;
  const double s = fractoriumZeps(P[6]), is = 1.0 / s;
  const double vxp = P[1] * p, pxa = p * a, pixa = (kPi - p) * a;
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] * s - cx, py = y[i] * s + cy;
    const double d = std::max(kFractoriumEps, std::sqrt(px * px * (py * py)));
    const double nx = px / d, ny = py / d;
    const double wave = std::cos(f * d - vxp);
    const double d1 = wave * pxa + d, d2 = wave * pixa + d;
    const double u1 = cx + nx * d1, v1 = -cy + ny * d1, u2 = cx + nx * d2, v2 = -cy + ny * d2;
    outX[i] += w * (u1 + (u2 - u1) * p) * is;
    outY[i] += w * (v1 + (v2 - v1) * p) * is;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(rippled, {
  const double d = fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
  outX[i] += w / 2.0 * (std::tanh(d) * 2.0 * x[i]);
  outY[i] += w / 2.0 * (std::cos(d) * 2.0 * y[i]);
})

// ---- rotation and inversions -----------------------------------------------------------------

// A turn by angle degrees.
VOXFLAME_VARIATION_TARGETS void rotate(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rad = P[0] / 180.0 * kPi;
  const double s = std::sin(rad), c = std::cos(rad);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] * c - y[i] * s);
    outY[i] += w * (x[i] * s + y[i] * c);
    outZ[i] += w * z[i];
  }
}

// Fractorium's roundspher applies the weight twice: w · (w/r²) p / (1/r² + (2/π)²).
VOXFLAME_VARIATION_2D(roundspher, {
  const double r2 = fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
  const double e = 1.0 / r2 + kTwoOverPiSquared;
  const double t = w / r2;
  outX[i] += w * (t * x[i] / e);
  outY[i] += w * (t * y[i] / e);
})

}  // namespace

void variation_kernels::addFractorium2dMVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("lazyjess",
      "inside the n-gon of radius √2 w sin v/sin(π − ((φ + π/n) mod 2π/n) − v), v = π(n − 2)/2n (the strip |x| < w for "
      "n = 2): w r (cos, sin)(φ + spin), or where that leaves the polygon, w r (cos α, −sin α), α = its angle − spin + "
      "(corner − 1) 2π/n; outside: w (1 + space/r) p; z; n at least 2 (w the weight, which sizes the polygon; "
      "Fractorium's)",
      k2D, kFixed, &lazyjess,
      {{"n", 4.0, 2.0, 12.0}, {"spin", kPi, -kTwoPi, kTwoPi}, {"space", 0.0, -2.0, 2.0}, {"corner", 1.0, -4.0, 4.0}});
  add("lens", "(½(x² − y²), x y), z (Fractorium's)", k2D, kFixed, &lens);
  add("linearT", "(±|x|^powX, ±|y|^powY), z; ± the sign of each coordinate, + at 0 (Fractorium's)", k2D, kFixed,
      &linearT, {{"powX", 1.0, -4.0, 4.0}, {"powY", 1.0, -4.0, 4.0}});
  add("loonie2",
      "p √|w²/q − 1| where 0 < q < w², p/√(|w²/q| − 1) where q < 0, else p; z; q = m², or |m| m for sides ≤ 2, m = "
      "cos(π circle/2) max over the sides' normals k (tilted by −π star/2) of p·k + sin(π circle/2) r (w the weight, "
      "which shapes the variation; Fractorium's flam3-compatible form; power is not used)",
      k2D, kFixed, &loonie2,
      {count("sides", 4.0, 1.0, 50.0),
       {"star", 0.0, -1.0, 1.0},
       {"circle", 0.0, -1.0, 1.0},
       {"power", 4.0, 1.0, 12.0}});
  add("loonie3",
      "p √(w²/q² − 1) where q² < w², else p, z; q = r²/x, taken as beyond w where x ≤ ε (w the weight, so it "
      "shapes the variation; Fractorium's)",
      k2D, kFixed, &loonie3);
  add("lozi", "(1 − a |x| + y, b x), z: the Lozi map (Fractorium's)", k2D, kFixed, &lozi,
      {{"a", 0.5, -2.0, 2.0}, {"b", 1.0, -2.0, 2.0}});
  add("mask",
      "(sin X, cos X) (cosh Y + ushift) sin² X / r², z; X = xscale·x + xshift, Y = yscale·y + yshift; r² as ε where "
      "0 (Fractorium's, with JWildfire's parameters)",
      k2D, kFixed, &mask,
      {{"xshift", 0.0, -2.0, 2.0},
       {"yshift", 0.0, -2.0, 2.0},
       {"ushift", 1.0, -2.0, 2.0},
       {"xscale", 1.0, -2.0, 2.0},
       {"yscale", 1.0, -2.0, 2.0}});
  add("mcarpet", "(x x₀, y y₀)/(r²/4 + 1) + (1 − twist x² + y, tilt x), z; x₀, y₀ the parameters x, y (Fractorium's)",
      k2D, kFixed, &mcarpet,
      {{"x", 0.0, -2.0, 2.0}, {"y", 0.0, -2.0, 2.0}, {"twist", 0.0, -2.0, 2.0}, {"tilt", 0.0, -2.0, 2.0}});
  add("mobius_strip",
      "the x and y of the Möbius strip point ((R + s cos(t/2)) cos t, (R + s cos(t/2)) sin t, s sin(t/2)) turned by "
      "rotate_y turns about x, then rotate_x turns about y; t = 2π frac((x + rect_x)/(2 rect_x)), s = width (2 "
      "frac((y + rect_y)/(2 rect_y)) − 1), each 0 where its rect is 0, R = radius; z (Fractorium's)",
      k2D, kFixed, &mobiusStrip,
      {{"radius", 2.0, 0.0, 4.0},
       {"width", 1.0, 0.0, 4.0},
       {"rect_x", kTwoPi, 0.0, 10.0},
       {"rect_y", 1.0, 0.0, 4.0},
       {"rotate_x", 0.0, -1.0, 1.0},
       {"rotate_y", 0.0, -1.0, 1.0}});
  add("modulusx",
      "(f − x₀ where f ≥ 0, else f + x₀, y), z; f = fmod(x + x₀ + shift, 2x₀), x₀ the parameter x (Fractorium's)", k2D,
      kFixed, &modulusx, {{"x", 1.0, 0.0, 4.0}, {"shift", 0.0, -2.0, 2.0}});
  add("modulusy",
      "(x, f − y₀ where f ≥ 0, else f + y₀), z; f = fmod(y + y₀ + shift, 2y₀), y₀ the parameter y (Fractorium's)", k2D,
      kFixed, &modulusy, {{"y", 1.0, 0.0, 4.0}, {"shift", 0.0, -2.0, 2.0}});
  add("murl", "w (c' + 1) p/(1 + c' ζ^power), z; ζ = x + iy, c' = c/(power − 1), power at least 2 (Fractorium's)", k2D,
      kFixed, &murl, {{"c", 0.0, -2.0, 2.0}, {"power", 2.0, 2.0, 10.0}});
  add("murl2",
      "w (c + 1)^(2/power) p m̄/|m|², z; m = (1 + c ζ^power)^(1/power) with its angle doubled, ζ = x + iy, c in [−1, 1] "
      "(Fractorium's)",
      k2D, kFixed, &murl2, {{"c", 0.0, -1.0, 1.0}, {"power", 1.0, -10.0, 10.0}});
  add("ortho",
      "inside the unit circle the point moved along the circle through it orthogonal to the unit circle by in·θ (θ "
      "its half-angle, the position wrapped into [−θ, θ)), mirrored for x < 0; outside, its inversion moved so by out "
      "and inverted back; in and out wrapped into [−π, π]; z (Fractorium's)",
      k2D, kFixed, &ortho, {{"in", 0.0, -kPi, kPi}, {"out", 0.0, -kPi, kPi}});
  add("oscilloscope2",
      "−p inside the band |y| ≤ t, else p, z; t = amplitude e^(−damping |x|) cos(2π frequencyx x + perturbation "
      "sin(2π frequencyy y)) + separation, separation at least 0 (Fractorium's)",
      k2D, kFixed, &oscilloscope2,
      {{"separation", 1.0, 0.0, 4.0},
       {"frequencyx", kPi, -10.0, 10.0},
       {"frequencyy", kPi, -10.0, 10.0},
       {"amplitude", 1.0, -2.0, 2.0},
       {"perturbation", 1.0, -2.0, 2.0},
       {"damping", 0.0, 0.0, 4.0}});
  add("ovoid", "(x x₀, y y₀)/r², z; x₀, y₀ the parameters x, y, r² as ε where 0 (Fractorium's)", k2D, kFixed, &ovoid,
      {{"x", 1.0, -2.0, 2.0}, {"y", 1.0, -2.0, 2.0}});
  add("panorama1", "(atan2(x', y')/π, |q| − ½), z; q = (x', y') = p/√(r² + 1) (Fractorium's)", k2D, kFixed, &panorama1);
  add("panorama2", "(atan2(x', y')/π, |q| − ½), z; q = (x', y') = p/(r + 1) (Fractorium's)", k2D, kFixed, &panorama2);
  add("petal", "cos x ((cos x cos y)³, (sin x cos y)³), z (Fractorium's)", k2D, kFixed, &petal);
  add("poincare",
      "q ↦ c + r² (q − c)/|q − c|² for circle 1 then circle 2, centres √(1 + r²)(cos a, sin a) with r, a = c1r, c1a "
      "and c2r, c2a (a wrapped into [−π, π], then mod π); no weight (Fractorium's, which applies none); z",
      k2D, kFixed, &poincare,
      {{"c1r", 1.0, 0.0, 4.0}, {"c1a", -1.0, -kPi, kPi}, {"c2r", 1.0, 0.0, 4.0}, {"c2a", 1.0, -kPi, kPi}});
  add("poincare2",
      "(ζ − c)/(1 − c̄ ζ), z; ζ = x + iy, c = (cos 2π/p, sin 2π/p)/√(1 − (cos(2π/p) − 1)/(cos(2π/p) + cos(2π/q))) "
      "where 1/p + 1/q < ½, else 0 (Fractorium's)",
      k2D, kFixed, &poincare2, {{"p", 3.0, 3.0, 12.0}, {"q", 7.0, 3.0, 12.0}});
  add("polynomial",
      "(|w x|^powx sgn x + lcx x + scx, |w y|^powy sgn y + lcy y + scy, w z): the weight inside the powers, the "
      "other terms not weighted (w the weight; Fractorium's)",
      k2D, kFixed, &polynomial,
      {{"powx", 1.0, -4.0, 4.0},
       {"powy", 1.0, -4.0, 4.0},
       {"lcx", 0.0, -2.0, 2.0},
       {"lcy", 0.0, -2.0, 2.0},
       {"scx", 0.0, -2.0, 2.0},
       {"scy", 0.0, -2.0, 2.0}});
  add("pressure_wave", "(x + sin(2π x_freq x)/(2π x_freq), y + sin(2π y_freq y)/(2π y_freq)), z (Fractorium's)", k2D,
      kFixed, &pressureWave, {{"x_freq", 1.0, -4.0, 4.0}, {"y_freq", 1.0, -4.0, 4.0}});
  add("projective", "(A1 x + B1 y + C1, A2 x + B2 y + C2)/(A x + B y + C), z; the divisor ε where 0 (Fractorium's)",
      k2D, kFixed, &projective,
      {{"A", 0.0, -2.0, 2.0},
       {"B", 0.0, -2.0, 2.0},
       {"C", 1.0, -2.0, 2.0},
       {"A1", 1.0, -2.0, 2.0},
       {"B1", 0.0, -2.0, 2.0},
       {"C1", 0.0, -2.0, 2.0},
       {"A2", 0.0, -2.0, 2.0},
       {"B2", 1.0, -2.0, 2.0},
       {"C2", 0.0, -2.0, 2.0}});
  add("pulse", "(x + scalex sin(freqx x), y + scaley sin(freqy y)), z (Fractorium's)", k2D, kFixed, &pulse,
      {{"freqx", 2.0, -10.0, 10.0},
       {"freqy", 2.0, -10.0, 10.0},
       {"scalex", 1.0, -2.0, 2.0},
       {"scaley", 1.0, -2.0, 2.0}});
  add("q_ode",
      "(q01 + w q02 x + q03 x² + q04 x y + q05 y + q06 y², q07 + q08 x + q09 x² + q10 x y + w q11 y + q12 y²), z: "
      "the weight on q02 and q11 only (w the weight; Fractorium's, whose files write q_ode01 … q_ode12)",
      k2D, kFixed, &qOde,
      {{"01", 1.0, -2.0, 2.0},
       {"02", -1.0, -2.0, 2.0},
       {"03", 0.0, -2.0, 2.0},
       {"04", 0.0, -2.0, 2.0},
       {"05", 0.0, -2.0, 2.0},
       {"06", 0.0, -2.0, 2.0},
       {"07", 1.0, -2.0, 2.0},
       {"08", 0.0, -2.0, 2.0},
       {"09", 0.0, -2.0, 2.0},
       {"10", 0.0, -2.0, 2.0},
       {"11", 0.0, -2.0, 2.0},
       {"12", 0.0, -2.0, 2.0}});
  add("rational3",
      "T(ζ)/B(ζ), z; ζ = x + iy, T = t3 ζ³ + t2 ζ² + t1 ζ + tc, B = b3 ζ³ + b2 ζ² + b1 ζ + bc, |B|² as ε where 0 "
      "(Fractorium's)",
      k2D, kFixed, &rational3,
      {{"t3", 1.0, -2.0, 2.0},
       {"t2", 0.0, -2.0, 2.0},
       {"t1", 0.0, -2.0, 2.0},
       {"tc", 1.0, -2.0, 2.0},
       {"b3", 0.0, -2.0, 2.0},
       {"b2", 1.0, -2.0, 2.0},
       {"b1", 0.0, -2.0, 2.0},
       {"bc", 1.0, -2.0, 2.0}});
  add("rays1",
      "u r² (1/x, 1/y), z; u = 1/tan r + w (2/π)², each divisor ε where 0 (w the weight; Fractorium's, which "
      "discards the terms before it)",
      k2D, kFixed, &rays1);
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("rays2",
      "u r² (1/x, 1/y)/10, z; u = 1/cos(r² tan(1/r²)), each divisor ε where 0 (Fractorium's, which discards the "
      "terms before it)",
      k2D, kFixed, &rays2);
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("rays3",
      "u r² (cos r²/x, tan r²/y)/10, z; u = 1/√cos(sin r⁴ sin(1/r⁴)), each divisor ε where 0 (Fractorium's, which "
      "discards the terms before it)",
      k2D, kFixed, &rays3);
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("ripple",
      "(c + n d_k, with y centre negated) blended by P = 2π phase − π between k = 1, 2 and divided by scale, z; q = "
      "scale p − (centerx, −centery), d = max(ε, √(q_x² q_y²)) (Fractorium's product), n = q/d, d_k = d + a_k "
      "cos(5 frequency d − velocity P), a₁ = P amplitude/100, a₂ = (π − P) amplitude/100 (Fractorium's)",
      k2D, kFixed, &ripple,
      {{"frequency", 2.0, -10.0, 10.0},
       {"velocity", 1.0, -4.0, 4.0},
       {"amplitude", 0.5, -2.0, 2.0},
       {"centerx", 0.0, -2.0, 2.0},
       {"centery", 0.0, -2.0, 2.0},
       {"phase", 0.0, -1.0, 1.0},
       {"scale", 1.0, 0.01, 4.0}});
  add("rippled", "(tanh(r²) x, cos(r²) y), z; r² as ε where 0 (Fractorium's)", k2D, kFixed, &rippled);
  add("rotate", "p turned by angle degrees about the z axis, z (Fractorium's)", k2D, kFixed, &rotate,
      {{"angle", 0.0, -180.0, 180.0}});
  add("roundspher", "w p / (r² (1/r² + (2/π)²)), z; r² as ε where 0 (w the weight, applied twice as Fractorium does)",
      k2D, kFixed, &roundspher);
}

}  // namespace voxflame::core
