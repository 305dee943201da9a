#include "scene.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <nlohmann/json.hpp>

#include "error.h"
#include "flame_variations.h"
#include "grid.h"
#include "keyframes.h"

namespace voxflame::core {

using nlohmann::json;

std::filesystem::path Scene::resolvedMeshPath() const {
  const std::filesystem::path mesh(meshPath);
  if (mesh.is_absolute() || embedded) return mesh;
  return baseDirectory / mesh;
}

std::string_view toString(RenderMethod method) {
  return method == RenderMethod::Points ? "points" : "volume";
}

std::string_view toString(ColorMode mode) {
  switch (mode) {
    case ColorMode::Speed:
      return "speed";
    case ColorMode::Curvature:
      return "curvature";
    case ColorMode::Time:
      return "time";
    case ColorMode::Axis:
      return "axis";
    case ColorMode::Distance:
      return "distance";
    case ColorMode::Index:
      return "index";
  }
  return "speed";
}

ColorMode colorModeFromString(std::string_view name) {
  for (ColorMode mode : {ColorMode::Speed, ColorMode::Curvature, ColorMode::Time, ColorMode::Axis, ColorMode::Distance,
                         ColorMode::Index})
    if (toString(mode) == name) return mode;
  throw Error("is '" + std::string(name) +
              "'; the known colour modes are: speed, curvature, time, axis, distance, index");
}

std::string_view toString(PatternKind kind) {
  switch (kind) {
    case PatternKind::Attractor:
      return "attractor";
    case PatternKind::Flame:
      return "flame";
    case PatternKind::QuaternionJulia:
      return "quaternion_julia";
  }
  return "attractor";
}

PatternKind patternKindFromString(std::string_view name) {
  for (PatternKind kind : {PatternKind::Attractor, PatternKind::Flame, PatternKind::QuaternionJulia})
    if (toString(kind) == name) return kind;
  throw Error("is '" + std::string(name) + "'; the known kinds are: attractor, flame, quaternion_julia");
}

std::string PatternLayer::patternName() const {
  return kind == PatternKind::Attractor ? attractor : std::string(toString(kind));
}

std::string_view toString(FitMode mode) {
  switch (mode) {
    case FitMode::Contain:
      return "contain";
    case FitMode::Cover:
      return "cover";
    case FitMode::Stretch:
      return "stretch";
  }
  return "contain";
}

FitMode fitModeFromString(std::string_view name) {
  for (FitMode mode : {FitMode::Contain, FitMode::Cover, FitMode::Stretch})
    if (toString(mode) == name) return mode;
  throw Error("is '" + std::string(name) + "'; the known fit modes are: contain, cover, stretch");
}

namespace {

// Reads one JSON object strictly: every key read is remembered, and finish() reports any key
// that was not, so misspelt keys are errors. Messages carry the source and the key path.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string source, std::string path)
      : object_(object), source_(std::move(source)), path_(std::move(path)) {
    if (!object_.is_object()) fail(path_.empty() ? "the preset must be a JSON object" : "must be an object");
  }

  [[noreturn]] void fail(const std::string& reason, const std::string& key = "") const {
    const std::string where = key.empty() ? path_ : keyPath(key);
    throw Error(source_ + ": " + (where.empty() ? "" : "'" + where + "' ") + reason);
  }
  std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const std::string& source() const { return source_; }

  const json* find(const std::string& key) {
    seen_.insert(key);
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }

  double number(const std::string& key, double fallback, double min, double max) {
    const json* value = find(key);
    if (!value) return fallback;
    return checkNumber(*value, key, min, max);
  }

  double checkNumber(const json& value, const std::string& key, double min, double max) const {
    if (!value.is_number()) fail("must be a number", key);
    const double v = value.get<double>();
    if (!std::isfinite(v) || v < min || v > max) {
      std::ostringstream range;
      range << "is " << v << ", outside the allowed range [" << min << ", " << max << "]";
      fail(range.str(), key);
    }
    return v;
  }

  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_number_integer()) fail("must be a whole number", key);
    const auto v = value->get<std::int64_t>();
    if (v < min || v > max)
      fail("is " + std::to_string(v) + ", outside the allowed range [" + std::to_string(min) + ", " +
               std::to_string(max) + "]",
           key);
    return v;
  }

  std::string string(const std::string& key, const std::string& fallback) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_string()) fail("must be a string", key);
    return value->get<std::string>();
  }

  std::string requiredString(const std::string& key) {
    if (!object_.contains(key)) fail("is missing", key);
    return string(key, "");
  }

  glm::vec3 color(const std::string& key, glm::vec3 fallback) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_string()) fail("must be a colour string like \"#ff8800\"", key);
    try {
      return parseHexColor(value->get<std::string>());
    } catch (const Error& e) {
      fail(e.what(), key);
    }
  }

  bool boolean(const std::string& key, bool fallback) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_boolean()) fail("must be true or false", key);
    return value->get<bool>();
  }

  glm::dvec3 vector(const std::string& key, glm::dvec3 fallback, double min, double max) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_array() || value->size() != 3) fail("must be an array of three numbers", key);
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = checkNumber((*value)[static_cast<std::size_t>(i)], key, min, max);
    return v;
  }

  void finish() const {
    for (auto it = object_.begin(); it != object_.end(); ++it)
      if (!seen_.count(it.key())) fail("is not a known key", it.key());
  }

 private:
  const json& object_;
  std::string source_;
  std::string path_;
  std::set<std::string> seen_;
};

glm::dvec3 readVector(ObjectReader& reader, const std::string& key, glm::dvec3 fallback, double limit) {
  const json* value = reader.find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 3) reader.fail("must be an array of three numbers", key);
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) v[i] = reader.checkNumber((*value)[static_cast<std::size_t>(i)], key, -limit, limit);
  return v;
}

ColorSettings readColor(ObjectReader& parent, const std::string& key, ColorMode defaultMode = ColorMode::Speed) {
  ColorSettings color;
  color.mode = defaultMode;
  color.gradient = {{0.0f, parseHexColor("#2a6cff")}, {1.0f, parseHexColor("#ffb347")}};
  const json* value = parent.find(key);
  if (!value) return color;
  ObjectReader reader(*value, parent.source(), parent.keyPath(key));
  const std::string mode = reader.string("mode", std::string(toString(defaultMode)));
  try {
    color.mode = colorModeFromString(mode);
  } catch (const Error& e) {
    reader.fail(e.what(), "mode");
  }
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
  color.axis = readVector(reader, "axis", color.axis, 1e6);
  if (glm::dot(color.axis, color.axis) < 1e-24) reader.fail("must not be the zero vector", "axis");
  color.period = reader.number("period", color.period, 1.0, 1e9);
  color.scale = reader.number("scale", color.scale, 1e-6, 1e6);
  reader.finish();
  return color;
}

LayerTransform readTransform(ObjectReader& parent, const std::string& key) {
  LayerTransform transform;
  const json* value = parent.find(key);
  if (!value) return transform;
  ObjectReader reader(*value, parent.source(), parent.keyPath(key));
  transform.scale = reader.number("scale", transform.scale, 1e-3, 1e3);
  transform.rotationDeg = readVector(reader, "rotation_deg", transform.rotationDeg, 3600.0);
  transform.offset = readVector(reader, "offset", transform.offset, 100.0);
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
  const std::string fit = reader.string("fit", std::string(toString(transform.fit)));
  try {
    transform.fit = fitModeFromString(fit);
  } catch (const Error& e) {
    reader.fail(e.what(), "fit");
  }
  if (const json* locked = reader.find("locked_fit")) {
    ObjectReader lockedReader(*locked, parent.source(), reader.keyPath("locked_fit"));
    transform.lockFit = true;
    if (!locked->contains("center")) lockedReader.fail("is missing", "center");
    if (!locked->contains("scale")) lockedReader.fail("is missing", "scale");
    transform.lockedCenter = readVector(lockedReader, "center", transform.lockedCenter, 1e9);
    transform.lockedScale = lockedReader.number("scale", transform.lockedScale, 1e-12, 1e12);
    transform.lockedAxisScale = readVector(lockedReader, "axis_scale", transform.lockedAxisScale, 1e12);
    if (glm::any(glm::lessThan(transform.lockedAxisScale, glm::dvec3(1e-12))))
      lockedReader.fail("must be three numbers from 1e-12 to 1e12", "axis_scale");
    lockedReader.finish();
  }
  reader.finish();
  return transform;
}

Affine3 readAffine(ObjectReader& reader, const std::string& key, const Affine3& fallback) {
  const json* value = reader.find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 12)
    reader.fail("must be 12 numbers: the 3×4 matrix row by row, [m00, m01, m02, t0, m10, ..., t2]", key);
  Affine3 affine;
  for (std::size_t i = 0; i < 12; ++i) affine.m[i] = reader.checkNumber((*value)[i], key, -1e6, 1e6);
  return affine;
}

// A variation term: {"name": "julian", "weight": 0.5, "power": 3, "dist": 1}; parameters left out
// take their defaults.
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
  term.weight = reader.number("weight", 1.0, -1e6, 1e6);
  term.params = info->defaultParams();
  for (std::size_t i = 0; i < info->params.size(); ++i)
    term.params[i] = reader.number(info->params[i].name, info->params[i].defaultValue, -1e6, 1e6);
  reader.finish();
  return term;
}

FlameXform readXform(const json& value, const std::string& source, const std::string& path, bool isFinal) {
  ObjectReader reader(value, source, path);
  FlameXform xform;
  if (!isFinal) xform.weight = reader.number("weight", xform.weight, 0.0, 1e6);
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
  xform.color = reader.number("color", xform.color, 0.0, 1.0);
  xform.colorSpeed = reader.number("color_speed", xform.colorSpeed, 0.0, 1.0);
  xform.opacity = reader.number("opacity", xform.opacity, 0.0, 1.0);
  reader.finish();
  return xform;
}

FlameGenome readFlame(ObjectReader& parent) {
  const json* value = parent.find("flame");
  if (!value) parent.fail("is missing (a flame layer needs its transforms)", "flame");
  ObjectReader reader(*value, parent.source(), parent.keyPath("flame"));
  FlameGenome genome;
  const json* xforms = reader.find("xforms");
  if (!xforms) reader.fail("is missing", "xforms");
  if (!xforms->is_array() || xforms->empty() || xforms->size() > kMaxFlameXforms)
    reader.fail("must be an array of 1 to " + std::to_string(kMaxFlameXforms) + " transforms", "xforms");
  double total = 0.0;
  for (std::size_t i = 0; i < xforms->size(); ++i) {
    genome.xforms.push_back(
        readXform((*xforms)[i], parent.source(), reader.keyPath("xforms") + "[" + std::to_string(i) + "]", false));
    total += genome.xforms.back().weight;
  }
  if (!(total > 0.0)) reader.fail("all have weight 0; at least one transform needs a positive weight", "xforms");
  if (const json* finalXform = reader.find("final")) {
    genome.hasFinal = true;
    genome.finalXform = readXform(*finalXform, parent.source(), reader.keyPath("final"), true);
  }
  if (const json* symmetry = reader.find("symmetry")) {
    ObjectReader symmetryReader(*symmetry, parent.source(), reader.keyPath("symmetry"));
    genome.symmetry.rotational =
        static_cast<int>(symmetryReader.integer("rotational", genome.symmetry.rotational, 1, kMaxFlameSymmetry));
    genome.symmetry.axis = readVector(symmetryReader, "axis", genome.symmetry.axis, 1e6);
    if (glm::dot(genome.symmetry.axis, genome.symmetry.axis) < 1e-24)
      symmetryReader.fail("must not be the zero vector", "axis");
    genome.symmetry.mirror = symmetryReader.boolean("mirror", genome.symmetry.mirror);
    symmetryReader.finish();
  }
  reader.finish();
  return genome;
}

QuaternionJuliaSettings readJulia(ObjectReader& parent) {
  QuaternionJuliaSettings q;
  const json* value = parent.find("julia");
  if (!value) return q;
  ObjectReader reader(*value, parent.source(), parent.keyPath("julia"));
  if (const json* c = reader.find("c")) {
    if (!c->is_array() || c->size() != 4) reader.fail("must be four numbers (1, i, j, k components)", "c");
    for (std::size_t i = 0; i < 4; ++i) q.c[static_cast<int>(i)] = reader.checkNumber((*c)[i], "c", -10.0, 10.0);
  }
  const std::string view = reader.string("view", "project");
  if (view == "project") {
    q.view = QuaternionView::Project;
  } else if (view == "slice") {
    q.view = QuaternionView::Slice;
  } else {
    reader.fail("is '" + view + "'; expected 'project' or 'slice'", "view");
  }
  q.turnDeg = reader.number("turn_deg", q.turnDeg, -3600.0, 3600.0);
  q.sliceW = reader.number("slice_w", q.sliceW, -10.0, 10.0);
  q.thickness = reader.number("thickness", q.thickness, 1e-4, 10.0);
  reader.finish();
  return q;
}

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
    if (layer.kind == PatternKind::Flame) {
      layer.flame = readFlame(reader);
    } else {
      layer.julia = readJulia(reader);
    }
    layer.weight = reader.number("weight", 1.0, 0.0, 1000.0);
    layer.color = readColor(reader, "color", ColorMode::Index);
    layer.transform = readTransform(reader, "transform");
    reader.finish();
    return layer;
  }
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
  const std::string integrator = reader.string("integrator", std::string(toString(info->defaultIntegrator)));
  try {
    layer.integrator = integratorFromString(integrator);
  } catch (const Error& e) {
    reader.fail(e.what(), "integrator");
  }
  layer.step = reader.number("step", info->defaultStep, 1e-6, 1.0);
  layer.weight = reader.number("weight", 1.0, 0.0, 1000.0);
  layer.color = readColor(reader, "color");
  layer.transform = readTransform(reader, "transform");
  reader.finish();
  return layer;
}

AnimationSettings readAnimation(ObjectReader& root) {
  AnimationSettings animation;
  const json* value = root.find("animation");
  if (!value) return animation;
  ObjectReader reader(*value, root.source(), "animation");
  animation.duration = reader.number("duration", animation.duration, 0.0, kMaxAnimationSeconds);
  animation.fps = reader.number("fps", animation.fps, 0.01, 1000.0);
  animation.loop = reader.boolean("loop", animation.loop);
  animation.time = reader.number("time", animation.time, 0.0, kMaxAnimationSeconds);
  reader.finish();
  return animation;
}

// The keyframe value as the track's kind: a number, an array of numbers or a colour string.
Keyframe readKey(const json& value, const std::string& source, const std::string& path, KeyframeTrack& track,
                 bool first) {
  ObjectReader reader(value, source, path);
  Keyframe key;
  const json* time = reader.find("time");
  if (!time) reader.fail("is missing", "time");
  key.time = reader.checkNumber(*time, "time", 0.0, kMaxAnimationSeconds);
  const json* v = reader.find("value");
  if (!v) reader.fail("is missing", "value");
  KeyKind kind = KeyKind::Number;
  if (v->is_number()) {
    key.values = {reader.checkNumber(*v, "value", -1e12, 1e12)};
  } else if (v->is_string()) {
    kind = KeyKind::Color;
    try {
      const glm::vec3 linear = parseHexColor(v->get<std::string>());
      key.values = {linear.r, linear.g, linear.b};
    } catch (const Error& e) {
      reader.fail(e.what(), "value");
    }
  } else if (v->is_array() && !v->empty() && v->size() <= 64) {
    kind = KeyKind::Array;
    for (const json& element : *v) key.values.push_back(reader.checkNumber(element, "value", -1e12, 1e12));
  } else {
    reader.fail("must be a number, an array of 1 to 64 numbers or a colour string like \"#ff8800\"", "value");
  }
  if (first) {
    track.kind = kind;
  } else if (kind != track.kind || key.values.size() != track.keys.front().values.size()) {
    reader.fail(
        "must be of the same kind as the track's first key (a number, an array of as many numbers, or a colour)",
        "value");
  }
  reader.finish();
  return key;
}

std::vector<KeyframeTrack> readKeyframes(ObjectReader& root, const AnimationSettings& animation) {
  std::vector<KeyframeTrack> tracks;
  const json* value = root.find("keyframes");
  if (!value) return tracks;
  if (!value->is_array() || value->size() > kMaxKeyframeTracks)
    root.fail("must be an array of at most " + std::to_string(kMaxKeyframeTracks) + " tracks", "keyframes");
  for (std::size_t i = 0; i < value->size(); ++i) {
    const std::string path = "keyframes[" + std::to_string(i) + "]";
    ObjectReader reader((*value)[i], root.source(), path);
    KeyframeTrack track;
    track.path = reader.requiredString("path");
    if (track.path.empty() || track.path[0] != '/')
      reader.fail(
          "is '" + track.path + "'; a JSON Pointer into the preset starts with '/', like \"/camera/azimuth_deg\"",
          "path");
    const std::string interpolation = reader.string("interpolation", "smooth");
    if (interpolation == "linear") {
      track.interpolation = Interpolation::Linear;
    } else if (interpolation == "smooth") {
      track.interpolation = Interpolation::Smooth;
    } else {
      reader.fail("is '" + interpolation + "'; expected 'linear' or 'smooth'", "interpolation");
    }
    const json* keys = reader.find("keys");
    if (!keys) reader.fail("is missing", "keys");
    if (!keys->is_array() || keys->empty() || keys->size() > kMaxKeyframes)
      reader.fail("must be an array of 1 to " + std::to_string(kMaxKeyframes) + " keys", "keys");
    for (std::size_t k = 0; k < keys->size(); ++k) {
      const std::string keyPath = reader.keyPath("keys") + "[" + std::to_string(k) + "]";
      Keyframe key = readKey((*keys)[k], root.source(), keyPath, track, k == 0);
      if (k > 0 && key.time <= track.keys.back().time) {
        std::ostringstream reason;
        reason << "is " << key.time << ", not after the previous key's " << track.keys.back().time
               << "; key times must increase";
        throw Error(root.source() + ": '" + keyPath + ".time' " + reason.str());
      }
      if (animation.duration > 0.0 && key.time > animation.duration) {
        std::ostringstream reason;
        reason << "is " << key.time << ", after the animation's duration " << animation.duration;
        throw Error(root.source() + ": '" + keyPath + ".time' " + reason.str());
      }
      track.keys.push_back(std::move(key));
    }
    for (const KeyframeTrack& other : tracks)
      if (other.path == track.path) reader.fail("'" + track.path + "' already has a track", "path");
    reader.finish();
    tracks.push_back(std::move(track));
  }
  return tracks;
}

// One step per schema version: migrations[v - 1] turns a version-v document into version v + 1.
json migrateV1ToV2(json document, const std::string& source) {
  // Version 1 had no animation; its keys mean the same in version 2.
  for (const char* key : {"animation", "keyframes"})
    if (document.contains(key))
      throw Error(source + ": '" + key + "' needs schema_version 2 or later (this preset says 1)");
  document["schema_version"] = 2;
  return document;
}
using Migration = json (*)(json, const std::string&);
constexpr Migration kMigrations[] = {&migrateV1ToV2};
static_assert(std::size(kMigrations) == kSchemaVersion - 1, "one migration per schema version step");

}  // namespace

json migratePreset(json document, std::string_view sourceName) {
  const std::string source(sourceName);
  if (!document.is_object()) throw Error(source + ": the preset must be a JSON object");
  const auto found = document.find("schema_version");
  if (found == document.end()) return document;  // written without one: read as the current version
  if (!found->is_number_integer() || found->get<std::int64_t>() < 1)
    throw Error(source + ": 'schema_version' must be a whole number from 1 to " + std::to_string(kSchemaVersion));
  std::int64_t version = found->get<std::int64_t>();
  if (version > kSchemaVersion)
    throw Error(source + ": 'schema_version' is " + std::to_string(version) +
                ", newer than this voxflame understands (" + std::to_string(kSchemaVersion) +
                "); update voxflame to read it");
  for (; version < kSchemaVersion; ++version) document = kMigrations[version - 1](std::move(document), source);
  return document;
}

Scene sceneFromJson(std::string_view text, std::string_view sourceName) {
  const std::string source(sourceName);
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(source + ": not valid JSON (" + e.what() + ")");
  } catch (const json::exception& e) {
    // e.g. a number too large for a double ("1e999"): refused by the parser, not a parse_error.
    throw Error(source + ": not valid JSON (" + e.what() + ")");
  }
  return sceneFromDocument(migratePreset(std::move(document), source), source);
}

Scene sceneFromDocument(const json& document, std::string_view sourceName, bool checkKeyframes) {
  const std::string source(sourceName);
  ObjectReader root(document, source, "");
  Scene scene;
  root.integer("schema_version", kSchemaVersion, kSchemaVersion, kSchemaVersion);  // migrated already
  scene.name = root.string("name", scene.name);

  const json* mesh = root.find("mesh");
  if (!mesh) root.fail("is missing", "mesh");
  {
    ObjectReader meshReader(*mesh, source, "mesh");
    scene.meshPath = meshReader.requiredString("path");
    if (scene.meshPath.empty()) meshReader.fail("must not be empty", "path");
    if (scene.meshPath.rfind(kBuiltinMeshPrefix, 0) == 0) {
      scene.meshPath = scene.meshPath.substr(std::string_view(kBuiltinMeshPrefix).size());
      scene.embedded = true;
      scene.baseDirectory = "presets";
    }
    meshReader.finish();
  }
  if (const json* grid = root.find("grid")) {
    ObjectReader gridReader(*grid, source, "grid");
    scene.gridResolution = static_cast<int>(
        gridReader.integer("resolution", scene.gridResolution, kMinGridResolution, kMaxGridResolution));
    gridReader.finish();
  }

  const json* layers = root.find("layers");
  if (!layers) root.fail("is missing", "layers");
  if (!layers->is_array() || layers->empty() || layers->size() > 16)
    root.fail("must be an array of 1 to 16 pattern layers", "layers");
  for (std::size_t i = 0; i < layers->size(); ++i)
    scene.layers.push_back(readLayer((*layers)[i], source, "layers[" + std::to_string(i) + "]"));

  if (const json* tone = root.find("tone")) {
    ObjectReader toneReader(*tone, source, "tone");
    ToneMapSettings& t = scene.tone;
    t.brightness = toneReader.number("brightness", t.brightness, 0.0, 1000.0);
    t.gamma = toneReader.number("gamma", t.gamma, 0.1, 10.0);
    t.gammaThreshold = toneReader.number("gamma_threshold", t.gammaThreshold, 0.0, 1.0);
    t.vibrancy = toneReader.number("vibrancy", t.vibrancy, 0.0, 1.0);
    t.highlightPower = toneReader.number("highlight_power", t.highlightPower, -1.0, 10.0);
    t.exposure = toneReader.number("exposure", t.exposure, -20.0, 20.0);
    t.contrast = toneReader.number("contrast", t.contrast, 0.0, 10.0);
    t.opacity = toneReader.number("opacity", t.opacity, 0.0, 100.0);
    t.background = toneReader.color("background", t.background);
    t.estimatorRadius = toneReader.number("estimator_radius", t.estimatorRadius, 0.0, 50.0);
    t.estimatorMinimum = toneReader.number("estimator_minimum", t.estimatorMinimum, 0.0, 50.0);
    t.estimatorCurve = toneReader.number("estimator_curve", t.estimatorCurve, 0.01, 5.0);
    if (t.estimatorMinimum > t.estimatorRadius && t.estimatorRadius > 0.0)
      toneReader.fail("must not be larger than 'estimator_radius'", "estimator_minimum");
    toneReader.finish();
  }
  if (const json* camera = root.find("camera")) {
    ObjectReader cameraReader(*camera, source, "camera");
    CameraSettings& c = scene.camera;
    c.azimuthDeg = cameraReader.number("azimuth_deg", c.azimuthDeg, -3600.0, 3600.0);
    c.elevationDeg = cameraReader.number("elevation_deg", c.elevationDeg, -360.0, 360.0);
    c.rollDeg = cameraReader.number("roll_deg", c.rollDeg, -360.0, 360.0);
    c.distance = cameraReader.number("distance", c.distance, 0.01, 1000.0);
    c.fovDeg = cameraReader.number("fov_deg", c.fovDeg, 1.0, 170.0);
    c.orthoHeight = cameraReader.number("ortho_height", c.orthoHeight, 0.001, 1000.0);
    const std::string projection = cameraReader.string("projection", "perspective");
    if (projection == "perspective") {
      c.projection = Projection::Perspective;
    } else if (projection == "orthographic") {
      c.projection = Projection::Orthographic;
    } else {
      cameraReader.fail("is '" + projection + "'; expected 'perspective' or 'orthographic'", "projection");
    }
    c.target = cameraReader.vector("target", c.target, -1000.0, 1000.0);
    c.nearClip = cameraReader.number("near", c.nearClip, 0.0, 1000.0);
    c.farClip = cameraReader.number("far", c.farClip, 0.0, 10000.0);
    if (c.farClip > 0.0 && c.farClip <= c.nearClip) cameraReader.fail("must be larger than 'near'", "far");
    cameraReader.finish();
  }
  if (const json* render = root.find("render")) {
    ObjectReader renderReader(*render, source, "render");
    RenderSettingsDoc& r = scene.render;
    r.stepVoxels = renderReader.number("step", r.stepVoxels, 0.05, 4.0);
    r.samples = static_cast<int>(renderReader.integer("samples", r.samples, 1, 1024));
    const std::string meshDisplay = renderReader.string("mesh", "off");
    if (meshDisplay == "off") {
      r.meshDisplay = MeshDisplay::Off;
    } else if (meshDisplay == "ghost") {
      r.meshDisplay = MeshDisplay::Ghost;
    } else if (meshDisplay == "silhouette") {
      r.meshDisplay = MeshDisplay::Silhouette;
    } else {
      renderReader.fail("is '" + meshDisplay + "'; expected 'off', 'ghost' or 'silhouette'", "mesh");
    }
    r.meshColor = renderReader.color("mesh_color", r.meshColor);
    r.meshStrength = renderReader.number("mesh_strength", r.meshStrength, 0.0, 10.0);
    if (const json* lighting = renderReader.find("lighting")) {
      if (!lighting->is_boolean()) renderReader.fail("must be true or false", "lighting");
      r.lighting = lighting->get<bool>();
    }
    r.lightAzimuthDeg = renderReader.number("light_azimuth_deg", r.lightAzimuthDeg, -3600.0, 3600.0);
    r.lightElevationDeg = renderReader.number("light_elevation_deg", r.lightElevationDeg, -90.0, 90.0);
    r.lightStrength = renderReader.number("light_strength", r.lightStrength, 0.0, 1.0);
    const std::string method = renderReader.string("method", "volume");
    if (method == "volume") {
      r.method = RenderMethod::Volume;
    } else if (method == "points") {
      r.method = RenderMethod::Points;
    } else {
      renderReader.fail("is '" + method + "'; expected 'volume' or 'points'", "method");
    }
    r.oversample = static_cast<int>(renderReader.integer("oversample", r.oversample, 1, 4));
    r.filterRadius = renderReader.number("filter_radius", r.filterRadius, 0.0, 10.0);
    if (const json* dof = renderReader.find("dof")) {
      ObjectReader dofReader(*dof, source, "render.dof");
      r.dofAperture = dofReader.number("aperture", r.dofAperture, 0.0, 10.0);
      r.dofFocusDistance = dofReader.number("focus_distance", r.dofFocusDistance, 0.0, 1000.0);
      dofReader.finish();
    }
    r.fog = renderReader.number("fog", r.fog, 0.0, 100.0);
    renderReader.finish();
  }
  scene.seed = static_cast<std::uint64_t>(root.integer("seed", 1, 0, std::int64_t{1} << 53));
  scene.points = static_cast<std::uint64_t>(root.integer("points", 20'000'000, 1'000, std::int64_t{1} << 40));
  scene.animation = readAnimation(root);
  scene.keyframes = readKeyframes(root, scene.animation);
  root.finish();
  if (checkKeyframes) checkKeyframeTracks(scene, source);
  return scene;
}

Scene loadScene(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error("preset file '" + path.string() + "' does not exist");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open preset file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene = sceneFromJson(text.str(), path.string());
  if (!scene.embedded) scene.baseDirectory = path.parent_path();  // a builtin: mesh lives in the binary
  return scene;
}

namespace {

json affineToJson(const Affine3& affine) {
  return json(affine.m);
}

json xformToJson(const FlameXform& xform, bool isFinal, bool complete) {
  json out = json::object();
  if (!isFinal) out["weight"] = xform.weight;
  out["affine"] = affineToJson(xform.affine);
  if (xform.hasPost) out["post"] = affineToJson(xform.post);
  json variations = json::array();
  for (const VariationTerm& term : xform.variations) {
    json v = {{"name", term.name}, {"weight", term.weight}};
    const VariationInfo& info = variationOrThrow(term.name);
    for (std::size_t i = 0; i < info.params.size() && i < term.params.size(); ++i)
      v[info.params[i].name] = term.params[i];
    variations.push_back(v);
  }
  out["variations"] = variations;
  const FlameXform defaults;
  if (complete || xform.color != defaults.color) out["color"] = xform.color;
  if (complete || xform.colorSpeed != defaults.colorSpeed) out["color_speed"] = xform.colorSpeed;
  if (complete || xform.opacity != defaults.opacity) out["opacity"] = xform.opacity;
  return out;
}

json flameToJson(const FlameGenome& genome, bool complete) {
  json xforms = json::array();
  for (const FlameXform& x : genome.xforms) xforms.push_back(xformToJson(x, false, complete));
  json out = {{"xforms", xforms}};
  if (genome.hasFinal) out["final"] = xformToJson(genome.finalXform, true, complete);
  const FlameSymmetry none;
  const FlameSymmetry& s = genome.symmetry;
  if (complete || s != none)
    out["symmetry"] = {{"rotational", s.rotational}, {"axis", {s.axis.x, s.axis.y, s.axis.z}}, {"mirror", s.mirror}};
  return out;
}

json buildDocument(const Scene& scene, bool complete, bool withAnimation) {
  json root;
  root["schema_version"] = kSchemaVersion;
  root["name"] = scene.name;
  root["mesh"] = {{"path", (scene.embedded ? std::string(kBuiltinMeshPrefix) : std::string()) + scene.meshPath}};
  root["grid"] = {{"resolution", scene.gridResolution}};
  json layers = json::array();
  for (const auto& layer : scene.layers) {
    json gradient = json::array();
    for (const auto& stop : layer.color.gradient) gradient.push_back(toHexColor(stop.color));
    const auto vector = [](glm::dvec3 v) { return json::array({v.x, v.y, v.z}); };
    json color = {{"mode", std::string(toString(layer.color.mode))}};
    if (layer.color.palette.empty())
      color["gradient"] = gradient;
    else
      color["palette"] = layer.color.palette;
    const ColorSettings defaults;
    if (complete || layer.color.axis != defaults.axis) color["axis"] = vector(layer.color.axis);
    if (complete || layer.color.period != defaults.period) color["period"] = layer.color.period;
    if (complete || layer.color.scale != defaults.scale) color["scale"] = layer.color.scale;
    json entry;
    if (layer.kind == PatternKind::Flame) {
      entry = {{"kind", "flame"}, {"flame", flameToJson(layer.flame, complete)}};
    } else if (layer.kind == PatternKind::QuaternionJulia) {
      const QuaternionJuliaSettings& q = layer.julia;
      entry = {{"kind", "quaternion_julia"},
               {"julia",
                {{"c", {q.c.x, q.c.y, q.c.z, q.c.w}},
                 {"view", q.view == QuaternionView::Slice ? "slice" : "project"},
                 {"turn_deg", q.turnDeg},
                 {"slice_w", q.sliceW},
                 {"thickness", q.thickness}}}};
    } else {
      const AttractorInfo& info = attractorOrThrow(layer.attractor);
      json params = json::object();
      for (std::size_t i = 0; i < info.params.size() && i < layer.params.size(); ++i)
        params[info.params[i].name] = layer.params[i];
      entry = {{"attractor", layer.attractor},
               {"params", params},
               {"integrator", std::string(toString(layer.integrator))},
               {"step", layer.step}};
    }
    entry["weight"] = layer.weight;
    entry["color"] = color;
    const LayerTransform& t = layer.transform;
    const LayerTransform none;
    if (complete || t.scale != none.scale || t.rotationDeg != none.rotationDeg || t.offset != none.offset ||
        t.fit != none.fit || !t.copies.empty() || t.lockFit) {
      json transform = {{"scale", t.scale}, {"rotation_deg", vector(t.rotationDeg)}, {"offset", vector(t.offset)}};
      if (complete || t.fit != none.fit) transform["fit"] = std::string(toString(t.fit));
      if (complete || !t.copies.empty()) {
        json copies = json::array();
        for (const glm::dvec3& copy : t.copies) copies.push_back(vector(copy));
        transform["copies"] = copies;
      }
      if (t.lockFit) {
        transform["locked_fit"] = {{"center", vector(t.lockedCenter)}, {"scale", t.lockedScale}};
        if (complete || t.lockedAxisScale != none.lockedAxisScale)
          transform["locked_fit"]["axis_scale"] = vector(t.lockedAxisScale);
      }
      entry["transform"] = transform;
    }
    layers.push_back(entry);
  }
  root["layers"] = layers;
  const ToneMapSettings& t = scene.tone;
  root["tone"] = {{"brightness", t.brightness},
                  {"gamma", t.gamma},
                  {"gamma_threshold", t.gammaThreshold},
                  {"vibrancy", t.vibrancy},
                  {"highlight_power", t.highlightPower},
                  {"exposure", t.exposure},
                  {"contrast", t.contrast},
                  {"opacity", t.opacity},
                  {"background", toHexColor(t.background)},
                  {"estimator_radius", t.estimatorRadius},
                  {"estimator_minimum", t.estimatorMinimum},
                  {"estimator_curve", t.estimatorCurve}};
  const CameraSettings& c = scene.camera;
  root["camera"] = {{"azimuth_deg", c.azimuthDeg},
                    {"elevation_deg", c.elevationDeg},
                    {"roll_deg", c.rollDeg},
                    {"distance", c.distance},
                    {"fov_deg", c.fovDeg},
                    {"ortho_height", c.orthoHeight},
                    {"projection", c.projection == Projection::Orthographic ? "orthographic" : "perspective"},
                    {"target", {c.target.x, c.target.y, c.target.z}},
                    {"near", c.nearClip},
                    {"far", c.farClip}};
  const RenderSettingsDoc& r = scene.render;
  const char* meshNames[] = {"off", "ghost", "silhouette"};
  root["render"] = {{"step", r.stepVoxels},
                    {"samples", r.samples},
                    {"mesh", meshNames[static_cast<int>(r.meshDisplay)]},
                    {"mesh_color", toHexColor(r.meshColor)},
                    {"mesh_strength", r.meshStrength},
                    {"lighting", r.lighting},
                    {"light_azimuth_deg", r.lightAzimuthDeg},
                    {"light_elevation_deg", r.lightElevationDeg},
                    {"light_strength", r.lightStrength},
                    {"method", toString(r.method)},
                    {"oversample", r.oversample},
                    {"filter_radius", r.filterRadius},
                    {"dof", {{"aperture", r.dofAperture}, {"focus_distance", r.dofFocusDistance}}},
                    {"fog", r.fog}};
  root["seed"] = scene.seed;
  root["points"] = scene.points;
  if (!withAnimation) return root;
  const AnimationSettings& a = scene.animation;
  const AnimationSettings still;
  if (complete || !scene.keyframes.empty() || a.duration != still.duration || a.fps != still.fps ||
      a.loop != still.loop || a.time != still.time)
    root["animation"] = {{"duration", a.duration}, {"fps", a.fps}, {"loop", a.loop}, {"time", a.time}};
  if (!scene.keyframes.empty()) {
    json tracks = json::array();
    for (const KeyframeTrack& track : scene.keyframes) {
      json keys = json::array();
      for (const Keyframe& key : track.keys)
        keys.push_back({{"time", key.time}, {"value", keyValueToJson(track, key)}});
      tracks.push_back({{"path", track.path},
                        {"interpolation", track.interpolation == Interpolation::Linear ? "linear" : "smooth"},
                        {"keys", keys}});
    }
    root["keyframes"] = tracks;
  }
  return root;
}

}  // namespace

json sceneToDocument(const Scene& scene, bool withAnimation) {
  return buildDocument(scene, true, withAnimation);
}

std::string sceneToJson(const Scene& scene) {
  return buildDocument(scene, false, true).dump(2) + "\n";
}

}  // namespace voxflame::core
