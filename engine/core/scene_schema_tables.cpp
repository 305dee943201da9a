// The schema's tables: a row for every key of every object of a preset (see scene_schema.h), and
// the names of what a change affects. The reader, the writer, the JSON Pointer resolution, diff()
// and SCHEMA.md all walk these rows.
#include "scene_schema.h"

#include "grid.h"
#include "scene_schema_internal.h"

namespace voxflame::core {

using namespace schema_internal;

std::string toString(Affects affects) {
  if (!any(affects)) return "nothing drawn";
  std::string text;
  for (auto [bit, name] : {std::pair{Affects::Pattern, "pattern"}, std::pair{Affects::View, "view"},
                           std::pair{Affects::Tone, "tone"}, std::pair{Affects::Still, "still"}})
    if (any(affects & bit)) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

namespace {

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

constexpr double kTwo53 = 9007199254740992.0;
constexpr double kTwo40 = 1099511627776.0;

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
     .member = choice<&PatternLayer::integrator>(kIntegratorNames, "integrator"),
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
     .member = choice<&ColorSettings::mode>(kColorModeNames, "colour mode"),
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
     .member = choice<&LayerTransform::fit>(kFitModeNames, "fit mode"),
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
    {.key = "final_chain",
     .help = "further final transforms, applied one after the other after `final` (JWildfire chains several)",
     .affects = kPattern,
     .typeText = "array",
     .rangeText = "0–16 transforms without `weight`; needs `final`",
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
    {.key = "direct_color",
     .member = &FlameXform::directColor,
     .min = 0.0,
     .max = 1.0,
     .ui = {"direct colour", 0.0, 1.0},
     .help = "how much of the colour index its direct-colour variations (dc_linear, ...) set is kept "
             "(Fractorium's var_color)",
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
     .member = choice<&QuaternionJuliaSettings::view>(kQuaternionViewNames, "view"),
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
    {.key = "projection",
     .member = choice<&CameraSettings::projection>(kProjectionNames, "projection"),
     .affects = kView},
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
     .member = choice<&RenderSettingsDoc::meshDisplay>(kMeshDisplayNames, "mesh display"),
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
     .member = choice<&RenderSettingsDoc::method>(kRenderMethodNames, "render method"),
     .ui = {"still method"},
     .help = "how stills are made: ray-march the voxel grid, or project every point into a supersampled screen "
             "histogram (pixel-fine filaments; the grid only dims points by the density in front of them). The "
             "explorer's view shows the same picture once it is still",
     .affects = kStill,
     .defaultText = "`volume` (`points` when a layer is a flame)"},
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
     .member = choice<&FlatViewSettings::paletteMode>(kPaletteModeNames, "palette mode"),
     .help = "flam3's colour lookup, in the flat view and in stills in the mesh: step takes the palette entry "
             "⌊index · 256⌋, linear blends the two around it",
     // The grid's colours too: the live view refines the pattern again.
     .affects = kPattern},
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

}  // namespace voxflame::core
