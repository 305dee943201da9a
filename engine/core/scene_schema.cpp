#include "scene_schema.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "error.h"
#include "flame_variations.h"
#include "grid.h"
#include "json_reader.h"

namespace voxflame::core {

using nlohmann::json;

std::string toString(Affects affects) {
  if (!any(affects)) return "nothing drawn";
  std::string text;
  for (auto [bit, name] : {std::pair{Affects::Pattern, "pattern"}, std::pair{Affects::View, "view"},
                           std::pair{Affects::Tone, "tone"}, std::pair{Affects::Still, "still"}})
    if (any(affects & bit)) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

namespace {

// ---------------------------------------------------------------------------------------------
// The tables.

template <class T>
struct MemberOf;
template <class O, class V>
struct MemberOf<V O::*> {
  using Owner = O;
  using Value = V;
};

// A Choice over the enum member M, whose enumerators are 0, 1, 2, ... in the order of `names`.
template <auto M>
constexpr Choice<typename MemberOf<decltype(M)>::Owner> choice(std::span<const std::string_view> names,
                                                               std::string_view noun) {
  using O = typename MemberOf<decltype(M)>::Owner;
  using V = typename MemberOf<decltype(M)>::Value;
  return {[](const O& o) { return static_cast<int>(o.*M); }, [](O& o, int v) { o.*M = static_cast<V>(v); }, names,
          noun};
}

constexpr Affects kPattern = Affects::Pattern;
constexpr Affects kView = Affects::View;
constexpr Affects kTone = Affects::Tone;
constexpr Affects kStill = Affects::Still;
constexpr Affects kNothing = Affects::None;
constexpr double kTwo53 = 9007199254740992.0;
constexpr double kTwo40 = 1099511627776.0;

constexpr std::string_view kColorModes[] = {"speed", "curvature", "time", "axis", "distance", "index"};
constexpr std::string_view kFitModes[] = {"contain", "cover", "stretch", "previous"};
constexpr std::string_view kIntegrators[] = {"euler", "rk4"};
constexpr std::string_view kProjections[] = {"perspective", "orthographic"};
constexpr std::string_view kMeshDisplays[] = {"off", "ghost", "silhouette"};
constexpr std::string_view kRenderMethods[] = {"volume", "points"};
constexpr std::string_view kQuaternionViews[] = {"project", "slice"};
constexpr std::string_view kPaletteModes[] = {"step", "linear"};

using SF = Field<Scene>;
const SF kSceneFields[] = {
    {.key = "name", .member = &Scene::name, .help = "shown in the explorer", .affects = kNothing},
    {.key = "mesh.path",
     .help = "the mesh, in any format Assimp reads; relative paths resolve against the preset's folder; "
             "`builtin:meshes/bunny.obj` is the bunny compiled into the binary",
     .affects = kPattern | kView,
     .typeText = "string",
     .rangeText = "not empty",
     .defaultText = "required"},
    {.key = "grid.resolution",
     .member = &Scene::gridResolution,
     .min = kMinGridResolution,
     .max = kMaxGridResolution,
     .ui = {"grid", 32, 1024, true, "%d voxels"},
     .help = "voxels along the mesh's longest axis",
     .affects = kPattern | kView},
    {.key = "layers",
     .help = "patterns sharing the volume",
     .affects = kPattern,
     .typeText = "array",
     .rangeText = "1–16 layers",
     .defaultText = "required"},
    {.key = "tone", .help = "tone mapping (no restart when changed)", .typeText = "object"},
    {.key = "camera", .help = "the view", .typeText = "object"},
    {.key = "render", .help = "how a frame is drawn", .typeText = "object"},
    {.key = "seed",
     .member = &Scene::seed,
     .min = 0,
     .max = kTwo53,
     .help = "fixes every random number of the accumulation",
     .affects = kPattern},
    {.key = "points",
     .member = &Scene::points,
     .min = 1000,
     .max = kTwo40,
     .help = "points a still accumulates inside the mesh",
     .affects = kStill},
    {.key = "animation", .help = "duration, frame rate, loop (version 2)", .typeText = "object"},
    {.key = "flat",
     .help = "flam3's 2D framing of an imported flame, for `voxflame render --flat`",
     .typeText = "object",
     .defaultText = "flam3's"},
    {.key = "keyframes",
     .help = "animated values (version 2)",
     .typeText = "array",
     .rangeText = "0–4096 tracks",
     .defaultText = "none"},
};

bool isAttractorLayer(const PatternLayer& layer) {
  return layer.kind == PatternKind::Attractor;
}

using LF = Field<PatternLayer>;
const LF kLayerFields[] = {
    {.key = "kind",
     .help = "what the layer iterates; `flame` and `quaternion_julia` below",
     .affects = kPattern,
     .typeText = "string",
     .rangeText = "`attractor`, `flame`, `quaternion_julia`",
     .defaultText = "`attractor`"},
    {.key = "attractor",
     .affects = kPattern,
     .typeText = "string",
     .rangeText = "an id of `voxflame list`",
     .defaultText = "required for attractors"},
    {.key = "params",
     .help = "by parameter name (`voxflame list`)",
     .affects = kPattern,
     .typeText = "object",
     .rangeText = "each −10⁶–10⁶",
     .defaultText = "the catalogue's values"},
    {.key = "integrator",
     .member = choice<&PatternLayer::integrator>(kIntegrators, "integrator"),
     .help = "flows only",
     .affects = kPattern,
     .present = isAttractorLayer,
     .defaultText = "the attractor's"},
    {.key = "step",
     .member = &PatternLayer::step,
     .min = 1e-6,
     .max = 1.0,
     .ui = {"step", 0.0005, 0.3, true, "%.4f"},
     .help = "integration step, flows only",
     .affects = kPattern,
     .present = isAttractorLayer,
     .defaultText = "the attractor's"},
    {.key = "weight",
     .member = &PatternLayer::weight,
     .min = 0.0,
     .max = 1000.0,
     .ui = {"weight", 0.01, 10.0, true},
     .help = "share of the points",
     .affects = kPattern},
};

using CF = Field<ColorSettings>;
const CF kColorFields[] = {
    {.key = "mode",
     .member = choice<&ColorSettings::mode>(kColorModes, "colour mode"),
     .help = "what the colour follows; `index` is flam3's colour index (chaos-game layers only)",
     .affects = kPattern,
     .defaultText = "`speed` (`index` for flames and quaternion Julia sets)"},
    {.key = "gradient",
     .help = "evenly spaced stops, interpolated in OKLab (an imported flame's palette has 256)",
     .affects = kPattern,
     .typeText = "array of colours",
     .rangeText = "2–256",
     .defaultText = "`[\"#2a6cff\", \"#ffb347\"]`"},
    {.key = "palette",
     .help = "a named gradient; not together with `gradient`",
     .affects = kPattern,
     .typeText = "string",
     .rangeText = "ember, glacier, aurora, dusk, reef, nebula, moss, steel, seed",
     .defaultText = "none"},
    {.key = "axis",
     .member = &ColorSettings::axis,
     .min = -1e6,
     .max = 1e6,
     .ui = {"axis", -1.0, 1.0, false, "%.2f"},
     .help = "`axis` mode's direction",
     .affects = kPattern,
     .write = Write::UnlessDefault,
     .rangeText = "each −10⁶–10⁶, not all 0"},
    {.key = "period",
     .member = &ColorSettings::period,
     .min = 1.0,
     .max = 1e9,
     .ui = {"period (steps)", 10.0, 100000.0, true, "%.0f"},
     .help = "`time` mode: steps per trip through the gradient",
     .affects = kPattern,
     .write = Write::UnlessDefault},
    {.key = "scale",
     .member = &ColorSettings::scale,
     .min = 1e-6,
     .max = 1e6,
     .ui = {"colour scale", 0.05, 20.0, true},
     .help = "stretches the mode's value over the gradient",
     .affects = kPattern,
     .write = Write::UnlessDefault},
};

using TF = Field<LayerTransform>;
const TF kTransformFields[] = {
    {.key = "scale",
     .member = &LayerTransform::scale,
     .min = 1e-3,
     .max = 1e3,
     .ui = {"scale", 0.1, 4.0, true},
     .help = "scales the automatic fit into the mesh",
     .affects = kPattern},
    {.key = "rotation_deg",
     .member = &LayerTransform::rotationDeg,
     .min = -3600.0,
     .max = 3600.0,
     .ui = {"rotation", -180.0, 180.0, false, "%.0f°"},
     .help = "about x, then y, then z",
     .affects = kPattern},
    {.key = "offset",
     .member = &LayerTransform::offset,
     .min = -100.0,
     .max = 100.0,
     .ui = {"offset", -0.5, 0.5, false, "%.2f"},
     .help = "in grid lengths",
     .affects = kPattern},
    {.key = "copies",
     .help = "more copies of the layer's pattern, each turned by these angles (added to `rotation_deg` angle by "
             "angle); the layer's `weight` is shared among the original and its copies",
     .affects = kPattern,
     .typeText = "array of up to 15 × 3 numbers",
     .rangeText = "each −3600–3600",
     .defaultText = "`[]`"},
    {.key = "fit",
     .member = choice<&LayerTransform::fit>(kFitModes, "fit mode"),
     .ui = {"fit"},
     .help = "how the automatic fit sizes the attractor (below): `contain` fits the shape's middle axis, `cover` "
             "fills every axis (the mesh carves it), `stretch` scales each axis to the shape, `previous` takes the fit "
             "of the layer before (imported JWildfire layers stay in register)",
     .affects = kPattern,
     .write = Write::UnlessDefault},
};

const TF kLockedFitFields[] = {
    {.key = "center",
     .member = &LayerTransform::lockedCenter,
     .min = -1e9,
     .max = 1e9,
     .help = "attractor point put at the mesh's centre",
     .affects = kPattern,
     .defaultText = "required in `locked_fit`"},
    {.key = "scale",
     .member = &LayerTransform::lockedScale,
     .min = 1e-12,
     .max = 1e12,
     .help = "voxels per attractor unit",
     .affects = kPattern,
     .defaultText = "required in `locked_fit`"},
    {.key = "axis_scale",
     .member = &LayerTransform::lockedAxisScale,
     .min = 1e-12,
     .max = 1e12,
     .help = "per attractor axis, times `scale` (a `stretch` fit's shape)",
     .affects = kPattern,
     .write = Write::UnlessDefault},
};

using FF = Field<FlameGenome>;
const FF kFlameFields[] = {
    {.key = "xforms",
     .help = "the transforms; at least one with a positive weight",
     .affects = kPattern,
     .typeText = "array",
     .rangeText = "1–128 transforms",
     .defaultText = "required"},
    {.key = "final",
     .help = "applied to what is drawn, never fed back",
     .affects = kPattern,
     .typeText = "object",
     .rangeText = "a transform without `weight`",
     .defaultText = "none"},
};

using XF = Field<FlameXform>;
const XF kXformFields[] = {
    {.key = "weight",
     .member = &FlameXform::weight,
     .min = 0.0,
     .max = kFlameCoefficientLimit,
     .ui = {"transform weight", 0.01, 10.0, true},
     .help = "relative chance of being picked",
     .affects = kPattern},
    {.key = "affine",
     .help = "p ↦ M p + t, row by row: `[m00, m01, m02, t0, m10, m11, m12, t1, m20, m21, m22, t2]`; flam3's 2D "
             "`coefs=\"a d b e c f\"` are `m00 = a, m01 = b, t0 = c, m10 = d, m11 = e, t1 = f`",
     .affects = kPattern,
     .typeText = "12 numbers",
     .rangeText = "each −10⁶–10⁶",
     .defaultText = "identity"},
    {.key = "variations",
     .help = "each `{\"name\": N, \"weight\": W, PARAM: V, ...}`; parameters left out take their defaults; none "
             "acts as linear",
     .affects = kPattern,
     .typeText = "array",
     .rangeText = "0–16",
     .defaultText = "`[{\"name\": \"linear\"}]`"},
    {.key = "xaos",
     .help = "flam3's and Apophysis' xaos (`chaos`): entry j multiplies transform j's weight when the transform "
             "after this one is chosen (0 forbids that step); entries left out are 1; not in `final`",
     .affects = kPattern,
     .typeText = "array of numbers",
     .rangeText = "each 0–10⁶, at most 128",
     .defaultText = "all 1"},
    {.key = "post",
     .help = "a second affine map after the variations",
     .affects = kPattern,
     .typeText = "12 numbers",
     .rangeText = "each −10⁶–10⁶",
     .defaultText = "none"},
    {.key = "color",
     .member = &FlameXform::color,
     .min = 0.0,
     .max = 1.0,
     .ui = {"colour", 0.0, 1.0},
     .help = "the colour index the transform pulls towards",
     .affects = kPattern,
     .write = Write::UnlessDefault},
    {.key = "color_speed",
     .member = &FlameXform::colorSpeed,
     .min = 0.0,
     .max = 1.0,
     .ui = {"colour speed", 0.0, 1.0},
     .help = "how far each step moves the colour index",
     .affects = kPattern,
     .write = Write::UnlessDefault},
    {.key = "opacity",
     .member = &FlameXform::opacity,
     .min = 0.0,
     .max = 1.0,
     .ui = {"opacity", 0.0, 1.0},
     .help = "the chance that a point it makes is drawn",
     .affects = kPattern,
     .write = Write::UnlessDefault},
};

using VF = Field<VariationTerm>;
const VF kVariationFields[] = {
    {.key = "name",
     .help = "a variation of `voxflame list --variations`",
     .affects = kPattern,
     .typeText = "string",
     .rangeText = "a variation's name",
     .defaultText = "required"},
    {.key = "weight",
     .member = &VariationTerm::weight,
     .min = -kFlameCoefficientLimit,
     .max = kFlameCoefficientLimit,
     .affects = kPattern},
};

using YF = Field<FlameSymmetry>;
const YF kSymmetryFields[] = {
    {.key = "rotational",
     .member = &FlameSymmetry::rotational,
     .min = 1,
     .max = kMaxFlameSymmetry,
     .ui = {"rotational", 1, kMaxFlameSymmetry, false, "%d-fold"},
     .help = "N-fold rotational symmetry about `axis`",
     .affects = kPattern},
    {.key = "axis",
     .member = &FlameSymmetry::axis,
     .min = -1e6,
     .max = 1e6,
     .ui = {"axis", -1.0, 1.0, false, "%.2f"},
     .affects = kPattern,
     .rangeText = "each −10⁶–10⁶, not all 0"},
    {.key = "mirror",
     .member = &FlameSymmetry::mirror,
     .ui = {"mirror"},
     .help = "also mirror across a plane through the axis",
     .affects = kPattern},
};

using QF = Field<QuaternionJuliaSettings>;
const QF kJuliaFields[] = {
    {.key = "c",
     .help = "the constant: 1, i, j, k components",
     .affects = kPattern,
     .typeText = "4 numbers",
     .rangeText = "each −10–10",
     .defaultText = "`[-0.2, 0.8, 0, 0]`"},
    {.key = "view",
     .member = choice<&QuaternionJuliaSettings::view>(kQuaternionViews, "view"),
     .ui = {"view"},
     .help = "`project`: drop the fourth coordinate; `slice`: keep the points within `thickness` of the hyperplane "
             "w = `slice_w`",
     .affects = kPattern},
    {.key = "turn_deg",
     .member = &QuaternionJuliaSettings::turnDeg,
     .min = -3600.0,
     .max = 3600.0,
     .ui = {"turn", -180.0, 180.0, false, "%.1f°"},
     .help = "turns the (z, w) plane before the fourth coordinate is dropped or sliced",
     .affects = kPattern},
    {.key = "slice_w",
     .member = &QuaternionJuliaSettings::sliceW,
     .min = -10.0,
     .max = 10.0,
     .ui = {"slice w", -2.0, 2.0},
     .help = "`slice`: the hyperplane",
     .affects = kPattern},
    {.key = "thickness",
     .member = &QuaternionJuliaSettings::thickness,
     .min = 1e-4,
     .max = 10.0,
     .ui = {"thickness", 0.001, 1.0, true},
     .help = "`slice`: its half thickness (thinner is sharper but slower: hidden points are still computed)",
     .affects = kPattern},
};

using NF = Field<ToneMapSettings>;
const NF kToneFields[] = {
    {.key = "brightness",
     .member = &ToneMapSettings::brightness,
     .min = 0.0,
     .max = 1000.0,
     .ui = {"brightness", 0.01, 50.0, true},
     .help = "flam3's k1: scales the log density",
     .affects = kTone},
    {.key = "gamma",
     .member = &ToneMapSettings::gamma,
     .min = 0.1,
     .max = 10.0,
     .ui = {"gamma", 0.5, 6.0},
     .affects = kTone},
    {.key = "gamma_threshold",
     .member = &ToneMapSettings::gammaThreshold,
     .min = 0.0,
     .max = 1.0,
     .ui = {"gamma threshold", 0.0, 0.5},
     .help = "below it the gamma curve is linear",
     .affects = kTone},
    {.key = "vibrancy",
     .member = &ToneMapSettings::vibrancy,
     .min = 0.0,
     .max = 1.0,
     .ui = {"vibrancy", 0.0, 1.0},
     .help = "1: gamma on opacity; 0: per channel",
     .affects = kTone},
    {.key = "highlight_power",
     .member = &ToneMapSettings::highlightPower,
     .min = -1.0,
     .max = 10.0,
     .ui = {"highlight power", -1.0, 5.0},
     .help = "< 0 clips overexposed colours, ≥ 0 fades them to white",
     .affects = kTone},
    {.key = "exposure",
     .member = &ToneMapSettings::exposure,
     .min = -20.0,
     .max = 20.0,
     .ui = {"exposure", -5.0, 5.0},
     .help = "stops",
     .affects = kTone},
    {.key = "contrast",
     .member = &ToneMapSettings::contrast,
     .min = 0.0,
     .max = 10.0,
     .ui = {"contrast", 0.2, 3.0},
     .help = "around mid grey",
     .affects = kTone},
    {.key = "opacity",
     .member = &ToneMapSettings::opacity,
     .min = 0.0,
     .max = 100.0,
     .ui = {"opacity", 0.0, 1.0},
     .help = "how much dense regions hide what is behind them (absorption from raw density)",
     .affects = kView},
    {.key = "background", .member = &ToneMapSettings::background, .ui = {"background"}, .affects = kTone},
    {.key = "estimator_radius",
     .member = &ToneMapSettings::estimatorRadius,
     .min = 0.0,
     .max = 50.0,
     .ui = {"estimator radius", 0.0, 20.0},
     .help = "density estimation: kernel radius in output pixels where one point fell; 0 turns it off",
     .affects = kTone},
    {.key = "estimator_minimum",
     .member = &ToneMapSettings::estimatorMinimum,
     .min = 0.0,
     .max = 50.0,
     .ui = {"estimator minimum", 0.0, 10.0},
     .help = "the kernel never narrows below this radius; at most `estimator_radius`",
     .affects = kTone},
    {.key = "estimator_curve",
     .member = &ToneMapSettings::estimatorCurve,
     .min = 0.01,
     .max = 5.0,
     .ui = {"estimator curve", 0.05, 2.0},
     .help = "how fast the kernel narrows as hits grow: radius / (hits + 1)^curve",
     .affects = kTone},
};

using MF = Field<CameraSettings>;
const MF kCameraFields[] = {
    {.key = "azimuth_deg",
     .member = &CameraSettings::azimuthDeg,
     .min = -3600.0,
     .max = 3600.0,
     .ui = {"azimuth", -180.0, 180.0, false, "%.1f°"},
     .help = "orbit around `target`",
     .affects = kView},
    {.key = "elevation_deg",
     .member = &CameraSettings::elevationDeg,
     .min = -360.0,
     .max = 360.0,
     .ui = {"elevation", -90.0, 90.0, false, "%.1f°"},
     .help = "any value works, straight up included",
     .affects = kView},
    {.key = "roll_deg",
     .member = &CameraSettings::rollDeg,
     .min = -360.0,
     .max = 360.0,
     .ui = {"roll", -180.0, 180.0, false, "%.1f°"},
     .affects = kView},
    {.key = "distance",
     .member = &CameraSettings::distance,
     .min = 0.01,
     .max = 1000.0,
     .ui = {"distance", 0.2, 20.0, true},
     .help = "in radii of the grid's bounding sphere",
     .affects = kView},
    {.key = "fov_deg",
     .member = &CameraSettings::fovDeg,
     .min = 1.0,
     .max = 170.0,
     .ui = {"field of view", 5.0, 120.0, false, "%.0f°"},
     .help = "perspective: vertical field of view",
     .affects = kView},
    {.key = "projection", .member = choice<&CameraSettings::projection>(kProjections, "projection"), .affects = kView},
    {.key = "ortho_height",
     .member = &CameraSettings::orthoHeight,
     .min = 0.001,
     .max = 1000.0,
     .help = "orthographic: visible height in radii",
     .affects = kView},
    {.key = "target",
     .member = &CameraSettings::target,
     .min = -1000.0,
     .max = 1000.0,
     .help = "in radii, from the grid's centre",
     .affects = kView},
    {.key = "near",
     .member = &CameraSettings::nearClip,
     .min = 0.0,
     .max = 1000.0,
     .help = "clip distance in radii; 0: automatic",
     .affects = kView},
    {.key = "far",
     .member = &CameraSettings::farClip,
     .min = 0.0,
     .max = 10000.0,
     .help = "clip distance in radii, larger than `near`; 0: automatic",
     .affects = kView},
};

using RF = Field<RenderSettingsDoc>;
const RF kRenderFields[] = {
    {.key = "step",
     .member = &RenderSettingsDoc::stepVoxels,
     .min = 0.05,
     .max = 4.0,
     .ui = {"step (voxels)", 0.1, 2.0},
     .help = "ray-march step in voxels",
     .affects = kView},
    {.key = "samples",
     .member = &RenderSettingsDoc::samples,
     .min = 1,
     .max = 1024,
     .help = "jittered sub-samples per pixel for stills",
     .affects = kStill},
    {.key = "mesh",
     .member = choice<&RenderSettingsDoc::meshDisplay>(kMeshDisplays, "mesh display"),
     .ui = {"show mesh"},
     .help = "how the mesh is shown",
     .affects = kView | kTone},
    {.key = "mesh_color", .member = &RenderSettingsDoc::meshColor, .ui = {"mesh colour"}, .affects = kView | kTone},
    {.key = "mesh_strength",
     .member = &RenderSettingsDoc::meshStrength,
     .min = 0.0,
     .max = 10.0,
     .ui = {"mesh strength", 0.0, 2.0},
     .affects = kTone},
    {.key = "lighting",
     .member = &RenderSettingsDoc::lighting,
     .ui = {"lighting"},
     .help = "directional light with a shadow volume",
     .affects = kView},
    {.key = "light_azimuth_deg",
     .member = &RenderSettingsDoc::lightAzimuthDeg,
     .min = -3600.0,
     .max = 3600.0,
     .ui = {"light azimuth", -180.0, 180.0, false, "%.0f°"},
     .affects = kView},
    {.key = "light_elevation_deg",
     .member = &RenderSettingsDoc::lightElevationDeg,
     .min = -90.0,
     .max = 90.0,
     .ui = {"light elevation", -90.0, 90.0, false, "%.0f°"},
     .affects = kView},
    {.key = "light_strength",
     .member = &RenderSettingsDoc::lightStrength,
     .min = 0.0,
     .max = 1.0,
     .ui = {"light strength", 0.0, 1.0},
     .help = "how much shadowed emission is dimmed",
     .affects = kView},
    {.key = "method",
     .member = choice<&RenderSettingsDoc::method>(kRenderMethods, "render method"),
     .ui = {"still method"},
     .help = "how stills are made: ray-march the voxel grid, or project every point into a supersampled screen "
             "histogram (pixel-fine filaments; the grid only dims points by the density in front of them). The "
             "explorer previews with `volume`",
     .affects = kStill},
    {.key = "oversample",
     .member = &RenderSettingsDoc::oversample,
     .min = 1,
     .max = 4,
     .ui = {"oversample", 1, 4, false, "%d"},
     .help = "supersampled pixels per output pixel along each axis",
     .affects = kView},
    {.key = "filter_radius",
     .member = &RenderSettingsDoc::filterRadius,
     .min = 0.0,
     .max = 10.0,
     .ui = {"filter radius", 0.0, 3.0},
     .help = "flam3's Gaussian spatial filter, in output pixels",
     .affects = kTone},
    {.key = "dof.aperture",
     .member = &RenderSettingsDoc::dofAperture,
     .min = 0.0,
     .max = 10.0,
     .ui = {"lens aperture", 0.0, 0.5},
     .help = "points method: lens radius in radii of the grid's bounding sphere; 0 is a pinhole",
     .affects = kStill},
    {.key = "dof.focus_distance",
     .member = &RenderSettingsDoc::dofFocusDistance,
     .min = 0.0,
     .max = 1000.0,
     .ui = {"focus distance", 0.0, 10.0},
     .help = "points method: distance in focus, in radii from the eye; 0: the camera's target",
     .affects = kStill},
    {.key = "fog",
     .member = &RenderSettingsDoc::fog,
     .min = 0.0,
     .max = 100.0,
     .ui = {"fog", 0.0, 5.0},
     .help = "points method: dims points by exp(−fog × depth behind the grid's front, in grid sides)",
     .affects = kStill},
};

using FV = Field<FlatViewSettings>;
const FV kFlatFields[] = {
    {.key = "width",
     .member = &FlatViewSettings::width,
     .min = 1,
     .max = 65536,
     .help = "flam3's size: image width in pixels",
     .affects = kStill},
    {.key = "height",
     .member = &FlatViewSettings::height,
     .min = 1,
     .max = 65536,
     .help = "image height in pixels",
     .affects = kStill},
    {.key = "center_x",
     .member = &FlatViewSettings::centerX,
     .min = -1e6,
     .max = 1e6,
     .help = "the flame point at the image's centre",
     .affects = kStill},
    {.key = "center_y", .member = &FlatViewSettings::centerY, .min = -1e6, .max = 1e6, .affects = kStill},
    {.key = "scale",
     .member = &FlatViewSettings::scale,
     .min = 1e-6,
     .max = 1e6,
     .help = "pixels per flame unit at zoom 0",
     .affects = kStill},
    {.key = "zoom",
     .member = &FlatViewSettings::zoom,
     .min = -30.0,
     .max = 30.0,
     .help = "pixels per unit = scale · 2^zoom (flam3 draws 4^zoom times the samples)",
     .affects = kStill},
    {.key = "rotate",
     .member = &FlatViewSettings::rotateDeg,
     .min = -3600.0,
     .max = 3600.0,
     .help = "degrees the picture turns about the centre",
     .affects = kStill},
    {.key = "oversample",
     .member = &FlatViewSettings::oversample,
     .min = 1,
     .max = 4,
     .help = "supersampled pixels per output pixel along each axis",
     .affects = kStill},
    {.key = "filter_radius",
     .member = &FlatViewSettings::filterRadius,
     .min = 0.0,
     .max = 10.0,
     .help = "Gaussian spatial filter, in output pixels",
     .affects = kStill},
    {.key = "quality",
     .member = &FlatViewSettings::quality,
     .min = 1e-3,
     .max = 1e6,
     .help = "samples per output pixel (flam3's quality)",
     .affects = kStill},
    {.key = "palette_mode",
     .member = choice<&FlatViewSettings::paletteMode>(kPaletteModes, "palette mode"),
     .help = "flam3's colour lookup: step takes the palette entry ⌊index · 256⌋, linear blends the two around it",
     .affects = kStill},
};

using AF = Field<AnimationSettings>;
const AF kAnimationFields[] = {
    {.key = "duration",
     .member = &AnimationSettings::duration,
     .min = 0.0,
     .max = 1e6,  // kMaxAnimationSeconds (keyframes.h)
     .ui = {"duration", 0.0, 600.0, false, "%.2f s"},
     .help = "length in seconds; 0: until the last key",
     .affects = kNothing,
     .rangeText = "0–10⁶ s"},
    {.key = "fps",
     .member = &AnimationSettings::fps,
     .min = 0.01,
     .max = 1000.0,
     .ui = {"fps", 1.0, 240.0, true, "%.0f"},
     .help = "frames per second for `voxflame animate`",
     .affects = kNothing},
    {.key = "loop",
     .member = &AnimationSettings::loop,
     .ui = {"loop"},
     .help = "time wraps at the duration; smooth tracks join their ends without a kink",
     .affects = kNothing},
    {.key = "time",
     .member = &AnimationSettings::time,
     .min = 0.0,
     .max = 1e6,
     .help = "the moment `voxflame render` shows (a rendered frame stores its own)",
     .affects = kNothing,
     .rangeText = "0–10⁶ s"},
};

// ---------------------------------------------------------------------------------------------
// Reading and writing one table's fields.

// "dof.aperture" → {"dof", "aperture"}; "gamma" → {"", "gamma"}.
std::pair<std::string, std::string> splitKey(std::string_view key) {
  const auto dot = key.find('.');
  if (dot == std::string_view::npos) return {"", std::string(key)};
  return {std::string(key.substr(0, dot)), std::string(key.substr(dot + 1))};
}

std::string choiceList(std::span<const std::string_view> names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += i == 0 ? "" : i + 1 == names.size() ? " or " : ", ";
    text += '\'';
    text += names[i];
    text += '\'';
  }
  return text;
}

template <class Owner>
void readField(ObjectReader& reader, const std::string& key, const Field<Owner>& f, Owner& owner) {
  std::visit(
      [&]<class M>(const M& member) {
        if constexpr (std::is_same_v<M, double Owner::*>) {
          owner.*member = reader.number(key, owner.*member, f.min, f.max);
        } else if constexpr (std::is_same_v<M, int Owner::*>) {
          owner.*member = static_cast<int>(
              reader.integer(key, owner.*member, static_cast<std::int64_t>(f.min), static_cast<std::int64_t>(f.max)));
        } else if constexpr (std::is_same_v<M, std::uint64_t Owner::*>) {
          owner.*member = static_cast<std::uint64_t>(reader.integer(key, static_cast<std::int64_t>(owner.*member),
                                                                    static_cast<std::int64_t>(f.min),
                                                                    static_cast<std::int64_t>(f.max)));
        } else if constexpr (std::is_same_v<M, bool Owner::*>) {
          owner.*member = reader.boolean(key, owner.*member);
        } else if constexpr (std::is_same_v<M, std::string Owner::*>) {
          owner.*member = reader.string(key, owner.*member);
        } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
          owner.*member = reader.color(key, owner.*member);
        } else if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
          owner.*member = reader.vector(key, owner.*member, f.min, f.max);
        } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
          const std::string name =
              reader.string(key, std::string(member.names[static_cast<std::size_t>(member.get(owner))]));
          const auto found = std::find(member.names.begin(), member.names.end(), name);
          if (found == member.names.end())
            reader.fail(
                "is '" + name + "', an unknown " + std::string(member.noun) + "; expected " + choiceList(member.names),
                key);
          member.set(owner, static_cast<int>(found - member.names.begin()));
        }
      },
      f.member);
}

// Reads every member row of `table` that the owner has (its `present`), taking the owner's
// current values as the defaults; rows of nested objects ("dof.aperture") read through one reader
// per nested object, which then refuses unknown keys of its own. `skip` leaves one key out.
template <class Owner>
void readFields(ObjectReader& reader, Table<Owner> table, Owner& owner, std::string_view skip = {}) {
  std::map<std::string, ObjectReader> nested;
  for (const Field<Owner>& f : table) {
    if (f.type() == FieldType::Hand || !f.presentIn(owner) || f.key == skip) continue;
    const auto [object, key] = splitKey(f.key);
    if (object.empty()) {
      readField(reader, key, f, owner);
      continue;
    }
    auto it = nested.find(object);
    if (it == nested.end()) {
      const json* value = reader.find(object);
      if (!value) continue;
      it = nested.try_emplace(object, *value, reader.source(), reader.keyPath(object)).first;
    }
    readField(it->second, key, f, owner);
  }
  for (const auto& [name, child] : nested) child.finish();
}

template <class Owner>
json fieldJson(const Owner& owner, const Field<Owner>& f) {
  return std::visit(
      [&]<class M>(const M& member) -> json {
        if constexpr (std::is_same_v<M, std::monostate>) {
          return nullptr;
        } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
          return toHexColor(owner.*member);
        } else if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
          const glm::dvec3& v = owner.*member;
          return json::array({v.x, v.y, v.z});
        } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
          return std::string(member.names[static_cast<std::size_t>(member.get(owner))]);
        } else {
          return owner.*member;
        }
      },
      f.member);
}

template <class Owner>
bool fieldEqual(const Owner& a, const Owner& b, const Field<Owner>& f) {
  return std::visit(
      [&]<class M>(const M& member) {
        if constexpr (std::is_same_v<M, std::monostate>) {
          return true;
        } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
          return member.get(a) == member.get(b);
        } else {
          return a.*member == b.*member;
        }
      },
      f.member);
}

template <class Owner>
void writeFields(json& out, Table<Owner> table, const Owner& owner, bool complete, std::string_view skip = {}) {
  static const Owner defaults{};
  for (const Field<Owner>& f : table) {
    if (f.type() == FieldType::Hand || !f.presentIn(owner) || f.key == skip) continue;
    if (!complete && f.write == Write::UnlessDefault && fieldEqual(owner, defaults, f)) continue;
    const auto [object, key] = splitKey(f.key);
    (object.empty() ? out[key] : out[object][key]) = fieldJson(owner, f);
  }
}

// ---------------------------------------------------------------------------------------------
// Cross-field checks (hand code: each names the key it blames and why).

struct Failure {
  std::string key;
  std::string reason;
};

std::optional<Failure> toneFailure(const ToneMapSettings& t) {
  if (t.estimatorMinimum > t.estimatorRadius && t.estimatorRadius > 0.0)
    return Failure{"estimator_minimum", "must not be larger than 'estimator_radius'"};
  return std::nullopt;
}

std::optional<Failure> cameraFailure(const CameraSettings& c) {
  if (c.farClip > 0.0 && c.farClip <= c.nearClip) return Failure{"far", "must be larger than 'near'"};
  return std::nullopt;
}

std::optional<Failure> zeroAxisFailure(const glm::dvec3& axis) {
  if (glm::dot(axis, axis) < 1e-24) return Failure{"axis", "must not be the zero vector"};
  return std::nullopt;
}

std::optional<Failure> flameWeightFailure(const FlameGenome& genome) {
  double total = 0.0;
  for (const FlameXform& x : genome.xforms) total += x.weight;
  if (!(total > 0.0)) return Failure{"xforms", "all have weight 0; at least one transform needs a positive weight"};
  return std::nullopt;
}

void failOn(ObjectReader& reader, const std::optional<Failure>& failure) {
  if (failure) reader.fail(failure->reason, failure->key);
}

// ---------------------------------------------------------------------------------------------
// The reader: the tables, plus the marked hand code for what they cannot hold.

// Hand code: gradient stops (an array of colours) or a named palette, not both.
ColorSettings readColor(ObjectReader& parent, ColorMode defaultMode) {
  ColorSettings color;
  color.mode = defaultMode;
  color.gradient = {{0.0f, parseHexColor("#2a6cff")}, {1.0f, parseHexColor("#ffb347")}};
  const json* value = parent.find("color");
  if (!value) return color;
  ObjectReader reader(*value, parent.source(), parent.keyPath("color"));
  readFields(reader, colorFields(), color);
  const json* stops = reader.find("gradient");
  color.palette = reader.string("palette", "");
  if (!color.palette.empty()) {
    if (stops) reader.fail("cannot be given together with 'gradient'; choose one", "palette");
    try {
      color.gradient = paletteStops(color.palette);
    } catch (const Error& e) {
      reader.fail(e.what(), "palette");
    }
  }
  if (stops) {
    const std::string path = reader.keyPath("gradient");
    if (!stops->is_array() || stops->size() < 2 || stops->size() > kMaxGradientStops)
      reader.fail("must be an array of 2 to 256 colours like \"#ff8800\" (a flame's palette has 256)", "gradient");
    color.gradient.clear();
    const std::size_t count = stops->size();
    for (std::size_t i = 0; i < count; ++i) {
      const json& stop = (*stops)[i];
      if (!stop.is_string())
        throw Error(parent.source() + ": '" + path + "[" + std::to_string(i) + "]' must be a colour string");
      try {
        color.gradient.push_back(
            {static_cast<float>(i) / static_cast<float>(count - 1), parseHexColor(stop.get<std::string>())});
      } catch (const Error& e) {
        throw Error(parent.source() + ": '" + path + "[" + std::to_string(i) + "]' " + e.what());
      }
    }
  }
  failOn(reader, zeroAxisFailure(color.axis));
  reader.finish();
  return color;
}

// Hand code: `copies` (an array of rotations) and the `locked_fit` block, whose presence locks the fit.
LayerTransform readTransform(ObjectReader& parent) {
  LayerTransform transform;
  const json* value = parent.find("transform");
  if (!value) return transform;
  ObjectReader reader(*value, parent.source(), parent.keyPath("transform"));
  readFields(reader, transformFields(), transform);
  if (const json* copies = reader.find("copies")) {
    if (!copies->is_array() || copies->size() > kMaxLayerCopies)
      reader.fail("must be an array of at most " + std::to_string(kMaxLayerCopies) + " rotations", "copies");
    for (std::size_t i = 0; i < copies->size(); ++i) {
      const json& copy = (*copies)[i];
      const std::string copyKey = "copies[" + std::to_string(i) + "]";
      if (!copy.is_array() || copy.size() != 3) reader.fail("must be an array of three numbers (degrees)", copyKey);
      glm::dvec3 angles;
      for (int axis = 0; axis < 3; ++axis)
        angles[axis] = reader.checkNumber(copy[static_cast<std::size_t>(axis)], copyKey, -3600.0, 3600.0);
      transform.copies.push_back(angles);
    }
  }
  if (const json* locked = reader.find("locked_fit")) {
    ObjectReader lockedReader(*locked, parent.source(), reader.keyPath("locked_fit"));
    transform.lockFit = true;
    if (!lockedReader.has("center")) lockedReader.fail("is missing", "center");
    if (!lockedReader.has("scale")) lockedReader.fail("is missing", "scale");
    readFields(lockedReader, lockedFitFields(), transform);
    lockedReader.finish();
  }
  reader.finish();
  return transform;
}

// Hand code: 12 numbers, the 3×4 matrix row by row.
Affine3 readAffine(ObjectReader& reader, const std::string& key, const Affine3& fallback) {
  const json* value = reader.find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 12)
    reader.fail("must be 12 numbers: the 3×4 matrix row by row, [m00, m01, m02, t0, m10, ..., t2]", key);
  Affine3 affine;
  for (std::size_t i = 0; i < 12; ++i) affine.m[i] = reader.checkNumber((*value)[i], key, -1e6, 1e6);
  return affine;
}

// Hand code: a variation's parameters are keys named by the catalogue entry its `name` picks.
VariationTerm readVariation(const json& value, const std::string& source, const std::string& path) {
  ObjectReader reader(value, source, path);
  VariationTerm term;
  term.name = reader.requiredString("name");
  const VariationInfo* info = findVariation(term.name);
  if (!info) {
    try {
      variationOrThrow(term.name);
    } catch (const Error& e) {
      reader.fail(e.what(), "name");
    }
  }
  readFields(reader, variationFields(), term);
  term.params = info->defaultParams();
  for (std::size_t i = 0; i < info->params.size(); ++i)
    term.params[i] = reader.number(info->params[i].name, info->params[i].defaultValue, -1e6, 1e6);
  reader.finish();
  return term;
}

FlameXform readXform(const json& value, const std::string& source, const std::string& path, bool isFinal) {
  ObjectReader reader(value, source, path);
  FlameXform xform;
  readFields(reader, xformFields(), xform, isFinal ? "weight" : "");
  xform.affine = readAffine(reader, "affine", xform.affine);
  if (reader.find("post")) {
    xform.hasPost = true;
    xform.post = readAffine(reader, "post", xform.post);
  }
  if (const json* variations = reader.find("variations")) {
    if (!variations->is_array() || variations->size() > kMaxXformVariations)
      reader.fail("must be an array of at most " + std::to_string(kMaxXformVariations) + " variations", "variations");
    for (std::size_t i = 0; i < variations->size(); ++i)
      xform.variations.push_back(
          readVariation((*variations)[i], source, reader.keyPath("variations") + "[" + std::to_string(i) + "]"));
  } else {
    xform.variations = {{"linear", 1.0, {}}};
  }
  if (const json* xaos = isFinal ? nullptr : reader.find("xaos")) {
    if (!xaos->is_array() || xaos->size() > kMaxFlameXforms)
      reader.fail("must be an array of at most " + std::to_string(kMaxFlameXforms) + " numbers", "xaos");
    for (const json& factor : *xaos) xform.xaos.push_back(reader.checkNumber(factor, "xaos", 0.0, 1e6));
  }
  reader.finish();
  return xform;
}

// Hand code: the transforms (an array, required) and the optional final one.
FlameGenome readFlame(ObjectReader& parent) {
  const json* value = parent.find("flame");
  if (!value) parent.fail("is missing (a flame layer needs its transforms)", "flame");
  ObjectReader reader(*value, parent.source(), parent.keyPath("flame"));
  FlameGenome genome;
  const json* xforms = reader.find("xforms");
  if (!xforms) reader.fail("is missing", "xforms");
  if (!xforms->is_array() || xforms->empty() || xforms->size() > kMaxFlameXforms)
    reader.fail("must be an array of 1 to " + std::to_string(kMaxFlameXforms) + " transforms", "xforms");
  for (std::size_t i = 0; i < xforms->size(); ++i)
    genome.xforms.push_back(
        readXform((*xforms)[i], parent.source(), reader.keyPath("xforms") + "[" + std::to_string(i) + "]", false));
  failOn(reader, flameWeightFailure(genome));
  if (const json* finalXform = reader.find("final")) {
    genome.hasFinal = true;
    genome.finalXform = readXform(*finalXform, parent.source(), reader.keyPath("final"), true);
  }
  if (const json* symmetry = reader.find("symmetry")) {
    ObjectReader symmetryReader(*symmetry, parent.source(), reader.keyPath("symmetry"));
    readFields(symmetryReader, symmetryFields(), genome.symmetry);
    failOn(symmetryReader, zeroAxisFailure(genome.symmetry.axis));
    symmetryReader.finish();
  }
  reader.finish();
  return genome;
}

// Hand code: `c` is four numbers.
QuaternionJuliaSettings readJulia(ObjectReader& parent) {
  QuaternionJuliaSettings q;
  const json* value = parent.find("julia");
  if (!value) return q;
  ObjectReader reader(*value, parent.source(), parent.keyPath("julia"));
  if (const json* c = reader.find("c")) {
    if (!c->is_array() || c->size() != 4) reader.fail("must be four numbers (1, i, j, k components)", "c");
    for (std::size_t i = 0; i < 4; ++i) q.c[static_cast<int>(i)] = reader.checkNumber((*c)[i], "c", -10.0, 10.0);
  }
  readFields(reader, juliaFields(), q);
  reader.finish();
  return q;
}

// Hand code: the kind decides which keys a layer has; an attractor's params are named by its
// catalogue entry, and its integrator and step default to the catalogue's.
PatternLayer readLayer(const json& value, const std::string& source, const std::string& path) {
  ObjectReader reader(value, source, path);
  PatternLayer layer;
  const std::string kind = reader.string("kind", "attractor");
  try {
    layer.kind = patternKindFromString(kind);
  } catch (const Error& e) {
    reader.fail(e.what(), "kind");
  }
  if (layer.isChaosGame()) {
    layer.attractor.clear();
    layer.params.clear();
    if (layer.kind == PatternKind::Flame)
      layer.flame = readFlame(reader);
    else
      layer.julia = readJulia(reader);
  } else {
    layer.attractor = reader.requiredString("attractor");
    const AttractorInfo* info = findAttractor(layer.attractor);
    if (!info) {
      try {
        attractorOrThrow(layer.attractor);
      } catch (const Error& e) {
        reader.fail(e.what(), "attractor");
      }
    }
    layer.params = info->defaultParams();
    if (const json* params = reader.find("params")) {
      ObjectReader paramReader(*params, source, reader.keyPath("params"));
      for (std::size_t i = 0; i < info->params.size(); ++i)
        layer.params[i] = paramReader.number(info->params[i].name, info->params[i].defaultValue, -1e6, 1e6);
      paramReader.finish();
    }
    layer.integrator = info->defaultIntegrator;
    layer.step = info->defaultStep;
  }
  readFields(reader, layerFields(), layer);
  layer.color = readColor(reader, layer.isChaosGame() ? ColorMode::Index : ColorMode::Speed);
  layer.transform = readTransform(reader);
  reader.finish();
  return layer;
}

// Hand code: mesh.path, with the builtin: prefix naming a mesh inside the binary.
void readMesh(ObjectReader& root, Scene& scene) {
  const json* mesh = root.find("mesh");
  if (!mesh) root.fail("is missing", "mesh");
  ObjectReader meshReader(*mesh, root.source(), "mesh");
  scene.meshPath = meshReader.requiredString("path");
  if (scene.meshPath.empty()) meshReader.fail("must not be empty", "path");
  if (scene.meshPath.rfind(kBuiltinMeshPrefix, 0) == 0) {
    scene.meshPath = scene.meshPath.substr(std::string_view(kBuiltinMeshPrefix).size());
    scene.embedded = true;
    scene.baseDirectory = "presets";
  }
  meshReader.finish();
}

template <class Owner>
void readBlock(ObjectReader& root, const std::string& key, Table<Owner> table, Owner& owner,
               std::optional<Failure> (*check)(const Owner&) = nullptr) {
  const json* value = root.find(key);
  if (!value) return;
  ObjectReader reader(*value, root.source(), key);
  readFields(reader, table, owner);
  if (check) failOn(reader, check(owner));
  reader.finish();
}

// ---------------------------------------------------------------------------------------------
// The writer.

json vectorJson(const glm::dvec3& v) {
  return json::array({v.x, v.y, v.z});
}

json xformJson(const FlameXform& xform, bool isFinal, bool complete) {
  json out = json::object();
  writeFields(out, xformFields(), xform, complete, isFinal ? "weight" : "");
  out["affine"] = json(xform.affine.m);
  if (xform.hasPost) out["post"] = json(xform.post.m);
  json variations = json::array();
  for (const VariationTerm& term : xform.variations) {
    json v = {{"name", term.name}};
    writeFields(v, variationFields(), term, complete);
    const VariationInfo& info = variationOrThrow(term.name);
    for (std::size_t i = 0; i < info.params.size() && i < term.params.size(); ++i)
      v[info.params[i].name] = term.params[i];
    variations.push_back(v);
  }
  out["variations"] = variations;
  if (!isFinal && !xform.xaos.empty()) out["xaos"] = json(xform.xaos);
  return out;
}

json flameJson(const FlameGenome& genome, bool complete) {
  json xforms = json::array();
  for (const FlameXform& x : genome.xforms) xforms.push_back(xformJson(x, false, complete));
  json out = {{"xforms", xforms}};
  if (genome.hasFinal) out["final"] = xformJson(genome.finalXform, true, complete);
  if (complete || genome.symmetry != FlameSymmetry{})
    writeFields(out["symmetry"], symmetryFields(), genome.symmetry, complete);
  return out;
}

json layerJson(const PatternLayer& layer, bool complete) {
  json entry = json::object();
  if (layer.kind == PatternKind::Flame) {
    entry["kind"] = "flame";
    entry["flame"] = flameJson(layer.flame, complete);
  } else if (layer.kind == PatternKind::QuaternionJulia) {
    const QuaternionJuliaSettings& q = layer.julia;
    entry["kind"] = "quaternion_julia";
    json julia = {{"c", {q.c.x, q.c.y, q.c.z, q.c.w}}};
    writeFields(julia, juliaFields(), q, complete);
    entry["julia"] = julia;
  } else {
    const AttractorInfo& info = attractorOrThrow(layer.attractor);
    json params = json::object();
    for (std::size_t i = 0; i < info.params.size() && i < layer.params.size(); ++i)
      params[info.params[i].name] = layer.params[i];
    entry["attractor"] = layer.attractor;
    entry["params"] = params;
  }
  writeFields(entry, layerFields(), layer, complete);

  json color = json::object();
  writeFields(color, colorFields(), layer.color, complete);
  if (layer.color.palette.empty()) {
    json gradient = json::array();
    for (const auto& stop : layer.color.gradient) gradient.push_back(toHexColor(stop.color));
    color["gradient"] = gradient;
  } else {
    color["palette"] = layer.color.palette;
  }
  entry["color"] = color;

  // The block is left out while it places the layer as the automatic fit does.
  const LayerTransform& t = layer.transform;
  const LayerTransform none;
  if (complete || t.scale != none.scale || t.rotationDeg != none.rotationDeg || t.offset != none.offset ||
      t.fit != none.fit || !t.copies.empty() || t.lockFit) {
    json transform = json::object();
    writeFields(transform, transformFields(), t, complete);
    if (complete || !t.copies.empty()) {
      json copies = json::array();
      for (const glm::dvec3& copy : t.copies) copies.push_back(vectorJson(copy));
      transform["copies"] = copies;
    }
    if (t.lockFit) writeFields(transform["locked_fit"], lockedFitFields(), t, complete);
    entry["transform"] = transform;
  }
  return entry;
}

}  // namespace

Table<Scene> sceneFields() {
  return kSceneFields;
}
Table<PatternLayer> layerFields() {
  return kLayerFields;
}
Table<ColorSettings> colorFields() {
  return kColorFields;
}
Table<LayerTransform> transformFields() {
  return kTransformFields;
}
Table<LayerTransform> lockedFitFields() {
  return kLockedFitFields;
}
Table<FlameGenome> flameFields() {
  return kFlameFields;
}
Table<FlameXform> xformFields() {
  return kXformFields;
}
Table<VariationTerm> variationFields() {
  return kVariationFields;
}
Table<FlameSymmetry> symmetryFields() {
  return kSymmetryFields;
}
Table<QuaternionJuliaSettings> juliaFields() {
  return kJuliaFields;
}
Table<ToneMapSettings> toneFields() {
  return kToneFields;
}
Table<CameraSettings> cameraFields() {
  return kCameraFields;
}
Table<RenderSettingsDoc> renderFields() {
  return kRenderFields;
}
Table<AnimationSettings> animationFields() {
  return kAnimationFields;
}
Table<FlatViewSettings> flatFields() {
  return kFlatFields;
}

Scene sceneFromDocument(const json& document, std::string_view sourceName,
                        std::span<const std::string_view> readElsewhere) {
  const std::string source(sourceName);
  ObjectReader root(document, source, "");
  Scene scene;
  root.integer("schema_version", kSchemaVersion, kSchemaVersion, kSchemaVersion);  // migrated already
  for (std::string_view key : readElsewhere) root.find(std::string(key));
  readFields(root, sceneFields(), scene);
  readMesh(root, scene);

  // Hand code: the layers, an array of objects.
  const json* layers = root.find("layers");
  if (!layers) root.fail("is missing", "layers");
  if (!layers->is_array() || layers->empty() || layers->size() > 16)
    root.fail("must be an array of 1 to 16 pattern layers", "layers");
  for (std::size_t i = 0; i < layers->size(); ++i)
    scene.layers.push_back(readLayer((*layers)[i], source, "layers[" + std::to_string(i) + "]"));

  readBlock(root, "tone", toneFields(), scene.tone, &toneFailure);
  readBlock(root, "camera", cameraFields(), scene.camera, &cameraFailure);
  readBlock(root, "render", renderFields(), scene.render);
  readBlock(root, "animation", animationFields(), scene.animation);
  readBlock(root, "flat", flatFields(), scene.flat);
  root.finish();
  return scene;
}

json sceneDocument(const Scene& scene, bool complete) {
  json root = json::object();
  root["schema_version"] = kSchemaVersion;
  writeFields(root, sceneFields(), scene, complete);
  root["mesh"] = {{"path", (scene.embedded ? std::string(kBuiltinMeshPrefix) : std::string()) + scene.meshPath}};
  json layers = json::array();
  for (const PatternLayer& layer : scene.layers) layers.push_back(layerJson(layer, complete));
  root["layers"] = layers;
  writeFields(root["tone"], toneFields(), scene.tone, complete);
  writeFields(root["camera"], cameraFields(), scene.camera, complete);
  writeFields(root["render"], renderFields(), scene.render, complete);
  // A still's document has no animation block; one with keyframes always has it.
  if (complete || !scene.keyframes.empty() || scene.animation != AnimationSettings{})
    writeFields(root["animation"], animationFields(), scene.animation, complete);
  // Only imported flames have a framing of their own; other presets leave the block out.
  if (complete || scene.flat != FlatViewSettings{}) writeFields(root["flat"], flatFields(), scene.flat, complete);
  return root;
}

void checkSceneConstraints(const Scene& scene, const std::string& sourceName) {
  const auto check = [&](const std::string& path, const std::optional<Failure>& failure) {
    if (failure) throw Error(sourceName + ": '" + path + "." + failure->key + "' " + failure->reason);
  };
  check("tone", toneFailure(scene.tone));
  check("camera", cameraFailure(scene.camera));
  for (std::size_t i = 0; i < scene.layers.size(); ++i) {
    const PatternLayer& layer = scene.layers[i];
    const std::string path = "layers[" + std::to_string(i) + "]";
    check(path + ".color", zeroAxisFailure(layer.color.axis));
    if (layer.kind == PatternKind::Flame) {
      check(path + ".flame", flameWeightFailure(layer.flame));
      check(path + ".flame.symmetry", zeroAxisFailure(layer.flame.symmetry.axis));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Values by JSON Pointer.

double NumberSlot::get() const {
  return std::visit([](auto* p) { return static_cast<double>(*p); }, target);
}

namespace {

std::string unescapeToken(std::string_view token) {
  std::string out;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (token[i] == '~' && i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1')) {
      out += token[i + 1] == '0' ? '~' : '/';
      ++i;
    } else {
      out += token[i];
    }
  }
  return out;
}

std::string escapeToken(std::string_view token) {
  std::string out;
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

// An array index as RFC 6901 writes it: "0" or digits without a leading zero.
std::optional<std::size_t> arrayIndex(const std::string& token) {
  if (token.empty() || token.size() > 9 ||
      !std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  if (token.size() > 1 && token[0] == '0') return std::nullopt;
  return static_cast<std::size_t>(std::stoul(token));
}

ValueRef missing() {
  return {};
}

ValueRef other(std::string what, std::string path) {
  ValueRef ref;
  ref.kind = ValueRef::Kind::Other;
  ref.what = std::move(what);
  ref.messagePath = std::move(path);
  return ref;
}

ValueRef textValue(const std::string& text, std::string path) {
  return other("the text " + json(text).dump(), std::move(path));
}

template <class T>
ValueRef numberRef(T* target, double min, double max, std::string path) {
  ValueRef ref;
  ref.kind = ValueRef::Kind::Number;
  ref.numbers.push_back({target, min, max});
  ref.messagePath = std::move(path);
  return ref;
}

ValueRef arrayRef(double* first, std::size_t count, double min, double max, std::string path) {
  ValueRef ref;
  ref.kind = ValueRef::Kind::Array;
  for (std::size_t i = 0; i < count; ++i) ref.numbers.push_back({first + i, min, max});
  ref.messagePath = std::move(path);
  return ref;
}

// Walks the pointer's tokens. Each step either ends on a value (the Ref functions) or descends.
struct Walk {
  std::vector<std::string> tokens;
  std::size_t at = 0;
  bool done() const { return at == tokens.size(); }
  const std::string& peek() const { return tokens[at]; }
  const std::string& next() { return tokens[at++]; }
};

// An array of numbers, or one of its elements.
ValueRef numbersAt(Walk& w, double* first, std::size_t count, double min, double max, const std::string& path) {
  if (w.done()) return arrayRef(first, count, min, max, path);
  const auto index = arrayIndex(w.next());
  if (!index || *index >= count || !w.done()) return missing();
  return numberRef(first + *index, min, max, path);
}

std::string joinPath(const std::string& base, std::string_view key) {
  return base.empty() ? std::string(key) : base + "." + std::string(key);
}

template <class Owner>
std::optional<ValueRef> fromTable(Walk& w, Table<Owner> table, Owner& owner, const std::string& base,
                                  std::string_view skip = {}) {
  for (const Field<Owner>& f : table) {
    if (f.type() == FieldType::Hand || !f.presentIn(owner) || f.key == skip) continue;
    const auto [object, key] = splitKey(f.key);
    const std::size_t start = w.at;
    if (!object.empty()) {
      if (w.peek() != object) continue;
      ++w.at;
      if (w.done()) return other("an object", joinPath(base, object));
    }
    if (w.peek() != key) {
      w.at = start;
      continue;
    }
    ++w.at;
    const std::string path = joinPath(base, f.key);
    return std::visit(
        [&]<class M>(const M& member) -> ValueRef {
          if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
            return numbersAt(w, &(owner.*member).x, 3, f.min, f.max, path);
          } else {
            if (!w.done()) return missing();
            if constexpr (std::is_same_v<M, double Owner::*> || std::is_same_v<M, int Owner::*> ||
                          std::is_same_v<M, std::uint64_t Owner::*>) {
              return numberRef(&(owner.*member), f.min, f.max, path);
            } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
              ValueRef ref;
              ref.kind = ValueRef::Kind::Color;
              ref.color = &(owner.*member);
              ref.messagePath = path;
              return ref;
            } else if constexpr (std::is_same_v<M, bool Owner::*>) {
              return other("true or false", path);
            } else if constexpr (std::is_same_v<M, std::string Owner::*>) {
              return textValue(owner.*member, path);
            } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
              return textValue(std::string(member.names[static_cast<std::size_t>(member.get(owner))]), path);
            } else {
              return missing();
            }
          }
        },
        f.member);
  }
  return std::nullopt;
}

template <class Owner>
ValueRef objectAt(Walk& w, Table<Owner> table, Owner& owner, const std::string& base, std::string_view skip = {}) {
  if (w.done()) return other("an object", base);
  if (auto ref = fromTable(w, table, owner, base, skip)) return *ref;
  return missing();
}

ValueRef xformAt(Walk& w, FlameXform& xform, const std::string& base, bool isFinal) {
  if (w.done()) return other("an object", base);
  const std::string& key = w.peek();
  if (key == "affine" || (key == "post" && xform.hasPost)) {
    w.next();
    Affine3& affine = key == "affine" ? xform.affine : xform.post;
    return numbersAt(w, affine.m.data(), 12, -1e6, 1e6, joinPath(base, key));
  }
  if (key == "variations") {
    w.next();
    const std::string path = joinPath(base, "variations");
    if (w.done()) return other("an array", path);
    const auto index = arrayIndex(w.next());
    if (!index || *index >= xform.variations.size()) return missing();
    VariationTerm& term = xform.variations[*index];
    const std::string termPath = path + "[" + std::to_string(*index) + "]";
    if (w.done()) return other("an object", termPath);
    if (w.peek() == "name") {
      w.next();
      return w.done() ? textValue(term.name, joinPath(termPath, "name")) : missing();
    }
    if (auto ref = fromTable(w, variationFields(), term, termPath)) return *ref;
    const VariationInfo* info = findVariation(term.name);
    const int param = info ? info->paramIndex(w.peek()) : -1;
    if (param < 0 || static_cast<std::size_t>(param) >= term.params.size()) return missing();
    const std::string name = w.next();
    if (!w.done()) return missing();
    return numberRef(&term.params[static_cast<std::size_t>(param)], -1e6, 1e6, joinPath(termPath, name));
  }
  return objectAt(w, xformFields(), xform, base, isFinal ? "weight" : "");
}

ValueRef flameAt(Walk& w, FlameGenome& flame, const std::string& base) {
  if (w.done()) return other("an object", base);
  const std::string key = w.next();
  if (key == "xforms") {
    const std::string path = joinPath(base, "xforms");
    if (w.done()) return other("an array", path);
    const auto index = arrayIndex(w.next());
    if (!index || *index >= flame.xforms.size()) return missing();
    return xformAt(w, flame.xforms[*index], path + "[" + std::to_string(*index) + "]", false);
  }
  if (key == "final" && flame.hasFinal) return xformAt(w, flame.finalXform, joinPath(base, "final"), true);
  if (key == "symmetry") return objectAt(w, symmetryFields(), flame.symmetry, joinPath(base, "symmetry"));
  return missing();
}

ValueRef colorAt(Walk& w, ColorSettings& color, const std::string& base) {
  if (w.done()) return other("an object", base);
  if (w.peek() == "gradient" && color.palette.empty()) {
    w.next();
    const std::string path = joinPath(base, "gradient");
    if (w.done()) return other("an array", path);
    const auto index = arrayIndex(w.next());
    if (!index || *index >= color.gradient.size() || !w.done()) return missing();
    ValueRef ref;
    ref.kind = ValueRef::Kind::Color;
    ref.color = &color.gradient[*index].color;
    ref.messagePath = path + "[" + std::to_string(*index) + "]";
    return ref;
  }
  if (w.peek() == "palette" && !color.palette.empty()) {
    w.next();
    return w.done() ? textValue(color.palette, joinPath(base, "palette")) : missing();
  }
  return objectAt(w, colorFields(), color, base);
}

ValueRef transformAt(Walk& w, LayerTransform& transform, const std::string& base) {
  if (w.done()) return other("an object", base);
  if (w.peek() == "copies") {
    w.next();
    const std::string path = joinPath(base, "copies");
    if (w.done()) return other("an array", path);
    const auto index = arrayIndex(w.next());
    if (!index || *index >= transform.copies.size()) return missing();
    return numbersAt(w, &transform.copies[*index].x, 3, -3600.0, 3600.0, path + "[" + std::to_string(*index) + "]");
  }
  if (w.peek() == "locked_fit" && transform.lockFit) {
    w.next();
    return objectAt(w, lockedFitFields(), transform, joinPath(base, "locked_fit"));
  }
  return objectAt(w, transformFields(), transform, base);
}

ValueRef layerAt(Walk& w, PatternLayer& layer, const std::string& base) {
  if (w.done()) return other("an object", base);
  const std::string& key = w.peek();
  const bool attractor = layer.kind == PatternKind::Attractor;
  if (key == "kind" && !attractor) {
    w.next();
    return w.done() ? textValue(std::string(toString(layer.kind)), joinPath(base, "kind")) : missing();
  }
  if (key == "attractor" && attractor) {
    w.next();
    return w.done() ? textValue(layer.attractor, joinPath(base, "attractor")) : missing();
  }
  if (key == "params" && attractor) {
    w.next();
    const std::string path = joinPath(base, "params");
    if (w.done()) return other("an object", path);
    const AttractorInfo* info = findAttractor(layer.attractor);
    const std::string name = w.next();
    if (!info || !w.done()) return missing();
    for (std::size_t i = 0; i < info->params.size() && i < layer.params.size(); ++i)
      if (info->params[i].name == name) return numberRef(&layer.params[i], -1e6, 1e6, joinPath(path, name));
    return missing();
  }
  if (key == "flame" && layer.kind == PatternKind::Flame) {
    w.next();
    return flameAt(w, layer.flame, joinPath(base, "flame"));
  }
  if (key == "julia" && layer.kind == PatternKind::QuaternionJulia) {
    w.next();
    const std::string path = joinPath(base, "julia");
    if (!w.done() && w.peek() == "c") {
      w.next();
      return numbersAt(w, &layer.julia.c.x, 4, -10.0, 10.0, joinPath(path, "c"));
    }
    return objectAt(w, juliaFields(), layer.julia, path);
  }
  if (key == "color") {
    w.next();
    return colorAt(w, layer.color, joinPath(base, "color"));
  }
  if (key == "transform") {
    w.next();
    return transformAt(w, layer.transform, joinPath(base, "transform"));
  }
  return objectAt(w, layerFields(), layer, base);
}

ValueRef sceneAt(Walk& w, Scene& scene) {
  if (w.done()) return other("an object", "");
  const std::string& key = w.peek();
  if (key == "schema_version" || key == "animation" || key == "keyframes") return missing();
  if (key == "mesh") {
    w.next();
    if (w.done()) return other("an object", "mesh");
    if (w.next() != "path" || !w.done()) return missing();
    return textValue((scene.embedded ? std::string(kBuiltinMeshPrefix) : "") + scene.meshPath, "mesh.path");
  }
  if (key == "layers") {
    w.next();
    if (w.done()) return other("an array", "layers");
    const auto index = arrayIndex(w.next());
    if (!index || *index >= scene.layers.size()) return missing();
    return layerAt(w, scene.layers[*index], "layers[" + std::to_string(*index) + "]");
  }
  if (key == "tone" || key == "camera" || key == "render" || key == "flat") {
    const std::string object = w.next();
    if (object == "tone") return objectAt(w, toneFields(), scene.tone, object);
    if (object == "camera") return objectAt(w, cameraFields(), scene.camera, object);
    if (object == "flat") return objectAt(w, flatFields(), scene.flat, object);
    return objectAt(w, renderFields(), scene.render, object);
  }
  if (auto ref = fromTable(w, sceneFields(), scene, "")) return *ref;
  return missing();
}

}  // namespace

ValueRef resolveValue(Scene& scene, std::string_view pointer) {
  if (pointer.empty() || pointer[0] != '/') return missing();
  Walk w;
  std::size_t start = 1;
  while (true) {
    const std::size_t slash = pointer.find('/', start);
    w.tokens.push_back(unescapeToken(pointer.substr(start, slash == std::string_view::npos ? slash : slash - start)));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return sceneAt(w, scene);
}

ValueRef resolveValue(const Scene& scene, std::string_view pointer) {
  return resolveValue(const_cast<Scene&>(scene), pointer);  // the header's contract: only read through it
}

void setNumbers(const ValueRef& ref, std::span<const double> values, const std::string& sourceName) {
  const auto fail = [&](const std::string& reason) {
    throw Error(sourceName + ": '" + ref.messagePath + "' " + reason);
  };
  std::vector<double> checked(values.begin(), values.end());
  for (std::size_t i = 0; i < ref.numbers.size() && i < checked.size(); ++i) {
    const NumberSlot& slot = ref.numbers[i];
    double v = checked[i];
    if (slot.integer()) {
      v = std::round(v);
      if (!(std::abs(v) < 9e18)) fail(outsideRange(v, slot.min, slot.max));
      const auto whole = static_cast<std::int64_t>(v);
      if (v < slot.min || v > slot.max)
        fail(outsideRange(whole, static_cast<std::int64_t>(slot.min), static_cast<std::int64_t>(slot.max)));
    } else if (!std::isfinite(v) || v < slot.min || v > slot.max) {
      fail(outsideRange(v, slot.min, slot.max));
    }
    checked[i] = v;
  }
  for (std::size_t i = 0; i < ref.numbers.size() && i < checked.size(); ++i)
    std::visit([&](auto* p) { *p = static_cast<std::remove_pointer_t<decltype(p)>>(checked[i]); },
               ref.numbers[i].target);
}

std::string describe(const ValueRef& ref) {
  switch (ref.kind) {
    case ValueRef::Kind::Number:
      return "a number";
    case ValueRef::Kind::Array:
      return "an array of " + std::to_string(ref.numbers.size()) + " numbers";
    case ValueRef::Kind::Color:
      return "a colour";
    case ValueRef::Kind::Other:
      return ref.what;
    case ValueRef::Kind::Missing:
      break;
  }
  return "nothing";
}

namespace {

template <class Owner>
void tablePaths(Table<Owner> table, const Owner& owner, const std::string& base, std::vector<std::string>& out,
                std::string_view skip = {}) {
  for (const Field<Owner>& f : table) {
    const FieldType type = f.type();
    if (!f.presentIn(owner) || f.key == skip) continue;
    if (type != FieldType::Number && type != FieldType::Integer && type != FieldType::Unsigned &&
        type != FieldType::Vector3 && type != FieldType::Color)
      continue;
    std::string key(f.key);
    std::replace(key.begin(), key.end(), '.', '/');
    out.push_back(base + "/" + key);
  }
}

void xformPaths(const FlameXform& xform, const std::string& base, bool isFinal, std::vector<std::string>& out) {
  tablePaths(xformFields(), xform, base, out, isFinal ? "weight" : "");
  out.push_back(base + "/affine");
  if (xform.hasPost) out.push_back(base + "/post");
  for (std::size_t k = 0; k < xform.variations.size(); ++k) {
    const VariationTerm& term = xform.variations[k];
    const std::string path = base + "/variations/" + std::to_string(k);
    tablePaths(variationFields(), term, path, out);
    if (const VariationInfo* info = findVariation(term.name))
      for (std::size_t p = 0; p < info->params.size() && p < term.params.size(); ++p)
        out.push_back(path + "/" + escapeToken(info->params[p].name));
  }
}

// Document order: object keys sorted as strings, array elements by index.
bool documentOrder(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const std::size_t ei = std::min(a.find('/', i + 1), a.size()), ej = std::min(b.find('/', j + 1), b.size());
    const std::string ta = a.substr(i + 1, ei - i - 1), tb = b.substr(j + 1, ej - j - 1);
    if (ta != tb) {
      const auto na = arrayIndex(ta), nb = arrayIndex(tb);
      if (na && nb) return *na < *nb;
      return ta < tb;
    }
    i = ei, j = ej;
  }
  return a.size() - i < b.size() - j;
}

}  // namespace

std::vector<std::string> animatablePaths(const Scene& scene) {
  std::vector<std::string> out;
  tablePaths(sceneFields(), scene, "", out);
  tablePaths(toneFields(), scene.tone, "/tone", out);
  tablePaths(cameraFields(), scene.camera, "/camera", out);
  tablePaths(renderFields(), scene.render, "/render", out);
  tablePaths(flatFields(), scene.flat, "/flat", out);
  for (std::size_t i = 0; i < scene.layers.size(); ++i) {
    const PatternLayer& layer = scene.layers[i];
    const std::string base = "/layers/" + std::to_string(i);
    tablePaths(layerFields(), layer, base, out);
    if (layer.kind == PatternKind::Attractor) {
      if (const AttractorInfo* info = findAttractor(layer.attractor))
        for (std::size_t p = 0; p < info->params.size() && p < layer.params.size(); ++p)
          out.push_back(base + "/params/" + escapeToken(info->params[p].name));
    } else if (layer.kind == PatternKind::Flame) {
      for (std::size_t j = 0; j < layer.flame.xforms.size(); ++j)
        xformPaths(layer.flame.xforms[j], base + "/flame/xforms/" + std::to_string(j), false, out);
      if (layer.flame.hasFinal) xformPaths(layer.flame.finalXform, base + "/flame/final", true, out);
      tablePaths(symmetryFields(), layer.flame.symmetry, base + "/flame/symmetry", out);
    } else {
      out.push_back(base + "/julia/c");
      tablePaths(juliaFields(), layer.julia, base + "/julia", out);
    }
    tablePaths(colorFields(), layer.color, base + "/color", out);
    if (layer.color.palette.empty())
      for (std::size_t k = 0; k < layer.color.gradient.size(); ++k)
        out.push_back(base + "/color/gradient/" + std::to_string(k));
    tablePaths(transformFields(), layer.transform, base + "/transform", out);
    for (std::size_t c = 0; c < layer.transform.copies.size(); ++c)
      out.push_back(base + "/transform/copies/" + std::to_string(c));
    if (layer.transform.lockFit) tablePaths(lockedFitFields(), layer.transform, base + "/transform/locked_fit", out);
  }
  std::sort(out.begin(), out.end(), documentOrder);
  return out;
}

// ---------------------------------------------------------------------------------------------
// diff

bool SceneDiff::touches(std::string_view path) const {
  const auto under = [](std::string_view inner, std::string_view outer) {
    return inner.size() > outer.size() && inner.substr(0, outer.size()) == outer && inner[outer.size()] == '/';
  };
  return std::any_of(paths.begin(), paths.end(),
                     [&](const std::string& p) { return p == path || under(p, path) || under(path, p); });
}

namespace {

void note(SceneDiff& d, std::string path, Affects affects) {
  d.paths.push_back(std::move(path));
  d.affects |= affects;
}

template <class Owner>
void diffTable(const Owner& a, const Owner& b, Table<Owner> table, const std::string& base, SceneDiff& d) {
  for (const Field<Owner>& f : table) {
    if (f.type() == FieldType::Hand || fieldEqual(a, b, f)) continue;
    std::string key(f.key);
    std::replace(key.begin(), key.end(), '.', '/');
    note(d, base + "/" + key, f.affects);
  }
}

void diffXform(const FlameXform& a, const FlameXform& b, const std::string& base, SceneDiff& d) {
  diffTable(a, b, xformFields(), base, d);
  if (a.affine != b.affine) note(d, base + "/affine", kPattern);
  if (a.hasPost != b.hasPost || a.post != b.post) note(d, base + "/post", kPattern);
  if (a.variations != b.variations) note(d, base + "/variations", kPattern);
  if (a.xaos != b.xaos) note(d, base + "/xaos", kPattern);
}

void diffLayer(const PatternLayer& a, const PatternLayer& b, const std::string& base, SceneDiff& d) {
  const std::size_t before = d.paths.size();
  if (a.kind != b.kind) note(d, base + "/kind", kPattern);
  if (a.attractor != b.attractor) note(d, base + "/attractor", kPattern);
  if (a.params.size() != b.params.size()) {
    note(d, base + "/params", kPattern);
  } else {
    const AttractorInfo* info = a.attractor == b.attractor ? findAttractor(a.attractor) : nullptr;
    for (std::size_t i = 0; i < a.params.size(); ++i)
      if (a.params[i] != b.params[i])
        note(d,
             base + "/params/" +
                 (info && i < info->params.size() ? escapeToken(info->params[i].name) : std::to_string(i)),
             kPattern);
  }
  diffTable(a, b, layerFields(), base, d);
  if (a.flame != b.flame) {
    const std::string flame = base + "/flame";
    if (a.flame.xforms.size() != b.flame.xforms.size()) {
      note(d, flame + "/xforms", kPattern);
    } else {
      for (std::size_t j = 0; j < a.flame.xforms.size(); ++j)
        if (a.flame.xforms[j] != b.flame.xforms[j])
          diffXform(a.flame.xforms[j], b.flame.xforms[j], flame + "/xforms/" + std::to_string(j), d);
    }
    if (a.flame.hasFinal != b.flame.hasFinal)
      note(d, flame + "/final", kPattern);
    else if (a.flame.finalXform != b.flame.finalXform)
      diffXform(a.flame.finalXform, b.flame.finalXform, flame + "/final", d);
    diffTable(a.flame.symmetry, b.flame.symmetry, symmetryFields(), flame + "/symmetry", d);
  }
  if (a.julia.c != b.julia.c) note(d, base + "/julia/c", kPattern);
  diffTable(a.julia, b.julia, juliaFields(), base + "/julia", d);
  diffTable(a.color, b.color, colorFields(), base + "/color", d);
  if (a.color.gradient != b.color.gradient) note(d, base + "/color/gradient", kPattern);
  if (a.color.palette != b.color.palette) note(d, base + "/color/palette", kPattern);
  diffTable(a.transform, b.transform, transformFields(), base + "/transform", d);
  if (a.transform.copies != b.transform.copies) note(d, base + "/transform/copies", kPattern);
  if (a.transform.lockFit != b.transform.lockFit)
    note(d, base + "/transform/locked_fit", kPattern);
  else
    diffTable(a.transform, b.transform, lockedFitFields(), base + "/transform/locked_fit", d);
  if (d.paths.size() == before) note(d, base, kPattern);  // unequal in a way no path names: say the layer
}

}  // namespace

SceneDiff diff(const Scene& a, const Scene& b) {
  SceneDiff d;
  if (a == b) return d;
  diffTable(a, b, sceneFields(), "", d);
  if (a.meshPath != b.meshPath || a.embedded != b.embedded || a.baseDirectory != b.baseDirectory)
    note(d, "/mesh/path", kPattern | kView);
  if (a.layers.size() != b.layers.size()) {
    note(d, "/layers", kPattern);
  } else {
    for (std::size_t i = 0; i < a.layers.size(); ++i)
      if (a.layers[i] != b.layers[i]) diffLayer(a.layers[i], b.layers[i], "/layers/" + std::to_string(i), d);
  }
  diffTable(a.tone, b.tone, toneFields(), "/tone", d);
  diffTable(a.camera, b.camera, cameraFields(), "/camera", d);
  diffTable(a.render, b.render, renderFields(), "/render", d);
  diffTable(a.animation, b.animation, animationFields(), "/animation", d);
  diffTable(a.flat, b.flat, flatFields(), "/flat", d);
  if (a.keyframes != b.keyframes) note(d, "/keyframes", kNothing);
  return d;
}

}  // namespace voxflame::core
