// What the files of the variation catalogue share (flame/variations_*.cpp, one per family): the
// constants and helpers, the prologue every variation function opens with, the build targets, the
// one way entries are added to the catalogue, and each family's table function. Internal to those
// files and catalogue.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/flame/variations.h"

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
  // A real number here (flam3's), an int in JWildfire (VariationParam::jwildfireInt).
  static VariationParam jwildfireInt(std::string name, double value, double low, double high) {
    return VariationParam{std::move(name), value, low, high, false, true};
  }

 private:
  std::vector<VariationInfo>& catalogue_;
};

using namespace variation_kernels;

// Our own guard where flam3 divides by r unguarded (sin θ = x / r at the origin would be 0/0): small
// enough to change no result away from the origin.
constexpr double kEpsilon = 1e-300;
// flam3's EPS, used exactly where flam3 adds it (to a parameter such as rings' c² or to a
// denominator), so imported flames come out as flam3 draws them.
constexpr double kFlam3Eps = 1e-10;

// A count parameter (sides, power, slices) as used: rounded, 0 taken as 1 so nothing divides by 0.
// Stays a double: converting a huge or NaN value to an integer would be undefined behaviour.
inline double countParam(double value) {
  const double rounded = std::round(value);
  return rounded == 0.0 ? 1.0 : rounded;
}

// std::fmod(a, m) in a form GCC vectorises: libm's fmod has no vector variant (vector_math.h), and
// one scalar call keeps the whole loop scalar. a − m·trunc(a/m), moved back into fmod's range (the
// sign of a, magnitude below |m|) when the rounded quotient is one off; it differs from the exact
// fmod by at most an ulp of a. NaN where fmod is NaN (an infinite a, a zero m).
inline double laneFmod(double a, double m) {
  const double am = std::abs(m);
  double r = a - std::trunc(a / m) * m;
  r = a >= 0.0 ? (r < 0.0 ? r + am : r) : (r > 0.0 ? r - am : r);
  return a >= 0.0 ? (r >= am ? r - am : r) : (r <= -am ? r + am : r);
}

// flam3's own count-like parameters (julian's power, pie's slices, ngon's sides) are real numbers
// there, and files hold values such as 3.8967: used as they are, with 0 taken as 1 as above.
inline double flam3Count(double value) {
  return value == 0.0 ? 1.0 : value;
}

// Apophysis' rounding (Fractorium's LRint): half away from zero, through a 64-bit integer; values
// beyond its range are whole numbers already and stay as they are (NaN too).
inline double apophysisRound(double v) {
  if (!(std::abs(v) < 0x1p62)) return v;
  return static_cast<double>(static_cast<std::int64_t>(v >= 0.0 ? v + 0.5 : v - 0.5));
}

// flam3's affine coefficients inside the row-major 3×4 pre-affine (see flame.h).
constexpr std::size_t kAffineB = 1;  // m01
constexpr std::size_t kAffineC = 3;  // t0
constexpr std::size_t kAffineE = 5;  // m11
constexpr std::size_t kAffineF = 7;  // t1

// JWildfire's MathLib.EPSILON, used exactly where JWildfire adds or compares with it.
constexpr double kJwfEpsilon = 1e-8;

// ---- Fractorium's parameter rules --------------------------------------------------------------

// Fractorium rounds an integer parameter (⌊v + ½⌋) and clamps it into its range when it is set.
inline double fractoriumInteger(double value, double low, double high) {
  return std::clamp(std::floor(value + 0.5), low, high);
}

// Apophysis' log map and log scale (Fractorium's VarFuncs), used by falloff3's third blur.
inline double signNz(double value) {
  return value < 0.0 ? -1.0 : 1.0;
}
inline double logMap(double value) {
  return value == 0.0 ? 0.0 : (std::numbers::e + std::log(value * std::numbers::e)) * 0.25 * signNz(value);
}
inline double logScale(double value) {
  return value == 0.0 ? 0.0 : std::log((std::abs(value) + 1.0) * std::numbers::e) * signNz(value) / std::numbers::e;
}

// ---- Java's integer arithmetic -------------------------------------------------------------------

// Java's (int) of a double: truncation towards 0, saturating at the int range, NaN as 0.
inline std::int32_t javaInt(double value) {
  if (std::isnan(value)) return 0;
  if (value >= 2147483647.0) return std::numeric_limits<std::int32_t>::max();
  if (value <= -2147483648.0) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(value);
}

// A painted pixel of a picture JWildfire's svg_wf and text_wf draw from: pixel ⌊Ψ₁ count⌋ of (px, py),
// moved by JWildfire's blur (e^{radius √(−ln(1 − Ψ₂))} − 1) / 1000 along 2πΨ₃ when radius > 0.01 (JWildfire
// takes −ln Ψ₂, infinite at 0; 1 − Ψ₂ has the same distribution and never is). count must be at least 1.
inline void pickBlurredPixel(const double* px, const double* py, std::size_t count, double radius, std::uint32_t& state,
                             double& x, double& y) {
  const auto k = std::min(static_cast<std::size_t>(laneUniform(state) * static_cast<double>(count)), count - 1);
  x = px[k];
  y = py[k];
  if (radius > 0.01) {
    const double dr = (std::exp(radius * std::sqrt(-std::log(1.0 - laneUniform(state)))) - 1.0) * 0.001;
    const double da = laneUniform(state) * kTwoPi;
    x += dr * std::cos(da);
    y += dr * std::sin(da);
  }
}

// JWildfire's dbl2int of a colour channel in [0, 1]: ⌊256 c⌋ as Java's int, held within 0 … 255 (a byte).
inline double rgbByte(double c) {
  return std::clamp(static_cast<double>(javaInt(std::floor(c * 256.0))), 0.0, 255.0);
}
// Java's int + and ×, which wrap around.
inline std::int32_t wrapAdd(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b));
}
inline std::int32_t wrapMul(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) * static_cast<std::uint32_t>(b));
}

// The sum of four uniforms less 2: flam3's cheap bell-shaped number in (−2, 2).
[[gnu::always_inline]] inline double laneGauss(std::uint32_t& state) {
  const double a = laneUniform(state), b = laneUniform(state), c = laneUniform(state), d = laneUniform(state);
  return a + b + c + d - 2.0;
}

// What a variation builds from its parameters alone and draws from at every call (hopalong's
// orbit, svg_wf's painted pixels, subflame_wf's cloud of an embedded flame), shared so that a render
// builds each once: every thread keeps the last one it used (`last`, a thread_local of the caller),
// and the `kept` most recent ones are kept for all threads (an animation changes the parameters
// every frame). `same(value)` says whether a kept one is for these parameters; `build()` makes a new
// one, under the lock, so one thread builds while the others wait for it instead of building too.
template <class Value>
class RecentBuilds {
 public:
  explicit RecentBuilds(std::size_t kept) : kept_(kept) {}
  template <class Same, class Build>
  std::shared_ptr<const Value> get(std::shared_ptr<const Value>& last, const Same& same, const Build& build) {
    if (last && same(*last)) return last;
    const std::scoped_lock lock(mutex_);
    for (const auto& value : recent_)
      if (same(*value)) return last = value;
    std::shared_ptr<const Value> built = build();
    if (recent_.size() >= kept_) recent_.erase(recent_.begin());
    recent_.push_back(built);
    return last = built;
  }

 private:
  std::size_t kept_;
  std::mutex mutex_;
  std::vector<std::shared_ptr<const Value>> recent_;
};

// The families' tables (one file each), in the catalogue's order.
void addFlam3ClassicVariations(std::vector<VariationInfo>& catalogue);
void add3DVariations(std::vector<VariationInfo>& catalogue);
void addFlam3Variations(std::vector<VariationInfo>& catalogue);
void addApophysisVariations(std::vector<VariationInfo>& catalogue);
void addPluginVariations(std::vector<VariationInfo>& catalogue);
void addFractoriumVariations(std::vector<VariationInfo>& catalogue);
void addJwildfireVariations(std::vector<VariationInfo>& catalogue);
void addFractorium2dMVariations(std::vector<VariationInfo>& catalogue);
void addFractorium2dSVariations(std::vector<VariationInfo>& catalogue);
void addFractoriumTruchetVariations(std::vector<VariationInfo>& catalogue);
void addQuaternionVariations(std::vector<VariationInfo>& catalogue);
void addFractorium3DShapeVariations(std::vector<VariationInfo>& catalogue);
void addFractorium3DMoreVariations(std::vector<VariationInfo>& catalogue);
void addFractoriumRandom2DVariations(std::vector<VariationInfo>& catalogue);
void addDirectColourVariations(std::vector<VariationInfo>& catalogue);
void addBlurVariations(std::vector<VariationInfo>& catalogue);
// Fractorium's other 2D variations (variations_2d_*.cpp).
void addFractorium2DVariationsA(std::vector<VariationInfo>& catalogue);
void addFractorium2DVariationsB(std::vector<VariationInfo>& catalogue);
void addFractorium2DVariationsC(std::vector<VariationInfo>& catalogue);
void addFractorium2DVariationsD(std::vector<VariationInfo>& catalogue);
void addJwildfireShapeVariations(std::vector<VariationInfo>& catalogue);
void addJwildfireMoreVariations(std::vector<VariationInfo>& catalogue);
void addJwildfireTailVariations(std::vector<VariationInfo>& catalogue);
// Fractorium's remaining random 2D ones (variations_blurs_more.cpp) and the 3D ones that read the
// running sum (variations_3d_sum.cpp).
void addFractoriumBlursMoreVariations(std::vector<VariationInfo>& catalogue);
void addFractorium3DSumVariations(std::vector<VariationInfo>& catalogue);
// Variations that flames of the shared corpus need (variations_jwildfire_corpus.cpp).
void addJwildfireCorpusVariations(std::vector<VariationInfo>& catalogue);
// JWildfire variations that published JWildfire flames use (variations_jwildfire_holdout.cpp).
void addJwildfireHoldoutVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's svg_wf, points of an SVG drawing (variations_svg.cpp).
void addSvgVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's colormap_wf, colour from a picture laid over the plane (variations_colormap.cpp).
void addColormapVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's subflame variations, which embed a whole flame (variations_subflame.cpp).
void addSubflameVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's parplot2d_wf, a parametric surface of formulas (variations_parplot.cpp).
void addParplotVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's obj_mesh_primitive_wf, points on built-in meshes (variations_jwildfire_mesh.cpp).
void addJwildfireMeshVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's text_wf, points of a line of text drawn by FreeType (variations_text.cpp).
void addTextVariations(std::vector<VariationInfo>& catalogue);
// JWildfire's glsl_apollonian, dc_crackle_wf and fract_mandelbrot_wf (variations_jwildfire_glsl.cpp).
void addJwildfireGlslVariations(std::vector<VariationInfo>& catalogue);
// JWildfire variations that flames in public repositories use: mandelbrot, invsquircular, sph3D, colorscale_wf,
// bubble_wf, bwraps2, invpolar, threeply, spligon, lazysensen, disc3, cpow3_wf (variations_jwildfire_wild.cpp).
void addJwildfireWildVariations(std::vector<VariationInfo>& catalogue);
// JWildfire variations that a few published flames use: polarplot3d_wf, isosfplot3d_wf, sunflower,
// dc_warping (variations_jwildfire_rare.cpp).
void addJwildfireRareVariations(std::vector<VariationInfo>& catalogue);
// Rarer plugins that published flames use: JWildfire's sym_bg2, sym_ng11, sym_ng15, glsl_circlesblue, glsl_grid3D,
// glsl_mandala and glsl_acrilic, flam3's original secant and the Apophysis plugins julian2dc and shape
// (variations_plugins_rare.cpp).
void addPluginsRareVariations(std::vector<VariationInfo>& catalogue);

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
  double* __restrict colour = (in).colour;       \
  (void)x;                                       \
  (void)y;                                       \
  (void)z;                                       \
  (void)rnd;                                     \
  (void)outX;                                    \
  (void)outY;                                    \
  (void)w;                                       \
  (void)P;                                       \
  (void)colour;

// Each variation is built for AVX2 and for any x86-64, picked when the program loads: with AVX2
// the loops that vectorise run four lanes at a time.
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__SANITIZE_THREAD__)
#define VOXFLAME_VARIATION_TARGETS [[gnu::target_clones("avx2", "default")]]
#else
#define VOXFLAME_VARIATION_TARGETS
#endif

// A shorthand for the common shape: a loop over the lanes with x, y, z and the lane's random state
// in scope, where the body adds to outX[i] and outY[i]; z is carried through.
#define VOXFLAME_VARIATION_2D(fn, ...)                                                                       \
  VOXFLAME_VARIATION_TARGETS void fn(const VariationInput& in, double* __restrict ox, double* __restrict oy, \
                                     double* __restrict oz) {                                                \
    VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)                                                                 \
    for (std::size_t i = 0; i < n; ++i) {                                                                    \
      __VA_ARGS__                                                                                            \
      outZ[i] += w * z[i];                                                                                   \
    }                                                                                                        \
  }
