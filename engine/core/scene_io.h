// Where a Scene's inputs come from: the embedded default preset, preset files, and the mesh a
// scene names (on disk, or inside the binary for the embedded default).
//
// scene_io.cpp is also the preset loader: sceneFromJson, loadScene, sceneToJson and
// sceneToDocument (declared in scene.h) migrate old schema versions and compose the scene's
// reader and writer (scene_schema.h) with the keyframes' (keyframes.h), which know nothing of
// each other.
#pragma once

#include "mesh.h"
#include "scene.h"

namespace voxflame::core {

inline constexpr const char* kDefaultPresetName = "presets/default.json";

Scene defaultScene();                            // the preset embedded in the binary
TriangleMesh loadSceneMesh(const Scene& scene);  // throws core::Error naming the mesh file

}  // namespace voxflame::core
