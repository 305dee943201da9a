// diff(): what differs between two scenes, as JSON Pointers, and what the differences affect.
#include "scene_schema.h"

#include <algorithm>

#include "scene_schema_internal.h"

namespace voxflame::core {

using namespace schema_internal;

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
    if (a.flame.chainedFinals != b.flame.chainedFinals) note(d, flame + "/final_chain", kPattern);
    if (a.flame.backgroundXforms != b.flame.backgroundXforms) note(d, flame + "/background_xforms", kPattern);
    if (a.flame.backgroundZoom != b.flame.backgroundZoom) note(d, flame + "/background_zoom", kPattern);
    diffTable(a.flame.symmetry, b.flame.symmetry, symmetryFields(), flame + "/symmetry", d);
    diffTable(a.flame.postSymmetry, b.flame.postSymmetry, postSymmetryFields(), flame + "/post_symmetry", d);
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
  diffTable(a.flat.solid, b.flat.solid, solidFields(), "/flat/solid", d);
  if (a.flat.solid.lights.size() != b.flat.solid.lights.size()) {
    note(d, "/flat/solid/lights", kStill);
  } else {
    for (std::size_t i = 0; i < a.flat.solid.lights.size(); ++i)
      diffTable(a.flat.solid.lights[i], b.flat.solid.lights[i], solidLightFields(),
                "/flat/solid/lights/" + std::to_string(i), d);
  }
  if (a.flat.solid.materials.size() != b.flat.solid.materials.size()) {
    note(d, "/flat/solid/materials", kStill);
  } else {
    for (std::size_t i = 0; i < a.flat.solid.materials.size(); ++i)
      diffTable(a.flat.solid.materials[i], b.flat.solid.materials[i], solidMaterialFields(),
                "/flat/solid/materials/" + std::to_string(i), d);
  }
  if (a.keyframes != b.keyframes) note(d, "/keyframes", kNothing);
  return d;
}

}  // namespace voxflame::core
