// What every panel builds with: probes for the tests, dim and error text, sliders, buttons, and the
// widget of one schema field (core/scene_schema.h), which brings its label, range, format, help,
// keyed mark and right-click reset from the table.
#pragma once

#include <imgui.h>

#include <string>
#include <string_view>
#include <variant>

#include "core/color.h"
#include "core/scene_schema.h"
#include "explorer_ui.h"

namespace voxflame::app::panels {

// What a panel that edits the document draws with: the document, whose edits it reports
// (reportEdit, fieldWidget), and the frame's outputs its widgets write (probes for the tests,
// typed text, a keyboard request). Panels that only show things take FrameOutputs alone; a Ui
// passes for either.
struct Ui {
  Document& document;
  FrameOutputs& frame;
  operator Document&() const { return document; }
  operator FrameOutputs&() const { return frame; }
};

inline const ImVec4 kErrorColor(1.0f, 0.45f, 0.35f, 1.0f);
inline const ImVec4 kDimColor(0.62f, 0.65f, 0.72f, 1.0f);
// Sliders clamp, Ctrl+click typing included: no value made in a panel is one a preset refuses.
inline constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;

// The status line's height: the docked panels end above it.
float statusBarHeight(float scale);
// A hint or a message in the dim colour, wrapped at the panel's edge rather than cut there.
IM_FMTARGS(1) void dimText(const char* format, ...);
// Records the last widget's rectangle under `name` when a test set FrameOutputs::probe.
void probe(FrameOutputs& frame, const std::string& name);
// Records `text` as what the widget `name` shows, when a test set FrameOutputs::probe.
void probeText(FrameOutputs& frame, const std::string& name, const std::string& text);
// Whether `label` fits beside the next widget, in the room the panel keeps right of its widgets
// (PushItemWidth). A label that does not goes on a line of its own above the widget instead, so no
// label is cut at the panel's edge: the caller draws it there (labelAbove) and gives the widget an
// id alone ("##..."). Records the label under `probeName`.
bool labelFitsBeside(FrameOutputs& frame, const std::string& label, const std::string& probeName);
// `text` when it is at most `width` wide, else as much of it as fits before an ellipsis ("…"),
// or nothing where not even the ellipsis fits.
std::string fittedText(const std::string& text, float width);
// A label on a line of its own, wrapped at the panel's edge; probed as `probeName` + "/label".
void labelAbove(FrameOutputs& frame, const std::string& label, const std::string& probeName);
// After a text field: what it now holds, when it changed this frame and typing is recorded.
void noteTyped(FrameOutputs& frame, const char* field, const char* text);
bool slider(FrameOutputs& frame, const std::string& scope, const char* label, double& value, double min, double max,
            ImGuiSliderFlags flags = 0, const char* format = "%.3f");
// The JSON pointer of a panel value: a widget's scope names its object ("tone/", "camera/",
// "layer2/" for /layers/2/), then the key.
std::string valuePath(const std::string& scope, std::string_view key);
// A value with keys on the Timeline carries a mark: a small key at the widget's top right corner.
void markIfKeyed(Ui& ui, const std::string& path, const std::string& probeName);
bool button(FrameOutputs& frame, const std::string& scope, const char* label);
// Gives the next widget the keyboard. ImGui 1.86 drops the characters of the frame that activates
// it, so the window loop holds the next frame's characters (FrameOutputs::keyboardFocusMoved):
// every panel that moves the keyboard goes through here.
void takeKeyboard(FrameOutputs& frame);
// Reports an edit of the document made by the widget just drawn, when `changed`, with what it
// affects (Document::edited); returns `changed`. Every panel edit of the scene goes through here or
// through fieldWidget, which reports its row's class.
bool reportEdit(Document& document, bool changed, core::Affects affects);
// Whether the last widget was right-clicked in this frame: what resets a value to its default at
// once, with no menu to confirm it (Ctrl+Z undoes it like any edit).
bool resetClicked();
// The right-click reset and the tooltip of the last widget, for a number no schema table holds (an
// attractor's or a variation's parameter): back to `defaultValue`, reported as a pattern edit, and
// a tooltip with the default and `hint`, after `name` when that is given (a label too long for the
// panel shows whole there).
void parameterReset(Ui& ui, double& value, double defaultValue, const char* hint, const std::string& name = {});
std::string lowercase(std::string text);
bool keyDown(int key);

// The widget of one schema field (core/scene_schema.h): its label, slider range, format and help
// come from the table. Sliders always clamp, Ctrl+click typing included, and every table's slider
// range lies inside what the reader allows, so no value made here is one a preset refuses.
// `probeName` replaces the probe's usual name (scope + label).
template <class Owner>
bool fieldWidget(Ui& ui, const std::string& scope, Owner& owner, core::Table<Owner> table, std::string_view key,
                 const char* probeName = nullptr) {
  const core::Field<Owner>& f = core::field(table, key);
  const std::string label(f.ui.label);
  const std::string format(f.ui.format);
  const std::string probed = probeName ? std::string(probeName) : scope + label;
  // A check box's label follows its box; every other widget's goes where labels go, or above the
  // widget when it is too long for the room there.
  const bool beside = std::holds_alternative<bool Owner::*>(f.member) || labelFitsBeside(ui, label, probed);
  if (!beside) labelAbove(ui, label, probed);
  const std::string shown = beside ? label : "##" + label;
  const ImGuiSliderFlags flags =
      ImGuiSliderFlags_AlwaysClamp | (f.ui.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
  const bool changed = std::visit(
      [&]<class M>(const M& member) -> bool {
        if constexpr (std::is_same_v<M, double Owner::*>) {
          const double min = f.ui.min, max = f.ui.max;
          return ImGui::SliderScalar(shown.c_str(), ImGuiDataType_Double, &(owner.*member), &min, &max, format.c_str(),
                                     flags);
        } else if constexpr (std::is_same_v<M, int Owner::*>) {
          return ImGui::SliderInt(shown.c_str(), &(owner.*member), static_cast<int>(f.ui.min),
                                  static_cast<int>(f.ui.max), format.c_str(), flags);
        } else if constexpr (std::is_same_v<M, bool Owner::*>) {
          return ImGui::Checkbox(label.c_str(), &(owner.*member));
        } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
          const glm::vec3 srgb = core::linearToSrgb(owner.*member);
          float rgb[3] = {srgb.r, srgb.g, srgb.b};
          // Without the editor's own right-click menu: a right-click resets here as everywhere.
          if (!ImGui::ColorEdit3(shown.c_str(), rgb, ImGuiColorEditFlags_NoOptions)) return false;
          owner.*member = core::srgbToLinear(glm::vec3(rgb[0], rgb[1], rgb[2]));
          return true;
        } else if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
          glm::dvec3& value = owner.*member;
          double v[3] = {value.x, value.y, value.z};
          const double min = f.ui.min, max = f.ui.max;
          if (!ImGui::SliderScalarN(shown.c_str(), ImGuiDataType_Double, v, 3, &min, &max, format.c_str(), flags))
            return false;
          const glm::dvec3 chosen(v[0], v[1], v[2]);
          // An axis must not be the zero vector (the reader refuses it): keep the last one.
          if (key == "axis" && glm::length(chosen) <= 1e-3) return false;
          value = chosen;
          return true;
        } else if constexpr (std::is_same_v<M, core::Choice<Owner>>) {
          int index = member.get(owner);
          std::string items;
          for (std::string_view name : member.names) (items += name) += '\0';
          if (!ImGui::Combo(shown.c_str(), &index, items.c_str())) return false;
          member.set(owner, index);
          return true;
        } else {
          return false;  // no widget for this kind of field
        }
      },
      f.member);
  probe(ui, probed);
  markIfKeyed(ui, valuePath(scope, key), probed);
  // Right-click: back to the default at once, as the pattern sliders do (a default-made owner
  // holds it).
  const bool reset = resetClicked();
  if (reset) {
    static const Owner defaults{};
    std::visit(
        [&]<class M>(const M& member) {
          if constexpr (std::is_same_v<M, core::Choice<Owner>>)
            member.set(owner, member.get(defaults));
          else if constexpr (std::is_member_object_pointer_v<M>)
            owner.*member = defaults.*member;
        },
        f.member);
  }
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
    if (f.help.empty())
      ImGui::SetTooltip("right-click to reset to the default");
    else
      ImGui::SetTooltip("%.*s\nright-click to reset to the default", static_cast<int>(f.help.size()), f.help.data());
  }
  return reportEdit(ui, changed || reset, f.affects);
}

}  // namespace voxflame::app::panels
