#include "flame_variations.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "error.h"

namespace voxflame::core {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Our own guard where flam3 divides by r unguarded (sin θ = x / r at the origin would be 0/0): small
// enough to change no result away from the origin.
constexpr double kEpsilon = 1e-300;
// flam3's EPS, used exactly where flam3 adds it (to a parameter such as rings' c² or to a
// denominator), so imported flames come out as flam3 draws them.
constexpr double kFlam3Eps = 1e-10;

// A count parameter (sides, power, slices) as used: rounded, 0 taken as 1 so nothing divides by 0.
// Stays a double: converting a huge or NaN value to an integer would be undefined behaviour.
inline double countParam(double value) {
  const double rounded = std::round(value);
  return rounded == 0.0 ? 1.0 : rounded;
}

// flam3's affine coefficients inside the row-major 3×4 pre-affine (see flame.h).
constexpr std::size_t kAffineB = 1;  // m01
constexpr std::size_t kAffineC = 3;  // t0
constexpr std::size_t kAffineE = 5;  // m11
constexpr std::size_t kAffineF = 7;  // t1

// The arrays of a variation call as restrict-qualified locals: GCC vectorises loops over arrays it
// knows do not alias. The outputs must carry `__restrict` in the function's own parameters too:
// GCC 12 does not vectorise stores through a restrict local copied from an unqualified parameter
// (it left even `linear` scalar). Loops that call sin, cos, atan2 or pow stay scalar, as libm has
// no vector variants without -ffast-math; those without such calls vectorise.
#define VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz) \
  const double* __restrict x = (in).x;           \
  const double* __restrict y = (in).y;           \
  const double* __restrict z = (in).z;           \
  std::uint32_t* __restrict rnd = (in).random;   \
  double* __restrict outX = (ox);                \
  double* __restrict outY = (oy);                \
  double* __restrict outZ = (oz);                \
  const std::size_t n = (in).count;              \
  const double w = (in).weight;                  \
  const double* __restrict P = (in).params;      \
  (void)x;                                       \
  (void)y;                                       \
  (void)z;                                       \
  (void)rnd;                                     \
  (void)outX;                                    \
  (void)outY;                                    \
  (void)P;

// Each variation is built for AVX2 and for any x86-64, picked when the program loads: with AVX2
// the loops that vectorise run four lanes at a time.
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__SANITIZE_THREAD__)
#define VOXFLAME_VARIATION_TARGETS [[gnu::target_clones("avx2", "default")]]
#else
#define VOXFLAME_VARIATION_TARGETS
#endif

// ---- flam3's classics: x and y mapped, z carried through -------------------------------------

VOXFLAME_VARIATION_TARGETS void linear(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * x[i];
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void sinusoidal(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]);
    outY[i] += w * std::sin(y[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void spherical(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (x[i] * x[i] + y[i] * y[i] + kEpsilon);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void swirl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double s = std::sin(r2), c = std::cos(r2);
    outX[i] += w * (x[i] * s - y[i] * c);
    outY[i] += w * (x[i] * c + y[i] * s);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void horseshoe(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + kFlam3Eps);
    outX[i] += s * (x[i] - y[i]) * (x[i] + y[i]);
    outY[i] += s * 2.0 * x[i] * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void polar(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::atan2(x[i], y[i]) / kPi;
    outY[i] += w * (std::sqrt(x[i] * x[i] + y[i] * y[i]) - 1.0);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void handkerchief(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = std::atan2(x[i], y[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    outX[i] += w * r * std::sin(theta + r);
    outY[i] += w * r * std::cos(theta - r);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void heart(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double a = r * std::atan2(x[i], y[i]);
    outX[i] += w * r * std::sin(a);
    outY[i] -= w * r * std::cos(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void disc(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(x[i], y[i]) / kPi;
    const double r = kPi * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    outX[i] += w * std::sin(r) * a;
    outY[i] += w * std::cos(r) * a;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void spiral(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double rawR = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double sinTheta = x[i] / (rawR + kEpsilon), cosTheta = y[i] / (rawR + kEpsilon);
    const double r = rawR + kFlam3Eps;
    const double s = w / r;
    outX[i] += s * (cosTheta + std::sin(r));
    outY[i] += s * (sinTheta - std::cos(r));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void hyperbolic(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double rawR = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double sinTheta = x[i] / (rawR + kEpsilon), cosTheta = y[i] / (rawR + kEpsilon);
    const double r = rawR + kFlam3Eps;
    outX[i] += w * sinTheta / r;
    outY[i] += w * cosTheta * r;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void diamond(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double sinTheta = x[i] / (r + kEpsilon), cosTheta = y[i] / (r + kEpsilon);
    outX[i] += w * sinTheta * std::cos(r);
    outY[i] += w * cosTheta * std::sin(r);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void ex(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                   double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = std::atan2(x[i], y[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double n0 = std::sin(theta + r), n1 = std::cos(theta - r);
    const double m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
    outX[i] += w * (m0 + m1);
    outY[i] += w * (m0 - m1);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void julia(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 0.5 * std::atan2(x[i], y[i]) + (laneUniform(rnd[i]) < 0.5 ? 0.0 : kPi);
    const double r = w * std::sqrt(std::sqrt(x[i] * x[i] + y[i] * y[i]));
    outX[i] += r * std::cos(angle);
    outY[i] += r * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void bent(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] < 0.0 ? 2.0 * x[i] : x[i]);
    outY[i] += w * (y[i] < 0.0 ? 0.5 * y[i] : y[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void waves(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double b = in.affine[kAffineB], c = in.affine[kAffineC];
  const double e = in.affine[kAffineE], f = in.affine[kAffineF];
  const double dx2 = 1.0 / (c * c + kFlam3Eps), dy2 = 1.0 / (f * f + kFlam3Eps);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + b * std::sin(y[i] * dx2));
    outY[i] += w * (y[i] + e * std::sin(x[i] * dy2));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void fisheye(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 2.0 * w / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1.0);
    outX[i] += s * y[i];  // swapped, as flam3 has always drawn it (eyefish is the unswapped fix)
    outY[i] += s * x[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void popcorn(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c = in.affine[kAffineC], f = in.affine[kAffineF];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + c * std::sin(std::tan(3.0 * y[i])));
    outY[i] += w * (y[i] + f * std::sin(std::tan(3.0 * x[i])));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void exponential(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double d = w * std::exp(x[i] - 1.0);
    const double a = kPi * y[i];
    outX[i] += d * std::cos(a);
    outY[i] += d * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void power(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double sinTheta = x[i] / (r + kEpsilon), cosTheta = y[i] / (r + kEpsilon);
    const double s = w * std::pow(r, sinTheta);
    outX[i] += s * cosTheta;
    outY[i] += s * sinTheta;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void cosine(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kPi * x[i];
    outX[i] += w * std::cos(a) * std::cosh(y[i]);
    outY[i] -= w * std::sin(a) * std::sinh(y[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void rings(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c = in.affine[kAffineC];
  const double dx = c * c + kFlam3Eps;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double sinTheta = x[i] / (r + kEpsilon), cosTheta = y[i] / (r + kEpsilon);
    const double s = w * (std::fmod(r + dx, 2.0 * dx) - dx + r * (1.0 - dx));
    outX[i] += s * cosTheta;
    outY[i] += s * sinTheta;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void fan(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                    double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c = in.affine[kAffineC], f = in.affine[kAffineF];
  const double dx = kPi * (c * c + kFlam3Eps);
  const double half = 0.5 * dx;
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = std::atan2(x[i], y[i]);
    const double a = theta + (std::fmod(theta + f, dx) > half ? -half : half);
    const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void blob(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double low = P[0], high = P[1], wavesCount = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double rawR = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double theta = std::atan2(x[i], y[i]);
    const double sinTheta = x[i] / (rawR + kEpsilon), cosTheta = y[i] / (rawR + kEpsilon);
    const double r = rawR * (low + (high - low) * (0.5 + 0.5 * std::sin(wavesCount * theta)));
    outX[i] += w * sinTheta * r;
    outY[i] += w * cosTheta * r;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void pdj(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                    double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1], c = P[2], d = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (std::sin(a * y[i]) - std::cos(b * x[i]));
    outY[i] += w * (std::sin(c * x[i]) - std::cos(d * y[i]));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void fan2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double dy = P[1];
  const double dx = kPi * (P[0] * P[0] + kFlam3Eps);
  const double half = 0.5 * dx;
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = std::atan2(x[i], y[i]);
    const double t = theta + dy - dx * std::trunc((theta + dy) / dx);
    const double a = t > half ? theta - half : theta + half;
    const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    outX[i] += r * std::sin(a);
    outY[i] += r * std::cos(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void rings2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double dx = P[0] * P[0] + kFlam3Eps;
  for (std::size_t i = 0; i < n; ++i) {
    const double rawR = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double sinTheta = x[i] / (rawR + kEpsilon), cosTheta = y[i] / (rawR + kEpsilon);
    const double r = rawR - 2.0 * dx * std::trunc((rawR + dx) / (2.0 * dx)) + rawR * (1.0 - dx);
    outX[i] += w * sinTheta * r;
    outY[i] += w * cosTheta * r;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void eyefish(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 2.0 * w / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1.0);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void bubble(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (0.25 * (x[i] * x[i] + y[i] * y[i]) + 1.0);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void cylinder(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]);
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void perspective(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double angle = P[0] * kPi / 2.0, dist = P[1];
  const double vsin = std::sin(angle), vfcos = dist * std::cos(angle);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 1.0 / (dist - y[i] * vsin);
    outX[i] += w * dist * x[i] * t;
    outY[i] += w * vfcos * y[i] * t;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void noise(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double s = w * laneUniform(rnd[i]);
    outX[i] += x[i] * s * std::cos(a);
    outY[i] += y[i] * s * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void julian(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]);
  const double rootCount = std::abs(powerN);
  const double exponent = P[1] / powerN / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double root = std::trunc(rootCount * laneUniform(rnd[i]));
    const double a = (std::atan2(y[i], x[i]) + kTwoPi * root) / powerN;
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], exponent);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void juliascope(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]);
  const double rootCount = std::abs(powerN);
  const double exponent = P[1] / powerN / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double root = std::trunc(rootCount * laneUniform(rnd[i]));
    const double phi = std::atan2(y[i], x[i]);
    const bool odd = root - 2.0 * std::floor(0.5 * root) != 0.0;  // root ≥ 0: flam3's (t_rnd & 1)
    const double a = (kTwoPi * root + (odd ? -phi : phi)) / powerN;
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], exponent);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void blur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double r = w * laneUniform(rnd[i]);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// The sum of four uniforms less 2: flam3's cheap bell-shaped number in (−2, 2).
[[gnu::always_inline]] inline double laneGauss(std::uint32_t& state) {
  const double a = laneUniform(state), b = laneUniform(state), c = laneUniform(state), d = laneUniform(state);
  return a + b + c + d - 2.0;
}

VOXFLAME_VARIATION_TARGETS void gaussianBlur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double r = w * laneGauss(rnd[i]);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void radialBlur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double angle = P[0] * kPi / 2.0;
  const double spin = std::sin(angle), zoom = std::cos(angle);
  for (std::size_t i = 0; i < n; ++i) {
    const double g = w * laneGauss(rnd[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double a = std::atan2(y[i], x[i]) + spin * g;
    const double rz = zoom * g - 1.0;
    // flam3's form: the point itself is subtracted, so weight only scales the blur.
    outX[i] += r * std::cos(a) + rz * x[i];
    outY[i] += r * std::sin(a) + rz * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void pie(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                    double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double slices = countParam(P[0]), rotation = P[1], thickness = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double slice = std::trunc(laneUniform(rnd[i]) * slices + 0.5);
    const double a = rotation + kTwoPi * (slice + laneUniform(rnd[i]) * thickness) / slices;
    const double r = w * laneUniform(rnd[i]);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void ngon(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = countParam(P[0]), halfPower = P[1] / 2.0, circle = P[2], corners = P[3];
  const double b = kTwoPi / sides;
  for (std::size_t i = 0; i < n; ++i) {
    const double rFactor = std::pow(x[i] * x[i] + y[i] * y[i], halfPower);
    const double phi = std::atan2(y[i], x[i]);
    double wedge = phi - b * std::floor(phi / b);
    wedge = wedge > 0.5 * b ? wedge - b : wedge;
    const double amp = (corners * (1.0 / (std::cos(wedge) + kFlam3Eps) - 1.0) + circle) / (rFactor + kFlam3Eps);
    outX[i] += w * x[i] * amp;
    outY[i] += w * y[i] * amp;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void curl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c1 = P[0], c2 = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double re = 1.0 + c1 * x[i] + c2 * (x[i] * x[i] - y[i] * y[i]);
    const double im = c1 * y[i] + 2.0 * c2 * x[i] * y[i];
    const double s = w / (re * re + im * im);
    outX[i] += (x[i] * re + y[i] * im) * s;
    outY[i] += (y[i] * re - x[i] * im) * s;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void rectangles(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rx = P[0], ry = P[1];
  // A zero size leaves that axis linear; the division by it is computed and then not selected.
  const double safeX = rx == 0.0 ? 1.0 : rx, safeY = ry == 0.0 ? 1.0 : ry;
  for (std::size_t i = 0; i < n; ++i) {
    const double cellX = (2.0 * std::floor(x[i] / safeX) + 1.0) * safeX - x[i];
    const double cellY = (2.0 * std::floor(y[i] / safeY) + 1.0) * safeY - y[i];
    outX[i] += w * (rx == 0.0 ? x[i] : cellX);
    outY[i] += w * (ry == 0.0 ? y[i] : cellY);
    outZ[i] += w * z[i];
  }
}

// ---- 3D variations ---------------------------------------------------------------------------

VOXFLAME_VARIATION_TARGETS void spherical3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (x[i] * x[i] + y[i] * y[i] + z[i] * z[i] + kEpsilon);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += s * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void julia3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]);
  const double absPower = std::abs(powerN);
  const double exponent = (1.0 / powerN - 1.0) * 0.5;
  // JWildfire draws power −1 as spherical3D; the general formula would mirror y.
  const double ySign = powerN == -1.0 ? -1.0 : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double zs = z[i] / absPower;
    const double r2d = x[i] * x[i] + y[i] * y[i];
    const double r = w * std::pow(r2d + zs * zs + kEpsilon, exponent);
    const double r2 = r * std::sqrt(r2d);
    const double root = std::trunc(laneUniform(rnd[i]) * absPower);
    const double a = (std::atan2(y[i], x[i]) + kTwoPi * root) / powerN;
    outX[i] += r2 * std::cos(a);
    outY[i] += ySign * r2 * std::sin(a);
    outZ[i] += r * zs;
  }
}

VOXFLAME_VARIATION_TARGETS void julia3Dz(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]);
  const double absPower = std::abs(powerN);
  const double exponent = 0.5 / powerN;
  const double ySign = powerN == -1.0 ? -1.0 : 1.0;  // power −1 is JWildfire's 1/r² inversion
  const double quirk = absPower == 2.0 ? 1.0 : 0.0;  // JWildfire's ±2 case adds a second z term
  for (std::size_t i = 0; i < n; ++i) {
    const double r2d = x[i] * x[i] + y[i] * y[i] + kEpsilon;
    const double rho = std::sqrt(r2d);
    const double r = w * std::pow(r2d, exponent);
    const double root = std::trunc(laneUniform(rnd[i]) * absPower);
    const double a = (std::atan2(y[i], x[i]) + kTwoPi * root) / powerN;
    outX[i] += r * std::cos(a);
    outY[i] += ySign * r * std::sin(a);
    outZ[i] += r * z[i] / (rho * absPower) + quirk * r * z[i] / (2.0 * std::sqrt(rho));
  }
}

VOXFLAME_VARIATION_TARGETS void bubble3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double d = 0.25 * (x[i] * x[i] + y[i] * y[i]) + 1.0;
    const double s = w / d;
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * (2.0 / d - 1.0);
  }
}

VOXFLAME_VARIATION_TARGETS void hemisphere(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / std::sqrt(x[i] * x[i] + y[i] * y[i] + 1.0);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += s;
  }
}

VOXFLAME_VARIATION_TARGETS void cylinder3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = std::clamp(P[0], 0.0, 0.5), halfHeight = std::clamp(P[1], 0.0, 0.5);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double rho = radius * std::sqrt(laneUniform(rnd[i]));  // √: uniform over the disc's area
    const double h = halfHeight * (2.0 * laneUniform(rnd[i]) - 1.0);
    outX[i] += w * rho * std::cos(a);
    outY[i] += w * h;
    outZ[i] += w * rho * std::sin(a);
  }
}

VOXFLAME_VARIATION_TARGETS void sinusoidal3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]);
    outY[i] += w * std::sin(y[i]);
    outZ[i] += w * std::atan2(x[i] * x[i], y[i] * y[i]) * std::cos(z[i]);
  }
}

VOXFLAME_VARIATION_TARGETS void swirl3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double s = std::sin(r2), c = std::cos(r2);
    outX[i] += w * (x[i] * s - y[i] * c);
    outY[i] += w * (x[i] * c + y[i] * s);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void curl3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1], cz = P[2];
  const double c2 = cx * cx + cy * cy + cz * cz;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double s = w / (r2 * c2 + 2.0 * cx * x[i] - 2.0 * cy * y[i] + 2.0 * cz * z[i] + 1.0);
    outX[i] += s * (x[i] + cx * r2);
    outY[i] += s * (y[i] - cy * r2);
    outZ[i] += s * (z[i] + cz * r2);
  }
}

VOXFLAME_VARIATION_TARGETS void pie3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double slices = countParam(P[0]), rotation = P[1], thickness = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double slice = std::trunc(laneUniform(rnd[i]) * slices + 0.5);
    const double a = rotation + kTwoPi * (slice + laneUniform(rnd[i]) * thickness) / slices;
    const double r = w * laneUniform(rnd[i]);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += r * std::sin(r);
  }
}

VOXFLAME_VARIATION_TARGETS void blur3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double b = kPi * laneUniform(rnd[i]);
    const double r = w * laneGauss(rnd[i]);
    outX[i] += r * std::sin(b) * std::cos(a);
    outY[i] += r * std::sin(b) * std::sin(a);
    outZ[i] += r * std::cos(b);
  }
}

VOXFLAME_VARIATION_TARGETS void zblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * laneGauss(rnd[i]);
}

VOXFLAME_VARIATION_TARGETS void zscale(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * z[i];
}

VOXFLAME_VARIATION_TARGETS void ztranslate(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w;
}

VOXFLAME_VARIATION_TARGETS void zcone(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
}

#undef VOXFLAME_VARIATION_BEGIN

std::vector<VariationInfo> buildCatalogue() {
  std::vector<VariationInfo> c;
  const auto add = [&](std::string name, std::string formula, bool threeD, bool random, VariationFn fn,
                       std::vector<VariationParam> params = {}) {
    VariationInfo info;
    info.name = std::move(name);
    info.formula = std::move(formula);
    info.threeD = threeD;
    info.random = random;
    info.apply = fn;
    info.params = std::move(params);
    c.push_back(std::move(info));
  };
  constexpr bool k2D = false, k3D = true, kRandom = true, kFixed = false;
  const auto count = [](std::string name, double value, double low, double high) {
    return VariationParam{std::move(name), value, low, high, true};
  };

  // flam3's classics (variations.c), in flam3's order.
  add("linear", "(x, y, z)", k2D, kFixed, &linear);
  add("sinusoidal", "(sin x, sin y, z)", k2D, kFixed, &sinusoidal);
  add("spherical", "(x, y) / r², z", k2D, kFixed, &spherical);
  add("swirl", "(x sin r² − y cos r², x cos r² + y sin r², z)", k2D, kFixed, &swirl);
  add("horseshoe", "((x − y)(x + y), 2xy) / (r + ε), z", k2D, kFixed, &horseshoe);
  add("polar", "(θ/π, r − 1, z)", k2D, kFixed, &polar);
  add("handkerchief", "r (sin(θ + r), cos(θ − r)), z", k2D, kFixed, &handkerchief);
  add("heart", "r (sin(θr), −cos(θr)), z", k2D, kFixed, &heart);
  add("disc", "(θ/π)(sin πr, cos πr), z", k2D, kFixed, &disc);
  add("spiral", "(cos θ + sin r, sin θ − cos r) / r, z (r + ε)", k2D, kFixed, &spiral);
  add("hyperbolic", "(sin θ / r, r cos θ, z) (r + ε)", k2D, kFixed, &hyperbolic);
  add("diamond", "(sin θ cos r, cos θ sin r, z)", k2D, kFixed, &diamond);
  add("ex", "r (p0³ + p1³, p0³ − p1³), z; p0 = sin(θ + r), p1 = cos(θ − r)", k2D, kFixed, &ex);
  add("julia", "√r (cos(θ/2 + Ω), sin(θ/2 + Ω)), z; Ω = 0 or π at random", k2D, kRandom, &julia);
  add("bent", "(x < 0 ? 2x : x, y < 0 ? y/2 : y, z)", k2D, kFixed, &bent);
  add("waves", "(x + b sin(y / (c² + ε)), y + e sin(x / (f² + ε)), z); b, c, e, f of the pre-affine", k2D, kFixed,
      &waves);
  add("fisheye", "2 (y, x) / (r + 1), z (x and y swapped, as flam3 draws it)", k2D, kFixed, &fisheye);
  add("popcorn", "(x + c sin(tan 3y), y + f sin(tan 3x), z); c, f of the pre-affine", k2D, kFixed, &popcorn);
  add("exponential", "e^(x − 1) (cos πy, sin πy), z", k2D, kFixed, &exponential);
  add("power", "r^(sin θ) (cos θ, sin θ), z", k2D, kFixed, &power);
  add("cosine", "(cos πx cosh y, −sin πx sinh y, z)", k2D, kFixed, &cosine);
  add("rings", "ρ (cos θ, sin θ), z; ρ = ((r + d) mod 2d) − d + r(1 − d), d = c² + ε, c of the pre-affine", k2D, kFixed,
      &rings);
  add("fan",
      "r (cos α, sin α), z; t = π(c² + ε), α = θ − t/2 if (θ + f) mod t > t/2, else θ + t/2; c, f of the "
      "pre-affine",
      k2D, kFixed, &fan);
  add("blob", "r (low + (high − low)(½ + ½ sin(waves·θ))) (sin θ, cos θ), z", k2D, kFixed, &blob,
      {{"low", 0.3, 0.0, 1.0}, {"high", 1.0, 0.0, 2.0}, {"waves", 4.0, 0.0, 20.0}});
  add("pdj", "(sin(a y) − cos(b x), sin(c x) − cos(d y), z)", k2D, kFixed, &pdj,
      {{"a", 1.1, -3.0, 3.0}, {"b", 1.3, -3.0, 3.0}, {"c", -1.9, -3.0, 3.0}, {"d", -2.1, -3.0, 3.0}});
  add("fan2",
      "r (sin α, cos α), z; t = π(x² + ε), u = θ + y − t·trunc((θ + y)/t), α = θ − t/2 if u > t/2, else θ + t/2", k2D,
      kFixed, &fan2, {{"x", 0.6, -1.0, 1.0}, {"y", 0.4, -1.0, 1.0}});
  add("rings2", "ρ (sin θ, cos θ), z; ρ = r − 2d·trunc((r + d)/2d) + r(1 − d), d = val² + ε", k2D, kFixed, &rings2,
      {{"val", 0.5, 0.0, 2.0}});
  add("eyefish", "2 (x, y) / (r + 1), z", k2D, kFixed, &eyefish);
  add("bubble", "(x, y) / (r²/4 + 1), z", k2D, kFixed, &bubble);
  add("cylinder", "(sin x, y, z)", k2D, kFixed, &cylinder);
  add("perspective", "dist (x, y cos β) / (dist − y sin β), z; β = angle·π/2", k2D, kFixed, &perspective,
      {{"angle", 0.5, -1.0, 1.0}, {"dist", 2.0, 0.5, 5.0}});
  add("noise", "Ψ₂ (x cos 2πΨ₁, y sin 2πΨ₁), z", k2D, kRandom, &noise);
  add("julian", "r^(dist/power)·(cos α, sin α), z; α = (φ + 2πk)/power, k = trunc(|power|·Ψ)", k2D, kRandom, &julian,
      {count("power", 4.0, -12.0, 12.0), {"dist", 1.0, -3.0, 3.0}});
  add("juliascope", "r^(dist/power)·(cos α, sin α), z; α = (2πk ± φ)/power, k = trunc(|power|·Ψ), − for odd k", k2D,
      kRandom, &juliascope, {count("power", 4.0, -12.0, 12.0), {"dist", 1.0, -3.0, 3.0}});
  add("blur", "Ψ₂ (cos 2πΨ₁, sin 2πΨ₁), z", k2D, kRandom, &blur);
  add("gaussian_blur", "G (cos 2πΨ, sin 2πΨ), z; G = Ψ + Ψ + Ψ + Ψ − 2", k2D, kRandom, &gaussianBlur);
  add("radial_blur",
      "r (cos(φ + G sin β), sin(φ + G sin β)) + (G cos β − 1)(x, y), z; G = weight·(Ψ + Ψ + Ψ + Ψ − 2), "
      "β = angle·π/2 (flam3's: weight scales the blur, not the point)",
      k2D, kRandom, &radialBlur, {{"angle", 0.5, -1.0, 1.0}});
  add("pie", "Ψ₃ (cos α, sin α), z; α = rotation + 2π(trunc(Ψ₁·slices + ½) + Ψ₂·thickness)/slices", k2D, kRandom, &pie,
      {count("slices", 6.0, 1.0, 24.0), {"rotation", 0.0, -kPi, kPi}, {"thickness", 0.5, 0.0, 1.0}});
  add("ngon", "(x, y)(corners (1/(cos β + ε) − 1) + circle) / (r^power + ε), z; β = φ mod 2π/sides, in ±π/sides", k2D,
      kFixed, &ngon,
      {count("sides", 5.0, 1.0, 12.0),
       {"power", 3.0, 0.0, 6.0},
       {"circle", 1.0, 0.0, 3.0},
       {"corners", 2.0, 0.0, 6.0}});
  add("curl", "(x·re + y·im, y·re − x·im) / (re² + im²), z; re = 1 + c1 x + c2(x² − y²), im = c1 y + 2 c2 xy", k2D,
      kFixed, &curl, {{"c1", 1.0, -2.0, 2.0}, {"c2", 0.0, -1.0, 1.0}});
  add("rectangles", "((2⌊x/x₀⌋ + 1) x₀ − x, (2⌊y/y₀⌋ + 1) y₀ − y, z); an axis with size 0 stays linear", k2D, kFixed,
      &rectangles, {{"x", 1.0, 0.0, 3.0}, {"y", 1.0, 0.0, 3.0}});

  // 3D variations: Apophysis 3D and JWildfire (its classes of the same name), unless said otherwise.
  add("linear3D", "(x, y, z)", k3D, kFixed, &linear);
  add("spherical3D", "(x, y, z) / (x² + y² + z²)", k3D, kFixed, &spherical3D);
  add("julia3D",
      "ρ^(1/power − 1) (√(x² + y²) cos α, √(x² + y²) sin α, z/|power|); ρ = |(x, y, z/|power|)|, "
      "α = (φ + 2πk)/power, k = trunc(|power|·Ψ); power −1 is spherical3D (as JWildfire)",
      k3D, kRandom, &julia3D, {count("power", 3.0, -8.0, 8.0)});
  add("julia3Dz",
      "(x² + y²)^(1/(2·power)) (cos α, sin α, z/(|power| √(x² + y²))); α as julia3D; power ±2 adds JWildfire's "
      "second z term, power −1 is (x, y, z)/(x² + y²)",
      k3D, kRandom, &julia3Dz, {count("power", 3.0, -8.0, 8.0)});
  add("bubble3D", "(x, y, 2 − d) / d, d = r²/4 + 1: the plane wrapped onto the unit sphere (JWildfire's bubble)", k3D,
      kFixed, &bubble3D);
  add("hemisphere", "(x, y, 1) / √(r² + 1)", k3D, kFixed, &hemisphere);
  add("cylinder3D",
      "a random point of the solid cylinder of radius d and half-height H about the y axis: (ρ cos 2πΨ₁, "
      "H(2Ψ₃ − 1), ρ sin 2πΨ₁), ρ = d√Ψ₂ (what JWildfire's keeps; d, H in [0, ½])",
      k3D, kRandom, &cylinder3D, {{"d", 0.3, 0.0, 0.5}, {"H", 0.25, 0.0, 0.5}});
  add("sinusoidal3D", "(sin x, sin y, atan2(x², y²) cos z) (JWildfire's sinusoidal3d)", k3D, kFixed, &sinusoidal3D);
  add("swirl3D",
      "(x sin ρ² − y cos ρ², x cos ρ² + y sin ρ², z); ρ² = x² + y² + z² (ours: swirl about z by the 3D radius)", k3D,
      kFixed, &swirl3D);
  add("curl3D", "((x, y, z) + r²(cx, −cy, cz)) / (r²|c|² + 2cx x − 2cy y + 2cz z + 1); r² = x² + y² + z²", k3D, kFixed,
      &curl3D, {{"cx", 0.0, -1.0, 1.0}, {"cy", 0.05, -1.0, 1.0}, {"cz", 0.05, -1.0, 1.0}});
  add("pie3D", "pie's (x, y) with R = Ψ₃, and z = R sin R", k3D, kRandom, &pie3D,
      {count("slices", 7.0, 1.0, 24.0), {"rotation", 0.0, -kPi, kPi}, {"thickness", 0.5, 0.0, 1.0}});
  add("blur3D", "G (sin β cos α, sin β sin α, cos β); α = 2πΨ, β = πΨ, G = Ψ + Ψ + Ψ + Ψ − 2", k3D, kRandom, &blur3D);
  add("zblur", "(0, 0, Ψ + Ψ + Ψ + Ψ − 2)", k3D, kRandom, &zblur);
  add("zscale", "(0, 0, z): with linear, stretches depth", k3D, kFixed, &zscale);
  add("ztranslate", "(0, 0, 1): moves along z by the weight", k3D, kFixed, &ztranslate);
  add("zcone", "(0, 0, √(x² + y²))", k3D, kFixed, &zcone);
  return c;
}

}  // namespace

int VariationInfo::paramIndex(std::string_view paramName) const {
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].name == paramName) return static_cast<int>(i);
  return -1;
}

std::vector<double> VariationInfo::defaultParams() const {
  std::vector<double> values;
  values.reserve(params.size());
  for (const auto& p : params) values.push_back(p.defaultValue);
  return values;
}

const std::vector<VariationInfo>& variationCatalogue() {
  static const std::vector<VariationInfo> catalogue = buildCatalogue();
  return catalogue;
}

const VariationInfo* findVariation(std::string_view name) {
  for (const auto& info : variationCatalogue())
    if (info.name == name) return &info;
  return nullptr;
}

namespace {

std::string lowered(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return out;
}

// Levenshtein distance, for "did you mean": swapped or missing letters are the usual typos.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

const VariationInfo& variationOrThrow(std::string_view name) {
  if (const VariationInfo* info = findVariation(name)) return *info;
  // Close names: the same letters in another case, a shared three-letter start, or two edits away
  // (ignoring case and underscores, so "spherical_3d" finds "spherical3D").
  const std::string lower = lowered(name);
  std::string bare = lower;
  std::erase(bare, '_');
  std::string close;
  if (!lower.empty()) {
    for (const auto& info : variationCatalogue()) {
      const std::string candidate = lowered(info.name);
      std::string candidateBare = candidate;
      std::erase(candidateBare, '_');
      const bool near = candidate == lower || (lower.size() >= 3 && candidate.rfind(lower.substr(0, 3), 0) == 0) ||
                        editDistance(bare, candidateBare) <= 2;
      if (!near) continue;
      if (!close.empty()) close.append(", ");
      close.append(info.name);
    }
  }
  std::string message = "'";
  message.append(name);
  message.append("' is not a known variation");
  if (close.empty()) {
    message.append("; `voxflame list --variations` lists them");
  } else {
    message.append("; did you mean ");
    message.append(close);
    message.append("?");
  }
  throw Error(message);
}

namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A table cell: '|' would end the cell early.
std::string cell(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

}  // namespace

std::string variationsMarkdown() {
  std::ostringstream md;
  md << "# Flame variations\n\n"
     << "The variations a flame transform can use (`\"variations\": [{\"name\": ..., \"weight\": ..., "
        "PARAMETER: VALUE}]` in a preset;\nsee [SCHEMA.md](SCHEMA.md)). Parameters left out take the default "
        "shown; the range is the slider's,\nnot a limit. This file is generated from the catalogue: "
        "`voxflame list --variations --markdown > presets/VARIATIONS.md`.\n\n"
     << "Notation (flam3's): p = (x, y, z) is the point after the transform's affine map, r² = x² + y², "
        "θ = atan2(x, y),\nφ = atan2(y, x), ε = 10⁻¹⁰, Ψ a uniform random number in [0, 1) (a new one each "
        "time it appears), and\nb, c, e, f the pre-affine's coefficients as flam3 names them. Each formula "
        "is V(p); a transform adds\nweight · V(p). A 2D variation maps x and y and carries z through; a 3D one "
        "acts on z itself.\n\n"
     << "| name | kind | parameters (default, slider range) | formula |\n"
     << "| --- | --- | --- | --- |\n";
  for (const VariationInfo& info : variationCatalogue()) {
    std::string params;
    for (const VariationParam& p : info.params) {
      params += (params.empty() ? "" : "<br>") +
                ("`" + p.name + "` = " + formatNumber(p.defaultValue) + " (" + formatNumber(p.sliderMin) + " … " +
                 formatNumber(p.sliderMax) + (p.integer ? ", whole" : "") + ")");
    }
    md << "| `" << info.name << "` | " << (info.threeD ? "3D" : "2D") << (info.random ? ", random" : "") << " | "
       << (params.empty() ? "—" : params) << " | " << cell(info.formula) << " |\n";
  }
  return md.str();
}

}  // namespace voxflame::core
