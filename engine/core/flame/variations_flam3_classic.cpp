// flam3's classic variations (variations.c, in flam3's order): x and y mapped, z carried through.
// Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

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

}  // namespace

void variation_kernels::addFlam3ClassicVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  const auto jwildfireInt = &CatalogueAdder::jwildfireInt;

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
      {jwildfireInt("power", 4.0, -12.0, 12.0), {"dist", 1.0, -3.0, 3.0}});
  add("juliascope", "r^(dist/power)·(cos α, sin α), z; α = (2πk ± φ)/power, k = trunc(|power|·Ψ), − for odd k", k2D,
      kRandom, &juliascope, {jwildfireInt("power", 4.0, -12.0, 12.0), {"dist", 1.0, -3.0, 3.0}});
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
}

}  // namespace voxflame::core
