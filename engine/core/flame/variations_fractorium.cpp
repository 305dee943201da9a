// Fractorium's own variations and plugins it carries: mirrors, shapes, waves, powers, blurs that grow with the
// distance, cells and polygons. Each variation is a kernel below and one row of the table at the end (see variations.h
// for the notation and variation_kernels.h for what the files share).
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

// ---- mirrors and symmetries ----------------------------------------------------------------

// Fractorium's mirror_x/y/z: one coordinate's absolute value, negated half the time (Ψ < ½); the
// weight is not applied (Fractorium ignores it). Fractorium meant them as pre_/post_ terms; as an
// ordinary term Fractorium also discards the terms summed before it, and so does the chaos game
// here (VariationInfo::replaces).
VOXFLAME_VARIATION_TARGETS void mirrorX(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double flip = laneUniform(rnd[i]) < 0.5 ? -1.0 : 1.0;
    outX[i] += flip * std::abs(x[i]);
    outY[i] += y[i];
    outZ[i] += z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void mirrorY(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double flip = laneUniform(rnd[i]) < 0.5 ? -1.0 : 1.0;
    outX[i] += x[i];
    outY[i] += flip * std::abs(y[i]);
    outZ[i] += z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void mirrorZ(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double flip = laneUniform(rnd[i]) < 0.5 ? -1.0 : 1.0;
    outX[i] += x[i];
    outY[i] += y[i];
    outZ[i] += flip * std::abs(z[i]);
  }
}

// JWildfire's post_axis_symmetry_wf: the point, kept on its side of a plane through the centre or
// mirrored across it at random, moved half the weight away from it, then turned by ±rotation
// degrees about the centre. The weight is the distance, not a factor: the result is the point itself.
// Its axis-z branch turns about (centre_x, centre_y) in the x–z plane, as JWildfire's does. The
// colour index moves by the axis' first colour shift on the near side, its second on the mirrored side
// (mod 1, negative below 0 as JWildfire's fmod).
VOXFLAME_VARIATION_TARGETS void axisSymmetryWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double axis = std::clamp(std::round(P[0]), 0.0, 2.0);
  const double cx = P[1], cy = P[2], cz = P[3];
  const double half = P[4] * kTwoPi / 180.0 / 2.0;
  const bool rotate = std::abs(half) > kJwfEpsilon;
  const double s = std::sin(half), c = std::cos(half);
  const double shift = w / 2.0;
  const bool active = std::abs(w) > kJwfEpsilon;
  const int axisIndex = static_cast<int>(axis);
  const double nearShift = P[5 + axisIndex], farShift = P[8 + axisIndex];
  for (std::size_t i = 0; i < n; ++i) {
    const bool near = laneUniform(rnd[i]) < 0.5;
    double px = x[i], py = y[i], pz = z[i];
    if (active) {
      colour[i] = std::fmod(colour[i] + (near ? nearShift : farShift), 1.0);
      const double sign = near ? 1.0 : -1.0;  // the rotation turns the two sides opposite ways
      if (axis == 0.0) {
        const double d = px - cx;
        px = near ? cx + d + shift : cx - d - shift;
        if (rotate) {
          const double dx = px - cx, dy = py - cy;
          px = cx + dx * c + sign * dy * s;
          py = cy + dy * c - sign * dx * s;
        }
      } else if (axis == 1.0) {
        const double d = py - cy;
        py = near ? cy + d + shift : cy - d - shift;
        if (rotate) {
          const double dx = px - cx, dy = py - cy;
          px = cx + dx * c + sign * dy * s;
          py = cy + dy * c - sign * dx * s;
        }
      } else {
        const double d = pz - cz;
        pz = near ? cz + d + shift : cz - d - shift;
        if (rotate) {
          const double dx = px - cx, dz = pz - cz;
          px = cx + dx * c + sign * dz * s;
          pz = cy + dz * c - sign * dx * s;
        }
      }
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += pz;
  }
}

// ---- shapes ----------------------------------------------------------------------------------

// octagon (FracFx's Apophysis plugin, as JWildfire ports it): three terms summed. JWildfire takes
// √z, which is NaN below the plane z = 0; here √z is 0 there, so 3D points stay finite.
VOXFLAME_VARIATION_TARGETS void octagon(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double offX = P[0], offY = P[1], offZ = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double x2 = x[i] * x[i], y2 = y[i] * y[i], z2 = z[i] * z[i];
    const double r = w / (x2 * x2 + z2 + y2 * y2 + z2 + kJwfEpsilon);
    const double near = r < 2.0 ? r : w;
    double px = near * x[i], py = near * y[i], pz = near * z[i];
    const double rootZ = std::sqrt(std::max(z[i], 0.0));
    const double t = w / (std::abs(x[i]) + rootZ + std::abs(y[i]) + rootZ + kJwfEpsilon);
    const double far = r >= 0.0 ? t : w;
    px += far * x[i];
    py += far * y[i];
    pz += far * z[i];
    px += w * (x[i] >= 0.0 ? x[i] + offX : x[i] - offX);
    py += w * (y[i] >= 0.0 ? y[i] + offY : y[i] - offY);
    pz += w * (z[i] >= 0.0 ? z[i] + offZ : z[i] - offZ);
    outX[i] += px;
    outY[i] += py;
    outZ[i] += pz;
  }
}

// Fractorium's bcircle: inside the unit circle (after scaling) the scaled point; outside, a ring
// 0.2·|borderwidth| wide just beyond it, or the origin when borderwidth is 0.
VOXFLAME_VARIATION_TARGETS void bcircle(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = P[0], border = std::abs(P[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double sx = x[i] * scale, sy = y[i] * scale;
    const double r = std::sqrt(sx * sx + sy * sy);
    double px = 0.0, py = 0.0;
    if (r <= 1.0) {
      px = sx;
      py = sy;
    } else if (border != 0.0) {
      const double a = std::atan2(sy, sx), radius = 0.2 * border * u + 1.0;
      px = radius * std::cos(a);
      py = radius * std::sin(a);
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// ---- waves and discs -------------------------------------------------------------------------

// waves23 (Tatyana Zabanova's, as JWildfire has it): a sawtooth of each coordinate added to the
// other, folded at ½.
VOXFLAME_VARIATION_TARGETS void waves23(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], freqX = P[2], freqY = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double mx = y[i] * freqX / kTwoPi, my = x[i] * freqY / kTwoPi;
    double fx = mx - std::floor(mx), fy = my - std::floor(my);
    if (fx > 0.5) fx = 0.5 - fx;
    if (fy > 0.5) fy = 0.5 - fy;
    outX[i] += w * (x[i] + fx * scaleX);
    outY[i] += w * (y[i] + fy * scaleY);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void wdisc(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    double a = kPi / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1.0);
    const double r = std::atan2(y[i], x[i]) / kPi;
    if (r > 0.0) a = kPi - a;
    outX[i] += w * r * std::cos(a);
    outY[i] += w * r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// ---- powers and depth ------------------------------------------------------------------------

// Fractorium's pow_block: r^(numerator / (denominator · correctn / correctd)) with the angle
// divided by the denominator, plus one of its roots at random.
VOXFLAME_VARIATION_TARGETS void powBlock(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double numerator = P[0], denominator = P[1], root = P[2], correctN = P[3], correctD = P[4];
  const double power = numerator / fractoriumZeps(denominator * correctN * (1.0 / correctD));
  const double divisor = fractoriumZeps(denominator);
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::floor(laneUniform(rnd[i]) * denominator);
    const double r = std::pow(x[i] * x[i] + y[i] * y[i], power * 0.5) * w;
    const double a = (std::atan2(y[i], x[i]) / divisor + root * kTwoPi * k / divisor) * numerator;
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

// Fractorium's depth: the point scaled by |z|^power, plus the transform's affine point t (in.tx),
// which for ordinary and pre_ terms is the point itself; for post_depth, the point the transform's
// variations summed from.
VOXFLAME_VARIATION_TARGETS void depth(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double* __restrict tx = in.tx;
  const double* __restrict ty = in.ty;
  const double* __restrict tz = in.tz;
  const double power = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    double coeff = std::abs(z[i]);
    if (coeff != 0.0 && power != 1.0) coeff = std::exp(std::log(coeff) * power);
    outX[i] += w * (tx[i] + x[i] * coeff);
    outY[i] += w * (ty[i] + y[i] * coeff);
    outZ[i] += w * (tz[i] + z[i] * coeff);
  }
}

// poincare3D (Zueuk's, as JWildfire has it): the Möbius map of 3D space that moves the unit
// ball's centre to c = r (−cos a' cos b', sin a' cos b', −sin b'), a' = aπ/2, b' = bπ/2.
VOXFLAME_VARIATION_TARGETS void poincare3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], a = P[1] * kPi / 2.0, b = P[2] * kPi / 2.0;
  const double cx = -radius * std::cos(a) * std::cos(b), cy = radius * std::sin(a) * std::cos(b);
  const double cz = -radius * std::sin(b);
  const double c2 = cx * cx + cy * cy + cz * cz;
  const double sx = cx * cx - cy * cy - cz * cz + 1.0, sy = cy * cy - cx * cx - cz * cz + 1.0;
  const double sz = cz * cz - cy * cy - cx * cx + 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double kx = 2.0 * cx * x[i], ky = 2.0 * cy * y[i], kz = 2.0 * cz * z[i];
    const double d = w / (c2 * r2 - kx - ky - kz + 1.0);
    outX[i] += d * (x[i] * sx + cx * (ky + kz - r2 - 1.0));
    outY[i] += d * (y[i] * sy + cy * (kx + kz - r2 - 1.0));
    outZ[i] += d * (z[i] * sz + cz * (ky + kx - r2 - 1.0));
  }
}

// ---- blurs that grow with the distance from a centre ------------------------------------------

// Fractorium's falloff: the point blurred by D = max(0, (|p − (x0, y0, z0)| (or 1 − that, at
// least 0, with invert) − mindist) · 0.04 scatter), the blur's shape by type. Its box blur adds
// the mul · a^boxpow · D / scale term without the weight, as Fractorium does.
VOXFLAME_VARIATION_TARGETS void falloff(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scatter = 0.04 * std::max(P[0], std::numeric_limits<double>::epsilon());
  const double minDist = std::max(P[1], 0.0);
  const double mulX = std::clamp(P[2], 0.0, 1.0), mulY = std::clamp(P[3], 0.0, 1.0), mulZ = std::clamp(P[4], 0.0, 1.0);
  const double x0 = P[5], y0 = P[6], z0 = P[7];
  const bool invert = fractoriumInteger(P[8], 0.0, 1.0) != 0.0;
  const double type = fractoriumInteger(P[9], 0.0, 2.0);
  const double boxPow = fractoriumInteger(P[10], 2.0, 32.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = laneUniform(rnd[i]) - 0.5, ay = laneUniform(rnd[i]) - 0.5, az = laneUniform(rnd[i]) - 0.5;
    const double dx = x[i] - x0, dy = y[i] - y0, dz = z[i] - z0;
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double rs = std::max(((invert ? std::max(1.0 - r, 0.0) : std::max(r, 0.0)) - minDist) * scatter, 0.0);
    if (type == 0.0) {
      outX[i] += w * (x[i] + mulX * ax * rs);
      outY[i] += w * (y[i] + mulY * ay * rs);
      outZ[i] += w * (z[i] + mulZ * az * rs);
    } else if (type == 1.0) {
      const double radius = r + mulX * ax * rs;
      const double phi = std::atan2(y[i], x[i]) + mulY * ay * rs;
      const double sigma = std::asin(r == 0.0 ? 0.0 : z[i] / r) + mulZ * az * rs;
      outX[i] += radius * std::cos(sigma) * w * std::cos(phi);
      outY[i] += radius * std::cos(sigma) * w * std::sin(phi);
      outZ[i] += radius * std::sin(sigma) * w;
    } else {
      const double scale = std::clamp(rs, 0.0, 0.9) + 0.1, denom = 1.0 / scale;
      const auto box = [&](double v, double a, double mul) {
        const double target = std::floor(v * denom) + scale * a;
        return w * (v + (target - v) * mul * rs) + mul * std::pow(a, boxPow) * rs * denom;
      };
      outX[i] += box(x[i], ax, mulX);
      outY[i] += box(y[i], ay, mulY);
      outZ[i] += box(z[i], az, mulZ);
    }
  }
}

// Fractorium's falloff3: like falloff, with the distance measured round (blur_shape 0) or square
// (1), and a Gaussian (0), radial (1) or logarithmic (2, 3) blur; its colour shift (mul_c) moves the
// colour index by the fourth draw times the blur, mod 1, as Fractorium's does (a direct-colour variation).
VOXFLAME_VARIATION_TARGETS void falloff3(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double type = fractoriumInteger(P[0], 0.0, 3.0);
  const bool square = fractoriumInteger(P[1], 0.0, 1.0) != 0.0;
  const double rMax = 0.04 * std::max(P[2], std::numeric_limits<double>::epsilon());
  const double minDist = std::max(P[3], 0.0);
  const bool invert = fractoriumInteger(P[4], 0.0, 1.0) != 0.0;
  const double mulX = std::clamp(P[5], 0.0, 1.0), mulY = std::clamp(P[6], 0.0, 1.0), mulZ = std::clamp(P[7], 0.0, 1.0);
  const double mulC = std::clamp(P[8], 0.0, 1.0);
  const double cx = P[9], cy = P[10], cz = P[11], alpha = P[12];
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = laneUniform(rnd[i]) - 0.5, ry = laneUniform(rnd[i]) - 0.5, rz = laneUniform(rnd[i]) - 0.5;
    const double rc = laneUniform(rnd[i]) - 0.5;
    const double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
    const double radius =
        square ? std::max(std::abs(dx), std::max(std::abs(dy), std::abs(dz))) : std::sqrt(dx * dx + dy * dy + dz * dz);
    const double dist =
        std::max(((invert ? std::max(1.0 - radius, 0.0) : std::max(radius, 0.0)) - minDist) * rMax, 0.0);
    if (type == 0.0) {
      const double sigma = dist * ry * kTwoPi, phi = dist * rz * kPi, rad = dist * rx;
      outX[i] += (x[i] + mulX * rad * std::cos(sigma) * std::cos(phi)) * w;
      outY[i] += (y[i] + mulY * rad * std::cos(sigma) * std::sin(phi)) * w;
      outZ[i] += (z[i] + mulZ * rad * std::sin(sigma)) * w;
      colour[i] = std::abs(laneFmod(colour[i] + mulC * rc * dist, 1.0));
    } else if (type == 1.0) {
      if (x[i] == 0.0 && y[i] == 0.0 && z[i] == 0.0) continue;  // adds w·0
      const double rIn = std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
      const double r = rIn + mulX * rx * dist;
      const double phi = std::atan2(y[i], x[i]) + mulY * ry * dist;
      const double sigma = std::asin(z[i] / rIn) + mulZ * rz * dist;
      outX[i] += r * std::cos(sigma) * w * std::cos(phi);
      outY[i] += r * std::cos(sigma) * w * std::sin(phi);
      outZ[i] += r * std::sin(sigma) * w;
      colour[i] = std::abs(laneFmod(colour[i] + mulC * rc * dist, 1.0));
    } else {
      const double coeff = rMax <= std::numeric_limits<double>::epsilon() ? dist : dist + alpha * (logMap(dist) - dist);
      outX[i] += (x[i] + logMap(mulX) * logScale(rx) * coeff) * w;
      outY[i] += (y[i] + logMap(mulY) * logScale(ry) * coeff) * w;
      outZ[i] += (z[i] + logMap(mulZ) * logScale(rz) * coeff) * w;
      colour[i] = std::abs(laneFmod(colour[i] + logMap(mulC) * logScale(rc) * coeff, 1.0));
    }
  }
}

// ---- cells and polygons ------------------------------------------------------------------------

// Fractorium's Voron: cells of side Step, each holding 1 to Num seed points placed by a hash of
// the cell; the point is pulled towards the nearest seed of its own and the eight neighbouring
// cells: K (p − s) + s. The hash is Hugo Elias' integer noise with 32-bit wrap-around.
inline double voronNoise(std::int64_t value) {
  auto v = static_cast<std::uint32_t>(value);
  v = (v << 13) ^ v;
  const std::uint32_t mixed = v * (v * v * 15731u + 789221u) + 1376312589u;
  return static_cast<double>(mixed & 0x7fffffffu) * (1.0 / 2147483647.0);
}

VOXFLAME_VARIATION_TARGETS void voron(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double k = P[0];
  const double step = std::abs(P[1]) < 1e-6 ? std::numeric_limits<double>::epsilon() * (P[1] < 0.0 ? -1.0 : 1.0) : P[1];
  const double count = fractoriumInteger(P[2], 1.0, 25.0);
  // Seeds past ±2³¹ would overflow Fractorium's int too; they are held there.
  const double seedX = std::clamp(std::floor(P[3] + 0.5), -2147483648.0, 2147483647.0);
  const double seedY = std::clamp(std::floor(P[4] + 0.5), -2147483648.0, 2147483647.0);
  // Cell numbers stay well inside Fractorium's int arithmetic; a point beyond ±2²⁰ cells (far
  // outside any flame) escapes instead.
  constexpr double kCellLimit = 1048576.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double cellX = std::floor(x[i] / step), cellY = std::floor(y[i] / step);
    if (!(std::abs(cellX) < kCellLimit && std::abs(cellY) < kCellLimit)) {
      outX[i] += std::numeric_limits<double>::quiet_NaN();
      outY[i] += std::numeric_limits<double>::quiet_NaN();
      outZ[i] += w * z[i];
      continue;
    }
    const auto m = static_cast<std::int64_t>(cellX), nn = static_cast<std::int64_t>(cellY);
    double best = 20.0, bestX = 0.0, bestY = 0.0;
    for (std::int64_t di = -1; di < 2; ++di)
      for (std::int64_t dj = -1; dj < 2; ++dj) {
        const std::int64_t m1 = m + di, n1 = nn + dj;
        const auto seeds = static_cast<std::int64_t>(
            1.0 +
            std::floor(count * voronNoise(static_cast<std::int64_t>(static_cast<double>(19 * m1 + 257 * n1) + seedX))));
        for (std::int64_t l = 0; l < seeds; ++l) {
          const double sx = (voronNoise(static_cast<std::int64_t>(static_cast<double>(l + 64 * m1 + 15 * n1) + seedX)) +
                             static_cast<double>(m1)) *
                            step;
          const double sy = (voronNoise(static_cast<std::int64_t>(static_cast<double>(l + 21 * m1 + 33 * n1) + seedY)) +
                             static_cast<double>(n1)) *
                            step;
          const double ddx = x[i] - sx, ddy = y[i] - sy;
          const double r = std::sqrt(ddx * ddx + ddy * ddy);
          if (r < best) {
            best = r;
            bestX = sx;
            bestY = sy;
          }
        }
      }
    outX[i] += w * (k * (x[i] - bestX) + bestX);
    outY[i] += w * (k * (y[i] - bestY) + bestY);
    outZ[i] += w * z[i];
  }
}

// Fractorium's smartshape: the plane bent into a regular polygon of `power` sides (at least 2),
// its corners rounded by roundstr and roundwidth, distortion the exponent of the bending.
VOXFLAME_VARIATION_TARGETS void smartshape(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = std::max(P[0], 2.0), roundStr = P[1], roundWidth = P[2], distortion = P[3];
  const bool compensate = std::clamp(P[4], 0.0, 1.0) > 0.0;
  const double alpha = kTwoPi / power;
  const double alphaCoeff = std::tan(alpha * 0.5) * 2.0;
  const double roundCoeff = roundStr / std::sin(alpha * 0.5) / power * 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dang = (std::atan2(y[i], x[i]) + kPi) / alpha;
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double zang1 = std::floor(dang), xang1 = dang - zang1;
    const double xang2 = xang1 > 0.5 ? 1.0 - xang1 : xang1;
    const double zang = xang1 > 0.5 ? zang1 + 1.0 : zang1;
    const double sign = xang1 > 0.5 ? -1.0 : 1.0;
    const double xang = compensate && distortion >= 1.0 ? std::atan(xang2 * alphaCoeff) / alpha : xang2;
    double coeff1 = 1.0;
    if (distortion != 0.0) {
      const double coeff0 = 1.0 / std::cos(xang * alpha);
      if (roundStr != 0.0) {
        const double width =
            roundWidth != 1.0 ? std::exp(std::log(xang * 2.0) * roundWidth) * roundCoeff : xang * 2.0 * roundCoeff;
        coeff1 = std::abs((1.0 - width) * coeff0 + width);
      } else {
        coeff1 = coeff0;
      }
    }
    const double coeff = distortion != 1.0 ? std::exp(std::log(coeff1) * distortion) : coeff1;
    const double ang = (zang + sign * xang) * alpha - kPi;
    const double t = w * coeff * rad;
    outX[i] += std::cos(ang) * t;
    outY[i] += std::sin(ang) * t;
    outZ[i] += w * z[i];
  }
}

// lazyTravis (Michael Faber's, as JWildfire has it): the square of half-side s = max(|x|, |y|)
// walked round by its perimeter position plus a spin; outside the weight's square (s > w) it is
// also pushed out by `space`. At the origin, where s = 0, JWildfire's result is NaN.
VOXFLAME_VARIATION_TARGETS void lazyTravis(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double spinIn = 4.0 * P[0], spinOut = 4.0 * P[1], space = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = std::abs(x[i]), ay = std::abs(y[i]);
    const bool outside = ax > w || ay > w;
    const double spin = outside ? spinOut : spinIn;
    double s, p;
    if (ax > ay) {
      s = ax;
      p = x[i] > 0.0 ? s + y[i] + s * spin : 5.0 * s - y[i] + s * spin;
    } else {
      s = ay;
      p = y[i] > 0.0 ? 3.0 * s - x[i] + s * spin : 7.0 * s + x[i] + s * spin;
    }
    p = std::fmod(p, s * 8.0);
    double px, py;
    if (outside) {
      if (p <= 2.0 * s) {
        px = s + space;
        py = -(s - p);
        py = py + py / s * space;
      } else if (p <= 4.0 * s) {
        py = s + space;
        px = 3.0 * s - p;
        px = px + px / s * space;
      } else if (p <= 6.0 * s) {
        px = -(s + space);
        py = 5.0 * s - p;
        py = py + py / s * space;
      } else {
        py = -(s + space);
        px = -(7.0 * s - p);
        px = px + px / s * space;
      }
    } else if (p <= 2.0 * s) {
      px = s;
      py = -(s - p);
    } else if (p <= 4.0 * s) {
      px = 3.0 * s - p;
      py = s;
    } else if (p <= 6.0 * s) {
      px = -s;
      py = 5.0 * s - p;
    } else {
      px = -(7.0 * s - p);
      py = -s;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// waves4_wf (JWildfire's): waves2 with sin·cos·sin (or cos·sin·cos) waves, both terms scaled by
// e^damp (1 when |damp| < 10⁻⁸).
VOXFLAME_VARIATION_TARGETS void waves4Wf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], freqX = P[2], freqY = P[3];
  const bool cosX = std::round(P[4]) == 1.0, cosY = std::round(P[5]) == 1.0;
  const double dampX = std::abs(P[6]) < kJwfEpsilon ? 1.0 : std::exp(P[6]);
  const double dampY = std::abs(P[7]) < kJwfEpsilon ? 1.0 : std::exp(P[7]);
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = std::sin(y[i] * freqX), cx = std::cos(y[i] * freqX);
    const double sy = std::sin(x[i] * freqY), cy = std::cos(x[i] * freqY);
    const double waveX = cosX ? cx * sx * cx : sx * cx * sx, waveY = cosY ? cy * sy * cy : sy * cy * sy;
    outX[i] += w * (x[i] + dampX * scaleX * waveX) * dampX;
    outY[i] += w * (y[i] + dampY * scaleY * waveY) * dampY;
    outZ[i] += w * z[i];
  }
}

// Fractorium's y: the point's direction kept, its distance r replaced by w·T²/r, T the sum of four
// shapes' radii at its angle a = φ: a hypergon, a star, a lituus and a superformula curve.
VOXFLAME_VARIATION_TARGETS void yShapes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double hypergon = P[0], hypergonN = std::max(std::floor(P[1] + 0.5), 3.0), hypergonR = P[2];
  const double star = P[3], starN = std::max(std::floor(P[4] + 0.5), 3.0);
  const double starSlope = std::clamp(P[5], std::numeric_limits<double>::epsilon(), kPi / 2.0);
  const double lituus = P[6], lituusA = P[7];
  const double super = P[8], superM = P[9], superN1 = P[10], superN2 = P[11], superN3 = P[12];
  const double hypergonD = std::sqrt(1.0 + hypergonR * hypergonR), hd2 = hypergonD * hypergonD;
  // Fractorium steps back from tan(π/2), which is undefined.
  const double tanStarSlope = std::abs(starSlope - kPi / 2.0) < 1e-6 ? std::tan(starSlope - 0.05) : std::tan(starSlope);
  const double oneOverN1 = -1.0 / fractoriumZeps(superN1);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::atan2(y[i], x[i]);
    double total = 0.0;
    if (hypergon != 0.0) {
      const double t1 = std::fmod(std::abs(a), kTwoPi / hypergonN) - kPi / hypergonN;
      const double t2 = std::tan(t1) * std::tan(t1) + 1.0;
      total += t2 >= hd2 ? hypergon : hypergon * (hypergonD - std::sqrt(hd2 - t2)) / std::sqrt(t2);
    }
    if (star != 0.0) {
      const double t1 = std::tan(std::abs(std::fmod(std::abs(a), kTwoPi / starN) - kPi / starN));
      total +=
          star * std::sqrt(tanStarSlope * tanStarSlope * (1.0 + t1 * t1) / ((t1 + tanStarSlope) * (t1 + tanStarSlope)));
    }
    if (lituus != 0.0) total += lituus * std::pow(std::abs(a / kPi + 1.0), -lituusA);
    if (super != 0.0) {
      const double t4 = a * superM / 4.0;
      total += super * std::pow(std::pow(std::abs(std::cos(t4)), superN2) + std::pow(std::abs(std::sin(t4)), superN3),
                                oneOverN1);
    }
    // Fractorium divides by r unguarded; the tiny guard keeps the origin finite (0 when T is 0).
    const double r = w * total * total / (std::sqrt(x[i] * x[i] + y[i] * y[i]) + 1e-300);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractoriumVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("mirror_x",
      "(±|x|, y, z), − when Ψ < ½ (Fractorium's; the weight is not applied, and the terms before it are discarded)",
      k2D, kRandom, &mirrorX);
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("mirror_y",
      "(x, ±|y|, z), − when Ψ < ½ (Fractorium's; the weight is not applied, and the terms before it are discarded)",
      k2D, kRandom, &mirrorY);
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("mirror_z",
      "(x, y, ±|z|), − when Ψ < ½ (Fractorium's; the weight is not applied, and the terms before it are discarded)",
      k3D, kRandom, &mirrorZ);
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("axis_symmetry_wf",
      "the point with one coordinate u (x, y or z by axis) mirrored about the centre's and moved w/2 outward: "
      "u' = u + w/2 when Ψ < ½, else 2cu − u − w/2; then turned about the centre by ±rotation "
      "degrees (the two sides opposite ways) in the plane of u and the next coordinate (x–z for axis z, centred "
      "at (centre_x, centre_y) as JWildfire does); the weight is not applied again (w the weight; JWildfire's "
      "post_axis_symmetry_wf); the colour index moves by x1colorshift (axis x, Ψ < ½) or x2colorshift (axis x, "
      "mirrored), y1/y2 and z1/z2 likewise, mod 1",
      k3D, kRandom, &axisSymmetryWf,
      {count("axis", 0.0, 0.0, 2.0),
       {"centre_x", 0.25, -2.0, 2.0},
       {"centre_y", 0.5, -2.0, 2.0},
       {"centre_z", 0.5, -2.0, 2.0},
       {"rotation", 30.0, -180.0, 180.0},
       {"x1colorshift", 0.0, -1.0, 1.0},
       {"y1colorshift", 0.0, -1.0, 1.0},
       {"z1colorshift", 0.0, -1.0, 1.0},
       {"x2colorshift", 0.0, -1.0, 1.0},
       {"y2colorshift", 0.0, -1.0, 1.0},
       {"z2colorshift", 0.0, -1.0, 1.0}});
  catalogue.back().directColour = true;
  add("octagon",
      "s p + t p + (x ± x₀, y ± y₀, z ± z₀); s = 1/(x⁴ + y⁴ + 2z² + 10⁻⁸) where w s < 2, else 1; t = 1/(|x| + |y| "
      "+ 2√z + 10⁻⁸) (√z taken as 0 below z = 0, where JWildfire's is NaN), or 1 when w < 0; ± the sign of each "
      "coordinate; x₀, y₀, z₀ the parameters x, y, z (w the weight; Apophysis writes them octa_x, octa_y, octa_z)",
      k3D, kFixed, &octagon, {{"x", 0.0, -1.0, 1.0}, {"y", 0.0, -1.0, 1.0}, {"z", 0.0, -1.0, 1.0}});
  add("bcircle",
      "q = scale·(x, y): q where |q| ≤ 1, else (0.2 |borderwidth| Ψ + 1)(cos ∠q, sin ∠q), or (0, 0) when borderwidth "
      "is 0; z",
      k2D, kRandom, &bcircle, {{"scale", 1.0, 0.0, 4.0}, {"borderwidth", 0.0, -2.0, 2.0}});
  add("waves23",
      "(x + scalex·f(freqx y/2π), y + scaley·f(freqy x/2π), z); f(m) = m − ⌊m⌋, or ½ − that when it exceeds ½", k2D,
      kFixed, &waves23,
      {{"scalex", 0.05, -2.0, 2.0},
       {"scaley", 0.05, -2.0, 2.0},
       {"freqx", 7.0, -20.0, 20.0},
       {"freqy", 13.0, -20.0, 20.0}});
  add("wdisc", "(φ/π)(cos a, sin a), z; a = π/(r + 1), or π − π/(r + 1) when φ > 0", k2D, kFixed, &wdisc);
  add("pow_block",
      "r^q (cos a, sin a), z; q = numerator/(denominator·correctn/correctd), a = numerator (φ + 2π root "
      "⌊Ψ·denominator⌋) "
      "/ denominator (Fractorium's)",
      k2D, kRandom, &powBlock,
      {{"numerator", 3.0, -10.0, 10.0},
       {"denominator", 2.0, -10.0, 10.0},
       {"root", 1.0, -4.0, 4.0},
       {"correctn", 1.0, -4.0, 4.0},
       {"correctd", 1.0, -4.0, 4.0}});
  add("depth",
      "t + p |z|^power; t the transform's affine point: p itself, but for post_depth the point that the transform's "
      "variations summed from (Fractorium's)",
      k3D, kFixed, &depth, {{"power", 1.0, -4.0, 4.0}});
  add("poincare3D",
      "(p (1 + 2c_i² − |c|²) + c (2 c·p − 2c_i p_i − |p|² − 1)) / (|c|²|p|² − 2 c·p + 1) per coordinate i; c = r (−cos "
      "a' cos b', sin a' cos b', −sin b'), a' = aπ/2, b' = bπ/2",
      k3D, kFixed, &poincare3D, {{"r", 0.0, -1.0, 1.0}, {"a", 0.0, -2.0, 2.0}, {"b", 0.0, -2.0, 2.0}});
  add("falloff",
      "p blurred by D = max(0, (|p − (x0, y0, z0)| − mindist) · 0.04 scatter) (|…| as max(0, 1 − |…|) with invert), "
      "a = (Ψ₁, Ψ₂, Ψ₃) − ½: type 0 p + mul·a D; type 1 ρ (cos σ cos φ', cos σ sin φ', sin σ) with ρ = |p| + mul_x "
      "a₁ D, φ' = φ + mul_y a₂ D, σ = asin(z/|p|) + mul_z a₃ D; type 2 per coordinate v + (⌊v/s⌋ + s a − v) mul D, "
      "s = min(D, 0.9) + 0.1, plus mul a^boxpow D/s outside the weight (Fractorium's)",
      k3D, kRandom, &falloff,
      {{"scatter", 1.0, 0.0, 20.0},
       {"mindist", 0.5, 0.0, 3.0},
       {"mul_x", 1.0, 0.0, 1.0},
       {"mul_y", 1.0, 0.0, 1.0},
       {"mul_z", 0.0, 0.0, 1.0},
       {"x0", 0.0, -3.0, 3.0},
       {"y0", 0.0, -3.0, 3.0},
       {"z0", 0.0, -3.0, 3.0},
       count("invert", 0.0, 0.0, 1.0),
       count("type", 0.0, 0.0, 2.0),
       count("boxpow", 2.0, 2.0, 32.0)});
  add("falloff3",
      "p blurred by D = max(0, (d − min_distance) · 0.04 blur_strength), d = |p − centre| (blur_shape 0) or its "
      "largest coordinate (1), as max(0, 1 − d) with invert_distance; a = (Ψ₁, Ψ₂, Ψ₃) − ½: blur_type 0 p + D a₁ "
      "(mul_x cos σ cos φ', mul_y cos σ sin φ', mul_z sin σ), σ = 2π a₂ D, φ' = π a₃ D; 1 as falloff's type 1; 2 "
      "and 3 p + L(mul) S(a) (D + alpha (L(D) − D)), L(v) = (e + ln(e v))/4, S(v) = ln(e (|v| + 1))/e, signed "
      "(Fractorium's); the colour index moves by mul_c (Ψ₄ − ½) D (types 0, 1) or L(mul_c) S(Ψ₄ − ½) (D + alpha (L(D) "
      "− D)) (2, 3), then |… mod 1|",
      k3D, kRandom, &falloff3,
      {count("blur_type", 0.0, 0.0, 3.0),
       count("blur_shape", 0.0, 0.0, 1.0),
       {"blur_strength", 1.0, 0.0, 20.0},
       {"min_distance", 0.5, 0.0, 3.0},
       count("invert_distance", 0.0, 0.0, 1.0),
       {"mul_x", 1.0, 0.0, 1.0},
       {"mul_y", 1.0, 0.0, 1.0},
       {"mul_z", 0.0, 0.0, 1.0},
       {"mul_c", 0.0, 0.0, 1.0},
       {"center_x", 0.0, -3.0, 3.0},
       {"center_y", 0.0, -3.0, 3.0},
       {"center_z", 0.0, -3.0, 3.0},
       {"alpha", 0.0, -1.0, 1.0}});
  catalogue.back().directColour = true;
  add("Voron",
      "K (x, y) + (1 − K) s, z; s the nearest of the seed points of the 3×3 cells of side Step around p, 1 to Num "
      "per cell, placed by Hugo Elias' integer hash of the cell and XSeed, YSeed (Fractorium's)",
      k2D, kFixed, &voron,
      {{"K", 0.99, -2.0, 2.0},
       {"Step", 0.25, 0.01, 2.0},
       count("Num", 1.0, 1.0, 25.0),
       count("XSeed", 3.0, 0.0, 100.0),
       count("YSeed", 7.0, 0.0, 100.0)});
  add("smartshape",
      "r c (cos α', sin α'), z: the angle φ + π in sectors of 2π/power, α' its sector's middle ± x' where x' is the "
      "offset in the sector (tan-compensated with compensation); c = (1/cos x', its corners blended by roundstr "
      "and roundwidth)^distortion (Fractorium's)",
      k2D, kFixed, &smartshape,
      {{"power", 4.0, 2.0, 12.0},
       {"roundstr", 0.0, -1.0, 1.0},
       {"roundwidth", 1.0, 0.0, 4.0},
       {"distortion", 1.0, -2.0, 4.0},
       {"compensation", 0.0, 0.0, 1.0}});
  add("lazyTravis",
      "the point on the square of half-side s = max(|x|, |y|) at perimeter position (its own + 4 s·spin) mod 8s; "
      "outside the weight's square (s > w) spin_out and pushed out by space, inside spin_in; z (w the weight)",
      k2D, kFixed, &lazyTravis,
      {{"spin_in", 1.0, -2.0, 2.0}, {"spin_out", 0.5, -2.0, 2.0}, {"space", kPi / 2.0, -2.0, 2.0}});
  add("waves4_wf",
      "(x + dx scalex W(freqx y), y + dy scaley W'(freqy x)) scaled by (dx, dy), z; W = cos·sin·cos with use_cos_x, "
      "else sin·cos·sin (likewise W'), dx = e^dampx, dy = e^dampy",
      k2D, kFixed, &waves4Wf,
      {{"scalex", 0.25, -2.0, 2.0},
       {"scaley", 0.5, -2.0, 2.0},
       {"freqx", kPi / 2.0, -10.0, 10.0},
       {"freqy", kPi / 4.0, -10.0, 10.0},
       count("use_cos_x", 1.0, 0.0, 1.0),
       count("use_cos_y", 0.0, 0.0, 1.0),
       {"dampx", 0.0, -2.0, 2.0},
       {"dampy", 0.0, -2.0, 2.0}});
  add("y",
      "(T²/r)(cos φ, sin φ), z; T = hypergon H + star S + lituus (|φ/π + 1|)^(−lituus_a) + super (|cos(φ "
      "super_m/4)|^super_n2 + |sin(φ super_m/4)|^super_n3)^(−1/super_n1); H = 1, or (d − √(d² − u))/√u where u = tan² "
      "t + 1 < d², d² = 1 + hypergon_r², t = (|φ| mod 2π/hypergon_n) − π/hypergon_n; S = √(k²(1 + v²))/(v + k), v = "
      "|tan t| with star_n, k = tan star_slope (Fractorium's, whose hypergon is 0 unless set: Fractorium writes "
      "every parameter, and at 0 the variation would draw nothing)",
      k2D, kFixed, &yShapes,
      {{"hypergon", 1.0, -3.0, 3.0},
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
