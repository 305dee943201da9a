// The Pattern panel: each layer's kind, attractor and parameters, placement and colour, a Julia
// set's sliders, layers added and removed. Changes the scene's layers.
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/attractor.h"
#include "core/color.h"
#include "core/flame/flame.h"
#include "core/scene_schema.h"
#include "panels.h"
#include "widgets.h"

namespace voxflame::app::panels {

// ---------------------------------------------------------------------------------------------
// Panels.

void attractorPicker(Ui& ui, PatternPanelState& pattern, core::PatternLayer& layer, const core::AttractorInfo& info) {
  if (std::exchange(pattern.focusAttractorFilter, false)) takeKeyboard(ui);
  const bool enter = ImGui::InputTextWithHint("##filter", "filter attractors (Ctrl+F)", pattern.attractorFilter,
                                              sizeof pattern.attractorFilter, ImGuiInputTextFlags_EnterReturnsTrue);
  probe(ui, "attractor/filter");
  noteTyped(ui, "attractor filter", pattern.attractorFilter);
  const std::string filter = lowercase(pattern.attractorFilter);
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
    ui.document.edited(core::Affects::Pattern);
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
        pattern.attractorFilter[0] = '\0';
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

void colourEditor(Ui& ui, const std::string& scope, core::ColorSettings& color, bool chaosGame) {
  // ColorMode's order; flam3's colour index only exists for chaos-game layers.
  int mode = static_cast<int>(color.mode);
  const char* modes =
      chaosGame ? "speed\0curvature\0time\0axis\0distance\0index\0" : "speed\0curvature\0time\0axis\0distance\0";
  if (reportEdit(ui, ImGui::Combo("colour by", &mode, modes), core::Affects::Pattern))
    color.mode = static_cast<core::ColorMode>(mode);
  probe(ui, scope + "colour by");
  if (color.mode == core::ColorMode::Time) fieldWidget(ui, scope, color, core::colorFields(), "period");
  if (color.mode == core::ColorMode::Axis) fieldWidget(ui, scope, color, core::colorFields(), "axis");
  fieldWidget(ui, scope, color, core::colorFields(), "scale");

  // Palettes: a named one fills the stops; editing a stop makes the gradient custom.
  const char* current = color.palette.empty() ? "custom gradient" : color.palette.c_str();
  if (ImGui::BeginCombo("palette", current, ImGuiComboFlags_HeightLarge)) {
    // Each choice with its gradient beside its name.
    const float nameWidth = 7.0f * ImGui::GetFontSize();
    for (const core::NamedPalette& palette : core::namedPalettes()) {
      if (ImGui::Selectable(palette.name.c_str(), palette.name == color.palette)) {
        color.palette = palette.name;
        color.gradient = core::paletteStops(palette.name);
        ui.document.edited(core::Affects::Pattern);
      }
      ImGui::SameLine(nameWidth);
      gradientPreview(core::paletteStops(palette.name), std::max(20.0f, ImGui::GetContentRegionAvail().x),
                      ImGui::GetTextLineHeight());
    }
    ImGui::EndCombo();
  }
  probe(ui, scope + "palette");
  gradientPreview(color.gradient, ImGui::CalcItemWidth(), ImGui::GetFrameHeight());
  // A palette of many stops (a flame's 256 colours) shows as its strip; its stops open on demand.
  const bool manyStops = color.gradient.size() > 16;
  const bool stopsOpen = !manyStops || ImGui::TreeNode("stops", "edit the %zu stops", color.gradient.size());
  if (manyStops) probe(ui, scope + "edit stops");
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
    probe(ui, scope + "stop" + std::to_string(s));
    ImGui::SameLine();
    if (color.gradient.size() > 1 && ImGui::SmallButton("x")) remove = static_cast<int>(s);
    ImGui::PopID();
  }
  if (manyStops && stopsOpen) ImGui::TreePop();
  if (remove >= 0) {
    color.gradient.erase(color.gradient.begin() + remove);
    edited = true;
  }
  if (!manyStops && button(ui, scope, "Add stop") && color.gradient.size() < 16) {
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
    ui.document.edited(core::Affects::Pattern);
    color.palette.clear();
    // Stops stay in position order (the preset's order), except while one is being dragged past another.
    if (!ImGui::IsAnyItemActive())
      std::stable_sort(color.gradient.begin(), color.gradient.end(),
                       [](const auto& a, const auto& b) { return a.position < b.position; });
  }
}

void juliaEditor(Ui& ui, const std::string& scope, core::QuaternionJuliaSettings& julia) {
  static constexpr const char* kComponents[] = {"c (1)", "c (i)", "c (j)", "c (k)"};
  for (int i = 0; i < 4; ++i)
    reportEdit(ui, slider(ui, scope, kComponents[i], julia.c[i], -1.5, 1.5, kClamp, "%.4f"), core::Affects::Pattern);
  fieldWidget(ui, scope, julia, core::juliaFields(), "view");
  fieldWidget(ui, scope, julia, core::juliaFields(), "turn_deg");
  if (julia.view == core::QuaternionView::Slice) {
    fieldWidget(ui, scope, julia, core::juliaFields(), "slice_w");
    fieldWidget(ui, scope, julia, core::juliaFields(), "thickness");
  }
}

void attractorEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::PatternLayer& layer) {
  const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
  attractorPicker(ui, pattern, layer, info);
  if (layer.params.size() != info.params.size()) return;  // changed attractor: sliders next frame
  const core::AttractorInfo& current = core::attractorOrThrow(layer.attractor);
  for (std::size_t p = 0; p < current.params.size(); ++p) {
    const core::ParamInfo& param = current.params[p];
    // The slider's range is the catalogue's; Ctrl+click types any value the preset reader allows
    // (clamped to it here: ImGui can only clamp to the slider's range), right-click resets it.
    if (reportEdit(ui,
                   slider(ui, scope, param.name.c_str(), layer.params[p], param.sliderMin, param.sliderMax, 0, "%.4f"),
                   core::Affects::Pattern))
      layer.params[p] = std::isfinite(layer.params[p]) ? std::clamp(layer.params[p], -core::kAttractorParameterLimit,
                                                                    core::kAttractorParameterLimit)
                                                       : param.defaultValue;
    markIfKeyed(ui, valuePath(scope, "params/" + param.name), scope + param.name);
    parameterReset(ui, layer.params[p], param.defaultValue, "Ctrl+click to type, right-click to reset");
  }
  if (current.kind == core::AttractorKind::Flow) {
    int integrator = layer.integrator == core::Integrator::RK4 ? 1 : 0;
    if (reportEdit(ui, ImGui::Combo("integrator", &integrator, "Euler\0Runge-Kutta 4\0"), core::Affects::Pattern))
      layer.integrator = integrator == 1 ? core::Integrator::RK4 : core::Integrator::Euler;
    fieldWidget(ui, scope, layer, core::layerFields(), "step");
  }
  if (reportEdit(ui, button(ui, scope, "Reset parameters"), core::Affects::Pattern)) {
    layer.params = current.defaultParams();
    layer.step = current.defaultStep;
    layer.integrator = current.defaultIntegrator;
  }
}

void layerEditor(Ui& ui, PatternPanelState& pattern, ExplorePanelState& explore, FlatViewState& flat, std::size_t index,
                 bool& removeThis) {
  core::PatternLayer& layer = ui.document.scene.layers[index];
  const std::string scope = "layer" + std::to_string(index) + "/";
  const core::PatternKind kindBefore = layer.kind;
  patternKindChoice(ui, pattern, index, scope, layer);
  if (layer.kind != kindBefore) return;  // the new kind's widgets from the next frame
  switch (layer.kind) {
    case core::PatternKind::Attractor:
      attractorEditor(ui, pattern, scope, layer);
      break;
    case core::PatternKind::Flame:
      ImGui::Checkbox("flat view (as flam3 renders it)", &flat.on);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The flame in 2D at its own framing (the flame file's size, centre, scale, zoom) with\n"
            "flam3's tone: what the flame's author saw. `voxflame render --flat` renders it too.");
      flameEditor(ui, pattern, explore, index, scope, layer.flame);
      break;
    case core::PatternKind::QuaternionJulia:
      juliaEditor(ui, scope, layer.julia);
      break;
  }
  if (ui.document.scene.layers.size() > 1) {
    if (layer.kind == core::PatternKind::Attractor) ImGui::SameLine();  // beside "Reset parameters"
    if (button(ui, scope, "Remove layer")) removeThis = true;
    fieldWidget(ui, scope, layer, core::layerFields(), "weight");
  }
  // Open from the start: the fit decides how much of the mesh the pattern fills.
  if (ImGui::TreeNodeEx("Placement", ImGuiTreeNodeFlags_DefaultOpen)) {
    fieldWidget(ui, scope, layer.transform, core::transformFields(), "scale");
    fieldWidget(ui, scope, layer.transform, core::transformFields(), "fit");
    fieldWidget(ui, scope, layer.transform, core::transformFields(), "rotation_deg");
    fieldWidget(ui, scope, layer.transform, core::transformFields(), "offset");
    const double minDeg = -180.0, maxDeg = 180.0;
    // Copies: the same pattern again, turned; one set of parameters moves them all.
    std::vector<glm::dvec3>& copies = layer.transform.copies;
    std::size_t removeCopy = copies.size();
    for (std::size_t c = 0; c < copies.size(); ++c) {
      ImGui::PushID(static_cast<int>(c));
      double angles[3] = {copies[c].x, copies[c].y, copies[c].z};
      const std::string label = "copy " + std::to_string(c + 1);
      if (reportEdit(
              ui,
              ImGui::SliderScalarN(label.c_str(), ImGuiDataType_Double, angles, 3, &minDeg, &maxDeg, "%.0f°", kClamp),
              core::Affects::Pattern))
        copies[c] = glm::dvec3(angles[0], angles[1], angles[2]);
      probe(ui, scope + label);
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) removeCopy = c;
      probe(ui, scope + label + " remove");
      ImGui::PopID();
    }
    if (reportEdit(ui, removeCopy < copies.size(), core::Affects::Pattern))
      copies.erase(copies.begin() + static_cast<std::ptrdiff_t>(removeCopy));
    if (copies.size() < core::kMaxLayerCopies &&
        reportEdit(ui, button(ui, scope, "Add copy"), core::Affects::Pattern)) {
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
    colourEditor(ui, scope, layer.color, layer.isChaosGame());
    ImGui::TreePop();
  }
}

void patternWindow(Ui& ui, PatternPanelState& pattern, ExplorePanelState& explore, FlatViewState& flat,
                   Services& services, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  // Docked at the left, full height above the status line; only its width is the user's.
  const float height = io.DisplaySize.y - statusBarHeight(scale);
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(350 * scale, height), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(260 * scale, height), ImVec2(0.4f * io.DisplaySize.x, height));
  // Side panels stay behind the notice and popups even when clicked.
  ImGui::Begin("Pattern", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove);
  ui.frame.layout.left = ImGui::IsWindowCollapsed() ? 0.0f : ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  ImGui::PushItemWidth(-110 * scale);
  std::size_t removeIndex = ui.document.scene.layers.size();
  for (std::size_t li = 0; li < ui.document.scene.layers.size(); ++li) {
    const core::PatternLayer& shown = ui.document.scene.layers[li];
    const std::string what = shown.kind == core::PatternKind::Attractor ? core::attractorOrThrow(shown.attractor).name
                             : shown.kind == core::PatternKind::Flame
                                 ? "flame (" + std::to_string(shown.flame.xforms.size()) + " transforms)"
                                 : std::string("quaternion Julia");
    ImGui::PushID(static_cast<int>(li));
    const std::string header = "Layer " + std::to_string(li + 1) + ": " + what + "###layer";
    if (ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      bool remove = false;
      layerEditor(ui, pattern, explore, flat, li, remove);
      if (remove) removeIndex = li;
    }
    ImGui::PopID();
  }
  if (reportEdit(ui, removeIndex < ui.document.scene.layers.size(), core::Affects::Pattern))
    ui.document.scene.layers.erase(ui.document.scene.layers.begin() + static_cast<std::ptrdiff_t>(removeIndex));
  if (ui.document.scene.layers.size() < 8 && reportEdit(ui, button(ui, "", "Add layer"), core::Affects::Pattern)) {
    // A second pattern starts as a different attractor at half weight, coloured apart.
    core::PatternLayer layer;
    layer.attractor = ui.document.scene.layers.front().attractor == "aizawa" ? "thomas" : "aizawa";
    const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
    layer.params = info.defaultParams();
    layer.step = info.defaultStep;
    layer.integrator = info.defaultIntegrator;
    layer.weight = 0.5;
    layer.color.palette = core::namedPalettes().back().name;
    layer.color.gradient = core::paletteStops(layer.color.palette);
    ui.document.scene.layers.push_back(layer);
  }

  if (ImGui::CollapsingHeader("Explore", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (button(ui, "", "Search (F3)")) startSearch(ui.document, explore, services, 0.1, true);
    if (ImGui::IsItemHovered() && !ui.document.scene.layers.empty() && ui.document.scene.layers.front().isChaosGame())
      ImGui::SetTooltip("a new random pattern of this kind that fills its box");
    ImGui::SameLine();
    if (button(ui, "", "Mutate")) startSearch(ui.document, explore, services, explore.mutateStrength, false);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    slider(ui, "", "##strength", explore.mutateStrength, 0.01, 1.0, ImGuiSliderFlags_Logarithmic, "strength %.2f");
    ImGui::BeginDisabled(explore.visited.empty() || explore.visitedIndex == 0);
    if (button(ui, "", "< Back")) goVisited(ui.document, explore, -1);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(explore.visited.empty() || explore.visitedIndex + 1 >= explore.visited.size());
    if (button(ui, "", "Forward >")) goVisited(ui.document, explore, +1);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (explore.visited.empty())
      dimText("no history yet");
    else
      dimText("%zu of %zu (Alt+Left/Right)", explore.visitedIndex + 1, explore.visited.size());
    if (services.search.busy()) {
      if (services.searchTried && services.searchStrength)
        dimText("searching at strength %.2g: %d tried", services.searchStrength->load(), services.searchTried->load());
      else
        dimText("searching…");
      if (button(ui, "explore/", "Cancel search")) {
        services.search.cancel();
        explore.searchMessage =
            services.searchTried ? "search cancelled after " + std::to_string(services.searchTried->load()) + " tries"
                                 : std::string("search cancelled");
      }
    } else if (!explore.searchMessage.empty())
      ImGui::TextWrapped("%s", explore.searchMessage.c_str());
    // The message itself is the notice's, at the top of the view: one message, said once.
    if (!ui.frame.session.escapeNote.empty()) {
      if (button(ui, "", "Find a nearby one")) startSearch(ui.document, explore, services, 0.1, false);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("a bounded pattern close to this one (Mutate at strength 0.1)");
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace voxflame::app::panels
