// Fractorium's other 2D variations, third part: cells and grids, crops, interference and the random
// waffle, wavesn and vignette (bwraps_rand … wavesn). Each is a kernel below and one row of the table
// at the end (see variations.h for the notation, variation_kernels.h and variations_2d_shared.h for
// what the files share). Fractorium writes z = 0 for most of these; here z is carried as w·z, as for
// every 2D variation.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/flame/variations_2d_shared.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// Fractorium's Rand(n) from a lane's uniform: a whole number in [0, n), or in [0, 2³²) when n is 0
// (Fractorium's generator then returns its whole 32-bit draw).
inline double laneWhole(std::uint32_t& state, double upper) {
  return std::floor(laneUniform(state) * (upper == 0.0 ? 4294967296.0 : upper));
}

// ---- cells -----------------------------------------------------------------------------------------

// Bubbles in a grid of cells: inside each cell's circle (its radius hashed from the cell) the point
// is magnified like bubble wrap and twisted, from inner_twist at the centre to outer_twist at the edge.
VOXFLAME_VARIATION_TARGETS void bwrapsRand(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cell = P[0], space = P[1], gain = P[2], innerTwist = P[3], outerTwist = P[4], symm = P[5], seed = P[6];
  const double g2 = gain * gain, invCell = 1.0 / fractoriumZeps(cell);
  const double halfCell = 0.5 * (cell / (1.0 + space * space));
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    if (cell != 0.0) {
      const double cx = (std::floor(x[i] * invCell) + 0.5) * cell, cy = (std::floor(y[i] * invCell) + 0.5) * cell;
      const double lx = x[i] - cx, ly = y[i] - cy;
      const double radius =
          halfCell * (symm == 0.0 ? hashShadertoy(cx, cy, seed) : hashShadertoy(cx * cx, cy * cy, seed));
      const double mb = g2 * radius;
      const double maxBubble = mb > 2.0 ? 1.0 : mb / (mb * mb * 0.25 + 1.0);
      const double r2 = radius * radius;
      if (!(lx * lx + ly * ly > r2)) {
        const double rFactor = radius / fractoriumZeps(maxBubble);
        const double lx2 = lx * g2, ly2 = ly * g2;
        const double r = rFactor / ((lx2 * lx2 + ly2 * ly2) * 0.25 + 1.0);
        const double lx3 = lx2 * r, ly3 = ly2 * r;
        const double t = (lx3 * lx3 + ly3 * ly3) / fractoriumZeps(r2);
        const double theta = innerTwist * (1.0 - t) + outerTwist * t;
        const double c = std::cos(theta), s = std::sin(theta);
        px = cx + c * lx3 + s * ly3;
        py = cy - s * lx3 + c * ly3;
      }
    }
    outX[i] += px * w;
    outY[i] += py * w;
    outZ[i] += w * z[i];
  }
}

// Hugo Elias' integer noise of a cell, in [0, 1]: Fractorium's DiscreteNoise2 with its int
// arithmetic wrapping around.
inline double discreteNoise2(std::int32_t x, std::int32_t y) {
  std::uint32_t k = static_cast<std::uint32_t>(wrapAdd(x, wrapMul(y, 57)));
  k = (k << 13) ^ k;
  const std::uint32_t v = k * (k * k * 15731u + 789221u) + 1376312589u;
  return static_cast<double>(v & 0x7fffffffu) * (1.0 / 2147483647.0);
}

// Cells of side 2·Sc, in some of which (noise below Dens1) a disc of noisy radius is shrunk towards
// the centre by K, or its edge pulled in (Reverse picks which of the two by Dens2). X and Y are read
// but not used, as in Fractorium.
VOXFLAME_VARIATION_TARGETS void circleLinear(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sc = fractoriumNonzero(P[0]), k = P[1], dens1 = P[2], dens2 = P[3], reverse = P[4];
  const double seed = fractoriumInteger(P[7], -2147483647.0, 2147483647.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t m = javaInt(std::floor(0.5 * x[i] / sc)), nn = javaInt(std::floor(0.5 * y[i] / sc));
    const double m21 = 2.0 * m + 1.0, n21 = 2.0 * nn + 1.0;
    double px = x[i] - m21 * sc, py = y[i] - n21 * sc;
    const double u = fractoriumZeps(std::hypot(px, py));
    const double v = (0.3 + 0.7 * discreteNoise2(wrapAdd(m, 10), wrapAdd(nn, 3))) * sc;
    const double z1 = discreteNoise2(javaInt(m + seed), nn);
    if (z1 < dens1 && u < v) {
      const bool plain = reverse > 0.0 ? z1 < dens1 * dens2 : z1 > dens1 * dens2;
      const double f = plain ? k : v / u * (1.0 - k) + k;
      px *= f;
      py *= f;
    }
    outX[i] += w * (px + m21 * sc);
    outY[i] += w * (py + n21 * sc);
    outZ[i] += w * z[i];
  }
}

// foci_p's map, (c1 eˣ − c2 e⁻ˣ/c1, sin y)/(…), with a fuzz of the result by fuzzyMode, blended in
// by fuzzyInterpolationMode.
VOXFLAME_VARIATION_TARGETS void dragonfire(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double c1 = P[0], c2 = P[1], mode = fractoriumClamp(P[2], 0.0, 7.0), radius = P[3];
  const double blendMode = fractoriumClamp(P[4], 0.0, 6.0), position = P[5], logScalar = P[6], scalar = P[7];
  double val = position;
  if (!(blendMode < 2.0)) {
    const double a = position * kPi;
    const double trig = blendMode < 3.0   ? std::cos(a)
                        : blendMode < 4.0 ? std::tan(a)
                        : blendMode < 5.0 ? std::sinh(a)
                                          : std::asinh(a);
    val = (1.0 - trig) * scalar;
  }
  const double oneMinusVal = 1.0 - val;
  for (std::size_t i = 0; i < n; ++i) {
    const double ex = std::exp(x[i]) * c1, enx = c2 / fractoriumZeps(ex);
    const double r = w / fractoriumZeps(ex + enx - std::cos(y[i]));
    const double fx = (ex - enx) * r, fy = std::sin(y[i]) * r;
    double px = fx, py = fy;
    if (!(mode < 1.0)) {
      const double fuzzX = std::cos(logScalar / fractoriumZeps(std::log(std::abs(fx))));
      const double fuzzY = std::cos(logScalar / fractoriumZeps(std::log(std::abs(fy))));
      const double dirX = (fuzzX < 0.0 ? -1.0 : 1.0) * radius, dirY = (fuzzY < 0.0 ? -1.0 : 1.0) * radius;
      double nx, ny;
      if (mode < 2.0) {
        nx = fx + fuzzX;
        ny = fy + fuzzY;
      } else if (mode < 3.0) {
        nx = fx * std::sin(fuzzX);
        ny = fy * std::sin(fuzzY);
      } else if (mode < 4.0) {
        nx = fx * std::exp(std::sin(fuzzX));
        ny = fy * std::exp(std::sin(fuzzY));
      } else if (mode < 5.0) {
        nx = fx + dirX;
        ny = fy + dirY;
      } else if (mode < 6.0) {
        nx = fx + std::exp(dirX);
        ny = fy + std::exp(dirY);
      } else {
        nx = fx + std::exp(std::sin(dirX));
        ny = fy + std::exp(std::cos(dirY));
      }
      if (blendMode < 1.0) {
        px = nx;
        py = ny;
      } else {
        px = fx * oneMinusVal + nx * val;
        py = fy * oneMinusVal + ny * val;
      }
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// One variation per quadrant: spherical (x, y > 0), loonie (x > 0 > y), susan about (x, −y) with its
// spin, space and twist (x < 0 < y), linear elsewhere. w, the weight, is the loonie's and susan's
// radius.
VOXFLAME_VARIATION_TARGETS void fourth(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double spin = fractoriumCyclic(P[0], 0.0, kTwoPi), space = P[1], twist = P[2], cx = P[3], cy = P[4];
  const double w2 = w * w;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    double px = w * x[i], py = w * y[i];
    if (x[i] > 0.0 && y[i] > 0.0) {
      const double r = std::sqrt(r2), k = w / r / fractoriumZeps(r);
      px = k * x[i];
      py = k * y[i];
    } else if (x[i] > 0.0 && y[i] < 0.0) {
      if (r2 < w2) {
        const double r = w * std::sqrt(w2 / r2 - 1.0);
        px = r * x[i];
        py = r * y[i];
      }
    } else if (x[i] < 0.0 && y[i] > 0.0) {
      const double sx = x[i] - cx, sy = y[i] + cy;
      double r = std::sqrt(sx * sx + sy * sy);
      if (r < w) {
        const double a = std::atan2(sy, sx) + spin + twist * (w - r);
        r *= w;
        px = r * std::cos(a) + cx;
        py = r * std::sin(a) - cy;
      } else {
        r = w * (1.0 + space / fractoriumZeps(r));
        px = r * sx + cx;
        py = r * sy - cy;
      }
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// gdoffs' helpers: the fractional part keeping the sign, a cosine oscillation folded into [0, 1),
// and the blend c·(b − a) + a.
inline double gdoffsClip(double a) {
  return a < 0.0 ? -std::fmod(std::abs(a), 1.0) : std::fmod(std::abs(a), 1.0);
}
inline double gdoffsOsc(double p, double a) {
  return gdoffsClip((-std::cos(p * a * kTwoPi) + 1.0) / 2.0);
}
inline double gdoffsFlip(double a, double b, double c) {
  return c * (b - a) + a;
}

// Each coordinate blended towards a cosine of itself and a cosine of its scaled fractional part, by
// amounts set by delta_x, delta_y. With square, y uses x's amount (Fractorium's).
VOXFLAME_VARIATION_TARGETS void gdoffs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double dx = fractoriumClamp(P[0], 0.0, 16.0) * 0.1, dy = fractoriumClamp(P[1], 0.0, 16.0) * 0.1;
  const double ax = (std::abs(P[2]) < 0.1 ? 0.1 : std::abs(P[2])) * 2.0;
  const double ay = (std::abs(P[3]) < 0.1 ? 0.1 : std::abs(P[3])) * 2.0;
  const double cx = P[4], cy = P[5], gamma = fractoriumInteger(P[6], 1.0, 6.0);
  const bool square = fractoriumInteger(P[7], 0.0, 1.0) != 0.0;
  const double b = gamma * 2.0 / std::max(ax, ay);
  const double oscX = gdoffsOsc(dx, 1.0), oscY = square ? oscX : gdoffsOsc(dy, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] + cx, py = y[i] + cy;
    const double gx = gdoffsFlip(gdoffsFlip(px, gdoffsOsc(px, 4.0), oscX), gdoffsOsc(gdoffsClip(b * px), 4.0), oscX);
    const double gy = gdoffsFlip(gdoffsFlip(py, gdoffsOsc(py, 4.0), oscY), gdoffsOsc(gdoffsClip(b * py), 4.0), oscY);
    outX[i] += w * gx;
    outY[i] += w * gy;
    outZ[i] += w * z[i];
  }
}

// Cells of side cellsize, in each of which the inscribed disc is twisted by twist·ln(d²/r²).
VOXFLAME_VARIATION_TARGETS void gnarly(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cell = P[0], twist = P[1];
  const double r2 = fractoriumZeps(0.25 * cell * cell);
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    if (cell != 0.0) {
      const double cx = (std::floor(px / cell) + 0.5) * cell, cy = (std::floor(py / cell) + 0.5) * cell;
      const double lx = px - cx, ly = py - cy, d2 = lx * lx + ly * ly;
      if (d2 <= r2) {
        const double theta = twist * std::log(d2 / r2);
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

// Apophysis' rounding (halves away from 0), in double so that no value overflows an integer.
inline double lrint(double v) {
  return std::trunc(v >= 0.0 ? v + 0.5 : v - 0.5);
}

// The point moved one unit along the square ring of the rounded grid it sits on, clockwise round
// the origin.
VOXFLAME_VARIATION_2D(gridout, {
  const double rx = lrint(x[i]), ry = lrint(y[i]);
  double px = x[i], py = y[i];
  if (ry <= 0.0) {
    if (rx > 0.0) {
      if (-ry >= rx)
        px += 1.0;
      else
        py += 1.0;
    } else {
      if (ry <= rx)
        px += 1.0;
      else
        py -= 1.0;
    }
  } else {
    if (rx > 0.0) {
      if (ry >= rx)
        px -= 1.0;
      else
        py += 1.0;
    } else {
      if (ry > -rx)
        px -= 1.0;
      else
        py -= 1.0;
    }
  }
  outX[i] += w * px;
  outY[i] += w * py;
})

// The point less the centre of its hexagon (hexagons of the given size, found by rounding cube
// coordinates), scaled back.
VOXFLAME_VARIATION_TARGETS void hexModulus(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double root3 = std::sqrt(3.0), halfRoot3 = root3 / 2.0;
  const double hsize = halfRoot3 / fractoriumZeps(P[0]), scale = w / halfRoot3;
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] * hsize, py = y[i] * hsize, third = py / 3.0;
    const double cx = root3 / 3.0 * px - third, cz = 2.0 * third, cy = -cx - cz;
    double rx = std::round(cx), ry = std::round(cy), rz = std::round(cz);
    const double dx = std::abs(rx - cx), dy = std::abs(ry - cy), dz = std::abs(rz - cz);
    if (dx > dy && dx > dz)
      rx = -ry - rz;
    else if (dy > dz)
      ry = -rx - rz;
    else
      rz = -rx - ry;
    outX[i] += (px - (root3 * rx + halfRoot3 * rz)) * scale;
    outY[i] += (py - 1.5 * rz) * scale;
    outZ[i] += w * z[i];
  }
}

// Keeps what lies inside a hexagon (scaled by scale_x, scale_y, the point moved by the centre) and
// sends the rest to (dropoff, dropoff): Fractorium's default is 1e10, here 1e6, the largest value a
// flame's parameter may have (the importer clamps Fractorium's to it). As an ordinary term a dropped point discards the
// terms summed before it too, as in Fractorium; a kept one adds to them.
VOXFLAME_VARIATION_TARGETS void hexcrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], cx = P[2], cy = P[3], dropoff = P[4];
  constexpr double kHx[6] = {-0.5, 0.5, 1.4142135623730950488, 0.5, -0.5, -1.4142135623730950488};
  constexpr double kHy[6] = {1.0606601717798212866,  1.0606601717798212866,  0.0,
                             -1.0606601717798212866, -1.0606601717798212866, 0.0};
  double hx[6], hy[6];
  for (int k = 0; k < 6; ++k) {
    hx[k] = kHx[k] * sx;
    hy[k] = kHy[k] * sy;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i] + cx, py = y[i] + cy;
    bool inside = false;
    for (int k = 0, j = 5; k < 6; j = k++) {  // crossings of a ray to −x (even–odd rule)
      if ((hy[k] <= py && py < hy[j]) || (hy[j] <= py && py < hy[k]))
        if (px < (hx[j] - hx[k]) * (py - hy[k]) / fractoriumZeps(hy[j] - hy[k]) + hx[k]) inside = !inside;
    }
    if (inside) {
      outX[i] += px * w;
      outY[i] += py * w;
    } else {
      outX[i] = dropoff;
      outY[i] = dropoff;
    }
    outZ[i] += w * z[i];
  }
}

// The inversion 1/p shifted by shift along x, inverted again (scaled by 1 − shift²) and shifted
// back: a hyperbolic translation of the unit disc.
VOXFLAME_VARIATION_TARGETS void hypershift(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shift = P[0], scale = 1.0 - shift * shift;
  for (std::size_t i = 0; i < n; ++i) {
    const double inv = 1.0 / fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
    const double px = inv * x[i] + shift, py = inv * y[i];
    const double r = w * scale / fractoriumZeps(px * px + py * py);
    outX[i] += r * px + shift;
    outY[i] += r * py;
    outZ[i] += w * z[i];
  }
}

// Interference2's wave shapes: |sin|^p, a triangle wave, a square wave (ε in place of Fractorium's
// original −1, as Fractorium has it).
inline double interferenceWave(double type, double a, double b, double c, double p, double v) {
  if (type == 1.0) return a * 2.0 * std::pow(std::abs(std::asin(std::cos(b * v + c - kPi / 2.0))) / kPi, p);
  if (type == 2.0) return a * std::pow(std::sin(b * v + c) < 0.0 ? kFractoriumEps : 1.0, p);
  return a * std::pow(std::abs(std::sin(b * v + c)), p);
}

VOXFLAME_VARIATION_TARGETS void interference2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a1 = P[0], b1 = P[1], c1 = P[2], p1 = P[3], t1 = fractoriumInteger(P[4], 0.0, 2.0);
  const double a2 = P[5], b2 = P[6], c2 = P[7], p2 = P[8], t2 = fractoriumInteger(P[9], 0.0, 2.0);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (interferenceWave(t1, a1, b1, c1, p1, x[i]) + interferenceWave(t2, a2, b2, c2, p2, x[i]));
    outY[i] += w * (interferenceWave(t1, a1, b1, c1, p1, y[i]) + interferenceWave(t2, a2, b2, c2, p2, y[i]));
    outZ[i] += w * z[i];
  }
}

// ---- random ones ---------------------------------------------------------------------------------

// Inside inner_radius of (posx, posy) the point (or the origin when inner_radius < 0); beyond it,
// at the fade distance d (in units of fade_radius), the point is kept with a chance that falls with
// d (1 − Ψ₁^(1/|power|) ≥ d; with fade_radius < 0 the other way round) and blurred by blur·(dΨ₂)²
// in the direction 2πΨ₃, else sent to the origin. Ψ₁…Ψ₃ are drawn for every point.
VOXFLAME_VARIATION_TARGETS void vignette(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double posX = P[0], posY = P[1], innerRadius = P[2], fadeRadius = fractoriumNonzero(P[3]);
  const double power = fractoriumNonzero(P[4]), blur = P[5];
  const double inner = std::abs(innerRadius), fade = std::abs(fadeRadius), powerHelper = 1.0 / std::abs(power);
  for (std::size_t i = 0; i < n; ++i) {
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]), u3 = laneUniform(rnd[i]);
    double px = x[i], py = y[i];
    double dist = std::sqrt((px - posX) * (px - posX) + (py - posY) * (py - posY));
    if (dist < inner) {
      if (innerRadius < 0.0) px = py = 0.0;
    } else {
      dist = (dist - inner) / fade;
      const double kept = 1.0 - std::pow(u1, powerHelper);
      const double blurR = blur * std::pow(dist * u2, 2.0), blurA = u3 * kTwoPi;
      const bool dropped = fadeRadius > 0.0 ? kept < dist : 1.0 - kept > dist;
      if (dropped) {
        px = py = 0.0;
      } else {
        px += blurR * std::cos(blurA);
        py += blurR * std::sin(blurA);
      }
    }
    outX[i] += px * w;
    outY[i] += py * w;
    outZ[i] += w * z[i];
  }
}

// A random point of a waffle: slices × slices cells, of which a point lands in one of the bars of
// width xthickness or ythickness (five cases, one by Ψ), turned by rotation; the input point is not
// used. Fractorium's draws in C++'s unspecified order are taken here left to right; its Rand(slices)
// is ⌊Ψ·|slices|⌋ (slices truncated; 0 meaning 2³², as Fractorium's generator has it).
VOXFLAME_VARIATION_TARGETS void waffle(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double slices = fractoriumNonzero(P[0]), xt = P[1], yt = P[2];
  const double whole = std::trunc(std::min(std::abs(slices), 4294967296.0));
  const double sinR = w * std::sin(P[3]), cosR = w * std::cos(P[3]);
  for (std::size_t i = 0; i < n; ++i) {
    const double pick = laneWhole(rnd[i], 5.0);
    double a, r;
    if (pick == 0.0) {
      const double a0 = laneWhole(rnd[i], whole), a1 = laneUniform(rnd[i]);
      const double r0 = laneWhole(rnd[i], whole), r1 = laneUniform(rnd[i]);
      a = (a0 + a1 * xt) / slices;
      r = (r0 + r1 * yt) / slices;
    } else if (pick == 1.0) {
      const double a0 = laneWhole(rnd[i], whole), a1 = laneUniform(rnd[i]);
      const double r0 = laneWhole(rnd[i], whole);
      a = (a0 + a1) / slices;
      r = (r0 + yt) / slices;
    } else if (pick == 2.0) {
      const double a0 = laneWhole(rnd[i], whole);
      const double r0 = laneWhole(rnd[i], whole), r1 = laneUniform(rnd[i]);
      a = (a0 + xt) / slices;
      r = (r0 + r1) / slices;
    } else if (pick == 3.0) {
      a = laneUniform(rnd[i]);
      const double r0 = laneWhole(rnd[i], whole), r1 = laneUniform(rnd[i]);
      r = (r0 + yt + r1 * (1.0 - yt)) / slices;
    } else {
      const double a0 = laneWhole(rnd[i], whole), a1 = laneUniform(rnd[i]);
      a = (a0 + xt + a1 * (1.0 - xt)) / slices;
      r = laneUniform(rnd[i]);
    }
    outX[i] += cosR * a + sinR * r;
    outY[i] += -sinR * a + cosR * r;
    outZ[i] += w * z[i];
  }
}

// A random power root of the point (julian-like: angle (φ + 2πk)/power, k = ⌊Ψ·|power|⌋, radius
// r^(1/power)), then waves: each coordinate moved by half a sine of the other, scaled by scale + |·|·inc.
// The weight enters twice, as in Fractorium; power 0 is taken as 2, as Fractorium does.
VOXFLAME_VARIATION_TARGETS void wavesn(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freqX = P[0], freqY = P[1], scaleX = P[2], scaleY = P[3], incX = P[4], incY = P[5];
  const double power = P[6] == 0.0 ? 2.0 : P[6];
  const double absN = std::trunc(std::min(std::abs(power), 4294967296.0)), cn = 1.0 / power / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = (std::atan2(y[i], x[i]) + kTwoPi * laneWhole(rnd[i], absN)) / power;
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], cn);
    const double xn = r * std::cos(angle), yn = r * std::sin(angle);
    const double sinY = std::sin(freqX * yn), sinX = std::sin(freqY * xn);
    outX[i] += w * (xn + 0.5 * (scaleX * sinY + std::abs(xn) * incX * sinY));
    outY[i] += w * (yn + 0.5 * (scaleY * sinX + std::abs(yn) * incY * sinX));
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractorium2DVariationsC(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  add("bwraps_rand",
      "bubble wrap in cells of side cellsize: within radius R of a cell's centre C, C + T(ℓ' ) where ℓ = p − C, ℓ' "
      "= g²ℓ·(R/m)/(g⁴|ℓ|²/4 + 1), T a turn by inner_twist (1 − t) + outer_twist t, t = |ℓ'|²/R², g = gain, m = "
      "g²R/(g⁴R²/4 + 1) (1 when g²R > 2); R = cellsize/(2(1 + space²)) times a hash of C (of C² with symm) and "
      "seed; p elsewhere; z",
      k2D, kFixed, &bwrapsRand,
      {{"cellsize", 1.0, 0.0, 4.0},
       {"space", 0.0, -2.0, 2.0},
       {"gain", 2.0, -4.0, 4.0},
       {"inner_twist", 0.0, -6.0, 6.0},
       {"outer_twist", 0.0, -6.0, 6.0},
       {"symm", 0.0, 0.0, 1.0},
       {"seed", 1.0, 0.0, 100.0}});
  add("CircleLinear",
      "cells of side 2 Sc centred at c: where the cell's noise ν < Dens1 and |p − c| < ρ (ρ = Sc (0.3 + 0.7 "
      "noise)), c + (p − c) K, or c + (p − c)(ρ/|p − c| (1 − K) + K) (which by ν < Dens1 Dens2, the other way "
      "round unless Reverse > 0); else p; z (Hugo Elias' noise; X and Y unused, as in Fractorium)",
      k2D, kFixed, &circleLinear,
      {{"Sc", 1.0, 0.1, 4.0},
       {"K", 0.5, -2.0, 2.0},
       {"Dens1", 0.5, 0.0, 1.0},
       {"Dens2", 0.5, 0.0, 1.0},
       {"Reverse", 1.0, -1.0, 1.0},
       {"X", 10.0, 0.0, 20.0},
       {"Y", 10.0, 0.0, 20.0},
       count("Seed", 0.0, 0.0, 100.0)});
  add("dragonfire",
      "F = (c1 eˣ − c2/(c1 eˣ), sin y)/(c1 eˣ + c2/(c1 eˣ) − cos y), fuzzed by fuzzyMode (≥ 1) with u = "
      "cos(logScalarFuzzy/ln|F|) per coordinate: F + u, F sin u, F e^(sin u), F ± fuzzyRadius, F + e^(±r), F + "
      "(e^(sin ±r), e^(cos ±r)); blended in by v (fuzzyInterpolationMode ≥ 1): (1 − v) F + v F', v = "
      "fuzzyInterpolationPosition, or (1 − trig(π pos)) adjustedFuzzyScalar for modes 2 (cos), 3 (tan), 4 (sinh), "
      "5+ (asinh); z",
      k2D, kFixed, &dragonfire,
      {{"c1", 0.5, -2.0, 2.0},
       {"c2", 0.25, -2.0, 2.0},
       {"fuzzyMode", 0.0, 0.0, 7.0},
       {"fuzzyRadius", 1.0, -2.0, 2.0},
       {"fuzzyInterpolationMode", 0.0, 0.0, 6.0},
       {"fuzzyInterpolationPosition", 1.0, -2.0, 2.0},
       {"logScalarFuzzy", kTwoPi, -10.0, 10.0},
       {"adjustedFuzzyScalar", 0.5, -2.0, 2.0}});
  add("fourth",
      "by quadrant: x, y > 0 spherical p/r²; x > 0 > y loonie √(w²/r² − 1) p where r < w, else p; x < 0 < y susan "
      "about c = (x₀, −y₀): q = p − c, c + w|q|(cos a, sin a), a = ∠q + spin + twist (w − |q|) where |q| < w, else "
      "c + (1 + space/|q|) q; elsewhere p; z (w the weight, x₀, y₀ the parameters x, y)",
      k2D, kFixed, &fourth,
      {{"spin", kPi, 0.0, kTwoPi},
       {"space", 0.0, -2.0, 2.0},
       {"twist", 0.0, -2.0, 2.0},
       {"x", 0.0, -2.0, 2.0},
       {"y", 0.0, -2.0, 2.0}});
  add("gdoffs",
      "per coordinate v' = v + centre: L(L(v', O(v'), k), O(clip(b v')), k); O(t) = clip((1 − cos 8πt)/2), clip "
      "the signed fractional part, L(a, c, k) = a + k(c − a), k = clip((1 − cos 0.2π delta)/2), b = 2 gamma / "
      "max(2|area_x|, 2|area_y|) (|area| at least 0.1); with square y uses delta_x; z",
      k2D, kFixed, &gdoffs,
      {{"delta_x", 0.0, 0.0, 16.0},
       {"delta_y", 0.0, 0.0, 16.0},
       {"area_x", 2.0, 0.0, 4.0},
       {"area_y", 2.0, 0.0, 4.0},
       {"center_x", 0.0, -2.0, 2.0},
       {"center_y", 0.0, -2.0, 2.0},
       count("gamma", 1.0, 1.0, 6.0),
       count("square", 0.0, 0.0, 1.0)});
  add("gnarly",
      "cells of side cellsize centred at C: within the inscribed disc, C + ℓ turned by −twist ln(|ℓ|²/R²), ℓ = p − "
      "C, R = cellsize/2; p elsewhere; z",
      k2D, kFixed, &gnarly, {{"cellsize", 1.0, 0.0, 4.0}, {"twist", 1.0, -4.0, 4.0}});
  add("gridout",
      "p moved by one unit along the square ring through round(p) (halves away from 0): right, up, left or down by "
      "its side; z",
      k2D, kFixed, &gridout);
  add("hex_modulus",
      "(p − h)/(√3/2) where h is the centre of p's hexagon, the hexagons of size size (cube coordinates rounded); "
      "p scaled by √3/(2 size) first; z",
      k2D, kFixed, &hexModulus, {{"size", 1.0, 0.1, 4.0}});
  add("hexcrop",
      "p + centre inside the hexagon with corners (±½, ±1.0607), (±√2, 0) scaled by scale_x, scale_y; elsewhere "
      "(dropoff, dropoff) in place of the sum so far (Fractorium's); z",
      k2D, kFixed, &hexcrop,
      {{"scale_x", 1.0, 0.0, 4.0},
       {"scale_y", 1.0, 0.0, 4.0},
       {"center_x", 0.0, -2.0, 2.0},
       {"center_y", 0.0, -2.0, 2.0},
       {"dropoff", 1e6, 0.0, 1e6}});
  catalogue.back().readsSum = true;  // outside the hexagon it overwrites the sum so far
  add("hypershift",
      "q = p/r² + (shift, 0): (1 − shift²) q/|q|² + (shift, 0), z; as an ordinary term it replaces the sum so far "
      "(Fractorium's flam3-compatible behaviour)",
      k2D, kFixed, &hypershift, {{"shift", 0.01, -1.0, 1.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("interference2",
      "(f₁(x) + f₂(x), f₁(y) + f₂(y)), z; f_k(v) by type t_k: 0 a|sin(bv + c)|^p, 1 2a|asin(cos(bv + c − "
      "π/2))/π|^p, 2 a (ε where sin(bv + c) < 0, else 1)^p",
      k2D, kFixed, &interference2,
      {{"a1", 1.0, -2.0, 2.0},
       {"b1", 1.0, -4.0, 4.0},
       {"c1", 0.0, -kPi, kPi},
       {"p1", 1.0, 0.0, 4.0},
       count("t1", 0.0, 0.0, 2.0),
       {"a2", 1.0, -2.0, 2.0},
       {"b2", 1.0, -4.0, 4.0},
       {"c2", 0.0, -kPi, kPi},
       {"p2", 1.0, 0.0, 4.0},
       count("t2", 0.0, 0.0, 2.0)});
  add("vignette",
      "p within |inner_radius| of (posx, posy) ((0, 0) when inner_radius < 0); beyond, d = (distance − "
      "|inner_radius|)/|fade_radius|: p + blur (dΨ₂)² (cos 2πΨ₃, sin 2πΨ₃) when 1 − Ψ₁^(1/|power|) ≥ d (for "
      "fade_radius < 0: Ψ₁^(1/|power|) ≤ d), else (0, 0); z",
      k2D, kRandom, &vignette,
      {{"posx", 0.0, -2.0, 2.0},
       {"posy", 0.0, -2.0, 2.0},
       {"inner_radius", 0.5, -2.0, 2.0},
       {"fade_radius", 0.5, -2.0, 2.0},
       {"power", 4.0, 0.1, 10.0},
       {"blur", 1.0, 0.0, 4.0}});
  add("waffle",
      "(a cos ρ + r sin ρ, r cos ρ − a sin ρ), ρ = rotation, (a, r) a random point of the waffle's bars: cells of "
      "1/slices, bars xthickness and ythickness wide (one of five cases by Ψ); the point not used; z",
      k2D, kRandom, &waffle,
      {{"slices", 6.0, 1.0, 20.0},
       {"xthickness", 0.5, 0.0, 1.0},
       {"ythickness", 0.5, 0.0, 1.0},
       {"rotation", 0.0, -kPi, kPi}});
  add("wavesn",
      "q = w r^(1/power) (cos a, sin a), a = (φ + 2π⌊Ψ|power|⌋)/power; q + ½ (scalex + |q_x| incx) sin(freqx q_y), "
      "likewise y with freqy q_x (the weight w enters twice, as in Fractorium); z",
      k2D, kRandom, &wavesn,
      {{"freqx", 2.0, -10.0, 10.0},
       {"freqy", 2.0, -10.0, 10.0},
       {"scalex", 1.0, -2.0, 2.0},
       {"scaley", 1.0, -2.0, 2.0},
       {"incx", 0.0, -2.0, 2.0},
       {"incy", 0.0, -2.0, 2.0},
       {"power", 1.0, -6.0, 6.0}});
}

}  // namespace voxflame::core
