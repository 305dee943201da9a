// The Pattern panel: each layer's kind, attractor and parameters, placement and colour, a Julia
// set's sliders, layers added and removed. Changes the scene's layers.
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

// ---------------------------------------------------------------------------------------------
// Panels.

void attractorPicker(ExplorerState& state, core::PatternLayer& layer, const core::AttractorInfo& info) {
  if (std::exchange(state.panels.pattern.focusAttractorFilter, false)) takeKeyboard(state);
  const bool enter =
      ImGui::InputTextWithHint("##filter", "filter attractors (Ctrl+F)", state.panels.pattern.attractorFilter,
                               sizeof state.panels.pattern.attractorFilter, ImGuiInputTextFlags_EnterReturnsTrue);
  probe(state, "attractor/filter");
  noteTyped(state, "attractor filter", state.panels.pattern.attractorFilter);
  const std::string filter = lowercase(state.panels.pattern.attractorFilter);
  // Every word of the filter, anywhere in the id or the name: "sprott quadratic" finds
  // sprott_quadratic, "Sprott's 3D quadratic map".
  std::vector<std::string> words;
  {
    std::istringstream split(filter);
    for (std::string word; split >> word;) words.push_back(word);
  }
  auto matches = [&](const core::AttractorInfo& candidate) {
    std::string haystack = lowercase(candidate.id + " " + candidate.name);
    std::replace(haystack.begin(), haystack.end(), '_', ' ');
    return std::all_of(words.begin(), words.end(),
                       [&](const std::string& word) { return haystack.find(word) != std::string::npos; });
  };
  auto choose = [&](const core::AttractorInfo& candidate) {
    if (candidate.id == layer.attractor) return;
    layer.attractor = candidate.id;
    layer.params = candidate.defaultParams();
    layer.step = candidate.defaultStep;
    layer.integrator = candidate.defaultIntegrator;
    state.document.edited(core::Affects::Pattern);
  };
  // Enter takes the first match, so typing a name and Enter is enough.
  if (!filter.empty()) {
    const auto& catalogue = core::attractorCatalogue();
    const auto first = std::find_if(catalogue.begin(), catalogue.end(), matches);
    if (first == catalogue.end()) {
      dimText("no attractor matches");
    } else {
      dimText("Enter: %s", first->name.c_str());
      if (enter) {
        choose(*first);
        state.panels.pattern.attractorFilter[0] = '\0';
      }
    }
  }
  if (!ImGui::BeginCombo("attractor", info.name.c_str())) {
    if (ImGui::IsItemHovered() && !info.citation.empty()) ImGui::SetTooltip("%s", info.citation.c_str());
    return;
  }
  for (const core::AttractorInfo& candidate : core::attractorCatalogue()) {
    if (!matches(candidate)) continue;
    if (ImGui::Selectable(candidate.name.c_str(), candidate.id == layer.attractor)) choose(candidate);
  }
  ImGui::EndCombo();
}

void gradientPreview(const std::vector<core::GradientStop>& stops, float width, float height) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  if (!stops.empty()) {
    const core::Gradient gradient(stops);
    constexpr int kSegments = 48;
    for (int i = 0; i < kSegments; ++i) {
      const float t0 = static_cast<float>(i) / kSegments, t1 = static_cast<float>(i + 1) / kSegments;
      auto color = [&](float t) {
        const glm::vec3 srgb = core::linearToSrgb(gradient.at(t));
        return ImGui::ColorConvertFloat4ToU32(ImVec4(srgb.r, srgb.g, srgb.b, 1.0f));
      };
      const ImU32 left = color(t0), right = color(t1);
      draw->AddRectFilledMultiColor(ImVec2(origin.x + t0 * width, origin.y),
                                    ImVec2(origin.x + t1 * width, origin.y + height), left, right, right, left);
    }
  }
  ImGui::Dummy(ImVec2(width, height));
}

void colourEditor(ExplorerState& state, const std::string& scope, core::ColorSettings& color, bool chaosGame) {
  // ColorMode's order; flam3's colour index only exists for chaos-game layers.
  int mode = static_cast<int>(color.mode);
  const char* modes =
      chaosGame ? "speed\0curvature\0time\0axis\0distance\0index\0" : "speed\0curvature\0time\0axis\0distance\0";
  if (reportEdit(state, ImGui::Combo("colour by", &mode, modes), core::Affects::Pattern))
    color.mode = static_cast<core::ColorMode>(mode);
  probe(state, scope + "colour by");
  if (color.mode == core::ColorMode::Time) fieldWidget(state, scope, color, core::colorFields(), "period");
  if (color.mode == core::ColorMode::Axis) fieldWidget(state, scope, color, core::colorFields(), "axis");
  fieldWidget(state, scope, color, core::colorFields(), "scale");

  // Palettes: a named one fills the stops; editing a stop makes the gradient custom.
  const char* current = color.palette.empty() ? "custom gradient" : color.palette.c_str();
  if (ImGui::BeginCombo("palette", current, ImGuiComboFlags_HeightLarge)) {
    // Each choice with its gradient beside its name.
    const float nameWidth = 7.0f * ImGui::GetFontSize();
    for (const core::NamedPalette& palette : core::namedPalettes()) {
      if (ImGui::Selectable(palette.name.c_str(), palette.name == color.palette)) {
        color.palette = palette.name;
        color.gradient = core::paletteStops(palette.name);
        state.document.edited(core::Affects::Pattern);
      }
      ImGui::SameLine(nameWidth);
      gradientPreview(core::paletteStops(palette.name), std::max(20.0f, ImGui::GetContentRegionAvail().x),
                      ImGui::GetTextLineHeight());
    }
    ImGui::EndCombo();
  }
  probe(state, scope + "palette");
  gradientPreview(color.gradient, ImGui::CalcItemWidth(), ImGui::GetFrameHeight());
  // A palette of many stops (a flame's 256 colours) shows as its strip; its stops open on demand.
  const bool manyStops = color.gradient.size() > 16;
  const bool stopsOpen = !manyStops || ImGui::TreeNode("stops", "edit the %zu stops", color.gradient.size());
  if (manyStops) probe(state, scope + "edit stops");
  bool edited = false;
  int remove = -1;
  for (std::size_t s = 0; stopsOpen && s < color.gradient.size(); ++s) {
    core::GradientStop& stop = color.gradient[s];
    ImGui::PushID(static_cast<int>(s));
    const glm::vec3 srgb = core::linearToSrgb(stop.color);
    float rgb[3] = {srgb.r, srgb.g, srgb.b};
    if (ImGui::ColorEdit3("##colour", rgb, ImGuiColorEditFlags_NoInputs)) {
      stop.color = core::srgbToLinear(glm::vec3(rgb[0], rgb[1], rgb[2]));
      edited = true;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemSpacing.x);
    if (ImGui::SliderFloat("##position", &stop.position, 0.0f, 1.0f, "stop at %.2f")) edited = true;
    probe(state, scope + "stop" + std::to_string(s));
    ImGui::SameLine();
    if (color.gradient.size() > 1 && ImGui::SmallButton("x")) remove = static_cast<int>(s);
    ImGui::PopID();
  }
  if (manyStops && stopsOpen) ImGui::TreePop();
  if (remove >= 0) {
    color.gradient.erase(color.gradient.begin() + remove);
    edited = true;
  }
  if (!manyStops && button(state, scope, "Add stop") && color.gradient.size() < 16) {
    // A new stop goes into the widest gap, with the colour the gradient already has there.
    std::vector<core::GradientStop> sorted = color.gradient;
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.position < b.position; });
    float bestGap = -1.0f, at = 0.5f;
    float previous = 0.0f;
    for (std::size_t s = 0; s <= sorted.size(); ++s) {
      const float next = s < sorted.size() ? sorted[s].position : 1.0f;
      if (next - previous > bestGap) bestGap = next - previous, at = 0.5f * (previous + next);
      previous = next;
    }
    const glm::vec3 colour = sorted.empty() ? glm::vec3(1.0f) : core::Gradient(sorted).at(at);
    color.gradient.push_back({at, colour});
    edited = true;
  }
  if (edited) {
    state.document.edited(core::Affects::Pattern);
    color.palette.clear();
    // Stops stay in position order (the preset's order), except while one is being dragged past another.
    if (!ImGui::IsAnyItemActive())
      std::stable_sort(color.gradient.begin(), color.gradient.end(),
                       [](const auto& a, const auto& b) { return a.position < b.position; });
  }
}

void juliaEditor(ExplorerState& state, const std::string& scope, core::QuaternionJuliaSettings& julia) {
  static constexpr const char* kComponents[] = {"c (1)", "c (i)", "c (j)", "c (k)"};
  for (int i = 0; i < 4; ++i)
    reportEdit(state, slider(state, scope, kComponents[i], julia.c[i], -1.5, 1.5, kClamp, "%.4f"),
               core::Affects::Pattern);
  fieldWidget(state, scope, julia, core::juliaFields(), "view");
  fieldWidget(state, scope, julia, core::juliaFields(), "turn_deg");
  if (julia.view == core::QuaternionView::Slice) {
    fieldWidget(state, scope, julia, core::juliaFields(), "slice_w");
    fieldWidget(state, scope, julia, core::juliaFields(), "thickness");
  }
}

void attractorEditor(ExplorerState& state, const std::string& scope, core::PatternLayer& layer) {
  const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
  attractorPicker(state, layer, info);
  if (layer.params.size() != info.params.size()) return;  // changed attractor: sliders next frame
  const core::AttractorInfo& current = core::attractorOrThrow(layer.attractor);
  for (std::size_t p = 0; p < current.params.size(); ++p) {
    const core::ParamInfo& param = current.params[p];
    // The slider's range is the catalogue's; Ctrl+click types any value the preset reader allows
    // (clamped to it here: ImGui can only clamp to the slider's range), right-click resets it.
    if (reportEdit(
            state,
            slider(state, scope, param.name.c_str(), layer.params[p], param.sliderMin, param.sliderMax, 0, "%.4f"),
            core::Affects::Pattern))
      layer.params[p] = std::isfinite(layer.params[p]) ? std::clamp(layer.params[p], -core::kAttractorParameterLimit,
                                                                    core::kAttractorParameterLimit)
                                                       : param.defaultValue;
    markIfKeyed(state, valuePath(scope, "params/" + param.name), scope + param.name);
    if (ImGui::BeginPopupContextItem()) {
      if (reportEdit(state, ImGui::Selectable("Reset to default"), core::Affects::Pattern))
        layer.params[p] = param.defaultValue;
      ImGui::EndPopup();
    }
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
      ImGui::SetTooltip("default %.4g — Ctrl+click to type, right-click to reset", param.defaultValue);
  }
  if (current.kind == core::AttractorKind::Flow) {
    int integrator = layer.integrator == core::Integrator::RK4 ? 1 : 0;
    if (reportEdit(state, ImGui::Combo("integrator", &integrator, "Euler\0Runge-Kutta 4\0"), core::Affects::Pattern))
      layer.integrator = integrator == 1 ? core::Integrator::RK4 : core::Integrator::Euler;
    fieldWidget(state, scope, layer, core::layerFields(), "step");
  }
  if (reportEdit(state, button(state, scope, "Reset parameters"), core::Affects::Pattern)) {
    layer.params = current.defaultParams();
    layer.step = current.defaultStep;
    layer.integrator = current.defaultIntegrator;
  }
}

void layerEditor(ExplorerState& state, std::size_t index, bool& removeThis) {
  core::PatternLayer& layer = state.document.scene.layers[index];
  const std::string scope = "layer" + std::to_string(index) + "/";
  const core::PatternKind kindBefore = layer.kind;
  patternKindChoice(state, index, scope, layer);
  if (layer.kind != kindBefore) return;  // the new kind's widgets from the next frame
  switch (layer.kind) {
    case core::PatternKind::Attractor:
      attractorEditor(state, scope, layer);
      break;
    case core::PatternKind::Flame:
      ImGui::Checkbox("flat view (as flam3 renders it)", &state.panels.flat.on);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The flame in 2D at its own framing (the flame file's size, centre, scale, zoom) with\n"
            "flam3's tone: what the flame's author saw. `voxflame render --flat` renders it too.");
      flameEditor(state, index, scope, layer.flame);
      break;
    case core::PatternKind::QuaternionJulia:
      juliaEditor(state, scope, layer.julia);
      break;
  }
  if (state.document.scene.layers.size() > 1) {
    if (layer.kind == core::PatternKind::Attractor) ImGui::SameLine();  // beside "Reset parameters"
    if (button(state, scope, "Remove layer")) removeThis = true;
    fieldWidget(state, scope, layer, core::layerFields(), "weight");
  }
  // Open from the start: the fit decides how much of the mesh the pattern fills.
  if (ImGui::TreeNodeEx("Placement", ImGuiTreeNodeFlags_DefaultOpen)) {
    fieldWidget(state, scope, layer.transform, core::transformFields(), "scale");
    fieldWidget(state, scope, layer.transform, core::transformFields(), "fit");
    fieldWidget(state, scope, layer.transform, core::transformFields(), "rotation_deg");
    fieldWidget(state, scope, layer.transform, core::transformFields(), "offset");
    const double minDeg = -180.0, maxDeg = 180.0;
    // Copies: the same pattern again, turned; one set of parameters moves them all.
    std::vector<glm::dvec3>& copies = layer.transform.copies;
    std::size_t removeCopy = copies.size();
    for (std::size_t c = 0; c < copies.size(); ++c) {
      ImGui::PushID(static_cast<int>(c));
      double angles[3] = {copies[c].x, copies[c].y, copies[c].z};
      const std::string label = "copy " + std::to_string(c + 1);
      if (reportEdit(
              state,
              ImGui::SliderScalarN(label.c_str(), ImGuiDataType_Double, angles, 3, &minDeg, &maxDeg, "%.0f°", kClamp),
              core::Affects::Pattern))
        copies[c] = glm::dvec3(angles[0], angles[1], angles[2]);
      probe(state, scope + label);
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) removeCopy = c;
      probe(state, scope + label + " remove");
      ImGui::PopID();
    }
    if (reportEdit(state, removeCopy < copies.size(), core::Affects::Pattern))
      copies.erase(copies.begin() + static_cast<std::ptrdiff_t>(removeCopy));
    if (copies.size() < core::kMaxLayerCopies &&
        reportEdit(state, button(state, scope, "Add copy"), core::Affects::Pattern)) {
      // Each new copy turns a quarter further about the next axis, so it lands somewhere new.
      const auto n = static_cast<int>(copies.size());
      glm::dvec3 angles(0.0);
      angles[n % 3] = 90.0 * (1 + n / 3);
      copies.push_back(angles);
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the same pattern again, turned: fills a mesh that one copy leaves half empty");
    ImGui::TreePop();
  }
  if (ImGui::TreeNodeEx("Colour", ImGuiTreeNodeFlags_DefaultOpen)) {
    colourEditor(state, scope, layer.color, layer.isChaosGame());
    ImGui::TreePop();
  }
}

void patternWindow(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  // Docked at the left, full height above the status line; only its width is the user's.
  const float height = io.DisplaySize.y - statusBarHeight(scale);
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(350 * scale, height), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(260 * scale, height), ImVec2(0.4f * io.DisplaySize.x, height));
  // Side panels stay behind the notice and popups even when clicked.
  ImGui::Begin("Pattern", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove);
  state.frame.layout.left = ImGui::IsWindowCollapsed() ? 0.0f : ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  ImGui::PushItemWidth(-110 * scale);
  std::size_t removeIndex = state.document.scene.layers.size();
  for (std::size_t li = 0; li < state.document.scene.layers.size(); ++li) {
    const core::PatternLayer& shown = state.document.scene.layers[li];
    const std::string what = shown.kind == core::PatternKind::Attractor ? core::attractorOrThrow(shown.attractor).name
                             : shown.kind == core::PatternKind::Flame
                                 ? "flame (" + std::to_string(shown.flame.xforms.size()) + " transforms)"
                                 : std::string("quaternion Julia");
    ImGui::PushID(static_cast<int>(li));
    const std::string header = "Layer " + std::to_string(li + 1) + ": " + what + "###layer";
    if (ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      bool remove = false;
      layerEditor(state, li, remove);
      if (remove) removeIndex = li;
    }
    ImGui::PopID();
  }
  if (reportEdit(state, removeIndex < state.document.scene.layers.size(), core::Affects::Pattern))
    state.document.scene.layers.erase(state.document.scene.layers.begin() + static_cast<std::ptrdiff_t>(removeIndex));
  if (state.document.scene.layers.size() < 8 &&
      reportEdit(state, button(state, "", "Add layer"), core::Affects::Pattern)) {
    // A second pattern starts as a different attractor at half weight, coloured apart.
    core::PatternLayer layer;
    layer.attractor = state.document.scene.layers.front().attractor == "aizawa" ? "thomas" : "aizawa";
    const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
    layer.params = info.defaultParams();
    layer.step = info.defaultStep;
    layer.integrator = info.defaultIntegrator;
    layer.weight = 0.5;
    layer.color.palette = core::namedPalettes().back().name;
    layer.color.gradient = core::paletteStops(layer.color.palette);
    state.document.scene.layers.push_back(layer);
  }

  if (ImGui::CollapsingHeader("Explore", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (button(state, "", "Search (F3)")) startSearch(state, 0.1, true);
    if (ImGui::IsItemHovered() && !state.document.scene.layers.empty() &&
        state.document.scene.layers.front().isChaosGame())
      ImGui::SetTooltip("a new random pattern of this kind that fills its box");
    ImGui::SameLine();
    if (button(state, "", "Mutate")) startSearch(state, state.panels.explore.mutateStrength, false);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    slider(state, "", "##strength", state.panels.explore.mutateStrength, 0.01, 1.0, ImGuiSliderFlags_Logarithmic,
           "strength %.2f");
    ImGui::BeginDisabled(state.panels.explore.visited.empty() || state.panels.explore.visitedIndex == 0);
    if (button(state, "", "< Back")) goVisited(state, -1);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(state.panels.explore.visited.empty() ||
                         state.panels.explore.visitedIndex + 1 >= state.panels.explore.visited.size());
    if (button(state, "", "Forward >")) goVisited(state, +1);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (state.panels.explore.visited.empty())
      dimText("no history yet");
    else
      dimText("%zu of %zu (Alt+Left/Right)", state.panels.explore.visitedIndex + 1,
              state.panels.explore.visited.size());
    if (state.services.search.busy()) {
      if (state.services.searchTried && state.services.searchStrength)
        dimText("searching at strength %.2g: %d tried", state.services.searchStrength->load(),
                state.services.searchTried->load());
      else
        dimText("searching…");
      if (button(state, "explore/", "Cancel search")) {
        state.services.search.cancel();
        state.panels.explore.searchMessage =
            state.services.searchTried
                ? "search cancelled after " + std::to_string(state.services.searchTried->load()) + " tries"
                : std::string("search cancelled");
      }
    } else if (!state.panels.explore.searchMessage.empty())
      ImGui::TextWrapped("%s", state.panels.explore.searchMessage.c_str());
    // The message itself is the notice's, at the top of the view: one message, said once.
    if (!state.frame.session.escapeNote.empty()) {
      if (button(state, "", "Find a nearby one")) startSearch(state, 0.1, false);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("a bounded pattern close to this one (Mutate at strength 0.1)");
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace voxflame::app::panels
