#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <sstream>
#include <cstdarg>
#include <cctype>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "core/attractor.h"
#include "core/camera.h"
#include "core/color.h"
#include "core/error.h"
#include "core/flame.h"
#include "core/flame_search.h"
#include "core/flame_variations.h"
#include "core/flame_xml.h"
#include "core/flat_render.h"
#include "core/grid.h"
#include "core/keyframes.h"
#include "core/scene_schema.h"
#include "commands.h"
#include "pipeline.h"
#include "panels/panels.h"
#include "panels/widgets.h"

namespace voxflame::app {

using namespace panels;

void applyImportedFlame(ExplorerState& state, const std::filesystem::path& path,
                        const core::FlameFileContents& contents, const core::Scene& scene) {
  // A flame replaces the pattern and keeps the mesh and view: one undoable edit.
  state.scene = scene;
  state.notice.clear();
  const std::string file = path.filename().string();
  for (const std::string& warning : contents.flame.warnings) {
    if (!state.notice.empty()) state.notice += '\n';
    state.notice.append(file).append(": ").append(warning);
  }
  state.settings.addRecent(RecentKind::Preset, path);
}

bool hasUnsavedChanges(const ExplorerState& state) {
  return !(state.scene == state.savedScene);
}

void askToQuit(ExplorerState& state) {
  if (hasUnsavedChanges(state))
    state.quitPrompt = true;
  else
    state.requests.quit = true;
}

core::CameraSettings viewCamera(const ExplorerState& state) {
  const ExportSettings& exported = state.settings.lastExport;
  if (state.viewRect.z <= 0 || state.viewRect.w <= 0 || exported.width <= 0 || exported.height <= 0)
    return state.scene.camera;
  return core::viewCameraFor(state.scene.camera, static_cast<double>(state.viewRect.z) / state.viewRect.w,
                             static_cast<double>(exported.width) / exported.height);
}

std::string windowTitle(const ExplorerState& state) {
  return "voxflame — " + state.scene.name + (hasUnsavedChanges(state) ? " (unsaved)" : "");
}

void resetExplorerState(ExplorerState& state, const core::Scene& scene) {
  state.scene = scene;
  state.savedScene = scene;
  state.keyBase = scene;
  state.initialCamera = scene.camera;
  state.history.emplace(scene);
  state.visited.clear();
  state.visitedMessages.clear();
  state.visitedIndex = 0;
  state.searchMessage.clear();
  state.analysedKey.clear();
  state.playing = false;
}

bool openFile(ExplorerState& state, const std::filesystem::path& path) {
  try {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (core::isFlameFilePath(path)) {
      core::Scene scene;
      const core::FlameFileContents contents = importFlameScene(path, state.scene, {}, scene);
      // A file of several flames asks which one (flameChoiceWindow), as --index and --name do.
      if (contents.names.size() > 1) {
        state.flameChoice.emplace();
        state.flameChoice->path = path;
        state.flameChoice->names = contents.names;
        state.notice.clear();
        return true;
      }
      applyImportedFlame(state, path, contents, scene);
      return true;
    }
    const bool preset = extension == ".json" || extension == ".png";
    const core::Scene scene = preset ? sceneFromFile(path) : sceneWithMesh(state.scene, path);
    // A preset opens fresh, with its own history; a new mesh is one more undoable edit.
    if (preset)
      resetExplorerState(state, scene);
    else
      state.scene = scene;
    state.notice.clear();
    state.settings.addRecent(preset ? RecentKind::Preset : RecentKind::Mesh, path);
    if (preset && extension == ".json") state.settings.lastPreset = std::filesystem::absolute(path);
    return true;
  } catch (const core::Error& e) {
    state.notice = e.what();
    return false;
  }
}

void explorerUiFrame(ExplorerState& state) {
  const float scale = state.uiScale;
  state.requests = UiRequests{};
  if (state.probe) state.probe->items.clear();
  if (state.exportJob) state.exportStatus = state.exportJob->poll();
  handleShortcuts(state);
  handleCamera(state);
  handleHistory(state);
  collectSearch(state);
  updateAnalysis(state);
  updateFlatView(state);
  drawFlatView(state);
  advancePlayback(state);
  patternWindow(state, scale);
  viewWindow(state, scale);
  timelineWindow(state, scale);
  recoveryWindow(state, scale);
  quitPromptWindow(state, scale);
  flameChoiceWindow(state, scale);
  placeView(state, scale);
  dimLastBoundedPicture(state);
  drawExportFrame(state);
  statusBar(state, scale);
  noticeWindow(state, scale);
  // Read after the panels, which make a widget active on the frame it is pressed: an edit on that
  // very frame is already part of a drag.
  state.interacting = ImGui::IsAnyItemActive() || state.orbiting || state.panning;
}

void applyUiScale(float scale) {
  ImGuiStyle& style = ImGui::GetStyle();
  style = ImGuiStyle();
  ImGui::StyleColorsDark();
  style.WindowRounding = 6.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 4.0f;
  style.WindowBorderSize = 0.0f;
  style.Colors[ImGuiCol_WindowBg].w = 0.86f;
  style.ScaleAllSizes(scale);
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  // DejaVu Sans has the Greek, arrows and punctuation the panels use; ImGui's built-in font is
  // the fallback (and is what tests get when the font is not installed).
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2044, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  ImFontConfig config;
  config.OversampleH = 2;
  if (!std::filesystem::exists(kFont) || !io.Fonts->AddFontFromFileTTF(kFont, 14.0f * scale, &config, kRanges)) {
    ImFontConfig fallback;
    fallback.SizePixels = 13.0f * scale;
    io.Fonts->AddFontDefault(&fallback);
  }
}

}  // namespace voxflame::app
