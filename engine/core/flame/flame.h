// Chaos-game patterns: 3D fractal flames and quaternion Julia sets. Unlike the attractors of
// attractor.h (one deterministic map or flow), these pick one of several maps at random at every
// step; the points then fill a fractal set (an IFS attractor) whose density and colour are the
// picture. A flame is Draves & Reckase's algorithm ("The Fractal Flame Algorithm", 2003) lifted
// into 3D: transforms ("xforms"), each an affine map followed by a weighted sum of variations
// (flame/variations.h) and an optional post-affine, chosen with probability proportional to their
// weights; an optional final transform bends what is drawn without feeding back; optional
// rotational and mirror symmetry. Colour is flam3's: each point carries a colour index in [0, 1]
// that moves towards the chosen transform's colour by its colour speed, and indexes the layer's
// gradient or palette.
//
// A quaternion Julia set (Norton 1982; Hart, Sandin & Kauffman 1989) is drawn by inverse iteration:
// q ← ±√(q − c) with a random root at every step, which samples the set's boundary.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace voxflame::core {

inline constexpr std::size_t kMaxFlameXforms = 128;
// Final transforms after the first that a flame may chain (FlameGenome::chainedFinals).
inline constexpr std::size_t kMaxChainedFinals = 16;
inline constexpr std::size_t kMaxXformVariations = 16;
inline constexpr int kMaxFlameSymmetry = 127;
// The largest magnitude a flame's numbers may have (affine and post coefficients, transform and variation weights,
// xaos factors): the validator, the flame importer and the preset schema all refuse beyond it.
inline constexpr double kFlameCoefficientLimit = 1e6;

// p ↦ M p + t, stored row-major as a 3×4 matrix: [m00 m01 m02 t0, m10 m11 m12 t1, m20 m21 m22 t2].
// flam3's 2D coefficients map onto it as a = m00, b = m01, c = t0, d = m10, e = m11, f = t1.
struct Affine3 {
  std::array<double, 12> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  glm::dvec3 apply(glm::dvec3 p) const {
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
  }
  bool isIdentity() const { return *this == Affine3{}; }
  bool operator==(const Affine3&) const = default;
};

// JWildfire's weighting fields: a noise n(p) over space (roughly in [−1, 1]) that a transform
// reads at each point, p the point after the transform's affine map (input `affine`) or the point
// it starts from (`position`), and that drives, each by its own intensity:
//  * amount: each variation's weight becomes weight · (1 + amount · n);
//  * params (up to three): a parameter of the transform's variations of one name becomes
//    value · (1 + intensity · n) for that point (a count rounded), or, for the parameter `amount`,
//    that variation's weight alone is scaled so;
//  * color: after the colour blend the point's colour index becomes c · (1 + 0.1 · color · n);
//  * jitter: after the post map each coordinate of the result q moves by 0.1 · jitter · n(q), n
//    read at q with its coordinates turned (x by n(x, y, z), then y by n(y, x, z), z by n(z, x, y)).
// Noise kinds: `noise` is one noise of the family `noise` at `frequency`, `fractal` sums
// `octaves` of it, each `lacunarity` times finer and `gain` times weaker (FastNoise's fractal
// sums: fbm, billow or rigid). The families are JWildfire's (FastNoise's): simplex, Perlin
// (gradient noise on the cube lattice), value (lattice values, smoothly blended), cubic (lattice
// values, cubic interpolation), cellular (Worley: distances to jittered lattice points, by
// `cell_distance`, returned as `cell_return` says) and white (a value per coordinate). `seed`
// picks another noise of the same family: voxflame's hashes and tables, so the same kind of
// field at the same frequency as JWildfire's, not the same values.
enum class WeightFieldKind { None, Noise, Fractal };
inline constexpr std::string_view kWeightFieldKindNames[] = {"none", "noise", "fractal"};
enum class WeightFieldInput { Affine, Position };
inline constexpr std::string_view kWeightFieldInputNames[] = {"affine", "position"};
enum class WeightFieldFractal { Fbm, Billow, Rigid };
inline constexpr std::string_view kWeightFieldFractalNames[] = {"fbm", "billow", "rigid"};
enum class WeightFieldNoise { Simplex, Perlin, Value, Cubic, Cellular, White };
inline constexpr std::string_view kWeightFieldNoiseNames[] = {"simplex", "perlin",   "value",
                                                              "cubic",   "cellular", "white"};
enum class CellDistance { Euclidean, Manhattan, Natural };
inline constexpr std::string_view kCellDistanceNames[] = {"euclidean", "manhattan", "natural"};
enum class CellReturn { CellValue, Distance, Distance2, Distance2Add, Distance2Sub, Distance2Mul, Distance2Div };
inline constexpr std::string_view kCellReturnNames[] = {
    "cell_value", "distance", "distance2", "distance2_add", "distance2_sub", "distance2_mul", "distance2_div"};
inline constexpr int kMaxWeightFieldOctaves = 10;

// One variation of a transform: its catalogue name, weight and parameters (catalogue order).
struct VariationTerm {
  std::string name;
  double weight = 1.0;
  std::vector<double> params;
  std::vector<std::string> texts{};  // its text parameters (catalogue order); empty: the defaults
  bool operator==(const VariationTerm&) const = default;
};

struct FlameXform {
  double weight = 1.0;  // relative probability of being chosen (ignored for the final transform)
  Affine3 affine;
  std::vector<VariationTerm> variations;  // summed; empty acts as linear
  bool hasPost = false;
  Affine3 post;
  double color = 0.0;       // the colour index this transform pulls points towards, 0–1
  double colorSpeed = 0.5;  // how far each step moves a point's colour towards `color`, 0–1
  double opacity = 1.0;     // the chance that a point this transform makes is drawn, 0–1
  // JWildfire's solid rendering: a point's material index is blended towards `material` as its
  // colour is towards `color`, m' = m · (1 + materialSpeed) / 2 + material · (1 − materialSpeed) / 2.
  double material = 0.0, materialSpeed = 0.0;
  // How much of the colour index its direct-colour variations (dc_linear, ...) set is kept, 0–1:
  // Fractorium's and Apophysis 7X's "direct color" (var_color in their files). The point's colour
  // becomes c + directColor · (dc − c), c being what the colour blend above made; 0 ignores them.
  double directColor = 1.0;
  // Xaos (flam3's and Apophysis' `chaos`): xaos[j] multiplies transform j's weight when the next
  // transform is chosen right after this one, so 0 forbids the step from this transform to j.
  // Entries past the end (and an empty list) are 1; the final transform's list is unused. When
  // every transform's weight times its factor is 0, the plain weights choose instead (flam3 would
  // refuse to render such a flame; a dead end must not stop the chaos game).
  std::vector<double> xaos;
  // The weighting field (above); kind None: none.
  WeightFieldKind fieldKind = WeightFieldKind::None;
  WeightFieldInput fieldInput = WeightFieldInput::Affine;
  WeightFieldFractal fieldFractal = WeightFieldFractal::Fbm;
  double fieldAmount = 0.0;  // JWildfire's "var amount intensity"
  double fieldFrequency = 1.0;
  int fieldSeed = 1337;
  int fieldOctaves = 3;
  double fieldGain = 0.5, fieldLacunarity = 2.0;
  WeightFieldNoise fieldNoise = WeightFieldNoise::Simplex;
  CellDistance fieldCellDistance = CellDistance::Euclidean;
  CellReturn fieldCellReturn = CellReturn::Distance2;  // JWildfire's default
  double fieldColor = 0.0;                             // JWildfire's "color intensity"
  double fieldJitter = 0.0;                            // JWildfire's "jitter intensity"
  // JWildfire's "var param 1–3": variation name, parameter name (or "amount"), intensity.
  std::string fieldParam1Variation, fieldParam1Name;
  double fieldParam1Intensity = 0.0;
  std::string fieldParam2Variation, fieldParam2Name;
  double fieldParam2Intensity = 0.0;
  std::string fieldParam3Variation, fieldParam3Name;
  double fieldParam3Intensity = 0.0;
  struct FieldParam {
    const std::string& variation;
    const std::string& name;
    double intensity;
  };
  std::array<FieldParam, 3> fieldParams() const {
    return {FieldParam{fieldParam1Variation, fieldParam1Name, fieldParam1Intensity},
            FieldParam{fieldParam2Variation, fieldParam2Name, fieldParam2Intensity},
            FieldParam{fieldParam3Variation, fieldParam3Name, fieldParam3Intensity}};
  }
  // JWildfire's isWeightingFieldActive: a noise kind and something for it to drive.
  bool hasWeightField() const {
    if (fieldKind == WeightFieldKind::None) return false;
    if (fieldAmount != 0.0 || fieldColor != 0.0 || fieldJitter != 0.0) return true;
    for (const FieldParam& p : fieldParams())
      if (p.intensity != 0.0 && !p.variation.empty()) return true;
    return false;
  }
  bool operator==(const FlameXform&) const = default;
};

// The weighting field's noise n(p) of a transform (0 without a field).
double weightFieldNoise(const FlameXform& xform, double x, double y, double z);
// Where a field's simplex noise of seed `seed` (an octave's: the field's seed + the octave) is read
// from: the point plus this offset, which moves each seed to a far-off place of the noise.
std::array<double, 3> weightFieldSimplexOffset(std::int32_t seed);

struct VariationInfo;
// What a transform's weighting field does to one of its terms besides the field's factor
// 1 + amount · n: the parameters it scales per point by 1 + n · intensity (rounded where the
// parameter is a count, or an int in JWildfire), and the term's own weight factor 1 + n · weight
// (the field's `amount` parameter). JWildfire's Variation.addWeightingFieldParam: every term of the
// named variation, the first entry of a parameter name counting, only parameters the term sets.
struct WeightFieldTerm {
  struct Param {
    std::size_t index = 0;
    double intensity = 0.0;
    bool integer = false;
  };
  std::vector<Param> params;
  double weight = 0.0;
};
WeightFieldTerm weightFieldTerm(const FlameXform& xform, const VariationTerm& term, const VariationInfo& info);

// Symmetry as flam3 makes it: extra transforms that turn the whole pattern by 360°/N about `axis`
// (and mirror it across a plane through the axis), chosen like any other transform but never
// changing a point's colour, so the attractor itself becomes symmetric.
struct FlameSymmetry {
  int rotational = 1;  // N-fold, 1 for none
  glm::dvec3 axis{0.0, 0.0, 1.0};
  bool mirror = false;
  bool operator==(const FlameSymmetry&) const = default;
};

// JWildfire's post symmetry (its post_symmetry_* keys): every point the flame draws is drawn again,
// turned or mirrored in the plane about `center`, after the final transforms and before any camera;
// unlike `symmetry` it leaves the iteration alone. The images (postSymmetryMaps):
//  * point: the point itself and its turns by −k · 360°/order about the centre, k = 0 … order − 1,
//    so the point itself twice, as JWildfire draws it (an order of 1 draws the point alone);
//  * x_axis: the point moved by distance/2 along x and turned by −rotation about the centre, and
//    its mirror image across the vertical line through the centre moved by −distance/2 along x
//    and turned by +rotation; y_axis the same across the horizontal line, along y.
// Where the flame is drawn as its author saw it (the flat view) each point is drawn through all of
// them, as JWildfire does; the 3D chaos game draws each through one of them at random, so the
// density has the same shape.
enum class PostSymmetryKind { None, Point, XAxis, YAxis };
inline constexpr std::string_view kPostSymmetryKindNames[] = {"none", "point", "x_axis", "y_axis"};
inline constexpr int kMaxPostSymmetryOrder = 64;  // JWildfire's limit

struct FlamePostSymmetry {
  PostSymmetryKind kind = PostSymmetryKind::None;
  int order = 3;  // point: 1–64
  double centerX = 0.0, centerY = 0.0;
  double distance = 1.25;    // x_axis, y_axis (JWildfire's defaults)
  double rotationDeg = 6.0;  // x_axis, y_axis
  bool operator==(const FlamePostSymmetry&) const = default;
};

// The maps every drawn point goes through (above): none for kind none or a point symmetry of order 1.
std::vector<Affine3> postSymmetryMaps(const FlamePostSymmetry& symmetry);

struct FlameGenome {
  std::vector<FlameXform> xforms;
  bool hasFinal = false;
  FlameXform finalXform;
  // Further final transforms, applied one after the other after finalXform (JWildfire chains
  // several); used only with hasFinal.
  std::vector<FlameXform> chainedFinals;
  // JWildfire's background transforms (<bgxform>): they draw no points; each paints the picture's
  // background. Every pixel's place, (pixel − centre) / half the image's diagonal · 1.41 / backgroundZoom
  // (y down), goes once through each of them from colour index 0, and the colour it comes out with (the
  // palette's entry, scaled by 200/256 as JWildfire's render palette is, or the RGB a variation painted)
  // times the transform's weight is added to the background colour. The flat view draws them.
  std::vector<FlameXform> backgroundXforms;
  double backgroundZoom = 1.0;  // JWildfire's cam_zoom, which alone frames the background
  FlameSymmetry symmetry;
  FlamePostSymmetry postSymmetry;
  bool operator==(const FlameGenome&) const = default;
};

// How the fourth coordinate of a quaternion Julia set becomes a 3D picture.
enum class QuaternionView {
  Project,  // drop the fourth coordinate after a turn by `turnDeg` in the (z, w) plane
  Slice,    // keep points within `thickness` of the hyperplane w = `sliceW` (after the same turn)
};
inline constexpr std::string_view kQuaternionViewNames[] = {"project", "slice"};

struct QuaternionJuliaSettings {
  glm::dvec4 c{-0.2, 0.8, 0.0, 0.0};  // the constant: 1, i, j, k components
  QuaternionView view = QuaternionView::Project;
  double turnDeg = 0.0;     // rotation in the (z, w) plane before the fourth coordinate is dropped
  double sliceW = 0.0;      // Slice: the hyperplane
  double thickness = 0.05;  // Slice: half its thickness
  bool operator==(const QuaternionJuliaSettings&) const = default;
};

// Whether any transform's xaos factor differs from 1 (the chaos game then picks by previous transform).
bool hasXaos(const FlameGenome& genome);

// The transforms that are actually iterated: the genome's own, then the symmetry transforms
// (N − 1 turns about the axis and, with mirror, a reflection), whose weights together equal the
// genome's total so the symmetry is as dense as the pattern itself.
std::vector<FlameXform> expandSymmetry(const FlameGenome& genome);

// Every element of the symmetry's group: the N turns about the axis (the identity first) and,
// with mirror, each of them followed by the reflection. The chaos game draws each point through
// one of them at random, so the drawn density is exactly symmetric, not only the attractor's shape
// (the symmetry transforms alone leave the points right after a genome transform over-represented).
std::vector<Affine3> symmetryGroup(const FlameSymmetry& symmetry);

// Checks a genome for what would make the chaos game meaningless or unsafe, naming the transform
// (`where`: the layer, e.g. "layers[0]"): 1–128 transforms, finite coefficients within ±1e6, known
// variations with the right number of finite parameters, weights ≥ 0 with a positive sum, colour,
// colour speed and opacity in [0, 1], at most one xaos factor per transform, each finite, 0–1e6.
// Throws core::Error.
void validateFlame(const FlameGenome& genome, const std::string& where);
void validateQuaternionJulia(const QuaternionJuliaSettings& settings, const std::string& where);

// A small, pretty genome for new flame layers (the explorer's "new flame", the tests).
FlameGenome defaultFlame();

}  // namespace voxflame::core
