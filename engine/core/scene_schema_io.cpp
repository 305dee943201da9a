// Reading a preset document into a Scene and writing a Scene as one: the generic code that walks
// a table's rows, the cross-field checks, and the marked hand code for the keys the tables cannot
// hold (arrays of objects, keys named by a catalogue entry).
#include "scene_schema.h"

#include <algorithm>
#include <map>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "enum_names.h"
#include "error.h"
#include "core/flame/variations.h"
#include "json_reader.h"
#include "scene_schema_internal.h"

namespace voxflame::core {

using namespace schema_internal;
using nlohmann::json;

namespace {

// ---------------------------------------------------------------------------------------------
// Reading and writing one table's fields.

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
            reader.fail("is '" + name + "', an unknown " + std::string(member.noun) + "; expected " +
                            quotedChoices(member.names),
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

// An optional nested object: `read` fills `value` from the object's own reader, which then checks
// that every key was read. When the key is absent, `value` stays as given (the defaults).
template <class T, class Read>
T readObject(ObjectReader& parent, const std::string& key, T value, Read read) {
  if (std::optional<ObjectReader> reader = parent.child(key)) {
    read(*reader, value);
    reader->finish();
  }
  return value;
}

// Hand code: gradient stops (an array of colours) or a named palette, not both.
ColorSettings readColor(ObjectReader& parent, ColorMode defaultMode) {
  ColorSettings defaults;
  defaults.mode = defaultMode;
  defaults.gradient = {{0.0f, parseHexColor("#2a6cff")}, {1.0f, parseHexColor("#ffb347")}};
  return readObject(parent, "color", defaults, [&parent](ObjectReader& reader, ColorSettings& color) {
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
  });
}

// Hand code: `copies` (an array of rotations) and the `locked_fit` block, whose presence locks the fit.
LayerTransform readTransform(ObjectReader& parent) {
  return readObject(parent, "transform", LayerTransform{}, [](ObjectReader& reader, LayerTransform& transform) {
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
    if (std::optional<ObjectReader> locked = reader.child("locked_fit")) {
      transform.lockFit = true;
      if (!locked->has("center")) locked->fail("is missing", "center");
      if (!locked->has("scale")) locked->fail("is missing", "scale");
      readFields(*locked, lockedFitFields(), transform);
      locked->finish();
    }
  });
}

// Hand code: 12 numbers, the 3×4 matrix row by row.
Affine3 readAffine(ObjectReader& reader, const std::string& key, const Affine3& fallback) {
  const json* value = reader.find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 12)
    reader.fail("must be 12 numbers: the 3×4 matrix row by row, [m00, m01, m02, t0, m10, ..., t2]", key);
  Affine3 affine;
  for (std::size_t i = 0; i < 12; ++i)
    affine.m[i] = reader.checkNumber((*value)[i], key, -kFlameCoefficientLimit, kFlameCoefficientLimit);
  return affine;
}

// The catalogue entry that `name` (the value of `key`) names; an unknown name fails at that key with
// the catalogue's own message, which lists the names it has or the nearest ones.
template <class Lookup>
decltype(auto) catalogueEntry(ObjectReader& reader, const std::string& key, const std::string& name, Lookup orThrow) {
  try {
    return orThrow(name);
  } catch (const Error& e) {
    reader.fail(e.what(), key);
  }
}

// Hand code: a variation's parameters are keys named by the catalogue entry its `name` picks.
VariationTerm readVariation(const json& value, const std::string& source, const std::string& path) {
  ObjectReader reader(value, source, path);
  VariationTerm term;
  term.name = reader.requiredString("name");
  const VariationInfo& info = catalogueEntry(reader, "name", term.name, variationOrThrow);
  readFields(reader, variationFields(), term);
  term.params = info.defaultParams();
  for (std::size_t i = 0; i < info.params.size(); ++i)
    term.params[i] = reader.number(info.params[i].name, info.params[i].defaultValue, -kFlameCoefficientLimit,
                                   kFlameCoefficientLimit);
  // Text parameters (svg_wf's SVG): kept only when the variation has them.
  if (!info.textParams.empty()) {
    term.texts = info.defaultTexts();
    for (std::size_t i = 0; i < info.textParams.size(); ++i)
      term.texts[i] = reader.string(info.textParams[i].name, info.textParams[i].defaultValue);
  }
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
    for (const json& factor : *xaos)
      xform.xaos.push_back(reader.checkNumber(factor, "xaos", 0.0, kFlameCoefficientLimit));
  }
  reader.finish();
  return xform;
}

// Hand code: the transforms (an array, required) and the optional final one.
FlameGenome readFlame(ObjectReader& parent) {
  std::optional<ObjectReader> flame = parent.child("flame");
  if (!flame) parent.fail("is missing (a flame layer needs its transforms)", "flame");
  ObjectReader& reader = *flame;
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
  if (const json* chain = reader.find("final_chain")) {
    if (!genome.hasFinal) reader.fail("needs a `final` transform to follow", "final_chain");
    if (!chain->is_array() || chain->size() > kMaxChainedFinals)
      reader.fail("must be an array of at most " + std::to_string(kMaxChainedFinals) + " transforms", "final_chain");
    for (std::size_t i = 0; i < chain->size(); ++i)
      genome.chainedFinals.push_back(
          readXform((*chain)[i], parent.source(), reader.keyPath("final_chain") + "[" + std::to_string(i) + "]", true));
  }
  if (const json* background = reader.find("background_xforms")) {
    if (!background->is_array() || background->size() > kMaxFlameXforms)
      reader.fail("must be an array of at most " + std::to_string(kMaxFlameXforms) + " transforms",
                  "background_xforms");
    for (std::size_t i = 0; i < background->size(); ++i)
      genome.backgroundXforms.push_back(readXform((*background)[i], parent.source(),
                                                  reader.keyPath("background_xforms") + "[" + std::to_string(i) + "]",
                                                  false));
  }
  if (const json* zoom = reader.find("background_zoom")) {
    if (!zoom->is_number() || !(zoom->get<double>() > 0.0) || !(zoom->get<double>() < 1e6))
      reader.fail("must be a number above 0 and below 10⁶", "background_zoom");
    genome.backgroundZoom = zoom->get<double>();
  }
  if (std::optional<ObjectReader> symmetry = reader.child("symmetry")) {
    readFields(*symmetry, symmetryFields(), genome.symmetry);
    failOn(*symmetry, zeroAxisFailure(genome.symmetry.axis));
    symmetry->finish();
  }
  if (std::optional<ObjectReader> post = reader.child("post_symmetry")) {
    readFields(*post, postSymmetryFields(), genome.postSymmetry);
    post->finish();
  }
  reader.finish();
  return genome;
}

// Hand code: `c` is four numbers.
QuaternionJuliaSettings readJulia(ObjectReader& parent) {
  return readObject(parent, "julia", QuaternionJuliaSettings{}, [](ObjectReader& reader, QuaternionJuliaSettings& q) {
    if (const json* c = reader.find("c")) {
      if (!c->is_array() || c->size() != 4) reader.fail("must be four numbers (1, i, j, k components)", "c");
      for (std::size_t i = 0; i < 4; ++i) q.c[static_cast<int>(i)] = reader.checkNumber((*c)[i], "c", -10.0, 10.0);
    }
    readFields(reader, juliaFields(), q);
  });
}

// Hand code: the kind decides which keys a layer has; an attractor's params are named by its
// catalogue entry, and its integrator and step default to the catalogue's.
PatternLayer readLayer(const json& value, const std::string& source, const std::string& path) {
  ObjectReader reader(value, source, path);
  PatternLayer layer;
  const std::string kind = reader.string("kind", std::string(toString(PatternKind::Attractor)));
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
    const AttractorInfo& info = catalogueEntry(reader, "attractor", layer.attractor, attractorOrThrow);
    layer.params = info.defaultParams();
    if (const json* params = reader.find("params")) {
      ObjectReader paramReader(*params, source, reader.keyPath("params"));
      for (std::size_t i = 0; i < info.params.size(); ++i)
        layer.params[i] = paramReader.number(info.params[i].name, info.params[i].defaultValue,
                                             -kAttractorParameterLimit, kAttractorParameterLimit);
      paramReader.finish();
    }
    layer.integrator = info.defaultIntegrator;
    layer.step = info.defaultStep;
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

// Hand code: the flat view's solid block, with its arrays of lights and materials.
constexpr std::size_t kMaxSolidEntries = 64;

template <class Entry>
std::vector<Entry> readSolidArray(ObjectReader& reader, const std::string& key, Table<Entry> table,
                                  std::string_view noun) {
  std::vector<Entry> entries;
  const json* value = reader.find(key);
  if (!value) return entries;
  if (!value->is_array() || value->size() > kMaxSolidEntries)
    reader.fail("must be an array of at most " + std::to_string(kMaxSolidEntries) + " " + std::string(noun), key);
  for (std::size_t i = 0; i < value->size(); ++i) {
    ObjectReader entry((*value)[i], reader.source(), reader.keyPath(key) + "[" + std::to_string(i) + "]");
    Entry e;
    readFields(entry, table, e);
    entry.finish();
    entries.push_back(e);
  }
  return entries;
}

void readFlat(ObjectReader& root, FlatViewSettings& flat) {
  const json* value = root.find("flat");
  if (!value) return;
  ObjectReader reader(*value, root.source(), "flat");
  readFields(reader, flatFields(), flat);
  if (std::optional<ObjectReader> solid = reader.child("solid")) {
    readFields(*solid, solidFields(), flat.solid);
    flat.solid.lights = readSolidArray(*solid, "lights", solidLightFields(), "lights");
    flat.solid.materials = readSolidArray(*solid, "materials", solidMaterialFields(), "materials");
    solid->finish();
  }
  reader.finish();
}

json solidJson(const FlatSolidSettings& solid, bool complete) {
  json out = json::object();
  writeFields(out, solidFields(), solid, complete);
  json lights = json::array();
  for (const SolidLight& light : solid.lights) {
    json entry = json::object();
    writeFields(entry, solidLightFields(), light, complete);
    lights.push_back(entry);
  }
  out["lights"] = lights;
  json materials = json::array();
  for (const SolidMaterial& material : solid.materials) {
    json entry = json::object();
    writeFields(entry, solidMaterialFields(), material, complete);
    materials.push_back(entry);
  }
  out["materials"] = materials;
  return out;
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
    for (std::size_t i = 0; i < info.textParams.size() && i < term.texts.size(); ++i)
      v[info.textParams[i].name] = term.texts[i];
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
  if (genome.hasFinal && !genome.chainedFinals.empty()) {
    json chain = json::array();
    for (const FlameXform& x : genome.chainedFinals) chain.push_back(xformJson(x, true, complete));
    out["final_chain"] = chain;
  }
  if (!genome.backgroundXforms.empty()) {
    json background = json::array();
    for (const FlameXform& x : genome.backgroundXforms) background.push_back(xformJson(x, false, complete));
    out["background_xforms"] = background;
  }
  // Only where it frames something: it is not a value a scene animates.
  if (!genome.backgroundXforms.empty() || genome.backgroundZoom != 1.0) out["background_zoom"] = genome.backgroundZoom;
  if (complete || genome.symmetry != FlameSymmetry{})
    writeFields(out["symmetry"], symmetryFields(), genome.symmetry, complete);
  if (complete || genome.postSymmetry != FlamePostSymmetry{})
    writeFields(out["post_symmetry"], postSymmetryFields(), genome.postSymmetry, complete);
  return out;
}

json layerJson(const PatternLayer& layer, bool complete) {
  json entry = json::object();
  if (layer.kind == PatternKind::Flame) {
    entry["kind"] = toString(layer.kind);
    entry["flame"] = flameJson(layer.flame, complete);
  } else if (layer.kind == PatternKind::QuaternionJulia) {
    const QuaternionJuliaSettings& q = layer.julia;
    entry["kind"] = toString(layer.kind);
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
  scene.render.method = defaultRenderMethod(scene.layers);
  readBlock(root, "render", renderFields(), scene.render);
  readBlock(root, "animation", animationFields(), scene.animation);
  readFlat(root, scene.flat);
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
  if (complete || scene.flat != FlatViewSettings{}) {
    writeFields(root["flat"], flatFields(), scene.flat, complete);
    if (complete || scene.flat.solid != FlatSolidSettings{})
      root["flat"]["solid"] = solidJson(scene.flat.solid, complete);
  }
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

}  // namespace voxflame::core
