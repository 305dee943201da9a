// The modal questions and the notice: autosaved work to restore, which flame of a file to import,
// unsaved changes on quitting; errors and warnings until dismissed. Changes the whole scene
// (restore, import) or asks the window loop to quit.
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
#include "panels.h"
#include "widgets.h"

namespace voxflame::app::panels {

namespace {

// Opens the modal question `title` (once), centred across the window at `heightFraction` of its
// height, `width` wide; true while it shows (then end it with ImGui::EndPopup).
bool beginModal(const char* title, float heightFraction, float width) {
  if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, heightFraction * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(width, 0));
  return ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
}

}  // namespace

// Scenes left by a session that crashed or was killed: restore or discard, one at a time.
void recoveryWindow(ExplorerState& state, float scale) {
  if (state.services.recoverable.empty()) return;
  const Recoverable& recoverable = state.services.recoverable.front();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.35f * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(440 * scale, 0));
  ImGui::Begin("Recover unsaved work", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  if (recoverable.scene) {
    ImGui::TextWrapped("voxflame did not close normally last time. Its scene \"%s\" was autosaved.",
                       recoverable.scene->name.c_str());
    if (button(state, "recover/", "Restore")) {
      state.document.replace(*recoverable.scene);
      state.document.keyBase = state.document.scene;
      dismissRecoverable(recoverable);
      state.services.recoverable.erase(state.services.recoverable.begin());
    }
    ImGui::SameLine();
  } else {
    ImGui::TextColored(kErrorColor, "%s", recoverable.error.c_str());
  }
  if (!state.services.recoverable.empty() && button(state, "recover/", "Discard")) {
    dismissRecoverable(state.services.recoverable.front());
    state.services.recoverable.erase(state.services.recoverable.begin());
  }
  ImGui::End();
}

// "Which flame?": the flames of a file opened with several, by name (filtered by words), to import
// one; Escape or Cancel imports none.
void flameChoiceWindow(ExplorerState& state, float scale) {
  if (!state.panels.prompts.flameChoice) return;
  PromptsState::FlameChoice& choice = *state.panels.prompts.flameChoice;
  if (!beginModal("Which flame?", 0.45f, 440 * scale)) return;
  ImGui::TextWrapped("%s holds %zu flames. Import which one?", choice.path.filename().string().c_str(),
                     choice.names.size());
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##flamefilter", "filter by name", choice.filter, sizeof choice.filter);
  noteTyped(state, "flame filter", choice.filter);
  const std::string filter = lowercase(choice.filter);
  std::optional<std::size_t> chosen;
  ImGui::BeginChild("flames", ImVec2(0, std::min(12.0f, static_cast<float>(choice.names.size())) *
                                                ImGui::GetTextLineHeightWithSpacing() +
                                            8 * scale));
  for (std::size_t i = 0; i < choice.names.size(); ++i) {
    const std::string& name = choice.names[i];
    if (!filter.empty() && lowercase(name).find(filter) == std::string::npos) continue;
    std::string label = std::to_string(i + 1);
    label += ". ";
    label += name;
    if (ImGui::Selectable(label.c_str())) chosen = i;
    probe(state, "flame/" + name);
  }
  ImGui::EndChild();
  const bool cancel = button(state, "flame/", "Cancel") || ImGui::IsKeyPressed(kKeyEscape, false);
  if (chosen) {
    try {
      core::FlameImportOptions options;
      options.index = *chosen;
      core::Scene scene;
      const core::FlameFileContents contents = importFlameScene(choice.path, state.document.scene, options, scene);
      applyImportedFlame(state, choice.path, contents, scene);
    } catch (const core::Error& e) {
      state.panels.prompts.notice = e.what();
    }
  }
  if (chosen || cancel) {
    state.panels.prompts.flameChoice.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Quitting with unsaved changes: save them (as the user's preset of the document's name), throw
// them away, or stay. S, D and Escape answer from the keyboard.
void quitPromptWindow(ExplorerState& state, float scale) {
  if (!state.panels.prompts.quitPrompt) return;
  if (!beginModal("Unsaved changes", 0.4f, 420 * scale)) return;
  ImGui::TextWrapped("\"%s\" has changes that are not saved. Save them before quitting?",
                     state.document.scene.name.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  ImGui::TextWrapped(
      "Save keeps them as your preset \"%s\", replacing one of that name. S saves, D discards, "
      "Escape cancels.",
      state.document.scene.name.c_str());
  ImGui::PopStyleColor();
  const bool typing = ImGui::GetIO().WantTextInput;
  const bool save = button(state, "quit/", "Save") || (!typing && ImGui::IsKeyPressed('S', false));
  ImGui::SameLine();
  const bool discard = button(state, "quit/", "Discard") || (!typing && ImGui::IsKeyPressed('D', false));
  ImGui::SameLine();
  const bool cancel = button(state, "quit/", "Cancel") || ImGui::IsKeyPressed(kKeyEscape, false);
  if (save) {
    state.frame.requests.saveAs = state.document.scene.name;
    state.frame.requests.saveReplacing = true;
    state.panels.prompts.quitAfterSave = true;
  } else if (discard) {
    state.frame.requests.quit = true;
  }
  if (save || discard || cancel) {
    state.panels.prompts.quitPrompt = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Errors stay on screen until dismissed; the explorer goes on with the last good state.
void noticeWindow(ExplorerState& state, float scale) {
  std::string text;
  auto addLine = [&text](const std::string& line) {
    if (line.empty()) return;
    if (!text.empty()) text += '\n';
    text += line;
  };
  addLine(state.panels.prompts.notice);
  addLine(state.frame.session.error);
  if (!state.frame.session.escapeNote.empty())
    addLine(state.frame.session.showingLastBounded ? state.frame.session.escapeNote
                                                   : state.frame.session.escapeNote + " — try Search (F3).");
  if (text.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 12 * scale), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(200 * scale, 0), ImVec2(io.DisplaySize.x * 0.45f, 400 * scale));
  // Never focused on appearing: focusing a window ends the drag of a widget in another, and an
  // escape that shows up in the middle of a slider's drag must not take the slider from the mouse.
  ImGui::Begin("##notice", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::PushTextWrapPos(io.DisplaySize.x * 0.43f);
  ImGui::TextColored(kErrorColor, "%s", text.c_str());
  ImGui::PopTextWrapPos();
  if (!state.panels.prompts.notice.empty() && button(state, "notice/", "Dismiss")) state.panels.prompts.notice.clear();
  ImGui::End();
}

}  // namespace voxflame::app::panels
