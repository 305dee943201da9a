// The widgets every panel builds from (widgets.h).
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cstdarg>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/scene_schema.h"
#include "widgets.h"

namespace voxflame::app::panels {

// The status line's height: the docked panels end above it.
float statusBarHeight(float scale) {
  return ImGui::GetFrameHeightWithSpacing() + 6 * scale;
}

// A hint or a message in the dim colour, wrapped at the panel's edge rather than cut there.
void dimText(const char* format, ...) {
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  va_list arguments;
  va_start(arguments, format);
  ImGui::TextWrappedV(format, arguments);
  va_end(arguments);
  ImGui::PopStyleColor();
}

void probe(FrameOutputs& frame, const std::string& name) {
  if (!frame.probe) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  frame.probe->items[name] = UiProbe::Rect{min.x, min.y, max.x, max.y};
}

void probeText(FrameOutputs& frame, const std::string& name, const std::string& text) {
  if (frame.probe) frame.probe->texts[name] = text;
}

bool labelFitsBeside(FrameOutputs& frame, const std::string& label, const std::string& probeName) {
  probeText(frame, probeName, label);
  // ImGui shows a window's content up to half its padding from its edge.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float room = ImGui::GetContentRegionAvail().x - ImGui::CalcItemWidth() - style.ItemInnerSpacing.x +
                     std::floor(0.5f * style.WindowPadding.x);
  return ImGui::CalcTextSize(label.c_str()).x <= room;
}

std::string fittedText(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  const char* ellipsis = "…";
  const float ellipsisWidth = ImGui::CalcTextSize(ellipsis).x;
  if (width < ellipsisWidth) return {};
  std::size_t length = text.size();
  // Whole UTF-8 characters only: a cut never leaves half of one.
  while (length > 0) {
    do --length;
    while (length > 0 && (static_cast<unsigned char>(text[length]) & 0xC0) == 0x80);
    if (ImGui::CalcTextSize(text.data(), text.data() + length).x + ellipsisWidth <= width) break;
  }
  return text.substr(0, length) + ellipsis;
}

void labelAbove(FrameOutputs& frame, const std::string& label, const std::string& probeName) {
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(label.c_str());
  ImGui::PopTextWrapPos();
  probe(frame, probeName + "/label");
}

// After a text field: what it now holds, when it changed this frame and typing is recorded.
void noteTyped(FrameOutputs& frame, const char* field, const char* text) {
  if (frame.recordTyping && ImGui::IsItemEdited()) frame.typedThisFrame.emplace_back(field, text);
}

bool slider(FrameOutputs& frame, const std::string& scope, const char* label, double& value, double min, double max,
            ImGuiSliderFlags flags, const char* format) {
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format, flags);
  probe(frame, scope + label);
  return changed;
}

// The JSON pointer of a panel value: a widget's scope names its object ("tone/", "camera/",
// "layer2/" for /layers/2/), then the key.
std::string valuePath(const std::string& scope, std::string_view key) {
  if (scope.rfind("layer", 0) == 0 && scope.size() > 6 && std::isdigit(static_cast<unsigned char>(scope[5]))) {
    const std::size_t slash = scope.find('/');
    return "/layers/" + scope.substr(5, slash - 5) + "/" + std::string(key);
  }
  return "/" + scope + std::string(key);
}

// A value with keys on the Timeline carries a mark: a small key at the widget's top right corner.
void markIfKeyed(Ui& ui, const std::string& path, const std::string& probeName) {
  const auto& tracks = ui.document.scene.keyframes;
  if (std::none_of(tracks.begin(), tracks.end(), [&](const core::KeyframeTrack& t) { return t.path == path; })) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const float size = 0.22f * (max.y - min.y);
  const ImVec2 centre(max.x - size - 1.0f, min.y + size + 1.0f);
  ImGui::GetWindowDrawList()->AddQuadFilled(ImVec2(centre.x, centre.y - size), ImVec2(centre.x + size, centre.y),
                                            ImVec2(centre.x, centre.y + size), ImVec2(centre.x - size, centre.y),
                                            IM_COL32(255, 190, 90, 255));
  probe(ui, probeName + "/keyed");
}

void takeKeyboard(FrameOutputs& frame) {
  ImGui::SetKeyboardFocusHere();
  frame.keyboardFocusMoved = true;
}

bool button(FrameOutputs& frame, const std::string& scope, const char* label) {
  const bool pressed = ImGui::Button(label);
  probe(frame, scope + label);
  return pressed;
}

bool reportEdit(Document& document, bool changed, core::Affects affects) {
  if (changed) document.edited(affects);
  return changed;
}

bool resetClicked() {
  // Hovered, not focused: the last item of some widgets (a colour editor, a vector's sliders) is
  // their group, which has no id of its own to open a menu on.
  return ImGui::IsItemHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Right);
}

void parameterReset(Ui& ui, double& value, double defaultValue, const char* hint, const std::string& name) {
  if (resetClicked()) {
    value = defaultValue;
    ui.document.edited(core::Affects::Pattern);
  }
  if (!ImGui::IsItemHovered() || ImGui::IsItemActive()) return;
  if (name.empty())
    ImGui::SetTooltip("default %.4g — %s", defaultValue, hint);
  else
    ImGui::SetTooltip("%s\ndefault %.4g — %s", name.c_str(), defaultValue, hint);
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool keyDown(int key) {
  return key >= 0 && key < IM_ARRAYSIZE(ImGui::GetIO().KeysDown) && ImGui::GetIO().KeysDown[key];
}

}  // namespace voxflame::app::panels
