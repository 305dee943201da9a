// The long tail of plugin variations that real flame files use: each in the notation and with the
// conventions of flame_variations.h. Where JWildfire, Fractorium and the Apophysis plugin differ,
// the comment says whose behaviour is followed (that of the program that wrote the flames which
// use it). Everything those programs precompute from the parameters is computed here per call, as
// variations are stateless.
#include "flame_variations_more.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace voxflame::core {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// JWildfire's MathLib.EPSILON, used exactly where JWildfire adds or compares with it.
constexpr double kJwfEpsilon = 1e-8;
// Fractorium's Zeps(): a zero divisor becomes the double's machine epsilon.
inline double fractoriumZeps(double value) {
  return value == 0.0 ? std::numeric_limits<double>::epsilon() : value;
}

// The arrays of one call as restrict-qualified locals (see flame_variations.cpp: GCC vectorises
// only loops over arrays it knows do not alias).
#define VOXFLAME_MORE_BEGIN(in, ox, oy, oz)    \
  const double* __restrict x = (in).x;         \
  const double* __restrict y = (in).y;         \
  const double* __restrict z = (in).z;         \
  std::uint32_t* __restrict rnd = (in).random; \
  double* __restrict outX = (ox);              \
  double* __restrict outY = (oy);              \
  double* __restrict outZ = (oz);              \
  const std::size_t n = (in).count;            \
  const double w = (in).weight;                \
  const double* __restrict P = (in).params;    \
  (void)x;                                     \
  (void)y;                                     \
  (void)z;                                     \
  (void)rnd;                                   \
  (void)w;                                     \
  (void)P;

// ---- mirrors and symmetries ----------------------------------------------------------------

// Fractorium's mirror_x/y/z: one coordinate's absolute value, negated half the time (Ψ < ½); the
// weight is not applied (Fractorium ignores it). Fractorium meant them as pre_/post_ terms; as an
// ordinary term Fractorium also discards the terms summed before it, which a sum cannot do, so
// here it simply adds its point.
void mirrorX(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double flip = laneUniform(rnd[i]) < 0.5 ? -1.0 : 1.0;
    outX[i] += flip * std::abs(x[i]);
    outY[i] += y[i];
    outZ[i] += z[i];
  }
}

void mirrorY(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double flip = laneUniform(rnd[i]) < 0.5 ? -1.0 : 1.0;
    outX[i] += x[i];
    outY[i] += flip * std::abs(y[i]);
    outZ[i] += z[i];
  }
}

void mirrorZ(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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
// colour shifts are not applied (the importer says so when a file sets them).
void axisSymmetryWf(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
  const double axis = std::clamp(std::round(P[0]), 0.0, 2.0);
  const double cx = P[1], cy = P[2], cz = P[3];
  const double half = P[4] * kTwoPi / 180.0 / 2.0;
  const bool rotate = std::abs(half) > kJwfEpsilon;
  const double s = std::sin(half), c = std::cos(half);
  const double shift = w / 2.0;
  const bool active = std::abs(w) > kJwfEpsilon;
  for (std::size_t i = 0; i < n; ++i) {
    const bool near = laneUniform(rnd[i]) < 0.5;
    double px = x[i], py = y[i], pz = z[i];
    if (active) {
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
void octagon(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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
void bcircle(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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
void waves23(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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

void wdisc(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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
void powBlock(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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

// Fractorium's depth: the point plus itself scaled by |z|^power. Fractorium adds the transform's
// affine point, which for ordinary and pre_ terms is the point itself; a post_ term would need the
// point from before the variations, which the importer therefore refuses to fake.
void depth(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
  const double power = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    double coeff = std::abs(z[i]);
    if (coeff != 0.0 && power != 1.0) coeff = std::exp(std::log(coeff) * power);
    outX[i] += w * (x[i] + x[i] * coeff);
    outY[i] += w * (y[i] + y[i] * coeff);
    outZ[i] += w * (z[i] + z[i] * coeff);
  }
}

// poincare3D (Zueuk's, as JWildfire has it): the Möbius map of 3D space that moves the unit
// ball's centre to c = r (−cos a' cos b', sin a' cos b', −sin b'), a' = aπ/2, b' = bπ/2.
void poincare3D(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_MORE_BEGIN(in, ox, oy, oz)
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

}  // namespace

void addMoreVariations(std::vector<VariationInfo>& catalogue) {
  const auto add = [&](std::string name, std::string formula, bool threeD, bool random, VariationFn fn,
                       std::vector<VariationParam> params = {}) {
    VariationInfo info;
    info.name = std::move(name);
    info.formula = std::move(formula);
    info.threeD = threeD;
    info.random = random;
    info.apply = fn;
    info.params = std::move(params);
    catalogue.push_back(std::move(info));
  };
  constexpr bool k2D = false, k3D = true, kRandom = true, kFixed = false;
  const auto count = [](std::string name, double value, double low, double high) {
    return VariationParam{std::move(name), value, low, high, true};
  };

  add("mirror_x", "(±|x|, y, z), − when Ψ < ½ (Fractorium's; the weight is not applied)", k2D, kRandom, &mirrorX);
  add("mirror_y", "(x, ±|y|, z), − when Ψ < ½ (Fractorium's; the weight is not applied)", k2D, kRandom, &mirrorY);
  add("mirror_z", "(x, y, ±|z|), − when Ψ < ½ (Fractorium's; the weight is not applied)", k3D, kRandom, &mirrorZ);
  add("axis_symmetry_wf",
      "the point with one coordinate u (x, y or z by axis) mirrored about the centre's and moved w/2 outward: "
      "u' = u + w/2 when Ψ < ½, else 2cu − u − w/2; then turned about the centre by ±rotation "
      "degrees (the two sides opposite ways) in the plane of u and the next coordinate (x–z for axis z, centred "
      "at (centre_x, centre_y) as JWildfire does); the weight is not applied again (w the weight; JWildfire's "
      "post_axis_symmetry_wf; its colour shifts are not applied)",
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
      "p (1 + |z|^power) (Fractorium's; its post_ form, which adds the transform's affine point instead of p, is not "
      "imported)",
      k3D, kFixed, &depth, {{"power", 1.0, -4.0, 4.0}});
  add("poincare3D",
      "(p (1 + 2c_i² − |c|²) + c (2 c·p − 2c_i p_i − |p|² − 1)) / (|c|²|p|² − 2 c·p + 1) per coordinate i; c = r (−cos "
      "a' cos b', sin a' cos b', −sin b'), a' = aπ/2, b' = bπ/2",
      k3D, kFixed, &poincare3D, {{"r", 0.0, -1.0, 1.0}, {"a", 0.0, -2.0, 2.0}, {"b", 0.0, -2.0, 2.0}});
}

}  // namespace voxflame::core
