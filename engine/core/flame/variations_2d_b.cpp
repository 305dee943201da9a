// Fractorium's other 2D variations, second part: the elliptic e* family, exponentials, flips,
// flowers, Jacobi's elliptic functions and the random tiles (dust … tile_log). Each is a kernel
// below and one row of the table at the end (see variations.h for the notation,
// variation_kernels.h and variations_2d_shared.h for what the files share). Fractorium writes z = 0
// for these; here z is carried as w·z, as for every 2D variation. Where Fractorium leaves the weight
// off a term, so does the port (it says so).
#include <math.h>  // IWYU pragma: keep; lgamma_r: std::lgamma writes the global signgam, a data race between threads

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/flame/variations_2d_shared.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// Cells of side 1 (the integer parts of |x|, |y|, taken mod density, over density) as polar
// coordinates: angle 2π(X + distortion·h₁), radius (Y + distortion·h₂)^power, h hashed from the cell.
VOXFLAME_VARIATION_TARGETS void dust(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double density = fractoriumZeps(fractoriumNonzero(P[0])), distortion = P[1], power = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double cx = std::fmod(std::floor(std::abs(x[i])), density) / density;
    const double cy = std::fmod(std::floor(std::abs(y[i])), density) / density;
    const double a = (cx + hashShadertoy(cx, cy, 1.0) * distortion) * kTwoPi;
    const double r = std::exp(std::log(cy + hashShadertoy(cy, cx, 2.0) * distortion) * power);
    outX[i] += w * std::cos(a) * r;
    outY[i] += w * std::sin(a) * r;
    outZ[i] += w * z[i];
  }
}

// Inside the disc of radius |w|, x moved by shift·w, mirrored when that leaves the disc's chord.
VOXFLAME_VARIATION_TARGETS void eclipse(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shift = fractoriumCyclic(P[0], -2.0, 2.0);
  for (std::size_t i = 0; i < n; ++i) {
    double px = w * x[i];
    if (std::abs(y[i]) <= w) {
      const double c2 = std::sqrt(w * w - y[i] * y[i]);
      if (std::abs(x[i]) <= c2) {
        const double moved = x[i] + shift * w;
        px = std::abs(moved) >= c2 ? -(w * x[i]) : w * moved;
      }
    }
    outX[i] += px;
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

// ---- elliptic coordinates: μ = acosh X, ν = ±acos(x/X), back as (cosh μ cos ν, sinh μ sin ν) -----

inline double ellipticNu(double x, double y, double xmax) {
  const double nu = std::acos(std::clamp(x / xmax, -1.0, 1.0));
  return y < 0.0 ? -nu : nu;
}

// ν in sectors of π/num, alternate ones turned by ±πa/num; mirrored where y ≤ 0.
VOXFLAME_VARIATION_TARGETS void eCollide(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = fractoriumCyclic(P[0], 0.0, 1.0), num = fractoriumInteger(P[1], 1.0, 2147483647.0);
  const double cnPi = num / kPi, piCn = kPi / num, caCn = kPi * a / num;
  for (std::size_t i = 0; i < n; ++i) {
    double xmax = ellipticXmax(x[i], y[i]);
    if (xmax < 1.0) xmax = 1.0;
    double nu = std::acos(std::clamp(x[i] / xmax, -1.0, 1.0));
    const double alt = std::trunc(nu * cnPi);
    nu = alt * piCn + std::fmod(isOddWhole(alt) ? nu - caCn : nu + caCn, piCn);
    if (!(y[i] > 0.0)) nu = -nu;
    outX[i] += w * xmax * std::cos(nu);
    outY[i] += w * std::sqrt(xmax - 1.0) * std::sqrt(xmax + 1.0) * std::sin(nu);
    outZ[i] += w * z[i];
  }
}

// μ within ±radius moved on by distance·radius and wrapped back into that band (the other way
// round where ν ≤ 0).
VOXFLAME_VARIATION_TARGETS void eMod(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = fractoriumClamp(P[0], 0.0, 1e300), distance = fractoriumCyclic(P[1], 0.0, 2.0);
  for (std::size_t i = 0; i < n; ++i) {
    double xmax = ellipticXmax(x[i], y[i]);
    if (!(xmax >= 1.0) || !std::isfinite(xmax)) xmax = 1.0;  // Fractorium's ClampGteRef
    double mu = std::acosh(xmax);
    const double nu = ellipticNu(x[i], y[i], xmax);
    if (mu < radius && -mu < radius)
      mu = nu > 0.0 ? std::fmod(mu + radius + distance * radius, 2.0 * radius) - radius
                    : std::fmod(mu - radius - distance * radius, 2.0 * radius) + radius;
    outX[i] += w * std::cosh(mu) * std::cos(nu);
    outY[i] += w * std::sinh(mu) * std::sin(nu);
    outZ[i] += w * z[i];
  }
}

// μ' = dist·μ + push, ν' = ν + rotate.
VOXFLAME_VARIATION_TARGETS void ePush(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double push = P[0], dist = P[1], rotate = fractoriumCyclic(P[2], -kPi, kPi);
  for (std::size_t i = 0; i < n; ++i) {
    double xmax = ellipticXmax(x[i], y[i]);
    if (!(xmax >= 1.0) || !std::isfinite(xmax)) xmax = 1.0;
    const double mu = std::acosh(xmax) * dist + push;
    const double nu = ellipticNu(x[i], y[i], xmax) + rotate;
    outX[i] += w * std::cosh(mu) * std::cos(nu);
    outY[i] += w * std::sinh(mu) * std::sin(nu);
    outZ[i] += w * z[i];
  }
}

// ν turned by rotate (wrapped into (−π, π]); written back with X and √(X² − 1).
VOXFLAME_VARIATION_TARGETS void eRotate(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rotate = fractoriumCyclic(P[0], -kPi, kPi);
  for (std::size_t i = 0; i < n; ++i) {
    double xmax = ellipticXmax(x[i], y[i]);
    if (xmax < 1.0) xmax = 1.0;
    const double nu = std::fmod(ellipticNu(x[i], y[i], xmax) + rotate + kPi, kTwoPi) - kPi;
    outX[i] += w * xmax * std::cos(nu);
    outY[i] += w * std::sqrt(xmax * xmax - 1.0) * std::sin(nu);
    outZ[i] += w * z[i];
  }
}

// μ scaled; ν scaled about angle and wrapped into [−π, π].
VOXFLAME_VARIATION_TARGETS void eScale(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = fractoriumNonzero(P[0], 0.0, 1.0), angle = fractoriumCyclic(P[1], 0.0, kTwoPi);
  for (std::size_t i = 0; i < n; ++i) {
    double xmax = ellipticXmax(x[i], y[i]);
    if (!(xmax >= 1.0) || !std::isfinite(xmax)) xmax = 1.0;
    const double mu = std::acosh(xmax) * scale;
    double nu = ellipticNu(x[i], y[i], xmax);
    nu = std::fmod(std::fmod(scale * (nu + kPi + angle), kTwoPi * scale) - angle - scale * kPi, kTwoPi);
    if (nu > kPi) nu -= kTwoPi;
    if (nu < -kPi) nu += kTwoPi;
    outX[i] += w * std::cosh(mu) * std::cos(nu);
    outY[i] += w * std::sinh(mu) * std::sin(nu);
    outZ[i] += w * z[i];
  }
}

// ν' = ν + out·μ + in/μ. At μ = 0 (the segment between the foci) with in = 0 the last term is 0
// where Fractorium's 0/0 would drop the point.
VOXFLAME_VARIATION_TARGETS void eSwirl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double inner = P[0], outer = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    double xmax = ellipticXmax(x[i], y[i]);
    if (!std::isfinite(xmax)) xmax = -1.0;      // Fractorium's ClampGteRef(xmax, −1): NaN below
    if (xmax > -1.0 && xmax < 1.0) xmax = 1.0;  // rounding just below 1 on the segment
    const double mu = std::acosh(xmax);
    const double nu = ellipticNu(x[i], y[i], xmax) + mu * outer + (inner == 0.0 ? 0.0 : inner / mu);
    outX[i] += w * std::cosh(mu) * std::cos(nu);
    outY[i] += w * std::sinh(mu) * std::sin(nu);
    outZ[i] += w * z[i];
  }
}

// ---- polynomials, exponentials and functions of r --------------------------------------------

// Enneper's surface's (x − x³/3 + x y², y − y³/3 + y x²); Fractorium weights only the first two
// terms of each.
VOXFLAME_VARIATION_2D(ennepers, {
  const double x2 = x[i] * x[i], y2 = y[i] * y[i];
  outX[i] += w * (x[i] - x2 * x[i] / 3.0) + x[i] * y2;
  outY[i] += w * (y[i] - y2 * y[i] / 3.0) + y[i] * x2;
})

VOXFLAME_VARIATION_2D(erfVariation, {
  outX[i] += w * std::erf(x[i]);
  outY[i] += w * std::erf(y[i]);
})

// (w/r')·(x² − y², 2xy) with r' = lengthscalar·r kept at least eps from 0, then f(w/r') by
// radiusFunc: the value itself, cos, exp, ln|·|, reciprocal. Fractorium leaves the weight off
// the result.
VOXFLAME_VARIATION_TARGETS void excinis(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double lengthScalar = P[0], radiusFunc = fractoriumClamp(P[1], 0.0, 5.0), eps = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double rPrior = std::sqrt(x[i] * x[i] + y[i] * y[i]) * lengthScalar;
    const double rEps = std::abs(rPrior) > eps ? 0.0 : (rPrior >= 0.0 ? 1.0 : -1.0) * eps;
    const double r = w / fractoriumZeps(rPrior + rEps);
    double f = r;
    if (radiusFunc < 1.0)
      f = r;
    else if (radiusFunc < 2.0)
      f = std::cos(r);
    else if (radiusFunc < 3.0)
      f = std::exp(r);
    else if (radiusFunc < 4.0)
      f = std::log(std::abs(r) + std::abs(rEps));
    else
      f = 1.0 / fractoriumZeps(r + rEps);
    outX[i] += (x[i] - y[i]) * (x[i] + y[i]) * f;
    outY[i] += 2.0 * x[i] * y[i] * f;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(exp2Variation, {
  const double e = w * std::exp(x[i] * kPi);
  outX[i] += e * std::cos(y[i] * kPi);
  outY[i] += e * std::sin(y[i] * kPi);
})

// The complex power (real + i·imaginary)^(x + iy).
VOXFLAME_VARIATION_TARGETS void expo(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = 0.5 * std::log(fractoriumZeps(P[0] * P[0] + P[1] * P[1])), t = std::atan2(P[1], P[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const double e = w * std::exp(x[i] * k - y[i] * t), a = x[i] * t + y[i] * k;
    outX[i] += e * std::cos(a);
    outY[i] += e * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// ((φ/π + 1)/2)(cos a, sin a), a = 2π/(r + 1).
VOXFLAME_VARIATION_2D(fdisc, {
  const double a = kTwoPi / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1.0);
  const double r = (std::atan2(y[i], x[i]) / kPi + 1.0) * 0.5;
  outX[i] += w * r * std::cos(a);
  outY[i] += w * r * std::sin(a);
})

// Binet's formula for the Fibonacci numbers continued to the complex plane: (φᶻ − (−φ)⁻ᶻ)/√5, φ
// the golden ratio, z = x + iy; sc and sc2 scale the two exponentials and their exponents.
inline void fibonacciTerm(double x, double y, double w, double sc, double sc2, double& outX, double& outY) {
  const double lnPhi = std::log((1.0 + std::sqrt(5.0)) / 2.0), invRoot5 = 1.0 / std::sqrt(5.0);
  const double a1 = y * lnPhi, a2 = -(x * kPi + y * lnPhi);
  const double e1 = sc * std::exp(sc2 * (x * lnPhi)), e2 = sc * std::exp(sc2 * -(x * lnPhi - y * kPi));
  outX += w * (e1 * std::cos(a1) - e2 * std::cos(a2)) * invRoot5;
  outY += w * (e1 * std::sin(a1) - e2 * std::sin(a2)) * invRoot5;
}

VOXFLAME_VARIATION_2D(fibonacci, { fibonacciTerm(x[i], y[i], w, 1.0, 1.0, outX[i], outY[i]); })

VOXFLAME_VARIATION_TARGETS void fibonacci2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sc = P[0], sc2 = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    fibonacciTerm(x[i], y[i], w, sc, sc2, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

// ---- flips and flowers ---------------------------------------------------------------------------

// y negated inside the circle of radius |w|.
VOXFLAME_VARIATION_2D(flipcircle, {
  outX[i] += w * x[i];
  outY[i] += x[i] * x[i] + y[i] * y[i] > w * w ? w * y[i] : -(w * y[i]);
})

// x negated above the x axis.
VOXFLAME_VARIATION_2D(flipx, {
  outX[i] += y[i] > 0.0 ? -(w * x[i]) : w * x[i];
  outY[i] += w * y[i];
})

// y negated right of the y axis.
VOXFLAME_VARIATION_2D(flipy, {
  outX[i] += w * x[i];
  outY[i] += x[i] > 0.0 ? -(w * y[i]) : w * y[i];
})

VOXFLAME_VARIATION_TARGETS void flowerdb(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double petals = P[0], split = petals * P[1], spread = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]), t = std::atan2(y[i], x[i]);
    const double r2 = r * std::abs((spread + std::sin(petals * t)) * std::cos(split * t));
    outX[i] += r2 * std::cos(t);
    outY[i] += r2 * std::sin(t);
    outZ[i] += w * z[i];
  }
}

// foci with its two exponentials weighted: (c1 eˣ − c2 e⁻ˣ, sin y) / (c1 eˣ + c2 e⁻ˣ − cos y).
VOXFLAME_VARIATION_TARGETS void fociP(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c1 = P[0], c2 = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double ex = fractoriumZeps(std::exp(x[i]));
    const double e1 = ex * c1, e2 = c2 / ex;
    const double r = w / fractoriumZeps(e1 + e2 - std::cos(y[i]));
    outX[i] += (e1 - e2) * r;
    outY[i] += std::sin(y[i]) * r;
    outZ[i] += w * z[i];
  }
}

// (tanh x, tanh y)(1/cos y + effect·π).
VOXFLAME_VARIATION_TARGETS void funnel(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double effect = fractoriumInteger(P[0], -2147483647.0, 2147483647.0) * kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 1.0 / fractoriumZeps(std::cos(y[i])) + effect;
    outX[i] += w * (std::tanh(x[i]) * t);
    outY[i] += w * (std::tanh(y[i]) * t);
    outZ[i] += w * z[i];
  }
}

// (ln Γ(r), φ).
VOXFLAME_VARIATION_TARGETS void gammaVariation(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    int sign = 0;
    outX[i] += w * ::lgamma_r(std::sqrt(x[i] * x[i] + y[i] * y[i]), &sign);
    outY[i] += w * std::atan2(y[i], x[i]);
    outZ[i] += w * z[i];
  }
}

// One step of Hénon's map: (1 − a x² + y, b x).
VOXFLAME_VARIATION_TARGETS void henon(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += (1.0 - a * x[i] * x[i] + y[i]) * w;
    outY[i] += b * x[i] * w;
    outZ[i] += w * z[i];
  }
}

// A hole at the origin: radius δ/(r + δ) (inside) or r + δ, δ = (φ/π + 1)^a; Fractorium leaves the
// weight off δ in the second.
VOXFLAME_VARIATION_TARGETS void hole(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0];
  const bool inside = fractoriumInteger(P[1], 0.0, 1.0) != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r0 = std::sqrt(x[i] * x[i] + y[i] * y[i]), rz = fractoriumZeps(r0);
    const double delta = std::pow(std::atan2(y[i], x[i]) / kPi + 1.0, a);
    const double r = inside ? w * delta / (r0 + delta) : w * r0 + delta;
    outX[i] += r * x[i] / rz;
    outY[i] += r * y[i] / rz;
    outZ[i] += w * z[i];
  }
}

// (φ/π)(cos a, sin a), a = π/(r + 1).
VOXFLAME_VARIATION_2D(idisc, {
  const double a = kPi / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1.0);
  const double r = std::atan2(y[i], x[i]) * w / kPi;
  outX[i] += r * std::cos(a);
  outY[i] += r * std::sin(a);
})

// The point pushed away from (x, y) as if a drop of radius r fell there: its distance d becomes
// √(d² + r²).
VOXFLAME_VARIATION_TARGETS void inkdrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double r = fractoriumClamp(P[0], 0.0, 1e300), cx = P[1], cy = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - cx, dy = y[i] - cy, d2 = dx * dx + dy * dy;
    const double adjust = std::sqrt(d2 + r * r) - std::sqrt(d2), bearing = std::atan2(dy, dx);
    outX[i] += w * (x[i] + std::cos(bearing) * adjust);
    outY[i] += w * (y[i] + std::sin(bearing) * adjust);
    outZ[i] += w * z[i];
  }
}

// ---- Jacobi's elliptic functions -------------------------------------------------------------------

// sn, cn and dn of u for the parameter 1 − emmc by the arithmetic–geometric mean (Numerical Recipes'
// sncndn, which Fractorium uses, with its accuracy 0.0003²).
inline void jacobiElliptic(double u, double emmc, double& sn, double& cn, double& dn) {
  constexpr double kAccuracy = 0.0003;
  double emc = emmc;
  if (emc == 0.0) {
    cn = 1.0 / std::cosh(u);
    dn = cn;
    sn = std::tanh(u);
    return;
  }
  const bool negative = emc < 0.0;
  double d = 1.0;
  if (negative) {
    d = 1.0 - emc;
    emc = -emc / d;
    d = std::sqrt(d);
    u = d * u;
  }
  double em[13], en[13], a = 1.0, c = 0.0;
  int last = 0;
  dn = 1.0;
  for (int i = 0; i < 8; ++i) {
    last = i;
    em[i] = a;
    emc = std::sqrt(emc);
    en[i] = emc;
    c = 0.5 * (a + emc);
    if (std::abs(a - emc) <= kAccuracy * a) break;
    emc = a * emc;
    a = c;
  }
  u = c * u;
  sn = std::sin(u);
  cn = std::cos(u);
  if (sn != 0.0) {
    a = cn / sn;
    c = a * c;
    for (int k = last; k >= 0; --k) {
      const double b = em[k];
      a = c * a;
      c = dn * c;
      dn = (en[k] + a) / (b + a);
      a = c / b;
    }
    a = 1.0 / std::sqrt(c * c + 1.0);
    sn = sn < 0.0 ? -a : a;
    cn = c * sn;
  }
  if (negative) {
    a = dn;
    dn = cn;
    cn = a;
    sn = sn / d;
  }
}

// The Jacobi functions of the complex number x + iy by the addition theorems, from those of x with
// parameter k and of y with 1 − k: which = 0 sn, 1 cn, 2 dn.
template <int which>
[[gnu::always_inline]] inline void jacobiTerm(double x, double y, double k, double w, double& outX, double& outY) {
  double snx, cnx, dnx, sny, cny, dny;
  jacobiElliptic(x, k, snx, cnx, dnx);
  jacobiElliptic(y, 1.0 - k, sny, cny, dny);
  double numX, numY;
  if constexpr (which == 0) {
    numX = snx * dny;
    numY = cnx * dnx * cny * sny;
  } else if constexpr (which == 1) {
    numX = cnx * cny;
    numY = -dnx * snx * dny * sny;
  } else {
    numX = dnx * cny * dny;
    numY = -cnx * snx * sny * k;
  }
  const double denom = w / fractoriumZeps(snx * snx * sny * sny * k + cny * cny);
  outX += denom * numX;
  outY += denom * numY;
}

VOXFLAME_VARIATION_TARGETS void jacSn(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = fractoriumClamp(P[0], -1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    jacobiTerm<0>(x[i], y[i], k, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void jacCn(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = fractoriumClamp(P[0], -1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    jacobiTerm<1>(x[i], y[i], k, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void jacDn(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = fractoriumClamp(P[0], -1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    jacobiTerm<2>(x[i], y[i], k, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

// Two halves of the plane turned by 45° (scaled by rotate) and pulled apart; Fractorium applies no
// weight to x and y (z is carried as w·z all the same).
VOXFLAME_VARIATION_TARGETS void kaleidoscope(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double pull = P[0], rotate = P[1], lineUp = P[2], shiftX = P[3], shiftY = P[4];
  const double s = std::sin(kPi / 4.0), c = std::cos(kPi / 4.0);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += rotate * x[i] * c - y[i] * s + lineUp + shiftX;
    outY[i] += y[i] > 0.0 ? rotate * y[i] * c + x[i] * s + pull + lineUp + shiftY
                          : rotate * y[i] * c + x[i] * s - pull - lineUp;
    outZ[i] += w * z[i];
  }
}

// ---- random ones -------------------------------------------------------------------------------------

// A point of the spiral tanh(t(1 + ia)/…): (sinh t, sin at)/(cos at + cosh t), t = 2π(Ψ − ½); the
// input point is not used.
VOXFLAME_VARIATION_TARGETS void tanhSpiral(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (laneUniform(rnd[i]) - 0.5) * kTwoPi;
    const double aux = fractoriumZeps(std::cos(a * t) + std::cosh(t));
    outX[i] += w * (std::sinh(t) / aux);
    outY[i] += w * (std::sin(a * t) / aux);
    outZ[i] += w * z[i];
  }
}

// Copies of the plane in columns of the given width, a point moved one column towards the middle
// with a probability that grows with its place in its column (cos(πf) < 2Ψ − 1, f = x/width less
// its integer part, plus it left of 0, as Fractorium has it). The shift is width·w.
VOXFLAME_VARIATION_TARGETS void tileHlp(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double width = fractoriumNonzero(P[0]), shift = width * w;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double v = x[i] / width;
    const bool positive = v > 0.0;
    const double f = positive ? v - std::trunc(v) : v + std::trunc(v);
    const double move = std::cos(f * kPi) < 2.0 * u - 1.0 ? (positive ? -shift : shift) : 0.0;
    outX[i] += w * x[i] + move;
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

// x moved by a whole number of steps: round(±spread·ln Ψ₁), the sign + when Ψ₂ < ½ (Fractorium's
// random bit). ln(1 − Ψ₁) stands for ln Ψ₁ (the same distribution) so that Ψ₁ = 0 cannot give −∞.
VOXFLAME_VARIATION_TARGETS void tileLog(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double spread = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double logU = std::log(1.0 - laneUniform(rnd[i]));
    const double sign = laneUniform(rnd[i]) < 0.5 ? spread : -spread;
    const double step = std::round(logU * sign);
    outX[i] += w * (x[i] + step);
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractorium2DVariationsB(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  add("dust",
      "ρ (cos 2π(X + distortion h₁), sin 2π(X + distortion h₁)), ρ = (Y + distortion h₂)^power, z; X = (⌊|x|⌋ mod "
      "density)/density, Y likewise with y, h₁ = H(X, Y, 1), h₂ = H(Y, X, 2), H(a, b, s) = frac(43758.5453 sin(12.9898 "
      "a + 78.233 b + s))",
      k2D, kFixed, &dust, {{"density", 5.0, 1.0, 20.0}, {"distortion", 1.0, -2.0, 2.0}, {"power", 1.0, -2.0, 4.0}});
  add("eclipse",
      "where |y| ≤ w and |x| ≤ c = √(w² − y²): (x + shift w, y), or (−x, y) when |x + shift w| ≥ c; elsewhere p; z "
      "(w the weight)",
      k2D, kFixed, &eclipse, {{"shift", 0.0, -2.0, 2.0}});
  add("eCollide",
      "(X cos ν', √(X² − 1) sin ν'), z; X = (d₊ + d₋)/2 (at least 1), ν = acos(x/X), ν' = ν in sectors of π/num, "
      "alternate ones turned by ±πa/num, negated where y ≤ 0",
      k2D, kFixed, &eCollide, {{"a", 0.0, 0.0, 1.0}, count("num", 1.0, 1.0, 10.0)});
  add("eMod",
      "(cosh μ cos ν, sinh μ sin ν), z; μ = acosh X, ν = ±acos(x/X) (elliptic, sign of y); μ within ±radius becomes "
      "((μ ± radius (1 + distance)) mod 2 radius) ∓ radius (the sign of ν)",
      k2D, kFixed, &eMod, {{"radius", 1.0, 0.0, 4.0}, {"distance", 0.0, 0.0, 2.0}});
  add("ennepers", "(x − x³/3 + x y²/w, y − y³/3 + y x²/w), z (Fractorium weights only the first two terms)", k2D,
      kFixed, &ennepers);
  add("ePush", "(cosh μ' cos ν', sinh μ' sin ν'), z; μ' = dist μ + push, ν' = ν + rotate (elliptic μ, ν as in eMod)",
      k2D, kFixed, &ePush, {{"push", 0.0, -2.0, 2.0}, {"dist", 1.0, -2.0, 2.0}, {"rotate", 0.0, -kPi, kPi}});
  add("erf", "(erf x, erf y), z", k2D, kFixed, &erfVariation);
  add("eRotate", "(X cos ν', √(X² − 1) sin ν'), z; ν' = ((ν + rotate + π) mod 2π) − π (X, ν as in eMod)", k2D, kFixed,
      &eRotate, {{"rotate", 0.0, -kPi, kPi}});
  add("eScale",
      "(cosh sμ cos ν', sinh sμ sin ν'), z; ν' = ((s(ν + π + angle) mod 2πs) − angle − sπ) mod 2π, into [−π, π]; s "
      "= scale (elliptic μ, ν as in eMod)",
      k2D, kFixed, &eScale, {{"scale", 1.0, 0.0, 1.0}, {"angle", 0.0, 0.0, kTwoPi}});
  add("eSwirl", "(cosh μ cos ν', sinh μ sin ν'), z; ν' = ν + out μ + in/μ (elliptic μ, ν as in eMod)", k2D, kFixed,
      &eSwirl, {{"in", 0.0, -2.0, 2.0}, {"out", 0.0, -2.0, 2.0}});
  add("excinis",
      "(x² − y², 2xy) f(w/ρ)/w, z; ρ = lengthscalar·r, moved to ±eps when within eps of 0; f by radiusFunc: < 1 "
      "itself, < 2 cos, < 3 exp, < 4 ln|·|, else the reciprocal (the weight w only inside f)",
      k2D, kFixed, &excinis, {{"lengthscalar", 1.0, -2.0, 2.0}, {"radiusFunc", 0.0, 0.0, 5.0}, {"eps", 0.1, 0.0, 1.0}});
  add("exp2", "e^(πx) (cos πy, sin πy), z", k2D, kFixed, &exp2Variation);
  add("expo", "(real + i imaginary)^(x + iy), z", k2D, kFixed, &expo,
      {{"real", -1.0, -2.0, 2.0}, {"imaginary", 1.0, -2.0, 2.0}});
  add("fdisc", "((φ/π + 1)/2)(cos a, sin a), a = 2π/(r + 1), z", k2D, kFixed, &fdisc);
  add("fibonacci", "(φ^q − (−φ)^−q)/√5 with q = x + iy, φ the golden ratio (Binet's formula), z", k2D, kFixed,
      &fibonacci);
  add("fibonacci2",
      "sc (e^(sc2 q ln φ) − e^(−sc2 (x ln φ − πy)) e^(−i(πx + y ln φ)))/√5, q = x + iy, φ the golden ratio, z", k2D,
      kFixed, &fibonacci2, {{"sc", 1.0, -2.0, 2.0}, {"sc2", 1.0, -2.0, 2.0}});
  add("flipcircle", "(x, −y) where r² ≤ w², else p; z (w the weight)", k2D, kFixed, &flipcircle);
  add("flipx", "(−x, y) where y > 0, else p; z", k2D, kFixed, &flipx);
  add("flipy", "(x, −y) where x > 0, else p; z", k2D, kFixed, &flipy);
  add("flowerdb", "r |(petal_spread + sin(petals φ)) cos(petals petal_split φ)| (cos φ, sin φ), z", k2D, kFixed,
      &flowerdb, {{"petals", 6.0, 0.0, 20.0}, {"petal_split", 0.0, -2.0, 2.0}, {"petal_spread", 1.0, -2.0, 2.0}});
  add("foci_p", "(c1 eˣ − c2 e⁻ˣ, sin y) / (c1 eˣ + c2 e⁻ˣ − cos y), z", k2D, kFixed, &fociP,
      {{"c1", 0.5, -2.0, 2.0}, {"c2", 0.5, -2.0, 2.0}});
  add("funnel", "(tanh x, tanh y)(1/cos y + effect π), z", k2D, kFixed, &funnel, {count("effect", 8.0, -10.0, 10.0)});
  add("gamma", "(ln Γ(r), φ), z", k2D, kFixed, &gammaVariation);
  add("henon", "(1 − a x² + y, b x), z (Hénon's map)", k2D, kFixed, &henon,
      {{"a", 0.5, -2.0, 2.0}, {"b", 1.0, -2.0, 2.0}});
  add("hole",
      "ρ (cos φ, sin φ), z; δ = (φ/π + 1)^a, ρ = δ/(r + δ) with inside, else r + δ/w (δ outside the weight w, as "
      "Fractorium has it)",
      k2D, kFixed, &hole, {{"a", 1.0, -2.0, 4.0}, count("inside", 0.0, 0.0, 1.0)});
  add("idisc", "(φ/π)(cos a, sin a), a = π/(r + 1), z", k2D, kFixed, &idisc);
  add("inkdrop", "p + (√(d² + r²) − d)(p − c)/d, z; c = (x, y) the parameters, d = |p − c|", k2D, kFixed, &inkdrop,
      {{"r", 0.5, 0.0, 2.0}, {"x", 0.0, -2.0, 2.0}, {"y", 0.0, -2.0, 2.0}});
  add("jac_cn",
      "cn(x + iy | k) by the addition theorem: (cn_x cn_y, −dn_x sn_x dn_y sn_y) / (k sn_x² sn_y² + cn_y²), the x "
      "functions with parameter k, the y ones with 1 − k; z",
      k2D, kFixed, &jacCn, {{"k", 0.5, -1.0, 1.0}});
  add("jac_dn", "dn(x + iy | k): (dn_x cn_y dn_y, −k cn_x sn_x sn_y) / (k sn_x² sn_y² + cn_y²), as jac_cn; z", k2D,
      kFixed, &jacDn, {{"k", 0.5, -1.0, 1.0}});
  add("jac_sn", "sn(x + iy | k): (sn_x dn_y, cn_x dn_x cn_y sn_y) / (k sn_x² sn_y² + cn_y²), as jac_cn; z", k2D, kFixed,
      &jacSn, {{"k", 0.5, -1.0, 1.0}});
  add("Kaleidoscope",
      "(rotate x c − y s + line_up + x₀, rotate y c + x s ± (pull + line_up) (+ y₀ where y > 0)), c = s = √½, x₀, "
      "y₀ the parameters x, y; the weight not applied (Fractorium's), z",
      k2D, kFixed, &kaleidoscope,
      {{"pull", 0.0, -2.0, 2.0},
       {"rotate", 1.0, -2.0, 2.0},
       {"line_up", 1.0, -2.0, 2.0},
       {"x", 0.0, -2.0, 2.0},
       {"y", 0.0, -2.0, 2.0}});
  add("tanh_spiral", "(sinh t, sin at)/(cos at + cosh t), t = 2π(Ψ − ½); the point not used; z", k2D, kRandom,
      &tanhSpiral, {{"a", 4.0, -10.0, 10.0}});
  add("tile_hlp",
      "(x + s, y), z; s = −width (x > 0) or +width when cos(π f) < 2Ψ − 1, f = x/width ∓ its integer part (− right "
      "of 0, + left, as Fractorium has it), else 0",
      k2D, kRandom, &tileHlp, {{"width", 1.0, 0.1, 4.0}});
  add("tile_log", "(x + round(±spread ln Ψ₁), y), z; + when Ψ₂ < ½ (ln(1 − Ψ₁) in place of ln Ψ₁)", k2D, kRandom,
      &tileLog, {{"spread", 1.0, 0.0, 4.0}});
}

}  // namespace voxflame::core
