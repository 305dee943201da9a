// Fractorium's other 2D variations, first part: inverse hyperbolic functions, the bipolar b* family,
// blocks, circles and kaleidoscopes (arcsech … deltaa). Each is a kernel below and one row of the
// table at the end (see variations.h for the notation, variation_kernels.h and variations_2d_shared.h
// for what the files share). Fractorium writes z = 0 for these; here z is carried as w·z, as for
// every 2D variation. Where Fractorium leaves the weight off a term, so does the port (it says so).
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/flame/variations_2d_shared.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;
using Complex = std::complex<double>;

// ---- inverse hyperbolic functions (principal branches of log and √) --------------------------

VOXFLAME_VARIATION_TARGETS void arcsech(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = w / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const Complex q = 1.0 / Complex(x[i], y[i]);
    const Complex result = scale * std::log(q + std::sqrt(q + 1.0) * std::sqrt(q - 1.0));
    outX[i] += result.real();
    outY[i] += result.imag();
    outZ[i] += w * z[i];
  }
}

// arcsech scaled by 2/π, its two halves moved apart: by +1 in y below the axis, mirrored and by −1
// above it. Fractorium adds the ±1 outside the weight.
VOXFLAME_VARIATION_TARGETS void arcsech2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = 2.0 * w / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const Complex q = 1.0 / Complex(x[i], y[i]);
    const Complex result = scale * std::log(q + std::sqrt(q + 1.0) * std::sqrt(q - 1.0));
    if (result.imag() < 0.0) {
      outX[i] += result.real();
      outY[i] += result.imag() + 1.0;
    } else {
      outX[i] -= result.real();
      outY[i] += result.imag() - 1.0;
    }
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void arcsinh(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = 2.0 * w / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const Complex q(x[i], y[i]);
    const Complex result = scale * std::log(q + std::sqrt(q * q + 1.0));
    outX[i] += result.real();
    outY[i] += result.imag();
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void arctanh(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = w / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const Complex q(x[i], y[i]);
    const Complex result = scale * std::log((q + 1.0) / (-q + 1.0));
    outX[i] += result.real();
    outY[i] += result.imag();
    outZ[i] += w * z[i];
  }
}

// ---- barycentric and bipolar coordinates -------------------------------------------------------

// The point's coordinates (u, v) in the basis (a, b), (c, d), each lengthened by the matching
// coordinate of the point: (sgn u √(u² + x²), sgn v √(v² + y²)).
VOXFLAME_VARIATION_TARGETS void barycentroid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1], c = P[2], d = P[3];
  const double dot00 = a * a + b * b, dot01 = a * c + b * d, dot11 = c * c + d * d;
  const double invDenom = 1.0 / fractoriumZeps(dot00 * dot11 - dot01 * dot01);
  for (std::size_t i = 0; i < n; ++i) {
    const double dot02 = a * x[i] + b * y[i], dot12 = c * x[i] + d * y[i];
    const double u = (dot11 * dot02 - dot01 * dot12) * invDenom;
    const double v = (dot00 * dot12 - dot01 * dot02) * invDenom;
    const double su = u < 0.0 ? -1.0 : (u > 0.0 ? 1.0 : 0.0), sv = v < 0.0 ? -1.0 : (v > 0.0 ? 1.0 : 0.0);
    outX[i] += w * std::sqrt(u * u + x[i] * x[i]) * su;
    outY[i] += w * std::sqrt(v * v + y[i] * y[i]) * sv;
    outZ[i] += w * z[i];
  }
}

// Back from bipolar coordinates (τ, σ): (sinh τ, sin σ) / (cosh τ − cos σ).
inline void fromBipolar(double tau, double sigma, double w, double& outX, double& outY) {
  const double t = fractoriumZeps(std::cosh(tau) - std::cos(sigma));
  outX += w * std::sinh(tau) / t;
  outY += w * std::sin(sigma) / t;
}

// σ folded into num sectors of π/num, alternate sectors turned by ±πa/num (Fractorium's bCollide).
VOXFLAME_VARIATION_TARGETS void bCollide(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = fractoriumCyclic(P[0], -1.0, 1.0), num = fractoriumClamp(P[1], kFractoriumEps, 2147483647.0);
  const double cnPi = num / kPi, piCn = kPi / fractoriumZeps(num), caCn = kPi * a / fractoriumZeps(num);
  for (std::size_t i = 0; i < n; ++i) {
    const double tau = bipolarTau(x[i], y[i]);
    double sigma = bipolarSigma(x[i], y[i]);
    const double alt = std::trunc(sigma * cnPi);
    sigma = alt * piCn + std::fmod(isOddWhole(alt) ? sigma - caCn : sigma + caCn, piCn);
    fromBipolar(tau, sigma, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

// τ within ±radius moved on by distance·radius and wrapped back into that band.
VOXFLAME_VARIATION_TARGETS void bMod(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = fractoriumClamp(P[0], 0.0, 1e300), distance = fractoriumCyclic(P[1], 0.0, 2.0);
  for (std::size_t i = 0; i < n; ++i) {
    double tau = bipolarTau(x[i], y[i]);
    const double sigma = bipolarSigma(x[i], y[i]);
    if (tau < radius && -tau < radius) tau = std::fmod(tau + radius + distance * radius, 2.0 * radius) - radius;
    fromBipolar(tau, sigma, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void bSwirl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double inner = P[0], outer = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double tau = bipolarTau(x[i], y[i]);
    const double sigma = bipolarSigma(x[i], y[i]) + tau * outer + inner / fractoriumZeps(tau);
    fromBipolar(tau, sigma, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

// 0.1 (cos y / tan x, −y / sin x).
VOXFLAME_VARIATION_2D(bisplit, {
  const double v = 0.1 * w;
  outX[i] += v / std::tan(x[i]) * std::cos(y[i]);
  outY[i] += v / std::sin(x[i]) * -y[i];
})

// blob with its lobes reshaped: outside radius the distance beyond it is scaled by
// |δ|^prescale·postscale (times mode, or the sign of δ when mode is 0), δ = (sin nφ + symmetry) /
// (1 + compensation |symmetry|); inside, the point itself.
VOXFLAME_VARIATION_TARGETS void blob2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double mode = P[0], waves = P[1], radius = P[2], prescale = P[3], postscale = P[4];
  const double symmetry = fractoriumClamp(P[5], -1.0, 1.0), compensation = P[6];
  const double deltaHelp = 1.0 + compensation * symmetry * (symmetry < 0.0 ? -1.0 : 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    if (r < radius) {
      outX[i] += w * x[i];
      outY[i] += w * y[i];
    } else {
      double delta = (std::sin(std::atan2(y[i], x[i]) * waves) + symmetry) / deltaHelp;
      const double positive = delta < 0.0 ? -1.0 : 1.0;
      delta = std::exp(prescale * std::log(delta * positive)) * postscale * (mode != 0.0 ? mode : positive);
      const double rad = radius + (r - radius) * delta, rz = fractoriumZeps(r);
      outX[i] += w * rad * x[i] / rz;
      outY[i] += w * rad * y[i] / rz;
    }
    outZ[i] += w * z[i];
  }
}

// ---- blocks ------------------------------------------------------------------------------------

// The square to the disc: each coordinate divided by the elliptic xmax of its own axis, then its
// arcsine.
inline double blockAngle(double v, double r2) {
  const double t = r2 + 1.0, v2 = 2.0 * v;
  const double vmax = 0.5 * (safeSqrt(t + v2) + safeSqrt(t - v2));
  const double a = v / fractoriumZeps(vmax);
  return std::atan2(a, safeSqrt(1.0 - a * a));
}

VOXFLAME_VARIATION_2D(block, {
  const double r2 = x[i] * x[i] + y[i] * y[i];
  outX[i] += w * (2.0 / kPi) * blockAngle(x[i], r2);
  outY[i] += w * (2.0 / kPi) * blockAngle(y[i], r2);
})

// block scaled per axis and by 1/((cos x + cos y)/mp + 1). The weight enters twice, as in Fractorium.
VOXFLAME_VARIATION_TARGETS void blocky(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double mp = fractoriumNonzero(P[2]);
  const double vx = w / (kPi / 2.0) * P[0], vy = w / (kPi / 2.0) * P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w / fractoriumZeps((std::cos(x[i]) + std::cos(y[i])) / mp + 1.0);
    const double r2 = x[i] * x[i] + y[i] * y[i];
    outX[i] += vx * blockAngle(x[i], r2) * r;
    outY[i] += vy * blockAngle(y[i], r2) * r;
    outZ[i] += w * z[i];
  }
}

// ---- circles -----------------------------------------------------------------------------------

VOXFLAME_VARIATION_TARGETS void cardioid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i], rz = fractoriumZeps(std::sqrt(r2));
    const double r = w * std::sqrt(r2 + std::sin(std::atan2(y[i], x[i]) * a) + 1.0);
    outX[i] += r * x[i] / rz;
    outY[i] += r * y[i] / rz;
    outZ[i] += w * z[i];
  }
}

// Inside the ring between inner and outer the point itself; outside it, the point on the outer
// circle at (sin φ, cos φ) (Fractorium's order, a mirror of the direction), or the origin while zero
// is not 0.
VOXFLAME_VARIATION_TARGETS void circlecrop2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double inner = std::min(P[0], P[1]), outer = std::max(P[0], P[1]);
  const bool zero = fractoriumClamp(P[2], 0.0, 1.0) != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    double s = 0.0, c = 0.0;
    if (r > outer || r < inner) {
      if (!zero) {
        const double a = std::atan2(y[i], x[i]);
        s = std::sin(a) * outer * w;
        c = std::cos(a) * outer * w;
      }
    } else {
      s = x[i] * w;
      c = y[i] * w;
    }
    outX[i] += s;
    outY[i] += c;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void circlesplit(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], split = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    double px = x[i], py = y[i];
    if (!(r < radius - split)) {
      const double a = std::atan2(y[i], x[i]), len = r + split;
      px = std::cos(a) * len;
      py = std::sin(a) * len;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// The square of half-side s = max(|x|, |y|) onto the circle: the position along its perimeter
// (0 … 8s from the +x axis) becomes the angle.
inline double circlizeAngle(double px, double py, double& side) {
  const double ax = std::abs(px), ay = std::abs(py);
  double perimeter;
  if (ax >= ay) {
    perimeter = px >= ay ? ax + py : 5.0 * ax - py;
    side = ax;
  } else {
    perimeter = py >= ax ? 3.0 * ay - px : 7.0 * ay + px;
    side = ay;
  }
  return kPi / 4.0 * perimeter / side - kPi / 4.0;
}

// Radius 4s/π + hole (the weight on the first term only, as Fractorium's precalc has it).
VOXFLAME_VARIATION_TARGETS void circlize(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double hole = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    double side = 0.0;
    const double a = circlizeAngle(x[i], y[i], side);
    const double r = w / (kPi / 4.0) * side + hole;
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void circlize2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double hole = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    double side = 0.0;
    const double a = circlizeAngle(x[i], y[i], side);
    const double r = w * (side + hole);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// The radius times scale inside the unit circle, divided by it outside.
VOXFLAME_VARIATION_TARGETS void circus(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = P[0], inverse = 1.0 / P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double r0 = std::sqrt(x[i] * x[i] + y[i] * y[i]), rz = fractoriumZeps(r0);
    const double r = r0 <= 1.0 ? r0 * scale : r0 * inverse;
    outX[i] += w * r * x[i] / rz;
    outY[i] += w * r * y[i] / rz;
    outZ[i] += w * z[i];
  }
}

// φ folded into num sectors of π/num each way from the x axis, alternate sectors turned by ±πa/num.
VOXFLAME_VARIATION_TARGETS void collideoscope(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double num = fractoriumZeps(P[1]);
  const double knPi = num / kPi, piKn = kPi / num, kaKn = kPi * P[0] / num;
  for (std::size_t i = 0; i < n; ++i) {
    double a = std::atan2(y[i], x[i]);
    const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    if (a >= 0.0) {
      const double alt = std::trunc(a * knPi);
      a = alt * piKn + std::fmod(isOddWhole(alt) ? a - kaKn : a + kaKn, piKn);
    } else {
      const double alt = std::trunc(-a * knPi);
      a = -(alt * piKn + std::fmod(isOddWhole(alt) ? -kaKn - a : kaKn - a, piKn));
    }
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// Each coordinate, mapped to u = (v + 1)/2, blended towards ½ − ½cos(4u + πphase) and that of u's
// fractional part after repeat; the blend amount ½ − ½cos(amount + πphase). Fractorium writes
// −1 + 2w·(…): the −1 outside the weight.
VOXFLAME_VARIATION_TARGETS void coswrap(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double repeat = std::abs(fractoriumIntegerNonzero(P[0]));
  const double px = kPi * fractoriumCyclic(P[3], -1.0, 1.0), py = kPi * fractoriumCyclic(P[4], -1.0, 1.0);
  const double blendX = 0.5 - std::cos(P[1] + px) * 0.5, blendY = 0.5 - std::cos(P[2] + py) * 0.5;
  const auto wrap = [&](double v, double phase, double blend) {
    const double u = 0.5 * v + 0.5;
    const double b = std::fmod(repeat * u, 1.0);  // modf's fractional part: the sign of repeat·u
    const double near = u + (0.5 - std::cos(u * 4.0 + phase) * 0.5 - u) * blend;
    return near + (0.5 - std::cos(b * 4.0 + phase) * 0.5 - near) * blend;
  };
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += -1.0 + 2.0 * w * wrap(x[i], px, blendX);
    outY[i] += -1.0 + 2.0 * w * wrap(y[i], py, blendY);
    outZ[i] += w * z[i];
  }
}

// sin² x (1 + cosh y) (sin x, cos x).
VOXFLAME_VARIATION_2D(crescents, {
  const double s = std::sin(x[i]), c = std::cos(x[i]), k = w * (std::cosh(y[i]) + 1.0) * s * s;
  outX[i] += k * s;
  outY[i] += k * c;
})

// (w/r, φ): Fractorium leaves the weight off φ.
VOXFLAME_VARIATION_2D(curvature, {
  outX[i] += w / fractoriumZeps(std::sqrt(x[i] * x[i] + y[i] * y[i]));
  outY[i] += std::atan2(y[i], x[i]);
})

VOXFLAME_VARIATION_2D(cylinder2, {
  outX[i] += w * (x[i] / fractoriumZeps(std::sqrt(x[i] * x[i] + 1.0)));
  outY[i] += w * y[i];
})

// The ratio of the distances to (−1, 0) and (1, 0) at half the difference of the angles seen from them.
VOXFLAME_VARIATION_2D(deltaa, {
  const double y2 = y[i] * y[i];
  const double r = w * (std::sqrt(y2 + (x[i] + 1.0) * (x[i] + 1.0)) / std::sqrt(y2 + (x[i] - 1.0) * (x[i] - 1.0)));
  const double a = (std::atan2(y[i], x[i] - 1.0) - std::atan2(y[i], x[i] + 1.0)) / 2.0;
  outX[i] += r * std::cos(a);
  outY[i] += r * std::sin(a);
})

}  // namespace

void variation_kernels::addFractorium2DVariationsA(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  add("arcsech", "(1/π) ln(q + √(q + 1) √(q − 1)), q = 1/(x + iy) (principal branches), z", k2D, kFixed, &arcsech);
  add("arcsech2",
      "(2/π) arcsech as above, = (u, v): (u, v + 1/w) where v < 0, else (−u, v − 1/w) (the ±1 outside the weight, as "
      "Fractorium has it; w the weight), z",
      k2D, kFixed, &arcsech2);
  add("arcsinh", "(2/π) ln(q + √(q² + 1)), q = x + iy, z", k2D, kFixed, &arcsinh);
  add("arctanh", "(1/π) ln((1 + q)/(1 − q)), q = x + iy, z", k2D, kFixed, &arctanh);
  add("barycentroid",
      "(sgn u √(u² + x²), sgn v √(v² + y²)), z; (u, v) the point's coordinates in the basis (a, b), (c, d)", k2D,
      kFixed, &barycentroid,
      {{"a", 1.0, -2.0, 2.0}, {"b", 0.0, -2.0, 2.0}, {"c", 0.0, -2.0, 2.0}, {"d", 1.0, -2.0, 2.0}});
  add("bCollide",
      "(sinh τ, sin σ)/(cosh τ − cos σ), z; τ = ln(d₊/d₋), σ = π − atan2(y, x + 1) − atan2(y, 1 − x) (bipolar), σ "
      "in sectors of π/num, alternate ones turned by ±πa/num",
      k2D, kFixed, &bCollide, {{"a", 0.0, -1.0, 1.0}, {"num", 1.0, 1.0, 10.0}});
  add("bisplit", "0.1 (cos y / tan x, −y / sin x), z", k2D, kFixed, &bisplit);
  add("blob2",
      "p where r < radius, else (radius + (r − radius) D)(cos φ, sin φ); D = |δ|^prescale postscale (mode, or sgn δ "
      "when mode is 0), δ = (sin(n φ) + symmetry)/(1 + compensation |symmetry|); z",
      k2D, kFixed, &blob2,
      {{"mode", 0.5, -2.0, 2.0},
       {"n", 1.0, 0.0, 20.0},
       {"radius", 0.0, 0.0, 2.0},
       {"prescale", 1.0, -2.0, 4.0},
       {"postscale", 0.5, -2.0, 2.0},
       {"symmetry", 0.0, -1.0, 1.0},
       {"compensation", 0.0, 0.0, 1.0}});
  add("block",
      "(2/π)(asin(x/X), asin(y/Y)), z; X = (√(r² + 1 + 2x) + √(r² + 1 − 2x))/2, Y likewise with y (a square to the "
      "disc)",
      k2D, kFixed, &block);
  add("blocky",
      "(2w/π)(x' asin(x/X), y' asin(y/Y)) / ((cos x + cos y)/mp + 1), X, Y as in block, x', y' the parameters x, y "
      "(the weight w enters twice, as in Fractorium), z",
      k2D, kFixed, &blocky, {{"x", 1.0, -2.0, 2.0}, {"y", 1.0, -2.0, 2.0}, {"mp", 4.0, 0.5, 10.0}});
  add("bMod",
      "(sinh τ, sin σ)/(cosh τ − cos σ), z (bipolar τ, σ as in bCollide); τ within ±radius becomes ((τ + radius (1 + "
      "distance)) mod 2 radius) − radius",
      k2D, kFixed, &bMod, {{"radius", 1.0, 0.0, 4.0}, {"distance", 0.0, 0.0, 2.0}});
  add("bSwirl", "(sinh τ, sin σ')/(cosh τ − cos σ'), z (bipolar τ, σ as in bCollide); σ' = σ + out τ + in/τ", k2D,
      kFixed, &bSwirl, {{"in", 0.0, -2.0, 2.0}, {"out", 0.0, -2.0, 2.0}});
  add("cardioid", "√(r² + sin(a φ) + 1) (cos φ, sin φ), z", k2D, kFixed, &cardioid, {{"a", 1.0, -4.0, 4.0}});
  add("circlecrop2",
      "p where inner ≤ r ≤ outer (the smaller and larger of the two); outside, outer (sin φ, cos φ), or (0, 0) while "
      "zero is not 0; z",
      k2D, kFixed, &circlecrop2, {{"inner", 0.5, 0.0, 2.0}, {"outer", 1.0, 0.0, 2.0}, {"zero", 1.0, 0.0, 1.0}});
  add("circlesplit", "p where r < radius − split, else (r + split)(cos φ, sin φ); z", k2D, kFixed, &circlesplit,
      {{"radius", 1.0, 0.0, 2.0}, {"split", 0.5, -1.0, 1.0}});
  add("circlize",
      "(4 s/π + hole/w)(cos a, sin a), z; s = max(|x|, |y|), a = (π/4)(t/s − 1), t the position along the square of "
      "half-side s (0 … 8s from the +x axis)",
      k2D, kFixed, &circlize, {{"hole", 0.0, -2.0, 2.0}});
  add("circlize2", "(s + hole)(cos a, sin a), z; s and a as in circlize", k2D, kFixed, &circlize2,
      {{"hole", 0.0, -2.0, 2.0}});
  add("circus", "r' (cos φ, sin φ), z; r' = r·scale where r ≤ 1, else r/scale", k2D, kFixed, &circus,
      {{"scale", 1.0, 0.1, 4.0}});
  add("collideoscope",
      "r (cos φ', sin φ'), z; φ' = φ in sectors of π/num (mirrored below the x axis), alternate ones turned by "
      "±πa/num",
      k2D, kFixed, &collideoscope, {{"a", 0.0, -1.0, 1.0}, {"num", 1.0, 1.0, 10.0}});
  add("coswrap",
      "(−1/w + 2 W(x, ax, px), −1/w + 2 W(y, ay, py)), z; u = (v + 1)/2, W = lerp(lerp(u, F(u), k), F(frac(|repeat| "
      "u)), k), F(t) = ½ − ½ cos(4t + π phase), k = ½ − ½ cos(amount + π phase) (the −1 outside the weight w, as "
      "Fractorium has it)",
      k2D, kFixed, &coswrap,
      {count("repeat", 1.0, 1.0, 10.0),
       {"amount_x", 0.0, -4.0, 4.0},
       {"amount_y", 0.0, -4.0, 4.0},
       {"phase_x", 0.0, -1.0, 1.0},
       {"phase_y", 0.0, -1.0, 1.0}});
  add("crescents", "sin² x (1 + cosh y) (sin x, cos x), z", k2D, kFixed, &crescents);
  add("curvature", "(1/r, φ/w), z (Fractorium leaves the weight w off φ)", k2D, kFixed, &curvature);
  add("cylinder2", "(x/√(x² + 1), y), z", k2D, kFixed, &cylinder2);
  add("deltaa", "(d₊/d₋)(cos a, sin a), z; d± = √(y² + (x ± 1)²), a = (atan2(y, x − 1) − atan2(y, x + 1))/2", k2D,
      kFixed, &deltaa);
}

}  // namespace voxflame::core
