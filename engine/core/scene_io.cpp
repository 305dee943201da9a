#include "scene_io.h"

#include <string>

#include "embedded_files.h"
#include "error.h"

namespace voxflame::core {

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
