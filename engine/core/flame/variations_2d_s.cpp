// Fractorium's smaller 2D variations, s to z: swirls, targets, shreds, sine grids and waves. Each is a kernel below
// and one row of the table at the end (see variations.h for the notation and variation_kernels.h for what the files
// share). They follow Fractorium's formulas (Source/Ember/Variations0*.h), including where Fractorium leaves the
// weight out; z is carried as w·z (voxflame's rule for 2D variations, where Fractorium writes 0).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// ---- swirls and polygons ---------------------------------------------------------------------

// Fractorium's scry2: the scry inversion p/(r (r² + 1)), then stretched onto a regular polygon of `power` sides
// (the angle within each sector pulled towards the sector's edge and the radius grown by 1/cos of it).
VOXFLAME_VARIATION_TARGETS void scry2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sector = kTwoPi / fractoriumZeps(P[0]);
  const double tanHalf2 = 2.0 * std::tan(sector * 0.5);
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double s = 1.0 / fractoriumZeps(std::sqrt(r2) * (r2 + 1.0));
    const double nx = x[i] * s, ny = y[i] * s;
    const double dang = (std::atan2(ny, nx) + kPi) / sector;
    const double rad = std::sqrt(nx * nx + ny * ny);
    const double whole = std::floor(dang), frac = dang - whole;
    const bool upper = frac > 0.5;
    const double xang = std::atan((upper ? 1.0 - frac : frac) * tanHalf2) / sector;
    const double coeff = 1.0 / std::cos(xang * sector);
    const double ang = ((upper ? whole + 1.0 : whole) + (upper ? -xang : xang)) * sector - kPi;
    outX[i] += w * coeff * rad * std::cos(ang);
    outY[i] += w * coeff * rad * std::sin(ang);
    outZ[i] += w * z[i];
  }
}

// Fractorium's shredrad: the angle cut into n sectors, each narrowed to `width` of itself. The sector index is
// truncated towards 0, as Fractorium's int() does (std::trunc here: an int of a NaN angle would be undefined).
VOXFLAME_VARIATION_TARGETS void shredrad(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = P[0] == 0.0 ? kFractoriumEps : P[0];
  const double width = std::clamp(P[1], -1.0, 1.0);
  const double alpha = kTwoPi / sides;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double xang = (std::atan2(y[i], x[i]) + 3.0 * kPi + alpha / 2.0) / alpha;
    const double k = std::trunc(xang);
    const double zang = ((xang - k) * width + k) * alpha - kPi - alpha / 2.0 * width;
    outX[i] += w * r * std::cos(zang);
    outY[i] += w * r * std::sin(zang);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(squarize, {
  const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
  double a = std::atan2(y[i], x[i]);
  if (a < 0.0) a += kTwoPi;
  const double p = 4.0 * r * a / kPi;
  double px = r, py = -(8.0 * r - p);
  if (p <= r) {
    px = r;
    py = p;
  } else if (p <= 3.0 * r) {
    px = 2.0 * r - p;
    py = r;
  } else if (p <= 5.0 * r) {
    px = -r;
    py = 4.0 * r - p;
  } else if (p <= 7.0 * r) {
    px = -(6.0 * r - p);
    py = -r;
  }
  outX[i] += w * px;
  outY[i] += w * py;
})

// swirl3: the angle turned by shift · ln r. At the origin the result is its limit, the origin (Fractorium's is NaN).
VOXFLAME_VARIATION_TARGETS void swirl3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shift = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double a = std::atan2(y[i], x[i]) + std::log(r) * shift;
    outX[i] += r == 0.0 ? 0.0 : w * r * std::cos(a);
    outY[i] += r == 0.0 ? 0.0 : w * r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// swirl3r: swirl3 between the radii min and max; inside and outside them the turn of the nearer radius.
VOXFLAME_VARIATION_TARGETS void swirl3r(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shift = P[0], lo = std::max(P[1], 0.0), hi = std::max(P[2], 0.0);
  const double minR = std::min(lo, hi), maxR = std::max(lo, hi);
  const double minA = minR > 0.0 ? std::log(minR) * shift : 0.0, maxA = maxR > 0.0 ? std::log(maxR) * shift : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double turn = r < minR ? minA : (r > maxR ? maxA : std::log(r) * shift);
    const double a = std::atan2(y[i], x[i]) + turn;
    outX[i] += r == 0.0 ? 0.0 : w * r * std::cos(a);
    outY[i] += r == 0.0 ? 0.0 : w * r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// target, target0, target2: the point turned by `even` or `odd` by the ring of width size/2 (in ln r, or for target2
// in tightness · ln r + (φ + π)/π, a spiral) it lies in. Fractorium's target applies no weight; target0 and target2 do.
template <bool kWeighted, bool kSpiral>
[[gnu::always_inline]] inline void targetRings(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz, double minSize) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double even = P[0], odd = P[1], size = std::max(P[2], minSize);
  const double half = size * 0.5;
  const double tightness = kSpiral ? P[3] : 0.0;
  const double factor = kWeighted ? w : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double phi = std::atan2(y[i], x[i]);
    double t = kSpiral ? tightness * std::log(r) + (phi + kPi) / kPi : std::log(r);
    if (t < 0.0) t -= half;
    t = laneFmod(std::abs(t), size);
    const double a = phi + (t < half ? even : odd);
    outX[i] += factor * r * std::cos(a);
    outY[i] += factor * r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void target(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  targetRings<false, false>(in, ox, oy, oz, kFractoriumEps);
}
VOXFLAME_VARIATION_TARGETS void target0(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  targetRings<true, false>(in, ox, oy, oz, 0.0);
}
VOXFLAME_VARIATION_TARGETS void target2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  targetRings<true, true>(in, ox, oy, oz, kFractoriumEps);
}

// Fractorium's xheart: the point scaled by (4, 6 + 2 ratio)/(r² + 4), turned by π/4 (1 + angle/2), and mirrored in y
// where it lands at x ≤ 0.
VOXFLAME_VARIATION_TARGETS void xheart(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double ang = kPi / 4.0 + 0.5 * (kPi / 4.0) * P[0];
  const double sa = std::sin(ang), ca = std::cos(ang);
  const double rat = 6.0 + 2.0 * P[1];
  for (std::size_t i = 0; i < n; ++i) {
    double r24 = x[i] * x[i] + y[i] * y[i] + 4.0;
    if (r24 == 0.0) r24 = 1.0;
    const double bx = 4.0 / r24, by = rat / r24;
    const double px = ca * (bx * x[i]) - sa * (by * y[i]);
    const double py = sa * (bx * x[i]) + ca * (by * y[i]);
    outX[i] += w * px;
    outY[i] += px > 0.0 ? w * py : -w * py;
    outZ[i] += w * z[i];
  }
}

// ---- sine grids and shifts -------------------------------------------------------------------

// A shift by (x₀, y₀) turned by angle degrees, with Fractorium's signs (y moves by −(cos·y₀ + sin·x₀)).
VOXFLAME_VARIATION_TARGETS void shift(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], rad = P[2] / 180.0 * kPi;
  const double s = std::sin(rad), c = std::cos(rad);
  const double dx = c * sx - s * sy, dy = -(c * sy) - s * sx;
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] + dx);
    outY[i] += w * (y[i] + dy);
    outZ[i] += w * z[i];
  }
}

// Fractorium's sigmoid: each coordinate through a logistic curve 2/(1 + e^(s v)) − 1 (times ±1), s = −5 shift, or
// −5/shift (and the sign of shift) for |shift| < 1, ε for 0; scaled by |w|.
VOXFLAME_VARIATION_TARGETS void sigmoid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const auto slope = [](double shift, double& amp) {
    amp = 1.0;
    if (shift < 1.0 && shift > -1.0) {
      if (shift == 0.0) return -5.0 * kFractoriumEps;
      amp = shift < 0.0 ? -1.0 : 1.0;
      return -5.0 / shift;
    }
    return -5.0 * shift;
  };
  double ax = 1.0, ay = 1.0;
  const double sx = slope(P[0], ax), sy = slope(P[1], ay);
  const double vv = std::abs(w);
  for (std::size_t i = 0; i < n; ++i) {
    const double c0 = ax / fractoriumZeps(1.0 + std::exp(sx * x[i]));
    const double c1 = ay / fractoriumZeps(1.0 + std::exp(sy * y[i]));
    outX[i] += vv * 2.0 * (c0 - 0.5);
    outY[i] += vv * 2.0 * (c1 - 0.5);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void sintrange(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double x2 = x[i] * x[i], y2 = y[i] * y[i];
    const double v = (x2 + y2) * k;
    outX[i] += w * std::sin(x[i]) * (x2 + k - v);
    outY[i] += w * std::sin(y[i]) * (y2 + k - v);
    outZ[i] += w * z[i];
  }
}

// Each coordinate blended towards −cos(2π freq ·) by amp.
VOXFLAME_VARIATION_TARGETS void sinusgrid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double ax = P[0], ay = P[1];
  const double fx = fractoriumZeps(P[2] * kTwoPi), fy = fractoriumZeps(P[3] * kTwoPi);
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = -std::cos(x[i] * fx), sy = -std::cos(y[i] * fy);
    outX[i] += w * (x[i] + (sx - x[i]) * ax);
    outY[i] += w * (y[i] + (sy - y[i]) * ay);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(spiralwing, {
  const double d = fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
  const double c1 = fractoriumZeps(x[i] * x[i]), c2 = fractoriumZeps(y[i] * y[i]);
  outX[i] += w * (1.0 / d) * std::cos(c1) * std::sin(c2);
  outY[i] += w * (1.0 / d) * std::sin(c1) * std::sin(c2);
})

// Fractorium clamps the radicand at 0 where the original plugin took √ of a negative number.
VOXFLAME_VARIATION_TARGETS void squirrel(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = fractoriumZeps(P[0]), b = fractoriumZeps(P[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = std::sqrt(std::max(a * x[i] * x[i] + b * y[i] * y[i], 0.0));
    outX[i] += w * std::cos(u) * std::tan(x[i]);
    outY[i] += w * std::sin(u) * std::tan(y[i]);
    outZ[i] += w * z[i];
  }
}

// Fractorium's stwin: w p plus a term added to both coordinates outside the weight, computed at 0.05 w p.
VOXFLAME_VARIATION_TARGETS void stwin(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double distort = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = x[i] * w * 0.05, sy = y[i] * w * 0.05;
    const double x2 = sx * sx, y2 = sy * sy;
    const double sum = x2 + y2;
    const double result = (x2 - y2) * std::sin(kTwoPi * distort * (sx + sy)) / (sum != 0.0 ? sum : 1.0);
    outX[i] += w * x[i] + result;
    outY[i] += w * y[i] + result;
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_2D(tancos, {
  const double d = fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
  outX[i] += w / d * (std::tanh(d) * 2.0 * x[i]);
  outY[i] += w / d * (std::cos(d) * 2.0 * y[i]);
})

// Fractorium's trade: the disc of radius r1 about (r1 + d1, 0) (for x > 0) and the disc of radius r2 about
// (−r2 − d2, 0) (for x ≤ 0) swap places, each scaled to the other's radius and mirrored in x; outside them the
// point stays.
VOXFLAME_VARIATION_TARGETS void trade(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double r1 = std::max(P[0], kFractoriumEps), r2 = std::max(P[2], kFractoriumEps);
  const double c1 = r1 + std::max(P[1], 0.0), c2 = r2 + std::max(P[3], 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool right = x[i] > 0.0;
    const double dx = right ? c1 - x[i] : -c2 - x[i];
    const double r = std::sqrt(dx * dx + y[i] * y[i]);
    const bool inside = r <= (right ? r1 : r2);
    const double scaled = r * (right ? r2 / r1 : r1 / r2), a = std::atan2(y[i], dx);
    outX[i] += inside ? w * (scaled * std::cos(a) + (right ? -c2 : c1)) : w * x[i];
    outY[i] += inside ? w * scaled * std::sin(a) : w * y[i];
    outZ[i] += w * z[i];
  }
}

// Fractorium's unicorngaloshen: ((x − y)(x + mult_y y) f_x, x y f_y) w/√(mult_y y² + mult_x x²); f = (sin_x_amplitude,
// sin_y_amplitude) without sine, else (1, 2) + the amplitudes times sin(π freq s), s by mode (0 the point, 1 e^(−p),
// 2 1/p, 3 (ln|x|, sin_y_amplitude ln|y|), 4 (θ, φ)); mode clamped to [0, 4] and compared as Fractorium does.
VOXFLAME_VARIATION_TARGETS void unicornGaloshen(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                                double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double multX = P[0], multY = P[1], sine = P[2], ampX = P[3], ampY = P[5];
  const double freqX = kPi * P[4], freqY = kPi * P[6], mode = std::clamp(P[7], 0.0, 4.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w / fractoriumZeps(std::sqrt(y[i] * y[i] * multY + multX * x[i] * x[i]));
    double fx = ampX, fy = ampY;
    if (sine > 0.0) {
      double sx = 0.0, sy = 0.0;
      if (mode <= 0.0) {
        sx = x[i];
        sy = y[i];
      } else if (mode <= 1.0) {
        sx = std::exp(-x[i]);
        sy = std::exp(-y[i]);
      } else if (mode <= 2.0) {
        sx = 1.0 / fractoriumZeps(x[i]);
        sy = 1.0 / fractoriumZeps(y[i]);
      } else if (mode <= 3.0) {
        sx = std::log(std::abs(x[i]));
        sy = ampY * std::log(std::abs(y[i]));
      } else {
        sx = std::atan2(x[i], y[i]);
        sy = std::atan2(y[i], x[i]);
      }
      fx = 1.0 + ampX * std::sin(sx * freqX);
      fy = 2.0 + ampY * std::sin(sy * freqY);
    }
    outX[i] += fx * (x[i] - y[i]) * (x[i] + multY * y[i]) * r;
    outY[i] += fy * x[i] * y[i] * r;
    outZ[i] += w * z[i];
  }
}

// Fractorium's wrap of a cyclic parameter into [low, high] when it is set.
double wrapCyclic(double value, double low, double high) {
  if (value > high) return low + std::fmod(value - low, high - low);
  if (value < low) return high - std::fmod(high - value, high - low);
  return value;
}

// Fractorium's vibration: two plane waves, each displacing the point by amp sin(2π freq d + 2π phase/freq) (d its
// distance along dir) in the direction dir + angle. The phases are wrapped into [0, 1] as Fractorium does when they
// are set (a phase of 1.25 is 0.25).
VOXFLAME_VARIATION_TARGETS void vibration(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cosDir = std::cos(P[0]), sinDir = std::sin(P[0]);
  const double cosTot = std::cos(P[1] + P[0]), sinTot = std::sin(P[1] + P[0]);
  const double freq = P[2] * kTwoPi, amp = P[3], shift = kTwoPi * wrapCyclic(P[4], 0.0, 1.0) / fractoriumZeps(P[2]);
  const double cosDir2 = std::cos(P[5]), sinDir2 = std::sin(P[5]);
  const double cosTot2 = std::cos(P[6] + P[5]), sinTot2 = std::sin(P[6] + P[5]);
  const double freq2 = P[7] * kTwoPi, amp2 = P[8], shift2 = kTwoPi * wrapCyclic(P[9], 0.0, 1.0) / fractoriumZeps(P[7]);
  for (std::size_t i = 0; i < n; ++i) {
    const double a1 = amp * std::sin((x[i] * cosDir + y[i] * sinDir) * freq + shift);
    const double a2 = amp2 * std::sin((x[i] * cosDir2 + y[i] * sinDir2) * freq2 + shift2);
    outX[i] += w * (x[i] + a1 * cosTot + a2 * cosTot2);
    outY[i] += w * (y[i] + a1 * sinTot + a2 * sinTot2);
    outZ[i] += w * z[i];
  }
}

// ---- Truchet tiles ---------------------------------------------------------------------------

// Fractorium's truchet_knot: a random point on a bar across the unit cell the point is in, the bar turned a quarter in
// the cells whose x + y is odd, so that the bars weave a knot. The ⌊·⌋ are floors (Fractorium's integer floor,
// kept as a double here so that huge and NaN inputs stay defined).
VOXFLAME_VARIATION_TARGETS void truchetKnot(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  constexpr double kWidth = 0.5, kSpace = 0.1;
  for (std::size_t i = 0; i < n; ++i) {
    const double cellX = std::floor(x[i]), cellY = std::floor(y[i]);
    const double along = (laneUniform(rnd[i]) - 0.5) * kWidth;
    const double across = (laneUniform(rnd[i]) * 2.0 - 1.0) * (1.0 - kSpace - kWidth * 0.5);
    const double dir0 = std::abs(cellX + cellY);
    const bool turned = dir0 - 2.0 * std::floor(dir0 * 0.5) >= 0.5;
    outX[i] += w * (cellX + (turned ? -across : along));
    outY[i] += w * (cellY + (turned ? along : across));
    outZ[i] += w * z[i];
  }
}

// ---- waves -----------------------------------------------------------------------------------

// Fractorium's waves22: waves2 with each sine (or with mode 1 its lift ½(1 + sin)) raised to an integer power (the
// power truncated towards 0, as Fractorium's int()).
VOXFLAME_VARIATION_TARGETS void waves22(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], freqX = P[2], freqY = P[3];
  const bool liftX = fractoriumInteger(P[4], 0.0, 1.0) >= 0.5, liftY = fractoriumInteger(P[5], 0.0, 1.0) >= 0.5;
  const double powX = std::trunc(P[6]), powY = std::trunc(P[7]);
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = std::sin(y[i] * freqX), sy = std::sin(x[i] * freqY);
    const double bx = liftX ? 0.5 * (1.0 + sx) : sx, by = liftY ? 0.5 * (1.0 + sy) : sy;
    outX[i] += w * (x[i] + std::pow(bx, powX) * scaleX);
    outY[i] += w * (y[i] + std::pow(by, powY) * scaleY);
    outZ[i] += w * z[i];
  }
}

// waves2 whose amplitude grows from 0 at radius null to full at radius distance.
VOXFLAME_VARIATION_TARGETS void waves2Radial(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freqX = P[0], scaleX = P[1], freqY = P[2], scaleY = P[3], null = P[4], distance = P[5];
  const double span = fractoriumZeps(distance - null);
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double factor = d < null ? 0.0 : (d < distance ? (d - null) / span : 1.0);
    outX[i] += w * (x[i] + factor * std::sin(y[i] * freqX) * scaleX);
    outY[i] += w * (y[i] + factor * std::sin(x[i] * freqY) * scaleY);
    outZ[i] += w * z[i];
  }
}

// The Jacobi elliptic function sn(u | m), m = 1 − emmc, by the descending Landen (AGM) transformation, as
// Fractorium's VarFuncs::JacobiElliptic computes it (from the IROIRO++ library): at most 8 steps, stopping at a
// relative accuracy of 3·10⁻⁴ per step; tanh u where emmc = 0.
inline double jacobiSn(double uu, double emmc) {
  constexpr double kAccuracy = 0.0003;
  if (emmc == 0.0) return std::tanh(uu);
  double emc = emmc, u = uu, d = 1.0;
  const bool negative = emc < 0.0;
  if (negative) {
    d = 1.0 - emc;
    emc = -emc / d;
    d = std::sqrt(d);
    u = d * u;
  }
  double em[8], en[8];
  double a = 1.0, c = 1.0, dn = 1.0;
  int last = 0;
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
  double sn = std::sin(u);
  const double cn = std::cos(u);
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
  }
  return negative ? sn / d : sn;
}

// Fractorium's waves2b: waves2 whose amplitude falls from scale (at 0) towards scaleinf as unity/(unity + x²) falls,
// and whose wave is sin(freq · sgn(v) |v|^pw), or for pw in [0, 10⁻⁴) the Jacobi sn(freq v | 1 − jacok) and for pw in
// (−10⁻⁴, 0) the Bessel function J₁(freq v), as Fractorium has them.
VOXFLAME_VARIATION_TARGETS void waves2b(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freqX = P[0], freqY = P[1], pwX = std::clamp(P[2], -10.0, 10.0), pwY = std::clamp(P[3], -10.0, 10.0);
  const double scaleInfX = P[5], scaleInfY = P[7], unity = P[8], jacok = std::clamp(P[9], -1.0, 1.0);
  const double sIX = P[4] - scaleInfX, sIY = P[6] - scaleInfY;
  // Fractorium's SafeDivInv(q, r): 1/r where r < ε, else q/r.
  const auto safeDivInv = [](double q, double r) { return r < kFractoriumEps ? 1.0 / r : q / r; };
  const auto wave = [jacok](double v, double freq, double pw) {
    if (pw >= 0.0 && pw < 1e-4) return jacobiSn(v * freq, jacok);
    if (pw < 0.0 && pw > -1e-4) return ::j1(v * freq);
    return std::sin((v < 0.0 ? -1.0 : 1.0) * std::pow(fractoriumZeps(std::abs(v)), pw) * freq);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double csX = safeDivInv(unity, unity + x[i] * x[i]) * sIX + scaleInfX;
    const double csY = safeDivInv(unity, unity + y[i] * y[i]) * sIY + scaleInfY;
    outX[i] += w * (x[i] + csX * wave(y[i], freqX, pwX));
    outY[i] += w * (y[i] + csY * wave(x[i], freqY, pwY));
    outZ[i] += w * z[i];
  }
}

// waves2 whose amplitudes themselves wave: ½ scale (1 + sin(sx_freq y)), ½ scale (1 + sin(sy_freq x)).
VOXFLAME_VARIATION_TARGETS void waves3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double halfX = P[0] * 0.5, halfY = P[1] * 0.5, freqX = P[2], freqY = P[3], sxFreq = P[4], syFreq = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = halfX * (1.0 + std::sin(y[i] * sxFreq)), sy = halfY * (1.0 + std::sin(x[i] * syFreq));
    outX[i] += w * (x[i] + std::sin(y[i] * freqX) * sx);
    outY[i] += w * (y[i] + std::sin(x[i] * freqY) * sy);
    outZ[i] += w * z[i];
  }
}

// waves4 and waves42: waves2 whose x amplitude is a hash of the band of y the point is in (the shader hash
// fract(sin(k) · 43758.5453), with Fractorium's truncation: negative values stay negative), squared; with cont the
// hash is rounded to 0 or 1. waves4's bands are 2π/freqx wide, waves42's 1/freqx2.
template <bool kOwnBands>
[[gnu::always_inline]] inline void wavesHashed(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], freqX = P[2], freqY = P[3];
  const bool cont = fractoriumInteger(P[4], 0.0, 1.0) == 1.0;
  const double yfact = P[5] * 0.001;
  const double band = kOwnBands ? P[6] : freqX / kTwoPi;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::floor(y[i] * band);
    double h = std::sin(k * 12.9898 + k * 78.233 + 1.0 + y[i] * yfact) * 43758.5453;
    h -= std::trunc(h);
    if (cont) h = h > 0.5 ? 1.0 : 0.0;
    outX[i] += w * (x[i] + std::sin(y[i] * freqX) * h * h * scaleX);
    outY[i] += w * (y[i] + std::sin(x[i] * freqY) * scaleY);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void waves4(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  wavesHashed<false>(in, ox, oy, oz);
}
VOXFLAME_VARIATION_TARGETS void waves42(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  wavesHashed<true>(in, ox, oy, oz);
}

// ---- w, x, z: Fractorium's shape family (with y in variations_fractorium.cpp) ----------------------------

// The radius T(a) at angle a of the sum of four shapes, each scaled by its own parameter and left out at 0: a
// hypergon, a star, a lituus and a superformula curve. `P` holds the 13 shape parameters from hypergon on.
struct ShapeSum {
  double hypergon, hypergonN, hypergonD, star, starN, tanStarSlope, lituus, invLituusA, super, superM4, superN2,
      superN3, oneOverN1;
  explicit ShapeSum(const double* P)
      : hypergon(P[0]),
        hypergonN(std::max(std::floor(P[1] + 0.5), 3.0)),
        hypergonD(std::sqrt(1.0 + P[2] * P[2])),
        star(P[3]),
        starN(std::max(std::floor(P[4] + 0.5), 3.0)),
        tanStarSlope(0.0),
        lituus(P[6]),
        invLituusA(-P[7]),
        super(P[8]),
        superM4(P[9] / 4.0),
        superN2(P[11]),
        superN3(P[12]),
        oneOverN1(-1.0 / fractoriumZeps(P[10])) {
    const double slope = std::clamp(P[5], kFractoriumEps, kPi / 2.0);
    // Fractorium steps back from tan(π/2), which is undefined.
    tanStarSlope = std::abs(slope - kPi / 2.0) < 1e-6 ? std::tan(slope - 0.05) : std::tan(slope);
  }
  [[gnu::always_inline]] double at(double a) const {
    double total = 0.0;
    if (hypergon != 0.0) {
      const double t1 = std::fmod(std::abs(a), kTwoPi / hypergonN) - kPi / hypergonN;
      const double t2 = std::tan(t1) * std::tan(t1) + 1.0, d2 = hypergonD * hypergonD;
      total += t2 >= d2 ? hypergon : hypergon * (hypergonD - std::sqrt(d2 - t2)) / std::sqrt(t2);
    }
    if (star != 0.0) {
      const double t1 = std::tan(std::abs(std::fmod(std::abs(a), kTwoPi / starN) - kPi / starN));
      const double k = tanStarSlope;
      total += star * std::sqrt(k * k * (1.0 + t1 * t1) / ((t1 + k) * (t1 + k)));
    }
    if (lituus != 0.0) total += lituus * std::pow(std::abs(a / kPi + 1.0), invLituusA);
    if (super != 0.0) {
      const double t4 = a * superM4;
      total += super * std::pow(std::pow(std::abs(std::cos(t4)), superN2) + std::pow(std::abs(std::sin(t4)), superN3),
                                oneOverN1);
    }
    return total;
  }
};

// Fractorium's w: inside the shape (r ≤ T(φ)) the point is turned by angle and its radius scaled by T(φ + angle)/T(φ);
// outside it stays.
VOXFLAME_VARIATION_TARGETS void wShapes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double turn = wrapCyclic(P[0], -kPi, kPi);
  const ShapeSum shape(P + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(y[i], x[i]), r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    double a2 = a + turn;
    if (a2 < -kPi) a2 += kTwoPi;
    if (a2 > kPi) a2 -= kTwoPi;
    const double total = shape.at(a);
    if (r <= total) {
      const double scaled = w * shape.at(a2) * r / total;
      outX[i] += scaled * std::cos(a2);
      outY[i] += scaled * std::sin(a2);
    } else {
      outX[i] += w * x[i];
      outY[i] += w * y[i];
    }
    outZ[i] += w * z[i];
  }
}

// Fractorium's x: the radius becomes √(r² + T(φ)²).
VOXFLAME_VARIATION_TARGETS void xShapes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const ShapeSum shape(P);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(y[i], x[i]), total = shape.at(a);
    const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i] + total * total);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// Fractorium's z: the radius becomes r + T(φ).
VOXFLAME_VARIATION_TARGETS void zShapes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const ShapeSum shape(P);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(y[i], x[i]);
    const double r = w * (std::sqrt(x[i] * x[i] + y[i] * y[i]) + shape.at(a));
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractorium2dSVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("scry2",
      "q = p/(r (r² + 1)) stretched onto a regular polygon of `power` sides: |q| (cos a, sin a)/cos(x' s), a = (k ± "
      "x') s − π, s = 2π/power, k, x' the sector and the offset in it of (∠q + π)/s (x' through atan(2 x tan(s/2))/s) "
      "(Fractorium's)",
      k2D, kFixed, &scry2, {{"power", 4.0, 1.0, 12.0}});
  add("shift",
      "(x + x₀ cos α − y₀ sin α, y − y₀ cos α − x₀ sin α), z; α = angle in degrees, x₀, y₀ the parameters x, y "
      "(Fractorium's)",
      k2D, kFixed, &shift, {{"x", 0.0, -2.0, 2.0}, {"y", 0.0, -2.0, 2.0}, {"angle", 0.0, -180.0, 180.0}});
  add("shredrad",
      "r (cos a, sin a), z; a = ((k' − ⌊k'⌉) width + ⌊k'⌉) α − π − α width/2, k' = (φ + 3π + α/2)/α truncated as ⌊k'⌉, "
      "α = 2π/n (Fractorium's)",
      k2D, kFixed, &shredrad, {{"n", 4.0, 1.0, 12.0}, {"width", 0.5, -1.0, 1.0}});
  add("sigmoid",
      "|w| (2a/(1 + e^(s_x x)) − 1, 2b/(1 + e^(s_y y)) − 1), z; s = −5 shift, or −5/shift with a = sgn shift where "
      "|shift| < 1 (ε at 0), else a = 1 (w the weight; Fractorium's)",
      k2D, kFixed, &sigmoid, {{"shiftx", 1.0, -4.0, 4.0}, {"shifty", 1.0, -4.0, 4.0}});
  add("sintrange", "(sin x (x² + k − k r²), sin y (y² + k − k r²)), z; k the parameter w (Fractorium's)", k2D, kFixed,
      &sintrange, {{"w", 1.0, -2.0, 2.0}});
  add("sinusgrid", "(x + ampx (−cos(2π freqx x) − x), y + ampy (−cos(2π freqy y) − y)), z (Fractorium's)", k2D, kFixed,
      &sinusgrid,
      {{"ampx", 0.5, -2.0, 2.0}, {"ampy", 0.5, -2.0, 2.0}, {"freqx", 1.0, -4.0, 4.0}, {"freqy", 1.0, -4.0, 4.0}});
  add("spiralwing", "(cos x², sin x²) sin(y²)/r², z; r², x², y² as ε where 0 (Fractorium's)", k2D, kFixed, &spiralwing);
  add("squarize",
      "the point on the square of half-side r at perimeter position 4 r φ'/π from (r, 0), φ' = φ in [0, 2π), z "
      "(Fractorium's)",
      k2D, kFixed, &squarize);
  add("squirrel", "(cos u tan x, sin u tan y), z; u = √max(0, a x² + b y²), a and b as ε where 0 (Fractorium's)", k2D,
      kFixed, &squirrel, {{"a", 1.0, -2.0, 2.0}, {"b", 1.0, -2.0, 2.0}});
  add("stwin",
      "w p + t (1, 1), z; t = (x'² − y'²) sin(2π distort (x' + y'))/(x'² + y'²) (1 where 0), (x', y') = 0.05 w p, the "
      "term t not weighted (w the weight; Fractorium's)",
      k2D, kFixed, &stwin, {{"distort", 1.0, -4.0, 4.0}});
  add("swirl3", "r (cos(φ + shift ln r), sin(φ + shift ln r)), z; the origin at r = 0 (Fractorium's)", k2D, kFixed,
      &swirl3, {{"shift", 0.5, -2.0, 2.0}});
  add("swirl3r",
      "swirl3 for min ≤ r ≤ max (either order), the turn of the nearer limit outside; a limit ≤ 0 turns by 0 "
      "(Fractorium's)",
      k2D, kFixed, &swirl3r, {{"shift", 0.5, -2.0, 2.0}, {"min", 0.5, 0.0, 4.0}, {"max", 1.0, 0.0, 4.0}});
  add("tancos", "2 (tanh(r²) x, cos(r²) y)/r², z; r² as ε where 0 (Fractorium's)", k2D, kFixed, &tancos);
  add("target",
      "r (cos(φ + δ), sin(φ + δ)) without the weight, z; δ = even where fmod(|t|, size) < size/2, else odd; t = ln r, "
      "less size/2 where negative; size at least ε (Fractorium's, which applies no weight here)",
      k2D, kFixed, &target, {{"even", 0.0, 0.0, kTwoPi}, {"odd", 0.0, 0.0, kTwoPi}, {"size", 1.0, 0.01, 4.0}});
  add("target0", "target with the weight applied, size at least 0 (at 0 every point turns by odd) (Fractorium's)", k2D,
      kFixed, &target0, {{"even", 0.0, 0.0, kTwoPi}, {"odd", 0.0, 0.0, kTwoPi}, {"size", 0.0, 0.0, 4.0}});
  add("target2",
      "target0 with t = thightness ln r + (φ + π)/π (a spiral), size at least ε (Fractorium's; the parameter's "
      "spelling is Fractorium's)",
      k2D, kFixed, &target2,
      {{"even", 0.0, 0.0, kTwoPi},
       {"odd", 0.0, 0.0, kTwoPi},
       {"size", 1.0, 0.01, 4.0},
       {"thightness", 0.0, -4.0, 4.0}});
  add("trade",
      "for x > 0 and |p − c₁| ≤ r1 (c₁ = (r1 + d1, 0)): the point mirrored about c₁ in x, scaled by r2/r1 and moved "
      "to c₂ = (−r2 − d2, 0); for x ≤ 0 and |p − c₂| ≤ r2 the reverse; else p; z (Fractorium's)",
      k2D, kFixed, &trade,
      {{"r1", 1.0, 0.01, 4.0}, {"d1", 1.0, 0.0, 4.0}, {"r2", 1.0, 0.01, 4.0}, {"d2", 1.0, 0.0, 4.0}});
  add("truchet_knot",
      "⌊p⌋ + (a, b), or (−b, a) where ⌊x⌋ + ⌊y⌋ is odd, z; a = (Ψ₁ − ½)/2, b = (2Ψ₂ − 1) 0.65 (Fractorium's)", k2D,
      kRandom, &truchetKnot);
  add("unicorngaloshen",
      "((x − y)(x + mult_y y) f_x, x y f_y)/√(mult_y y² + mult_x x²), z; f = (sin_x_amplitude, sin_y_amplitude) where "
      "sine ≤ 0, else (1 + sin_x_amplitude sin(π sin_x_freq s_x), 2 + sin_y_amplitude sin(π sin_y_freq s_y)), s by "
      "mode: ≤ 0 p, ≤ 1 e^(−p), ≤ 2 1/p, ≤ 3 (ln|x|, sin_y_amplitude ln|y|), else (θ, φ) (Fractorium's)",
      k2D, kFixed, &unicornGaloshen,
      {{"mult_x", 1.0, -2.0, 2.0},
       {"mult_y", 1.0, -2.0, 2.0},
       {"sine", 0.0, -1.0, 1.0},
       {"sin_x_amplitude", 1.0, -4.0, 4.0},
       {"sin_x_freq", 0.1, -2.0, 2.0},
       {"sin_y_amplitude", 2.0, -4.0, 4.0},
       {"sin_y_freq", 0.2, -2.0, 2.0},
       {"mode", 0.0, 0.0, 4.0}});
  add("vibration",
      "p + Σₖ amp_k sin(2π freq_k (p · (cos dir_k, sin dir_k)) + 2π phase_k/freq_k) (cos(dir_k + angle_k), sin(dir_k "
      "+ angle_k)) over the two waves (parameters without and with 2), phases wrapped into [0, 1]; z (Fractorium's)",
      k2D, kFixed, &vibration,
      {{"dir", 0.0, 0.0, kTwoPi},
       {"angle", kPi / 2.0, 0.0, kTwoPi},
       {"freq", 1.0, -10.0, 10.0},
       {"amp", 0.25, -2.0, 2.0},
       {"phase", 0.0, 0.0, 1.0},
       {"dir2", kPi / 2.0, 0.0, kTwoPi},
       {"angle2", kPi / 2.0, 0.0, kTwoPi},
       {"freq2", 1.0, -10.0, 10.0},
       {"amp2", 0.25, -2.0, 2.0},
       {"phase2", 0.0, 0.0, 1.0}});
  add("w",
      "inside the shape (r ≤ T(φ)) r T(φ')/T(φ) (cos φ', sin φ'), φ' = φ + angle (in [−π, π]), else p; z; T = y's sum "
      "of "
      "shapes (hypergon, star, lituus, super; Fractorium's)",
      k2D, kFixed, &wShapes,
      {{"angle", 0.0, -kPi, kPi},
       {"hypergon", 0.0, -3.0, 3.0},
       count("hypergon_n", 4.0, 3.0, 12.0),
       {"hypergon_r", 1.0, 0.0, 3.0},
       {"star", 0.0, -3.0, 3.0},
       count("star_n", 5.0, 3.0, 12.0),
       {"star_slope", 2.0, 0.0, 2.0},
       {"lituus", 0.0, -3.0, 3.0},
       {"lituus_a", 1.0, -3.0, 3.0},
       {"super", 0.0, -3.0, 3.0},
       {"super_m", 1.0, 0.0, 12.0},
       {"super_n1", 1.0, 0.1, 10.0},
       {"super_n2", 1.0, 0.0, 10.0},
       {"super_n3", 1.0, 0.0, 10.0}});
  add("waves22",
      "(x + scalex s_x^⌊powerx⌉, y + scaley s_y^⌊powery⌉), z; s_x = sin(freqx y), or ½(1 + sin(freqx y)) with modex "
      "(likewise s_y with x), powers truncated to integers (Fractorium's)",
      k2D, kFixed, &waves22,
      {{"scalex", 0.05, -2.0, 2.0},
       {"scaley", 0.05, -2.0, 2.0},
       {"freqx", 7.0, -20.0, 20.0},
       {"freqy", 13.0, -20.0, 20.0},
       count("modex", 0.0, 0.0, 1.0),
       count("modey", 0.0, 0.0, 1.0),
       {"powerx", 2.0, -4.0, 8.0},
       {"powery", 2.0, -4.0, 8.0}});
  add("waves2_radial",
      "(x + f scalex sin(freqx y), y + f scaley sin(freqy x)), z; f = 0 for r < null, (r − null)/(distance − null) "
      "below distance, else 1 (Fractorium's)",
      k2D, kFixed, &waves2Radial,
      {{"freqx", 7.0, -20.0, 20.0},
       {"scalex", 0.1, -2.0, 2.0},
       {"freqy", 13.0, -20.0, 20.0},
       {"scaley", 0.1, -2.0, 2.0},
       {"null", 2.0, 0.0, 10.0},
       {"distance", 10.0, 0.0, 20.0}});
  add("waves2b",
      "(x + c_x g(y, freqx, pwx), y + c_y g(x, freqy, pwy)), z; c_x = (scalex − scaleinfx) unity/(unity + x²) + "
      "scaleinfx (likewise c_y with y); g(v, f, p) = sin(f sgn(v) |v|^p), or sn(f v | 1 − jacok) for p in [0, 10⁻⁴), "
      "J₁(f v) for p in (−10⁻⁴, 0) (Fractorium's)",
      k2D, kFixed, &waves2b,
      {{"freqx", 2.0, -10.0, 10.0},
       {"freqy", 2.0, -10.0, 10.0},
       {"pwx", 1.0, -10.0, 10.0},
       {"pwy", 1.0, -10.0, 10.0},
       {"scalex", 1.0, -2.0, 2.0},
       {"scaleinfx", 1.0, -2.0, 2.0},
       {"scaley", 1.0, -2.0, 2.0},
       {"scaleinfy", 1.0, -2.0, 2.0},
       {"unity", 1.0, -2.0, 2.0},
       {"jacok", 0.25, -1.0, 1.0}});
  add("waves3",
      "(x + ½ scalex (1 + sin(sx_freq y)) sin(freqx y), y + ½ scaley (1 + sin(sy_freq x)) sin(freqy x)), z "
      "(Fractorium's)",
      k2D, kFixed, &waves3,
      {{"scalex", 0.05, -2.0, 2.0},
       {"scaley", 0.05, -2.0, 2.0},
       {"freqx", 7.0, -20.0, 20.0},
       {"freqy", 13.0, -20.0, 20.0},
       {"sx_freq", 0.0, -10.0, 10.0},
       {"sy_freq", 2.0, -10.0, 10.0}});
  add("waves4",
      "(x + h² scalex sin(freqx y), y + scaley sin(freqy x)), z; h = the fractional part (towards 0) of 43758.5453 "
      "sin(91.2228 k + 1 + 0.001 yfact y), k = ⌊freqx y/2π⌋, rounded to 0 or 1 with cont (Fractorium's)",
      k2D, kFixed, &waves4,
      {{"scalex", 0.05, -2.0, 2.0},
       {"scaley", 0.05, -2.0, 2.0},
       {"freqx", 7.0, -20.0, 20.0},
       {"freqy", 13.0, -20.0, 20.0},
       count("cont", 0.0, 0.0, 1.0),
       {"yfact", 0.1, -2.0, 2.0}});
  add("waves42", "waves4 with the bands k = ⌊freqx2 y⌋ (Fractorium's)", k2D, kFixed, &waves42,
      {{"scalex", 0.05, -2.0, 2.0},
       {"scaley", 0.05, -2.0, 2.0},
       {"freqx", 7.0, -20.0, 20.0},
       {"freqy", 13.0, -20.0, 20.0},
       count("cont", 0.0, 0.0, 1.0),
       {"yfact", 0.1, -2.0, 2.0},
       {"freqx2", 1.0, -10.0, 10.0}});
  add("xheart",
      "(u, v) where u > 0, else (u, −v), z; (u, v) = (4x, (6 + 2 ratio) y)/(r² + 4) turned by π/4 (1 + angle/2) "
      "(Fractorium's)",
      k2D, kFixed, &xheart, {{"angle", 0.0, -4.0, 4.0}, {"ratio", 0.0, -2.0, 2.0}});
  add("x", "√(r² + T(φ)²) (cos φ, sin φ), z; T = y's sum of shapes (hypergon, star, lituus, super; Fractorium's)", k2D,
      kFixed, &xShapes,
      {{"hypergon", 0.0, -3.0, 3.0},
       count("hypergon_n", 4.0, 3.0, 12.0),
       {"hypergon_r", 1.0, 0.0, 3.0},
       {"star", 0.0, -3.0, 3.0},
       count("star_n", 5.0, 3.0, 12.0),
       {"star_slope", 2.0, 0.0, 2.0},
       {"lituus", 0.0, -3.0, 3.0},
       {"lituus_a", 1.0, -3.0, 3.0},
       {"super", 0.0, -3.0, 3.0},
       {"super_m", 1.0, 0.0, 12.0},
       {"super_n1", 1.0, 0.1, 10.0},
       {"super_n2", 1.0, 0.0, 10.0},
       {"super_n3", 1.0, 0.0, 10.0}});
  add("z", "(r + T(φ)) (cos φ, sin φ), z; T = y's sum of shapes (hypergon, star, lituus, super; Fractorium's)", k2D,
      kFixed, &zShapes,
      {{"hypergon", 0.0, -3.0, 3.0},
       count("hypergon_n", 4.0, 3.0, 12.0),
       {"hypergon_r", 1.0, 0.0, 3.0},
       {"star", 0.0, -3.0, 3.0},
       count("star_n", 5.0, 3.0, 12.0),
       {"star_slope", 2.0, 0.0, 2.0},
       {"lituus", 0.0, -3.0, 3.0},
       {"lituus_a", 1.0, -3.0, 3.0},
       {"super", 0.0, -3.0, 3.0},
       {"super_m", 1.0, 0.0, 12.0},
       {"super_n1", 1.0, 0.1, 10.0},
       {"super_n2", 1.0, 0.0, 10.0},
       {"super_n3", 1.0, 0.0, 10.0}});
}

}  // namespace voxflame::core
