// JWildfire, Apophysis and Fractorium plugins that real flame files use.
// Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/noise.h"
#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// ---- JWildfire / Apophysis / Fractorium plugins (issue 25: what real flame files use) -------------

// Java's (int) floor(v), which saturates, as a double.
inline double javaFloorToInt(double v) {
  const double f = std::floor(v);
  if (!(f == f)) return 0.0;
  return std::clamp(f, -2147483648.0, 2147483647.0);
}

// slobo777's crackle (Apophysis plugin, JWildfire's CrackleFunc): a Voronoi cell pattern. Each
// point is a fresh random one on a blurred unit disc, pulled towards the centre of its cell
// (crackleStep, noise.h). The plugin caches the centres near the origin, which changes nothing but
// speed, so they are worked out here each time.
VOXFLAME_VARIATION_TARGETS void crackle(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = P[0], power = P[1], distort = P[2], scale = P[3], slice = P[4];
  for (std::size_t i = 0; i < n; ++i) {
    outZ[i] += w * z[i];
    if (cellsize == 0.0) continue;  // the plugin's guard: no cells, nothing drawn
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]), c = laneUniform(rnd[i]);
    const double blurred = (a + b) / 2.0 + (c - 0.5) / 4.0;
    const double theta = kTwoPi * laneUniform(rnd[i]);
    const CrackleStep step =
        crackleStep(blurred * std::sin(theta), blurred * std::cos(theta), cellsize / 2.0, distort, slice, power, scale);
    outX[i] += w * step.x;
    outY[i] += w * step.y;
  }
}

// Zy0rg's post_smartcrop (Fractorium's, which the corpus's flames come from; JWildfire's lacks the
// rotation): keeps the point inside a rounded polygon of `power` sides and radius `radius` (a
// sector of power·π when |power| < 2) and moves what lies outside back onto its edge, or beyond it
// by scatter and offset (cropmode 1), to the origin (0), keeps the radius and turns it (−1), or
// puts the last point it let through there instead, with that point's colour (2). A negative
// radius or power keeps the outside instead. Fractorium's `static` picks what it reads and what it
// returns (compared as the real numbers they are, as Fractorium does): the point it maps p (static
// > 1, the usual post_ use) or the transform's point t after its affine map (≤ 1) is the one
// cropped, q; a kept q returns w q (static > 0; static 3 keeps and returns w t) or p + w q (≤ 0); a
// cropped one returns its new place (static > 1 or −1) or p plus it (else). Cropmode 0 with static
// 0 or 1 leaves Fractorium's output as the variation before it left it; p stands in for that here.
// The last point let through is each lane's own memory (Fractorium keeps it per iterating thread),
// 0 and colour 0 at first.
constexpr std::size_t kSmartcropState = 4;  // x, y, z, colour of the last point let through

VOXFLAME_VARIATION_TARGETS void smartcrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[0], radius = P[1], roundstr = P[2], roundwidth = P[3], distortion = P[4];
  const double edge = P[5], scatter = P[6], offset = P[7], rotation = P[8];
  const double cropmode = P[9], staticMode = P[10];
  const bool keepInside = (power > 0.0) == (radius > 0.0);
  const double workRadius = std::abs(radius);
  double workPower = power == 0.0 ? kFractoriumEps : std::abs(power);
  const bool radial = workPower < 2.0;
  if (radial) workPower *= kPi;
  const double alpha = kTwoPi / workPower;
  const double halfSin = std::sin(alpha / 2.0);
  const double roundCoeff = roundstr / (halfSin == 0.0 ? kFractoriumEps : halfSin) / workPower * 2.0;
  const double turn = rotation * alpha;
  const bool readsPoint = staticMode > 1.0;                          // else the transform's point
  const bool cropReplaces = staticMode > 1.0 || staticMode == -1.0;  // a cropped point: its place alone
  const bool keepReplaces = staticMode > 0.0;                        // a kept point: w q alone
  const bool keepsTransformPoint = staticMode == 3.0;
  const double* __restrict tx = in.tx;
  const double* __restrict ty = in.ty;
  const double* __restrict tz = in.tz;
  for (std::size_t i = 0; i < n; ++i) {
    // The lane's memory; a single evaluation (no game) starts from Fractorium's zeros.
    double scratch[kSmartcropState] = {0.0, 0.0, 0.0, 0.0};
    double* memory = in.state ? in.state + kSmartcropState * (in.lanes ? in.lanes[i] : i) : scratch;
    const double qx = readsPoint ? x[i] : tx[i], qy = readsPoint ? y[i] : ty[i], qz = readsPoint ? z[i] : tz[i];
    const double angle = std::atan2(qy, qx);
    const double rad = std::sqrt(qx * qx + qy * qy);
    // The plugin draws only what a branch uses; drawing all of them, in its order, gives the same
    // numbers to the branch taken.
    const double a = laneUniform(rnd[i]), b = laneUniform(rnd[i]), c = laneUniform(rnd[i]);
    bool cropped = false, toMemory = false, toOrigin = false;
    double px = 0.0, py = 0.0;  // a cropped point's new place (w · ...)
    if (radial) {
      const double jitter = edge * (a - 0.5);
      double sector = angle / kTwoPi + 1.0 + jitter;
      sector = (sector - std::trunc(sector)) * kTwoPi;
      if ((sector > workPower) == keepInside) {
        cropped = true;
        if (cropmode == 2.0) {
          toMemory = true;
        } else {
          const double spread = (c * scatter + offset + jitter) * kPi;
          const double turned = std::trunc(b * 2.0) > 0.0 ? workPower + spread : -spread;
          px = w * rad * std::cos(turned);
          py = w * rad * std::sin(turned);
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
        cropped = true;
        if (cropmode == 2.0) {
          toMemory = true;
        } else if (cropmode == 0.0) {
          toOrigin = true;
        } else {
          const double r = cropmode == -1.0 ? rad : reach + coeff * ((edge != 0.0 ? b : a) * scatter + offset);
          px = w * r * std::cos(angle + turn);
          py = w * r * std::sin(angle + turn);
        }
      }
    }
    double rx, ry, rz;
    if (!cropped) {
      memory[0] = w * (keepsTransformPoint ? tx[i] : qx);
      memory[1] = w * (keepsTransformPoint ? ty[i] : qy);
      memory[2] = w * (keepsTransformPoint ? tz[i] : qz);
      if (cropmode == 2.0) memory[3] = colour[i];
      rx = memory[0];
      ry = memory[1];
      rz = memory[2];
      if (!keepReplaces) {
        rx += x[i];
        ry += y[i];
        rz += z[i];
      }
    } else if (toMemory) {
      rx = memory[0];
      ry = memory[1];
      rz = memory[2];
      colour[i] = memory[3];
      if (!cropReplaces) {
        rx += x[i];
        ry += y[i];
        rz += z[i];
      }
    } else if (toOrigin) {
      rx = cropReplaces ? 0.0 : x[i];
      ry = cropReplaces ? 0.0 : y[i];
      rz = cropReplaces ? 0.0 : z[i];
    } else {
      rx = px;
      ry = py;
      rz = w * qz;
      if (!cropReplaces) {
        rx += x[i];
        ry += y[i];
        rz += z[i];
      }
    }
    outX[i] += rx;
    outY[i] += ry;
    outZ[i] += rz;
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

}  // namespace

void variation_kernels::addPluginVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

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
      "keeps the outside; cropmode 2: the last point let through, and its colour index; the values are w times "
      "these; q = p (static > 1) or t is what is cropped; a kept q gives w q (static > 0; w t for static 3) or "
      "p + w q (≤ 0), a cropped one its new place (static > 1 or −1) or p plus it (Zy0rg's post_smartcrop as "
      "Fractorium has it)",
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
  // cropmode 2 sets the colour index to the last kept point's, which each lane remembers.
  catalogue.back().directColour = true;
  catalogue.back().laneState = kSmartcropState;
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
}

}  // namespace voxflame::core
