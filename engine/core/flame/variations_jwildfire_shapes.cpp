// JWildfire's own variations that neither flam3 nor Fractorium has: bubble wraps, yin-yang, an
// affine map in 3D, planes, curves drawn as shapes (cannabis, clover, maple leaf, crown), a
// recurrence plot, and a few 3D maps. Each variation is a kernel below and one row of the table at
// the end (see variations.h for the notation and variation_kernels.h for what the files share).
// JWildfire's conventions: MathLib.SMALL_EPSILON = 1e-300 and EPSILON = 1e-8 (kJwfEpsilon), Tools.FTOI
// rounds half away from 0, and pContext.random() is uniform in [0, 1) as laneUniform is.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

constexpr double kJwfSmallEpsilon = 1e-300;  // JWildfire's MathLib.SMALL_EPSILON

// Tools.FTOI: rounds half away from 0 (std::round does the same); kept a double (see countParam).
inline double jwfFtoi(double value) {
  return std::round(value);
}

// bwraps7 (slobo777's Bubble Wrap plugin, as JWildfire has it): the plane cut into square cells of
// cellsize; inside each cell's bubble (radius ½ cellsize/(1 + space²)) the point is magnified by
// gain like bubble and twisted about the cell's centre, from inner_twist at the centre to
// outer_twist at the rim; outside the bubbles (and for cellsize 0) it is linear.
VOXFLAME_VARIATION_TARGETS void bwraps7(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = P[0], space = P[1], gain = P[2], innerTwist = P[3], outerTwist = P[4];
  const double radius = 0.5 * (cellsize / (1.0 + space * space));
  const double g2 = gain * gain + 1e-6;
  double maxBubble = g2 * radius;
  // Beyond 2 the bubble would curve round its own back: JWildfire then takes 1.
  maxBubble = maxBubble > 2.0 ? 1.0 : maxBubble / (maxBubble * maxBubble / 4.0 + 1.0);
  const double r2 = radius * radius, rFactor = radius / maxBubble;
  const bool linear = std::abs(cellsize) < kJwfSmallEpsilon;
  for (std::size_t i = 0; i < n; ++i) {
    double vx = x[i], vy = y[i];
    if (!linear) {
      const double cx = (std::floor(vx / cellsize) + 0.5) * cellsize;
      const double cy = (std::floor(vy / cellsize) + 0.5) * cellsize;
      double lx = vx - cx, ly = vy - cy;
      if (!(lx * lx + ly * ly > r2)) {
        lx *= g2;
        ly *= g2;
        const double scale = rFactor / ((lx * lx + ly * ly) / 4.0 + 1.0);
        lx *= scale;
        ly *= scale;
        const double t = (lx * lx + ly * ly) / r2;  // 0 at the centre, 1 at the rim
        const double theta = innerTwist * (1.0 - t) + outerTwist * t;
        const double s = std::sin(theta), c = std::cos(theta);
        vx = cx + c * lx + s * ly;
        vy = cy - s * lx + c * ly;
      }
    }
    outX[i] += w * vx;
    outY[i] += w * vy;
    outZ[i] += w * z[i];
  }
}

// yin_yang (dark-beam's, as JWildfire has it): the unit disc, turned by ang1·π, folded into the
// yin half of a yin-yang of inner radius `radius`; with dual_t, half the points (Ψ ≥ ½) are turned
// by ang2·π instead and folded into the mirrored yang half (radius 1 − radius). Outside the disc
// linear with `outside`, else nothing. Ψ is drawn for every point (JWildfire draws it only inside
// the disc with dual_t; the picture is the same).
VOXFLAME_VARIATION_TARGETS void yinYang(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = std::clamp(P[0], 0.0, 1.0);
  const double sinA = std::sin(kPi * P[1]), cosA = std::cos(kPi * P[1]);
  const double sinB = std::sin(kPi * P[2]), cosB = std::cos(kPi * P[2]);
  const bool dual = std::clamp(jwfFtoi(P[3]), 0.0, 1.0) == 1.0;
  const bool outside = std::clamp(jwfFtoi(P[4]), 0.0, 1.0) == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double psi = laneUniform(rnd[i]);
    const double px = x[i], py = y[i];
    double rx = 0.0, ry = 0.0;
    if (px * px + py * py < 1.0) {
      const bool yang = dual && psi > 0.5;
      const double inv = yang ? -1.0 : 1.0, rr = yang ? 1.0 - radius : radius;
      const double s = yang ? sinB : sinA, c = yang ? cosB : cosA;
      const double xx = px * c - py * s, yy = px * s + py * c;
      if (yy > 0.0) {
        const double t = std::sqrt(1.0 - yy * yy);
        const double alfa = (1.0 - xx / t) * 0.5;
        const double t1 = (t - 0.5) * 2.0;
        const double k1 = alfa * rr + (1.0 - alfa);
        rx = (t1 * k1 + alfa * (rr - 1.0)) * inv;
        ry = std::sqrt(1.0 - t1 * t1) * k1 * inv;
      } else {
        rx = (xx * (1.0 - rr) + rr) * inv;
        ry = yy * (1.0 - rr) * inv;
      }
    } else if (outside) {
      rx = px;
      ry = py;
    }
    outX[i] += w * rx;
    outY[i] += w * ry;
    outZ[i] += w * z[i];
  }
}

// affine3D (Flamelet's, as JWildfire has it): p scaled, sheared, then turned about x, y and z
// (degrees) and translated. JWildfire skips the shears when all are below 1e-8; the full formula
// gives the same there.
VOXFLAME_VARIATION_TARGETS void affine3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double tx = P[0], ty = P[1], tz = P[2], sx = P[3], sy = P[4], sz = P[5];
  const double degree = kPi / 180.0;
  const double sinX = std::sin(P[6] * degree), cosX = std::cos(P[6] * degree);
  const double sinY = std::sin(P[7] * degree), cosY = std::cos(P[7] * degree);
  const double sinZ = std::sin(P[8] * degree), cosZ = std::cos(P[8] * degree);
  const double shXY = P[9], shXZ = P[10], shYX = P[11], shYZ = P[12], shZX = P[13], shZY = P[14];
  for (std::size_t i = 0; i < n; ++i) {
    const double px = sx * x[i], py = sy * y[i], pz = sz * z[i];
    const double ax = px + shXY * py + shXZ * pz;
    const double ay = shYX * px + py + shYZ * pz;
    const double az = shZX * px + shZY * py + pz;
    const double u = cosY * ax + sinY * (sinX * ay + cosX * az);
    const double v = cosX * ay - sinX * az;
    outX[i] += w * (cosZ * u - sinZ * v + tx);
    outY[i] += w * (sinZ * u + cosZ * v + ty);
    outZ[i] += w * (-sinY * ax + cosY * (sinX * ay + cosX * az) + tz);
  }
}

// plane_wf (JWildfire's): a random point of a size × size square in the plane xy, yz or zx (axis
// 0, 1, 2) at `position` along the remaining axis; the point itself is not used. Its direct colour
// and its colour and displacement maps (images) are not applied; the importer says so when a file
// sets direct_color.
VOXFLAME_VARIATION_TARGETS void planeWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double position = P[0], size = P[1];
  const double axis = std::clamp(jwfFtoi(P[2]), 0.0, 2.0);
  const bool direct = std::clamp(jwfFtoi(P[3]), 0.0, 1.0) == 1.0;
  const double colourMode = std::clamp(jwfFtoi(P[4]), 0.0, 3.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 0.5 - laneUniform(rnd[i]), b = 0.5 - laneUniform(rnd[i]);
    if (direct) {
      // JWildfire colours by the square's own coordinates (u, v), which on the plane zx are (z, x).
      const double cu = (axis == 2.0 ? b : a) + 0.5, cv = (axis == 2.0 ? a : b) + 0.5;
      if (colourMode == 1.0) colour[i] = cu;
      if (colourMode == 2.0) colour[i] = cv;
      if (colourMode == 3.0) colour[i] = cu * cv;
      colour[i] = std::clamp(colour[i], 0.0, 1.0);
    }
    const double u = a * size, v = b * size;
    double px = u, py = v, pz = position;  // axis 0: the plane xy
    if (axis == 1.0) {
      px = position;
      py = u;
      pz = v;
    } else if (axis == 2.0) {
      py = position;
      pz = v;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * pz;
  }
}

// point_symmetry_wf (JWildfire's post_point_symmetry_wf): the point's offset from the centre,
// scaled by the weight, turned by a random multiple k·2π/order (k = ⌊Ψ·order⌋) clockwise about
// it. The result is the point itself, not a weighted term; JWildfire has it only as a post_ term.
// The colour index moves by k · colorshift (mod 1, negative below 0 as JWildfire's fmod).
VOXFLAME_VARIATION_TARGETS void pointSymmetryWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                                double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1];
  const double order = std::clamp(jwfFtoi(P[2]), 1.0, 2147483647.0);
  const double step = kTwoPi / order, colourShift = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::min(std::floor(laneUniform(rnd[i]) * order), order - 1.0);
    if (colourShift != 0.0) colour[i] = std::fmod(colour[i] + k * colourShift, 1.0);
    const double s = std::sin(k * step), c = std::cos(k * step);
    const double dx = (x[i] - cx) * w, dy = (y[i] - cy) * w;
    outX[i] += cx + dx * c + dy * s;
    outY[i] += cy + dy * c - dx * s;
    outZ[i] += w * z[i];
  }
}

// The "filled" curves of JWildfire (cannabiscurve_wf, cloverleaf_wf, japanese_maple_leaf): the
// point's angle θ = atan2(x, y) picks a point of the curve r(θ), moved towards the origin by Ψ₂
// with probability `filled` (when Ψ₁ < filled). Both numbers are drawn for every point.
inline double filledFactor(double filled, std::uint32_t& state) {
  const double psi1 = laneUniform(state), psi2 = laneUniform(state);
  return filled > 0.0 && filled > psi1 ? psi2 : 1.0;
}

inline double pow10(double v) {
  const double v2 = v * v, v4 = v2 * v2, v8 = v4 * v4;
  return v8 * v2;
}

// cannabiscurve_wf: Wolfram's cannabis curve r = (1 + 9/10 cos 8θ)(1 + 1/10 cos 24θ)(9/10 + 1/10
// cos 200θ)(1 + sin θ), drawn at angle θ + π/2.
VOXFLAME_VARIATION_TARGETS void cannabisCurveWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                                double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double filled = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(x[i], y[i]);
    double r = (1.0 + 0.9 * std::cos(8.0 * a)) * (1.0 + 0.1 * std::cos(24.0 * a)) * (0.9 + 0.1 * std::cos(200.0 * a)) *
               (1.0 + std::sin(a));
    r *= filledFactor(filled, rnd[i]);
    const double turned = a + kPi / 2.0;
    outX[i] += w * std::sin(turned) * r;
    outY[i] += w * std::cos(turned) * r;
    outZ[i] += w * z[i];
  }
}

// cloverleaf_wf: r = sin 2θ + ¼ sin 6θ, drawn at angle θ.
VOXFLAME_VARIATION_TARGETS void cloverleafWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double filled = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(x[i], y[i]);
    const double r = (std::sin(2.0 * a) + 0.25 * std::sin(6.0 * a)) * filledFactor(filled, rnd[i]);
    outX[i] += w * std::sin(a) * r;
    outY[i] += w * std::cos(a) * r;
    outZ[i] += w * z[i];
  }
}

// japanese_maple_leaf: Hamid Naderi Yeganeh's maple leaf (x(t), y(t)) at t = θ/2 + π/2, scaled by
// 0.667.
VOXFLAME_VARIATION_TARGETS void japaneseMapleLeaf(const VariationInput& in, double* __restrict ox,
                                                  double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double filled = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::atan2(x[i], y[i]) * 0.5 + kPi / 2.0;
    const double r = w * 0.667 * filledFactor(filled, rnd[i]);
    const double c8 = std::cos(8.0 * t), c80 = std::cos(80.0 * t), ct = std::cos(t), c3 = std::cos(3.0 * t);
    const double st = std::sin(t), ct2 = ct * ct, ct4 = ct2 * ct2, ct8 = ct4 * ct4;  // cos⁹ t = ct8 · ct
    const double common = c8 * c8 + 0.2 * pow10(c8 * std::cos(24.0 * t));
    const double fringe = c80 * c80 / 6.0 + pow10(c80) / 15.0;
    const double notch = 1.0 - pow10(std::sin(8.0 * t));
    const double lobe = 1.0 - pow10(ct) * c3 * c3;
    const double lx = (4.0 / 15.0 + common + fringe) * notch * std::sin(2.0 * t) * (1.0 + st) *
                      (lobe + ct8 * ct * pow10(std::cos(5.0 * t)) / 30.0);
    const double ly = (8.0 / 30.0 + common + fringe * lobe * notch) * std::cos(2.0 * t) * (1.0 + st + pow10(ct * c3));
    outX[i] += r * lx;
    outY[i] += r * ly;
    outZ[i] += w * z[i];
  }
}

// spherical3D_wf: p / (|p|² + 1e-300)^(exponent/2), negated with invert ≠ 0.
VOXFLAME_VARIATION_TARGETS void spherical3DWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sign = jwfFtoi(P[0]) == 0.0 ? 1.0 : -1.0;
  const double exponent = P[1];
  const bool regular = std::abs(exponent - 2.0) < kJwfEpsilon;
  for (std::size_t i = 0; i < n; ++i) {
    const double rr = x[i] * x[i] + y[i] * y[i] + z[i] * z[i] + kJwfSmallEpsilon;
    const double r = sign * w / (regular ? rr : std::pow(rr, exponent / 2.0));
    outX[i] += x[i] * r;
    outY[i] += y[i] * r;
    outZ[i] += z[i] * r;
  }
}

// waves2_wf (Joel Faber's waves2 with cosines and damping, as JWildfire has it).
VOXFLAME_VARIATION_TARGETS void waves2Wf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], freqX = P[2], freqY = P[3];
  const bool cosX = jwfFtoi(P[4]) == 1.0, cosY = jwfFtoi(P[5]) == 1.0;
  const double dampX = std::abs(P[6]) < kJwfEpsilon ? 1.0 : std::exp(P[6]);
  const double dampY = std::abs(P[7]) < kJwfEpsilon ? 1.0 : std::exp(P[7]);
  for (std::size_t i = 0; i < n; ++i) {
    const double wx = cosX ? std::cos(y[i] * freqX) : std::sin(y[i] * freqX);
    const double wy = cosY ? std::cos(x[i] * freqY) : std::sin(x[i] * freqY);
    outX[i] += w * (x[i] + dampX * scaleX * wx) * dampX;
    outY[i] += w * (y[i] + dampY * scaleY * wy) * dampY;
    outZ[i] += w * z[i];
  }
}

// butterfly3D (as JWildfire has it): Apophysis' butterfly, lifted by |2y|·√(x² + y²)/4.
VOXFLAME_VARIATION_TARGETS void butterfly3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double wx = w * 1.3029400317411197908970256609023;  // 4/√(3π)
  for (std::size_t i = 0; i < n; ++i) {
    const double y2 = 2.0 * y[i];
    const double r = wx * std::sqrt(std::abs(x[i] * y[i]) / (kJwfSmallEpsilon + x[i] * x[i] + y2 * y2));
    outX[i] += r * x[i];
    outY[i] += r * y2;
    outZ[i] += r * std::abs(y2) * std::sqrt(x[i] * x[i] + y[i] * y[i]) / 4.0;
  }
}

// cylinder_apo (Apophysis 3D's cylinder): (sin x, y, cos x); z is not carried.
VOXFLAME_VARIATION_TARGETS void cylinderApo(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]);
    outY[i] += w * y[i];
    outZ[i] += w * std::cos(x[i]);
  }
}

// crown_js (Jesus Sosa's, after Roger Bagula's crown, Paul Bourke's page): the point at t = −π +
// 2πΨ of the curve Σ_{k=1}^{14} (sin θ_k, cos θ_k)/a^(b k), θ_k = ±a^k t (− for even k), with z =
// (x² + y²)²; the point itself is not used. JWildfire also sets the colour from x² + y²; that is
// not applied.
VOXFLAME_VARIATION_TARGETS void crownJs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = P[0], b = P[1];
  double inverse[14], speed[14];
  for (int k = 1; k < 15; ++k) {
    inverse[k - 1] = 1.0 / std::pow(a, b * k);
    speed[k - 1] = std::pow(a, static_cast<double>(k)) * (k % 2 == 0 ? -1.0 : 1.0);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double t = -kPi + kTwoPi * laneUniform(rnd[i]);
    double re = 0.0, im = 0.0;
    for (int k = 0; k < 14; ++k) {
      const double th = speed[k] * t;
      re += std::sin(th) * inverse[k];
      im += std::cos(th) * inverse[k];
    }
    const double mag2 = re * re + im * im;
    outX[i] += w * re;
    outY[i] += w * im;
    outZ[i] += w * mag2 * mag2;
  }
}

// flower_db (as JWildfire has it): a rose r·|(petal_spread + sin(petals φ)) cos(petal_split·petals
// φ)| at angle φ (drawn as (sin φ, cos φ)), r = w·√(x² + y²); z falls by stem_thickness·(2/r − 1)
// into a stem, rises by petal_fold_strength beyond petal_fold_radius and is held at −stem_length
// (when not 0). As JWildfire does, the fold and the stem read the sum so far (the terms before it
// on the transform) and the stem's clamp replaces its z.
VOXFLAME_VARIATION_TARGETS void flowerDb(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double petals = P[0], split = P[1], spread = P[2], thickness = P[3], stem = P[4], foldStrength = P[5],
               foldRadius = P[6];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::atan2(y[i], x[i]);
    const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]) *
                     std::abs((spread + std::sin(petals * t)) * std::cos(split * petals * t));
    outX[i] += std::sin(t) * r;
    outY[i] += std::cos(t) * r;
    double pz = outZ[i] - thickness * (2.0 / r - 1.0);
    const double rNew = std::sqrt(outX[i] * outX[i] + outY[i] * outY[i]);
    if (rNew > foldRadius) pz += (rNew - foldRadius) * foldStrength;
    if (stem != 0.0 && pz <= -stem) pz = -stem;
    outZ[i] = pz;
  }
}

// ---- recurrenceplot ----------------------------------------------------------------------------

// The signal y(i) of Jesus Sosa's recurrenceplot (as JWildfire has it) at sample i of N, for the
// function func_id (0…29: sums of sines, a sigmoid, Legendre and Chebyshev polynomials, Fourier
// series of square, sawtooth, rectified sine and parabola waves, sinc, Gabor); other ids give 0.
struct RecurrenceSetup {
  int id;
  double a, b, n;
  int k;
};

inline double legendre(int degree, double x) {
  double previous = 1.0, current = x;
  if (degree == 0) return 1.0;
  for (int d = 1; d < degree; ++d) {
    const double next = ((2.0 * d + 1.0) * x * current - d * previous) / (d + 1.0);
    previous = current;
    current = next;
  }
  return current;
}

inline double chebyshev(int degree, double x) {
  double previous = 1.0, current = x;
  if (degree == 0) return 1.0;
  for (int d = 1; d < degree; ++d) {
    const double next = 2.0 * x * current - previous;
    previous = current;
    current = next;
  }
  return current;
}

double recurrenceSignal(const RecurrenceSetup& s, double i) {
  const double a = s.a, b = s.b, n = s.n;
  const double u = i * kPi / n;  // i π / N
  const double h = i * kPi / (0.5 * n);
  switch (s.id) {
    case 0:
      return 50.0 * std::sin(4.0 * u) + 25.0 * std::sin(40.0 * u);
    case 1:
      return 10.0 * std::sin(5.0 * u) * 5.0 * std::sin(15.0 * u);
    case 2:
      return 50.0 * std::cos(24.0 * u + 5.0 * std::sin(6.0 * u));
    case 3:
      return 50.0 * std::sin(20.0 * u) + 50.0 * std::sin(22.0 * u + kPi);
    case 4:
      return 50.0 * std::sin(20.0 * u) + 10.0 * std::sin(22.0 * u);
    case 5:
      return 50.0 * std::sin(a * u + std::sin(a * u));
    case 6:
      return a / (1.0 + std::exp(-b * (i - n / 2.0) / n));
    case 7:
      return (400.0 / kPi) *
             (std::sin(h) + std::sin(3.0 * h) / 3.0 + std::sin(5.0 * h) / 5.0 + std::sin(7.0 * h) / 7.0);
    case 8:  // JWildfire's 400/π·π, which is 400
      return 400.0 / kPi * kPi *
             (std::sin(h) - std::sin(3.0 * h) / 9.0 + std::sin(5.0 * h) / 25.0 - std::sin(7.0 * h) / 49.0);
    case 9:
      return std::tanh(a * u);
    case 10:
      return std::tan(a * u);
    case 11: {
      double sum = 0.0;
      for (int m = 1; m <= 8; ++m) sum += std::sin(m * h) / m;
      return (-200.0 / kPi) * sum;
    }
    case 12:
      return 50.0 * std::sin(40.0 * u) + 50.0 * std::sin(44.0 * u);
    case 13:
      return 50.0 * std::sin(40.0 * u) + 50.0 * std::sin(44.0 * u + kPi);
    case 14:
      return 100.0 * std::sin(16.0 * u) - 500.0 + i * 0.25;
    case 15:
      return 100.0 * std::sin(16.0 * u);
    case 16:
      return 1.0 / std::cos(a * u);
    case 17:
      return 50.0 * std::cos(50.0 * u + 25.0 * std::sin(u));
    case 18: {
      const double d = 2.0 * a * i / n - a;
      return a * std::exp(-b * d * d);
    }
    case 19:
      return 500.0 * std::sin(10.0 * u) * std::exp(-5.0 * i / n);
    case 20:
      return 500.0 * std::sin(20.0 * u) * std::exp(-3.0 * i / n);
    case 21:
      return 50.0 * std::tan(2.0 * u);
    case 22: {  // Legendre polynomial of degree (int) b, 0…10
      const int degree = javaInt(b);
      return degree >= 0 && degree <= 10 ? a * legendre(degree, 2.0 * i / n - 1.0) : 0.0;
    }
    case 23: {  // square wave
      double sum = 0.0;
      for (int j = 1; j <= s.k; ++j) sum += std::sin(i * (2.0 * j - 1.0) * b * kTwoPi / n) / (2.0 * j - 1.0);
      return sum * (4.0 * a / kPi);
    }
    case 24: {  // sawtooth
      double sum = 0.0;
      for (int j = 1; j <= s.k; ++j) sum += std::sin(i * j * b * kTwoPi / n) / j;
      return sum * (-2.0 * a / kPi);
    }
    case 25: {  // rectified sine
      double sum = 0.0;
      for (int j = 1; j <= s.k; ++j)
        sum += std::cos(i * (2.0 * j) * b * kTwoPi / n) / ((2.0 * j - 1.0) * (2.0 * j + 1.0));
      return (4.0 * a / kPi) * (0.5 - sum);
    }
    case 26: {  // parabola
      double sum = 0.0;
      for (int j = 1; j <= s.k; ++j) sum += (j % 2 == 0 ? 1.0 : -1.0) * std::cos(i * (2.0 * j) * b * kPi / n) / (j * j);
      return a * kPi * kPi / 3.0 + 4.0 * a * sum;
    }
    case 27: {
      const double v = b * kPi * (i - 0.5 * n) / n;
      return a * std::sin(v) / v;
    }
    case 28: {
      const double v = (i - 0.5 * n) / n;
      return a * std::exp(-b * v * v) * std::cos(2.0 * s.k * kPi * i / n);
    }
    case 29:  // Chebyshev polynomial of degree k, 0…12
      return s.k >= 0 && s.k <= 12 ? a * chebyshev(s.k, 2.0 * i / n - 1.0) : 0.0;
    default:
      return 0.0;
  }
}

// recurrenceplot (Jesus Sosa's, as JWildfire has it): the recurrence plot of a signal y sampled at
// N (Density) points: a random pair of samples (i, j) is drawn at (i/N − ½, j/N − ½) when |y(i) −
// y(j)| < tolerance; the point itself is not used. JWildfire repeats the last point drawn when a
// pair misses (a variation here has no memory); here pairs are drawn again until one is near, up to
// 1000 times, and the point is dropped (NaN, the chaos game's escape) if none is. k is held within
// 0…1000 (the Fourier series' terms). Direct colour dc 1 sets the colour index to |½ x y / scale + offset|
// mod 1 and dc 2 to |½ ((c x + s y + offset) / scale + 1)| mod 1 (c, s the cosine and sine of angle), at
// the running sum (x, y) as JWildfire's pVarTP holds it (an ordinary term's output arrays; a pre_ or post_
// term's start from 0, so its input point is added), with a zero scale taken as 1e-5 as JWildfire's.
VOXFLAME_VARIATION_TARGETS void recurrencePlot(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  RecurrenceSetup s{};
  s.id = javaInt(P[0]);
  s.a = P[1];
  s.b = P[2];
  s.k = std::clamp(javaInt(P[3]), 0, 1000);
  s.n = static_cast<double>(javaInt(P[4]));
  const int directColour = javaInt(P[5]);
  const double colourScale = 1.0 / (P[6] == 0.0 ? 1e-5 : P[6]);
  const double cosAngle = std::cos(P[7]), sinAngle = std::sin(P[7]), colourOffset = P[8];
  const double runningSum = in.stage == VariationStage::Normal ? 0.0 : 1.0;
  const double tolerance = P[9];
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr int kTries = 1000;
  for (std::size_t i = 0; i < n; ++i) {
    double px = kNaN, py = kNaN;
    for (int tries = 0; tries < kTries; ++tries) {
      const double si = static_cast<double>(javaInt(s.n * laneUniform(rnd[i])));
      const double sj = static_cast<double>(javaInt(s.n * laneUniform(rnd[i])));
      const double d = std::abs(recurrenceSignal(s, si) - recurrenceSignal(s, sj));
      if (d < tolerance) {
        px = si / s.n - 0.5;
        py = sj / s.n - 0.5;
        break;
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
    if (directColour == 0 || std::isnan(px)) continue;
    const double sx = outX[i] + runningSum * x[i], sy = outY[i] + runningSum * y[i];
    const double index = directColour == 1 ? 0.5 * colourScale * sx * sy + colourOffset
                                           : 0.5 * (colourScale * (cosAngle * sx + sinAngle * sy + colourOffset) + 1.0);
    if (directColour == 1 || directColour == 2) colour[i] = laneFmod(std::abs(index), 1.0);
  }
}

// ---- minkowskope ---------------------------------------------------------------------------------------------------

// Minkowski's question-mark function ?(x) on [0, 1], by 20 steps down the Stern–Brocot tree (dark-beam's, as JWildfire
// has it: 2⁻²⁰ added at the end).
inline double minkowskiQuestionMark(double x) {
  double p = 0.0, q = 1.0, r = 1.0, s = 1.0, y = 0.0, d = 1.0;
  for (int step = 0; step < 20; ++step) {
    d *= 0.5;
    const double m = p + r, n = q + s;
    if (x < m / n) {
      r = m;
      s = n;
    } else {
      y += d;
      p = m;
      q = n;
    }
  }
  return y + d;
}

// A sine-like wave of period 4 made of ?(x) on a triangle wave (less x with altWave), its sign as JWildfire's.
inline double minkowskiSine(double x, bool altWave) {
  const double lp = std::fmod(std::abs(x), 4.0);
  double p = std::fmod(std::abs(x), 2.0);
  if (p > 1.0) p = 2.0 - p;
  const double mink = altWave ? minkowskiQuestionMark(p) - p : minkowskiQuestionMark(p);
  return (lp < 2.0) != (x > 0.0) ? mink : -mink;
}

// minkowskope (dark-beam's tweak of the oscilloscope plugin, as JWildfire has it): −p inside the band |y| ≤ t and p
// outside it, t = amplitude·e^(−damping |x|)·M(frequencyx·x/2 − 1 + perturbation·M(frequencyy·y/2)) + separation, M
// the Minkowski wave above (its alternative form when frequencyx ≤ 0; no damping where |damping| ≤ 10⁻⁸).
VOXFLAME_VARIATION_TARGETS void minkowskope(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double separation = P[0], frequencyX = P[1], frequencyY = P[2], amplitude = P[3], perturbation = P[4],
               damping = P[5];
  const double tpf = 0.5 * frequencyX, tpf2 = 0.5 * frequencyY;
  const bool noDamping = std::abs(damping) <= kJwfEpsilon, altWave = frequencyX <= 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double pt = perturbation * minkowskiSine(tpf2 * y[i], altWave);
    const double wave = minkowskiSine(tpf * x[i] + pt - 1.0, altWave);
    const double t = amplitude * (noDamping ? 1.0 : std::exp(-std::abs(x[i]) * damping)) * wave + separation;
    const double sign = std::abs(y[i]) <= t ? -w : w;
    outX[i] += sign * x[i];
    outY[i] += sign * y[i];
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addJwildfireShapeVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("bwraps7",
      "p outside the bubbles (radius ρ = ½ cellsize/(1 + space²)) of the cells of cellsize; inside: c + R(θ)·l·f, "
      "c the cell's centre, l = g²(p − c), g² = gain² + 10⁻⁶, f = ρ/(m(|l|²/4 + 1)), m = g²ρ/((g²ρ)²/4 + 1) (1 "
      "when g²ρ > 2), θ = inner_twist (1 − t) + outer_twist t, t = |l f|²/ρ², R turning clockwise; z (slobo777's, "
      "as JWildfire has it)",
      k2D, kFixed, &bwraps7,
      {{"cellsize", 1.0, -5.0, 5.0},
       {"space", 0.0, -2.0, 2.0},
       {"gain", 2.0, -5.0, 5.0},
       {"inner_twist", 0.0, -kPi, kPi},
       {"outer_twist", 0.0, -kPi, kPi}});
  add("yin_yang",
      "inside the unit disc: q = p turned by ang1·π folded into a yin-yang half of inner radius `radius` (with "
      "dual_t, for Ψ > ½: turned by ang2·π, radius 1 − radius, negated); q_y > 0: ((2t − 1)k + α(R − 1), "
      "√(1 − (2t − 1)²)·k), t = √(1 − q_y²), α = (1 − q_x/t)/2, k = αR + 1 − α; else (q_x(1 − R) + R, q_y(1 − R)); "
      "outside: p with outside, else 0; z (dark-beam's, as JWildfire has it)",
      k2D, kRandom, &yinYang,
      {{"radius", 0.5, 0.0, 1.0},
       {"ang1", 0.0, -2.0, 2.0},
       {"ang2", 0.0, -2.0, 2.0},
       count("dual_t", 1.0, 0.0, 1.0),
       count("outside", 0.0, 0.0, 1.0)});
  add("affine3D",
      "Rz Ry Rx (S p + shear) + translate: p scaled by (scaleX, scaleY, scaleZ), sheared (x += shearXY·y + shearXZ·z "
      "of the scaled point, y += shearYX·x + shearYZ·z, z += shearZX·x + shearZY·y), turned by rotateX, rotateY, "
      "rotateZ degrees about x, y, z, then moved by (translateX, translateY, translateZ) (Flamelet's, as JWildfire "
      "has it)",
      k3D, kFixed, &affine3D,
      {{"translateX", 0.0, -2.0, 2.0},
       {"translateY", 0.0, -2.0, 2.0},
       {"translateZ", 0.0, -2.0, 2.0},
       {"scaleX", 1.0, -2.0, 2.0},
       {"scaleY", 1.0, -2.0, 2.0},
       {"scaleZ", 1.0, -2.0, 2.0},
       {"rotateX", 0.0, -180.0, 180.0},
       {"rotateY", 0.0, -180.0, 180.0},
       {"rotateZ", 0.0, -180.0, 180.0},
       {"shearXY", 0.0, -1.0, 1.0},
       {"shearXZ", 0.0, -1.0, 1.0},
       {"shearYX", 0.0, -1.0, 1.0},
       {"shearYZ", 0.0, -1.0, 1.0},
       {"shearZX", 0.0, -1.0, 1.0},
       {"shearZY", 0.0, -1.0, 1.0}});
  add("plane_wf",
      "a random point of a square of side `size` in the plane xy (axis 0: (size(½ − Ψ₁), size(½ − Ψ₂), position)), "
      "yz (axis 1: (position, size(½ − Ψ₁), size(½ − Ψ₂))) or zx (axis 2: (size(½ − Ψ₁), position, size(½ − "
      "Ψ₂))); the point itself is not used; direct_color sets the colour index to the square's u + ½ (color_mode 1), "
      "v + ½ (2) or their product (3), (u, v) = (½ − Ψ₁, ½ − Ψ₂) on xy and yz, (½ − Ψ₂, ½ − Ψ₁) on zx (JWildfire's; "
      "its colour and displacement images are not applied)",
      k3D, kRandom, &planeWf,
      {{"position", 3.0, -5.0, 5.0},
       {"size", 10.0, 0.0, 20.0},
       count("axis", 2.0, 0.0, 2.0),
       count("direct_color", 1.0, 0.0, 1.0),
       count("color_mode", 3.0, 0.0, 3.0),
       count("blend_colormap", 0.0, 0.0, 1.0),
       {"displ_amount", 0.0, -1.0, 1.0},
       count("blend_displ_map", 0.0, 0.0, 1.0),
       count("calc_color_idx", 0.0, 0.0, 1.0),
       count("receive_only_shadows", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  add("point_symmetry_wf",
      "c + R(2πk/order)·w(p − c), c = (centre_x, centre_y), k = ⌊Ψ·order⌋, R turning clockwise; z: the point "
      "itself, the weight scaling its offset from c; the colour index moves by k·colorshift (mod 1) (JWildfire's "
      "post_point_symmetry_wf)",
      k2D, kRandom, &pointSymmetryWf,
      {{"centre_x", 0.25, -2.0, 2.0},
       {"centre_y", 0.5, -2.0, 2.0},
       count("order", 3.0, 1.0, 12.0),
       {"colorshift", 0.0, -1.0, 1.0}});
  catalogue.back().directColour = true;
  add("cannabiscurve_wf",
      "r (sin(θ + π/2), cos(θ + π/2)), z; r = (1 + 0.9 cos 8θ)(1 + 0.1 cos 24θ)(0.9 + 0.1 cos 200θ)(1 + sin θ), times "
      "Ψ₂ when Ψ₁ < filled (JWildfire's)",
      k2D, kRandom, &cannabisCurveWf, {{"filled", 0.85, 0.0, 1.0}});
  add("cloverleaf_wf", "r (sin θ, cos θ), z; r = sin 2θ + ¼ sin 6θ, times Ψ₂ when Ψ₁ < filled (JWildfire's)", k2D,
      kRandom, &cloverleafWf, {{"filled", 0.85, 0.0, 1.0}});
  add("japanese_maple_leaf",
      "0.667 s (x(t), y(t)), z: Hamid Naderi Yeganeh's Japanese maple leaf at t = θ/2 + π/2, s = Ψ₂ when Ψ₁ < "
      "filled, else 1 (JWildfire's)",
      k2D, kRandom, &japaneseMapleLeaf, {{"filled", 0.15, 0.0, 1.0}});
  add("spherical3D_wf", "±p/(|p|² + 10⁻³⁰⁰)^(exponent/2), − with invert ≠ 0 (JWildfire's)", k3D, kFixed, &spherical3DWf,
      {count("invert", 0.0, 0.0, 1.0), {"exponent", 2.0, 0.1, 4.0}});
  add("waves2_wf",
      "(d_x (x + d_x scalex f(y·freqx)), d_y (y + d_y scaley g(x·freqy)), z); f = cos with use_cos_x = 1, else sin "
      "(g likewise with use_cos_y), d = e^damp (1 where |damp| < 10⁻⁸) (JWildfire's)",
      k2D, kFixed, &waves2Wf,
      {{"scalex", 0.25, -1.0, 1.0},
       {"scaley", 0.5, -1.0, 1.0},
       {"freqx", kPi / 2.0, 0.0, 10.0},
       {"freqy", kPi / 4.0, 0.0, 10.0},
       count("use_cos_x", 1.0, 0.0, 1.0),
       count("use_cos_y", 0.0, 0.0, 1.0),
       {"dampx", 0.0, -1.0, 1.0},
       {"dampy", 0.0, -1.0, 1.0}});
  add("butterfly3D", "r (x, 2y, |2y|·√(x² + y²)/4), r = 4/√(3π) · √(|xy|/(x² + 4y² + 10⁻³⁰⁰)) (as JWildfire has it)",
      k3D, kFixed, &butterfly3D);
  add("cylinder_apo", "(sin x, y, cos x) (Apophysis 3D's cylinder)", k3D, kFixed, &cylinderApo);
  add("crown_js",
      "(u, v, (u² + v²)²), u + iv = Σ_{k=1}^{14} (sin θ_k + i cos θ_k)/a^(bk), θ_k = (−1)^(k+1) a^k t, t = −π + 2πΨ: "
      "Roger Bagula's crown; the point itself is not used (Jesus Sosa's, as JWildfire has it; its colour is not "
      "applied)",
      k3D, kRandom, &crownJs, {{"a", 5.0, 1.0, 10.0}, {"b", std::log(2.0) / std::log(3.0), 0.0, 2.0}});
  add("flower_db",
      "r (sin φ, cos φ) with r = w √(x² + y²) |(petal_spread + sin(petals φ)) cos(petal_split petals φ)|; z: the sum "
      "so far's z − stem_thickness (2/r − 1), + (ρ − petal_fold_radius) petal_fold_strength where the sum so far "
      "reaches ρ > petal_fold_radius from the axis, held at −stem_length from below when stem_length ≠ 0 (as "
      "JWildfire has it, whose z replaces the sum's)",
      k3D, kFixed, &flowerDb,
      {{"petals", 6.0, 0.0, 20.0},
       {"petal_split", 0.0, 0.0, 2.0},
       {"petal_spread", 1.0, 0.0, 2.0},
       {"stem_thickness", 1.0, 0.0, 2.0},
       {"stem_length", 0.0, 0.0, 2.0},
       {"petal_fold_strength", 0.0, -2.0, 2.0},
       {"petal_fold_radius", 1.0, 0.0, 2.0}});
  catalogue.back().readsSum = true;  // its z is the sum so far's, moved
  add("recurrenceplot",
      "(i/N − ½, j/N − ½, z) for a random pair of samples i, j = ⌊NΨ⌋ of the signal func_id (30 of them) with |y(i) − "
      "y(j)| < tolerance, N = Density; the point itself is not used; pairs are drawn again until one is near (up to "
      "1000 times, then the point is dropped) where JWildfire repeats its last point (Jesus Sosa's); dc 1: colour "
      "index |½ x y / scale + offset| mod 1, dc 2: |½ ((x cos angle + y sin angle + offset) / scale + 1)| mod 1, at "
      "the sum",
      k2D, kRandom, &recurrencePlot,
      {count("func_id", 0.0, 0.0, 29.0),
       {"a", 0.5, 0.0, 10.0},
       {"b", 10.0, 0.0, 10.0},
       count("k", 5.0, 0.0, 20.0),
       count("Density", 700.0, 100.0, 2000.0),
       count("dc", 0.0, 0.0, 2.0),
       {"scale", 1.0, 0.0, 2.0},
       {"angle", 0.0, -kPi, kPi},
       {"offset", 0.0, 0.0, 1.0},
       {"tolerance", 5.0, 0.0, 50.0}});
  catalogue.back().directColour = true;
  catalogue.back().readsSum = true;  // dc 1 and 2 colour at the sum so far with its own value added
  add("minkowskope",
      "−p where |y| ≤ t, else p; z; t = amplitude e^(−damping |x|) M(frequencyx x/2 − 1 + perturbation M(frequencyy "
      "y/2)) + separation, M a wave of Minkowski's question-mark function (dark-beam's, as JWildfire has it; files may "
      "write the parameters as mskope_separation, …)",
      k2D, kFixed, &minkowskope,
      {{"separation", 0.5, 0.0, 2.0},
       {"frequencyx", -2.0, -10.0, 10.0},
       {"frequencyy", 2.0, -10.0, 10.0},
       {"amplitude", 0.5, -2.0, 2.0},
       {"perturbation", 1.0, -2.0, 2.0},
       {"damping", 0.0, -1.0, 1.0}});
}

}  // namespace voxflame::core
