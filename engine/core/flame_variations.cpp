#include "flame_variations.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "error.h"

namespace voxflame::core {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEpsilon = 1e-300;  // keeps 1/r finite at the origin, as flam3's EPS does

// VARIATION(name) { body } defines one variation. The body sees restrict-qualified parameters
// (GCC vectorises loops over restrict parameters, not over restrict locals): x, y, z (the point
// after the affine map), rnd (each lane's generator), outX, outY, outZ (to add weight · V(p) to),
// n (lanes), w (the weight), P (the parameters) and A (the pre-affine, row-major 3×4). The public
// function is built for AVX2 and for any x86-64 and picked when the program loads.
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__SANITIZE_THREAD__)
#define VOXFLAME_VARIATION_TARGETS [[gnu::target_clones("avx2", "default")]]
#else
#define VOXFLAME_VARIATION_TARGETS
#endif
#define VARIATION(name)                                                                                         \
  [[gnu::always_inline]] inline void name##Body(                                                                \
      const double* __restrict x, const double* __restrict y, const double* __restrict z,                       \
      std::uint32_t* __restrict rnd, double* __restrict outX, double* __restrict outY, double* __restrict outZ, \
      std::size_t n, double w, const double* __restrict P, const double* __restrict A);                         \
  VOXFLAME_VARIATION_TARGETS void name(const VariationInput& in, double* ox, double* oy, double* oz) {          \
    name##Body(in.x, in.y, in.z, in.random, ox, oy, oz, in.count, in.weight, in.params, in.affine);             \
  }                                                                                                             \
  [[gnu::always_inline]] inline void name##Body(                                                                \
      [[maybe_unused]] const double* __restrict x, [[maybe_unused]] const double* __restrict y,                 \
      [[maybe_unused]] const double* __restrict z, [[maybe_unused]] std::uint32_t* __restrict rnd,              \
      [[maybe_unused]] double* __restrict outX, [[maybe_unused]] double* __restrict outY,                       \
      [[maybe_unused]] double* __restrict outZ, std::size_t n, [[maybe_unused]] double w,                       \
      [[maybe_unused]] const double* __restrict P, [[maybe_unused]] const double* __restrict A)

// linear: (x, y, z)
VARIATION(linear) {
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * x[i];
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
  }
}

// sinusoidal: (sin x, sin y, z)
VARIATION(sinusoidal) {
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * std::sin(x[i]);
    outY[i] += w * std::sin(y[i]);
    outZ[i] += w * z[i];
  }
}

// spherical: (x, y) / r², z
VARIATION(spherical) {
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (x[i] * x[i] + y[i] * y[i] + kEpsilon);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * z[i];
  }
}

// swirl: (x sin r² − y cos r², x cos r² + y sin r², z)
VARIATION(swirl) {
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double s = std::sin(r2), c = std::cos(r2);
    outX[i] += w * (x[i] * s - y[i] * c);
    outY[i] += w * (x[i] * c + y[i] * s);
    outZ[i] += w * z[i];
  }
}

// julia: √r (cos(θ/2 + Ω), sin(θ/2 + Ω)), z, with Ω = 0 or π at random (θ = atan2(x, y) as flam3)
VARIATION(julia) {
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 0.5 * std::atan2(x[i], y[i]) + (laneUniform(rnd[i]) < 0.5 ? 0.0 : kPi);
    const double r = w * std::sqrt(std::sqrt(x[i] * x[i] + y[i] * y[i]));
    outX[i] += r * std::cos(angle);
    outY[i] += r * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

// spherical3D: (x, y, z) / (x² + y² + z²)
VARIATION(spherical3D) {
  for (std::size_t i = 0; i < n; ++i) {
    const double s = w / (x[i] * x[i] + y[i] * y[i] + z[i] * z[i] + kEpsilon);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += s * z[i];
  }
}

// zscale: (0, 0, z) — with linear, weight w stretches depth by (1 + w)
VARIATION(zscale) {
  for (std::size_t i = 0; i < n; ++i) outZ[i] += w * z[i];
}

#undef VARIATION
#undef VOXFLAME_VARIATION_TARGETS

std::vector<VariationInfo> buildCatalogue() {
  std::vector<VariationInfo> c;
  const auto add = [&](std::string name, std::string formula, bool threeD, bool random, VariationFn fn,
                       std::vector<VariationParam> params = {}) {
    VariationInfo info;
    info.name = std::move(name);
    info.formula = std::move(formula);
    info.threeD = threeD;
    info.random = random;
    info.apply = fn;
    info.params = std::move(params);
    c.push_back(std::move(info));
  };
  add("linear", "(x, y, z)", false, false, &linear);
  add("sinusoidal", "(sin x, sin y, z)", false, false, &sinusoidal);
  add("spherical", "(x, y) / r², z", false, false, &spherical);
  add("swirl", "(x sin r² − y cos r², x cos r² + y sin r², z)", false, false, &swirl);
  add("julia", "√r (cos(θ/2 + Ω), sin(θ/2 + Ω)), z; Ω = 0 or π at random", false, true, &julia);
  add("spherical3D", "(x, y, z) / (x² + y² + z²)", true, false, &spherical3D);
  add("zscale", "(0, 0, z): with linear, stretches depth", true, false, &zscale);
  return c;
}

}  // namespace

int VariationInfo::paramIndex(std::string_view paramName) const {
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].name == paramName) return static_cast<int>(i);
  return -1;
}

std::vector<double> VariationInfo::defaultParams() const {
  std::vector<double> values;
  values.reserve(params.size());
  for (const auto& p : params) values.push_back(p.defaultValue);
  return values;
}

const std::vector<VariationInfo>& variationCatalogue() {
  static const std::vector<VariationInfo> catalogue = buildCatalogue();
  return catalogue;
}

const VariationInfo* findVariation(std::string_view name) {
  for (const auto& info : variationCatalogue())
    if (info.name == name) return &info;
  return nullptr;
}

const VariationInfo& variationOrThrow(std::string_view name) {
  if (const VariationInfo* info = findVariation(name)) return *info;
  // Names that share a prefix or differ only in case are the likely typos.
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return std::tolower(ch); });
  std::string close;
  for (const auto& info : variationCatalogue()) {
    std::string candidate = info.name;
    std::transform(candidate.begin(), candidate.end(), candidate.begin(),
                   [](unsigned char ch) { return std::tolower(ch); });
    if (!lower.empty() && (candidate.rfind(lower.substr(0, 3), 0) == 0 || candidate == lower))
      close += (close.empty() ? "" : ", ") + info.name;
  }
  throw Error(
      "'" + std::string(name) + "' is not a known variation" +
      (close.empty() ? std::string("; `voxflame list --variations` lists them") : "; did you mean " + close + "?"));
}

}  // namespace voxflame::core
