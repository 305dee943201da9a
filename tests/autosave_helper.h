// Shared by the autosave tests and autosave_helper, the "explorer" they kill: the scene it edits.
#pragma once

#include "core/scene.h"
#include "core/scene_io.h"

namespace voxflame::test {

inline core::Scene editedScene() {
  core::Scene scene = core::defaultScene();
  scene.name = "edited before the crash";
  scene.tone.brightness = 7.25;
  scene.layers.at(0).params.at(0) += 0.01;
  return scene;
}

}  // namespace voxflame::test
