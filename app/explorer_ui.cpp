#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/attractor.h"
#include "core/camera.h"
#include "core/color.h"
#include "core/error.h"
#include "core/flame_xml.h"
#include "core/grid.h"
#include "core/keyframes.h"
#include "commands.h"
#include "pipeline.h"

namespace voxflame::app {

namespace {

// The window backend fills io.KeysDown by GLFW key code; letters are their ASCII capitals.
constexpr int kKeyRight = 262, kKeyLeft = 263, kKeyF3 = 292;
constexpr int kKeyLeftAlt = 342, kKeyRightAlt = 346;

const ImVec4 kErrorColor(1.0f, 0.45f, 0.35f, 1.0f);
const ImVec4 kDimColor(0.62f, 0.65f, 0.72f, 1.0f);

void probe(ExplorerState& state, const std::string& name) {
  if (!state.probe) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state.probe->items[name] = UiProbe::Rect{min.x, min.y, max.x, max.y};
}

bool slider(ExplorerState& state, const std::string& scope, const char* label, double& value, double min, double max,
            ImGuiSliderFlags flags = 0, const char* format = "%.3f") {
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format, flags);
  probe(state, scope + label);
  return changed;
}

bool button(ExplorerState& state, const std::string& scope, const char* label) {
  const bool pressed = ImGui::Button(label);
  probe(state, scope + label);
  return pressed;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool keyDown(int key) {
  return key >= 0 && key < IM_ARRAYSIZE(ImGui::GetIO().KeysDown) && ImGui::GetIO().KeysDown[key];
}

core::OrbitSpec layerSpec(const core::PatternLayer& layer) {
  core::OrbitSpec spec = core::defaultOrbitSpec(core::attractorOrThrow(layer.attractor));
  spec.params = layer.params;
  spec.integrator = layer.integrator;
  spec.step = layer.step;
  return spec;
}

// ---------------------------------------------------------------------------------------------
// Background analysis, search and the search history.

std::string analysisKey(const core::PatternLayer& layer) {
  std::string key =
      layer.attractor + "/" + std::string(core::toString(layer.integrator)) + "/" + std::to_string(layer.step);
  for (double p : layer.params) {
    key += '/';
    key += std::to_string(p);
  }
  return key;
}

bool ready(const auto& future) {
  return future.valid() && future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

// Keeps the Lyapunov line in step with layer 0; one analysis at a time, never waited for.
void updateAnalysis(ExplorerState& state) {
  if (ready(state.analysis)) {
    try {
      const core::OrbitAnalysis result = state.analysis.get();
      char text[160];
      std::snprintf(text, sizeof text, "λ %.3f  %.3f  %.3f  (%s)", result.lyapunov[0], result.lyapunov[1],
                    result.lyapunov[2], std::string(core::toString(result.verdict)).c_str());
      state.lyapunovText = text;
    } catch (const core::Error& e) {
      state.lyapunovText = e.what();
    }
  }
  if (state.analysis.valid() || state.scene.layers.empty()) return;
  const std::string key = analysisKey(state.scene.layers.front());
  if (key == state.analysedKey) return;
  state.analysedKey = key;
  try {
    const core::OrbitSpec spec = layerSpec(state.scene.layers.front());
    core::LyapunovOptions options;
    options.steps = 20'000;
    state.analysis = std::async(std::launch::async, [spec, options] { return core::analyseOrbit(spec, options); });
  } catch (const core::Error& e) {
    state.lyapunovText = e.what();
  }
}

// The part of a layer that Search changes and the history restores; colour and placement stay.
void applyVisited(core::PatternLayer& layer, const core::PatternLayer& visited) {
  layer.attractor = visited.attractor;
  layer.params = visited.params;
  layer.integrator = visited.integrator;
  layer.step = visited.step;
}

void startSearch(ExplorerState& state, double strength) {
  if (state.search.valid() || state.scene.layers.empty()) return;  // one at a time
  try {
    const core::OrbitSpec spec = layerSpec(state.scene.layers.front());
    core::SearchOptions options;
    options.seed = state.searchSeed++;
    options.count = 1;
    options.strength = strength;
    state.searchMessage = "searching…";
    state.search = std::async(std::launch::async, [spec, options] { return core::searchChaos(spec, options); });
  } catch (const core::Error& e) {
    state.searchMessage = e.what();
  }
}

void collectSearch(ExplorerState& state) {
  if (!ready(state.search)) return;
  try {
    const auto results = state.search.get();
    if (results.empty()) {
      state.searchMessage = "no chaotic set found nearby; try a larger strength";
      return;
    }
    core::PatternLayer& layer = state.scene.layers.front();
    // The history keeps where the search started from, then each find; a find after going back
    // drops the forward part, as in a browser.
    if (state.visited.empty()) state.visited.push_back(layer);
    state.visited.resize(std::min(state.visited.size(), state.visitedIndex + 1));
    layer.params = results.front().params;
    state.visited.push_back(layer);
    state.visitedIndex = state.visited.size() - 1;
    char text[96];
    std::snprintf(text, sizeof text, "found: largest Lyapunov exponent %.3f", results.front().analysis.lyapunov[0]);
    state.searchMessage = text;
  } catch (const core::Error& e) {
    state.searchMessage = e.what();
  }
}

void goVisited(ExplorerState& state, int direction) {
  if (state.visited.empty() || state.scene.layers.empty()) return;
  const auto target = static_cast<long long>(state.visitedIndex) + direction;
  if (target < 0 || target >= static_cast<long long>(state.visited.size())) return;
  state.visitedIndex = static_cast<std::size_t>(target);
  applyVisited(state.scene.layers.front(), state.visited[state.visitedIndex]);
}

// ---------------------------------------------------------------------------------------------
// Input: undo/redo, camera, shortcuts.

// Ctrl+Z undoes, Ctrl+Shift+Z (or Ctrl+Y) redoes; an edit is recorded once it settles, so a
// whole slider drag or camera drag is one step.
void handleHistory(ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool z = ImGui::IsKeyPressed('Z', false), y = ImGui::IsKeyPressed('Y', false);
  if (!io.WantTextInput && io.KeyCtrl && (z || y)) {
    const bool redo = io.KeyShift || y;
    if (auto scene = redo ? state.history->redo() : state.history->undo()) {
      state.scene = *scene;
      state.keyBase = *scene;
    }
    return;
  }
  const bool mouseHeld = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                         ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (!mouseHeld && !ImGui::IsAnyItemActive()) state.history->record(state.scene);
}

// Left-drag orbits, right- or middle-drag pans, the wheel zooms; W/A/S/D/Q/E fly. Input that
// starts over a panel belongs to the panel.
void handleCamera(ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  core::CameraSettings& camera = state.scene.camera;
  const bool overUi = io.WantCaptureMouse;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !overUi) state.orbiting = true;
  if ((ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) && !overUi)
    state.panning = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) state.orbiting = false;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right) && !ImGui::IsMouseDown(ImGuiMouseButton_Middle))
    state.panning = false;
  const ImVec2 delta = io.MouseDelta;
  const bool moved = std::isfinite(delta.x) && std::isfinite(delta.y) && (delta.x != 0.0f || delta.y != 0.0f);
  const core::CameraFrame frame = core::orbitCamera(camera, core::Box{{-1, -1, -1}, {1, 1, 1}}, 1.0);
  if (state.orbiting && moved) {
    camera.azimuthDeg = std::remainder(camera.azimuthDeg - 0.3 * delta.x, 360.0);
    camera.elevationDeg = std::clamp(camera.elevationDeg + 0.3 * delta.y, -90.0, 90.0);
  }
  if (state.panning && moved) {
    // The target moves with the pointer: a screen's height of drag moves the view by about
    // what is visible at the target's distance.
    const double perPixel =
        2.0 * camera.distance * std::tan(0.5 * glm::radians(camera.fovDeg)) / std::max(1.0f, io.DisplaySize.y);
    camera.target += perPixel * (-static_cast<double>(delta.x) * frame.right + static_cast<double>(delta.y) * frame.up);
  }
  if (!overUi && io.MouseWheel != 0.0f)
    camera.distance = std::clamp(camera.distance * std::pow(0.9, io.MouseWheel), 0.2, 20.0);

  // Free flight: W/S move along the view, A/D sideways, Q/E down and up; the orbit target moves
  // with the eye, so the camera turns about itself when dragged afterwards.
  if (io.WantCaptureKeyboard || io.KeyCtrl) return;
  const double speed = 1.2 * camera.distance * std::min(0.1f, io.DeltaTime);
  auto held = [](int key) { return keyDown(key) ? 1.0 : 0.0; };
  const glm::dvec3 move = (held('W') - held('S')) * frame.forward + (held('D') - held('A')) * frame.right +
                          (held('E') - held('Q')) * frame.up;
  camera.target += speed * move;
}

void handleShortcuts(ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.KeyCtrl && ImGui::IsKeyPressed('Q', false)) state.requests.quit = true;
  if (io.WantTextInput) return;
  if (ImGui::IsKeyPressed(kKeyF3, false)) startSearch(state, 0.1);
  const bool alt = io.KeyAlt || keyDown(kKeyLeftAlt) || keyDown(kKeyRightAlt);
  if (alt && ImGui::IsKeyPressed(kKeyLeft, false)) goVisited(state, -1);
  if (alt && ImGui::IsKeyPressed(kKeyRight, false)) goVisited(state, +1);
}

// ---------------------------------------------------------------------------------------------
// Panels.

void attractorPicker(ExplorerState& state, core::PatternLayer& layer, const core::AttractorInfo& info) {
  ImGui::InputTextWithHint("##filter", "filter attractors", state.attractorFilter, sizeof state.attractorFilter);
  if (!ImGui::BeginCombo("attractor", info.name.c_str())) {
    if (ImGui::IsItemHovered() && !info.citation.empty()) ImGui::SetTooltip("%s", info.citation.c_str());
    return;
  }
  const std::string filter = lowercase(state.attractorFilter);
  for (const core::AttractorInfo& candidate : core::attractorCatalogue()) {
    if (!filter.empty() && lowercase(candidate.id + " " + candidate.name).find(filter) == std::string::npos) continue;
    if (ImGui::Selectable(candidate.name.c_str(), candidate.id == layer.attractor) && candidate.id != layer.attractor) {
      layer.attractor = candidate.id;
      layer.params = candidate.defaultParams();
      layer.step = candidate.defaultStep;
      layer.integrator = candidate.defaultIntegrator;
    }
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

void colourEditor(ExplorerState& state, const std::string& scope, core::ColorSettings& color) {
  int mode = static_cast<int>(color.mode);
  if (ImGui::Combo("colour by", &mode, "speed\0curvature\0time\0axis\0distance\0"))
    color.mode = static_cast<core::ColorMode>(mode);
  probe(state, scope + "colour by");
  if (color.mode == core::ColorMode::Time)
    slider(state, scope, "period (steps)", color.period, 10.0, 100000.0, ImGuiSliderFlags_Logarithmic, "%.0f");
  if (color.mode == core::ColorMode::Axis) {
    double axis[3] = {color.axis.x, color.axis.y, color.axis.z};
    const double min = -1.0, max = 1.0;
    if (ImGui::SliderScalarN("axis", ImGuiDataType_Double, axis, 3, &min, &max, "%.2f")) {
      const glm::dvec3 chosen(axis[0], axis[1], axis[2]);
      if (glm::length(chosen) > 1e-6) color.axis = chosen;
    }
  }
  slider(state, scope, "colour scale", color.scale, 0.05, 20.0, ImGuiSliderFlags_Logarithmic);

  // Palettes: a named one fills the stops; editing a stop makes the gradient custom.
  const char* current = color.palette.empty() ? "custom gradient" : color.palette.c_str();
  if (ImGui::BeginCombo("palette", current)) {
    for (const core::NamedPalette& palette : core::namedPalettes())
      if (ImGui::Selectable(palette.name.c_str(), palette.name == color.palette)) {
        color.palette = palette.name;
        color.gradient = core::paletteStops(palette.name);
      }
    ImGui::EndCombo();
  }
  probe(state, scope + "palette");
  gradientPreview(color.gradient, ImGui::CalcItemWidth(), ImGui::GetFrameHeight());
  bool edited = false;
  int remove = -1;
  for (std::size_t s = 0; s < color.gradient.size(); ++s) {
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
  if (remove >= 0) {
    color.gradient.erase(color.gradient.begin() + remove);
    edited = true;
  }
  if (button(state, scope, "Add stop") && color.gradient.size() < 16) {
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
    color.palette.clear();
    // Stops stay in position order (the preset's order), except while one is being dragged past another.
    if (!ImGui::IsAnyItemActive())
      std::stable_sort(color.gradient.begin(), color.gradient.end(),
                       [](const auto& a, const auto& b) { return a.position < b.position; });
  }
}

void layerEditor(ExplorerState& state, std::size_t index, bool& removeThis) {
  core::PatternLayer& layer = state.scene.layers[index];
  const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
  const std::string scope = "layer" + std::to_string(index) + "/";
  attractorPicker(state, layer, info);
  if (layer.params.size() != info.params.size()) return;  // changed attractor: sliders next frame
  const core::AttractorInfo& current = core::attractorOrThrow(layer.attractor);
  for (std::size_t p = 0; p < current.params.size(); ++p) {
    const core::ParamInfo& param = current.params[p];
    // The slider's range is the catalogue's; Ctrl+click types any value, right-click resets it.
    slider(state, scope, param.name.c_str(), layer.params[p], param.sliderMin, param.sliderMax, 0, "%.4f");
    if (ImGui::BeginPopupContextItem()) {
      if (ImGui::Selectable("Reset to default")) layer.params[p] = param.defaultValue;
      ImGui::EndPopup();
    }
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
      ImGui::SetTooltip("default %.4g — Ctrl+click to type, right-click to reset", param.defaultValue);
  }
  if (current.kind == core::AttractorKind::Flow) {
    int integrator = layer.integrator == core::Integrator::RK4 ? 1 : 0;
    if (ImGui::Combo("integrator", &integrator, "Euler\0Runge-Kutta 4\0"))
      layer.integrator = integrator == 1 ? core::Integrator::RK4 : core::Integrator::Euler;
    slider(state, scope, "step", layer.step, 0.0005, 0.3, ImGuiSliderFlags_Logarithmic, "%.4f");
  }
  if (button(state, scope, "Reset parameters")) {
    layer.params = current.defaultParams();
    layer.step = current.defaultStep;
    layer.integrator = current.defaultIntegrator;
  }
  if (state.scene.layers.size() > 1) {
    ImGui::SameLine();
    if (button(state, scope, "Remove layer")) removeThis = true;
    slider(state, scope, "weight", layer.weight, 0.01, 10.0, ImGuiSliderFlags_Logarithmic);
  }
  // Open from the start: the fit decides how much of the mesh the pattern fills.
  if (ImGui::TreeNodeEx("Placement", ImGuiTreeNodeFlags_DefaultOpen)) {
    slider(state, scope, "scale", layer.transform.scale, 0.1, 4.0, ImGuiSliderFlags_Logarithmic);
    int fit = static_cast<int>(layer.transform.fit);  // FitMode's order: contain, cover, stretch
    if (ImGui::Combo("fit", &fit, "contain\0cover\0stretch\0")) layer.transform.fit = static_cast<core::FitMode>(fit);
    probe(state, scope + "fit");
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
      ImGui::SetTooltip(
          "contain: fits the shape's middle axis; cover: fills every axis (the mesh carves it); "
          "stretch: scales each axis to the shape");
    double rotation[3] = {layer.transform.rotationDeg.x, layer.transform.rotationDeg.y, layer.transform.rotationDeg.z};
    const double minDeg = -180.0, maxDeg = 180.0;
    if (ImGui::SliderScalarN("rotation", ImGuiDataType_Double, rotation, 3, &minDeg, &maxDeg, "%.0f°"))
      layer.transform.rotationDeg = glm::dvec3(rotation[0], rotation[1], rotation[2]);
    double offset[3] = {layer.transform.offset.x, layer.transform.offset.y, layer.transform.offset.z};
    const double minOffset = -0.5, maxOffset = 0.5;
    if (ImGui::SliderScalarN("offset", ImGuiDataType_Double, offset, 3, &minOffset, &maxOffset, "%.2f"))
      layer.transform.offset = glm::dvec3(offset[0], offset[1], offset[2]);
    // Copies: the same pattern again, turned; one set of parameters moves them all.
    std::vector<glm::dvec3>& copies = layer.transform.copies;
    std::size_t removeCopy = copies.size();
    for (std::size_t c = 0; c < copies.size(); ++c) {
      ImGui::PushID(static_cast<int>(c));
      double angles[3] = {copies[c].x, copies[c].y, copies[c].z};
      const std::string label = "copy " + std::to_string(c + 1);
      if (ImGui::SliderScalarN(label.c_str(), ImGuiDataType_Double, angles, 3, &minDeg, &maxDeg, "%.0f°"))
        copies[c] = glm::dvec3(angles[0], angles[1], angles[2]);
      probe(state, scope + label);
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) removeCopy = c;
      probe(state, scope + label + " remove");
      ImGui::PopID();
    }
    if (removeCopy < copies.size()) copies.erase(copies.begin() + static_cast<std::ptrdiff_t>(removeCopy));
    if (copies.size() < core::kMaxLayerCopies && button(state, scope, "Add copy")) {
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
    colourEditor(state, scope, layer.color);
    ImGui::TreePop();
  }
}

void patternWindow(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(8 * scale, 8 * scale), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(350 * scale, io.DisplaySize.y - 48 * scale), ImGuiCond_FirstUseEver);
  // Side panels stay behind the notice and popups even when clicked.
  ImGui::Begin("Pattern", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PushItemWidth(-110 * scale);
  std::size_t removeIndex = state.scene.layers.size();
  for (std::size_t li = 0; li < state.scene.layers.size(); ++li) {
    const core::AttractorInfo& info = core::attractorOrThrow(state.scene.layers[li].attractor);
    ImGui::PushID(static_cast<int>(li));
    const std::string header = "Layer " + std::to_string(li + 1) + ": " + info.name + "###layer";
    if (ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      bool remove = false;
      layerEditor(state, li, remove);
      if (remove) removeIndex = li;
    }
    ImGui::PopID();
  }
  if (removeIndex < state.scene.layers.size())
    state.scene.layers.erase(state.scene.layers.begin() + static_cast<std::ptrdiff_t>(removeIndex));
  if (state.scene.layers.size() < 8 && button(state, "", "Add layer")) {
    // A second pattern starts as a different attractor at half weight, coloured apart.
    core::PatternLayer layer;
    layer.attractor = state.scene.layers.front().attractor == "aizawa" ? "thomas" : "aizawa";
    const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
    layer.params = info.defaultParams();
    layer.step = info.defaultStep;
    layer.integrator = info.defaultIntegrator;
    layer.weight = 0.5;
    layer.color.palette = core::namedPalettes().back().name;
    layer.color.gradient = core::paletteStops(layer.color.palette);
    state.scene.layers.push_back(layer);
  }

  if (ImGui::CollapsingHeader("Explore", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (button(state, "", "Search (F3)")) startSearch(state, 0.1);
    ImGui::SameLine();
    if (button(state, "", "Mutate")) startSearch(state, state.mutateStrength);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    slider(state, "", "##strength", state.mutateStrength, 0.01, 1.0, ImGuiSliderFlags_Logarithmic, "strength %.2f");
    ImGui::BeginDisabled(state.visited.empty() || state.visitedIndex == 0);
    if (button(state, "", "< Back")) goVisited(state, -1);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(state.visited.empty() || state.visitedIndex + 1 >= state.visited.size());
    if (button(state, "", "Forward >")) goVisited(state, +1);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (state.visited.empty())
      ImGui::TextColored(kDimColor, "no history yet");
    else
      ImGui::TextColored(kDimColor, "%zu of %zu (Alt+Left/Right)", state.visitedIndex + 1, state.visited.size());
    if (state.search.valid())
      ImGui::TextColored(kDimColor, "searching…");
    else if (!state.searchMessage.empty())
      ImGui::TextWrapped("%s", state.searchMessage.c_str());
    if (!state.session.stats.problem.empty()) {
      ImGui::TextColored(kErrorColor, "This pattern escapes to infinity.");
      ImGui::SameLine();
      if (button(state, "", "Find a nearby one")) startSearch(state, 0.1);
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

std::string formatBytes(double bytes) {
  char text[32];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.1f GB", bytes * 1e-9);
  else
    std::snprintf(text, sizeof text, "%.0f MB", bytes * 1e-6);
  return text;
}

void meshSection(ExplorerState& state) {
  const std::string file = std::filesystem::path(state.scene.meshPath).filename().string();
  ImGui::Text("mesh: %s%s", file.c_str(), state.scene.embedded ? " (built in)" : "");
  ImGui::InputTextWithHint("##meshpath", "path to a mesh, preset or image", state.meshPath, sizeof state.meshPath);
  probe(state, "mesh/path");
  ImGui::SameLine();
  if (button(state, "mesh/", "Open") && state.meshPath[0] != '\0') state.requests.open = state.meshPath;
  if (!state.settings.recent.empty() && ImGui::BeginCombo("recent", "recent files")) {
    for (const RecentFile& recent : state.settings.recent) {
      const std::string label = recent.path.filename().string() + "  (" + recent.path.parent_path().string() + ")";
      if (ImGui::Selectable(label.c_str())) state.requests.open = recent.path;
    }
    ImGui::EndCombo();
  }
  ImGui::TextColored(kDimColor, "or drop a mesh, preset or PNG onto the window");

  // The grid only changes when the slider is let go: each change rebuilds the mask.
  int& draft = state.gridDraft;
  if (!ImGui::IsAnyItemActive() || draft == 0) draft = state.scene.gridResolution;
  ImGui::SliderInt("grid", &draft, 32, 1024, "%d voxels", ImGuiSliderFlags_AlwaysClamp);
  probe(state, "mesh/grid");
  if (ImGui::IsItemDeactivatedAfterEdit()) state.scene.gridResolution = draft;
  // Cells, snapshot, packed copies: what pipeline::checkGridFitsInMemory counts, for a cube.
  const double voxels = std::pow(static_cast<double>(draft), 3.0);
  ImGui::TextColored(kDimColor, "at most %s of memory", formatBytes(voxels * 33.0).c_str());

  core::RenderSettingsDoc& render = state.scene.render;
  int meshMode = static_cast<int>(render.meshDisplay);
  if (ImGui::Combo("show mesh", &meshMode, "off\0ghost\0silhouette\0"))
    render.meshDisplay = static_cast<core::MeshDisplay>(meshMode);
  const glm::vec3 srgb = core::linearToSrgb(render.meshColor);
  float rgb[3] = {srgb.r, srgb.g, srgb.b};
  if (ImGui::ColorEdit3("mesh colour", rgb)) render.meshColor = core::srgbToLinear(glm::vec3(rgb[0], rgb[1], rgb[2]));
  slider(state, "mesh/", "mesh strength", render.meshStrength, 0.0, 2.0);
}

void renderSection(ExplorerState& state) {
  core::ToneMapSettings& tone = state.scene.tone;
  slider(state, "tone/", "brightness", tone.brightness, 0.01, 50.0, ImGuiSliderFlags_Logarithmic);
  slider(state, "tone/", "gamma", tone.gamma, 0.5, 6.0);
  slider(state, "tone/", "gamma threshold", tone.gammaThreshold, 0.0, 0.5);
  slider(state, "tone/", "vibrancy", tone.vibrancy, 0.0, 1.0);
  slider(state, "tone/", "highlight power", tone.highlightPower, -1.0, 5.0);
  slider(state, "tone/", "exposure", tone.exposure, -5.0, 5.0);
  slider(state, "tone/", "contrast", tone.contrast, 0.2, 3.0);
  slider(state, "tone/", "opacity", tone.opacity, 0.0, 1.0);
  slider(state, "tone/", "estimator radius", tone.estimatorRadius, 0.0, 20.0);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("density estimation: blur radius in pixels where few points fell; 0 turns it off");
  slider(state, "tone/", "estimator minimum", tone.estimatorMinimum, 0.0, 10.0);
  slider(state, "tone/", "estimator curve", tone.estimatorCurve, 0.05, 2.0);
  const glm::vec3 srgb = core::linearToSrgb(tone.background);
  float background[3] = {srgb.r, srgb.g, srgb.b};
  if (ImGui::ColorEdit3("background", background))
    tone.background = core::srgbToLinear(glm::vec3(background[0], background[1], background[2]));
  core::RenderSettingsDoc& render = state.scene.render;
  slider(state, "render/", "step (voxels)", render.stepVoxels, 0.1, 2.0);
  int method = static_cast<int>(render.method);
  if (ImGui::Combo("still method", &method, "volume\0points\0"))
    render.method = static_cast<core::RenderMethod>(method);
  probe(state, "render/method");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "how Export and the command line render stills: volume ray-marches the grid; points projects "
        "every point into the image (pixel-fine filaments). The view always previews with volume.");
  int oversample = render.oversample;
  if (ImGui::SliderInt("oversample", &oversample, 1, 4)) render.oversample = oversample;
  slider(state, "render/", "filter radius", render.filterRadius, 0.0, 3.0);
  if (render.method == core::RenderMethod::Points) {
    slider(state, "render/", "lens aperture", render.dofAperture, 0.0, 0.5);
    slider(state, "render/", "focus distance", render.dofFocusDistance, 0.0, 10.0);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("in bounding-sphere radii from the eye; 0 focuses on the target");
    slider(state, "render/", "fog", render.fog, 0.0, 5.0);
  }
  ImGui::Checkbox("lighting", &render.lighting);
  probe(state, "render/lighting");
  if (render.lighting) {
    slider(state, "render/", "light azimuth", render.lightAzimuthDeg, -180.0, 180.0, 0, "%.0f°");
    slider(state, "render/", "light elevation", render.lightElevationDeg, -90.0, 90.0, 0, "%.0f°");
    slider(state, "render/", "light strength", render.lightStrength, 0.0, 1.0);
  }
  ImGui::SliderFloat("preview scale", &state.renderScale, 0.25f, 1.0f, "%.2f");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("fraction of the window's pixels marched while you edit");
}

void cameraSection(ExplorerState& state) {
  core::CameraSettings& camera = state.scene.camera;
  slider(state, "camera/", "azimuth", camera.azimuthDeg, -180.0, 180.0, 0, "%.1f°");
  slider(state, "camera/", "elevation", camera.elevationDeg, -90.0, 90.0, 0, "%.1f°");
  slider(state, "camera/", "roll", camera.rollDeg, -180.0, 180.0, 0, "%.1f°");
  slider(state, "camera/", "distance", camera.distance, 0.2, 20.0, ImGuiSliderFlags_Logarithmic);
  slider(state, "camera/", "field of view", camera.fovDeg, 5.0, 120.0, 0, "%.0f°");
  bool orthographic = camera.projection == core::Projection::Orthographic;
  if (ImGui::Checkbox("orthographic", &orthographic))
    camera.projection = orthographic ? core::Projection::Orthographic : core::Projection::Perspective;
  auto view = [&](const char* label, double azimuth, double elevation) {
    if (button(state, "camera/", label)) {
      camera.azimuthDeg = azimuth, camera.elevationDeg = elevation, camera.rollDeg = 0.0;
      camera.target = glm::dvec3(0.0);
    }
  };
  view("Front", 0.0, 0.0);
  ImGui::SameLine();
  view("Side", 90.0, 0.0);
  ImGui::SameLine();
  view("Top", 0.0, 90.0);
  ImGui::SameLine();
  if (button(state, "camera/", "Reset")) camera = state.initialCamera;
  ImGui::TextColored(kDimColor, "drag: orbit · right/middle drag: pan · wheel: zoom · W/A/S/D/Q/E: fly");
}

void presetsSection(ExplorerState& state, float scale) {
  if (!state.presets) return;
  const PresetLibrary::Entries entries = state.presets->entries();
  // Saving comes first, so it stays in reach however long the library grows.
  ImGui::InputTextWithHint("##savename", "name of your preset", state.saveName, sizeof state.saveName);
  probe(state, "preset/name");
  ImGui::SameLine();
  if (button(state, "preset/", "Save as") && state.saveName[0] != '\0') state.requests.saveAs = state.saveName;
  ImGui::SameLine();
  if (button(state, "preset/", "Refresh")) state.presets->refresh();
  if (!state.presetMessage.empty()) ImGui::TextWrapped("%s", state.presetMessage.c_str());
  if (state.presets->busy()) ImGui::TextColored(kDimColor, "reading presets…");
  if (entries) {
    const float size = 92 * scale;
    const int columns = std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / (size + 8 * scale)));
    int column = 0;
    PresetSource lastSource = PresetSource::Shipped;
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const PresetEntry& entry = (*entries)[i];
      if (i == 0 || entry.source != lastSource) {
        ImGui::TextColored(kDimColor, entry.source == PresetSource::Shipped ? "shipped" : "yours (%s)",
                           state.presets->userFolder().string().c_str());
        column = 0;
      }
      lastSource = entry.source;
      if (column++ % columns != 0) ImGui::SameLine();
      ImGui::PushID(static_cast<int>(i));
      ImGui::BeginGroup();
      const auto texture = state.thumbnailTextures.find(entry.path);
      bool clicked = false;
      if (texture != state.thumbnailTextures.end() && entry.thumbnail) {
        const float aspect = static_cast<float>(entry.thumbnail->height) / static_cast<float>(entry.thumbnail->width);
        clicked = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture->second)),
                                     ImVec2(size, size * aspect));
      } else {
        clicked = ImGui::Button(entry.loads ? "no image" : "broken", ImVec2(size, size * 0.625f));
      }
      probe(state, "preset/" + entry.path.stem().string());
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s\n%s", entry.displayName.c_str(),
                          entry.loads ? entry.attractor.c_str() : entry.error.c_str());
      if (clicked) {
        if (entry.loads)
          state.requests.open = entry.path;
        else
          state.notice = entry.error;
      }
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size);
      ImGui::TextUnformatted(entry.displayName.c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndGroup();
      ImGui::PopID();
    }
  }
}

void exportSection(ExplorerState& state) {
  if (!state.exportJob) return;
  ExportSettings& settings = state.settings.lastExport;
  int size[2] = {settings.width, settings.height};
  if (ImGui::InputInt2("size", size)) {
    settings.width = std::clamp(size[0], 16, 65536);
    settings.height = std::clamp(size[1], 16, 65536);
  }
  ImGui::SliderInt("samples", &settings.samples, 1, 64, "%d", ImGuiSliderFlags_Logarithmic);
  double millions = static_cast<double>(settings.points ? settings.points : state.scene.points) * 1e-6;
  const double minPoints = 0.1, maxPoints = 10000.0;
  if (ImGui::SliderScalar("M points", ImGuiDataType_Double, &millions, &minPoints, &maxPoints, "%.1f",
                          ImGuiSliderFlags_Logarithmic))
    settings.points = static_cast<std::uint64_t>(millions * 1e6);
  ImGui::TextColored(kDimColor, "method: %s (Render panel)",
                     std::string(core::toString(state.scene.render.method)).c_str());
  int format = static_cast<int>(settings.format);
  if (ImGui::Combo("format", &format, "PNG 8-bit\0PNG 16-bit\0EXR (linear float)\0"))
    settings.format = static_cast<ExportFormat>(format);
  if (state.exportPath[0] == '\0') {
    const std::filesystem::path folder =
        state.settings.lastExportFolder.empty() ? std::filesystem::current_path() : state.settings.lastExportFolder;
    const std::string path = (folder / (sanitizePresetName(state.scene.name) + extensionOf(settings.format))).string();
    std::snprintf(state.exportPath, sizeof state.exportPath, "%s", path.c_str());
  }
  ImGui::InputText("file", state.exportPath, sizeof state.exportPath);
  probe(state, "export/file");
  const ExportStatus& status = state.exportStatus;
  if (status.state == ExportState::Running) {
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s %.0f%%", status.stage.c_str(), 100.0 * status.overall);
    ImGui::ProgressBar(static_cast<float>(status.overall), ImVec2(-80 * state.uiScale, 0), overlay);
    ImGui::SameLine();
    if (button(state, "export/", "Cancel")) state.exportJob->cancel();
    return;
  }
  if (button(state, "export/", "Export now")) {  // not "Export": the header above has that id
    try {
      ExportRequest request;
      request.scene = state.scene;
      request.settings = settings;
      request.output = withExtensionFor(state.exportPath, settings.format);
      request.executable = state.executable;
      std::snprintf(state.exportPath, sizeof state.exportPath, "%s", request.output.string().c_str());
      state.settings.lastExportFolder = std::filesystem::absolute(request.output).parent_path();
      state.exportJob->start(request);
      state.exportStatus = state.exportJob->poll();
    } catch (const core::Error& e) {
      state.notice = e.what();
    }
  }
  if (status.state == ExportState::Done) ImGui::TextWrapped("wrote %s", status.output.string().c_str());
  if (status.state == ExportState::Failed) ImGui::TextColored(kErrorColor, "%s", status.error.c_str());
  if (status.state == ExportState::Cancelled) ImGui::TextColored(kDimColor, "cancelled; nothing was written");
}

// Scenes left by a session that crashed or was killed: restore or discard, one at a time.
void recoveryWindow(ExplorerState& state, float scale) {
  if (state.recoverable.empty()) return;
  const Recoverable& recoverable = state.recoverable.front();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.35f * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(440 * scale, 0));
  ImGui::Begin("Recover unsaved work", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  if (recoverable.scene) {
    ImGui::TextWrapped("voxflame did not close normally last time. Its scene \"%s\" was autosaved.",
                       recoverable.scene->name.c_str());
    if (button(state, "recover/", "Restore")) {
      state.scene = *recoverable.scene;
      state.keyBase = state.scene;
      dismissRecoverable(recoverable);
      state.recoverable.erase(state.recoverable.begin());
    }
    ImGui::SameLine();
  } else {
    ImGui::TextColored(kErrorColor, "%s", recoverable.error.c_str());
  }
  if (!state.recoverable.empty() && button(state, "recover/", "Discard")) {
    dismissRecoverable(state.recoverable.front());
    state.recoverable.erase(state.recoverable.begin());
  }
  ImGui::End();
}

void viewWindow(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float width = 320 * scale;
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - width - 8 * scale, 8 * scale), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y - 48 * scale), ImGuiCond_FirstUseEver);
  ImGui::Begin("Scene", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PushItemWidth(-120 * scale);
  if (ImGui::CollapsingHeader("Mesh", ImGuiTreeNodeFlags_DefaultOpen)) meshSection(state);
  if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) renderSection(state);
  if (ImGui::CollapsingHeader("Camera")) cameraSection(state);
  const bool presetsOpen = ImGui::CollapsingHeader("Presets");
  probe(state, "header/Presets");
  if (presetsOpen) presetsSection(state, scale);
  const bool exportOpen = ImGui::CollapsingHeader("Export");
  probe(state, "header/Export");
  if (exportOpen) exportSection(state);
  ImGui::PopItemWidth();
  ImGui::End();
}

void statusBar(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = ImGui::GetFrameHeightWithSpacing() + 6 * scale;
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const core::AccumulatorStats& stats = state.session.stats;
  const FrameMetrics& m = state.metrics;
  if (state.session.buildingShape)
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "%s %.1f s", state.session.shapeStage.c_str(),
                       state.session.shapeSeconds);
  else
    ImGui::Text("%.1f M points  %.1f M/s  inside %.1f%%  escapes %llu", static_cast<double>(stats.points) * 1e-6,
                stats.pointsPerSecond * 1e-6, 100.0 * stats.insideFraction(),
                static_cast<unsigned long long>(stats.escapes));
  ImGui::SameLine();
  ImGui::TextColored(kDimColor, " |  %.0f fps  %.1f ms (worst %.0f)  upload %.1f ms  %d samples", m.fps, m.frameMs,
                     m.worstFrameMs, m.uploadMs, state.samples);
  if (m.changeToFrameMs >= 0.0) {
    ImGui::SameLine();
    ImGui::TextColored(kDimColor, " |  edit→frame %.0f ms (%d frames)", m.changeToFrameMs, m.changeToFrameFrames);
  }
  ImGui::SameLine();
  ImGui::TextColored(kDimColor, " |  %s", state.lyapunovText.c_str());
  ImGui::End();
}

// Errors stay on screen until dismissed; the explorer goes on with the last good state.
void noticeWindow(ExplorerState& state, float scale) {
  std::string text;
  auto addLine = [&text](const std::string& line) {
    if (line.empty()) return;
    if (!text.empty()) text += '\n';
    text += line;
  };
  addLine(state.notice);
  addLine(state.session.error);
  if (!state.session.stats.problem.empty()) addLine(state.session.stats.problem + " — try Search (F3).");
  if (text.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 12 * scale), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(200 * scale, 0), ImVec2(io.DisplaySize.x * 0.45f, 400 * scale));
  ImGui::Begin("##notice", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushTextWrapPos(io.DisplaySize.x * 0.43f);
  ImGui::TextColored(kErrorColor, "%s", text.c_str());
  ImGui::PopTextWrapPos();
  if (!state.notice.empty() && button(state, "notice/", "Dismiss")) state.notice.clear();
  ImGui::End();
}

// ---------------------------------------------------------------------------------------------
// Timeline: the scene shown is the animation at the current time; "Key" records what the user
// changed there as keyframes; scrubbing and playing re-evaluate the animation.

double timelineLength(const core::Scene& scene) {
  const double duration = core::animationDuration(scene);
  return duration > 0.0 ? duration : 5.0;  // room to place the first keys
}

void showTime(ExplorerState& state, double seconds) {
  try {
    state.scene = core::sceneAtTime(state.scene, seconds);
    state.keyBase = state.scene;
  } catch (const core::Error& e) {
    state.notice = e.what();
    state.playing = false;
  }
}

std::vector<double> keyTimes(const core::Scene& scene) {
  std::vector<double> times;
  for (const core::KeyframeTrack& track : scene.keyframes)
    for (const core::Keyframe& key : track.keys) times.push_back(key.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }),
              times.end());
  return times;
}

void advancePlayback(ExplorerState& state) {
  if (!state.playing) return;
  const double length = timelineLength(state.scene);
  double next = state.scene.animation.time + static_cast<double>(ImGui::GetIO().DeltaTime);
  if (next > length) {
    if (core::animationLoops(state.scene) || state.playLooping)
      next = std::fmod(next, length);
    else
      next = length, state.playing = false;
  }
  showTime(state, next);
}

void timelineWindow(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float statusHeight = ImGui::GetFrameHeightWithSpacing() + 6 * scale;
  const float left = 366 * scale, right = 336 * scale;
  const float height = 3 * ImGui::GetFrameHeightWithSpacing() + ImGui::GetTextLineHeightWithSpacing() + 14 * scale;
  ImGui::SetNextWindowPos(ImVec2(left, io.DisplaySize.y - statusHeight - height - 4 * scale), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(std::max(300.0f, io.DisplaySize.x - left - right), height), ImGuiCond_FirstUseEver);
  ImGui::Begin("Timeline", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus);
  core::Scene& scene = state.scene;
  const double length = timelineLength(scene);
  if (button(state, "timeline/", state.playing ? "Pause" : "Play")) state.playing = !state.playing;
  ImGui::SameLine();
  const std::vector<double> times = keyTimes(scene);
  const double now = scene.animation.time;
  if (button(state, "timeline/", "|<")) {
    double target = 0.0;
    for (double t : times)
      if (t < now - 1e-6) target = t;
    showTime(state, target);
  }
  ImGui::SameLine();
  if (button(state, "timeline/", ">|")) {
    double target = length;
    for (auto t = times.rbegin(); t != times.rend(); ++t)
      if (*t > now + 1e-6) target = *t;
    showTime(state, target);
  }
  ImGui::SameLine();
  if (button(state, "timeline/", "Key")) {
    try {
      // What changed since the time was last shown becomes keys; animated values always get one.
      core::Scene animated = state.keyBase;
      animated.keyframes = scene.keyframes;
      animated.animation = scene.animation;
      scene = core::withKeyframeAt(animated, scene, now);
      state.keyBase = scene;
      char text[64];
      std::snprintf(text, sizeof text, "keyed at %.2f s", now);
      state.timelineMessage = text;
    } catch (const core::Error& e) {
      state.notice = e.what();
    }
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("keyframe every value you changed here (and every animated one)");
  ImGui::SameLine();
  const bool keyHere = std::any_of(times.begin(), times.end(), [&](double t) { return std::abs(t - now) < 1e-6; });
  ImGui::BeginDisabled(!keyHere);
  if (button(state, "timeline/", "Delete key")) {
    for (core::KeyframeTrack& track : scene.keyframes)
      std::erase_if(track.keys, [&](const core::Keyframe& key) { return std::abs(key.time - now) < 1e-6; });
    std::erase_if(scene.keyframes, [](const core::KeyframeTrack& track) { return track.keys.empty(); });
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90 * scale);
  double duration = scene.animation.duration;
  const double minDuration = 0.0, maxDuration = 600.0;
  if (ImGui::DragScalar("duration", ImGuiDataType_Double, &duration, 0.05f, &minDuration, &maxDuration,
                        duration > 0.0 ? "%.2f s" : "auto"))
    scene.animation.duration = duration;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70 * scale);
  double fps = scene.animation.fps;
  const double minFps = 1.0, maxFps = 240.0;
  if (ImGui::DragScalar("fps", ImGuiDataType_Double, &fps, 0.2f, &minFps, &maxFps, "%.0f")) scene.animation.fps = fps;
  ImGui::SameLine();
  ImGui::Checkbox("loop", &scene.animation.loop);

  // The scrubber, with a tick for every key time.
  double time = now;
  const double zero = 0.0;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &time, &zero, &length, "%.2f s")) {
    state.playing = false;
    showTime(state, time);
  }
  probe(state, "timeline/time");
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const float grab = ImGui::GetStyle().GrabMinSize;
  for (double t : times) {
    const float x = min.x + grab * 0.5f + static_cast<float>(t / length) * (max.x - min.x - grab);
    ImGui::GetWindowDrawList()->AddTriangleFilled(ImVec2(x - 4 * scale, max.y), ImVec2(x + 4 * scale, max.y),
                                                  ImVec2(x, max.y - 6 * scale), IM_COL32(255, 190, 90, 255));
  }
  if (scene.keyframes.empty())
    ImGui::TextColored(kDimColor, "no keyframes: move the time, change something, press Key");
  else
    ImGui::TextColored(kDimColor, "%zu animated values, %zu key times  %s", scene.keyframes.size(), times.size(),
                       state.timelineMessage.c_str());
  ImGui::End();
}

}  // namespace

void resetExplorerState(ExplorerState& state, const core::Scene& scene) {
  state.scene = scene;
  state.keyBase = scene;
  state.initialCamera = scene.camera;
  state.history.emplace(scene);
  state.visited.clear();
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
      // A flame replaces the pattern and keeps the mesh and view: one undoable edit.
      core::Scene scene;
      const core::FlameFileContents contents = importFlameScene(path, state.scene, {}, scene);
      state.scene = scene;
      state.notice.clear();
      for (const std::string& warning : contents.flame.warnings)
        state.notice += (state.notice.empty() ? "" : "\n") + path.filename().string() + ": " + warning;
      state.settings.addRecent(RecentKind::Preset, path);
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
  advancePlayback(state);
  patternWindow(state, scale);
  viewWindow(state, scale);
  timelineWindow(state, scale);
  recoveryWindow(state, scale);
  statusBar(state, scale);
  noticeWindow(state, scale);
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
