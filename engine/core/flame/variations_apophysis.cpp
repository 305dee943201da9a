// The plugins of Apophysis 7X and JWildfire that real flames use most.
// Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

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
// or Gaussian (2). Its colour shift (mul_c) moves the colour index by a fourth draw − ½ times D,
// mod 1, as Fractorium's does (a direct-colour variation); the fourth number is drawn only when
// mul_c is set, so a falloff2 without colour shift draws as it always has.
VOXFLAME_VARIATION_TARGETS void falloff2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scale = 0.04 * std::max(P[0], 1e-6), mindist = std::max(P[1], 0.0);
  const double mulX = std::clamp(P[2], 0.0, 1.0), mulY = std::clamp(P[3], 0.0, 1.0);
  const double mulZ = std::clamp(P[4], 0.0, 1.0);
  const double x0 = P[6], y0 = P[7], z0 = P[8];
  const bool invert = std::round(P[9]) >= 1.0;
  const double type = std::round(P[10]);
  const double mulC = std::clamp(P[5], 0.0, 1.0);
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
    if (mulC != 0.0) colour[i] = std::abs(laneFmod(colour[i] + mulC * (laneUniform(rnd[i]) - 0.5) * d, 1.0));
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

// stun (Apophysis' post_stun plugin, written to act after the other terms on their sum: as post_stun it
// maps the point it is handed): beyond r² > r_min (r² itself against the radius, as the plugin does) the
// point is scaled by 1/m − 1, m = (r + |power r Ψ|)² where that exceeds r_max, else r²; then (3w/π atan2(x,
// y), 3w/2π ln(x² + y²), 3w z). power, r_min and r_max are clamped into [0, 10¹⁰¹] as the plugin's ranges.
VOXFLAME_VARIATION_TARGETS void stun(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const auto ranged = [](double v) { return std::clamp(v, 0.0, 1e101); };
  const double power = std::abs(ranged(P[0])), rMin = ranged(P[1]), rMax = ranged(P[2]);
  const double low = rMin < rMax ? rMin : rMax, high = rMin > rMax ? rMin : rMax;
  const double w3 = 3.0 * w, w1 = w3 / kPi, w2 = 0.5 * w1;
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    const double r2 = px * px + py * py;
    if (r2 > low) {
      const double r = std::sqrt(r2);
      const double reach = r + std::abs(power * r * laneUniform(rnd[i]));
      const double m = reach * reach > high ? reach * reach : r2;
      const double scale = 1.0 / m - 1.0;
      px *= scale;
      py *= scale;
    }
    outX[i] += w1 * std::atan2(px, py);
    outY[i] += w2 * std::log(px * px + py * py);
    outZ[i] += w3 * z[i];
  }
}

}  // namespace

void variation_kernels::addApophysisVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

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
      "random direction (2πΨ₁, πΨ₂) scaled by mul_x, mul_y, mul_z; the colour index c ↦ |c + mul_c (Ψ₄ − ½) D| mod 1 "
      "(Apophysis 7X's)",
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
  catalogue.back().directColour = true;
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
  add("stun",
      "(3w/π atan2(x', y'), 3w/2π ln(x'² + y'²), 3w z), p' = p (1/m − 1) where r² > min(r_min, r_max), m = (r + "
      "|power r Ψ|)² where that exceeds max(r_min, r_max), else r²; else p' = p (Apophysis' post_stun plugin, which "
      "maps the sum of the other terms: post_stun here)",
      k3D, kRandom, &stun, {{"power", 1.0, 0.0, 10.0}, {"r_min", 0.0, 0.0, 10.0}, {"r_max", 1.0, 0.0, 10.0}});
}

}  // namespace voxflame::core
