// The rest of flam3's variations (flam3 3.1's variations.c, in flam3's order): x and y mapped, z carried through.
// Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

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
  // JWildfire's shears (dark-beam's, to match the splits.dll plugin): each half also slides along the
  // axis it is split from. 0 by default, which is flam3's splits.
  const double lshear = P[2], rshear = P[3], ushear = P[4], dshear = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * ((x[i] >= 0.0 ? x[i] + sx : x[i] - sx) + (y[i] >= 0.0 ? ushear : -dshear));
    outY[i] += w * ((y[i] >= 0.0 ? y[i] + sy : y[i] - sy) + (x[i] >= 0.0 ? rshear : -lshear));
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
// transform applies it first, as a pre_ term that adds; see flame/variations.h).
VOXFLAME_VARIATION_2D(preBlur, {
  const double g = w * laneGauss(rnd[i]);
  const double a = kTwoPi * laneUniform(rnd[i]);
  outX[i] += g * std::cos(a);
  outY[i] += g * std::sin(a);
})

}  // namespace

void variation_kernels::addFlam3Variations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

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
  add("splits",
      "(x ± x₀ + (y ≥ 0 ? ushear : −dshear), y ± y₀ + (x ≥ 0 ? rshear : −lshear), z): each half moved away from the "
      "axis (x₀, y₀ the parameters x, y) and slid along it by JWildfire's shears",
      k2D, kFixed, &splits,
      {{"x", 0.0, -1.0, 1.0},
       {"y", 0.0, -1.0, 1.0},
       {"lshear", 0.0, -1.0, 1.0},
       {"rshear", 0.0, -1.0, 1.0},
       {"ushear", 0.0, -1.0, 1.0},
       {"dshear", 0.0, -1.0, 1.0}});
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
}

}  // namespace voxflame::core
