// The explorer: a GLFW window with Dear ImGui panels over the live, refining volume.
#pragma once

#include <filesystem>

#include "core/scene.h"

namespace voxflame::app {

struct ExplorerOptions {
  std::filesystem::path screenshotPath;  // when set: save the window after `frames` frames, exit
  int frames = 0;                        // frames showing the volume before the screenshot; 0: run until closed
  int width = 0, height = 0;             // window size in screen coordinates; 0: as last time (settings)
  float uiScale = 0.0f;                  // panel and font scale; 0: the monitor's content scale
  int minFrameMs = 0;                    // each frame lasts at least this long: a slow machine, for tests
  // When set: every change to a text field is appended as "SECONDS FIELD<tab>TEXT" (SECONDS on the
  // steady clock, which other processes share) when the frame showing it is drawn (bench explorer).
  std::filesystem::path inputLog;
};

// Opens the window and runs until it is closed. With no display, says so and renders the scene
// to a PNG instead. Returns the process exit status.
int runExplorer(const core::Scene& scene, const ExplorerOptions& options);

}  // namespace voxflame::app
