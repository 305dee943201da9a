// Input outside the panels: undo and redo, the camera (orbit, pan, zoom, fly) and the keyboard
// shortcuts. Changes the scene's camera, the history, and starts searches.
#include "explorer_ui.h"

#include <imgui.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

#include "core/camera.h"
#include "core/scene_schema.h"
#include "key_codes.h"
#include "panels.h"
#include "widgets.h"

namespace voxflame::app::panels {

// ---------------------------------------------------------------------------------------------
// Input: undo/redo, camera, shortcuts.

// Ctrl+Z undoes, Ctrl+Shift+Z (or Ctrl+Y) redoes; an edit is recorded once it settles, so a
// whole slider drag or camera drag is one step.
void handleHistory(Document& document) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool z = ImGui::IsKeyPressed('Z', false), y = ImGui::IsKeyPressed('Y', false);
  if (!io.WantTextInput && io.KeyCtrl && (z || y)) {
    const bool redo = io.KeyShift || y;
    if (auto scene = redo ? document.history->redo() : document.history->undo()) {
      document.replace(*scene);
      document.keyBase = *scene;
    }
    return;
  }
  const bool mouseHeld = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                         ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (!mouseHeld && !ImGui::IsAnyItemActive()) document.recordInHistory();
}

// However far one pans or flies, the target stays a value a preset can hold.
glm::dvec3 clampedTarget(const glm::dvec3& target) {
  const core::Field<core::CameraSettings>& field = core::field(core::cameraFields(), "target");
  return glm::clamp(target, glm::dvec3(field.min), glm::dvec3(field.max));
}

static void moveCamera(ViewDragState& drag, bool quitPromptOpen, core::CameraSettings& camera);

// Left-drag orbits, right- or middle-drag pans, the wheel zooms; W/A/S/D/Q/E fly. Input that
// starts over a panel belongs to the panel.
void handleCamera(Document& document, ViewDragState& drag, bool quitPromptOpen) {
  core::CameraSettings& camera = document.scene.camera;
  const core::CameraSettings before = camera;
  moveCamera(drag, quitPromptOpen, camera);
  if (!(camera == before)) document.edited(core::Affects::View);
}

static void moveCamera(ViewDragState& drag, bool quitPromptOpen, core::CameraSettings& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool overUi = io.WantCaptureMouse;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !overUi) drag.orbiting = true;
  if ((ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) && !overUi)
    drag.panning = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) drag.orbiting = false;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right) && !ImGui::IsMouseDown(ImGuiMouseButton_Middle)) drag.panning = false;
  const ImVec2 delta = io.MouseDelta;
  const bool moved = std::isfinite(delta.x) && std::isfinite(delta.y) && (delta.x != 0.0f || delta.y != 0.0f);
  const core::CameraFrame frame = core::orbitCamera(camera, core::Box{{-1, -1, -1}, {1, 1, 1}}, 1.0);
  if (drag.orbiting && moved) {
    camera.azimuthDeg = std::remainder(camera.azimuthDeg - 0.3 * delta.x, 360.0);
    camera.elevationDeg = std::clamp(camera.elevationDeg + 0.3 * delta.y, -90.0, 90.0);
  }
  if (drag.panning && moved) {
    // The target moves with the pointer: a screen's height of drag moves the view by about
    // what is visible at the target's distance.
    const double perPixel =
        2.0 * camera.distance * std::tan(0.5 * glm::radians(camera.fovDeg)) / std::max(1.0f, io.DisplaySize.y);
    camera.target = clampedTarget(camera.target + perPixel * (-static_cast<double>(delta.x) * frame.right +
                                                              static_cast<double>(delta.y) * frame.up));
  }
  if (!overUi && io.MouseWheel != 0.0f)
    camera.distance = std::clamp(camera.distance * std::pow(0.9, io.MouseWheel), 0.2, 20.0);

  // Free flight: W/S move along the view, A/D sideways, Q/E down and up; the orbit target moves
  // with the eye, so the camera turns about itself when dragged afterwards.
  // (Nor while the quit prompt is open: S and D answer it.)
  if (io.WantCaptureKeyboard || io.KeyCtrl || quitPromptOpen) return;
  const double speed = 1.2 * camera.distance * std::min(0.1f, io.DeltaTime);
  auto held = [](int key) { return keyDown(key) ? 1.0 : 0.0; };
  const glm::dvec3 move = (held('W') - held('S')) * frame.forward + (held('D') - held('A')) * frame.right +
                          (held('E') - held('Q')) * frame.up;
  camera.target = clampedTarget(camera.target + speed * move);
}

void handleShortcuts(ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.KeyCtrl && ImGui::IsKeyPressed('Q', false)) askToQuit(state);
  // Ctrl+S keeps the scene as the user's preset of its name, as the quit prompt's Save does (also
  // from a text field, as in any editor).
  if (io.KeyCtrl && ImGui::IsKeyPressed('S', false) && !state.panels.prompts.quitPrompt) {
    state.frame.requests.saveAs = state.document.scene.name;
    state.frame.requests.saveReplacing = true;
  }
  if (io.WantTextInput) return;
  if (ImGui::IsKeyPressed(kKeyF3, false)) startSearch(state.document, state.panels.explore, state.services, 0.1, true);
  if (io.KeyCtrl && ImGui::IsKeyPressed('F', false)) state.panels.pattern.focusAttractorFilter = true;
  const bool alt = io.KeyAlt || keyDown(kKeyLeftAlt) || keyDown(kKeyRightAlt);
  if (alt && ImGui::IsKeyPressed(kKeyLeft, false)) goVisited(state.document, state.panels.explore, -1);
  if (alt && ImGui::IsKeyPressed(kKeyRight, false)) goVisited(state.document, state.panels.explore, +1);
}

}  // namespace voxflame::app::panels
