// More of JWildfire's own variations: filled curves (rose, heart, maple leaf), waves, complex inverse hyperbolic
// functions, tangent3D, and its post_ mirrors and z scale. Each variation is a kernel below and one row of the table
// at the end (see variations.h for the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// As in variations_jwildfire_shapes.cpp: a curve point moved towards the origin by Ψ₂ when Ψ₁ < filled; both
// numbers are drawn for every point (JWildfire draws the second only when it is used).
inline double filledScale(double filled, std::uint32_t& state) {
  const double psi1 = laneUniform(state), psi2 = laneUniform(state);
  return filled > 0.0 && filled > psi1 ? psi2 : 1.0;
}

inline double power10(double v) {
  const double v2 = v * v, v4 = v2 * v2;
  return v4 * v4 * v2;
}

// rose_wf (JWildfire's): the rose r = amp cos(waves θ) at angle θ = atan2(x, y), filled as above; waves is rounded.
VOXFLAME_VARIATION_TARGETS void roseWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double amp = P[0], waves = std::round(P[1]), filled = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(x[i], y[i]);
    const double r = amp * std::cos(waves * a) * filledScale(filled, rnd[i]);
    outX[i] += w * std::sin(a) * r;
    outY[i] += w * std::cos(a) * r;
    outZ[i] += w * z[i];
  }
}

// heart_wf (JWildfire's): the angle θ = atan2(x, y) picks t on a heart curve (t = |θ|/π · 60 · scale_r_left or
// scale_r_right by the side, less shift_t, at most 60), drawn at the point's distance r from the origin.
VOXFLAME_VARIATION_TARGETS void heartWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], shiftT = P[1], scaleLeft = P[2], scaleRight = P[3];
  constexpr double kTMax = 60.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(x[i], y[i]);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const bool left = a < 0.0;
    const double t = std::min((left ? -a : a) / kPi * kTMax * (left ? scaleLeft : scaleRight) - shiftT, kTMax);
    const double side = left ? -1.0 : 1.0;
    const double nx = side * 0.001 * (-t * t + 40.0 * t + 1200.0) * std::sin(kPi * t / 180.0) * r;
    const double ny = -0.001 * (-t * t + 40.0 * t + 400.0) * std::cos(kPi * t / 180.0) * r;
    outX[i] += w * nx * scaleX;
    outY[i] += w * ny;
    outZ[i] += w * z[i];
  }
}

// maple_leaf (JWildfire's): Hamid Naderi Yeganeh's maple leaf (x(t), y(t)) at t = θ − π/2, filled as above. In
// JWildfire's x(t) the term 1/4 cos²(30t) is Java's integer 1/4 = 0, so it is left out here too.
VOXFLAME_VARIATION_TARGETS void mapleLeaf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double filled = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::atan2(x[i], y[i]) - kPi / 2.0;
    const double r = w * filledScale(filled, rnd[i]);
    const double c6 = std::cos(6.0 * t), c30 = std::cos(30.0 * t), ct = std::cos(t), c3 = std::cos(3.0 * t);
    const double ct2 = ct * ct, ct4 = ct2 * ct2;
    const double c30sq = c30 * c30, c30p4 = c30sq * c30sq, c30p12 = c30p4 * c30p4 * c30p4;
    const double notch = 1.0 - power10(std::sin(6.0 * t));
    const double lobe = 1.0 - power10(ct) * c3 * c3;
    const double lx = (1.0 + c6 * c6 + 0.2 * power10(c6 * std::cos(24.0 * t)) + (c30p12 / 9.0) * notch) *
                      std::sin(2.0 * t) * (1.0 - ct4) * lobe;
    const double ly =
        21.0 / 20.0 * std::cos(2.0 * t) * (1.0 - ct4 + 0.5 * power10(ct * c3)) *
        (1.0 + c6 * c6 + 0.2 * power10(c6 * std::cos(18.0 * t)) + (c30p4 / 4.0 + c30p12 / 10.0) * lobe * notch);
    outX[i] += r * lx;
    outY[i] += r * ly;
    outZ[i] += w * z[i];
  }
}

// waves3_wf (JWildfire's): waves2_wf with the squared sine or cosine.
VOXFLAME_VARIATION_TARGETS void waves3Wf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], freqX = P[2], freqY = P[3];
  const bool cosX = std::round(P[4]) == 1.0, cosY = std::round(P[5]) == 1.0;
  const double dampX = std::abs(P[6]) < kJwfEpsilon ? 1.0 : std::exp(P[6]);
  const double dampY = std::abs(P[7]) < kJwfEpsilon ? 1.0 : std::exp(P[7]);
  for (std::size_t i = 0; i < n; ++i) {
    const double wx = cosX ? std::cos(y[i] * freqX) : std::sin(y[i] * freqX);
    const double wy = cosY ? std::cos(x[i] * freqY) : std::sin(x[i] * freqY);
    outX[i] += w * (x[i] + dampX * scaleX * wx * wx) * dampX;
    outY[i] += w * (y[i] + dampY * scaleY * wy * wy) * dampY;
    outZ[i] += w * z[i];
  }
}

// tangent3D (Apophysis 3D's tangent, as JWildfire has it): (sin x / cos y, tan y, tan x).
VOXFLAME_VARIATION_TARGETS void tangent3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]) / std::cos(y[i]);
    outY[i] += w * std::tan(y[i]);
    outZ[i] += w * std::tan(x[i]);
  }
}

// ---- complex inverse hyperbolic functions (Whittaker Courtney's, after Tatyana Zabanova and dark-beam) ----------

// JWildfire's Complex: acosh q = log(q + √(q² − 1)) with its square root (the root with a non-negative real part, the
// imaginary part taking the sign of q² − 1's, + for 0) and its logarithm (½ log(|·|² + 10⁻²⁰), atan2).
inline void jwfAcosh(double& re, double& im) {
  const double dr = re * re - im * im - 1.0, di = 2.0 * re * im;
  const double radius = std::hypot(dr, di);
  const double sr = std::sqrt(0.5 * (radius + dr)), si = (di < 0.0 ? -1.0 : 1.0) * std::sqrt(0.5 * (radius - dr));
  const double ar = re + sr, ai = im + si;
  re = 0.5 * std::log(ar * ar + ai * ai + 1e-20);
  im = std::atan2(ai, ar);
}

// acosh: acosh(x + iy)·2/π, negated half the time (Ψ ≥ ½).
VOXFLAME_VARIATION_TARGETS void acoshJwf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = w * 2.0 / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    double re = x[i], im = y[i];
    jwfAcosh(re, im);
    const double sign = laneUniform(rnd[i]) < 0.5 ? scale : -scale;
    outX[i] += sign * re;
    outY[i] += sign * im;
    outZ[i] += w * z[i];
  }
}

// acosech: acosh(1/(x + iy)) with its real and imaginary parts swapped, ·2/π, negated half the time (Ψ ≥ ½).
// JWildfire's 1/q keeps q where |q|² < 10⁻¹⁰⁰ (it conjugates it only).
VOXFLAME_VARIATION_TARGETS void acosechJwf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = w * 2.0 / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const double m2 = x[i] * x[i] + y[i] * y[i];
    const double inverse = m2 < 1e-100 ? 1.0 : 1.0 / m2;
    double re = x[i] * inverse, im = -y[i] * inverse;
    jwfAcosh(re, im);
    const double sign = laneUniform(rnd[i]) < 0.5 ? scale : -scale;
    outX[i] += sign * im;
    outY[i] += sign * re;
    outZ[i] += w * z[i];
  }
}

// ---- JWildfire's post_ helpers --------------------------------------------------------------------------------

// zscale_wf (JWildfire's post_zscale_wf): z scaled by the weight and moved by ztranslate; x and y are kept (it maps z
// alone, so its post_ form replaces only z).
VOXFLAME_VARIATION_TARGETS void zscaleWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double translate = P[0];
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * z[i] + translate;
}

// mirror_wf (JWildfire's post_mirror_wf): with xaxis, half the time (Ψ₁ < ½) x becomes xscale (−x − xshift) and y
// yscale·y; then with yaxis, half the time (Ψ₂ < ½) x becomes xscale·x and y yscale (−y − yshift); then with zaxis,
// half the time (Ψ₃ < ½) z becomes −z − zshift. The weight only switches it off (|w| ≤ 10⁻⁸): the result is the point
// itself. All three numbers are drawn for every point. Each mirroring moves the colour index by its axis' colour shift
// (mod 1, negative below 0 as JWildfire's fmod).
VOXFLAME_VARIATION_TARGETS void mirrorWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const bool active = std::abs(w) > kJwfEpsilon;
  const bool xAxis = active && std::round(P[0]) > 0.0, yAxis = active && std::round(P[1]) > 0.0,
             zAxis = active && std::round(P[2]) > 0.0;
  const double xShift = P[3], yShift = P[4], zShift = P[5], xScale = P[6], yScale = P[7];
  const double xColour = P[8], yColour = P[9], zColour = P[10];
  for (std::size_t i = 0; i < n; ++i) {
    const double psi1 = laneUniform(rnd[i]), psi2 = laneUniform(rnd[i]), psi3 = laneUniform(rnd[i]);
    double px = x[i], py = y[i], pz = z[i];
    if (xAxis && psi1 < 0.5) {
      px = xScale * (-px - xShift);
      py = yScale * py;
      colour[i] = std::fmod(colour[i] + xColour, 1.0);
    }
    if (yAxis && psi2 < 0.5) {
      px = xScale * px;
      py = yScale * (-py - yShift);
      colour[i] = std::fmod(colour[i] + yColour, 1.0);
    }
    if (zAxis && psi3 < 0.5) {
      pz = -pz - zShift;
      colour[i] = std::fmod(colour[i] + zColour, 1.0);
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += pz;
  }
}

// ---- Brad Stefanov's complex trigonometric functions with separate frequencies (as JWildfire has them) ----------
// Each takes sin and cos of x (or y) at frequencies x1, x2 (y1, y2) where the plain function has 1; where the
// denominator is exactly 0 JWildfire adds nothing at all (z included), and so do these.

// cos2_bs: (cos(x2 x) cosh(y2 y), −sin(x1 x) sinh(y1 y)).
VOXFLAME_VARIATION_TARGETS void cos2Bs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double x1 = P[0], x2 = P[1], y1 = P[2], y2 = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::cos(x[i] * x2) * std::cosh(y[i] * y2);
    outY[i] -= w * std::sin(x[i] * x1) * std::sinh(y[i] * y1);
    outZ[i] += w * z[i];
  }
}

// coth2_bs: (sinh(x1 x), sin(y1 y))/(cosh(x2 x) − cos(y2 y)).
VOXFLAME_VARIATION_TARGETS void coth2Bs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double x1 = P[0], x2 = P[1], y1 = P[2], y2 = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::cosh(x2 * x[i]) - std::cos(y2 * y[i]);
    if (d == 0.0) continue;
    const double f = w / d;
    outX[i] += f * std::sinh(x1 * x[i]);
    outY[i] += f * std::sin(y1 * y[i]);
    outZ[i] += w * z[i];
  }
}

// sec2_bs: 2 (cos(x2 x) cosh(y2 y), sin(x1 x) sinh(y1 y))/(cos 2x + cosh 2y).
VOXFLAME_VARIATION_TARGETS void sec2Bs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double x1 = P[0], x2 = P[1], y1 = P[2], y2 = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::cos(2.0 * x[i]) + std::cosh(2.0 * y[i]);
    if (d == 0.0) continue;
    const double f = w * 2.0 / d;
    outX[i] += f * std::cos(x[i] * x2) * std::cosh(y[i] * y2);
    outY[i] += f * std::sin(x[i] * x1) * std::sinh(y[i] * y1);
    outZ[i] += w * z[i];
  }
}

// tan2_bs: (sin(x1 x), sinh(y1 y))/(cos(x2 x) + cosh(y2 y)).
VOXFLAME_VARIATION_TARGETS void tan2Bs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double x1 = P[0], x2 = P[1], y1 = P[2], y2 = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::cos(x2 * x[i]) + std::cosh(y2 * y[i]);
    if (d == 0.0) continue;
    const double f = w / d;
    outX[i] += f * std::sin(x1 * x[i]);
    outY[i] += f * std::sinh(y1 * y[i]);
    outZ[i] += w * z[i];
  }
}

// ---- shapes ----------------------------------------------------------------------------------------------------

// triangle (Jesus Sosa's, as JWildfire has it): a uniform random point of the triangle (x1, y1, z1), (x2, y2, z2),
// (x3, y3, z3) (barycentric 1 − √Ψ₁, √Ψ₁ (1 − Ψ₂), √Ψ₁ Ψ₂); the point itself is not used, and JWildfire assigns all
// three coordinates (VariationInfo::replaces).
VOXFLAME_VARIATION_TARGETS void triangle(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double root = std::sqrt(laneUniform(rnd[i])), r2 = laneUniform(rnd[i]);
    const double a = 1.0 - root, b = root * (1.0 - r2), c = r2 * root;
    outX[i] += w * (a * P[0] + b * P[3] + c * P[6]);
    outY[i] += w * (a * P[1] + b * P[4] + c * P[7]);
    outZ[i] += w * (a * P[2] + b * P[5] + c * P[8]);
  }
}

// chunk (zephyrtronium's Apophysis plugin, as JWildfire has it): the point where the conic w (a x² + b xy + c y² + d x
// + e y + f) is ≤ 0 (mode 0) or > 0 (mode 1), else nothing; x and y are not weighted, z is (JWildfire's).
VOXFLAME_VARIATION_TARGETS void chunk(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = w * P[0], b = w * P[1], c = w * P[2], d = w * P[3], e = w * P[4], f = w * P[5];
  const bool outside = std::clamp(std::round(P[6]), 0.0, 1.0) == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = a * x[i] * x[i] + b * x[i] * y[i] + c * y[i] * y[i] + d * x[i] + e * y[i] + f;
    const bool keep = outside ? r > 0.0 : r <= 0.0;
    outX[i] += keep ? x[i] : 0.0;
    outY[i] += keep ? y[i] : 0.0;
    outZ[i] += keep ? w * z[i] : 0.0;
  }
}

// spirograph3D (as JWildfire has it): the point at t = tmin + (tmax − tmin)Ψ of the 3D spirograph ((a + b) cos t −
// c cos(((a + b)/b) t), (a + b) sin t − c sin(((a + b)/b) t), c sin(((a + b)/b) t)), thickened by width: mode 0 one
// offset along (1, 1, 1), 1 that offset turned along the curve, 2 three uniform offsets, 3 three bell-shaped ones, 4
// ±width along x. The point itself is not used. Its direct colour is not applied (the importer says so).
VOXFLAME_VARIATION_TARGETS void spirograph3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1], c = P[2], tMin = P[3], tMax = P[4], width = P[5];
  const double mode = std::clamp(std::round(P[6]), 0.0, 4.0);
  const double ab = a + b, ratio = (a + b) / b;
  const bool directColour = std::clamp(std::round(P[7]), 0.0, 1.0) == 1.0;  // Tools.FTOI
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (tMax - tMin) * laneUniform(rnd[i]) + tMin;
    if (directColour) colour[i] = std::fmod(t / kTwoPi, 1.0);  // negative below t = 0, as JWildfire's
    double w1 = 0.0, w2 = 0.0, w3 = 0.0;
    if (mode == 0.0) {
      w1 = w2 = w3 = width * laneUniform(rnd[i]) - width / 2.0;
    } else if (mode == 1.0) {
      const double offset = width * laneUniform(rnd[i]) - width / 2.0;
      w1 = offset * std::sin(36.0 * t);
      w2 = offset * std::sin(36.0 * t + kTwoPi / 3.0);
      w3 = offset * std::sin(36.0 * t + 2.0 * kTwoPi / 3.0);
    } else if (mode == 2.0) {
      w1 = width * laneUniform(rnd[i]) - width / 2.0;
      w2 = width * laneUniform(rnd[i]) - width / 2.0;
      w3 = width * laneUniform(rnd[i]) - width / 2.0;
    } else if (mode == 3.0) {
      w1 = width * laneGauss(rnd[i]) / 2.0;
      w2 = width * laneGauss(rnd[i]) / 2.0;
      w3 = width * laneGauss(rnd[i]) / 2.0;
    } else {
      w1 = laneUniform(rnd[i]) < 0.5 ? width : -width;
    }
    outX[i] += w * (ab * std::cos(t) - c * std::cos(ratio * t) + w1);
    outY[i] += w * (ab * std::sin(t) - c * std::sin(ratio * t) + w2);
    outZ[i] += w * (c * std::sin(ratio * t) + w3);
  }
}

// ---- rhodonea ------------------------------------------------------------------------------------------------------

// rhodonea (CozyG's, as JWildfire has it): the rose r = cos(k t) + radial_offset, k = knumer/kdenom, at t = cycles·(φ +
// 2π cycle_offset), spread about the curve by the point's distance: inner_mode for points within the petal (spread
// · ratio x, spread y), outer_mode for points beyond it (modes 0–6: on the curve, scaled by the distance, pulled
// towards the point, pushed by it, halved distance plus spread, the point itself (unweighted) or dropped). cycles (0:
// enough to close the curve, times metacycles) as JWildfire works it out; each closed round adds metacycle_expansion
// to the weight. JWildfire hides a dropped point; here it is dropped (NaN, the chaos game's escape). Ψ is drawn for
// every point (JWildfire draws it only with fill). Where knumer/kdenom is not a ratio of integers JWildfire closes
// after 16 cycles on its first render, which is taken here.
struct RhodoneaSetup {
  double k, cycles, cyclesToClose;
};

inline double javaFmod(double a, double b) {
  return std::fmod(a, b);  // Java's % on doubles is C's fmod
}

inline std::int64_t javaLong(double value) {
  if (std::isnan(value)) return 0;
  if (value >= 9.2233720368547758e18) return std::numeric_limits<std::int64_t>::max();
  if (value <= -9.2233720368547758e18) return std::numeric_limits<std::int64_t>::min();
  return static_cast<std::int64_t>(value);
}

// BigInteger.gcd: the non-negative greatest common divisor (of |a| and |b|; gcd(0, 0) = 0).
inline double bigGcd(std::int64_t a, std::int64_t b) {
  std::uint64_t ua = a < 0 ? 0 - static_cast<std::uint64_t>(a) : static_cast<std::uint64_t>(a);
  std::uint64_t ub = b < 0 ? 0 - static_cast<std::uint64_t>(b) : static_cast<std::uint64_t>(b);
  while (ub != 0) {
    const std::uint64_t r = ua % ub;
    ua = ub;
    ub = r;
  }
  return static_cast<double>(ua);
}

RhodoneaSetup rhodoneaSetup(const double* P) {
  const double knumer = P[0], kdenom = P[1], innerSpread = P[4], outerSpread = P[5], fill = P[9], radialOffset = P[10];
  const double cyclesParam = P[11], metacycles = P[13];
  RhodoneaSetup s{};
  double kn = knumer, kd = kdenom;
  s.k = kn / kd;
  if (javaFmod(s.k, 1.0) == 0.0) {
    if (javaFmod(s.k, 2.0) == 0.0)
      s.cyclesToClose = 1.0;
    else
      s.cyclesToClose = radialOffset != 0.0 || innerSpread != 0.0 || outerSpread != 0.0 || fill != 0.0 ? 1.0 : 0.5;
  } else if (javaFmod(kn, 1.0) == 0.0 && javaFmod(kd, 1.0) == 0.0) {
    // BigInteger.valueOf((long) kn) and of (int) kd.
    const double gcd = bigGcd(javaLong(kn), javaInt(kd));
    if (gcd != 1.0) {
      kn /= gcd;
      kd /= gcd;
    }
    s.cyclesToClose = javaFmod(kn, 2.0) == 0.0 || javaFmod(kd, 2.0) == 0.0 ? kd : kd / 2.0;
  } else {
    s.cyclesToClose = 16.0;
  }
  s.cycles = cyclesParam == 0.0 ? s.cyclesToClose * metacycles : cyclesParam;
  return s;
}

VOXFLAME_VARIATION_TARGETS void rhodonea(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const RhodoneaSetup s = rhodoneaSetup(P);
  const auto modeOf = [](double v) {
    const double m = std::floor(v);
    return m >= 0.0 && m <= 6.0 ? m : 0.0;
  };
  const double innerMode = modeOf(P[2]), outerMode = modeOf(P[3]);
  const double innerSpread = P[4], outerSpread = P[5], innerRatio = P[6], outerRatio = P[7], split = P[8];
  const double fill = P[9], radialOffset = P[10], cycleOffset = P[12], expansionStep = P[14];
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    const double psi = laneUniform(rnd[i]);
    const double rin = split * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double tin = std::atan2(y[i], x[i]);
    const double t = s.cycles * (tin + cycleOffset * kTwoPi);
    double r = std::cos(s.k * t) + radialOffset;
    if (fill != 0.0) r += fill * (psi - 0.5);
    const double cx = r * std::cos(t), cy = r * std::sin(t);
    const double expansion = std::floor(s.cycles * (tin + kPi) / (s.cyclesToClose * kTwoPi));
    const double amount = w + expansion * expansionStep;
    const bool outer = std::abs(rin) > std::abs(r);
    const double mode = outer ? outerMode : innerMode;
    const double spread = outer ? outerSpread : innerSpread, ratio = outer ? outerRatio : innerRatio;
    // The point's coordinates with the signs of the curve's.
    const double xin = cx < 0.0 ? -std::abs(x[i]) : std::abs(x[i]), yin = cy < 0.0 ? -std::abs(y[i]) : std::abs(y[i]);
    double px = amount * cx, py = amount * cy;
    bool zeroXIfNoY = false;
    if (mode == 1.0) {
      px = amount * (rin * spread * ratio - spread * ratio + 1.0) * cx;
      py = amount * (rin * spread - spread + 1.0) * cy;
      zeroXIfNoY = true;
    } else if (mode == 2.0) {  // towards the point outside, away from it inside
      const double sign = outer ? 1.0 : -1.0;
      px = amount * (cx + sign * spread * ratio * (outer ? xin - cx : cx - xin));
      py = amount * (cy + sign * spread * (outer ? yin - cy : cy - yin));
    } else if (mode == 3.0) {
      const double sign = outer ? 1.0 : -1.0;
      px = amount * (cx + sign * spread * ratio * xin);
      py = amount * (cy + sign * spread * yin);
    } else if (mode == 4.0) {
      px = amount * (0.5 * rin + spread * ratio) * cx;
      py = amount * (0.5 * rin + spread) * cy;
    } else if (mode == 5.0 || mode == 6.0) {
      // Mode 5 keeps the point outside and drops it inside; mode 6 the reverse.
      const bool keep = outer == (mode == 5.0);
      px = keep ? x[i] : kNaN;
      py = keep ? y[i] : kNaN;
    }
    outX[i] += px;
    outY[i] += py;
    // JWildfire's mode 1 clears x where the sum so far has y exactly 0.
    if (zeroXIfNoY && outY[i] == 0.0) outX[i] = 0.0;
    outZ[i] += w * z[i];
  }
}

// ---- inversion ---------------------------------------------------------------------------------------------------

// inversion (CozyG's, as JWildfire has it): inversion in a shape rather than a circle. The point p at angle φ from the
// origin is mapped to p·|s|²/|p|², s where the ray through p meets the shape (a circle of radius scale, an ellipse,
// a hyperbola, a regular polygon, a rose, a superellipse or a supershape, shape 0–6, turned by rotation·π; a–f its
// parameters), each |·|² measured in the p-norms pnorm_shape/pnorm_point (with their pnorm_smod/pnorm_pmod). imode 1
// inverts only the points outside the shape, 2 only those inside; ring_mode 1 (2) only those inside (outside) the
// ring between ring_scale·scale and its inverse. The others pass unweighted, or are dropped with hide_uninverted
// (NaN, the chaos game's escape, where JWildfire hides them). With draw_shape a share of the points draws the shape's
// outline instead (thickened by shape_thickness), and with passthrough a share passes unchanged; both unweighted, z
// not carried, as JWildfire does. Five numbers Ψ₁…Ψ₅ are drawn for every point (outline test, its angle, its two
// thickness offsets, pass-through test). Its direct colour (color_measure) and editor guides are not applied.
struct InversionShape {
  double shape, scale, rotation, a, b, c, d, e, f, period;
  bool simple;
};

// The shape's point at angle t from the origin: its radius r (negative for some shapes) and (r cos t, r sin t).
inline double inversionRadius(const InversionShape& s, double tin) {
  const double t = tin - s.rotation;
  if (s.shape == 1.0)
    return s.a * s.b / std::sqrt(s.b * std::cos(t) * s.b * std::cos(t) + s.a * std::sin(t) * s.a * std::sin(t)) *
           s.scale;
  if (s.shape == 2.0) {
    const double ct = std::cos(t), st = std::sin(t);
    return std::sqrt(s.a * s.a * s.b * s.b / (s.b * s.b * ct * ct - s.a * s.a * st * st)) * s.scale;
  }
  if (s.shape == 3.0) {
    const double theta = std::abs(std::fmod(tin - s.rotation, kTwoPi));
    const double sides = std::floor(s.a);
    return std::cos(kPi / sides) / std::cos(std::fmod(theta, kTwoPi / sides) - kPi / sides) * s.scale;
  }
  if (s.shape == 4.0) return (std::cos(s.a / s.b * t) + s.c) * s.scale;
  if (s.shape == 5.0)
    return s.a * s.b /
           std::pow(std::pow(std::abs(s.a * std::sin(t)), s.c) + std::pow(std::abs(s.b * std::cos(t)), s.c),
                    1.0 / s.c) *
           s.scale;
  if (s.shape == 6.0)
    return std::pow(std::pow(std::abs(std::cos(s.c * t / 4.0) / s.a), s.e) +
                        std::pow(std::abs(std::sin(s.c * t / 4.0) / s.b), s.f),
                    -1.0 / s.d) *
           s.scale;
  return s.scale;  // the circle, and any other shape number
}

// Where the ray at angle tin meets the shape: for a rose (not a simple shape), the farthest of its crossings at tin,
// tin + π, … over its period, as JWildfire takes them (radius −0.0001 at the origin when the period is under 2π; at
// most 1000 of them).
inline void inversionCurvePoint(const InversionShape& s, double tin, double& r, double& cx, double& cy) {
  if (s.simple) {
    r = inversionRadius(s, tin);
    cx = r * std::cos(tin);
    cy = r * std::sin(tin);
    return;
  }
  r = -0.0001;
  cx = cy = 0.0;
  // JWildfire's (int)(period/2π) crossings, at most 1000 here (a rose of kdenom above 1000 would take longer).
  const double turns = std::min(static_cast<double>(javaInt(s.period / kTwoPi)), 1000.0);
  for (double i = 0.0; i < turns; i += 1.0) {
    const double theta = tin + i * kPi, ri = inversionRadius(s, theta);
    if (std::abs(ri) > r) {
      cx = ri * std::cos(theta);
      cy = ri * std::sin(theta);
      r = std::abs(ri);
    }
  }
}

// The rose's period (JWildfire's Rhodonea.calcPeriod): 2π, π for odd k without c, kd·2π or kd·π for k = kn/kd.
inline double rosePeriod(double a, double b, double c) {
  const double k = a / b;
  if (std::fmod(k, 1.0) == 0.0) return std::fmod(k, 2.0) == 0.0 || c != 0.0 ? kTwoPi : kPi;
  if (std::fmod(a, 1.0) == 0.0 && std::fmod(b, 1.0) == 0.0) {
    double kn = a, kd = b;
    const double gcd = bigGcd(javaLong(kn), javaInt(kd));
    if (gcd != 1.0) {
      kn /= gcd;
      kd /= gcd;
    }
    return std::fmod(kn, 2.0) == 0.0 || std::fmod(kd, 2.0) == 0.0 ? kd * kTwoPi : kd * kPi;
  }
  return kTwoPi;
}

inline double pNormSquared(double px, double py, double p, double mod) {
  return std::pow(std::pow(std::abs(px), p) + std::pow(std::abs(py), p), 2.0 / (p * mod));
}

VOXFLAME_VARIATION_TARGETS void inversion(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  InversionShape s{};
  s.scale = P[0];
  s.rotation = kPi * P[1];
  s.shape = static_cast<double>(javaInt(P[2]));
  if (!(s.shape >= 0.0 && s.shape <= 6.0)) s.shape = 0.0;
  s.a = P[5];
  s.b = P[6];
  s.c = P[7];
  s.d = P[8];
  s.e = P[9];
  s.f = P[10];
  s.simple = s.shape != 4.0;
  s.period = s.shape == 4.0 ? rosePeriod(s.a, s.b, s.c) : kTwoPi;
  const double imode = static_cast<double>(javaInt(P[3]));
  const bool hideUninverted = P[4] == 1.0;
  const double ringMode = static_cast<double>(javaInt(P[11])), ringScale = P[12];
  const double pnormPoint = P[13], pnormShape = P[14], pnormPmod = P[15], pnormSmod = P[16];
  const double drawShape = P[17], thickness = P[18], passthrough = P[19];
  const double ringMin = ringScale <= s.scale ? ringScale * s.scale : s.scale * s.scale / (ringScale * s.scale);
  const double ringMax = ringScale <= s.scale ? s.scale * s.scale / (ringScale * s.scale) : ringScale * s.scale;
  const bool ring = ringMode != 0.0 && ringScale != 1.0;
  const bool plainShape = pnormShape == 2.0 && pnormSmod == 1.0, plainPoint = pnormPoint == 2.0 && pnormPmod == 1.0;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    const double psi1 = laneUniform(rnd[i]), psi2 = laneUniform(rnd[i]), psi3 = laneUniform(rnd[i]),
                 psi4 = laneUniform(rnd[i]), psi5 = laneUniform(rnd[i]);
    const double xin = x[i], yin = y[i];
    double r, cx, cy;
    if (drawShape > 0.0 && psi1 < drawShape) {
      // The outline's own point at the angle (not the farthest crossing), as JWildfire draws it.
      const double theta = psi2 * s.period;
      r = inversionRadius(s, theta);
      cx = r * std::cos(theta);
      cy = r * std::sin(theta);
      if (thickness != 0.0) {
        cx += 0.01 * (psi3 - 0.5) * thickness;
        cy += 0.01 * (psi4 - 0.5) * thickness;
      }
      outX[i] += cx;
      outY[i] += cy;
      continue;
    }
    if (passthrough > 0.0 && psi5 < passthrough) {
      outX[i] += xin;
      outY[i] += yin;
      continue;
    }
    const double rin = std::sqrt(xin * xin + yin * yin);
    inversionCurvePoint(s, std::atan2(yin, xin), r, cx, cy);
    bool invert = imode == 1.0 ? rin > r : imode == 2.0 ? rin < r : true;
    if (invert && ring) {
      if (ringMode == 1.0) invert = rin >= ringMin && rin <= ringMax;
      if (ringMode == 2.0) invert = rin <= ringMin || rin >= ringMax;
    }
    if (invert) {
      const double num = plainShape ? r * r : pNormSquared(cx, cy, pnormShape, pnormSmod);
      const double den = plainPoint ? xin * xin + yin * yin : pNormSquared(xin, yin, pnormPoint, pnormPmod);
      const double factor = w * (num / den);
      outX[i] += factor * xin;
      outY[i] += factor * yin;
      outZ[i] += w * z[i];
    } else {
      outX[i] += hideUninverted ? kNaN : xin;
      outY[i] += hideUninverted ? kNaN : yin;
      outZ[i] += z[i];
    }
  }
}

// ---- maurer_rose -------------------------------------------------------------------------------------------------

// maurer_rose (CozyG's, as JWildfire has it): the Maurer rose of the rose r = cos(k θ) + c, k = kn/kd: chords between
// the rose's points line_offset_degrees apart (line_count of them). The point's angle φ picks t = cycles·φ, cycles =
// line_count·line_offset_degrees/360, and its chord (the step ⌊t/step⌋); then by Ψ₁ the point goes to a random place
// on that chord (show_lines), to one of its two ends (show_points) or onto the rose at t (show_curve), the shares in
// proportion to those three, each thickened (line_thickness, point_thickness, curve_thickness, in hundredths). Ψ₁…Ψ₄
// are drawn for every point: the choice, then the place along the chord (or the end's offset radius, or the curve's x
// offset), then the offsets.
VOXFLAME_VARIATION_TARGETS void maurerRose(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = P[0] / P[1], c = P[2];
  const double step = kTwoPi * (P[3] / 360.0);
  const double cycles = P[4] * step / kTwoPi;
  const double showSum = P[5] + P[6] + P[7];
  const double lineShare = P[5] / showSum, pointShare = P[6] / showSum;
  const double lineThreshold = lineShare, pointThreshold = lineShare + pointShare,
               pointHalfThreshold = lineShare + pointShare / 2.0;
  const double lineThickness = P[8] / 100.0, pointThickness = P[9] / 100.0, curveThickness = P[10] / 100.0;
  const auto rose = [&](double theta, double& px, double& py) {
    const double r = std::cos(k * theta) + c;
    px = r * std::cos(theta);
    py = r * std::sin(theta);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double psi1 = laneUniform(rnd[i]), psi2 = laneUniform(rnd[i]), psi3 = laneUniform(rnd[i]),
                 psi4 = laneUniform(rnd[i]);
    const double t = cycles * std::atan2(y[i], x[i]);
    const double theta1 = std::floor(t / step) * step, theta2 = theta1 + step;
    double x1, y1, x2, y2;
    rose(theta1, x1, y1);
    rose(theta2, x2, y2);
    double px, py;
    if (psi1 < lineThreshold) {
      // Along the chord by its slope, as JWildfire goes (NaN on an exactly vertical chord, as there).
      const double dx = x2 - x1, dy = y2 - y1, slope = dy / dx;
      const double along = psi2 * std::sqrt(dx * dx + dy * dy);
      double xOffset = along / std::sqrt(1.0 + slope * slope);
      if (x2 < x1) xOffset = -xOffset;
      double yOffset = std::abs(slope * xOffset);
      if (y2 < y1) yOffset = -yOffset;
      if (lineThickness != 0.0) {
        xOffset += (psi3 - 0.5) * lineThickness;
        yOffset += (psi4 - 0.5) * lineThickness;
      }
      px = x1 + xOffset;
      py = y1 + yOffset;
    } else if (psi1 <= pointThreshold) {
      double xOffset = 0.0, yOffset = 0.0;
      if (pointThickness != 0.0) {
        const double radius = psi2 * pointThickness, angle = psi3 * kTwoPi;
        xOffset = radius * std::cos(angle);
        yOffset = radius * std::sin(angle);
      }
      const bool first = psi1 <= pointHalfThreshold;
      px = (first ? x1 : x2) + xOffset;
      py = (first ? y1 : y2) + yOffset;
    } else {
      rose(t, px, py);
      if (curveThickness != 0.0) {
        px += (psi2 - 0.5) * curveThickness;
        py += (psi3 - 0.5) * curveThickness;
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addJwildfireMoreVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("rose_wf", "r (sin θ, cos θ), z; r = amp cos(waves θ), times Ψ₂ when Ψ₁ < filled (JWildfire's)", k2D, kRandom,
      &roseWf, {{"amp", 0.5, 0.0, 2.0}, count("waves", 4.0, 1.0, 12.0), {"filled", 0.85, 0.0, 1.0}});
  add("heart_wf",
      "r·(±(1200 + 40t − t²) sin(πt/180)·scale_x, −(400 + 40t − t²) cos(πt/180))/1000, z; r = √(x² + y²), t = "
      "min(60 |θ|/π · scale_r_left (θ < 0, −) or scale_r_right (+) − shift_t, 60) (JWildfire's)",
      k2D, kFixed, &heartWf,
      {{"scale_x", 1.0, -2.0, 2.0},
       {"shift_t", 0.0, -60.0, 60.0},
       {"scale_r_left", 1.0, 0.0, 2.0},
       {"scale_r_right", 1.0, 0.0, 2.0}});
  add("maple_leaf",
      "s (x(t), y(t)), z: Hamid Naderi Yeganeh's maple leaf at t = θ − π/2, s = Ψ₂ when Ψ₁ < filled, else 1 "
      "(JWildfire's, whose integer 1/4 drops one term of x(t))",
      k2D, kRandom, &mapleLeaf, {{"filled", 0.5, 0.0, 1.0}});
  add("waves3_wf",
      "(d_x (x + d_x scalex f²(y·freqx)), d_y (y + d_y scaley g²(x·freqy)), z); f = cos with use_cos_x = 1, else sin "
      "(g likewise with use_cos_y), d = e^damp (1 where |damp| < 10⁻⁸) (JWildfire's)",
      k2D, kFixed, &waves3Wf,
      {{"scalex", 0.25, -1.0, 1.0},
       {"scaley", 0.5, -1.0, 1.0},
       {"freqx", kPi / 2.0, 0.0, 10.0},
       {"freqy", kPi / 4.0, 0.0, 10.0},
       count("use_cos_x", 1.0, 0.0, 1.0),
       count("use_cos_y", 0.0, 0.0, 1.0),
       {"dampx", 0.0, -1.0, 1.0},
       {"dampy", 0.0, -1.0, 1.0}});
  add("tangent3D", "(sin x / cos y, tan y, tan x) (Apophysis 3D's, as JWildfire has it)", k3D, kFixed, &tangent3D);
  add("acosh",
      "±(2/π) acosh(x + iy), z; − for Ψ ≥ ½; acosh q = log(q + √(q² − 1)) (Whittaker Courtney's, as JWildfire has "
      "it)",
      k2D, kRandom, &acoshJwf);
  add("acosech", "±(2/π)(Im, Re) of acosh(1/(x + iy)), z; − for Ψ ≥ ½ (Whittaker Courtney's, as JWildfire has it)", k2D,
      kRandom, &acosechJwf);
  add("zscale_wf",
      "(0, 0, z + ztranslate/w): z scaled by the weight, then moved by ztranslate (JWildfire's post_zscale_wf)", k3D,
      kFixed, &zscaleWf, {{"ztranslate", 0.0, -2.0, 2.0}});
  add("mirror_wf",
      "p, its x mirrored to xscale (−x − xshift) (y to yscale·y) for Ψ₁ < ½ with xaxis, then y to yscale (−y − "
      "yshift) (x to xscale·x) for Ψ₂ < ½ with yaxis, then z to −z − zshift for Ψ₃ < ½ with zaxis: the point "
      "itself, not weighted; each mirroring adds its axis' colour shift to the colour index (mod 1) (JWildfire's "
      "post_mirror_wf)",
      k3D, kRandom, &mirrorWf,
      {count("xaxis", 1.0, 0.0, 1.0),
       count("yaxis", 0.0, 0.0, 1.0),
       count("zaxis", 0.0, 0.0, 1.0),
       {"xshift", 0.0, -2.0, 2.0},
       {"yshift", 0.0, -2.0, 2.0},
       {"zshift", 0.0, -2.0, 2.0},
       {"xscale", 1.0, -2.0, 2.0},
       {"yscale", 1.0, -2.0, 2.0},
       {"xcolorshift", 0.0, -1.0, 1.0},
       {"ycolorshift", 0.0, -1.0, 1.0},
       {"zcolorshift", 0.0, -1.0, 1.0}});
  catalogue.back().directColour = true;
  const auto bs = [](double x1, double x2, double y1, double y2) {
    return std::vector<VariationParam>{
        {"x1", x1, -5.0, 5.0}, {"x2", x2, -5.0, 5.0}, {"y1", y1, -5.0, 5.0}, {"y2", y2, -5.0, 5.0}};
  };
  add("cos2_bs", "(cos(x2 x) cosh(y2 y), −sin(x1 x) sinh(y1 y), z) (Brad Stefanov's, as JWildfire has it)", k2D, kFixed,
      &cos2Bs, bs(1.0, 1.0, 1.0, 1.0));
  add("coth2_bs",
      "(sinh(x1 x), sin(y1 y), z·d)/d, d = cosh(x2 x) − cos(y2 y); nothing where d = 0 (Brad Stefanov's, as "
      "JWildfire has it)",
      k2D, kFixed, &coth2Bs, bs(2.0, 2.0, 2.0, 2.0));
  add("sec2_bs",
      "2 (cos(x2 x) cosh(y2 y), sin(x1 x) sinh(y1 y), z·d/2)/d, d = cos 2x + cosh 2y; nothing where d = 0 (Brad "
      "Stefanov's, as JWildfire has it)",
      k2D, kFixed, &sec2Bs, bs(1.25, 0.75, 1.5, 0.5));
  add("tan2_bs",
      "(sin(x1 x), sinh(y1 y), z·d)/d, d = cos(x2 x) + cosh(y2 y); nothing where d = 0 (Brad Stefanov's, as "
      "JWildfire has it)",
      k2D, kFixed, &tan2Bs, bs(2.0, 2.0, 2.0, 2.0));
  add("triangle",
      "a uniform random point (1 − √Ψ₁) v₁ + √Ψ₁ (1 − Ψ₂) v₂ + √Ψ₁ Ψ₂ v₃ of the triangle v₁ = (x1, y1, z1), v₂, "
      "v₃; "
      "the point itself is not used, and it replaces the terms before it (Jesus Sosa's, as JWildfire has it)",
      k3D, kRandom, &triangle,
      {{"x1", -0.2, -2.0, 2.0},
       {"y1", -0.1, -2.0, 2.0},
       {"z1", 0.0, -2.0, 2.0},
       {"x2", 0.2, -2.0, 2.0},
       {"y2", -0.1, -2.0, 2.0},
       {"z2", 0.0, -2.0, 2.0},
       {"x3", 0.2, -2.0, 2.0},
       {"y3", 0.1, -2.0, 2.0},
       {"z3", 0.0, -2.0, 2.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("chunk",
      "p where w (a x² + b xy + c y² + d x + e y + f) ≤ 0 (mode 0) or > 0 (mode 1), else nothing; x and y are added "
      "unweighted, z weighted (zephyrtronium's, as JWildfire has it)",
      k2D, kFixed, &chunk,
      {{"a", 1.0, -2.0, 2.0},
       {"b", 0.0, -2.0, 2.0},
       {"c", 1.0, -2.0, 2.0},
       {"d", 0.0, -2.0, 2.0},
       {"e", 0.0, -2.0, 2.0},
       {"f", -1.0, -2.0, 2.0},
       count("mode", 0.0, 0.0, 1.0)});
  add("spirograph3D",
      "((a + b) cos t − c cos(q t), (a + b) sin t − c sin(q t), c sin(q t)) + offsets of width (by mode), q = (a + "
      "b)/b, t = tmin + (tmax − tmin)Ψ; the point itself is not used; direct_color sets the colour index to (t/2π) "
      "mod 1 (as JWildfire has it)",
      k3D, kRandom, &spirograph3D,
      {{"a", 1.0, -2.0, 2.0},
       {"b", -0.3, -2.0, 2.0},
       {"c", 0.4, -2.0, 2.0},
       {"tmin", 0.0, -1000.0, 1000.0},
       {"tmax", 1000.0, -1000.0, 1000.0},
       {"width", 0.0, 0.0, 1.0},
       count("mode", 0.0, 0.0, 4.0),
       count("direct_color", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  add("rhodonea",
      "the rose (cos(k t) + radial_offset (+ fill (Ψ − ½)))·(cos t, sin t), k = knumer/kdenom, t = cycles (φ + 2π "
      "cycle_offset), spread by the point's distance per inner_mode/outer_mode (0–6), times w + metacycle_expansion "
      "per closed round; z (CozyG's, as JWildfire has it; modes 5 and 6 drop the points JWildfire hides)",
      k2D, kRandom, &rhodonea,
      {{"knumer", 3.0, 1.0, 20.0},
       {"kdenom", 4.0, 1.0, 20.0},
       count("inner_mode", 1.0, 0.0, 6.0),
       count("outer_mode", 1.0, 0.0, 6.0),
       {"inner_spread", 0.0, -1.0, 1.0},
       {"outer_spread", 0.0, -1.0, 1.0},
       {"inner_spread_ratio", 1.0, 0.0, 2.0},
       {"outer_spread_ratio", 1.0, 0.0, 2.0},
       {"spread_split", 1.0, 0.0, 2.0},
       {"fill", 0.0, 0.0, 1.0},
       {"radial_offset", 0.0, -1.0, 1.0},
       {"cycles", 0.0, 0.0, 100.0},
       {"cycle_offset", 0.0, -1.0, 1.0},
       {"metacycles", 1.0, 1.0, 10.0},
       {"metacycle_expansion", 0.0, -1.0, 1.0}});
  add("inversion",
      "w·p·|s|²/|p|², s where the ray from the origin through p meets the shape (0 circle of radius scale, 1 ellipse, "
      "2 "
      "hyperbola, 3 regular a-gon, 4 rose, 5 superellipse, 6 supershape, turned by rotation·π), the |·|² in p-norms; "
      "imode and ring_mode limit which points invert, the rest pass unweighted (or are dropped with hide_uninverted); "
      "draw_shape and passthrough send shares of the points to the outline or through unchanged; z (CozyG's, as "
      "JWildfire has it; its direct colour is not applied)",
      k2D, kRandom, &inversion,
      {{"scale", 1.0, 0.0, 2.0},
       {"rotation", 0.0, -1.0, 1.0},
       count("shape", 0.0, 0.0, 6.0),
       count("imode", 0.0, 0.0, 2.0),
       count("hide_uninverted", 0.0, 0.0, 1.0),
       {"a", 1.0, 0.0, 5.0},
       {"b", 1.0, 0.0, 5.0},
       {"c", 0.0, -5.0, 5.0},
       {"d", 0.0, -5.0, 5.0},
       {"e", 0.0, -5.0, 5.0},
       {"f", 0.0, -5.0, 5.0},
       count("ring_mode", 0.0, 0.0, 2.0),
       {"ring_scale", 1.0, 0.0, 2.0},
       {"pnorm_point", 2.0, 0.1, 4.0},
       {"pnorm_shape", 2.0, 0.1, 4.0},
       {"pnorm_pmod", 1.0, 0.1, 4.0},
       {"pnorm_smod", 1.0, 0.1, 4.0},
       {"draw_shape", 0.0, 0.0, 1.0},
       {"shape_thickness", 0.0, 0.0, 10.0},
       {"passthrough", 0.0, 0.0, 1.0},
       count("guides_enabled", 1.0, 0.0, 1.0),
       count("color_measure", 0.0, 0.0, 4.0),
       count("color_gradient", 1.0, 1.0, 2.0),
       {"color_low_threshold", 0.0, 0.0, 1.0},
       {"color_high_threshold", 1.0, 0.0, 2.0}});
  add("maurer_rose",
      "a random point of the Maurer rose of r = cos(k θ) + c (k = kn/kd): on the chord between the rose's points at "
      "θ₁ = ⌊t/s⌋ s and θ₁ + s (show_lines), at one of its ends (show_points) or on the rose at t (show_curve), s = "
      "line_offset_degrees, t = φ·line_count·s/2π, each thickened; z (CozyG's, as JWildfire has it)",
      k2D, kRandom, &maurerRose,
      {{"kn", 2.0, 1.0, 20.0},
       {"kd", 1.0, 1.0, 20.0},
       {"c", 0.0, -1.0, 1.0},
       {"line_offset_degrees", 71.0, 0.0, 360.0},
       {"line_count", 360.0, 1.0, 1000.0},
       {"show_lines", 1.0, 0.0, 1.0},
       {"show_points", 0.0, 0.0, 1.0},
       {"show_curve", 0.05, 0.0, 1.0},
       {"line_thickness", 0.5, 0.0, 5.0},
       {"point_thickness", 3.0, 0.0, 10.0},
       {"curve_thickness", 1.0, 0.0, 5.0}});
}

}  // namespace voxflame::core
