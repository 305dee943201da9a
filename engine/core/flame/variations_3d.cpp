// The 3D variations of Apophysis 3D and JWildfire (their classes of the same name), unless said otherwise.
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

// linear3D is linear: the same map, which a 2D variation's carried z already makes 3D.
VOXFLAME_VARIATION_TARGETS void linear3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * x[i];
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

// ---- 3D variations ---------------------------------------------------------------------------

VOXFLAME_VARIATION_TARGETS void spherical3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (x[i] * x[i] + y[i] * y[i] + z[i] * z[i] + kEpsilon);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += s * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void julia3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]);
  const double absPower = std::abs(powerN);
  const double exponent = (1.0 / powerN - 1.0) * 0.5;
  // JWildfire draws power −1 as spherical3D; the general formula would mirror y.
  const double ySign = powerN == -1.0 ? -1.0 : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double zs = z[i] / absPower;
    const double r2d = x[i] * x[i] + y[i] * y[i];
    const double r = w * std::pow(r2d + zs * zs + kEpsilon, exponent);
    const double r2 = r * std::sqrt(r2d);
    const double root = std::trunc(laneUniform(rnd[i]) * absPower);
    const double a = (std::atan2(y[i], x[i]) + kTwoPi * root) / powerN;
    outX[i] += r2 * std::cos(a);
    outY[i] += ySign * r2 * std::sin(a);
    outZ[i] += r * zs;
  }
}

VOXFLAME_VARIATION_TARGETS void julia3Dz(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]);
  const double absPower = std::abs(powerN);
  const double exponent = 0.5 / powerN;
  const double ySign = powerN == -1.0 ? -1.0 : 1.0;  // power −1 is JWildfire's 1/r² inversion
  const double quirk = absPower == 2.0 ? 1.0 : 0.0;  // JWildfire's ±2 case adds a second z term
  for (std::size_t i = 0; i < n; ++i) {
    const double r2d = x[i] * x[i] + y[i] * y[i] + kEpsilon;
    const double rho = std::sqrt(r2d);
    const double r = w * std::pow(r2d, exponent);
    const double root = std::trunc(laneUniform(rnd[i]) * absPower);
    const double a = (std::atan2(y[i], x[i]) + kTwoPi * root) / powerN;
    outX[i] += r * std::cos(a);
    outY[i] += ySign * r * std::sin(a);
    outZ[i] += r * z[i] / (rho * absPower) + quirk * r * z[i] / (2.0 * std::sqrt(rho));
  }
}

VOXFLAME_VARIATION_TARGETS void bubble3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double d = 0.25 * (x[i] * x[i] + y[i] * y[i]) + 1.0;
    const double s = w / d;
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * (2.0 / d - 1.0);
  }
}

VOXFLAME_VARIATION_TARGETS void hemisphere(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / std::sqrt(x[i] * x[i] + y[i] * y[i] + 1.0);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += s;
  }
}

VOXFLAME_VARIATION_TARGETS void cylinder3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = std::clamp(P[0], 0.0, 0.5), halfHeight = std::clamp(P[1], 0.0, 0.5);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double rho = radius * std::sqrt(laneUniform(rnd[i]));  // √: uniform over the disc's area
    const double h = halfHeight * (2.0 * laneUniform(rnd[i]) - 1.0);
    outX[i] += w * rho * std::cos(a);
    outY[i] += w * h;
    outZ[i] += w * rho * std::sin(a);
  }
}

VOXFLAME_VARIATION_TARGETS void sinusoidal3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]);
    outY[i] += w * std::sin(y[i]);
    outZ[i] += w * std::atan2(x[i] * x[i], y[i] * y[i]) * std::cos(z[i]);
  }
}

VOXFLAME_VARIATION_TARGETS void swirl3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double s = std::sin(r2), c = std::cos(r2);
    outX[i] += w * (x[i] * s - y[i] * c);
    outY[i] += w * (x[i] * c + y[i] * s);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void curl3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1], cz = P[2];
  const double c2 = cx * cx + cy * cy + cz * cz;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double s = w / (r2 * c2 + 2.0 * cx * x[i] - 2.0 * cy * y[i] + 2.0 * cz * z[i] + 1.0);
    outX[i] += s * (x[i] + cx * r2);
    outY[i] += s * (y[i] - cy * r2);
    outZ[i] += s * (z[i] + cz * r2);
  }
}

VOXFLAME_VARIATION_TARGETS void pie3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double slices = countParam(P[0]), rotation = P[1], thickness = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double slice = std::trunc(laneUniform(rnd[i]) * slices + 0.5);
    const double a = rotation + kTwoPi * (slice + laneUniform(rnd[i]) * thickness) / slices;
    const double r = w * laneUniform(rnd[i]);
    outX[i] += r * std::cos(a);
    outY[i] += r * std::sin(a);
    outZ[i] += r * std::sin(r);
  }
}

VOXFLAME_VARIATION_TARGETS void blur3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = kTwoPi * laneUniform(rnd[i]);
    const double b = kPi * laneUniform(rnd[i]);
    const double r = w * laneGauss(rnd[i]);
    outX[i] += r * std::sin(b) * std::cos(a);
    outY[i] += r * std::sin(b) * std::sin(a);
    outZ[i] += r * std::cos(b);
  }
}

VOXFLAME_VARIATION_TARGETS void zblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * laneGauss(rnd[i]);
}

VOXFLAME_VARIATION_TARGETS void zscale(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * z[i];
}

VOXFLAME_VARIATION_TARGETS void ztranslate(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w;
}

VOXFLAME_VARIATION_TARGETS void zcone(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
}

}  // namespace

void variation_kernels::add3DVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  // 3D variations: Apophysis 3D and JWildfire (its classes of the same name), unless said otherwise.
  add("linear3D", "(x, y, z)", k3D, kFixed, &linear3D);
  add("spherical3D", "(x, y, z) / (x² + y² + z²)", k3D, kFixed, &spherical3D);
  add("julia3D",
      "ρ^(1/power − 1) (√(x² + y²) cos α, √(x² + y²) sin α, z/|power|); ρ = |(x, y, z/|power|)|, "
      "α = (φ + 2πk)/power, k = trunc(|power|·Ψ); power −1 is spherical3D (as JWildfire)",
      k3D, kRandom, &julia3D, {count("power", 3.0, -8.0, 8.0)});
  add("julia3Dz",
      "(x² + y²)^(1/(2·power)) (cos α, sin α, z/(|power| √(x² + y²))); α as julia3D; power ±2 adds JWildfire's "
      "second z term, power −1 is (x, y, z)/(x² + y²)",
      k3D, kRandom, &julia3Dz, {count("power", 3.0, -8.0, 8.0)});
  add("bubble3D", "(x, y, 2 − d) / d, d = r²/4 + 1: the plane wrapped onto the unit sphere (JWildfire's bubble)", k3D,
      kFixed, &bubble3D);
  add("hemisphere", "(x, y, 1) / √(r² + 1)", k3D, kFixed, &hemisphere);
  add("cylinder3D",
      "a random point of the solid cylinder of radius d and half-height H about the y axis: (ρ cos 2πΨ₁, "
      "H(2Ψ₃ − 1), ρ sin 2πΨ₁), ρ = d√Ψ₂ (what JWildfire's keeps; d, H in [0, ½])",
      k3D, kRandom, &cylinder3D, {{"d", 0.3, 0.0, 0.5}, {"H", 0.25, 0.0, 0.5}});
  add("sinusoidal3D", "(sin x, sin y, atan2(x², y²) cos z) (JWildfire's sinusoidal3d)", k3D, kFixed, &sinusoidal3D);
  add("swirl3D",
      "(x sin ρ² − y cos ρ², x cos ρ² + y sin ρ², z); ρ² = x² + y² + z² (ours: swirl about z by the 3D radius)", k3D,
      kFixed, &swirl3D);
  add("curl3D", "((x, y, z) + r²(cx, −cy, cz)) / (r²|c|² + 2cx x − 2cy y + 2cz z + 1); r² = x² + y² + z²", k3D, kFixed,
      &curl3D, {{"cx", 0.0, -1.0, 1.0}, {"cy", 0.05, -1.0, 1.0}, {"cz", 0.05, -1.0, 1.0}});
  add("pie3D", "pie's (x, y) with R = Ψ₃, and z = R sin R", k3D, kRandom, &pie3D,
      {count("slices", 7.0, 1.0, 24.0), {"rotation", 0.0, -kPi, kPi}, {"thickness", 0.5, 0.0, 1.0}});
  add("blur3D", "G (sin β cos α, sin β sin α, cos β); α = 2πΨ, β = πΨ, G = Ψ + Ψ + Ψ + Ψ − 2", k3D, kRandom, &blur3D);
  add("zblur", "(0, 0, Ψ + Ψ + Ψ + Ψ − 2)", k3D, kRandom, &zblur);
  add("zscale", "(0, 0, z): with linear, stretches depth", k3D, kFixed, &zscale);
  add("ztranslate", "(0, 0, 1): moves along z by the weight", k3D, kFixed, &ztranslate);
  add("zcone", "(0, 0, √(x² + y²))", k3D, kFixed, &zcone);
}

}  // namespace voxflame::core
