#include "flame_variations.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "error.h"
#include "flame_noise.h"
#include "flame_variation_kernels.h"
#include "flame_variations_more.h"
#include "vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

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

// std::fmod(a, m) in a form GCC vectorises: libm's fmod has no vector variant (vector_math.h), and
// one scalar call keeps the whole loop scalar. a − m·trunc(a/m), moved back into fmod's range (the
// sign of a, magnitude below |m|) when the rounded quotient is one off; it differs from the exact
// fmod by at most an ulp of a. NaN where fmod is NaN (an infinite a, a zero m).
inline double laneFmod(double a, double m) {
  const double am = std::abs(m);
  double r = a - std::trunc(a / m) * m;
  r = a >= 0.0 ? (r < 0.0 ? r + am : r) : (r > 0.0 ? r - am : r);
  return a >= 0.0 ? (r >= am ? r - am : r) : (r <= -am ? r + am : r);
}

// flam3's own count-like parameters (julian's power, pie's slices, ngon's sides) are real numbers
// there, and files hold values such as 3.8967: used as they are, with 0 taken as 1 as above.
inline double flam3Count(double value) {
  return value == 0.0 ? 1.0 : value;
}

// flam3's affine coefficients inside the row-major 3×4 pre-affine (see flame.h).
constexpr std::size_t kAffineB = 1;  // m01
constexpr std::size_t kAffineC = 3;  // t0
constexpr std::size_t kAffineE = 5;  // m11
constexpr std::size_t kAffineF = 7;  // t1

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
    const double s = w * (laneFmod(r + dx, 2.0 * dx) - dx + r * (1.0 - dx));
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
    const double a = theta + (laneFmod(theta + f, dx) > half ? -half : half);
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
  const double powerN = flam3Count(P[0]);
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
  const double powerN = flam3Count(P[0]);
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
  const double slices = flam3Count(P[0]), rotation = P[1], thickness = P[2];
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
  const double sides = flam3Count(P[0]), halfPower = P[1] / 2.0, circle = P[2], corners = P[3];
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

// ---- the rest of flam3's variations (variations.c of flam3 3.1), x and y mapped, z carried ------
// A shorthand for the common shape: a loop over the lanes with x, y, z and the lane's random state
// in scope, where the body adds to outX[i] and outY[i]; z is carried through.
#define VOXFLAME_VARIATION_2D(fn, ...)                                                                       \
  VOXFLAME_VARIATION_TARGETS void fn(const VariationInput& in, double* __restrict ox, double* __restrict oy, \
                                     double* __restrict oz) {                                                \
    VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)                                                                 \
    for (std::size_t i = 0; i < n; ++i) {                                                                    \
      __VA_ARGS__                                                                                            \
      outZ[i] += w * z[i];                                                                                   \
    }                                                                                                        \
  }

VOXFLAME_VARIATION_2D(arch, {
  const double a = laneUniform(rnd[i]) * w * kPi;
  const double s = std::sin(a), c = std::cos(a);
  // flam3 skips the point when cos a is 0; a far smaller guard keeps it finite instead.
  outX[i] += w * s;
  outY[i] += w * s * s / (c == 0.0 ? kEpsilon : c);
})

VOXFLAME_VARIATION_2D(tangent, {
  outX[i] += w * std::sin(x[i]) / std::cos(y[i]);
  outY[i] += w * std::tan(y[i]);
})

VOXFLAME_VARIATION_2D(square, {
  const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]);
  outX[i] += w * (a - 0.5);
  outY[i] += w * (b - 0.5);
})

VOXFLAME_VARIATION_2D(rays, {
  const double a = w * laneUniform(rnd[i]) * kPi;
  const double r = w / (x[i] * x[i] + y[i] * y[i] + kFlam3Eps);
  const double t = w * std::tan(a) * r;
  outX[i] += t * std::cos(x[i]);
  outY[i] += t * std::sin(y[i]);
})

VOXFLAME_VARIATION_2D(blade, {
  const double r = laneUniform(rnd[i]) * w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
  const double s = std::sin(r), c = std::cos(r);
  outX[i] += w * x[i] * (c + s);
  outY[i] += w * x[i] * (c - s);
})

VOXFLAME_VARIATION_2D(secant2, {
  const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
  const double c = std::cos(r);
  const double ic = 1.0 / c;
  outX[i] += w * x[i];
  outY[i] += c < 0.0 ? w * (ic + 1.0) : w * (ic - 1.0);
})

VOXFLAME_VARIATION_2D(twintrian, {
  const double r = laneUniform(rnd[i]) * w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
  const double s = std::sin(r), c = std::cos(r);
  double diff = std::log10(s * s) + c;
  if (!std::isfinite(diff)) diff = -30.0;  // flam3's badvalue guard
  outX[i] += w * x[i] * diff;
  outY[i] += w * x[i] * (diff - s * kPi);
})

VOXFLAME_VARIATION_2D(cross, {
  const double s = x[i] * x[i] - y[i] * y[i];
  const double r = w * std::sqrt(1.0 / (s * s + kFlam3Eps));
  outX[i] += x[i] * r;
  outY[i] += y[i] * r;
})

VOXFLAME_VARIATION_TARGETS void disc2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rot = P[0], twist = P[1];
  const double timesPi = rot * kPi;
  double sinAdd = std::sin(twist), cosAdd = std::cos(twist) - 1.0;
  // flam3's precalculation: a twist beyond a full turn scales the offsets.
  if (twist > kTwoPi) {
    const double k = 1.0 + twist - kTwoPi;
    cosAdd *= k;
    sinAdd *= k;
  }
  if (twist < -kTwoPi) {
    const double k = 1.0 + twist + kTwoPi;
    cosAdd *= k;
    sinAdd *= k;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double t = timesPi * (x[i] + y[i]);
    const double r = w * std::atan2(x[i], y[i]) / kPi;
    outX[i] += (std::sin(t) + cosAdd) * r;
    outY[i] += (std::cos(t) + sinAdd) * r;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void superShape(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rndMix = P[0], m4 = P[1] / 4.0, n1 = P[2], n2 = P[3], n3 = P[4], holes = P[5];
  const double negInvN1 = -1.0 / (n1 == 0.0 ? kFlam3Eps : n1);
  for (std::size_t i = 0; i < n; ++i) {
    const double rr = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double theta = m4 * std::atan2(y[i], x[i]) + kPi / 4.0;
    const double t1 = std::pow(std::abs(std::cos(theta)), n2);
    const double t2 = std::pow(std::abs(std::sin(theta)), n3);
    const double r = w * ((rndMix * laneUniform(rnd[i]) + (1.0 - rndMix) * rr - holes) * std::pow(t1 + t2, negInvN1)) /
                     (rr + kEpsilon);
    outX[i] += r * x[i];
    outY[i] += r * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void flower(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double petals = P[0], holes = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = std::atan2(y[i], x[i]);
    const double r = w * (laneUniform(rnd[i]) - holes) * std::cos(petals * theta) /
                     (std::sqrt(x[i] * x[i] + y[i] * y[i]) + kEpsilon);
    outX[i] += r * x[i];
    outY[i] += r * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void conic(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double e = P[0], holes = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double rr = std::sqrt(x[i] * x[i] + y[i] * y[i]) + kEpsilon;
    const double ct = x[i] / rr;
    const double r = w * (laneUniform(rnd[i]) - holes) * e / (1.0 + e * ct) / rr;
    outX[i] += r * x[i];
    outY[i] += r * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void parabola(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double height = P[0], width = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double s = std::sin(r), c = std::cos(r);
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]);
    outX[i] += height * w * s * s * a;
    outY[i] += width * w * c * b;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void bent2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double bx = P[0], by = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] < 0.0 ? x[i] * bx : x[i]);
    outY[i] += w * (y[i] < 0.0 ? y[i] * by : y[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void bipolar(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shift = -kPi / 2.0 * P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double t = r2 + 1.0, x2 = 2.0 * x[i];
    double v = 0.5 * std::atan2(2.0 * y[i], r2 - 1.0) + shift;
    if (v > kPi / 2.0)
      v = -kPi / 2.0 + std::fmod(v + kPi / 2.0, kPi);
    else if (v < -kPi / 2.0)
      v = kPi / 2.0 - std::fmod(kPi / 2.0 - v, kPi);
    const double f = t + x2, g = t - x2;
    // flam3 skips the point where the logarithm is undefined; it is carried through unmapped here.
    const bool defined = g != 0.0 && f / g > 0.0;
    outX[i] += defined ? w * 0.25 * (2.0 / kPi) * std::log(f / g) : 0.0;
    outY[i] += defined ? w * (2.0 / kPi) * v : 0.0;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(boarders, {
  const double rx = std::rint(x[i]), ry = std::rint(y[i]);
  const double dx = x[i] - rx, dy = y[i] - ry;
  double px, py;
  if (laneUniform(rnd[i]) >= 0.75) {
    px = dx * 0.5 + rx;
    py = dy * 0.5 + ry;
  } else if (std::abs(dx) >= std::abs(dy)) {
    const double side = dx >= 0.0 ? 0.25 : -0.25;
    px = dx * 0.5 + rx + side;
    py = dy * 0.5 + ry + side * dy / (dx == 0.0 ? kEpsilon : dx);
  } else {
    const double side = dy >= 0.0 ? 0.25 : -0.25;
    py = dy * 0.5 + ry + side;
    px = dx * 0.5 + rx + side * dx / (dy == 0.0 ? kEpsilon : dy);
  }
  outX[i] += w * px;
  outY[i] += w * py;
})

VOXFLAME_VARIATION_2D(butterfly, {
  const double wx = w * 1.3029400317411197908970256609023;
  const double y2 = 2.0 * y[i];
  const double r = wx * std::sqrt(std::abs(y[i] * x[i]) / (kFlam3Eps + x[i] * x[i] + y2 * y2));
  outX[i] += r * x[i];
  outY[i] += r * y2;
})

VOXFLAME_VARIATION_TARGETS void cell(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double size = P[0] == 0.0 ? kFlam3Eps : P[0];
  const double inv = 1.0 / size;
  for (std::size_t i = 0; i < n; ++i) {
    double cx = std::floor(x[i] * inv), cy = std::floor(y[i] * inv);
    const double dx = x[i] - cx * size, dy = y[i] - cy * size;
    // flam3 interleaves the cells of the four quadrants into one quadrant.
    cy = cy >= 0.0 ? 2.0 * cy : -(2.0 * cy + 1.0);
    cx = cx >= 0.0 ? 2.0 * cx : -(2.0 * cx + 1.0);
    outX[i] += w * (dx + cx * size);
    outY[i] -= w * (dy + cy * size);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void cpow(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[2] == 0.0 ? 1.0 : P[2];
  const double va = kTwoPi / power, vc = P[0] / power, vd = P[1] / power;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(y[i], x[i]);
    const double lnr = 0.5 * std::log(x[i] * x[i] + y[i] * y[i]);
    const double angle = vc * a + vd * lnr + va * std::floor(power * laneUniform(rnd[i]));
    const double m = w * std::exp(vc * lnr - vd * a);
    outX[i] += m * std::cos(angle);
    outY[i] += m * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void curve(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double xamp = P[0], yamp = P[1];
  const double xlen = std::max(P[2] * P[2], 1e-20), ylen = std::max(P[3] * P[3], 1e-20);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + xamp * std::exp(-y[i] * y[i] / xlen));
    outY[i] += w * (y[i] + yamp * std::exp(-x[i] * x[i] / ylen));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(edisc, {
  const double t = x[i] * x[i] + y[i] * y[i] + 1.0, x2 = 2.0 * x[i];
  const double xmax = 0.5 * (std::sqrt(t + x2) + std::sqrt(t - x2));
  const double a1 = std::log(xmax + std::sqrt(xmax - 1.0));
  const double a2 = -std::acos(std::clamp(x[i] / xmax, -1.0, 1.0));
  const double ww = w / 11.57034632;
  const double snv = y[i] > 0.0 ? -std::sin(a1) : std::sin(a1);
  outX[i] += ww * std::cosh(a2) * std::cos(a1);
  outY[i] += ww * std::sinh(a2) * snv;
})

// √(1 + v) − 1 without the cancellation near v = 0 (Claude Heiland-Allen's [4,4] Padé approximant
// there, as JWildfire's elliptic mode 2 has it).
inline double sqrt1pm1(double v) {
  if (-0.0625 < v && v < 0.0625) {
    const double num = (((1.0 / 32.0 * v + 5.0 / 16.0) * v + 3.0 / 4.0) * v + 1.0 / 2.0) * v;
    const double den = (((1.0 / 256.0 * v + 5.0 / 32.0) * v + 15.0 / 16.0) * v + 7.0 / 4.0) * v + 1.0;
    return num / den;
  }
  return std::sqrt(1.0 + v) - 1.0;
}

// flam3's elliptic (mode 0), and JWildfire's modes: 1 takes the sign of y at random (JWildfire's
// default, mirroring the picture in y), 2 is Heiland-Allen's more precise form. Only mode 1 draws a
// uniform: flam3's mode stays deterministic (and is listed as such, so the flam3 oracle checks it).
VOXFLAME_VARIATION_TARGETS void elliptic(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double mode = std::round(P[0]);
  const double ww = w / (kPi / 2.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double sq = x[i] * x[i] + y[i] * y[i], x2 = 2.0 * x[i];
    if (mode == 2.0) {
      const double xmaxm1 = 0.5 * (sqrt1pm1(sq + x2) + sqrt1pm1(sq - x2));
      const double ssx = xmaxm1 < 0.0 ? 0.0 : std::sqrt(xmaxm1);
      const double a = x[i] / (1.0 + xmaxm1);
      outX[i] += ww * std::asin(std::clamp(a, -1.0, 1.0));
      outY[i] += (y[i] > 0.0 ? ww : -ww) * std::log1p(xmaxm1 + ssx);
    } else {
      const double t = sq + 1.0;
      const double xmax = 0.5 * (std::sqrt(t + x2) + std::sqrt(t - x2));
      const double a = x[i] / xmax;
      const double b = std::sqrt(std::max(0.0, 1.0 - a * a));
      const double ssx = std::sqrt(std::max(0.0, xmax - 1.0));
      const bool up = mode == 1.0 ? laneUniform(rnd[i]) < 0.5 : y[i] > 0.0;
      outX[i] += ww * std::atan2(a, b);
      outY[i] += (up ? ww : -ww) * std::log(xmax + ssx);
    }
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void escher(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double vc = 0.5 * (1.0 + std::cos(P[0])), vd = 0.5 * std::sin(P[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(y[i], x[i]);
    const double lnr = 0.5 * std::log(x[i] * x[i] + y[i] * y[i]);
    const double m = w * std::exp(vc * lnr - vd * a);
    const double angle = vc * a + vd * lnr;
    outX[i] += m * std::cos(angle);
    outY[i] += m * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(foci, {
  const double ex = 0.5 * std::exp(x[i]);
  const double enx = 0.25 / ex;
  const double t = w / (ex + enx - std::cos(y[i]));
  outX[i] += t * (ex - enx);
  outY[i] += t * std::sin(y[i]);
})

VOXFLAME_VARIATION_TARGETS void lazysusan(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double spin = P[0], space = P[1], twist = P[2], cx = P[3], cy = P[4];
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] - cx, py = y[i] + cy;
    const double r = std::sqrt(px * px + py * py);
    if (r < w) {
      const double a = std::atan2(py, px) + spin + twist * (w - r);
      outX[i] += w * r * std::cos(a) + cx;
      outY[i] += w * r * std::sin(a) - cy;
    } else {
      const double s = w * (1.0 + space / (r + kEpsilon));
      outX[i] += s * px + cx;
      outY[i] += s * py - cy;
    }
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(loonie, {
  const double r2 = x[i] * x[i] + y[i] * y[i], w2 = w * w;
  const double s = r2 < w2 ? w * std::sqrt(w2 / (r2 + kEpsilon) - 1.0) : w;
  outX[i] += s * x[i];
  outY[i] += s * y[i];
})

VOXFLAME_VARIATION_TARGETS void modulus(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double mx = P[0], my = P[1];
  const double xr = 2.0 * mx == 0.0 ? kEpsilon : 2.0 * mx, yr = 2.0 * my == 0.0 ? kEpsilon : 2.0 * my;
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] > mx ? -mx + std::fmod(x[i] + mx, xr) : x[i] < -mx ? mx - std::fmod(mx - x[i], xr) : x[i];
    const double py = y[i] > my ? -my + std::fmod(y[i] + my, yr) : y[i] < -my ? my - std::fmod(my - y[i], yr) : y[i];
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void oscilloscope(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double separation = P[0], tpf = kTwoPi * P[1], amplitude = P[2], damping = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = damping == 0.0
                         ? amplitude * std::cos(tpf * x[i]) + separation
                         : amplitude * std::exp(-std::abs(x[i]) * damping) * std::cos(tpf * x[i]) + separation;
    outX[i] += w * x[i];
    outY[i] += std::abs(y[i]) <= t ? -w * y[i] : w * y[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(polar2, {
  const double p = w / kPi;
  outX[i] += p * std::atan2(x[i], y[i]);
  outY[i] += 0.5 * p * std::log(x[i] * x[i] + y[i] * y[i]);
})

VOXFLAME_VARIATION_TARGETS void popcorn2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double px = P[0], py = P[1], c = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + px * std::sin(std::tan(y[i] * c)));
    outY[i] += w * (y[i] + py * std::sin(std::tan(x[i] * c)));
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(scry, {
  const double t = x[i] * x[i] + y[i] * y[i];
  const double r = 1.0 / (std::sqrt(t) * (t + 1.0 / (w + kFlam3Eps)) + kEpsilon);
  outX[i] += x[i] * r;
  outY[i] += y[i] * r;
})

VOXFLAME_VARIATION_TARGETS void separation(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx2 = P[0] * P[0], xin = P[1], sy2 = P[2] * P[2], yin = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = std::sqrt(x[i] * x[i] + sx2), ry = std::sqrt(y[i] * y[i] + sy2);
    outX[i] += x[i] > 0.0 ? w * (rx - x[i] * xin) : -w * (rx + x[i] * xin);
    outY[i] += y[i] > 0.0 ? w * (ry - y[i] * yin) : -w * (ry + y[i] * yin);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void split(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0] * kPi, sy = P[1] * kPi;
  for (std::size_t i = 0; i < n; ++i) {
    outY[i] += std::cos(x[i] * sx) >= 0.0 ? w * y[i] : -w * y[i];
    outX[i] += std::cos(y[i] * sy) >= 0.0 ? w * x[i] : -w * x[i];
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void splits(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] >= 0.0 ? x[i] + sx : x[i] - sx);
    outY[i] += w * (y[i] >= 0.0 ? y[i] + sy : y[i] - sy);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void stripes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double space = P[0], warp = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = std::floor(x[i] + 0.5), dx = x[i] - rx;
    outX[i] += w * (dx * (1.0 - space) + rx);
    outY[i] += w * (y[i] + dx * dx * warp);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void wedge(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double angle = P[0], hole = P[1], count = P[2], swirlAmount = P[3];
  const double compression = 1.0 - angle * count / kPi * 0.5;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    double a = std::atan2(y[i], x[i]) + swirlAmount * r;
    const double c = std::floor((count * a + kPi) / kPi * 0.5);
    a = a * compression + c * angle;
    outX[i] += w * (r + hole) * std::cos(a);
    outY[i] += w * (r + hole) * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void wedgeJulia(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double angle = P[0], count = P[1], powerN = P[2] == 0.0 ? 1.0 : P[2], dist = P[3];
  const double cn = dist / powerN / 2.0, rootCount = std::abs(powerN);
  const double compression = 1.0 - angle * count / kPi * 0.5;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], cn);
    const double root = std::trunc(rootCount * laneUniform(rnd[i]));
    double a = (std::atan2(y[i], x[i]) + kTwoPi * root) / powerN;
    const double c = std::floor((count * a + kPi) / kPi * 0.5);
    a = a * compression + c * angle;
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void wedgeSph(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double angle = P[0], count = P[1], hole = P[2], swirlAmount = P[3];
  const double compression = 1.0 - angle * count / kPi * 0.5;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 1.0 / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + kFlam3Eps);
    double a = std::atan2(y[i], x[i]) + swirlAmount * r;
    const double c = std::floor((count * a + kPi) / kPi * 0.5);
    a = a * compression + c * angle;
    outX[i] += w * (r + hole) * std::cos(a);
    outY[i] += w * (r + hole) * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void whorl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double inside = P[0], outside = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double d = w - r == 0.0 ? kEpsilon : w - r;
    const double a = std::atan2(y[i], x[i]) + (r < w ? inside : outside) / d;
    outX[i] += w * r * std::cos(a);
    outY[i] += w * r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void waves2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freqX = P[0], scaleX = P[1], freqY = P[2], scaleY = P[3], freqZ = P[4], scaleZ = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + scaleX * std::sin(y[i] * freqX));
    outY[i] += w * (y[i] + scaleY * std::sin(x[i] * freqY));
    // Apophysis 7X's z part (waves2_freqz, waves2_scalez); 0 carries z through.
    outZ[i] += w * (z[i] + scaleZ * std::sin(std::sqrt(x[i] * x[i] + y[i] * y[i]) * freqZ));
  }
}

// The complex functions of flam3 3: z = x + iy.
VOXFLAME_VARIATION_2D(complexExp, {
  const double e = w * std::exp(x[i]);
  outX[i] += e * std::cos(y[i]);
  outY[i] += e * std::sin(y[i]);
})

// JWildfire adds a base (flam3's is e).
VOXFLAME_VARIATION_TARGETS void complexLog(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double lnBase = std::log(P[0]);
  const double scale = 0.5 / (lnBase == 0.0 ? kEpsilon : lnBase);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * scale * std::log(x[i] * x[i] + y[i] * y[i]);
    outY[i] += w * std::atan2(y[i], x[i]);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(complexSin, {
  outX[i] += w * std::sin(x[i]) * std::cosh(y[i]);
  outY[i] += w * std::cos(x[i]) * std::sinh(y[i]);
})

VOXFLAME_VARIATION_2D(complexCos, {
  outX[i] += w * std::cos(x[i]) * std::cosh(y[i]);
  outY[i] -= w * std::sin(x[i]) * std::sinh(y[i]);
})

VOXFLAME_VARIATION_2D(complexTan, {
  const double d = w / (std::cos(2.0 * x[i]) + std::cosh(2.0 * y[i]));
  outX[i] += d * std::sin(2.0 * x[i]);
  outY[i] += d * std::sinh(2.0 * y[i]);
})

VOXFLAME_VARIATION_2D(complexSec, {
  const double d = 2.0 * w / (std::cos(2.0 * x[i]) + std::cosh(2.0 * y[i]));
  outX[i] += d * std::cos(x[i]) * std::cosh(y[i]);
  outY[i] += d * std::sin(x[i]) * std::sinh(y[i]);
})

VOXFLAME_VARIATION_2D(complexCsc, {
  const double d = 2.0 * w / (std::cosh(2.0 * y[i]) - std::cos(2.0 * x[i]));
  outX[i] += d * std::sin(x[i]) * std::cosh(y[i]);
  outY[i] -= d * std::cos(x[i]) * std::sinh(y[i]);
})

VOXFLAME_VARIATION_2D(complexCot, {
  const double d = w / (std::cosh(2.0 * y[i]) - std::cos(2.0 * x[i]));
  outX[i] += d * std::sin(2.0 * x[i]);
  outY[i] -= d * std::sinh(2.0 * y[i]);
})

VOXFLAME_VARIATION_2D(complexSinh, {
  outX[i] += w * std::sinh(x[i]) * std::cos(y[i]);
  outY[i] += w * std::cosh(x[i]) * std::sin(y[i]);
})

VOXFLAME_VARIATION_2D(complexCosh, {
  outX[i] += w * std::cosh(x[i]) * std::cos(y[i]);
  outY[i] += w * std::sinh(x[i]) * std::sin(y[i]);
})

VOXFLAME_VARIATION_2D(complexTanh, {
  const double d = w / (std::cos(2.0 * y[i]) + std::cosh(2.0 * x[i]));
  outX[i] += d * std::sinh(2.0 * x[i]);
  outY[i] += d * std::sin(2.0 * y[i]);
})

VOXFLAME_VARIATION_2D(complexSech, {
  const double d = 2.0 * w / (std::cos(2.0 * y[i]) + std::cosh(2.0 * x[i]));
  outX[i] += d * std::cos(y[i]) * std::cosh(x[i]);
  outY[i] -= d * std::sin(y[i]) * std::sinh(x[i]);
})

VOXFLAME_VARIATION_2D(complexCsch, {
  const double d = 2.0 * w / (std::cosh(2.0 * x[i]) - std::cos(2.0 * y[i]));
  outX[i] += d * std::sinh(x[i]) * std::cos(y[i]);
  outY[i] -= d * std::cosh(x[i]) * std::sin(y[i]);
})

VOXFLAME_VARIATION_2D(complexCoth, {
  const double d = w / (std::cosh(2.0 * x[i]) - std::cos(2.0 * y[i]));
  outX[i] += d * std::sinh(2.0 * x[i]);
  outY[i] += d * std::sin(2.0 * y[i]);
})

VOXFLAME_VARIATION_TARGETS void auger(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freq = P[0], augerWeight = P[1], sym = P[2], scale = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double s = std::sin(freq * x[i]), t = std::sin(freq * y[i]);
    const double dy = y[i] + augerWeight * (scale * s / 2.0 + std::abs(y[i]) * s);
    const double dx = x[i] + augerWeight * (scale * t / 2.0 + std::abs(x[i]) * t);
    outX[i] += w * (x[i] + sym * (dx - x[i]));
    outY[i] += w * dy;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void flux(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double spread = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double xpw = x[i] + w, xmw = x[i] - w;
    const double r = w * (2.0 + spread) *
                     std::sqrt(std::sqrt(y[i] * y[i] + xpw * xpw) / (std::sqrt(y[i] * y[i] + xmw * xmw) + kEpsilon));
    const double a = (std::atan2(y[i], xmw) - std::atan2(y[i], xpw)) * 0.5;
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void mobius(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double reA = P[0], imA = P[1], reB = P[2], imB = P[3], reC = P[4], imC = P[5], reD = P[6], imD = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double reU = reA * x[i] - imA * y[i] + reB, imU = reA * y[i] + imA * x[i] + imB;
    const double reV = reC * x[i] - imC * y[i] + reD, imV = reC * y[i] + imC * x[i] + imD;
    const double s = w / (reV * reV + imV * imV + kEpsilon);
    outX[i] += s * (reU * reV + imU * imV);
    outY[i] += s * (imU * reV - reU * imV);
    outZ[i] += w * z[i];
  }
}

// flam3's only pre-variation: a Gaussian blur added to the point before the other variations (a
// transform applies it first, as a pre_ term that adds; see flame_variations.h).
VOXFLAME_VARIATION_2D(preBlur, {
  const double g = w * laneGauss(rnd[i]);
  const double a = kTwoPi * laneUniform(rnd[i]);
  outX[i] += g * std::cos(a);
  outY[i] += g * std::sin(a);
})

// ---- plugins the corpus uses most (Apophysis 7X and JWildfire) ------------------------------------

VOXFLAME_VARIATION_2D(unpolar, {
  const double r = w / kPi * 0.5 * std::exp(y[i]);
  outX[i] += r * std::sin(x[i]);
  outY[i] += r * std::cos(x[i]);
})

VOXFLAME_VARIATION_TARGETS void sineblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerP = std::max(0.0, P[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double u = laneUniform(rnd[i]);
    const double r =
        w * (powerP == 1.0 ? std::acos(u * 2.0 - 1.0) : std::acos(std::exp(std::log(u) * powerP) * 2.0 - 1.0)) / kPi;
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// Michael Faber's glynnia (JWildfire's): a random one of two square-root branches, mirrored
// inside the unit circle. A point where a root is 0 (flam3-style plugins skip it) is carried
// through unmapped.
VOXFLAME_VARIATION_2D(glynnia, {
  const double half = w * std::sqrt(2.0) / 2.0;
  const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
  const double side = r >= 1.0 ? 1.0 : -1.0;
  if (laneUniform(rnd[i]) > 0.5) {
    const double d = std::sqrt(r + x[i]);
    if (d != 0.0) {
      outX[i] += side * half * d;
      outY[i] -= half / d * y[i];
    }
  } else {
    const double d = r + x[i];
    const double dx = std::sqrt(r * (y[i] * y[i] + d * d));
    if (dx != 0.0) {
      outX[i] += side * w / dx * d;
      outY[i] += w / dx * y[i];
    }
  }
})

// cyberxaos' epispiral (the Apophysis plugin; JWildfire's differs only at thickness 0, where it
// uses 1/cos(nφ) − holes).
VOXFLAME_VARIATION_TARGETS void epispiral(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double waves = P[0], thickness = P[1], holes = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = std::atan2(y[i], x[i]);
    const double c = std::cos(waves * theta);
    const double t = laneUniform(rnd[i]) * thickness / (c == 0.0 ? kEpsilon : c) - holes;
    outX[i] += w * t * std::cos(theta);
    outY[i] += w * t * std::sin(theta);
    outZ[i] += w * z[i];
  }
}

// Xyrus02's falloff2 (Apophysis 7X): a blur that grows with the distance from a centre, linear
// (type 0), in spherical coordinates (1; its z is sin σ without the radius, as the plugin has it)
// or Gaussian (2). The plugin's colour shift (mul_c) is not applied: a variation here moves
// points, not colours.
VOXFLAME_VARIATION_TARGETS void falloff2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = 0.04 * std::max(P[0], 1e-6), mindist = std::max(P[1], 0.0);
  const double mulX = std::clamp(P[2], 0.0, 1.0), mulY = std::clamp(P[3], 0.0, 1.0);
  const double mulZ = std::clamp(P[4], 0.0, 1.0);
  const double x0 = P[6], y0 = P[7], z0 = P[8];
  const bool invert = std::round(P[9]) >= 1.0;
  const double type = std::round(P[10]);
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - x0, dy = y[i] - y0, dz = z[i] - z0;
    double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (invert) d = 1.0 - d;
    d = std::max(0.0, (std::max(d, 0.0) - mindist) * scale);
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]), c = laneUniform(rnd[i]);
    double px, py, pz;
    if (type == 1.0) {
      const double rIn = std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]) + 1e-6;
      const double sigma = std::asin(std::clamp(z[i] / rIn, -1.0, 1.0)) + mulZ * a * d;
      const double phi = std::atan2(y[i], x[i]) + mulY * b * d;
      const double r = rIn + mulX * c * d;
      px = r * std::cos(sigma) * std::cos(phi);
      py = r * std::cos(sigma) * std::sin(phi);
      pz = std::sin(sigma);
    } else if (type >= 2.0) {
      const double sigma = d * a * kTwoPi, phi = d * b * kPi, r = d * c;
      px = x[i] + mulX * r * std::cos(sigma) * std::cos(phi);
      py = y[i] + mulY * r * std::cos(sigma) * std::sin(phi);
      pz = z[i] + mulZ * r * std::sin(sigma);
    } else {
      px = x[i] + mulX * a * d;
      py = y[i] + mulY * b * d;
      pz = z[i] + mulZ * c * d;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * pz;
  }
}

// Apophysis 7X's crop: points outside the rectangle are moved back into it, onto a band of
// scatter_area of its half-size inside the crossed edge at random (or to the origin with zero).
// The pre_/post_ forms (crop the point before or after the other variations) are the usual use.
VOXFLAME_VARIATION_TARGETS void crop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double x0 = std::min(P[0], P[2]), x1 = std::max(P[0], P[2]);
  const double y0 = std::min(P[1], P[3]), y1 = std::max(P[1], P[3]);
  const double scatter = std::clamp(P[4], -1.0, 1.0);
  const double bandX = (x1 - x0) * 0.5 * scatter, bandY = (y1 - y0) * 0.5 * scatter;
  const bool zero = std::round(P[5]) >= 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]);
    const bool outside = x[i] < x0 || x[i] > x1 || y[i] < y0 || y[i] > y1;
    double px = x[i] < x0 ? x0 + a * bandX : x[i] > x1 ? x1 - a * bandX : x[i];
    double py = y[i] < y0 ? y0 + b * bandY : y[i] > y1 ? y1 - b * bandY : y[i];
    if (outside && zero) px = py = 0.0;
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// Xyrus02's julian2 (Apophysis plugin, JWildfire): julian of the point after a second affine map
// (a b e / c d f).
VOXFLAME_VARIATION_TARGETS void julian2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]), exponent = P[1] / powerN * 0.5, rootCount = std::abs(powerN);
  const double a = P[2], b = P[3], c = P[4], d = P[5], e = P[6], f = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double px = a * x[i] + b * y[i] + e, py = c * x[i] + d * y[i] + f;
    const double root = std::trunc(rootCount * laneUniform(rnd[i]));
    const double angle = (std::atan2(py, px) + kTwoPi * root) / powerN;
    const double r = w * std::pow(px * px + py * py, exponent);
    outX[i] += r * std::cos(angle);
    outY[i] += r * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

// ---- JWildfire / Apophysis / Fractorium plugins (issue 25: what real flame files use) -------------

// slobo777's crackle (Apophysis plugin, JWildfire's CrackleFunc): a Voronoi cell pattern. Each
// point is a fresh random one on a blurred unit disc, pulled towards the centre of its cell by
// L^power · scale / L, L the point's Voronoi distance (0 at the centre, 1 at the edge). The cells
// form a square grid of side cellsize/2 whose centres move by distort · simplex noise of the cell's
// coordinates (slice z of the noise), as in the plugin; the plugin caches the centres near the
// origin, which changes nothing but speed, so they are worked out here each time.
struct CrackleCells {
  double halfSize, distort, slice;
  void centre(double cx, double cy, double* out) const {
    const double nx = simplexNoise3D(cx * 2.5, cy * 2.5, slice * 2.5);
    // Cross-over of x and y as in the plugin, so the two noises do not correlate.
    const double ny = simplexNoise3D(cy * 2.5 + 30.2, cx * 2.5 - 12.1, slice * 2.5 + 19.8);
    out[0] = (cx + distort * nx) * halfSize;
    out[1] = (cy + distort * ny) * halfSize;
  }
  // The 3×3 block of centres around cell (cx, cy), column by column (x outer, y inner).
  void block(double cx, double cy, double (*centres)[2]) const {
    int k = 0;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) centre(cx + di, cy + dj, centres[k++]);
  }
};

// Java's (int) floor(v), which saturates, as a double.
inline double javaFloorToInt(double v) {
  const double f = std::floor(v);
  if (!(f == f)) return 0.0;
  return std::clamp(f, -2147483648.0, 2147483647.0);
}

VOXFLAME_VARIATION_TARGETS void crackle(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = P[0], power = P[1], scale = P[3];
  const CrackleCells cells{cellsize / 2.0, P[2], P[4]};
  for (std::size_t i = 0; i < n; ++i) {
    outZ[i] += w * z[i];
    if (cellsize == 0.0) continue;  // the plugin's guard: no cells, nothing drawn
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]), c = laneUniform(rnd[i]);
    const double blurred = (a + b) / 2.0 + (c - 0.5) / 4.0;
    const double theta = kTwoPi * laneUniform(rnd[i]);
    const double ux = blurred * std::sin(theta), uy = blurred * std::cos(theta);
    double cx = javaFloorToInt(ux / cells.halfSize), cy = javaFloorToInt(uy / cells.halfSize);
    double centres[9][2];
    cells.block(cx, cy, centres);
    // Re-centre the block on the nearest centre, so that its cell is surrounded on all sides.
    int nearest = 0;
    double nearestD2 = 1.0e100;
    for (int k = 0; k < 9; ++k) {
      const double dx = centres[k][0] - ux, dy = centres[k][1] - uy, d2 = dx * dx + dy * dy;
      if (d2 < nearestD2) nearestD2 = d2, nearest = k;
    }
    if (nearest != 4) {
      cx += nearest / 3 - 1;
      cy += nearest % 3 - 1;
      cells.block(cx, cy, centres);
    }
    // Voronoi distance from centre 4: the largest ratio over its neighbours (1 on a shared edge).
    double distance = -1.0e100;
    for (int k = 0; k < 9; ++k) {
      if (k == 4) continue;
      const double px = centres[k][0] - centres[4][0], py = centres[k][1] - centres[4][1];
      const double ratio = px == 0.0 && py == 0.0
                               ? 1.0
                               : 2.0 * ((ux - centres[4][0]) * px + (uy - centres[4][1]) * py) / (px * px + py * py);
      distance = std::max(distance, ratio);
    }
    const double pull = std::pow(distance + 1e-100, power) * scale / (distance + 1e-100);
    outX[i] += w * ((ux - centres[4][0]) * pull + centres[4][0]);
    outY[i] += w * ((uy - centres[4][1]) * pull + centres[4][1]);
  }
}

// Zy0rg's post_smartcrop (Fractorium's, which the corpus's flames come from; JWildfire's lacks the
// rotation): keeps the point inside a rounded polygon of `power` sides and radius `radius` (a
// sector of power·π when |power| < 2) and moves what lies outside back onto its edge, or beyond it
// by scatter and offset (cropmode 1), to the origin (0), or keeps the radius and turns it
// (cropmode −1). A negative radius or power keeps the outside instead. Its input is the point
// itself (static 2, the usual post_ use); static 0, 1 and 3 and cropmode 2 (the last kept point)
// read the transform's state, which a stateless variation has not: the importer reports them.
// cropmode 2 drops the point here, which draws what the plugin draws apart from a repeated point.
VOXFLAME_VARIATION_TARGETS void smartcrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[0], radius = P[1], roundstr = P[2], roundwidth = P[3], distortion = P[4];
  const double edge = P[5], scatter = P[6], offset = P[7], rotation = P[8];
  const double cropmode = std::round(P[9]);
  const bool keepInside = (power > 0.0) == (radius > 0.0);
  const double workRadius = std::abs(radius);
  double workPower = power == 0.0 ? kFractoriumEps : std::abs(power);
  const bool radial = workPower < 2.0;
  if (radial) workPower *= kPi;
  const double alpha = kTwoPi / workPower;
  const double halfSin = std::sin(alpha / 2.0);
  const double roundCoeff = roundstr / (halfSin == 0.0 ? kFractoriumEps : halfSin) / workPower * 2.0;
  const double turn = rotation * alpha;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = std::atan2(y[i], x[i]);
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    double px = x[i], py = y[i], pz = z[i];
    // The plugin draws only what a branch uses; drawing all of them, in its order, gives the same
    // numbers to the branch taken and keeps the loop free of data-dependent draws.
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]), c = laneUniform(rnd[i]);
    if (radial) {
      const double jitter = edge * (a - 0.5);
      double sector = angle / kTwoPi + 1.0 + jitter;
      sector = (sector - std::trunc(sector)) * kTwoPi;
      if ((sector > workPower) == keepInside) {
        if (cropmode == 2.0) {
          px = py = pz = kNaN;
        } else {
          const double spread = (c * scatter + offset + jitter) * kPi;
          const double turned = std::trunc(b * 2.0) > 0.0 ? workPower + spread : -spread;
          px = rad * std::cos(turned);
          py = rad * std::sin(turned);
        }
      }
    } else {
      double coeff = 1.0;
      if (distortion != 0.0) {
        double side = (angle + kPi) / alpha;
        side -= std::trunc(side);
        side = side < 0.5 ? side : 1.0 - side;
        coeff = 1.0 / std::cos(side * alpha);
        if (roundstr != 0.0) {
          const double width =
              (roundwidth != 1.0 ? std::exp(std::log(side * 2.0) * roundwidth) : side * 2.0) * roundCoeff;
          coeff = std::abs((1.0 - width) * coeff + width);
        }
        if (distortion != 1.0) coeff = std::exp(std::log(coeff) * distortion);
      }
      const double reach = coeff * (edge != 0.0 ? workRadius + edge * (a - 0.5) : workRadius);
      if ((rad > reach) == keepInside) {
        if (cropmode == 2.0) {
          px = py = pz = kNaN;
        } else if (cropmode == 0.0) {
          px = py = pz = 0.0;
        } else {
          const double r = cropmode == -1.0 ? rad : reach + coeff * ((edge != 0.0 ? b : a) * scatter + offset);
          px = r * std::cos(angle + turn);
          py = r * std::sin(angle + turn);
        }
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * pz;
  }
}

// Michael Faber's epispiral as JWildfire's epispiral_wf has it: the curve r = ½ / cos(waves·θ).
VOXFLAME_VARIATION_2D(epispiralWf, {
  const double theta = std::atan2(x[i], y[i]);
  const double d = std::cos(P[0] * theta);
  if (d != 0.0) {  // JWildfire skips the point there
    const double r = 0.5 / d;
    outX[i] += w * r * std::sin(theta);
    outY[i] += w * r * std::cos(theta);
  }
})

// Its result ignores the point: a uniform square (2Ψ₁ − 1, 2Ψ₂ − 1) mapped onto the disc of the
// same "radius" (the larger coordinate), keeping where along the square's perimeter it lay.
VOXFLAME_VARIATION_2D(blurCircle, {
  const double sx = 2.0 * laneUniform(rnd[i]) - 1.0, sy = 2.0 * laneUniform(rnd[i]) - 1.0;
  const double ax = std::abs(sx), ay = std::abs(sy);
  double perimeter, side;
  if (ax >= ay) {
    perimeter = sx >= ay ? ax + sy : 5.0 * ax - sy;
    side = ax;
  } else {
    perimeter = sy >= ax ? 3.0 * ay - sx : 7.0 * ay + sx;
    side = ay;
  }
  const double a = kPi / 4.0 * perimeter / side - kPi / 4.0;
  outX[i] += w * side * std::cos(a);
  outY[i] += w * side * std::sin(a);
})

VOXFLAME_VARIATION_TARGETS void blurLinear(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double length = P[0], c = std::cos(P[1]), s = std::sin(P[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = length * laneUniform(rnd[i]);
    outX[i] += w * (x[i] + r * c);
    outY[i] += w * (y[i] + r * s);
    outZ[i] += w * z[i];
  }
}

// Zephyrtronium's exblur (JWildfire's): a blur in spherical coordinates about an origin whose size
// grows as |p − o|^(2·dist). The plugin sums the last four of its uniforms (one new per call); four
// fresh ones here have the same distribution. Its y origin is added, not subtracted, as in JWildfire.
VOXFLAME_VARIATION_TARGETS void exblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double dist = P[0], spread = P[1], x0 = P[2], y0 = P[3], z0 = P[4];
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - x0, dy = y[i] + y0, dz = z[i] - z0;
    const double n2 = dx * dx + dy * dy + dz * dz;
    const double u = laneUniform(rnd[i]) * kTwoPi, v = laneUniform(rnd[i]) * kTwoPi;
    const double gauss = laneGauss(rnd[i]);
    const double rr = w * std::pow(n2, dist) * gauss;
    const double theta = std::atan2(dy, dx), phi = std::acos(dz / std::sqrt(n2));
    const double sv = std::sin(phi), rsv = spread * std::sin(v);
    outX[i] += rr * (sv * std::cos(theta) + rsv * std::cos(u));
    outY[i] += rr * (sv * std::sin(theta) + rsv * std::sin(u));
    outZ[i] += rr * (std::cos(phi) + spread * std::cos(v));
  }
}

VOXFLAME_VARIATION_2D(twoface, {
  const double r = x[i] > 0.0 ? w / (x[i] * x[i] + y[i] * y[i]) : w;
  outX[i] += r * x[i];
  outY[i] += r * y[i];
})

// Zueuk's hyperbolic tilings: a Möbius map of the disc that moves by one tile of the {p, q} tiling.
// p and q are read as Fractorium reads them, any real number (0 as its epsilon): the corpus's
// Fractorium flames use q = 0.5. JWildfire rounds them and takes at least 3, so its files hold
// such values already.
// The distance of a tile's centre for p and q.
inline double hypertileDistance(double p, double q) {
  const double cp = std::cos(kTwoPi / p);
  const double r2 = 1.0 - (cp - 1.0) / (cp + std::cos(kTwoPi / q));
  return r2 > 0.0 ? 1.0 / std::sqrt(r2) : 1.0;
}
// The plugins' random turn, a random whole multiple of 2π/p: one of |p| directions for a whole p;
// for another p the plugins' huge random multiple (a 32-bit integer) amounts to any angle.
inline double tilingTurn(double u, double p) {
  return p == std::round(p) ? std::trunc(u * std::abs(p)) * kTwoPi / p : kTwoPi * u;
}

// The plugins' move: (p + c̄) / (c p + 1) for p = x + iy and c = re + i·im, times the weight.
[[gnu::always_inline]] inline void hypertileMap(double x, double y, double re, double im, double w, double& outX,
                                                double& outY) {
  const double a = x + re, b = y - im;
  const double c = re * x - im * y + 1.0, d = re * y + im * x;
  const double vr = w / (c * c + d * d);
  outX += vr * (a * c + b * d);
  outY += vr * (b * c - a * d);
}

VOXFLAME_VARIATION_TARGETS void hypertile(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = fractoriumZeps(P[0]), q = fractoriumZeps(P[1]);
  const double a = P[2] * kTwoPi / p, r = hypertileDistance(p, q);
  const double re = r * std::cos(a), im = r * std::sin(a);
  for (std::size_t i = 0; i < n; ++i) {
    hypertileMap(x[i], y[i], re, im, w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

// hypertile1: the move towards one of the p neighbours, picked at random: ⌊Ψ·trunc(p)⌋·2π/p as
// Fractorium's default mode draws it (JWildfire's random integer times 2π/p is the same for its
// whole p).
VOXFLAME_VARIATION_TARGETS void hypertile1(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = fractoriumZeps(P[0]), q = fractoriumZeps(P[1]);
  const double r = hypertileDistance(p, q), whole = std::trunc(p);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::floor(laneUniform(rnd[i]) * whole) * kTwoPi / p;
    hypertileMap(x[i], y[i], r * std::cos(a), r * std::sin(a), w, outX[i], outY[i]);
    outZ[i] += w * z[i];
  }
}

// hypertile2: the move along x, then a rotation by a random multiple of 2π/p.
VOXFLAME_VARIATION_TARGETS void hypertile2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = fractoriumZeps(P[0]), q = fractoriumZeps(P[1]);
  const double r = hypertileDistance(p, q);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = x[i] + r, b = y[i];
    const double c = r * x[i] + 1.0, d = r * y[i];
    const double mx = a * c + b * d, my = b * c - a * d;
    const double vr = w / (c * c + d * d);
    const double turn = tilingTurn(laneUniform(rnd[i]), p);
    const double s = std::sin(turn), co = std::cos(turn);
    outX[i] += vr * (mx * co + my * s);
    outY[i] += vr * (my * co - mx * s);
    outZ[i] += w * z[i];
  }
}

// hypertile3D2: hypertile2's move along x in the unit ball (z scaled with y), then a rotation of x
// and y by a random multiple of 2π/p, as the plugin has it.
VOXFLAME_VARIATION_TARGETS void hypertile3D2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = fractoriumZeps(P[0]), q = fractoriumZeps(P[1]);
  const double pa = kTwoPi / p, qa = kTwoPi / q;
  const double t = -(std::cos(pa) - 1.0) / (std::cos(pa) + std::cos(qa));
  const double cx = t > 0.0 ? 1.0 / std::sqrt(1.0 + t) : 1.0;
  const double c2 = cx * cx, sx = 1.0 + c2, sy = 1.0 - c2;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double mx = x[i] * sx - cx * (-r2 - 1.0), my = y[i] * sy;
    const double vr = w / (c2 * r2 + 2.0 * cx * x[i] + 1.0);
    const double turn = tilingTurn(laneUniform(rnd[i]), p);
    const double s = std::sin(turn), co = std::cos(turn);
    outX[i] += vr * (mx * co + my * s);
    outY[i] += vr * (my * co - mx * s);
    outZ[i] += vr * z[i] * sy;
  }
}

// hypertile3D1: hypertile1's move towards one of the p neighbours, picked at random, in the unit
// ball: the move c = r (cos a, sin a, 0) for a random multiple a of 2π/p, with z shrunk by 1 − r²
// (Zueuk's plugin, as JWildfire and Fractorium have it).
VOXFLAME_VARIATION_TARGETS void hypertile3D1(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = fractoriumZeps(P[0]), q = fractoriumZeps(P[1]);
  const double pa = kTwoPi / p, qa = kTwoPi / q;
  const double t = -(std::cos(pa) - 1.0) / (std::cos(pa) + std::cos(qa));
  const double r = t > 0.0 ? 1.0 / std::sqrt(1.0 + t) : 1.0;
  const double r2c = r * r, sz = 1.0 - r2c;
  for (std::size_t i = 0; i < n; ++i) {
    const double turn = tilingTurn(laneUniform(rnd[i]), p);
    const double cx = r * std::cos(turn), cy = r * std::sin(turn);
    const double sx = 1.0 + cx * cx - cy * cy, sy = 1.0 + cy * cy - cx * cx;
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double tx = 2.0 * cx * x[i], ty = 2.0 * cy * y[i];
    const double d = w / fractoriumZeps(r2c * r2 + tx - ty + 1.0);
    outX[i] += d * (x[i] * sx - cx * (ty - r2 - 1.0));
    outY[i] += d * (y[i] * sy + cy * (-tx - r2 - 1.0));
    outZ[i] += d * z[i] * sz;
  }
}

// Apophysis 7X's rotations (JWildfire's pre_/post_rotate_*, Fractorium's rotate_*): the point
// turned about an axis by weight·π/2. The weight is the angle, not a scale, so these add the turned
// point itself; their pre_ and post_ forms, the usual ones, replace the point by it.
#define VOXFLAME_ROTATION(fn, ROTATE)                                                                        \
  VOXFLAME_VARIATION_TARGETS void fn(const VariationInput& in, double* __restrict ox, double* __restrict oy, \
                                     double* __restrict oz) {                                                \
    VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)                                                                 \
    const double s = std::sin(w * kPi / 2.0), c = std::cos(w * kPi / 2.0);                                   \
    for (std::size_t i = 0; i < n; ++i) {                                                                    \
      ROTATE                                                                                                 \
    }                                                                                                        \
  }
VOXFLAME_ROTATION(rotateX, outX[i] += x[i]; outY[i] += s * z[i] + c * y[i]; outZ[i] += c * z[i] - s * y[i];)
VOXFLAME_ROTATION(rotateY, outX[i] += c * x[i] - s * z[i]; outY[i] += y[i]; outZ[i] += s * x[i] + c * z[i];)
VOXFLAME_ROTATION(rotateZ, outX[i] += s * y[i] + c * x[i]; outY[i] += c * y[i] - s * x[i]; outZ[i] += z[i];)
#undef VOXFLAME_ROTATION

// Larry Berlin's foci_3D: foci with z taking the role of a second angle (φ when z is 0).
VOXFLAME_VARIATION_TARGETS void foci3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double expx = std::exp(x[i]) * 0.5, expnx = 0.25 / expx;
    const double boot = z[i] == 0.0 ? std::atan2(y[i], x[i]) : z[i];
    const double t = w / (expx + expnx - std::cos(y[i]) * std::cos(boot));
    outX[i] += (expx - expnx) * t;
    outY[i] += std::sin(y[i]) * t;
    outZ[i] += std::sin(boot) * t;
  }
}

// Xyrus02's circlecrop: points outside the circle go to its edge, scattered outwards by
// Ψ·scatter_area/2 (at most one), or with zero to the origin; the centre is not scaled by the weight.
// JWildfire also hides a point it sends to the origin; Fractorium, which most of the corpus's flames
// with it come from, draws it there, as here.
VOXFLAME_VARIATION_TARGETS void circlecrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], x0 = P[1], y0 = P[2], scatter = std::clamp(P[3], -1.0, 1.0);
  const bool zero = std::round(P[4]) == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - x0, dy = y[i] - y0;
    const double edge = radius + laneUniform(rnd[i]) * 0.5 * scatter;
    if (std::sqrt(dx * dx + dy * dy) > radius) {
      if (!zero) {
        const double a = std::atan2(dy, dx);
        outX[i] += w * edge * std::cos(a) + x0;
        outY[i] += w * edge * std::sin(a) + y0;
      }
    } else {
      outX[i] += w * dx + x0;
      outY[i] += w * dy + y0;
    }
    outZ[i] += w * z[i];
  }
}

// Xyrus02's bwraps (as Fractorium has it): the plane cut into square cells of side cellsize, each
// holding a bubble of radius cellsize/(2(1 + space²)) that magnifies by gain and twists from
// inner_twist at its centre to outer_twist at its rim; outside the bubbles the point stays.
VOXFLAME_VARIATION_TARGETS void bwraps(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = P[0], space = P[1], gain = P[2], innerTwist = P[3], outerTwist = P[4];
  const double radius = 0.5 * (cellsize / (1.0 + space * space));
  const double g2 = gain * gain + 1e-6;
  double maxBubble = g2 * radius;
  maxBubble = maxBubble > 2.0 ? 1.0 : maxBubble / (maxBubble * maxBubble / 4.0 + 1.0);
  const double r2 = radius * radius == 0.0 ? kFractoriumEps : radius * radius;
  const double rfactor = radius / maxBubble;
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    if (cellsize != 0.0) {
      const double cx = (std::floor(x[i] / cellsize) + 0.5) * cellsize;
      const double cy = (std::floor(y[i] / cellsize) + 0.5) * cellsize;
      double lx = x[i] - cx, ly = y[i] - cy;
      if (lx * lx + ly * ly <= r2) {
        lx *= g2;
        ly *= g2;
        const double d = (lx * lx + ly * ly) / 4.0 + 1.0;
        const double r = rfactor / (d == 0.0 ? kFractoriumEps : d);
        lx *= r;
        ly *= r;
        const double t = (lx * lx + ly * ly) / r2;
        const double theta = innerTwist * (1.0 - t) + outerTwist * t;
        const double s = std::sin(theta), c = std::cos(theta);
        px = cx + c * lx + s * ly;
        py = cy - s * lx + c * ly;
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// Joel Faber's juni (Apophysis 7X plugin): julian3Dz-like roots of the point inside the circle of
// radius weight (outside it with invert), the angle taken after the transform's own affine map once
// more (the plugin's a–f, as flam3 names them here); elsewhere the point times the weight. z is
// scaled as in julian3Dz. The plugin draws the root only where it uses it; here it is always drawn.
VOXFLAME_VARIATION_TARGETS void juni(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = countParam(P[0]), absn = std::abs(power);
  const bool invert = std::round(P[1]) >= 1.0;
  const double cn = (P[2] / power - 1.0) / 2.0;
  const double* m = in.affine;
  const double a = m[0], b = m[kAffineB], c = m[kAffineC], d = m[4], e = m[kAffineE], f = m[kAffineF];
  for (std::size_t i = 0; i < n; ++i) {
    const double zz = z[i] / absn;
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double r = w * std::pow(r2 + zz * zz, cn);
    const double root = std::trunc(laneUniform(rnd[i]) * absn);
    outZ[i] += r * zz;
    const bool plain = invert ? (r2 < w * w && r2 != 0.0) : (r2 > w * w || r2 == 0.0);
    if (plain) {
      outX[i] += w * x[i];
      outY[i] += w * y[i];
      continue;
    }
    const double xx = a * x[i] + b * y[i] + c, yy = d * x[i] + e * y[i] + f;
    const double alpha = (std::atan2(yy, xx) + kTwoPi * root) / power;
    const double gamma = r * std::sqrt(r2);
    outX[i] += gamma * std::cos(alpha);
    outY[i] += gamma * std::sin(alpha);
  }
}

// Whittaker Courtney's acoth (JWildfire's): the complex inverse hyperbolic cotangent, ½ log((1 + 1/p)
// / (1 − 1/p)), with its real and imaginary parts swapped, times 2/π. JWildfire's complex helpers
// guard 1/|q|² by treating |q|² < 1e-100 as 1 and add 1e-20 to |q|² inside the logarithm.
inline double guardedInverseNorm(double re, double im) {
  const double m2 = re * re + im * im;
  return m2 < 1e-100 ? 1.0 : 1.0 / m2;
}
VOXFLAME_VARIATION_2D(acoth, {
  const double inv = guardedInverseNorm(x[i], y[i]);
  const double re = x[i] * inv, im = -y[i] * inv;  // 1/p
  // (1 + q) / (1 − q) for q = 1/p, as JWildfire divides.
  const double nre = re + 1.0, nim = im, dre = -(re - 1.0), dim = -im;
  const double dinv = guardedInverseNorm(dre, dim);
  const double qre = (nim * dim + nre * dre) * dinv, qim = (nim * dre - nre * dim) * dinv;
  const double logRe = 0.5 * std::log(qre * qre + qim * qim + 1e-20), logIm = std::atan2(qim, qre);
  const double s = w * 2.0 / kPi * 0.5;
  outX[i] += s * logIm;
  outY[i] += s * logRe;
})

VOXFLAME_VARIATION_2D(biLinear, {
  outX[i] += w * y[i];
  outY[i] += w * x[i];
})

// Apophysis 7X's blur_zoom: a zoom blur towards (x, −y) of the parameters, as the plugin has the
// signs: the point's offset from the centre grows by 1 + Ψ·length.
VOXFLAME_VARIATION_TARGETS void blurZoom(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double length = P[0], cx = P[1], cy = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double zoom = 1.0 + length * laneUniform(rnd[i]);
    outX[i] += w * ((x[i] - cx) * zoom + cx);
    outY[i] += w * ((y[i] + cy) * zoom - cy);
    outZ[i] += w * z[i];
  }
}

// Larry Berlin's inflateZ_3: adds a z of 0.2 (π − φ) cos(3φ + y − x); x and y untouched.
VOXFLAME_VARIATION_TARGETS void inflateZ3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = std::atan2(y[i], x[i]);
    outZ[i] += w * 0.2 * (kPi - angle) * std::cos(3.0 * angle + (y[i] - x[i]));
  }
}

// Michael Faber's eSeries work in elliptic coordinates (μ, ν): p = (cosh μ cos ν, sinh μ sin ν).
// JWildfire's acosh is log(√(v² − 1) + v).
struct Elliptic {
  double mu, nu;
};
inline Elliptic toElliptic(double x, double y, double r2) {
  const double t = r2 + 1.0, x2 = 2.0 * x;
  const auto safeSqrt = [](double v) { return v <= 0.0 ? 0.0 : std::sqrt(v); };
  const double xmax = std::max(1.0, (safeSqrt(t + x2) + safeSqrt(t - x2)) * 0.5);
  const double mu = std::log(std::sqrt(xmax * xmax - 1.0) + xmax);
  const double nu = std::acos(std::clamp(x / xmax, -1.0, 1.0));
  return {mu, y < 0.0 ? -nu : nu};
}

// eJulia: the power-th roots in elliptic coordinates (μ/power, ν/power + 2πk/power, k =
// ⌊Ψ·power⌋); a negative power inverts the point first (x/r² with r² → 1/r²).
VOXFLAME_VARIATION_TARGETS void eJulia(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = countParam(P[0]);
  for (std::size_t i = 0; i < n; ++i) {
    double r2 = x[i] * x[i] + y[i] * y[i], px = x[i];
    if (power < 0.0) {
      r2 = 1.0 / r2;
      px = x[i] * r2;
    }
    Elliptic e = toElliptic(px, y[i], r2);
    e.nu = e.nu / power + kTwoPi / power * std::floor(laneUniform(rnd[i]) * power);
    e.mu /= power;
    outX[i] += w * std::cosh(e.mu) * std::cos(e.nu);
    outY[i] += w * std::sinh(e.mu) * std::sin(e.nu);
    outZ[i] += w * z[i];
  }
}

// eMotion: μ moved by ∓move (towards the focus on ν's side), reflected through 0, ν turned by rotate.
VOXFLAME_VARIATION_TARGETS void eMotion(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double move = P[0], rotate = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    Elliptic e = toElliptic(x[i], y[i], x[i] * x[i] + y[i] * y[i]);
    e.mu += e.nu < 0.0 ? move : -move;
    if (e.mu <= 0.0) {
      e.mu = -e.mu;
      e.nu = -e.nu;
    }
    e.nu += rotate;
    outX[i] += w * std::cosh(e.mu) * std::cos(e.nu);
    outY[i] += w * std::sinh(e.mu) * std::sin(e.nu);
    outZ[i] += w * z[i];
  }
}

// The Voronoi distance of (ux, uy) from centre q among `count` centres: the largest ratio over the
// others, 0 at q and 1 on a shared edge (slobo777's plugins).
inline double voronoiDistance(const double (*centres)[2], int count, int q, double ux, double uy) {
  double distance = -1.0e100;
  for (int k = 0; k < count; ++k) {
    if (k == q) continue;
    const double px = centres[k][0] - centres[q][0], py = centres[k][1] - centres[q][1];
    const double ratio = px == 0.0 && py == 0.0
                             ? 1.0
                             : 2.0 * ((ux - centres[q][0]) * px + (uy - centres[q][1]) * py) / (px * px + py * py);
    distance = std::max(distance, ratio);
  }
  return distance;
}

// slobo777's hexes: the plane cut into hexagons of size cellsize; within its cell the point is
// turned by rotate·2π about the centre and its Voronoi distance L mapped to L^power·scale, blending
// the distance before and after the turn between 0.5 and 0.8 to hide the corners' "rosette".
VOXFLAME_VARIATION_TARGETS void hexes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double s = P[0], power = P[1], scale = P[3];
  const double rotSin = std::sin(P[2] * kTwoPi), rotCos = std::cos(P[2] * kTwoPi);
  constexpr double kRoot3 = 1.7320508075688772935;
  const auto centre = [s](double hx, double hy, double* out) {
    out[0] = (1.5 * hx - 1.5 * hy) * s;
    out[1] = (kRoot3 / 2.0 * hx + kRoot3 / 2.0 * hy) * s;
  };
  for (std::size_t i = 0; i < n; ++i) {
    outZ[i] += w * z[i];
    if (s == 0.0) continue;  // the plugin's guard
    const double ux = x[i], uy = y[i];
    double hx = javaFloorToInt((ux / 3.0 + kRoot3 / 3.0 * uy) / s);
    double hy = javaFloorToInt((-ux / 3.0 + kRoot3 / 3.0 * uy) / s);
    double centres[9][2];
    int k = 0;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) centre(hx + di, hy + dj, centres[k++]);
    int nearest = 0;
    double nearestD2 = 1.0e100;
    for (k = 0; k < 9; ++k) {
      const double dx = centres[k][0] - ux, dy = centres[k][1] - uy, d2 = dx * dx + dy * dy;
      if (d2 < nearestD2) nearestD2 = d2, nearest = k;
    }
    hx += nearest / 3 - 1;
    hy += nearest % 3 - 1;
    // The chosen hexagon first, then its six neighbours.
    const double around[7][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0, -1}, {-1, -1}, {-1, 0}};
    for (k = 0; k < 7; ++k) centre(hx + around[k][0], hy + around[k][1], centres[k]);
    const double l1 = voronoiDistance(centres, 7, 0, ux, uy);
    const double dx = ux - centres[0][0], dy = uy - centres[0][1];
    const double target = std::pow(l1 + 1e-100, power) * scale;
    double vx = dx * rotCos + dy * rotSin, vy = -dx * rotSin + dy * rotCos;
    const double l2 = voronoiDistance(centres, 7, 0, vx + centres[0][0], vy + centres[0][1]);
    const double l = std::max(l1, l2);
    const double r = l < 0.5   ? target / l1
                     : l > 0.8 ? target / l2
                               : ((target / l1) * (0.8 - l) + (target / l2) * (l - 0.5)) / 0.3;
    vx = vx * r + centres[0][0];
    vy = vy * r + centres[0][1];
    outX[i] += w * vx;
    outY[i] += w * vy;
  }
}

// eralex61's GlynnSim1: inside the circle of `radius`, and inside a small circle of radius1 at angle
// phi1 (degrees) on its rim, points are replaced by random ones on a ring of that small circle
// (thickness its inner share); outside, a point is mirrored into the circle with probability
// contrast·(radius/r)^|pow| first.
VOXFLAME_VARIATION_TARGETS void glynnSim1(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], radius1 = P[1], thickness = P[3], absPow = std::abs(P[4]), contrast = P[5];
  const double phi1 = kPi * P[2] / 180.0;
  const double x1 = radius * std::cos(phi1), y1 = radius * std::sin(phi1);
  for (std::size_t i = 0; i < n; ++i) {
    // The plugin draws only what a branch uses; all three are drawn here, in its order.
    const double pick = laneUniform(rnd[i]), ringU = laneUniform(rnd[i]), ringA = laneUniform(rnd[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double alpha = radius / r;
    bool onRing = r < radius;
    double px = x[i], py = y[i];
    double u = pick, a = ringU;
    if (!onRing) {
      if (pick <= contrast * std::pow(alpha, absPow)) {
        px = alpha * alpha * x[i];
        py = alpha * alpha * y[i];
      }
      onRing = (px - x1) * (px - x1) + (py - y1) * (py - y1) < radius1 * radius1;
      u = ringU;
      a = ringA;
    }
    if (onRing) {
      const double ring = radius1 * (thickness + (1.0 - thickness) * u);
      px = ring * std::cos(kTwoPi * a) + x1;
      py = ring * std::sin(kTwoPi * a) + y1;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// cropn (Fractorium's, as its default, non-flam3-compatible mode draws it): keeps the point inside
// a regular polygon of |power| sides (at least 2) and circumradius-like radius, and moves what lies
// outside onto the polygon's edge, pushed out by Ψ·scatterdist, or with zero 0 to the origin; a
// negative power keeps the outside instead. Fractorium's flam3-compatible mode swaps zero's meaning.
VOXFLAME_VARIATION_TARGETS void cropn(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[0], radius = P[1], scatter = P[2];
  const bool zero = P[3] == 0.0;
  const double alpha = kTwoPi / std::max(2.0, std::abs(power)), half = alpha / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double around = std::fmod(std::atan2(y[i], x[i]) + kPi, alpha);
    const double c = std::cos(around < half ? around : alpha - around);
    const double reach = c > 0.0 ? radius / c : 1.0;
    double s = w;
    if ((r2 > reach * reach) == (power > 0.0)) {
      const double r = std::sqrt(r2);
      s = zero ? 0.0 : (reach + u * scatter) * w / (r == 0.0 ? kFractoriumEps : r);
    }
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * z[i];
  }
}

// Xyrus02's julian3Dx (Apophysis plugin, Fractorium): julian3Dz whose angle is taken after a second
// affine map (a b e / c d f), as julian2 does.
VOXFLAME_VARIATION_TARGETS void julian3Dx(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = countParam(P[1]), absn = std::abs(power), cn = (P[0] / power - 1.0) / 2.0;
  const double a = P[2], b = P[3], c = P[4], d = P[5], e = P[6], f = P[7];
  for (std::size_t i = 0; i < n; ++i) {
    const double zz = z[i] / absn;
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double radius = w * std::pow(r2 + zz * zz, cn);
    const double px = a * x[i] + b * y[i] + e, py = c * x[i] + d * y[i] + f;
    const double root = std::trunc(laneUniform(rnd[i]) * absn);
    const double alpha = (std::atan2(py, px) + kTwoPi * root) / power;
    const double gamma = radius * std::sqrt(r2);
    outX[i] += gamma * std::cos(alpha);
    outY[i] += gamma * std::sin(alpha);
    outZ[i] += radius * zz;
  }
}

// Apophysis 3D's flatten: the transform's z is 0. It adds nothing itself; the chaos game sets z to
// 0 after a transform's variations (before them for pre_flatten, after the post_ ones for
// post_flatten) when one of them is flatten.
VOXFLAME_VARIATION_TARGETS void flatten(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  (void)n;
  (void)w;
  (void)outZ;
}

#undef VOXFLAME_VARIATION_2D

#undef VOXFLAME_VARIATION_BEGIN

std::vector<VariationInfo> buildCatalogue() {
  std::vector<VariationInfo> c;
  const CatalogueAdder add(c);
  constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D, kRandom = CatalogueAdder::kRandom,
                 kFixed = CatalogueAdder::kFixed;
  const auto count = &CatalogueAdder::count;

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
      {{"power", 4.0, -12.0, 12.0}, {"dist", 1.0, -3.0, 3.0}});
  add("juliascope", "r^(dist/power)·(cos α, sin α), z; α = (2πk ± φ)/power, k = trunc(|power|·Ψ), − for odd k", k2D,
      kRandom, &juliascope, {{"power", 4.0, -12.0, 12.0}, {"dist", 1.0, -3.0, 3.0}});
  add("blur", "Ψ₂ (cos 2πΨ₁, sin 2πΨ₁), z", k2D, kRandom, &blur);
  add("gaussian_blur", "G (cos 2πΨ, sin 2πΨ), z; G = Ψ + Ψ + Ψ + Ψ − 2", k2D, kRandom, &gaussianBlur);
  add("radial_blur",
      "r (cos(φ + G sin β), sin(φ + G sin β)) + (G cos β − 1)(x, y), z; G = weight·(Ψ + Ψ + Ψ + Ψ − 2), "
      "β = angle·π/2 (flam3's: weight scales the blur, not the point)",
      k2D, kRandom, &radialBlur, {{"angle", 0.5, -1.0, 1.0}});
  add("pie", "Ψ₃ (cos α, sin α), z; α = rotation + 2π(trunc(Ψ₁·slices + ½) + Ψ₂·thickness)/slices", k2D, kRandom, &pie,
      {{"slices", 6.0, 1.0, 24.0}, {"rotation", 0.0, -kPi, kPi}, {"thickness", 0.5, 0.0, 1.0}});
  add("ngon", "(x, y)(corners (1/(cos β + ε) − 1) + circle) / (r^power + ε), z; β = φ mod 2π/sides, in ±π/sides", k2D,
      kFixed, &ngon,
      {{"sides", 5.0, 1.0, 12.0}, {"power", 3.0, 0.0, 6.0}, {"circle", 1.0, 0.0, 3.0}, {"corners", 2.0, 0.0, 6.0}});
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
  // The rest of flam3's variations (flam3 3.1's variations.c), in flam3's order.
  add("arch", "w (sin α, sin² α / cos α), z; α = Ψ·w·π (w the weight)", k2D, kRandom, &arch);
  add("tangent", "(sin x / cos y, tan y, z)", k2D, kFixed, &tangent);
  add("square", "(Ψ₁ − ½, Ψ₂ − ½, z)", k2D, kRandom, &square);
  add("rays", "t (cos x, sin y), z; t = w tan(Ψ·w·π) / (r² + ε) (w the weight)", k2D, kRandom, &rays);
  add("blade", "x (cos ρ + sin ρ, cos ρ − sin ρ), z; ρ = Ψ·w·r (w the weight)", k2D, kRandom, &blade);
  add("secant2", "(x, 1/cos(w r) ∓ 1, z); + 1 when cos(w r) < 0, else − 1 (w the weight)", k2D, kFixed, &secant2);
  add("twintrian", "x (d, d − π sin ρ), z; d = log₁₀(sin² ρ) + cos ρ (−30 where undefined), ρ = Ψ·w·r", k2D, kRandom,
      &twintrian);
  add("cross", "(x, y) / |x² − y²| (√ of 1/((x² − y²)² + ε)), z", k2D, kFixed, &cross);
  add("disc2",
      "(θ/π)(sin(rot·π(x + y)) + cos twist − 1, cos(rot·π(x + y)) + sin twist), z; the twist terms scaled by "
      "1 + twist ∓ 2π beyond ±2π",
      k2D, kFixed, &disc2, {{"rot", 0.0, -2.0, 2.0}, {"twist", 0.0, -2.0 * kPi, 2.0 * kPi}});
  add("super_shape", "(x, y)(rnd·Ψ + (1 − rnd) r − holes)(|cos t|^n2 + |sin t|^n3)^(−1/n1) / r, z; t = m φ/4 + π/4",
      k2D, kRandom, &superShape,
      {{"rnd", 0.0, 0.0, 1.0},
       {"m", 0.0, 0.0, 12.0},
       {"n1", 1.0, 0.1, 10.0},
       {"n2", 1.0, 0.0, 10.0},
       {"n3", 1.0, 0.0, 10.0},
       {"holes", 0.0, -1.0, 1.0}});
  add("flower", "(x, y)(Ψ − holes) cos(petals·φ) / r, z", k2D, kRandom, &flower,
      {{"petals", 0.0, 0.0, 12.0}, {"holes", 0.0, -1.0, 1.0}});
  add("conic", "(x, y)(Ψ − holes) e / (1 + e x/r) / r, z; e = eccentricity", k2D, kRandom, &conic,
      {{"eccentricity", 1.0, 0.0, 2.0}, {"holes", 0.0, -1.0, 1.0}});
  add("parabola", "(height sin² r·Ψ₁, width cos r·Ψ₂, z)", k2D, kRandom, &parabola,
      {{"height", 0.0, -2.0, 2.0}, {"width", 0.0, -2.0, 2.0}});
  add("bent2", "(x < 0 ? x·x₀ : x, y < 0 ? y·y₀ : y, z); x₀, y₀ the parameters x, y", k2D, kFixed, &bent2,
      {{"x", 1.0, -2.0, 2.0}, {"y", 1.0, -2.0, 2.0}});
  add("bipolar",
      "(ln((r² + 1 + 2x)/(r² + 1 − 2x)) / 2π, 2v/π, z); v = ½ atan2(2y, r² − 1) − shift·π/2 wrapped into ±π/2 "
      "(left unmapped where the logarithm is undefined)",
      k2D, kFixed, &bipolar, {{"shift", 0.0, -2.0, 2.0}});
  add("boarders",
      "(x, y) rounded to the grid plus half the offset, pushed ¼ towards the cell's edge 3 times in 4 (Ψ < ¾), z", k2D,
      kRandom, &boarders);
  add("butterfly", "1.30294 √(|xy| / (x² + 4y² + ε)) (x, 2y), z", k2D, kFixed, &butterfly);
  add("cell",
      "(dx + X·size, −(dy + Y·size), z); (X, Y) the cell ⌊(x, y)/size⌋ folded into one quadrant (2k, or −2k − 1 "
      "when negative), (dx, dy) the offset in it",
      k2D, kFixed, &cell, {{"size", 1.0, 0.05, 4.0}});
  add("cpow",
      "e^(c ln r − d φ) (cos α, sin α), z; α = c φ + d ln r + (2π/power)⌊power·Ψ⌋, c = r₀/power, d = i/power (r₀, i "
      "the parameters r, i)",
      k2D, kRandom, &cpow, {{"r", 1.0, -3.0, 3.0}, {"i", 0.0, -3.0, 3.0}, count("power", 1.0, -8.0, 8.0)});
  add("curve", "(x + xamp e^(−y²/xlength²), y + yamp e^(−x²/ylength²), z)", k2D, kFixed, &curve,
      {{"xamp", 0.0, -2.0, 2.0}, {"yamp", 0.0, -2.0, 2.0}, {"xlength", 1.0, 0.01, 4.0}, {"ylength", 1.0, 0.01, 4.0}});
  add("edisc",
      "(cosh a₂ cos a₁, ∓ sinh a₂ sin a₁) / 11.5703, z; m = (√(r² + 1 + 2x) + √(r² + 1 − 2x))/2, a₁ = ln(m + √(m − "
      "1)), "
      "a₂ = −acos(x/m); − for y > 0",
      k2D, kFixed, &edisc);
  add("elliptic",
      "(2/π)(atan2(a, √(1 − a²)), ± ln(m + √(m − 1))), z; m as edisc, a = x/m; + for y > 0 (mode 0, flam3's), + for "
      "Ψ < ½ (mode 1, JWildfire's default; the one mode that draws Ψ), or mode 2: Heiland-Allen's precise form of mode "
      "0 (JWildfire's)",
      k2D, kFixed, &elliptic, {count("mode", 0.0, 0.0, 2.0)});
  add("escher",
      "e^(c ln r − d φ) (cos(c φ + d ln r), sin(c φ + d ln r)), z; c = (1 + cos β)/2, d = (sin β)/2, β = beta", k2D,
      kFixed, &escher, {{"beta", 0.0, -kPi, kPi}});
  add("foci", "(e^x/2 − e^(−x)/4, sin y) / (e^x/2 + e^(−x)/4 − cos y), z", k2D, kFixed, &foci);
  add("lazysusan",
      "q = (x − x₀, y + y₀), ρ = |q|: inside the weight's radius w ρ (cos α, sin α), α = ∠q + spin + twist (w − ρ); "
      "outside (1 + space/ρ) q; then + (x₀, −y₀), z (w the weight; x₀, y₀ the parameters x, y)",
      k2D, kFixed, &lazysusan,
      {{"spin", 0.0, -kPi, kPi},
       {"space", 0.0, -2.0, 2.0},
       {"twist", 0.0, -2.0, 2.0},
       {"x", 0.0, -1.0, 1.0},
       {"y", 0.0, -1.0, 1.0}});
  add("loonie", "(x, y) √(w²/r² − 1) inside the weight's radius w, (x, y) outside, z", k2D, kFixed, &loonie);
  add("modulus", "(x, y) wrapped into [−x₀, x₀] × [−y₀, y₀], z (x₀, y₀ the parameters x, y)", k2D, kFixed, &modulus,
      {{"x", 1.0, 0.0, 3.0}, {"y", 1.0, 0.0, 3.0}});
  add("oscilloscope", "(x, |y| ≤ t ? −y : y, z); t = amplitude e^(−|x| damping) cos(2π frequency x) + separation", k2D,
      kFixed, &oscilloscope,
      {{"separation", 1.0, 0.0, 3.0},
       {"frequency", kPi, 0.0, 10.0},
       {"amplitude", 1.0, 0.0, 3.0},
       {"damping", 0.0, 0.0, 3.0}});
  add("polar2", "(θ/π, ln(r²)/2π, z)", k2D, kFixed, &polar2);
  add("popcorn2", "(x + x₀ sin(tan(c y)), y + y₀ sin(tan(c x)), z) (x₀, y₀ the parameters x, y)", k2D, kFixed,
      &popcorn2, {{"x", 0.1, -1.0, 1.0}, {"y", 0.1, -1.0, 1.0}, {"c", 3.0, -10.0, 10.0}});
  add("scry", "(x, y) / (r (r² + 1/(w + ε))), z (w the weight; the weight is not applied again)", k2D, kFixed, &scry);
  add("separation",
      "(±(√(x² + x₀²) ∓ x·xinside), ±(√(y² + y₀²) ∓ y·yinside), z): each side pushed away from its axis (x₀, y₀ the "
      "parameters x, y)",
      k2D, kFixed, &separation,
      {{"x", 0.5, 0.0, 2.0}, {"xinside", 0.0, -1.0, 1.0}, {"y", 0.5, 0.0, 2.0}, {"yinside", 0.0, -1.0, 1.0}});
  add("split", "(cos(π ysize·y) ≥ 0 ? x : −x, cos(π xsize·x) ≥ 0 ? y : −y, z)", k2D, kFixed, &split,
      {{"xsize", 0.5, -2.0, 2.0}, {"ysize", 0.5, -2.0, 2.0}});
  add("splits", "(x ± x₀, y ± y₀, z): each half moved away from the axis (x₀, y₀ the parameters x, y)", k2D, kFixed,
      &splits, {{"x", 0.0, -1.0, 1.0}, {"y", 0.0, -1.0, 1.0}});
  add("stripes", "(d (1 − space) + X, y + d² warp, z); X = ⌊x + ½⌋, d = x − X", k2D, kFixed, &stripes,
      {{"space", 0.0, -1.0, 1.0}, {"warp", 0.0, -2.0, 2.0}});
  add("wedge", "(r + hole)(cos α, sin α), z; a = φ + swirl·r, α = a (1 − angle·count/2π) + angle ⌊(count·a + π)/2π⌋",
      k2D, kFixed, &wedge,
      {{"angle", 0.0, -kPi, kPi}, {"hole", 0.0, -1.0, 1.0}, count("count", 1.0, 1.0, 12.0), {"swirl", 0.0, -2.0, 2.0}});
  add("wedge_julia", "r^(dist/power) (cos α, sin α), z; a = (φ + 2πk)/power, k = trunc(|power|·Ψ), α as wedge", k2D,
      kRandom, &wedgeJulia,
      {{"angle", 0.0, -kPi, kPi},
       count("count", 1.0, 1.0, 12.0),
       count("power", 1.0, -8.0, 8.0),
       {"dist", 0.0, -3.0, 3.0}});
  add("wedge_sph", "(1/r + hole)(cos α, sin α), z; a = φ + swirl/r, α as wedge", k2D, kFixed, &wedgeSph,
      {{"angle", 0.0, -kPi, kPi}, count("count", 1.0, 1.0, 12.0), {"hole", 0.0, -1.0, 1.0}, {"swirl", 0.0, -2.0, 2.0}});
  add("whorl", "r (cos α, sin α), z; α = φ + (r < w ? inside : outside)/(w − r) (w the weight)", k2D, kFixed, &whorl,
      {{"inside", 0.0, -2.0, 2.0}, {"outside", 0.0, -2.0, 2.0}});
  add("waves2",
      "(x + scalex sin(freqx y), y + scaley sin(freqy x), z + scalez sin(freqz r)) (the z part is Apophysis 7X's)", k2D,
      kFixed, &waves2,
      {{"freqx", 1.0, -10.0, 10.0},
       {"scalex", 0.0, -2.0, 2.0},
       {"freqy", 1.0, -10.0, 10.0},
       {"scaley", 0.0, -2.0, 2.0},
       {"freqz", 0.0, -10.0, 10.0},
       {"scalez", 0.0, -2.0, 2.0}});
  add("exp", "e^x (cos y, sin y), z: the complex exponential of x + iy", k2D, kFixed, &complexExp);
  add("log", "(log_base r, φ, z): the complex logarithm (base e, flam3's, unless JWildfire's base is set)", k2D, kFixed,
      &complexLog, {{"base", std::numbers::e, 1.1, 10.0}});
  add("sin", "(sin x cosh y, cos x sinh y, z): the complex sine", k2D, kFixed, &complexSin);
  add("cos", "(cos x cosh y, −sin x sinh y, z): the complex cosine", k2D, kFixed, &complexCos);
  add("tan", "(sin 2x, sinh 2y) / (cos 2x + cosh 2y), z: the complex tangent", k2D, kFixed, &complexTan);
  add("sec", "2 (cos x cosh y, sin x sinh y) / (cos 2x + cosh 2y), z: the complex secant", k2D, kFixed, &complexSec);
  add("csc", "2 (sin x cosh y, −cos x sinh y) / (cosh 2y − cos 2x), z: the complex cosecant", k2D, kFixed, &complexCsc);
  add("cot", "(sin 2x, −sinh 2y) / (cosh 2y − cos 2x), z: the complex cotangent", k2D, kFixed, &complexCot);
  add("sinh", "(sinh x cos y, cosh x sin y, z): the complex hyperbolic sine", k2D, kFixed, &complexSinh);
  add("cosh", "(cosh x cos y, sinh x sin y, z): the complex hyperbolic cosine", k2D, kFixed, &complexCosh);
  add("tanh", "(sinh 2x, sin 2y) / (cos 2y + cosh 2x), z: the complex hyperbolic tangent", k2D, kFixed, &complexTanh);
  add("sech", "2 (cos y cosh x, −sin y sinh x) / (cos 2y + cosh 2x), z: the complex hyperbolic secant", k2D, kFixed,
      &complexSech);
  add("csch", "2 (sinh x cos y, −cosh x sin y) / (cosh 2x − cos 2y), z: the complex hyperbolic cosecant", k2D, kFixed,
      &complexCsch);
  add("coth", "(sinh 2x, sin 2y) / (cosh 2x − cos 2y), z: flam3's hyperbolic cotangent (the complex one's conjugate)",
      k2D, kFixed, &complexCoth);
  add("auger",
      "(x + sym (dx − x), y + strength (scale sin(freq x)/2 + |y| sin(freq x)), z); dx = x + strength (scale "
      "sin(freq y)/2 + |x| sin(freq y)) (flame files call strength auger_weight)",
      k2D, kFixed, &auger,
      {{"freq", 1.0, -10.0, 10.0}, {"strength", 0.5, -2.0, 2.0}, {"sym", 0.0, -2.0, 2.0}, {"scale", 1.0, -2.0, 2.0}});
  add("flux",
      "w (2 + spread) ((y² + (x + w)²)/(y² + (x − w)²))^¼ (cos a, sin a), z; a = (atan2(y, x − w) − atan2(y, x + w))/2 "
      "(w the weight)",
      k2D, kFixed, &flux, {{"spread", 0.0, -2.0, 2.0}});
  add("mobius", "(a p + b) / (c p + d) with p = x + iy and complex a, b, c, d, z", k2D, kFixed, &mobius,
      {{"re_a", 1.0, -2.0, 2.0},
       {"im_a", 0.0, -2.0, 2.0},
       {"re_b", 0.0, -2.0, 2.0},
       {"im_b", 0.0, -2.0, 2.0},
       {"re_c", 0.0, -2.0, 2.0},
       {"im_c", 0.0, -2.0, 2.0},
       {"re_d", 1.0, -2.0, 2.0},
       {"im_d", 0.0, -2.0, 2.0}});
  add("pre_blur",
      "G (cos 2πΨ, sin 2πΨ), z; G = Ψ + Ψ + Ψ + Ψ − 2: flam3's Gaussian blur added to the point before the "
      "transform's other variations",
      k2D, kRandom, &preBlur);

  // Plugins of Apophysis 7X and JWildfire that real flames use most.
  add("unpolar", "e^y (sin x, cos x) / 2π, z (polar's inverse)", k2D, kFixed, &unpolar);
  add("sineblur", "(acos(2Ψ₂^power − 1)/π) (cos 2πΨ₁, sin 2πΨ₁), z (power ≥ 0)", k2D, kRandom, &sineblur,
      {{"power", 1.0, 0.0, 10.0}});
  add("glynnia",
      "one of two branches at random (Ψ > ½): ±(w√2/2)(√(r + x), −y/√(r + x)), or w (±(r + x), y) / √(r (y² + "
      "(r + x)²)); + outside the unit circle, − inside (w the weight)",
      k2D, kRandom, &glynnia);
  add("epispiral", "(Ψ·thickness / cos(n φ) − holes)(cos φ, sin φ), z", k2D, kRandom, &epispiral,
      {{"n", 6.0, 0.0, 20.0}, {"thickness", 0.0, -2.5, 2.5}, {"holes", 1.0, -5.0, 5.0}});
  add("falloff2",
      "p + blur growing with D = max(0, (|p − (x0, y0, z0)| − mindist)) · 0.04 scatter (|…| as 1 − |…| with invert): "
      "type 0 (mul_x Ψ₁, mul_y Ψ₂, mul_z Ψ₃) D; type 1 r (cos σ cos φ, cos σ sin φ), sin σ with σ = asin(z/r) + "
      "mul_z Ψ₁ D, φ = atan2(y, x) + mul_y Ψ₂ D, r = |p| + mul_x Ψ₃ D; type 2 a Gaussian-like offset D Ψ₃ in a "
      "random direction (2πΨ₁, πΨ₂) scaled by mul_x, mul_y, mul_z (Apophysis 7X's; mul_c, its colour shift, is not "
      "applied)",
      k3D, kRandom, &falloff2,
      {{"scatter", 1.0, 0.0, 20.0},
       {"mindist", 0.5, 0.0, 3.0},
       {"mul_x", 1.0, 0.0, 1.0},
       {"mul_y", 1.0, 0.0, 1.0},
       {"mul_z", 0.0, 0.0, 1.0},
       {"mul_c", 0.0, 0.0, 1.0},
       {"x0", 0.0, -3.0, 3.0},
       {"y0", 0.0, -3.0, 3.0},
       {"z0", 0.0, -3.0, 3.0},
       {"invert", 0.0, 0.0, 1.0},
       {"type", 0.0, 0.0, 2.0}});
  add("crop",
      "(x, y) clamped into [left, right] × [top, bottom]: a coordinate beyond an edge lands Ψ · scatter_area · half "
      "the side inside it; with zero, a point outside goes to the origin instead; z",
      k2D, kRandom, &crop,
      {{"left", -1.0, -5.0, 5.0},
       {"top", -1.0, -5.0, 5.0},
       {"right", 1.0, -5.0, 5.0},
       {"bottom", 1.0, -5.0, 5.0},
       {"scatter_area", 0.0, -1.0, 1.0},
       {"zero", 0.0, 0.0, 1.0}});
  add("julian2",
      "julian of q = (a x + b y + e, c x + d y + f): |q|^(dist/power) (cos α, sin α), z; α = (∠q + 2πk)/power, "
      "k = trunc(|power|·Ψ)",
      k2D, kRandom, &julian2,
      {count("power", 3.0, -12.0, 12.0),
       {"dist", 1.0, -3.0, 3.0},
       {"a", 1.0, -2.0, 2.0},
       {"b", 0.0, -2.0, 2.0},
       {"c", 0.0, -2.0, 2.0},
       {"d", 1.0, -2.0, 2.0},
       {"e", 0.0, -2.0, 2.0},
       {"f", 0.0, -2.0, 2.0}});
  // JWildfire, Apophysis and Fractorium plugins that the corpus's flames use (issue 25).
  add("crackle",
      "C + (U − C) L^power·scale / L, z: U = b (sin 2πΨ₄, cos 2πΨ₄) with b = (Ψ₁ + Ψ₂)/2 + (Ψ₃ − ½)/4, C the "
      "centre of U's cell on a square grid of side cellsize/2 whose centres move by distort · simplex noise of "
      "the cell (noise slice z), L the Voronoi distance of U from C (0 at C, 1 on the edge); nothing for "
      "cellsize 0 (slobo777's plugin, JWildfire's)",
      k2D, kRandom, &crackle,
      {{"cellsize", 1.0, 0.0, 5.0},
       {"power", 0.2, -2.0, 2.0},
       {"distort", 0.0, -2.0, 2.0},
       {"scale", 1.0, -2.0, 2.0},
       {"z", 0.0, -5.0, 5.0}});
  add("smartcrop",
      "p inside the polygon of |power| sides (corners at radius |radius| · c(φ), c from distortion, roundstr and "
      "roundwidth; the edge jittered by edge · (Ψ − ½)); outside: r (cos(φ + rotation·2π/power), sin(…)), z "
      "with r = edge + c (Ψ scatter + offset) (cropmode 1), |p| (−1), or the origin (0); for |power| < 2 the "
      "sector |power|·π instead, outside turned to a random side of it; power < 0 or radius < 0 (not both) "
      "keeps the outside; cropmode 2 drops the point (Zy0rg's post_smartcrop as Fractorium has it; only "
      "static 2, the point itself, is supported)",
      k3D, kRandom, &smartcrop,
      {{"power", 4.0, -10.0, 10.0},
       {"radius", 1.0, -3.0, 3.0},
       {"roundstr", 0.0, -1.0, 1.0},
       {"roundwidth", 1.0, 0.0, 5.0},
       {"distortion", 1.0, 0.0, 2.0},
       {"edge", 0.0, -0.5, 0.5},
       {"scatter", 0.0, -1.0, 1.0},
       {"offset", 0.0, -1.0, 1.0},
       {"rotation", 0.0, -1.0, 1.0},
       count("cropmode", 1.0, -1.0, 2.0),
       count("static", 2.0, -1.0, 3.0)});
  add("epispiral_wf", "(½ / cos(waves·θ)) (sin θ, cos θ), z; nothing where the cosine is 0 (JWildfire's)", k2D, kFixed,
      &epispiralWf, {{"waves", 4.0, -20.0, 20.0}});
  add("blur_circle",
      "s (cos α, sin α), z: (u, v) = (2Ψ₁ − 1, 2Ψ₂ − 1), s = max(|u|, |v|), α = (π/4)·(position of (u, v) along "
      "the square's perimeter, 0–8)/s − π/4: a uniform square folded onto the unit disc",
      k2D, kRandom, &blurCircle);
  add("blur_linear", "(x + Ψ·length·cos angle, y + Ψ·length·sin angle, z) (Joel Faber's)", k2D, kRandom, &blurLinear,
      {{"length", 1.0, 0.0, 3.0}, {"angle", 0.5, -kPi, kPi}});
  add("exblur",
      "G |q|^(2 dist) ((sin β cos α, sin β sin α, cos β) + r (sin v cos u, sin v sin u, cos v)); q = (x − x_origin, "
      "y + y_origin, z − z_origin), α = atan2(q_y, q_x), β = acos(q_z/|q|), u = 2πΨ₁, v = 2πΨ₂, G = Ψ + Ψ + Ψ + Ψ − 2 "
      "(Zephyrtronium's, as JWildfire has it)",
      k3D, kRandom, &exblur,
      {{"dist", 0.5, -2.0, 2.0},
       {"r", 0.25, -2.0, 2.0},
       {"x_origin", 0.0, -2.0, 2.0},
       {"y_origin", 0.0, -2.0, 2.0},
       {"z_origin", 0.0, -2.0, 2.0}});
  add("twoface", "(x, y)/r² for x > 0, else (x, y); z", k2D, kFixed, &twoface);
  add("hypertile",
      "(p + c̄)/(c p + 1) with p = x + iy, c = ρ e^(2πi·n/p), ρ = 1/√(1 + (1 − cos 2π/p)/(cos 2π/p + cos 2π/q)); z "
      "(Zueuk's: one tile of the {p, q} hyperbolic tiling; p, q and n real, as Fractorium reads them)",
      k2D, kFixed, &hypertile, {{"p", 3.0, 3.0, 10.0}, {"q", 7.0, 3.0, 10.0}, {"n", 1.0, 0.0, 10.0}});
  add("hypertile1", "hypertile with n = ⌊Ψ·trunc(p)⌋: a random neighbouring tile", k2D, kRandom, &hypertile1,
      {{"p", 3.0, 3.0, 10.0}, {"q", 7.0, 3.0, 10.0}});
  add("hypertile2",
      "(p + ρ)/(ρ p + 1) turned by −2π·trunc(Ψ·|p|)/p (by −2πΨ for a p that is not whole), p = x + iy, ρ as "
      "hypertile; z (Zueuk's)",
      k2D, kRandom, &hypertile2, {{"p", 3.0, 3.0, 10.0}, {"q", 7.0, 3.0, 10.0}});
  add("hypertile3D1",
      "d (x (1 + cx² − cy²) − cx (2 cy y − |p|² − 1), y (1 + cy² − cx²) − cy (2 cx x + |p|² + 1), z (1 − r²)), "
      "d = 1/(r² |p|² + 2 cx x − 2 cy y + 1); (cx, cy) = r (cos a, sin a), a = ⌊Ψ·p⌋·2π/p a random neighbouring "
      "tile (2πΨ for a p that is not whole), r = 1/√(1 + (1 − cos 2π/p)/(cos 2π/p + cos 2π/q)) (Zueuk's)",
      k3D, kRandom, &hypertile3D1, {{"p", 3.0, 3.0, 10.0}, {"q", 7.0, 3.0, 10.0}});
  add("hypertile3D2",
      "(x (1 + c²) + c (|p|² + 1), y (1 − c²), z (1 − c²)) / (c² |p|² + 2cx + 1), x and y turned as hypertile2; "
      "c = 1/√(1 + (1 − cos 2π/p)/(cos 2π/p + cos 2π/q)) (Zueuk's)",
      k3D, kRandom, &hypertile3D2, {{"p", 3.0, 3.0, 10.0}, {"q", 7.0, 3.0, 10.0}});
  add("rotate_x",
      "(x, y cos α + z sin α, z cos α − y sin α), α = weight·π/2: the weight is the angle, so this adds the turned "
      "point itself (Apophysis 7X's; pre_ and post_ forms turn the point)",
      k3D, kFixed, &rotateX);
  add("rotate_y", "(x cos α − z sin α, y, x sin α + z cos α), α = weight·π/2 (as rotate_x)", k3D, kFixed, &rotateY);
  add("rotate_z", "(x cos α + y sin α, y cos α − x sin α, z), α = weight·π/2 (as rotate_x)", k3D, kFixed, &rotateZ);
  add("foci_3D",
      "(e − 1/(4e), sin y, sin b) / (e + 1/(4e) − cos y cos b); e = eˣ/2, b = z, or φ where z is 0 (Larry Berlin's)",
      k3D, kFixed, &foci3D);
  add("circlecrop",
      "inside the circle of radius about (x, y): the point; outside: the origin with zero, else the circle's "
      "edge pushed out by Ψ·scatter_area/2 in the point's direction (the centre not scaled by the weight); z "
      "(Xyrus02's)",
      k2D, kRandom, &circlecrop,
      {{"radius", 1.0, 0.0, 5.0},
       {"x", 0.0, -3.0, 3.0},
       {"y", 0.0, -3.0, 3.0},
       {"scatter_area", 0.0, -1.0, 1.0},
       count("zero", 1.0, 0.0, 1.0)});
  add("bwraps",
      "in the bubble of radius ρ = cellsize/(2(1 + space²)) at the centre C of the point's cell: C + R(θ)·q, q = "
      "(p − C)·g·k/(|p − C|²g²/4 + 1), g = gain² + 10⁻⁶, k = ρ/b, b = gρ/((gρ)²/4 + 1) (1 when gρ > 2), θ = "
      "inner_twist (1 − |q|²/ρ²) + outer_twist |q|²/ρ²; elsewhere p; z (Xyrus02's, as Fractorium has it)",
      k2D, kFixed, &bwraps,
      {{"cellsize", 1.0, 0.0, 5.0},
       {"space", 0.0, -2.0, 2.0},
       {"gain", 1.0, -5.0, 5.0},
       {"inner_twist", 0.0, -kPi, kPi},
       {"outer_twist", 0.0, -kPi, kPi}});
  add("juni",
      "where 0 < r² ≤ w² (with invert: r² ≥ w² or r² = 0): |p′|^(stretch/power − 1)·r (cos α, sin α), α = (∠A(p) + "
      "2πk)/power, k = trunc(|power|·Ψ), A the transform's affine map, p′ = (x, y, z/|power|); elsewhere (x, y); "
      "z: |p′|^(stretch/power − 1)·z/|power| (w the weight; Joel Faber's plugin)",
      k3D, kRandom, &juni,
      {count("power", 2.0, -10.0, 10.0), count("invert", 0.0, 0.0, 1.0), {"stretch", 1.0, -3.0, 3.0}});
  add("acoth",
      "(2/π)(Im w, Re w), z for w = acoth(x + iy) = ½ log((1 + 1/p)/(1 − 1/p)): real and imaginary parts swapped "
      "(Whittaker Courtney's, JWildfire's)",
      k2D, kFixed, &acoth);
  add("bi_linear", "(y, x, z)", k2D, kFixed, &biLinear);
  add("blur_zoom", "((x − cx)(1 + Ψ·length) + cx, (y + cy)(1 + Ψ·length) − cy, z), (cx, cy) = (x, y) of the parameters",
      k2D, kRandom, &blurZoom, {{"length", 0.24, 0.0, 2.0}, {"x", 0.2, -2.0, 2.0}, {"y", -0.1, -2.0, 2.0}});
  add("inflateZ_3", "(0, 0, 0.2 (π − φ) cos(3φ + y − x)): adds to z only (Larry Berlin's)", k3D, kFixed, &inflateZ3);
  add("eJulia",
      "(cosh μ′ cos ν′, sinh μ′ sin ν′), z; (μ, ν) the elliptic coordinates of p (of p/r² for a negative power), "
      "μ′ = μ/power, ν′ = (ν + 2π⌊Ψ·power⌋)/power (Michael Faber's)",
      k2D, kRandom, &eJulia, {count("power", 2.0, -10.0, 10.0)});
  add("eMotion",
      "(cosh μ′ cos ν′, sinh μ′ sin ν′), z; (μ, ν) the elliptic coordinates of p, μ′ = μ + move for ν < 0 else μ − "
      "move, reflected (μ′, ν) → (−μ′, −ν) where μ′ ≤ 0, then ν′ = ν + rotate (Michael Faber's)",
      k2D, kFixed, &eMotion, {{"move", 0.0, -2.0, 2.0}, {"rotate", 0.0, -kPi, kPi}});
  add("hexes",
      "C + R(−2π·rotate)(p − C)·L^power·scale/L, z: C the centre of p's hexagon (size cellsize), L its Voronoi "
      "distance (blended with that after the turn between 0.5 and 0.8); nothing for cellsize 0 (slobo777's)",
      k2D, kFixed, &hexes,
      {{"cellsize", 1.0, 0.0, 5.0},
       {"power", 1.0, -2.0, 2.0},
       {"rotate", 0.166, -1.0, 1.0},
       {"scale", 1.0, -2.0, 2.0}});
  add("glynnSim1",
      "inside the circle of radius, and where p (mirrored into it, p·radius²/r², with chance "
      "contrast·(radius/r)^|pow|) "
      "falls in the circle of radius1 at angle phi1° on its rim: a random point of that circle's ring (inner share "
      "thickness); elsewhere p (or its mirror); z (eralex61's)",
      k2D, kRandom, &glynnSim1,
      {{"radius", 1.0, 0.0, 3.0},
       {"radius1", 0.1, 0.0, 1.0},
       {"phi1", 110.0, -360.0, 360.0},
       {"thickness", 0.1, 0.0, 1.0},
       {"pow", 1.5, -5.0, 5.0},
       {"contrast", 0.5, 0.0, 1.0}});
  add("cropn",
      "p inside the polygon of |power| sides (at least 2) reaching radius at its edges' middles; outside: p·(e + "
      "Ψ·scatterdist)/|p| with e the edge's distance in p's direction, or the origin with zero 0; power < 0 keeps "
      "the outside; z (Fractorium's default mode)",
      k2D, kRandom, &cropn,
      {{"power", 5.0, -10.0, 10.0},
       {"radius", 1.0, 0.0, 5.0},
       {"scatterdist", 0.0, -1.0, 1.0},
       count("zero", 0.0, 0.0, 1.0)});
  add("julian3Dx",
      "ρ^(dist/power − 1)·(r cos α, r sin α, z/|power|), ρ = |(x, y, z/|power|)|, α = (∠q + 2πk)/power, q = (a x + b y "
      "+ e, c x + d y + f), k = trunc(|power|·Ψ) (Xyrus02's)",
      k3D, kRandom, &julian3Dx,
      {{"dist", 1.0, -3.0, 3.0},
       count("power", 2.0, -10.0, 10.0),
       {"a", 1.0, -2.0, 2.0},
       {"b", 0.0, -2.0, 2.0},
       {"c", 0.0, -2.0, 2.0},
       {"d", 1.0, -2.0, 2.0},
       {"e", 0.0, -2.0, 2.0},
       {"f", 0.0, -2.0, 2.0}});
  add("flatten", "(0, 0, 0), and the transform's z is 0 after its variations (Apophysis 3D's flatten)", k3D, kFixed,
      &flatten);
  addMoreVariations(c);
  for (VariationInfo& info : c)
    if (info.name == "zblur" || info.name == "zscale" || info.name == "ztranslate" || info.name == "zcone" ||
        info.name == "flatten" || info.name == "inflateZ_3")
      info.mapsXY = false;
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

namespace {

// Whether a variation's result depends on the point: it is run at two points with the same random
// state and default parameters, and its mapped coordinates compared.
bool resultIgnoresThePoint(const VariationInfo& info) {
  constexpr double kAffine[12] = {0.9, 0.2, 0.0, 0.3, -0.1, 0.8, 0.0, -0.4, 0.0, 0.0, 1.0, 0.0};
  const std::vector<double> params = info.defaultParams();
  const auto at = [&](double x, double y, double z) {
    std::uint32_t random = 0x2545F491u;
    double ox = 0.0, oy = 0.0, oz = 0.0;
    VariationInput in;
    in.x = &x;
    in.y = &y;
    in.z = &z;
    in.random = &random;
    in.count = 1;
    in.params = params.data();
    in.affine = kAffine;
    in.tx = &x;
    in.ty = &y;
    in.tz = &z;
    info.apply(in, &ox, &oy, &oz);
    return std::array<double, 3>{info.mapsXY ? ox : 0.0, info.mapsXY ? oy : 0.0, info.threeD ? oz : 0.0};
  };
  return at(0.3, -0.7, 0.5) == at(-0.45, 0.2, -0.35);
}

}  // namespace

const std::vector<VariationInfo>& variationCatalogue() {
  static const std::vector<VariationInfo> catalogue = [] {
    std::vector<VariationInfo> c = buildCatalogue();
    for (VariationInfo& info : c) info.additive = resultIgnoresThePoint(info);
    return c;
  }();
  return catalogue;
}

namespace {

const VariationInfo* catalogueEntry(std::string_view name) {
  for (const auto& info : variationCatalogue())
    if (info.name == name) return &info;
  return nullptr;
}

constexpr std::string_view kPrePrefix = "pre_", kPostPrefix = "post_";

}  // namespace

VariationStage variationStage(std::string_view name) {
  // flam3's pre_blur is an entry of its own that acts before the others.
  if (catalogueEntry(name)) return name.starts_with(kPrePrefix) ? VariationStage::Pre : VariationStage::Normal;
  if (name.starts_with(kPrePrefix) && catalogueEntry(name.substr(kPrePrefix.size()))) return VariationStage::Pre;
  if (name.starts_with(kPostPrefix) && catalogueEntry(name.substr(kPostPrefix.size()))) return VariationStage::Post;
  return VariationStage::Normal;
}

const VariationInfo* findVariation(std::string_view name) {
  if (const VariationInfo* info = catalogueEntry(name)) return info;
  if (name.starts_with(kPrePrefix)) return catalogueEntry(name.substr(kPrePrefix.size()));
  if (name.starts_with(kPostPrefix)) return catalogueEntry(name.substr(kPostPrefix.size()));
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
     << "Every variation also has a `pre_` and a `post_` form (`pre_spherical`, `post_curl`), as in Apophysis "
        "7X,\nJWildfire and Fractorium: a transform applies its `pre_` terms one after the other to the point after "
        "its\naffine map, then sums its other variations, then applies its `post_` terms to the sum, before its "
        "post map.\nSuch a term replaces the coordinates its variation maps (x and y for a 2D one, z too for a 3D "
        "one, z alone\nfor zscale, zcone, zblur, ztranslate, inflateZ_3 and flatten) by weight · V(p) and keeps the "
        "others; a "
        "variation whose\nresult does not depend on the point (the blurs, ztranslate) adds weight · V(p) instead. "
        "`pre_blur` is\nflam3's own: a Gaussian blur added to the point first.\n\n"
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
