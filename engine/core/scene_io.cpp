#include "scene_io.h"

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "embedded_files.h"
#include "error.h"
#include "keyframes.h"
#include "scene_schema.h"

namespace voxflame::core {

using nlohmann::json;

namespace {

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

// The scene's keys go to the schema's reader, `keyframes` to the keyframes' reader; then the
// tracks are checked against the scene they animate.
Scene presetFromDocument(const json& document, const std::string& source) {
  static constexpr std::string_view kReadByKeyframes[] = {"keyframes"};
  Scene scene = sceneFromDocument(document, source, kReadByKeyframes);
  const auto tracks = document.find("keyframes");
  scene.keyframes = keyframesFromJson(tracks == document.end() ? nullptr : &*tracks, scene.animation, source);
  checkKeyframeTracks(scene, source);
  return scene;
}

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
  return presetFromDocument(migratePreset(std::move(document), source), source);
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

json sceneToDocument(const Scene& scene, bool withAnimation) {
  json document = sceneDocument(scene, true);
  if (!withAnimation)
    document.erase("animation");
  else if (!scene.keyframes.empty())
    document["keyframes"] = keyframesToJson(scene.keyframes);
  return document;
}

std::string sceneToJson(const Scene& scene) {
  json document = sceneDocument(scene, false);
  if (!scene.keyframes.empty()) document["keyframes"] = keyframesToJson(scene.keyframes);
  return document.dump(2) + "\n";
}

Scene defaultScene() {
  const auto bytes = embeddedFile(kDefaultPresetName);
  if (!bytes) throw Error("the default preset is missing from this build");
  Scene scene = sceneFromJson(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                              std::string("(embedded) ") + kDefaultPresetName);
  scene.embedded = true;
  scene.baseDirectory = "presets";
  return scene;
}

TriangleMesh loadSceneMesh(const Scene& scene) {
  if (scene.embedded) {
    const std::string name = (scene.baseDirectory / scene.meshPath).generic_string();
    const auto bytes = embeddedFile(name);
    if (!bytes) throw Error("mesh '" + name + "' is not embedded in this build");
    const std::string extension = std::filesystem::path(name).extension().string();
    // A mesh compiled into the binary is trusted: it is read in this process, without a child.
    MeshLoadOptions trusted;
    trusted.isolate = false;
    return loadMeshFromMemory(*bytes, extension.empty() ? "" : extension.substr(1), name, trusted);
  }
  return loadMesh(scene.resolvedMeshPath());
}

}  // namespace voxflame::core
