#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "core/camera.h"
#include "core/error.h"
#include "core/flame/xml.h"
#include "core/scene_schema.h"
#include "commands.h"
#include "pipeline.h"
#include "panels/panels.h"
#include "panels/widgets.h"

namespace voxflame::app {

using namespace panels;

void applyImportedFlame(Document& document, PromptsState& prompts, Settings& settings,
                        const std::filesystem::path& path, const core::FlameFileContents& contents,
                        const core::Scene& scene) {
  // A flame replaces the pattern and keeps the mesh and view: one undoable edit.
  document.replace(scene);
  prompts.notice.clear();
  const std::string file = path.filename().string();
  for (const std::string& warning : contents.flame.warnings) {
    if (!prompts.notice.empty()) prompts.notice += '\n';
    prompts.notice.append(file).append(": ").append(warning);
  }
  settings.addRecent(RecentKind::Preset, path);
}

bool hasUnsavedChanges(const ExplorerState& state) {
  return state.document.unsaved();
}

void askToQuit(ExplorerState& state) {
  if (hasUnsavedChanges(state))
    state.panels.prompts.quitPrompt = true;
  else
    state.frame.requests.quit = true;
}

core::CameraSettings viewCamera(const ExplorerState& state) {
  const ExportSettings& exported = state.services.settings.lastExport;
  if (state.frame.viewRect.z <= 0 || state.frame.viewRect.w <= 0 || exported.width <= 0 || exported.height <= 0)
    return state.document.scene.camera;
  return core::viewCameraFor(state.document.scene.camera,
                             static_cast<double>(state.frame.viewRect.z) / state.frame.viewRect.w,
                             static_cast<double>(exported.width) / exported.height);
}

std::string windowTitle(const ExplorerState& state) {
  return "voxflame — " + state.document.scene.name + (hasUnsavedChanges(state) ? " (unsaved)" : "");
}

void resetExplorerState(ExplorerState& state, const core::Scene& scene) {
  state.document.reset(scene);
  state.panels.explore.visited.clear();
  state.panels.explore.visitedMessages.clear();
  state.panels.explore.visitedIndex = 0;
  state.panels.explore.searchMessage.clear();
  state.panels.explore.analysedKey.clear();
  state.panels.explore.analysedRevision = ~std::uint64_t{0};
  state.panels.timeline.playing = false;
}

bool openFile(ExplorerState& state, const std::filesystem::path& path) {
  try {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (core::isFlameFilePath(path)) {
      core::Scene scene;
      const core::FlameFileContents contents = importFlameScene(path, state.document.scene, {}, scene);
      // A file of several flames asks which one (flameChoiceWindow), as --index and --name do.
      if (contents.names.size() > 1) {
        state.panels.prompts.flameChoice.emplace();
        state.panels.prompts.flameChoice->path = path;
        state.panels.prompts.flameChoice->names = contents.names;
        state.panels.prompts.notice.clear();
        return true;
      }
      applyImportedFlame(state.document, state.panels.prompts, state.services.settings, path, contents, scene);
      return true;
    }
    const bool preset = extension == ".json" || extension == ".png";
    const core::Scene scene = preset ? sceneFromFile(path) : sceneWithMesh(state.document.scene, path);
    // A preset opens fresh, with its own history; a new mesh is one more undoable edit.
    if (preset)
      resetExplorerState(state, scene);
    else
      state.document.replace(scene);
    state.panels.prompts.notice.clear();
    state.services.settings.addRecent(preset ? RecentKind::Preset : RecentKind::Mesh, path);
    if (preset && extension == ".json") state.services.settings.lastPreset = std::filesystem::absolute(path);
    return true;
  } catch (const core::Error& e) {
    state.panels.prompts.notice = e.what();
    return false;
  }
}

// Every change to the scene is reported where it is made (Document::edited); with
// checkEditReports on (the tests) the frame compares the scene before and after and throws when a
// change went unreported, or was reported as affecting less than it does.
static void checkEditReports(const core::Scene& before, Document& document, std::uint64_t reportsBefore) {
  const core::Affects reported = document.takeReported();
  const core::SceneDiff changed = core::diff(before, document.scene);
  if (changed.empty()) return;
  const bool unreported = document.revisions().any == reportsBefore;
  const core::Affects missing =
      static_cast<core::Affects>(static_cast<unsigned>(changed.affects) & ~static_cast<unsigned>(reported));
  if (unreported || core::any(missing))
    throw std::logic_error("an edit of " + changed.paths.front() + " (" + core::toString(changed.affects) +
                           ") was reported as " + (unreported ? "nothing" : core::toString(reported)));
}

void explorerUiFrame(ExplorerState& state) {
  std::optional<core::Scene> before;
  const std::uint64_t reportsBefore = state.document.revisions().any;
  if (state.frame.checkEditReports) {
    before = state.document.scene;
    state.document.takeReported();
  }
  const float scale = state.panels.uiScale;
  state.frame.requests = UiRequests{};
  if (state.frame.probe) state.frame.probe->items.clear();
  if (state.services.exportJob) state.services.exportStatus = state.services.exportJob->poll();
  // Each panel gets the parts it may change (panels/panels.h).
  Document& document = state.document;
  FrameOutputs& frame = state.frame;
  PanelState& panels = state.panels;
  Services& services = state.services;
  Ui ui{document, frame};
  handleShortcuts(state);
  handleCamera(document, panels.drag, panels.prompts.quitPrompt);
  handleHistory(document);
  collectSearch(document, panels.explore, services);
  updateAnalysis(document, panels.explore, services);
  updateFlatView(document, panels.flat, services, frame);
  advancePlayback(document, panels.timeline, panels.prompts);
  patternWindow(ui, panels.pattern, panels.explore, panels.flat, services, scale);
  viewWindow(ui, panels.scene, panels.prompts, services, scale);
  timelineWindow(ui, panels.timeline, panels.prompts, scale);
  recoveryWindow(ui, services.recoverable, scale);
  quitPromptWindow(document, frame, panels.prompts, scale);
  flameChoiceWindow(ui, panels.prompts, services.settings, scale);
  placeView(frame, scale);
  dimLastBoundedPicture(frame);
  drawExportFrame(frame, services);
  // Over the volume's picture in the view's rectangle, placed by this frame's panels. Not dimmed
  // with the volume: the flat view renders the pattern the sliders say, escaping or not.
  drawFlatView(panels.flat, services, frame);
  statusBar(frame, panels.explore, panels.status, scale);
  noticeWindow(frame, panels.prompts, scale);
  // Read after the panels, which make a widget active on the frame it is pressed: an edit on that
  // very frame is already part of a drag.
  state.frame.interacting = ImGui::IsAnyItemActive() || state.panels.drag.orbiting || state.panels.drag.panning;
  if (before) checkEditReports(*before, state.document, reportsBefore);
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
