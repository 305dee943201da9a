// The Scene is the one document: everything a user can set, and exactly what a JSON preset
// holds. Loading validates every key against its allowed range and refuses unknown keys, naming
// the file, the key path and the reason, so a typo never silently does nothing.
//
// Presets carry a `schema_version`. Older documents are brought up to date by a chain of
// migrations (one function per version step, JSON to JSON) before they are read, so a preset
// written by any earlier voxflame keeps loading; a newer version than this build knows is refused.
// presets/SCHEMA.md documents every key. Version 2 added animation: the `animation` block and
// keyframe tracks (keyframes.h evaluates them).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include "attractor.h"
#include "color.h"
#include "core/flame/flame.h"

namespace voxflame::core {

inline constexpr int kSchemaVersion = 2;
inline constexpr std::size_t kMaxGradientStops = 256;  // a flam3 palette's 256 colours fit
// A mesh path starting with this names a mesh compiled into the binary ("builtin:meshes/bunny.obj").
inline constexpr const char* kBuiltinMeshPrefix = "builtin:";

// What a point's colour follows. Each mode yields a value normalised on the layer's probe orbit
// (so the gradient spans what the attractor actually does), times `scale`, clamped to [0, 1].
enum class ColorMode {
  Speed,      // distance travelled in the last step
  Curvature,  // sine of the turning angle between the last two steps
  Time,       // steps since the orbit was seeded, cycling through the gradient every `period`
  Axis,       // position along `axis` across the attractor's extent
  Distance,   // distance from the attractor's centre
  Index,      // chaos-game patterns: flam3's colour index, pulled towards each transform's colour
};
inline constexpr std::string_view kColorModeNames[] = {"speed", "curvature", "time", "axis", "distance", "index"};
std::string_view toString(ColorMode mode);
ColorMode colorModeFromString(std::string_view name);  // throws core::Error listing the modes

struct ColorSettings {
  ColorMode mode = ColorMode::Speed;
  std::vector<GradientStop> gradient;  // linear RGB stops (filled from `palette` when one is named)
  std::string palette;                 // a named palette (color.h), or empty for `gradient`
  glm::dvec3 axis{0.0, 0.0, 1.0};      // Axis mode, in attractor coordinates
  double period = 1000.0;              // Time mode: steps per trip through the gradient
  double scale = 1.0;                  // stretches the normalised value before clamping
  bool operator==(const ColorSettings&) const = default;
};

// How the automatic fit sizes the attractor's robust (5–95%) box against the mesh's inside box.
enum class FitMode {
  Contain,  // uniform scale: covers the shape along its middle axis, at most 2.5× over along the widest
  Cover,    // uniform scale: covers the shape along every axis (the largest ratio); the mask carves it
  Stretch,  // a scale per axis: the box matches the shape's on each axis (before the user's rotation)
  // The automatic fit of the layer before it (contain for the first layer), so layers drawn in
  // one coordinate system (a JWildfire flame's layers) stay in register instead of each filling
  // the mesh on its own.
  Previous,
};
inline constexpr std::string_view kFitModeNames[] = {"contain", "cover", "stretch", "previous"};
std::string_view toString(FitMode mode);
FitMode fitModeFromString(std::string_view name);  // throws core::Error listing the modes

// Places a layer in the grid on top of the automatic fit: scale about the fitted centre,
// rotation (degrees about x, then y, then z), offset as a fraction of the grid's longest side.
// With `lockFit` the automatic fit is replaced by the stored one, so parameter changes (an
// animation) never move or resize the pattern.
inline constexpr std::size_t kMaxLayerCopies = 15;  // copies of one layer besides the original

struct LayerTransform {
  double scale = 1.0;
  glm::dvec3 rotationDeg{0.0};
  glm::dvec3 offset{0.0};
  FitMode fit = FitMode::Contain;
  // More copies of the same pattern, each turned by its angles (added to rotationDeg, angle by
  // angle): a ribbon or a sheet then fills a mesh that one copy leaves half empty, and the copies
  // keep one set of parameters, so a slider moves them all. The layer's weight is shared among
  // the original and its copies.
  std::vector<glm::dvec3> copies;
  bool lockFit = false;
  glm::dvec3 lockedCenter{0.0};     // attractor coordinates mapped to the mask's centre
  double lockedScale = 1.0;         // voxels per attractor unit
  glm::dvec3 lockedAxisScale{1.0};  // per attractor axis, times lockedScale (a stretch fit's shape)
  bool operator==(const LayerTransform&) const = default;
};

// What a layer iterates: an attractor of the catalogue (attractor.h) or a chaos game (flame.h).
enum class PatternKind { Attractor, Flame, QuaternionJulia };
inline constexpr std::string_view kPatternKindNames[] = {"attractor", "flame", "quaternion_julia"};
std::string_view toString(PatternKind kind);
PatternKind patternKindFromString(std::string_view name);  // throws core::Error listing the kinds

// One pattern filling the volume; several layers share one grid, each with its weight.
struct PatternLayer {
  PatternKind kind = PatternKind::Attractor;
  std::string attractor = "lorenz84";  // Attractor layers only
  std::vector<double> params;          // in the catalogue's parameter order
  Integrator integrator = Integrator::Euler;
  double step = 0.135;  // flows only
  double weight = 1.0;
  ColorSettings color;
  LayerTransform transform;
  FlameGenome flame;              // Flame layers only
  QuaternionJuliaSettings julia;  // QuaternionJulia layers only
  bool isChaosGame() const { return kind != PatternKind::Attractor; }
  // What the layer shows, for lists and messages: the attractor's id, "flame" or "quaternion_julia".
  std::string patternName() const;
  bool operator==(const PatternLayer&) const = default;
};

// flam3-style tone mapping (flame/image.h), applied to each pixel's summed density, so changing it
// never restarts accumulation. Names follow flam3 (Draves & Reckase, "The Fractal Flame Algorithm").
struct ToneMapSettings {
  double brightness = 4.0;  // k1: scales the log density
  double gamma = 2.2;
  double gammaThreshold = 0.01;  // below this opacity the gamma curve is linear (no noise boost)
  double vibrancy = 1.0;         // 1: gamma on opacity keeps hues; 0: gamma per channel
  double highlightPower = -1.0;  // < 0 clips overexposed colours; ≥ 0 fades them to white
  double exposure = 0.0;         // stops
  double contrast = 1.0;         // around mid grey, after gamma
  double opacity = 1.0;          // how strongly dense regions hide what is behind them
  glm::vec3 background{0.0f};    // linear RGB
  // Density estimation (flam3's keys): a kernel of estimatorRadius output pixels where one point
  // fell, narrowing as (hits + 1)^-estimatorCurve, never below estimatorMinimum; radius 0 is off.
  double estimatorRadius = 9.0;
  double estimatorMinimum = 0.0;
  double estimatorCurve = 0.4;
  bool operator==(const ToneMapSettings&) const = default;
};

// How flam3 frames a flame in 2D (its <flame> attributes), kept on import so the flame can be
// shown as its author saw it (`voxflame render --flat`, flame/flat_render.h). Defaults are flam3's own
// (clear_cp in flam3.c). The tone of the flat view is the scene's `tone`.
// flam3's palette_mode: how a colour index picks from the 256 palette entries.
enum class PaletteMode {
  Step,    // the entry ⌊index · 256⌋ (flam3's default)
  Linear,  // the two entries around index · 256, blended by its fraction (Apophysis 7X writes this)
};
inline constexpr std::string_view kPaletteModeNames[] = {"step", "linear"};

// Whose 3D camera the flat view has: Apophysis 3D's and Fractorium's, or JWildfire's (see
// FlatViewSettings below and flame/flat_render.h's FlatCamera).
enum class FlatCameraModel { Fractorium, Jwildfire };
inline constexpr std::string_view kFlatCameraModelNames[] = {"fractorium", "jwildfire"};

// The shape JWildfire's depth of field spreads an out-of-focus point into (its cam_dof_shape, the
// DOFBlurShape classes; FlatCamera in flame/flat_render.h draws each): a disc (bubble), a rectangle,
// and shapes drawn by variations of the catalogue. The names are JWildfire's, in lower case.
enum class FlatDofShape {
  Bubble,
  Rect,
  Cloverleaf,
  Heart,
  Flower,
  NBlur,
  PerlinNoise,
  SineBlur,
  StarBlur,
  Taurus,
  CannabisCurve
};
inline constexpr std::string_view kFlatDofShapeNames[] = {"bubble",   "rect",   "cloverleaf",   "heart",
                                                          "flower",   "nblur",  "perlin_noise", "sineblur",
                                                          "starblur", "taurus", "cannabiscurve"};

// JWildfire's solid rendering (its SolidRenderSettings): instead of a glowing density, the flat
// view keeps per pixel the nearest point (its depth, colour, material and flame coordinates),
// estimates surface normals from neighbouring pixels' points, and shades each with distant lights
// (diffuse, ambient, a phong highlight), screen-space ambient occlusion and shadow maps.
enum class SolidShadowType { Off, Fast, Smooth };
inline constexpr std::string_view kSolidShadowTypeNames[] = {"off", "fast", "smooth"};
// How a material's diffuse light answers the cosine a between the normal and the light
// (JWildfire's LightDiffFuncPreset): a, a², a/2 + ½, (a/2 + ½)².
enum class SolidDiffuseResponse { Cosa, CosaSquare, CosaHalve, CosaHalveSquare };
inline constexpr std::string_view kSolidDiffuseResponseNames[] = {"cosa", "cosa_square", "cosa_halve",
                                                                  "cosa_halve_square"};

// A distant light, from `altitude` degrees above and `azimuth` degrees around (JWildfire's
// DistantLight), with its colour (linear 0–1 multipliers as JWildfire keeps them).
struct SolidLight {
  double altitudeDeg = 60.0, azimuthDeg = -30.0;
  double intensity = 0.7;
  glm::dvec3 color{1.0};
  bool castShadows = false;
  double shadowIntensity = 0.6;  // 1: a shadow takes all of this light, 0: none
  bool operator==(const SolidLight&) const = default;
};

struct SolidMaterial {
  double diffuse = 0.5, ambient = 1.0;
  double phong = 1.0, phongSize = 24.0;  // the highlight's strength and exponent
  glm::dvec3 phongColor{1.0};
  SolidDiffuseResponse diffuseResponse = SolidDiffuseResponse::Cosa;
  bool operator==(const SolidMaterial&) const = default;
};

struct FlatSolidSettings {
  bool enabled = false;
  // Ambient occlusion (JWildfire's horizon search over the depth buffer): radii relative to the
  // image's diagonal (per 500), samples along each ray and around the circle.
  bool aoEnabled = false;
  double aoIntensity = 0.6, aoSearchRadius = 4.0, aoBlurRadius = 1.5;
  int aoRadiusSamples = 6, aoAzimuthSamples = 7;
  double aoFalloff = 0.5, aoAffectDiffuse = 0.1;
  SolidShadowType shadowType = SolidShadowType::Off;
  double shadowSmoothRadius = 1.0;  // SMOOTH: the blur of a shadow's edge, per 1000 of the diagonal · 6
  int shadowmapSize = 2048;         // texels along each side of a light's shadow map
  double shadowmapBias = 0.01;      // in flame units along the light
  std::vector<SolidLight> lights;
  std::vector<SolidMaterial> materials;
  bool operator==(const FlatSolidSettings&) const = default;
};

struct FlatViewSettings {
  int width = 100, height = 100;  // flam3's size, pixels
  double centerX = 0.0, centerY = 0.0;
  double scale = 50.0;        // pixels per flame unit at zoom 0
  double zoom = 0.0;          // pixels per unit = scale · 2^zoom; samples per pixel grow by 4^zoom
  double rotateDeg = 0.0;     // the picture turns by this about the center
  int oversample = 1;         // supersampled pixels per output pixel along each axis
  double filterRadius = 0.5;  // Gaussian spatial filter, in output pixels
  double quality = 1.0;       // samples per output pixel (flam3's sample_density)
  PaletteMode paletteMode = PaletteMode::Step;
  // The 3D camera of Apophysis 3D and Fractorium (flam3's cam_* keys), or JWildfire's (cameraModel):
  // the drawn point turned by yaw about z and pitch about x, seen in perspective, blurred with
  // depth by dof. JWildfire's also banks about y between the yaw and the pitch, turns by `rotate`
  // about the origin last (instead of about the center, after), then moves by cameraPosition.
  FlatCameraModel cameraModel = FlatCameraModel::Fractorium;
  double cameraPitchDeg = 0.0, cameraYawDeg = 0.0;
  double cameraBankDeg = 0.0;      // JWildfire's cam_roll
  double cameraPerspective = 0.0;  // cam_persp: a point at depth d is drawn 1 / (1 − perspective · d) as large
  double cameraZ = 0.0;            // cam_zpos: Fractorium's eye depth; JWildfire's depth in focus
  glm::dvec3 cameraPosition{0.0};  // JWildfire's cam_pos_x, _y, _z: added after the turn
  double cameraDof = 0.0;          // cam_dof
  double cameraDofScale = 1.0;     // JWildfire's cam_dof_scale: the blur's radius is scaled by it
  double cameraDofFade = 1.0;      // JWildfire's cam_dof_fade (see FlatCamera)
  // JWildfire's "new" depth of field (new_dof): points blur with their distance from a focus point
  // instead of with their depth in front of camera_z; those within `area` of it stay sharp, with a
  // smooth fade at its rim (FlatCamera). The distance is (|q − focus|²)^(1/exponent).
  bool cameraDofNew = false;
  glm::dvec3 cameraDofFocus{0.0};  // cam_xfocus, cam_yfocus, cam_zfocus: in the turned, moved space
  double cameraDofArea = 0.5;      // cam_dof_area
  double cameraDofExponent = 2.0;  // cam_dof_exponent
  // The blur's shape (cam_dof_shape), its turn in degrees (cam_dof_rotate) and its parameters
  // (cam_dof_param1–6, their meaning per shape: FlatCamera).
  FlatDofShape cameraDofShape = FlatDofShape::Bubble;
  double cameraDofRotateDeg = 0.0;
  double cameraDofParam1 = 0.0, cameraDofParam2 = 0.0, cameraDofParam3 = 0.0;
  double cameraDofParam4 = 0.0, cameraDofParam5 = 0.0, cameraDofParam6 = 0.0;
  FlatSolidSettings solid;  // JWildfire's solid rendering; off: the glowing flame
  bool hasCamera() const {
    if (cameraModel == FlatCameraModel::Jwildfire)  // JWildfire's is3dProjectionRequired: not cam_zpos alone
      return cameraPitchDeg != 0.0 || cameraYawDeg != 0.0 || cameraBankDeg != 0.0 || cameraPerspective != 0.0 ||
             cameraDof != 0.0 || cameraPosition != glm::dvec3(0.0);
    return cameraPitchDeg != 0.0 || cameraYawDeg != 0.0 || cameraPerspective != 0.0 || cameraZ != 0.0 ||
           cameraDof != 0.0;
  }
  bool operator==(const FlatViewSettings&) const = default;
};

enum class Projection { Perspective, Orthographic };
inline constexpr std::string_view kProjectionNames[] = {"perspective", "orthographic"};

// The camera orbits `target` (an offset from the grid's centre, in bounding-sphere radii) at
// `distance` radii; free flight moves the target with the eye. Any orientation is valid.
struct CameraSettings {
  double azimuthDeg = 30.0;
  double elevationDeg = 15.0;
  double rollDeg = 0.0;
  double distance = 2.6;     // in units of the grid's bounding-sphere radius
  double fovDeg = 35.0;      // perspective: vertical field of view
  double orthoHeight = 2.2;  // orthographic: visible height, in radii
  Projection projection = Projection::Perspective;
  glm::dvec3 target{0.0};  // in radii, relative to the grid's centre
  double nearClip = 0.0;   // distance from the eye in radii; 0: automatic
  double farClip = 0.0;    // distance from the eye in radii; 0: automatic
  bool operator==(const CameraSettings&) const = default;
};

enum class MeshDisplay { Off, Ghost, Silhouette };
inline constexpr std::string_view kMeshDisplayNames[] = {"off", "ghost", "silhouette"};

// How a still is made: "volume" ray-marches the voxel grid; "points" projects every accepted
// point into a supersampled screen histogram, dimmed by the camera's transmittance through the grid.
enum class RenderMethod { Volume, Points };
inline constexpr std::string_view kRenderMethodNames[] = {"volume", "points"};
std::string_view toString(RenderMethod method);
// The method a scene has when its preset names none: `points` when a layer is a flame (its
// filaments are finer than a voxel, and the volume method blurs them to the grid), else `volume`.
RenderMethod defaultRenderMethod(const std::vector<PatternLayer>& layers);

// How a frame is drawn; none of it restarts accumulation.
struct RenderSettingsDoc {
  double stepVoxels = 0.5;  // ray-march step as a fraction of a voxel edge
  int samples = 1;          // jittered sub-samples averaged per pixel for stills
  MeshDisplay meshDisplay = MeshDisplay::Off;
  glm::vec3 meshColor = parseHexColor("#c2d3e8");  // linear RGB of the ghost or outline
  double meshStrength = 0.35;
  bool lighting = false;  // directional light with a shadow volume
  double lightAzimuthDeg = 45.0;
  double lightElevationDeg = 50.0;
  double lightStrength = 0.8;  // how much shadowed emission is dimmed
  RenderMethod method = RenderMethod::Volume;
  int oversample = 1;         // supersampled pixels per output pixel along each axis (1–4)
  double filterRadius = 0.5;  // flam3's spatial filter, in output pixels
  // Depth of field (points method): lens radius in bounding-sphere radii (0: pinhole) and the
  // distance in focus, in radii from the eye (0: the camera's distance to its target).
  double dofAperture = 0.0;
  double dofFocusDistance = 0.0;
  double fog = 0.0;  // points method: dims by exp(-fog · depth behind the front of the grid / grid side)
  bool operator==(const RenderSettingsDoc&) const = default;
};

enum class Interpolation {
  Linear,
  Smooth,  // Catmull-Rom: passes through every key with a continuous first derivative
};

// What a keyframe track animates: one number, an array of numbers (e.g. "/camera/target"), or a
// colour (interpolated in OKLab).
enum class KeyKind { Number, Array, Color };

struct Keyframe {
  double time = 0.0;           // seconds
  std::vector<double> values;  // Number: one value; Array: one per element; Color: linear RGB
  bool operator==(const Keyframe&) const = default;
};

// A track addresses one value of the preset document by JSON Pointer (RFC 6901), e.g.
// "/layers/0/params/a", "/camera/azimuth_deg", "/layers/0/color/gradient/2"; keys are sorted by
// strictly increasing time.
struct KeyframeTrack {
  std::string path;
  Interpolation interpolation = Interpolation::Smooth;
  KeyKind kind = KeyKind::Number;
  std::vector<Keyframe> keys;
  bool operator==(const KeyframeTrack&) const = default;
};

struct AnimationSettings {
  double duration = 0.0;  // seconds; 0: until the last key
  double fps = 30.0;
  bool loop = false;  // time wraps at the duration and smooth tracks join their ends without a kink
  double time = 0.0;  // the moment a still (`voxflame render`) shows
  bool operator==(const AnimationSettings&) const = default;
};

struct Scene {
  std::string name = "untitled";
  std::string meshPath;                 // as written in the preset
  std::filesystem::path baseDirectory;  // relative mesh paths resolve against this
  bool embedded = false;                // the preset and its mesh live inside the binary
  int gridResolution = 192;
  std::vector<PatternLayer> layers;
  ToneMapSettings tone;
  CameraSettings camera;
  RenderSettingsDoc render;
  std::uint64_t seed = 1;
  std::uint64_t points = 20'000'000;  // points accumulated for a still
  AnimationSettings animation;
  std::vector<KeyframeTrack> keyframes;  // applied by sceneAtTime (keyframes.h)
  FlatViewSettings flat;                 // flam3's 2D framing of an imported flame

  std::filesystem::path resolvedMeshPath() const;
  bool operator==(const Scene&) const = default;
};

// The preset entry points. They are the preset loader of scene_io.cpp, which composes the scene's
// reader and writer (scene_schema.h) with the keyframes' (keyframes.h); they are declared here
// because this is the header every caller already has.

// Parses a preset (migrating older schema versions first). `sourceName` is what messages call
// it (a file path). Throws core::Error.
Scene sceneFromJson(std::string_view text, std::string_view sourceName);
Scene loadScene(const std::filesystem::path& path);
std::string sceneToJson(const Scene& scene);  // pretty-printed, loads back to an equal Scene

// Brings a preset document of any supported schema version up to kSchemaVersion, one version
// step at a time; a document without `schema_version` is taken as current. Throws core::Error
// (naming `sourceName`) for a version newer than this build or not a whole number.
nlohmann::json migratePreset(nlohmann::json document, std::string_view sourceName);

// The preset as a JSON document with every key present, defaults included: the document keyframe
// paths address. `withAnimation` false leaves out the animation block and the keyframes.
nlohmann::json sceneToDocument(const Scene& scene, bool withAnimation = true);

}  // namespace voxflame::core
