// Values by JSON Pointer into the complete document, without making the document: resolveValue,
// setNumbers, describe and animatablePaths, what keyframe tracks animate through.
#include "scene_schema.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "error.h"
#include "core/flame/variations.h"
#include "json_reader.h"
#include "scene_schema_internal.h"

namespace voxflame::core {

using namespace schema_internal;
using nlohmann::json;

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

// The flat view, with its solid block and that block's arrays of lights and materials.
template <class Entry>
ValueRef solidEntryAt(Walk& w, std::vector<Entry>& entries, Table<Entry> table, const std::string& path) {
  if (w.done()) return other("an array", path);
  const auto index = arrayIndex(w.next());
  if (!index || *index >= entries.size()) return missing();
  return objectAt(w, table, entries[*index], path + "[" + std::to_string(*index) + "]");
}

ValueRef flatAt(Walk& w, FlatViewSettings& flat) {
  if (w.done() || w.peek() != "solid") return objectAt(w, flatFields(), flat, "flat");
  w.next();
  if (w.done()) return other("an object", "flat.solid");
  if (w.peek() == "lights") {
    w.next();
    return solidEntryAt(w, flat.solid.lights, solidLightFields(), "flat.solid.lights");
  }
  if (w.peek() == "materials") {
    w.next();
    return solidEntryAt(w, flat.solid.materials, solidMaterialFields(), "flat.solid.materials");
  }
  return objectAt(w, solidFields(), flat.solid, "flat.solid");
}

ValueRef xformAt(Walk& w, FlameXform& xform, const std::string& base, bool isFinal) {
  if (w.done()) return other("an object", base);
  const std::string& key = w.peek();
  if (key == "affine" || (key == "post" && xform.hasPost)) {
    w.next();
    Affine3& affine = key == "affine" ? xform.affine : xform.post;
    return numbersAt(w, affine.m.data(), 12, -kFlameCoefficientLimit, kFlameCoefficientLimit, joinPath(base, key));
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
    return numberRef(&term.params[static_cast<std::size_t>(param)], -kFlameCoefficientLimit, kFlameCoefficientLimit,
                     joinPath(termPath, name));
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
  if (key == "post_symmetry")
    return objectAt(w, postSymmetryFields(), flame.postSymmetry, joinPath(base, "post_symmetry"));
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
      if (info->params[i].name == name)
        return numberRef(&layer.params[i], -kAttractorParameterLimit, kAttractorParameterLimit, joinPath(path, name));
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
    if (object == "flat") return flatAt(w, scene.flat);
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
  tablePaths(solidFields(), scene.flat.solid, "/flat/solid", out);
  for (std::size_t i = 0; i < scene.flat.solid.lights.size(); ++i)
    tablePaths(solidLightFields(), scene.flat.solid.lights[i], "/flat/solid/lights/" + std::to_string(i), out);
  for (std::size_t i = 0; i < scene.flat.solid.materials.size(); ++i)
    tablePaths(solidMaterialFields(), scene.flat.solid.materials[i], "/flat/solid/materials/" + std::to_string(i), out);
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
      tablePaths(postSymmetryFields(), layer.flame.postSymmetry, base + "/flame/post_symmetry", out);
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

std::string schema_internal::escapeToken(std::string_view token) {
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

}  // namespace voxflame::core
