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
  // The variation's text parameters (VariationInfo::textParams), in the catalogue's order, or
  // nullptr: then their defaults hold. JWildfire's svg_wf reads its picture from one.
  const std::string* texts = nullptr;
  // Per-lane memory that lasts from step to step, for a variation with VariationInfo::laneState > 0
  // (Fractorium's smartcrop keeps the last point it let through): lane i of this call owns
  // laneState doubles at state + laneState · (lanes ? lanes[i] : i), all 0 at first. nullptr where
  // no game keeps it (a single evaluation): the variation then starts from zeros each call.
  double* state = nullptr;
  const std::uint32_t* lanes = nullptr;
  // JWildfire's true colour per point (XYZPoint.rgbColor): a variation that paints an RGB colour
  // instead of (or besides) a colour index (VariationInfo::paintsRgb) writes paintedRgb(r, g, b) to
  // lane i's entry; the chaos game clears the entries before each transform, since JWildfire's flag
  // lasts one transform only. nullptr where nothing draws the colour (a single evaluation, or a
  // transform without such a variation): the variation then paints nothing.
  std::uint32_t* rgb = nullptr;
  // The flame's palette as the file writes it, 256 entries of r | g << 8 | b << 16 (bytes), for
  // the variations that pick the palette's entry nearest to a colour; nullptr outside a game.
  const std::uint32_t* palette = nullptr;
  // JWildfire's XYZPoint.doHide per lane: 1 where the point is not drawn. It lasts from step to step (a
  // point stays hidden until a variation that hides points says otherwise), so it comes in as the lane's
  // flag and a variation that hides points (VariationInfo::hidesPoints) may set or clear it. nullptr where
  // nothing keeps it (a single evaluation, or a transform without such a variation).
  std::uint8_t* hidden = nullptr;
};

// A painted true colour as VariationInput::rgb holds it: the channels (bytes) with kRgbPainted set,
// so 0 means "not painted, the colour index's palette entry".
inline constexpr std::uint32_t kRgbPainted = 1u << 24;
inline constexpr std::uint32_t paintedRgb(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return kRgbPainted | (r & 255u) | (g & 255u) << 8 | (b & 255u) << 16;
}
// The entry of a packed 256-entry palette nearest to (r, g, b) in RGB distance, the first of equals:
// JWildfire's DC_BaseFunc.findKey and SVGWFFunc.getColorIdx. `scale` multiplies the palette's
// channels first: colormap_wf's getColorIdx matches against JWildfire's render palette, the
// gradient scaled by 200/256.
inline std::size_t nearestPaletteEntry(const std::uint32_t* palette, std::int32_t red, std::int32_t green,
                                       std::int32_t blue, double scale = 1.0) {
  std::size_t best = 0;
  double bestDistance = 0.0;
  for (std::size_t k = 0; k < 256; ++k) {
    const double dr = static_cast<double>(palette[k] & 255u) * scale - red;
    const double dg = static_cast<double>(palette[k] >> 8 & 255u) * scale - green;
    const double db = static_cast<double>(palette[k] >> 16 & 255u) * scale - blue;
    const double d = dr * dr + dg * dg + db * db;
    if (k == 0 || d < bestDistance) {
      bestDistance = d;
      best = k;
    }
  }
  return best;
}

// Adds weight · V(p) to (outX, outY, outZ) for every lane of `in`.
using VariationFn = void (*)(const VariationInput& in, double* outX, double* outY, double* outZ);
// What a kernel picks from, as it builds it once per parameter set (and text) and keeps it, as
// numbers in the kernel's own layout (svg_wf's pixels and hopalong's orbit: (x, y) pairs;
// obj_mesh_primitive_wf: its faces). `texts`: the term's text parameters (the defaults where it has none).
using VariationTableFn = std::vector<double> (*)(const double* params, const std::string* texts);

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

// A parameter whose value is text (JWildfire's "resources": svg_wf's SVG document).
struct VariationTextParam {
  std::string name;
  std::string defaultValue;
};

struct VariationInfo {
  std::string name;  // flam3's / JWildfire's name: what flame files say
  std::vector<VariationParam> params;
  std::vector<VariationTextParam> textParams;  // after the numbers; VariationTerm::texts holds them
  std::string formula;                         // V(p) in the notation above, for the docs and the UI's tooltip
  bool threeD = false;                         // acts on z itself (not only carried through)
  bool random = false;                         // draws random numbers (Ψ)
  bool mapsXY = true;                          // false for the variations that act on z alone (zscale, zcone, ...)
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
  // May paint a point's true colour (VariationInput::rgb), JWildfire's XYZPoint.rgbColor: dc_quadtree's
  // Gradient 0. The chaos game keeps true colours only for flames with such a variation.
  bool paintsRgb = false;
  // May hide a point (VariationInput::hidden), JWildfire's XYZPoint.doHide: colormap_wf's with_alpha.
  bool hidesPoints = false;
  // How many doubles of memory per lane the variation keeps from step to step (VariationInput::state).
  std::size_t laneState = 0;
  VariationFn apply = nullptr;
  // For a kernel that picks from a table it builds (svg_wf's pixels, hopalong's orbit, a mesh's
  // faces): the table, for a backend that runs its own copy of the kernel (the GPU's); nullptr for
  // the others.
  VariationTableFn table = nullptr;

  int paramIndex(std::string_view paramName) const;  // -1 when absent
  std::vector<double> defaultParams() const;
  int textParamIndex(std::string_view paramName) const;  // -1 when absent
  std::vector<std::string> defaultTexts() const;
  // A term's text parameters as its kernel takes them: `texts` where it gives them all, else the defaults.
  std::vector<std::string> textsFor(const std::vector<std::string>& texts) const;
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
