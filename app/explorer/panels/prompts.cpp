// The modal questions and the notice: autosaved work to restore, which flame of a file to import,
// unsaved changes on quitting; errors and warnings until dismissed. Changes the whole scene
// (restore, import) or asks the window loop to quit.
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <sstream>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "core/error.h"
#include "core/flame/xml.h"
#include "commands.h"
#include "key_codes.h"
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
void recoveryWindow(Ui& ui, std::vector<Recoverable>& offered, float scale) {
  if (offered.empty()) return;
  const Recoverable& recoverable = offered.front();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.35f * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(440 * scale, 0));
  ImGui::Begin("Recover unsaved work", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  if (recoverable.scene) {
    ImGui::TextWrapped("voxflame did not close normally last time. Its scene \"%s\" was autosaved.",
                       recoverable.scene->name.c_str());
    if (button(ui, "recover/", "Restore")) {
      ui.document.replace(*recoverable.scene);
      ui.document.keyBase = ui.document.scene;
      dismissRecoverable(recoverable);
      offered.erase(offered.begin());
    }
    ImGui::SameLine();
  } else {
    ImGui::TextColored(kErrorColor, "%s", recoverable.error.c_str());
  }
  if (!offered.empty() && button(ui, "recover/", "Discard")) {
    dismissRecoverable(offered.front());
    offered.erase(offered.begin());
  }
  ImGui::End();
}

// "Which flame?": the flames of a file opened with several, by name (filtered by words), to import
// one; Escape or Cancel imports none. The filter has the keyboard from the start, and Enter takes
// the one flame it leaves.
void flameChoiceWindow(Ui& ui, PromptsState& prompts, Settings& settings, float scale) {
  if (!prompts.flameChoice) return;
  PromptsState::FlameChoice& choice = *prompts.flameChoice;
  if (!beginModal("Which flame?", 0.45f, 440 * scale)) return;
  ImGui::TextWrapped("%s holds %zu flames. Import which one?", choice.path.filename().string().c_str(),
                     choice.names.size());
  ImGui::SetNextItemWidth(-1);
  if (std::exchange(choice.focusFilter, false)) takeKeyboard(ui);
  const bool enter = ImGui::InputTextWithHint("##flamefilter", "filter by name", choice.filter, sizeof choice.filter,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  probe(ui, "flame/filter");
  noteTyped(ui, "flame filter", choice.filter);
  const std::string filter = lowercase(choice.filter);
  // Every word of the filter, anywhere in the name.
  std::vector<std::string> words;
  {
    std::istringstream split(filter);
    for (std::string word; split >> word;) words.push_back(word);
  }
  std::vector<std::size_t> matches;
  for (std::size_t i = 0; i < choice.names.size(); ++i) {
    const std::string name = lowercase(choice.names[i]);
    if (std::all_of(words.begin(), words.end(),
                    [&](const std::string& w) { return name.find(w) != std::string::npos; }))
      matches.push_back(i);
  }
  if (!words.empty()) {
    if (matches.empty())
      dimText("no flame matches");
    else if (matches.size() == 1)
      dimText("Enter: %s", choice.names[matches.front()].c_str());
    else
      dimText("%zu flames match", matches.size());
  }
  std::optional<std::size_t> chosen;
  if (enter && matches.size() == 1) chosen = matches.front();
  if (enter && !chosen) choice.focusFilter = true;
  ImGui::BeginChild("flames", ImVec2(0, std::min(12.0f, static_cast<float>(choice.names.size())) *
                                                ImGui::GetTextLineHeightWithSpacing() +
                                            8 * scale));
  for (const std::size_t i : matches) {
    const std::string& name = choice.names[i];
    std::string label = std::to_string(i + 1);
    label += ". ";
    label += name;
    if (ImGui::Selectable(label.c_str())) chosen = i;
    probe(ui, "flame/" + name);
  }
  ImGui::EndChild();
  const bool cancel = button(ui, "flame/", "Cancel") || ImGui::IsKeyPressed(kKeyEscape, false);
  if (chosen) {
    try {
      core::FlameImportOptions options;
      options.index = *chosen;
      core::Scene scene;
      const core::FlameFileContents contents = importFlameScene(choice.path, ui.document.scene, options, scene);
      applyImportedFlame(ui.document, prompts, settings, choice.path, contents, scene);
    } catch (const core::Error& e) {
      prompts.notice = e.what();
    }
  }
  if (chosen || cancel) {
    prompts.flameChoice.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Quitting with unsaved changes: save them (as the user's preset of the document's name), throw
// them away, or stay. S, D and Escape answer from the keyboard.
void quitPromptWindow(const Document& document, FrameOutputs& frame, PromptsState& prompts, float scale) {
  if (!prompts.quitPrompt) return;
  if (!beginModal("Unsaved changes", 0.4f, 420 * scale)) return;
  ImGui::TextWrapped("\"%s\" has changes that are not saved. Save them before quitting?", document.scene.name.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  ImGui::TextWrapped(
      "Save keeps them as your preset \"%s\", replacing one of that name. S saves, D discards, "
      "Escape cancels.",
      document.scene.name.c_str());
  ImGui::PopStyleColor();
  const bool typing = ImGui::GetIO().WantTextInput;
  const bool save = button(frame, "quit/", "Save") || (!typing && ImGui::IsKeyPressed('S', false));
  ImGui::SameLine();
  const bool discard = button(frame, "quit/", "Discard") || (!typing && ImGui::IsKeyPressed('D', false));
  ImGui::SameLine();
  const bool cancel = button(frame, "quit/", "Cancel") || ImGui::IsKeyPressed(kKeyEscape, false);
  if (save) {
    frame.requests.saveAs = document.scene.name;
    frame.requests.saveReplacing = true;
    prompts.quitAfterSave = true;
  } else if (discard) {
    frame.requests.quit = true;
  }
  if (save || discard || cancel) {
    prompts.quitPrompt = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Errors stay on screen until dismissed; the explorer goes on with the last good state.
void noticeWindow(FrameOutputs& frame, PromptsState& prompts, float scale) {
  std::string text;
  auto addLine = [&text](const std::string& line) {
    if (line.empty()) return;
    if (!text.empty()) text += '\n';
    text += line;
  };
  addLine(prompts.notice);
  addLine(frame.session.error);
  if (!frame.session.escapeNote.empty())
    addLine(frame.session.showingLastBounded ? frame.session.escapeNote
                                             : frame.session.escapeNote + " — try Search (F3).");
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
  if (!prompts.notice.empty() && button(frame, "notice/", "Dismiss")) prompts.notice.clear();
  ImGui::End();
}

}  // namespace voxflame::app::panels
