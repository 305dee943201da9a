// The preset schema as data. One table per object of the preset lists its keys: the JSON key, the
// member of the Scene struct it fills, its type, its default (the member's value in a
// default-made object), the range the reader accepts, the range the explorer's slider offers,
// help text, and what a change affects. From these tables come the strict reader and the writer
// (sceneFromDocument / sceneDocument), the keyframe addressing (resolveValue), the explorer's
// sliders, diff() and presets/SCHEMA.md (schemaMarkdown).
//
// A few keys cannot be plain members: arrays of objects (layers, gradient stops, copies, flame
// transforms and variations, keyframes), keys whose meaning depends on another key (an
// attractor's params by name, a layer's kind, the builtin: prefix of mesh.path). They are still
// rows of the tables, marked `Hand` (no member), so SCHEMA.md lists them in place; the code that
// reads and writes them is marked as such in scene_schema_io.cpp.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene.h"

namespace voxflame::core {

// What a change of a value sets in motion, as bits.
//   Pattern: the accumulated volume is stale (the accumulation restarts): layers, seed, mesh, grid.
//   View:    what a ray sees changed (the sample average restarts): camera, march step, opacity,
//            lighting, the drawn mesh.
//   Tone:    only the per-pixel resolve changed (brightness, gamma, the filter, ...).
//   Still:   only stills and exports change (render method, depth of field, fog, points).
//   None:    nothing drawn changes (the name, the animation settings, keyframes).
enum class Affects : std::uint8_t { None = 0, Pattern = 1, View = 2, Tone = 4, Still = 8 };
constexpr Affects operator|(Affects a, Affects b) {
  return static_cast<Affects>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
constexpr Affects operator&(Affects a, Affects b) {
  return static_cast<Affects>(static_cast<unsigned>(a) & static_cast<unsigned>(b));
}
constexpr Affects& operator|=(Affects& a, Affects b) {
  return a = a | b;
}
constexpr bool any(Affects a) {
  return a != Affects::None;
}
std::string toString(Affects affects);  // "pattern", "view, tone", "nothing drawn"

enum class FieldType { Hand, Number, Integer, Unsigned, Boolean, String, Color, Vector3, Choice };

// An enumeration stored as a member: its names in the enum's order.
template <class Owner>
struct Choice {
  int (*get)(const Owner&) = nullptr;
  void (*set)(Owner&, int) = nullptr;
  std::span<const std::string_view> names = {};
  std::string_view noun = {};  // "projection": messages say "an unknown projection"
};

// std::monostate: a `Hand` row, read and written by marked hand code (see the header comment).
template <class Owner>
using FieldMember = std::variant<std::monostate, double Owner::*, int Owner::*, std::uint64_t Owner::*, bool Owner::*,
                                 std::string Owner::*, glm::vec3 Owner::*, glm::dvec3 Owner::*, Choice<Owner>>;

// The explorer's slider for a field. An empty label: the explorer has no slider for it.
struct UiRange {
  std::string_view label = {};
  double min = 0.0, max = 0.0;
  bool logarithmic = false;
  std::string_view format = "%.3f";
};

enum class Write {
  Always,        // every preset written has the key
  UnlessDefault  // a saved preset leaves it out while it has its default (sceneDocument's complete form has it)
};

template <class Owner>
struct Field {
  std::string_view key = {};  // the JSON key in the owner's object; "dof.aperture" lives in a nested object
  FieldMember<Owner> member = {};
  double min = 0.0, max = 0.0;  // the allowed range (each element of a vector)
  UiRange ui = {};
  std::string_view help = {};
  Affects affects = Affects::None;
  Write write = Write::Always;
  bool (*present)(const Owner&) = nullptr;  // null: always; otherwise only when this says so
  // SCHEMA.md columns where the type alone cannot say it (Hand rows give all three).
  std::string_view typeText = {}, rangeText = {}, defaultText = {};

  FieldType type() const { return static_cast<FieldType>(member.index()); }
  bool presentIn(const Owner& owner) const { return !present || present(owner); }
};

template <class Owner>
using Table = std::span<const Field<Owner>>;

// The tables, one per object of the preset, in the order SCHEMA.md lists them.
Table<Scene> sceneFields();                     // top level: name, mesh.path, grid.resolution, seed, ...
Table<PatternLayer> layerFields();              // layers[i]
Table<ColorSettings> colorFields();             // layers[i].color
Table<LayerTransform> transformFields();        // layers[i].transform
Table<LayerTransform> lockedFitFields();        // layers[i].transform.locked_fit
Table<FlameGenome> flameFields();               // layers[i].flame
Table<FlameXform> xformFields();                // layers[i].flame.xforms[j] (the final one skips `weight`)
Table<VariationTerm> variationFields();         // ....xforms[j].variations[k]
Table<FlameSymmetry> symmetryFields();          // layers[i].flame.symmetry
Table<FlamePostSymmetry> postSymmetryFields();  // layers[i].flame.post_symmetry
Table<QuaternionJuliaSettings> juliaFields();   // layers[i].julia
Table<ToneMapSettings> toneFields();            // tone
Table<CameraSettings> cameraFields();           // camera
Table<RenderSettingsDoc> renderFields();        // render
Table<AnimationSettings> animationFields();     // animation
Table<FlatViewSettings> flatFields();           // flat
Table<FlatSolidSettings> solidFields();         // flat.solid
Table<SolidLight> solidLightFields();           // flat.solid.lights[i]
Table<SolidMaterial> solidMaterialFields();     // flat.solid.materials[i]

// The row of `table` with this key; throws std::out_of_range for a key it does not have (a
// programming error: the UI and tests name keys that exist).
template <class Owner>
const Field<Owner>& field(Table<Owner> table, std::string_view key) {
  for (const Field<Owner>& f : table)
    if (f.key == key) return f;
  throw std::out_of_range("no schema field '" + std::string(key) + "'");
}

// Reads a migrated preset document (kSchemaVersion) into a Scene: every key checked against its
// range, unknown keys refused, messages naming `sourceName`, the key path and the reason. Keys
// in `readElsewhere` (the preset loader passes "keyframes") are left to another reader. Throws
// core::Error.
Scene sceneFromDocument(const nlohmann::json& document, std::string_view sourceName,
                        std::span<const std::string_view> readElsewhere = {});
// The scene as a preset document without keyframes. `complete`: every key, defaults included
// (the document keyframe paths address); otherwise keys marked UnlessDefault are left out while
// they hold their defaults, as a saved preset has them.
nlohmann::json sceneDocument(const Scene& scene, bool complete);

// The cross-field checks the reader makes besides each value's range (estimator_minimum at most
// estimator_radius, far beyond near, no zero axis, a flame with some weight). Throws core::Error
// "SOURCE: 'PATH' REASON" for the first that fails.
void checkSceneConstraints(const Scene& scene, const std::string& sourceName);

// ---------------------------------------------------------------------------------------------
// Values by JSON Pointer (RFC 6901) into the complete document, without making the document:
// what keyframe tracks animate.

// One number of the scene, with the range the reader allows for it.
struct NumberSlot {
  std::variant<double*, int*, std::uint64_t*> target = {};
  double min = 0.0, max = 0.0;
  double get() const;
  bool integer() const { return target.index() != 0; }
};

struct ValueRef {
  enum class Kind {
    Missing,  // the pointer names no value of the complete document
    Number,   // numbers[0]
    Array,    // numbers, one per element
    Color,    // *color, linear RGB
    Other     // a value that cannot be animated; `what` describes it ("the text \"euler\"", "an object")
  };
  Kind kind = Kind::Missing;
  std::vector<NumberSlot> numbers;
  glm::vec3* color = nullptr;
  std::string what;
  std::string messagePath;  // how the reader names the key in messages: "layers[0].params.a"
};

// The value `pointer` addresses in `scene`. The pointers of a ValueRef point into `scene`; one
// resolved from a const Scene must only be read.
ValueRef resolveValue(Scene& scene, std::string_view pointer);
ValueRef resolveValue(const Scene& scene, std::string_view pointer);
// Writes `values` (one per number; whole-number targets take the nearest whole number) after
// checking each against its range. Throws core::Error "SOURCE: 'PATH' is V, outside the allowed
// range [A, B]" without writing anything when one is out of range.
void setNumbers(const ValueRef& ref, std::span<const double> values, const std::string& sourceName);
// Every value a keyframe track can animate (numbers, arrays of numbers, colours), in the order the
// complete document lists them.
std::vector<std::string> animatablePaths(const Scene& scene);
// "a number", "a colour", "an array of 3 numbers", or `what`, as messages describe a value.
std::string describe(const ValueRef& ref);

// ---------------------------------------------------------------------------------------------
// Comparing scenes.

struct SceneDiff {
  Affects affects = Affects::None;  // the union of the classes of everything that changed
  // What changed, as JSON Pointers into the complete document ("/tone/gamma", "/layers/0/params/a",
  // "/layers" when the number of layers changed, "/mesh/path" for the mesh or its folder).
  std::vector<std::string> paths;

  bool empty() const { return paths.empty(); }
  bool pattern() const { return any(affects & Affects::Pattern); }  // the accumulation must restart
  bool view() const { return any(affects & Affects::View); }        // the ray march must restart
  bool tone() const { return any(affects & Affects::Tone); }        // only the resolve changed
  bool touches(std::string_view path) const;                        // `path` or a value under it changed
};

// What differs between two scenes, and what that affects. Cheap when little changed (equal
// layers are compared with ==, not walked).
SceneDiff diff(const Scene& a, const Scene& b);

// ---------------------------------------------------------------------------------------------
// presets/SCHEMA.md: the prose around the tables is fixed text in scene_schema_doc.cpp; every
// table row comes from the tables above.
std::string schemaMarkdown();

}  // namespace voxflame::core
