// What the files of the variation catalogue share (flame_variations.cpp and
// flame_variations_more.cpp): the constants, the prologue every variation function opens with, the
// build targets, and the one way entries are added to the catalogue. Internal to those files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "flame_variations.h"

namespace voxflame::core::variation_kernels {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Fractorium's Zeps(): a zero divisor becomes the double's machine epsilon. Used where the flames
// that need a variation come from Fractorium, so they draw as Fractorium draws them.
inline constexpr double kFractoriumEps = std::numeric_limits<double>::epsilon();
inline double fractoriumZeps(double value) {
  return value == 0.0 ? kFractoriumEps : value;
}

// Adds entries to a catalogue: name, formula, 2D/3D, random or not, the function, parameters.
class CatalogueAdder {
 public:
  static constexpr bool k2D = false, k3D = true, kRandom = true, kFixed = false;
  explicit CatalogueAdder(std::vector<VariationInfo>& catalogue) : catalogue_(catalogue) {}
  void operator()(std::string name, std::string formula, bool threeD, bool random, VariationFn fn,
                  std::vector<VariationParam> params = {}) const {
    VariationInfo info;
    info.name = std::move(name);
    info.formula = std::move(formula);
    info.threeD = threeD;
    info.random = random;
    info.apply = fn;
    info.params = std::move(params);
    catalogue_.push_back(std::move(info));
  }
  // A count parameter (sides, power, slices): rounded where used.
  static VariationParam count(std::string name, double value, double low, double high) {
    return VariationParam{std::move(name), value, low, high, true};
  }

 private:
  std::vector<VariationInfo>& catalogue_;
};

}  // namespace voxflame::core::variation_kernels

// The arrays of a variation call as restrict-qualified locals: GCC vectorises loops over arrays it
// knows do not alias. The outputs must carry `__restrict` in the function's own parameters too:
// GCC 12 does not vectorise stores through a restrict local copied from an unqualified parameter
// (it left even `linear` scalar). Loops that call sin, cos, atan2 or pow stay scalar, as libm has
// no vector variants without -ffast-math; those without such calls vectorise.
#define VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz) \
  const double* __restrict x = (in).x;           \
  const double* __restrict y = (in).y;           \
  const double* __restrict z = (in).z;           \
  std::uint32_t* __restrict rnd = (in).random;   \
  double* __restrict outX = (ox);                \
  double* __restrict outY = (oy);                \
  double* __restrict outZ = (oz);                \
  const std::size_t n = (in).count;              \
  const double w = (in).weight;                  \
  const double* __restrict P = (in).params;      \
  (void)x;                                       \
  (void)y;                                       \
  (void)z;                                       \
  (void)rnd;                                     \
  (void)outX;                                    \
  (void)outY;                                    \
  (void)w;                                       \
  (void)P;

// Each variation is built for AVX2 and for any x86-64, picked when the program loads: with AVX2
// the loops that vectorise run four lanes at a time.
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__SANITIZE_THREAD__)
#define VOXFLAME_VARIATION_TARGETS [[gnu::target_clones("avx2", "default")]]
#else
#define VOXFLAME_VARIATION_TARGETS
#endif
