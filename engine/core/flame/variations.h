// The variation catalogue of 3D fractal flames: the non-linear functions a flame transform applies
// after its affine map (Draves & Reckase, "The Fractal Flame Algorithm", 2003, and the 3D ones that
// Apophysis 3D and JWildfire added). Each variation is data (name, parameters with defaults and
// slider ranges, the formula in words) plus one function that adds `weight · V(p)` for a whole
// group of chaos-game lanes at once: plain loops over arrays, so the compiler vectorises the
// arithmetic and no indirect call is made per point.
//
// Conventions for the formulas (flam3's names): p = (x, y, z) is the point after the transform's
// affine map, r² = x² + y², r = √r², θ = atan2(x, y) (flam3's "theta", x first), φ = atan2(y, x)
// (flam3's "phi"), a–f the transform's 2D affine coefficients as flam3 writes them (a = m00,
// b = m01, c = t0, d = m10, e = m11, f = t1). A 2D variation maps x and y and carries z through
// (adds weight · z to z), which is what Apophysis 3D and JWildfire do. Ψ is a uniform random
// number in [0, 1) drawn from the lane's own generator (laneUniform), so lanes never share a draw.
// ε is flam3's 1e-10, added exactly where flam3 adds it, so imported flames draw as in flam3; where
// flam3 divides by r unguarded (sin θ = x / r), a far smaller guard keeps the origin finite.
// presets/VARIATIONS.md lists every variation with its formula (variationsMarkdown below).
//
// Every variation also has a pre_ and a post_ form (`pre_spherical`, `post_curl`), as Apophysis 7X,
// JWildfire and Fractorium have them: a transform applies its pre_ terms in order to the point
// after its affine map, before its other variations, and its post_ terms in order to their sum,
// before its post-affine. Such a term replaces the coordinates its variation maps (x and y for a 2D
// one, z too for a 3D one, z alone for zscale/zcone/zblur/ztranslate/inflateZ_3/flatten) by weight · V(p)
// and keeps the others, except that a variation whose result does not depend on the point (blur,
// noise-like ones: `additive`) adds weight · V(p) instead, which is Fractorium's rule ("assign" vs
// "sum"). The catalogue's own pre_blur (flam3's) is such an additive Gaussian blur.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace voxflame::core {

// One xorshift32 step (Marsaglia 2003) per lane: shifts and xors only, so loops that draw random
// numbers still vectorise. The state is never 0.
[[gnu::always_inline]] inline std::uint32_t laneNext(std::uint32_t r) {
  r ^= r << 13;
  r ^= r >> 17;
  r ^= r << 5;
  return r;
}
// Advances the lane's state and returns a uniform number in [0, 1) from its top 24 bits.
[[gnu::always_inline]] inline double laneUniform(std::uint32_t& state) {
  state = laneNext(state);
  return static_cast<double>(static_cast<std::int32_t>(state >> 8)) * 0x1p-24;
}

// Where in its transform a variation term acts: its name's pre_/post_ prefix (see above); the
// catalogue's own pre_blur acts at the pre_ stage too.
enum class VariationStage { Pre, Normal, Post };

// What a variation sees for one group of lanes (all lanes that chose the same transform this step).
struct VariationInput {
  const double* x = nullptr;  // the point after the transform's affine map
  const double* y = nullptr;
  const double* z = nullptr;
  std::uint32_t* random = nullptr;  // one generator state per lane (advanced by variations that draw)
  std::size_t count = 0;
  double weight = 1.0;
  const double* params = nullptr;  // the variation's parameters, in the catalogue's order
  const double* affine = nullptr;  // the transform's pre-affine, row-major 3×4 (see flame.h)
  // The transform's point after its affine map and pre_ terms, which its ordinary terms map: for
  // pre_ and ordinary terms the same arrays as x, y, z; for a post_ term the point that the sum it
  // maps came from (Fractorium's depth adds it).
  const double* tx = nullptr;
  const double* ty = nullptr;
  const double* tz = nullptr;
  // The point's colour index per lane, as the transform's colour blend left it (flam3's, 0–1):
  // direct-colour variations (VariationInfo::directColour) read it and may overwrite it, and the
  // transform then blends the result in by its direct_color. The chaos game always passes it.
  double* colour = nullptr;
  // The stage the term acts at: some direct-colour variations (dc_linear) colour by the running
  // sum of an ordinary term but by the input point of a pre_/post_ one, as Fractorium does.
  VariationStage stage = VariationStage::Normal;
  // For an ordinary term in the chaos game, the transform's point (the arrays x, y and tx, ty read)
  // writable, else nullptr: Fractorium's crob moves the point that the terms after it map. A
  // variation that writes it reads x and y through unrestricted pointers, as they alias.
  double* movableX = nullptr;
  double* movableY = nullptr;
  // The term's text parameter (VariationInfo::textParam: subflame_wf's embedded flame), empty when
  // the variation has none or the term leaves it unset.
  std::string_view text;
};

// Adds weight · V(p) to (outX, outY, outZ) for every lane of `in`.
using VariationFn = void (*)(const VariationInput& in, double* outX, double* outY, double* outZ);

struct VariationParam {
  std::string name;
  double defaultValue = 0.0;
  double sliderMin = 0.0;
  double sliderMax = 1.0;
  bool integer = false;  // a count (sides, power, slices): rounded where used, 0 taken as 1
  // JWildfire holds it as an int where voxflame takes flam3's real number (julian's power): used
  // as it is, but a weighting field's scaled value of it is rounded (JWildfire's Tools.FTOI), as
  // that of an `integer` one is.
  bool jwildfireInt = false;
};

struct VariationInfo {
  std::string name;  // flam3's / JWildfire's name: what flame files say
  std::vector<VariationParam> params;
  std::string formula;  // V(p) in the notation above, for the docs and the UI's tooltip
  bool threeD = false;  // acts on z itself (not only carried through)
  bool random = false;  // draws random numbers (Ψ)
  bool mapsXY = true;   // false for the variations that act on z alone (zscale, zcone, ...)
  // Its result does not depend on the point (blurs, ztranslate): a pre_/post_ form adds to the
  // point instead of replacing it. Worked out from the function when the catalogue is built.
  bool additive = false;
  // What of the sum of the ordinary terms before it an ordinary term of this variation discards:
  // JWildfire's shredlin and crop_trapezoid assign x and y where others add them, Fractorium's
  // mirror_x/y/z clear all three, Fractorium's extrude and juliaNab z alone. The chaos game clears
  // those coordinates before the term adds.
  enum class Replaces { Nothing, XY, XYZ, Z };
  Replaces replaces = Replaces::Nothing;
  // An ordinary term of it reads the sum of the ordinary terms before it from the output arrays
  // (which hold that sum when it is called) and may rewrite it: Fractorium's cubic3D, octapol,
  // roundspher3D. Under a weighting field the chaos game hands it the sum and scales its change.
  bool readsSum = false;
  // Reads or writes the point's colour index (VariationInput::colour): Fractorium's dc_ variations.
  // The chaos game sets up the colour array and blends by direct_color only for transforms with one.
  bool directColour = false;
  // The name of the variation's one text parameter, empty when it has none: JWildfire's subflame
  // variations carry a whole flame as text (VariationTerm::text, VariationInput::text). Files and
  // scenes write it under this name beside the numeric parameters. The catalogue does not run such a
  // variation while it is being built (its text may name other variations), so `additive` is set by
  // its table row.
  std::string textParam;
  VariationFn apply = nullptr;

  int paramIndex(std::string_view paramName) const;  // -1 when absent
  std::vector<double> defaultParams() const;
};

VariationStage variationStage(std::string_view name);

const std::vector<VariationInfo>& variationCatalogue();
// The entry a term's name means: the catalogue's own, or for pre_X and post_X that of X. nullptr
// when unknown.
const VariationInfo* findVariation(std::string_view name);
const VariationInfo& variationOrThrow(std::string_view name);  // core::Error naming close matches

// presets/VARIATIONS.md: the catalogue as a Markdown table (name, 2D/3D, parameters with defaults
// and slider ranges, formula). A test keeps the committed file equal to this text.
std::string variationsMarkdown();

}  // namespace voxflame::core
