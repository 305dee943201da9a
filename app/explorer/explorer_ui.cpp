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

namespace voxflame::app {

// Puts a flame just imported from `path` in place of the pattern (openFile, flameChoiceWindow).
void applyImportedFlame(ExplorerState& state, const std::filesystem::path& path,
                        const core::FlameFileContents& contents, const core::Scene& scene);

namespace {

// The window backend fills io.KeysDown by GLFW key code; letters are their ASCII capitals.
constexpr int kKeyEscape = 256, kKeyRight = 262, kKeyLeft = 263, kKeyF3 = 292;
constexpr int kKeyLeftAlt = 342, kKeyRightAlt = 346;

// The status line's height: the docked panels end above it.
float statusBarHeight(float scale) {
  return ImGui::GetFrameHeightWithSpacing() + 6 * scale;
}

const ImVec4 kErrorColor(1.0f, 0.45f, 0.35f, 1.0f);
const ImVec4 kDimColor(0.62f, 0.65f, 0.72f, 1.0f);

// A hint or a message in the dim colour, wrapped at the panel's edge rather than cut there.
IM_FMTARGS(1) void dimText(const char* format, ...) {
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  va_list arguments;
  va_start(arguments, format);
  ImGui::TextWrappedV(format, arguments);
  va_end(arguments);
  ImGui::PopStyleColor();
}

void probe(ExplorerState& state, const std::string& name) {
  if (!state.probe) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state.probe->items[name] = UiProbe::Rect{min.x, min.y, max.x, max.y};
}

// After a text field: what it now holds, when it changed this frame and typing is recorded.
void noteTyped(ExplorerState& state, const char* field, const char* text) {
  if (state.recordTyping && ImGui::IsItemEdited()) state.typedThisFrame.emplace_back(field, text);
}

bool slider(ExplorerState& state, const std::string& scope, const char* label, double& value, double min, double max,
            ImGuiSliderFlags flags = 0, const char* format = "%.3f") {
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format, flags);
  probe(state, scope + label);
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
void markIfKeyed(ExplorerState& state, const std::string& path, const std::string& probeName) {
  const auto& tracks = state.scene.keyframes;
  if (std::none_of(tracks.begin(), tracks.end(), [&](const core::KeyframeTrack& t) { return t.path == path; })) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const float size = 0.22f * (max.y - min.y);
  const ImVec2 centre(max.x - size - 1.0f, min.y + size + 1.0f);
  ImGui::GetWindowDrawList()->AddQuadFilled(ImVec2(centre.x, centre.y - size), ImVec2(centre.x + size, centre.y),
                                            ImVec2(centre.x, centre.y + size), ImVec2(centre.x - size, centre.y),
                                            IM_COL32(255, 190, 90, 255));
  probe(state, probeName + "/keyed");
}

// The widget of one schema field (core/scene_schema.h): its label, slider range, format and help
// come from the table. Sliders always clamp, Ctrl+click typing included, and every table's slider
// range lies inside what the reader allows, so no value made here is one a preset refuses.
// `probeName` replaces the probe's usual name (scope + label).
template <class Owner>
bool fieldWidget(ExplorerState& state, const std::string& scope, Owner& owner, core::Table<Owner> table,
                 std::string_view key, const char* probeName = nullptr) {
  const core::Field<Owner>& f = core::field(table, key);
  const std::string label(f.ui.label);
  const std::string format(f.ui.format);
  const ImGuiSliderFlags flags =
      ImGuiSliderFlags_AlwaysClamp | (f.ui.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
  const bool changed = std::visit(
      [&]<class M>(const M& member) -> bool {
        if constexpr (std::is_same_v<M, double Owner::*>) {
          const double min = f.ui.min, max = f.ui.max;
          return ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &(owner.*member), &min, &max, format.c_str(),
                                     flags);
        } else if constexpr (std::is_same_v<M, int Owner::*>) {
          return ImGui::SliderInt(label.c_str(), &(owner.*member), static_cast<int>(f.ui.min),
                                  static_cast<int>(f.ui.max), format.c_str(), flags);
        } else if constexpr (std::is_same_v<M, bool Owner::*>) {
          return ImGui::Checkbox(label.c_str(), &(owner.*member));
        } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
          const glm::vec3 srgb = core::linearToSrgb(owner.*member);
          float rgb[3] = {srgb.r, srgb.g, srgb.b};
          if (!ImGui::ColorEdit3(label.c_str(), rgb)) return false;
          owner.*member = core::srgbToLinear(glm::vec3(rgb[0], rgb[1], rgb[2]));
          return true;
        } else if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
          glm::dvec3& value = owner.*member;
          double v[3] = {value.x, value.y, value.z};
          const double min = f.ui.min, max = f.ui.max;
          if (!ImGui::SliderScalarN(label.c_str(), ImGuiDataType_Double, v, 3, &min, &max, format.c_str(), flags))
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
          if (!ImGui::Combo(label.c_str(), &index, items.c_str())) return false;
          member.set(owner, index);
          return true;
        } else {
          return false;  // no widget for this kind of field
        }
      },
      f.member);
  const std::string probed = probeName ? std::string(probeName) : scope + label;
  probe(state, probed);
  markIfKeyed(state, valuePath(scope, key), probed);
  // Right-click: back to the default, as the pattern sliders do (a default-made owner holds it).
  bool reset = false;
  // A named popup: the last item of some widgets (a colour editor's label) has no id of its own.
  if (ImGui::BeginPopupContextItem(("reset##" + probed).c_str())) {
    reset = ImGui::Selectable("Reset to default");
    probe(state, probed + "/reset");
    ImGui::EndPopup();
  }
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
  return changed || reset;
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

// ---------------------------------------------------------------------------------------------
// The flat view: rendered off the main thread when what it shows changed, drawn behind the panels.
namespace {

// At most this wide and this quality, so an edit shows within about a second.
constexpr int kFlatViewMaxWidth = 640;
constexpr double kFlatViewMaxQuality = 50.0;

const core::PatternLayer* firstFlameLayer(const core::Scene& scene) {
  for (const core::PatternLayer& layer : scene.layers)
    if (layer.kind == core::PatternKind::Flame) return &layer;
  return nullptr;
}

// The part of the scene the flat view shows: the first flame layer, the tone and the framing.
core::Scene flatViewScene(const core::Scene& scene) {
  core::Scene shown;
  shown.name = scene.name;
  if (const core::PatternLayer* layer = firstFlameLayer(scene)) shown.layers = {*layer};
  shown.tone = scene.tone;
  shown.flat = scene.flat;
  return shown;
}

void updateFlatView(ExplorerState& state) {
  if (!state.flatView) {
    // Runs every frame while the view is off: costs nothing unless a render was under way or kept.
    if (state.flatRender.busy()) state.flatRender.cancel();
    state.flatRendered.layers.clear();  // so that turning the view on renders afresh
    return;
  }
  if (state.flatRender.ready()) {
    try {
      state.flatImage = *state.flatRender.take();
      state.flatImagePending = true;
      state.flatMessage.clear();
    } catch (const std::exception& e) {
      state.flatMessage = e.what();
    }
  }
  const core::Scene shown = flatViewScene(state.scene);
  if (shown.layers.empty()) {
    state.flatMessage = "the flat view shows flame layers; this scene has none";
    return;
  }
  if (shown == state.flatRendered) return;
  state.flatRendered = shown;
  core::FlatRenderOptions options;
  options.width = std::min(shown.flat.width, kFlatViewMaxWidth);
  options.quality = std::min(shown.flat.quality, kFlatViewMaxQuality);
  state.flatRender.start([shown, options](std::stop_token stop) mutable {
    std::atomic<bool> cancel{false};
    const std::stop_callback onStop(stop, [&cancel] { cancel = true; });
    options.cancel = &cancel;
    try {
      return core::renderFlat(shown, options).image;
    } catch (const core::FlatRenderCancelled&) {
      return core::ImageRGBA{};
    }
  });
}

// The flat image over the whole window behind the panels, letterboxed to its aspect.
void drawFlatView(const ExplorerState& state) {
  if (!state.flatView) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  draw->AddRectFilled(ImVec2(0.0f, 0.0f), display, IM_COL32(0, 0, 0, 255));
  if (state.flatTexture && state.flatTextureWidth > 0 && state.flatTextureHeight > 0) {
    const float fit = std::min(display.x / static_cast<float>(state.flatTextureWidth),
                               display.y / static_cast<float>(state.flatTextureHeight));
    const ImVec2 size(fit * static_cast<float>(state.flatTextureWidth),
                      fit * static_cast<float>(state.flatTextureHeight));
    const ImVec2 corner(0.5f * (display.x - size.x), 0.5f * (display.y - size.y));
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(state.flatTexture)), corner,
                   ImVec2(corner.x + size.x, corner.y + size.y));
  }
  const char* text = !state.flatMessage.empty() ? state.flatMessage.c_str()
                     : state.flatRender.busy()  ? "flat view: rendering…"
                                                : "flat view (as flam3 renders it)";
  draw->AddText(ImVec2(12.0f, display.y - 48.0f), IM_COL32(220, 220, 220, 255), text);
}

}  // namespace

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

// Keeps the Lyapunov line in step with layer 0; one analysis at a time, never waited for.
void updateAnalysis(ExplorerState& state) {
  const bool chaosGame = !state.scene.layers.empty() && state.scene.layers.front().isChaosGame();
  if (state.analysis.ready()) {
    try {
      const core::OrbitAnalysis result = *state.analysis.take();
      char text[160];
      std::snprintf(text, sizeof text, "λ %.3f  %.3f  %.3f  (%s)", result.lyapunov[0], result.lyapunov[1],
                    result.lyapunov[2], std::string(core::toString(result.verdict)).c_str());
      if (!chaosGame) state.lyapunovText = text;  // an attractor's analysis that finished after a switch is stale
    } catch (const core::Error& e) {
      if (!chaosGame) state.lyapunovText = e.what();
    }
  }
  if (state.scene.layers.empty()) return;
  const core::PatternLayer& front = state.scene.layers.front();
  if (chaosGame) {
    // A chaos game picks a map at random every step: there is no one orbit whose Lyapunov
    // exponents would mean anything, so the line just says what the layer is.
    state.lyapunovText =
        front.kind == core::PatternKind::Flame ? "flame (chaos game)" : "quaternion Julia (chaos game)";
    state.analysedKey.clear();
    return;
  }
  if (state.analysis.busy()) return;
  const std::string key = analysisKey(front);
  if (key == state.analysedKey) return;
  state.analysedKey = key;
  try {
    const core::OrbitSpec spec = core::orbitSpecOf(state.scene.layers.front());
    core::LyapunovOptions options;
    options.steps = 20'000;
    state.analysis.start([spec, options](std::stop_token) { return core::analyseOrbit(spec, options); });
  } catch (const core::Error& e) {
    state.lyapunovText = e.what();
  }
}

// The part of a layer that Search changes and the history restores (its kind and pattern);
// colour and placement stay.
void applyVisited(core::PatternLayer& layer, const core::PatternLayer& visited) {
  const bool kindChanges = layer.kind != visited.kind;
  layer.kind = visited.kind;
  layer.attractor = visited.attractor;
  layer.params = visited.params;
  layer.integrator = visited.integrator;
  layer.step = visited.step;
  layer.flame = visited.flame;
  layer.julia = visited.julia;
  // An attractor cannot colour by flam3's index; a chaos layer starts with it.
  if (kindChanges) layer.color.mode = visited.isChaosGame() ? core::ColorMode::Index : core::ColorMode::Speed;
}

std::string fillText(const core::FillReport& fill) {
  char text[128];
  std::snprintf(text, sizeof text, "fills %.0f%% of its box, thinnest side %.2f of the longest", 100.0 * fill.occupancy,
                fill.extentRatio);
  return text;
}

// Search (fresh) draws new patterns near nothing; Mutate (and "Find a nearby one") moves the
// current one by `strength`. Attractors always search near their parameters, as before; flames
// and Julia sets use the fill test of flame_search.h.
void startSearch(ExplorerState& state, double strength, bool fresh) {
  if (state.search.busy() || state.scene.layers.empty()) return;  // one at a time
  using Outcome = ExplorerState::SearchOutcome;
  try {
    const core::PatternLayer layer = state.scene.layers.front();
    const std::uint64_t seed = state.searchSeed++;
    if (layer.isChaosGame()) {
      core::FlameSearchOptions options;
      options.seed = seed;
      options.count = 1;
      options.strength = strength;
      options.juliaView = layer.julia;
      state.searchTried.reset();  // the flame and Julia searches count no tries
      state.searchStrength.reset();
      state.searchMessage = "searching…";
      state.search.start([layer, options, fresh](std::stop_token stop) mutable {
        options.stop = stop;
        Outcome outcome;
        core::PatternLayer found = layer;
        if (layer.kind == core::PatternKind::Flame) {
          const auto results =
              core::searchFlames(fresh ? std::nullopt : std::optional<core::FlameGenome>(layer.flame), options);
          if (results.empty()) {
            outcome.message = "no flame that fills its box was found; try again or a smaller strength";
            return outcome;
          }
          found.flame = results.front().genome;
          outcome.message = "found a flame: " + fillText(results.front().fill);
        } else {
          const auto results = core::searchQuaternionJulia(
              fresh ? std::nullopt : std::optional<core::QuaternionJuliaSettings>(layer.julia), options);
          if (results.empty()) {
            outcome.message = "no Julia set that fills its box was found; try again or a smaller strength";
            return outcome;
          }
          found.julia = results.front().julia;
          outcome.message = "found a Julia set: " + fillText(results.front().fill);
        }
        outcome.found = found;
        return outcome;
      });
      return;
    }
    const core::OrbitSpec spec = core::orbitSpecOf(layer);
    core::SearchOptions options;
    options.seed = seed;
    options.count = 1;
    options.strength = strength;
    // Nothing nearby: it widens by itself, a few hundred tries at each strength, before giving up.
    options.widenTo = std::max(strength, core::kSearchWidenTo);
    options.maxCandidates = core::kSearchTriesPerStrength;
    state.searchTried = std::make_shared<std::atomic<int>>(0);
    state.searchStrength = std::make_shared<std::atomic<double>>(strength);
    state.searchMessage = "searching…";
    state.search.start([layer, spec, options, tried = state.searchTried,
                        strengthNow = state.searchStrength](std::stop_token stop) mutable {
      options.stop = stop;
      options.tried = tried.get();
      options.strengthNow = strengthNow.get();
      Outcome outcome;
      const auto results = core::searchChaos(spec, options);
      if (results.empty()) {
        char text[160];
        std::snprintf(text, sizeof text, "no chaotic set within strength %.2g–%.2g after %d tries", options.strength,
                      options.widenTo, tried->load());
        outcome.message = text;
        return outcome;
      }
      core::PatternLayer found = layer;
      found.params = results.front().params;
      outcome.found = found;
      char text[128];
      std::snprintf(text, sizeof text, "found: largest Lyapunov exponent %.3f (strength %.2g, %d tries)",
                    results.front().analysis.lyapunov[0], strengthNow->load(), tried->load());
      outcome.message = text;
      return outcome;
    });
  } catch (const core::Error& e) {
    state.searchMessage = e.what();
  }
}

void collectSearch(ExplorerState& state) {
  if (!state.search.ready()) return;
  try {
    const ExplorerState::SearchOutcome outcome = *state.search.take();
    state.searchMessage = outcome.message;
    if (!outcome.found || state.scene.layers.empty()) return;
    core::PatternLayer& layer = state.scene.layers.front();
    if (layer.kind != outcome.found->kind) {
      state.searchMessage = "the layer changed kind while the search ran; its result was dropped";
      return;
    }
    // The history keeps where the search started from, then each find; a find after going back
    // drops the forward part, as in a browser.
    if (state.visited.empty()) {
      state.visited.push_back(layer);
      state.visitedMessages.assign(1, "where the search started");
    }
    state.visited.resize(std::min(state.visited.size(), state.visitedIndex + 1));
    state.visitedMessages.resize(state.visited.size());
    applyVisited(layer, *outcome.found);
    state.visited.push_back(layer);
    state.visitedMessages.push_back(outcome.message);
    state.visitedIndex = state.visited.size() - 1;
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
  // The "found:" line is the one of the pattern now shown.
  if (state.visitedIndex < state.visitedMessages.size())
    state.searchMessage = state.visitedMessages[state.visitedIndex];
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

// However far one pans or flies, the target stays a value a preset can hold.
glm::dvec3 clampedTarget(const glm::dvec3& target) {
  const core::Field<core::CameraSettings>& field = core::field(core::cameraFields(), "target");
  return glm::clamp(target, glm::dvec3(field.min), glm::dvec3(field.max));
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
    camera.target = clampedTarget(camera.target + perPixel * (-static_cast<double>(delta.x) * frame.right +
                                                              static_cast<double>(delta.y) * frame.up));
  }
  if (!overUi && io.MouseWheel != 0.0f)
    camera.distance = std::clamp(camera.distance * std::pow(0.9, io.MouseWheel), 0.2, 20.0);

  // Free flight: W/S move along the view, A/D sideways, Q/E down and up; the orbit target moves
  // with the eye, so the camera turns about itself when dragged afterwards.
  // (Nor while the quit prompt is open: S and D answer it.)
  if (io.WantCaptureKeyboard || io.KeyCtrl || state.quitPrompt) return;
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
  if (io.KeyCtrl && ImGui::IsKeyPressed('S', false) && !state.quitPrompt) {
    state.requests.saveAs = state.scene.name;
    state.requests.saveReplacing = true;
  }
  if (io.WantTextInput) return;
  if (ImGui::IsKeyPressed(kKeyF3, false)) startSearch(state, 0.1, true);
  if (io.KeyCtrl && ImGui::IsKeyPressed('F', false)) state.focusAttractorFilter = true;
  const bool alt = io.KeyAlt || keyDown(kKeyLeftAlt) || keyDown(kKeyRightAlt);
  if (alt && ImGui::IsKeyPressed(kKeyLeft, false)) goVisited(state, -1);
  if (alt && ImGui::IsKeyPressed(kKeyRight, false)) goVisited(state, +1);
}

// ---------------------------------------------------------------------------------------------
// Panels.

void attractorPicker(ExplorerState& state, core::PatternLayer& layer, const core::AttractorInfo& info) {
  if (std::exchange(state.focusAttractorFilter, false)) ImGui::SetKeyboardFocusHere();
  const bool enter = ImGui::InputTextWithHint("##filter", "filter attractors (Ctrl+F)", state.attractorFilter,
                                              sizeof state.attractorFilter, ImGuiInputTextFlags_EnterReturnsTrue);
  probe(state, "attractor/filter");
  noteTyped(state, "attractor filter", state.attractorFilter);
  const std::string filter = lowercase(state.attractorFilter);
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
        state.attractorFilter[0] = '\0';
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
  if (ImGui::Combo("colour by", &mode, modes)) color.mode = static_cast<core::ColorMode>(mode);
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
    color.palette.clear();
    // Stops stay in position order (the preset's order), except while one is being dragged past another.
    if (!ImGui::IsAnyItemActive())
      std::stable_sort(color.gradient.begin(), color.gradient.end(),
                       [](const auto& a, const auto& b) { return a.position < b.position; });
  }
}

// ---------------------------------------------------------------------------------------------
// Chaos-game layers: the kind of a layer, a flame's transforms and variations, a Julia set.

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr double kParamLimit = 1e6;  // what the preset reader allows for an attractor's parameter

// A layer's kind; a new kind starts from its defaults (the default flame, the classic Julia set,
// the attractor catalogue's first-layer default) and the colour mode that suits it.
void patternKindChoice(ExplorerState& state, std::size_t index, const std::string& scope, core::PatternLayer& layer) {
  static constexpr const char* kKindLabels[] = {"attractor", "flame", "quaternion Julia"};
  const int current = static_cast<int>(layer.kind);
  if (ImGui::BeginCombo("pattern", kKindLabels[current])) {
    for (int k = 0; k < 3; ++k) {
      const bool chosen = ImGui::Selectable(kKindLabels[k], k == current);
      probe(state, scope + "pattern/" + kKindLabels[k]);
      if (!chosen || k == current) continue;
      const core::PatternLayer defaults;
      layer.kind = static_cast<core::PatternKind>(k);
      if (layer.isChaosGame()) {
        layer.attractor.clear();
        layer.params.clear();
        layer.flame = layer.kind == core::PatternKind::Flame ? core::defaultFlame() : core::FlameGenome{};
        layer.julia = core::QuaternionJuliaSettings{};
        layer.color.mode = core::ColorMode::Index;
      } else {
        const core::AttractorInfo& info = core::attractorOrThrow(defaults.attractor);
        layer.attractor = info.id;
        layer.params = info.defaultParams();
        layer.step = info.defaultStep;
        layer.integrator = info.defaultIntegrator;
        layer.flame = {};
        layer.julia = {};
        if (layer.color.mode == core::ColorMode::Index) layer.color.mode = core::ColorMode::Speed;
      }
      state.selectedXform[index] = 0;
    }
    ImGui::EndCombo();
  }
  probe(state, scope + "pattern");
}

// The length of column `col` of the 3×3 part: how much the map stretches its own axis `col`.
double columnLength(const std::array<double, 12>& m, int col) {
  const auto c = static_cast<std::size_t>(col);
  return std::sqrt(m[c] * m[c] + m[4 + c] * m[4 + c] + m[8 + c] * m[8 + c]);
}

// rotation about x, then y, then z (degrees), as a 3×3 row-major matrix.
std::array<double, 9> eulerRotation(const double degrees[3]) {
  const double a = glm::radians(degrees[0]), b = glm::radians(degrees[1]), c = glm::radians(degrees[2]);
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b), cc = std::cos(c),
               sc = std::sin(c);
  // Rz · Ry · Rx
  return {cc * cb,
          cc * sb * sa - sc * ca,
          cc * sb * ca + sc * sa,  //
          sc * cb,
          sc * sb * sa + cc * ca,
          sc * sb * ca - cc * sa,  //
          -sb,
          cb * sa,
          cb * ca};
}

// Translate, rotate and scale handles for one affine map, then its 12 numbers on request. The
// rotate handle turns the matrix about the transform's own frame (M ← M · R), so its scales and
// offset stay; the scale handles set the length of each column of the 3×3 part.
void affineEditor(ExplorerState& state, const std::string& scope, core::Affine3& affine) {
  std::array<double, 12>& m = affine.m;
  double translate[3] = {m[3], m[7], m[11]};
  const double minT = -3.0, maxT = 3.0;
  if (ImGui::SliderScalarN("translate", ImGuiDataType_Double, translate, 3, &minT, &maxT, "%.3f", kClamp))
    m[3] = translate[0], m[7] = translate[1], m[11] = translate[2];
  probe(state, scope + "translate");

  const std::string rotateId = scope + "rotate";
  const bool rotatingThis = state.rotatingId == rotateId;
  double shown[3] = {0.0, 0.0, 0.0};
  if (rotatingThis) std::copy(std::begin(state.rotateAngles), std::end(state.rotateAngles), shown);
  const double minDeg = -180.0, maxDeg = 180.0;
  // Relative: each drag turns the map from where it is, so the handle reads +0° before and after one.
  const bool turned =
      ImGui::SliderScalarN("turn by", ImGuiDataType_Double, shown, 3, &minDeg, &maxDeg, "%+.0f°", kClamp);
  probe(state, rotateId);
  if (ImGui::IsItemActivated()) {
    state.rotatingId = rotateId;
    state.rotateStart = m;
  }
  if (turned && state.rotatingId == rotateId) {
    std::copy(std::begin(shown), std::end(shown), state.rotateAngles);
    const std::array<double, 9> r = eulerRotation(shown);
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 3; ++col) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k)
          sum += state.rotateStart[static_cast<std::size_t>(row * 4 + k)] * r[static_cast<std::size_t>(k * 3 + col)];
        m[static_cast<std::size_t>(row * 4 + col)] = sum;
      }
  }
  if (ImGui::IsItemDeactivated() && state.rotatingId == rotateId) {
    state.rotatingId.clear();
    if (m != state.rotateStart) {
      state.turnedId = rotateId;
      std::copy(std::begin(state.rotateAngles), std::end(state.rotateAngles), state.turnedAngles.begin());
      state.turnedResult = m;
    }
    std::fill(std::begin(state.rotateAngles), std::end(state.rotateAngles), 0.0);
  }
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
    ImGui::SetTooltip(
        "relative: drag to turn the map by so many degrees about its own x, y and z axes.\n"
        "Each drag starts at +0° and the turn stays when you let go (Ctrl+Z undoes it).");
  if (state.turnedId == rotateId && state.turnedResult == m && !rotatingThis) {
    dimText("turned by %+.0f°, %+.0f°, %+.0f° (Ctrl+Z undoes)", state.turnedAngles[0], state.turnedAngles[1],
            state.turnedAngles[2]);
    probe(state, scope + "turned");
  }

  double scales[3] = {columnLength(m, 0), columnLength(m, 1), columnLength(m, 2)};
  const double minS = 0.01, maxS = 2.0;
  // Absolute, unlike the turn: each value is the length of one axis of the map, and stays as dragged.
  if (ImGui::SliderScalarN("axis lengths", ImGuiDataType_Double, scales, 3, &minS, &maxS, "%.3f", kClamp))
    for (int col = 0; col < 3; ++col) {
      const double length = columnLength(m, col);
      const auto c = static_cast<std::size_t>(col);
      if (length > 1e-12) {
        const double factor = scales[col] / length;
        m[c] *= factor, m[4 + c] *= factor, m[8 + c] *= factor;
      } else {  // a collapsed axis comes back along itself
        m[c] = m[4 + c] = m[8 + c] = 0.0;
        m[static_cast<std::size_t>(col * 4 + col)] = scales[col];
      }
    }
  probe(state, scope + "scale");
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
    ImGui::SetTooltip("absolute: the length of the map's x, y and z axes (1 keeps a length; under 1 contracts)");

  if (ImGui::TreeNode("numbers")) {
    static constexpr const char* kRows[] = {"x' = x y z 1", "y' = x y z 1", "z' = x y z 1"};
    const double minV = -100.0, maxV = 100.0;
    for (int row = 0; row < 3; ++row) {
      ImGui::DragScalarN(kRows[row], ImGuiDataType_Double, &m[static_cast<std::size_t>(row * 4)], 4, 0.002f, &minV,
                         &maxV, "%.3f", kClamp);
      probe(state, scope + "row" + std::to_string(row));
    }
    ImGui::TreePop();
  }
}

// A transform's variations: weight and parameter sliders each, remove buttons, and a filterable
// list of the whole catalogue to add from.
void variationsEditor(ExplorerState& state, const std::string& scope, core::FlameXform& xform) {
  std::size_t removeIndex = xform.variations.size();
  for (std::size_t v = 0; v < xform.variations.size(); ++v) {
    core::VariationTerm& term = xform.variations[v];
    const core::VariationInfo* info = core::findVariation(term.name);
    const std::string vscope = scope + "var" + std::to_string(v) + "/";
    ImGui::PushID(static_cast<int>(v));
    // The weight slider is labelled with the variation's name; its formula is the tooltip.
    const double minW = -2.0, maxW = 2.0;
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemSpacing.x);
    ImGui::SliderScalar((term.name + "##weight").c_str(), ImGuiDataType_Double, &term.weight, &minW, &maxW,
                        "weight %.3f", kClamp);
    probe(state, vscope + "weight");
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive() && info) ImGui::SetTooltip("%s", info->formula.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) removeIndex = v;
    probe(state, vscope + "remove");
    if (info && term.params.size() == info->params.size()) {
      ImGui::Indent();
      for (std::size_t p = 0; p < info->params.size(); ++p) {
        const core::VariationParam& param = info->params[p];
        const std::string label = term.name + " " + param.name;
        ImGui::PushID(static_cast<int>(p));
        if (param.integer) {
          int value = static_cast<int>(std::lround(term.params[p]));
          if (ImGui::SliderInt(label.c_str(), &value, static_cast<int>(std::ceil(param.sliderMin)),
                               static_cast<int>(std::floor(param.sliderMax)), "%d", kClamp))
            term.params[p] = value;
        } else {
          ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &term.params[p], &param.sliderMin, &param.sliderMax,
                              "%.3f", kClamp);
        }
        probe(state, vscope + param.name);
        if (ImGui::BeginPopupContextItem()) {
          if (ImGui::Selectable("Reset to default")) term.params[p] = param.defaultValue;
          ImGui::EndPopup();
        }
        if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
          ImGui::SetTooltip("default %.4g — right-click to reset", param.defaultValue);
        ImGui::PopID();
      }
      ImGui::Unindent();
    }
    ImGui::PopID();
  }
  if (removeIndex < xform.variations.size())
    xform.variations.erase(xform.variations.begin() + static_cast<std::ptrdiff_t>(removeIndex));

  ImGui::BeginDisabled(xform.variations.size() >= core::kMaxXformVariations);
  if (ImGui::BeginCombo("add variation", "choose…", ImGuiComboFlags_HeightLarge)) {
    if (ImGui::IsWindowAppearing()) {
      state.variationFilter[0] = '\0';
      ImGui::SetKeyboardFocusHere();
    }
    ImGui::InputTextWithHint("##variationfilter", "filter", state.variationFilter, sizeof state.variationFilter);
    noteTyped(state, "variation filter", state.variationFilter);
    const std::string filter = lowercase(state.variationFilter);
    for (const core::VariationInfo& info : core::variationCatalogue()) {
      if (!filter.empty() && lowercase(info.name).find(filter) == std::string::npos) continue;
      const bool chosen = ImGui::Selectable(info.name.c_str());
      probe(state, scope + "add/" + info.name);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", info.formula.c_str());
      if (chosen) {
        // A new term starts small, so adding one bends the flame rather than replacing it.
        xform.variations.push_back({info.name, xform.variations.empty() ? 1.0 : 0.25, info.defaultParams()});
      }
    }
    ImGui::EndCombo();
  }
  probe(state, scope + "add variation");
  ImGui::EndDisabled();
}

// Xaos (flam3's chaos) as a matrix: row i is transform i's xaos, and its cell in column j scales
// transform j's weight when the transform after i is chosen (1 is no xaos, 0 forbids the step). A
// missing factor is 1. The final transform has no row or column: flam3 gives it no xaos. Each
// cell is an ordinary ImGui item, so handleHistory records a whole drag as one undo step.
//
// ImGui 1.86 tables hold at most 64 columns (IMGUI_TABLE_MAX_COLUMNS) and a flame up to 128
// transforms, so wide flames show their "to" columns a page at a time.
constexpr std::size_t kXaosColumnsPerPage = 32;
constexpr std::size_t kXaosVisibleRows = 8;  // taller matrices scroll, their header row frozen
constexpr double kXaosMin = 0.0, kXaosMax = 5.0;

double xaosFactor(const core::FlameXform& from, std::size_t to) {
  return to < from.xaos.size() ? from.xaos[to] : 1.0;
}

// A cell's tint: red where the step is forbidden, blue where it is less likely, amber where it is
// more likely; none at 1, so a flame without xaos shows a plain matrix.
ImU32 xaosCellColor(double factor) {
  if (factor == 0.0) return IM_COL32(180, 50, 40, 120);
  return factor < 1.0 ? IM_COL32(50, 100, 190, 110) : IM_COL32(200, 150, 30, 110);
}

// The "to" columns shown: all of them, or for flames wider than a page the page chosen in a combo.
std::pair<std::size_t, std::size_t> xaosColumnPage(ExplorerState& state, std::size_t index, const std::string& scope,
                                                   std::size_t count) {
  if (count <= kXaosColumnsPerPage) return {0, count};
  const auto pageLabel = [count](std::size_t page) {
    const std::size_t first = page * kXaosColumnsPerPage;
    return "to " + std::to_string(first + 1) + "–" + std::to_string(std::min(count, first + kXaosColumnsPerPage));
  };
  const std::size_t pages = (count + kXaosColumnsPerPage - 1) / kXaosColumnsPerPage;
  std::size_t& page = state.xaosColumnPage[index];
  page = std::min(page, pages - 1);  // the flame may have lost transforms since
  if (ImGui::BeginCombo("columns", pageLabel(page).c_str())) {
    for (std::size_t p = 0; p < pages; ++p) {
      const std::string label = pageLabel(p);
      if (ImGui::Selectable(label.c_str(), p == page)) page = p;
      probe(state, scope + "xaos columns/" + label);
    }
    ImGui::EndCombo();
  }
  probe(state, scope + "xaos columns");
  const std::size_t first = page * kXaosColumnsPerPage;
  return {first, std::min(count, first + kXaosColumnsPerPage)};
}

// The matrix under an "Xaos" tree node: a row per transform (named by number, as the transform
// buttons name them, the selected one highlighted) with its reset button, a column per transform,
// and a reset for the whole matrix. Cells are probed as "xaos <from> to <to>", both 1-based.
void xaosMatrix(ExplorerState& state, std::size_t index, const std::string& scope, core::FlameGenome& flame,
                int selected) {
  const bool open = ImGui::TreeNode("Xaos");
  probe(state, scope + "Xaos");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("row: the transform just applied; column: the next one, chosen by its weight times this factor");
  if (!open) return;
  const std::size_t count = flame.xforms.size();
  const auto [firstColumn, endColumn] = xaosColumnPage(state, index, scope, count);

  const ImGuiStyle& style = ImGui::GetStyle();
  const float cellWidth = ImGui::CalcTextSize("0.000").x + 2.0f * style.FramePadding.x;
  const float rowHeight = ImGui::GetFrameHeight() + 2.0f * style.CellPadding.y;
  // Room for the header, up to kXaosVisibleRows rows and a horizontal scroll bar.
  const float height = ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y +
                       rowHeight * static_cast<float>(std::min(count, kXaosVisibleRows)) + style.ScrollbarSize;
  constexpr ImGuiTableFlags kFlags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY;
  // The transform's number and its reset button stay in view while the factors scroll.
  constexpr int kFrozenColumns = 2;
  const int columns = kFrozenColumns + static_cast<int>(endColumn - firstColumn);
  if (ImGui::BeginTable("xaos matrix", columns, kFlags, ImVec2(0.0f, height))) {
    ImGui::TableSetupScrollFreeze(kFrozenColumns, 1);
    ImGui::TableSetupColumn("from\\to");
    ImGui::TableSetupColumn("##reset");
    for (std::size_t to = firstColumn; to < endColumn; ++to)
      ImGui::TableSetupColumn(std::to_string(to + 1).c_str(), ImGuiTableColumnFlags_WidthFixed, cellWidth);
    ImGui::TableHeadersRow();
    for (std::size_t from = 0; from < count; ++from) {
      core::FlameXform& row = flame.xforms[from];
      const std::string fromName = std::to_string(from + 1);
      ImGui::PushID(static_cast<int>(from));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(fromName.c_str());
      if (static_cast<int>(from) == selected)
        ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, ImGui::GetColorU32(ImGuiCol_Header));
      ImGui::TableNextColumn();
      ImGui::BeginDisabled(row.xaos.empty());
      if (ImGui::SmallButton("reset")) row.xaos.clear();
      probe(state, scope + "xaos reset " + fromName);
      ImGui::EndDisabled();
      for (std::size_t to = firstColumn; to < endColumn; ++to) {
        ImGui::TableNextColumn();
        ImGui::PushID(static_cast<int>(to));
        double factor = xaosFactor(row, to);
        ImGui::SetNextItemWidth(-FLT_MIN);
        if (ImGui::DragScalar("##factor", ImGuiDataType_Double, &factor, 0.01f, &kXaosMin, &kXaosMax, "%.2f", kClamp)) {
          if (row.xaos.size() <= to) row.xaos.resize(to + 1, 1.0);
          row.xaos[to] = factor;
        }
        const std::string toName = std::to_string(to + 1);
        probe(state, scope + "xaos " + fromName + " to " + toName);
        if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
          ImGui::SetTooltip("after %s, %s's weight × %.3f (0: never) — drag, or double-click to type", fromName.c_str(),
                            toName.c_str(), factor);
        if (factor != 1.0) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, xaosCellColor(factor));
        ImGui::PopID();
      }
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  const bool anyXaos =
      std::any_of(flame.xforms.begin(), flame.xforms.end(), [](const core::FlameXform& x) { return !x.xaos.empty(); });
  ImGui::BeginDisabled(!anyXaos);
  if (button(state, scope, "Reset xaos"))
    for (core::FlameXform& x : flame.xforms) x.xaos.clear();
  ImGui::EndDisabled();
  ImGui::TreePop();
}

// One transform: weight (not for the final one), colour, colour speed, opacity, the affine map
// and an optional post map, the variations. Its xaos is a row of the flame's xaos matrix.
void xformEditor(ExplorerState& state, const std::string& scope, core::FlameXform& xform, bool isFinal) {
  if (!isFinal) fieldWidget(state, scope, xform, core::xformFields(), "weight");
  fieldWidget(state, scope, xform, core::xformFields(), "color");
  fieldWidget(state, scope, xform, core::xformFields(), "color_speed");
  fieldWidget(state, scope, xform, core::xformFields(), "opacity");
  affineEditor(state, scope, xform.affine);
  ImGui::Checkbox("post-affine", &xform.hasPost);
  probe(state, scope + "post-affine");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a second affine map applied after the variations");
  if (xform.hasPost) {
    ImGui::PushID("post");
    ImGui::Indent();
    affineEditor(state, scope + "post/", xform.post);
    ImGui::Unindent();
    ImGui::PopID();
  }
  ImGui::Separator();
  dimText("variations");
  variationsEditor(state, scope, xform);
}

void flameEditor(ExplorerState& state, std::size_t index, const std::string& scope, core::FlameGenome& flame) {
  int& selected = state.selectedXform[index];
  if (selected >= static_cast<int>(flame.xforms.size()) || (selected < 0 && !flame.hasFinal)) selected = 0;
  // The transform selector: one button per transform, then the final one.
  dimText("transform");
  // Up to 128 transforms: 16 buttons a row.
  constexpr std::size_t kButtonsPerRow = 16;
  for (std::size_t i = 0; i < flame.xforms.size(); ++i) {
    if (i == 0 || i % kButtonsPerRow != 0) ImGui::SameLine();
    const std::string label = std::to_string(i + 1);
    if (ImGui::Selectable(label.c_str(), selected == static_cast<int>(i), 0, ImVec2(ImGui::GetFrameHeight(), 0)))
      selected = static_cast<int>(i);
    probe(state, scope + "xform " + label);
  }
  if (flame.hasFinal) {
    ImGui::SameLine();
    if (ImGui::Selectable("final", selected < 0, 0, ImVec2(ImGui::CalcTextSize("final").x, 0))) selected = -1;
    probe(state, scope + "xform final");
  }
  const bool full = flame.xforms.size() >= core::kMaxFlameXforms;
  ImGui::BeginDisabled(full);
  if (button(state, scope, "Add transform")) {
    flame.xforms.push_back(
        core::randomTransform(state.searchSeed++, std::fmod(0.37 * static_cast<double>(flame.xforms.size()), 1.0)));
    selected = static_cast<int>(flame.xforms.size()) - 1;
  }
  ImGui::SameLine();
  if (button(state, scope, "Duplicate") && selected >= 0) {
    const auto at = static_cast<std::size_t>(selected);
    flame.xforms.insert(flame.xforms.begin() + selected + 1, flame.xforms[at]);
    // Xaos columns follow the transforms: the copy is followed as often as its original.
    for (core::FlameXform& x : flame.xforms)
      if (x.xaos.size() > at) x.xaos.insert(x.xaos.begin() + selected + 1, x.xaos[at]);
    ++selected;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(selected >= 0 && flame.xforms.size() <= 1);
  if (button(state, scope, "Remove")) {
    if (selected < 0) {
      flame.hasFinal = false;
      selected = 0;
    } else if (flame.xforms.size() > 1) {
      flame.xforms.erase(flame.xforms.begin() + selected);
      for (core::FlameXform& x : flame.xforms)
        if (x.xaos.size() > static_cast<std::size_t>(selected)) x.xaos.erase(x.xaos.begin() + selected);
      selected = std::min(selected, static_cast<int>(flame.xforms.size()) - 1);
    }
  }
  ImGui::EndDisabled();
  if (ImGui::Checkbox("final transform", &flame.hasFinal)) {
    if (flame.hasFinal) {
      if (flame.finalXform.variations.empty()) flame.finalXform.variations = {{"linear", 1.0, {}}};
      selected = -1;
    } else if (selected < 0) {
      selected = 0;
    }
  }
  probe(state, scope + "final transform");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("bends what is drawn without feeding back into the iteration");

  const std::string xscope = scope + (selected < 0 ? "final/" : "xform/");
  ImGui::PushID(selected);
  core::FlameXform& xform = selected < 0 ? flame.finalXform : flame.xforms[static_cast<std::size_t>(selected)];
  xformEditor(state, xscope, xform, selected < 0);
  ImGui::PopID();
  // With one transform every factor leads back to it (a 0 falls back to the plain weights).
  if (flame.xforms.size() > 1) xaosMatrix(state, index, scope, flame, selected);

  if (ImGui::TreeNode("Symmetry")) {
    core::FlameSymmetry& symmetry = flame.symmetry;
    fieldWidget(state, scope, symmetry, core::symmetryFields(), "rotational");
    fieldWidget(state, scope, symmetry, core::symmetryFields(), "mirror");
    const std::string axisProbe = scope + "symmetry axis";
    fieldWidget(state, scope, symmetry, core::symmetryFields(), "axis", axisProbe.c_str());
    ImGui::TreePop();
  }
}

void juliaEditor(ExplorerState& state, const std::string& scope, core::QuaternionJuliaSettings& julia) {
  static constexpr const char* kComponents[] = {"c (1)", "c (i)", "c (j)", "c (k)"};
  for (int i = 0; i < 4; ++i) slider(state, scope, kComponents[i], julia.c[i], -1.5, 1.5, kClamp, "%.4f");
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
    if (slider(state, scope, param.name.c_str(), layer.params[p], param.sliderMin, param.sliderMax, 0, "%.4f"))
      layer.params[p] =
          std::isfinite(layer.params[p]) ? std::clamp(layer.params[p], -kParamLimit, kParamLimit) : param.defaultValue;
    markIfKeyed(state, valuePath(scope, "params/" + param.name), scope + param.name);
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
    fieldWidget(state, scope, layer, core::layerFields(), "step");
  }
  if (button(state, scope, "Reset parameters")) {
    layer.params = current.defaultParams();
    layer.step = current.defaultStep;
    layer.integrator = current.defaultIntegrator;
  }
}

void layerEditor(ExplorerState& state, std::size_t index, bool& removeThis) {
  core::PatternLayer& layer = state.scene.layers[index];
  const std::string scope = "layer" + std::to_string(index) + "/";
  const core::PatternKind kindBefore = layer.kind;
  patternKindChoice(state, index, scope, layer);
  if (layer.kind != kindBefore) return;  // the new kind's widgets from the next frame
  switch (layer.kind) {
    case core::PatternKind::Attractor:
      attractorEditor(state, scope, layer);
      break;
    case core::PatternKind::Flame:
      ImGui::Checkbox("flat view (as flam3 renders it)", &state.flatView);
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
  if (state.scene.layers.size() > 1) {
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
      if (ImGui::SliderScalarN(label.c_str(), ImGuiDataType_Double, angles, 3, &minDeg, &maxDeg, "%.0f°", kClamp))
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
  state.layout.left = ImGui::IsWindowCollapsed() ? 0.0f : ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  ImGui::PushItemWidth(-110 * scale);
  std::size_t removeIndex = state.scene.layers.size();
  for (std::size_t li = 0; li < state.scene.layers.size(); ++li) {
    const core::PatternLayer& shown = state.scene.layers[li];
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
    if (button(state, "", "Search (F3)")) startSearch(state, 0.1, true);
    if (ImGui::IsItemHovered() && !state.scene.layers.empty() && state.scene.layers.front().isChaosGame())
      ImGui::SetTooltip("a new random pattern of this kind that fills its box");
    ImGui::SameLine();
    if (button(state, "", "Mutate")) startSearch(state, state.mutateStrength, false);
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
      dimText("no history yet");
    else
      dimText("%zu of %zu (Alt+Left/Right)", state.visitedIndex + 1, state.visited.size());
    if (state.search.busy()) {
      if (state.searchTried && state.searchStrength)
        dimText("searching at strength %.2g: %d tried", state.searchStrength->load(), state.searchTried->load());
      else
        dimText("searching…");
      if (button(state, "explore/", "Cancel search")) {
        state.search.cancel();
        state.searchMessage = state.searchTried
                                  ? "search cancelled after " + std::to_string(state.searchTried->load()) + " tries"
                                  : std::string("search cancelled");
      }
    } else if (!state.searchMessage.empty())
      ImGui::TextWrapped("%s", state.searchMessage.c_str());
    // The message itself is the notice's, at the top of the view: one message, said once.
    if (!state.session.escapeNote.empty()) {
      if (button(state, "", "Find a nearby one")) startSearch(state, 0.1, false);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("a bounded pattern close to this one (Mutate at strength 0.1)");
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
  noteTyped(state, "mesh path", state.meshPath);
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
  dimText("or drop a mesh, preset or PNG onto the window");

  // The grid only changes when the slider is let go: each change rebuilds the mask.
  int& draft = state.gridDraft;
  if (!ImGui::IsAnyItemActive() || draft == 0) draft = state.scene.gridResolution;
  const core::Field<core::Scene>& grid = core::field(core::sceneFields(), "grid.resolution");
  ImGui::SliderInt(std::string(grid.ui.label).c_str(), &draft, static_cast<int>(grid.ui.min),
                   static_cast<int>(grid.ui.max), std::string(grid.ui.format).c_str(), ImGuiSliderFlags_AlwaysClamp);
  probe(state, "mesh/grid");
  if (ImGui::IsItemDeactivatedAfterEdit()) state.scene.gridResolution = draft;
  // What a session on the grid over this mesh holds (a cube before the first shape is ready).
  core::GridGeometry draftGrid;
  try {
    const core::Box box =
        state.session.hasShape ? state.session.grid.box() : core::Box{glm::dvec3(0.0), glm::dvec3(1.0)};
    draftGrid = core::gridOverBox(box, std::clamp(draft, core::kMinGridResolution, core::kMaxGridResolution));
  } catch (const core::Error&) {
    draftGrid.size = glm::ivec3(std::max(draft, 1));
  }
  dimText("about %s of memory", formatBytes(static_cast<double>(ExplorerSession::estimatedBytes(draftGrid))).c_str());

  core::RenderSettingsDoc& render = state.scene.render;
  fieldWidget(state, "mesh/", render, core::renderFields(), "mesh");
  fieldWidget(state, "mesh/", render, core::renderFields(), "mesh_color");
  fieldWidget(state, "mesh/", render, core::renderFields(), "mesh_strength");
}

void renderSection(ExplorerState& state) {
  core::ToneMapSettings& tone = state.scene.tone;
  for (std::string_view key :
       {"brightness", "gamma", "gamma_threshold", "vibrancy", "highlight_power", "exposure", "contrast", "opacity",
        "estimator_radius", "estimator_minimum", "estimator_curve", "background"})
    fieldWidget(state, "tone/", tone, core::toneFields(), key);
  core::RenderSettingsDoc& render = state.scene.render;
  fieldWidget(state, "render/", render, core::renderFields(), "step");
  fieldWidget(state, "render/", render, core::renderFields(), "method", "render/method");
  fieldWidget(state, "render/", render, core::renderFields(), "oversample");
  fieldWidget(state, "render/", render, core::renderFields(), "filter_radius");
  if (render.method == core::RenderMethod::Points)
    for (std::string_view key : {"dof.aperture", "dof.focus_distance", "fog"})
      fieldWidget(state, "render/", render, core::renderFields(), key);
  fieldWidget(state, "render/", render, core::renderFields(), "lighting");
  if (render.lighting)
    for (std::string_view key : {"light_azimuth_deg", "light_elevation_deg", "light_strength"})
      fieldWidget(state, "render/", render, core::renderFields(), key);
  ImGui::SliderFloat("preview scale", &state.renderScale, 0.25f, 1.0f, "%.2f");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "fraction of the window's pixels marched while the view is still (playback goes as sharp as "
        "the frame budget allows)");
  ImGui::SliderFloat("frame budget", &state.frameBudgetMs, 8.0f, 200.0f, "%.0f ms");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("while you edit, orbit or play, as many pixels are marched as keep frames this quick");
  // 0 reads "never": the slider's left end is refining until the next edit.
  double& stopAt = state.settings.refineUntilNoisePercent;
  const double low = 0.0, high = 10.0;
  ImGui::SliderScalar("stop refining at noise", ImGuiDataType_Double, &stopAt, &low, &high,
                      stopAt <= 0.0 ? "at the cap" : "%.2f%%", ImGuiSliderFlags_Logarithmic);
  probe(state, "render/stop_refining_at_noise");
  stopAt = std::clamp(stopAt, 0.0, 100.0);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "the volume stops refining (and the explorer rests) once two measurements of its noise in a row are this\n"
        "low, or at the grid's cap of points per voxel, whichever comes first; a lower target refines on from\n"
        "the points already there");
}

void cameraSection(ExplorerState& state) {
  core::CameraSettings& camera = state.scene.camera;
  for (std::string_view key : {"azimuth_deg", "elevation_deg", "roll_deg", "distance", "fov_deg"})
    fieldWidget(state, "camera/", camera, core::cameraFields(), key);
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
  dimText("drag: orbit · right/middle drag: pan · wheel: zoom · W/A/S/D/Q/E: fly");
}

void presetsSection(ExplorerState& state, float scale) {
  if (!state.presets) return;
  const PresetLibrary::Entries entries = state.presets->entries();
  // Saving comes first, so it stays in reach however long the library grows.
  ImGui::InputTextWithHint("##savename", "name of your preset", state.saveName, sizeof state.saveName);
  noteTyped(state, "preset name", state.saveName);
  probe(state, "preset/name");
  ImGui::SameLine();
  if (button(state, "preset/", "Save as") && state.saveName[0] != '\0') state.requests.saveAs = state.saveName;
  ImGui::SameLine();
  if (button(state, "preset/", "Refresh")) state.presets->refresh();
  if (!state.presetMessage.empty()) ImGui::TextWrapped("%s", state.presetMessage.c_str());
  if (state.presets->busy()) dimText("reading presets…");
  if (entries) {
    const float size = 92 * scale;
    const int columns = std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / (size + 8 * scale)));
    int column = 0;
    PresetSource lastSource = PresetSource::Shipped;
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const PresetEntry& entry = (*entries)[i];
      if (i == 0 || entry.source != lastSource) {
        dimText(entry.source == PresetSource::Shipped ? "shipped" : "yours (%s)",
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
  dimText("method: %s (Render panel)", std::string(core::toString(state.scene.render.method)).c_str());
  int format = static_cast<int>(settings.format);
  if (ImGui::Combo("format", &format, "PNG 8-bit\0PNG 16-bit\0EXR (linear float)\0"))
    settings.format = static_cast<ExportFormat>(format);
  // The file is named after the document, and follows it (a save-as renames it) until typed over.
  if (state.exportPath[0] == '\0' || state.exportPathMade == state.exportPath) {
    const std::filesystem::path folder =
        state.settings.lastExportFolder.empty() ? std::filesystem::current_path() : state.settings.lastExportFolder;
    const std::string path = (folder / (sanitizePresetName(state.scene.name) + extensionOf(settings.format))).string();
    std::snprintf(state.exportPath, sizeof state.exportPath, "%s", path.c_str());
    state.exportPathMade = state.exportPath;
  }
  ImGui::InputText("file", state.exportPath, sizeof state.exportPath);
  noteTyped(state, "export file", state.exportPath);
  probe(state, "export/file");
  if (state.viewRect.z > 0 && state.viewRect.w > 0) {
    ImGui::SameLine();
    if (button(state, "export/", "view size")) {
      settings.width = std::clamp(state.viewRect.z, 16, 65536);
      settings.height = std::clamp(state.viewRect.w, 16, 65536);
    }
  }
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
    ExportRequest request;
    request.scene = state.scene;
    request.settings = settings;
    request.output = withExtensionFor(state.exportPath, settings.format);
    request.executable = state.executable;
    const bool madePath = state.exportPathMade == state.exportPath;
    std::snprintf(state.exportPath, sizeof state.exportPath, "%s", request.output.string().c_str());
    if (madePath) state.exportPathMade = state.exportPath;
    std::error_code error;
    if (std::filesystem::exists(request.output, error))
      state.exportToConfirm = std::move(request);  // asked below first
    else
      state.requests.exportStill = std::move(request);
  }
  if (state.exportToConfirm) {
    ImGui::TextColored(kErrorColor, "%s exists.", state.exportToConfirm->output.filename().string().c_str());
    ImGui::SameLine();
    if (button(state, "export/", "Replace it")) {
      state.requests.exportStill = std::move(*state.exportToConfirm);
      state.exportToConfirm.reset();
    }
    ImGui::SameLine();
    if (state.exportToConfirm && button(state, "export/", "Keep it")) state.exportToConfirm.reset();
  }
  if (status.state == ExportState::Done) ImGui::TextWrapped("wrote %s", status.output.string().c_str());
  if (status.state == ExportState::Failed) ImGui::TextColored(kErrorColor, "%s", status.error.c_str());
  if (status.state == ExportState::Cancelled) dimText("cancelled; nothing was written");
}

}  // namespace

void startExport(ExplorerState& state, ExportJob& job, const ExportRequest& request) {
  try {
    state.settings.lastExportFolder = std::filesystem::absolute(request.output).parent_path();
    job.start(request);
    state.exportStatus = job.poll();
  } catch (const core::Error& e) {
    state.notice = e.what();
  }
}

namespace {

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

// "Which flame?": the flames of a file opened with several, by name (filtered by words), to import
// one; Escape or Cancel imports none.
void flameChoiceWindow(ExplorerState& state, float scale) {
  if (!state.flameChoice) return;
  ExplorerState::FlameChoice& choice = *state.flameChoice;
  constexpr const char* kTitle = "Which flame?";
  if (!ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.45f * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(440 * scale, 0));
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings)) return;
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
      const core::FlameFileContents contents = importFlameScene(choice.path, state.scene, options, scene);
      applyImportedFlame(state, choice.path, contents, scene);
    } catch (const core::Error& e) {
      state.notice = e.what();
    }
  }
  if (chosen || cancel) {
    state.flameChoice.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// Quitting with unsaved changes: save them (as the user's preset of the document's name), throw
// them away, or stay. S, D and Escape answer from the keyboard.
void quitPromptWindow(ExplorerState& state, float scale) {
  if (!state.quitPrompt) return;
  constexpr const char* kTitle = "Unsaved changes";
  if (!ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.4f * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(420 * scale, 0));
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings)) return;
  ImGui::TextWrapped("\"%s\" has changes that are not saved. Save them before quitting?", state.scene.name.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  ImGui::TextWrapped(
      "Save keeps them as your preset \"%s\", replacing one of that name. S saves, D discards, "
      "Escape cancels.",
      state.scene.name.c_str());
  ImGui::PopStyleColor();
  const bool typing = io.WantTextInput;
  const bool save = button(state, "quit/", "Save") || (!typing && ImGui::IsKeyPressed('S', false));
  ImGui::SameLine();
  const bool discard = button(state, "quit/", "Discard") || (!typing && ImGui::IsKeyPressed('D', false));
  ImGui::SameLine();
  const bool cancel = button(state, "quit/", "Cancel") || ImGui::IsKeyPressed(kKeyEscape, false);
  if (save) {
    state.requests.saveAs = state.scene.name;
    state.requests.saveReplacing = true;
    state.quitAfterSave = true;
  } else if (discard) {
    state.requests.quit = true;
  }
  if (save || discard || cancel) {
    state.quitPrompt = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// The view's rectangle in window coordinates (from the top), from framebuffer pixels from the bottom.
ImVec4 viewRectInWindow(const ExplorerState& state, glm::dvec4 rect) {
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 scale = io.DisplayFramebufferScale;
  return ImVec4(static_cast<float>(state.viewRect.x + rect.x) / scale.x,
                io.DisplaySize.y - static_cast<float>(state.viewRect.y + rect.y + rect.w) / scale.y,
                static_cast<float>(state.viewRect.x + rect.x + rect.z) / scale.x,
                io.DisplaySize.y - static_cast<float>(state.viewRect.y + rect.y) / scale.y);
}

// While the pattern escapes the view keeps the last bounded picture, dimmed: it is not the
// pattern the sliders say.
void dimLastBoundedPicture(const ExplorerState& state) {
  if (!state.session.showingLastBounded || state.viewRect.z <= 0 || state.viewRect.w <= 0) return;
  const ImVec4 r = viewRectInWindow(state, glm::dvec4(0.0, 0.0, state.viewRect.z, state.viewRect.w));
  ImGui::GetBackgroundDrawList()->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.z, r.w), IM_COL32(0, 0, 0, 140));
}

// Where the export's picture lies in the view, when its aspect is not the view's: a thin frame.
void drawExportFrame(const ExplorerState& state) {
  const ExportSettings& settings = state.settings.lastExport;
  if (state.viewRect.z <= 0 || state.viewRect.w <= 0 || settings.width <= 0 || settings.height <= 0) return;
  const double viewAspect = static_cast<double>(state.viewRect.z) / state.viewRect.w;
  const double aspect = static_cast<double>(settings.width) / settings.height;
  if (std::abs(aspect / viewAspect - 1.0) < 0.005) return;
  const ImVec4 r = viewRectInWindow(state, core::exportFrame(glm::dvec2(state.viewRect.z, state.viewRect.w), aspect));
  ImGui::GetBackgroundDrawList()->AddRect(ImVec2(r.x, r.y), ImVec2(r.z, r.w), IM_COL32(255, 255, 255, 110));
}

// The picture's rectangle: between the side panels, above the Timeline, in framebuffer pixels.
void placeView(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float left = std::clamp(state.layout.left, 0.0f, io.DisplaySize.x);
  const float right =
      std::clamp(state.layout.right > left ? state.layout.right : io.DisplaySize.x, left, io.DisplaySize.x);
  const float bottom =
      std::clamp(state.layout.bottom > 0.0f ? state.layout.bottom : io.DisplaySize.y - statusBarHeight(scale), 0.0f,
                 io.DisplaySize.y);
  const ImVec2 toPixels = io.DisplayFramebufferScale;
  const int x = static_cast<int>(std::lround(left * toPixels.x));
  const int width = static_cast<int>(std::lround(right * toPixels.x)) - x;
  const int height = static_cast<int>(std::lround(bottom * toPixels.y));
  const int fromBottom = static_cast<int>(std::lround(io.DisplaySize.y * toPixels.y)) - height;
  state.viewRect = width > 0 && height > 0 ? glm::ivec4(x, fromBottom, width, height) : glm::ivec4(0);
}

void viewWindow(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  // Docked at the right, full height above the status line; only its width is the user's.
  const float height = io.DisplaySize.y - statusBarHeight(scale);
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x, 0), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(320 * scale, height), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(260 * scale, height), ImVec2(0.4f * io.DisplaySize.x, height));
  ImGui::Begin("Scene", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove);
  state.layout.right = ImGui::IsWindowCollapsed() ? io.DisplaySize.x : ImGui::GetWindowPos().x;
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

}  // namespace

std::string convergenceText(const SessionStatus& status) {
  if (!status.hasShape) return "";
  if (!status.escapeNote.empty()) return status.escapeNote;  // nothing refines: this is the news
  char text[200];
  const double noise = 100.0 * status.noise, target = 100.0 * status.noiseTarget;
  const double millions = static_cast<double>(status.stats.points) * 1e-6;
  if (status.paused)
    std::snprintf(text, sizeof text, "refining paused for the export");
  else if (status.converged)
    std::snprintf(text, sizeof text, "at rest: the noise reached its target (%.2g%% of %.2g%%)", noise, target);
  else if (status.capped)
    std::snprintf(text, sizeof text, "at rest: the cap of %.0f points per voxel (noise %.2g%%)",
                  status.capPointsPerVoxel, noise);
  else if (!std::isfinite(noise))
    std::snprintf(text, sizeof text, "refining: %.0f M points, measuring the noise", millions);
  else if (status.noiseTarget > 0.0)
    std::snprintf(text, sizeof text, "refining: %.0f M points, noise %.2g%% of %.2g%%", millions, noise, target);
  else
    std::snprintf(text, sizeof text, "refining: %.0f M points, noise %.2g%%", millions, noise);
  return text;
}

double frameWaitSeconds(const ExplorerState& state, bool viewResting, int restingFrames) {
  if (state.exportStatus.state == ExportState::Running) return 0.1;
  const bool busy = state.playing || state.search.busy() || state.analysis.busy() || state.flatRender.busy() ||
                    state.flatImagePending || state.orbiting || state.panning;
  if (busy || !viewResting || !state.session.resting || restingFrames < 3) return 0.0;
  // Other threads do not wake the loop; this bounds how late it notices one that finished.
  return 0.5;
}

namespace {

void statusBar(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = statusBarHeight(scale);
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const core::AccumulatorStats& stats = state.session.stats;
  const FrameMetrics& m = state.metrics;
  // Words first: what is happening. The technical figures are one click (Stats) or a hover away.
  if (state.session.buildingShape)
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "%s %.1f s", state.session.shapeStage.c_str(),
                       state.session.shapeSeconds);
  else if (const std::string convergence = convergenceText(state.session); !convergence.empty())
    ImGui::TextUnformatted(convergence.c_str());
  char figures[400];
  std::snprintf(figures, sizeof figures,
                "%.1f M points  %.1f M/s  inside %.1f%%  reseeded %llu  |  %.0f fps  %.1f ms (worst %.0f)  upload "
                "%.1f ms  %d samples",
                static_cast<double>(stats.points) * 1e-6, stats.pointsPerSecond * 1e-6, 100.0 * stats.insideFraction(),
                static_cast<unsigned long long>(stats.escapes), m.fps, m.frameMs, m.worstFrameMs, m.uploadMs,
                state.samples);
  // While the pattern escapes, the figures are the last bounded pattern's (or none): say so.
  std::string details = state.session.showingLastBounded ? std::string("last bounded pattern: ") + figures : figures;
  if (m.changeToFrameMs >= 0.0) {
    std::snprintf(figures, sizeof figures, "  |  edit→frame %.0f ms (%d frames)", m.changeToFrameMs,
                  m.changeToFrameFrames);
    details += figures;
  }
  // The analysis of an orbit that escapes may read as a fixed point: the escape is what is true.
  if (!state.session.escapeNote.empty())
    details += "  |  escapes";
  else if (!state.lyapunovText.empty())
    details += "  |  " + state.lyapunovText;
  if (ImGui::IsItemHovered() && !state.showStats) ImGui::SetTooltip("%s", details.c_str());
  if ((state.session.converged || state.session.capped) && !state.session.buildingShape) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Refine further")) state.requests.refineFurther = true;
    probe(state, "status/refine_further");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("go on from the %.0f points per voxel already there to twice as many",
                        state.session.pointsPerVoxel);
  }
  ImGui::SameLine();
  if (ImGui::SmallButton(state.showStats ? "Hide stats###stats" : "Stats###stats")) state.showStats = !state.showStats;
  probe(state, "status/stats");
  if (state.showStats) {
    ImGui::SameLine();
    ImGui::TextColored(kDimColor, "%s", details.c_str());
  }
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
  if (!state.session.escapeNote.empty())
    addLine(state.session.showingLastBounded ? state.session.escapeNote
                                             : state.session.escapeNote + " — try Search (F3).");
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
    // Play stops at the end unless the animation loops (its loop box).
    if (core::animationLoops(state.scene) && length > 0.0)
      next = std::fmod(next, length);
    else
      next = length, state.playing = false;
  }
  showTime(state, next);
}

// An animated value's name for people: "/layers/0/params/a" reads "layer 1 a",
// "/camera/azimuth_deg" reads "camera azimuth deg".
std::string trackName(const std::string& path) {
  std::vector<std::string> parts;
  std::istringstream split(path);
  for (std::string part; std::getline(split, part, '/');)
    if (!part.empty()) parts.push_back(part);
  std::string name;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::string part = parts[i];
    if (part == "params" || part == "tone" || part == "render") continue;
    if (part == "layers" && i + 1 < parts.size() && std::all_of(parts[i + 1].begin(), parts[i + 1].end(), ::isdigit)) {
      part = "layer " + std::to_string(std::stoi(parts[++i]) + 1);
    }
    std::replace(part.begin(), part.end(), '_', ' ');
    name += (name.empty() ? "" : " ") + part;
  }
  return name.empty() ? path : name;
}

// What Key did: the values that got a key at `time` ("keyed layer 1 a, camera azimuth deg at 1.50 s").
std::string keyedText(const std::vector<core::KeyframeTrack>& before, const std::vector<core::KeyframeTrack>& after,
                      double time) {
  std::vector<std::string> keyed;
  for (const core::KeyframeTrack& track : after) {
    const auto old =
        std::find_if(before.begin(), before.end(), [&](const core::KeyframeTrack& t) { return t.path == track.path; });
    const bool keyedNow = std::any_of(track.keys.begin(), track.keys.end(),
                                      [&](const core::Keyframe& key) { return std::abs(key.time - time) < 1e-6; });
    if (keyedNow && (old == before.end() || !(old->keys == track.keys))) keyed.push_back(trackName(track.path));
  }
  char at[32];
  std::snprintf(at, sizeof at, " at %.2f s", time);
  if (keyed.empty()) return std::string("nothing changed to key") + at;
  std::string text = "keyed ";
  for (std::size_t i = 0; i < keyed.size() && i < 4; ++i) text += (i ? ", " : "") + keyed[i];
  if (keyed.size() > 4) text += " and " + std::to_string(keyed.size() - 4) + " more";
  return text + at;
}

void timelineWindow(ExplorerState& state, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  // Docked under the picture, between the side panels, above the status line.
  const float statusHeight = statusBarHeight(scale);
  const float left = state.layout.left, right = std::max(state.layout.right, left + 1.0f);
  // Room for up to four animated values' rows; more scroll.
  const auto rows = static_cast<float>(std::min<std::size_t>(state.scene.keyframes.size(), 4) + 1);
  const float height = 2 * ImGui::GetFrameHeightWithSpacing() + rows * ImGui::GetTextLineHeightWithSpacing() +
                       ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().WindowPadding.y +
                       ImGui::GetTextLineHeightWithSpacing();
  ImGui::SetNextWindowPos(ImVec2(left, io.DisplaySize.y - statusHeight), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(right - left, height), ImGuiCond_Always);
  ImGui::Begin("Timeline", nullptr,
               ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  state.layout.bottom = ImGui::GetWindowPos().y;
  core::Scene& scene = state.scene;
  const double length = timelineLength(scene);
  if (button(state, "timeline/", state.playing ? "Pause" : "Play")) {
    state.playing = !state.playing;
    // Play at the end starts over.
    if (state.playing && scene.animation.time >= length - 1e-9) showTime(state, 0.0);
  }
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
      const std::vector<core::KeyframeTrack> before = scene.keyframes;
      scene = core::withKeyframeAt(animated, scene, now);
      state.keyBase = scene;
      state.timelineMessage = keyedText(before, scene.keyframes, now);
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
  const core::Field<core::AnimationSettings>& durationField = core::field(core::animationFields(), "duration");
  double duration = scene.animation.duration;
  if (ImGui::DragScalar("duration", ImGuiDataType_Double, &duration, 0.05f, &durationField.ui.min,
                        &durationField.ui.max, duration > 0.0 ? std::string(durationField.ui.format).c_str() : "auto",
                        ImGuiSliderFlags_AlwaysClamp))
    scene.animation.duration = duration;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70 * scale);
  const core::Field<core::AnimationSettings>& fpsField = core::field(core::animationFields(), "fps");
  double fps = scene.animation.fps;
  if (ImGui::DragScalar("fps", ImGuiDataType_Double, &fps, 0.2f, &fpsField.ui.min, &fpsField.ui.max,
                        std::string(fpsField.ui.format).c_str(), ImGuiSliderFlags_AlwaysClamp))
    scene.animation.fps = fps;
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
  if (scene.keyframes.empty()) {
    dimText("no keyframes: move the time, change something, press Key");
  } else {
    if (!state.timelineMessage.empty()) dimText("%s", state.timelineMessage.c_str());
    // One row per animated value: its name, then its keys as ticks over the animation's length
    // (right of the names); a value with one key holds still.
    const float nameWidth = 170 * scale;
    for (const core::KeyframeTrack& track : scene.keyframes) {
      const bool holds = track.keys.size() == 1;
      const std::string name = trackName(track.path);
      ImGui::TextUnformatted(name.c_str());
      probe(state, "timeline/track/" + track.path);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", track.path.c_str());
      if (holds) {
        ImGui::SameLine();
        ImGui::TextColored(kDimColor, "(one key: holds still)");
        probe(state, "timeline/track/" + track.path + "/holds");
      }
      ImGui::SameLine(std::max(nameWidth, ImGui::GetCursorPosX()));
      const ImVec2 row = ImGui::GetCursorScreenPos();
      const float rowHeight = ImGui::GetTextLineHeight();
      const float rowLeft = row.x + 6 * scale, rowRight = std::max(rowLeft + 1.0f, max.x - grab * 0.5f);
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->AddLine(ImVec2(rowLeft, row.y + 0.5f * rowHeight), ImVec2(rowRight, row.y + 0.5f * rowHeight),
                    IM_COL32(110, 115, 130, 255));
      for (const core::Keyframe& key : track.keys) {
        const float x = rowLeft + static_cast<float>(key.time / std::max(length, 1e-9)) * (rowRight - rowLeft);
        draw->AddQuadFilled(ImVec2(x, row.y + 1), ImVec2(x + 4 * scale, row.y + 0.5f * rowHeight),
                            ImVec2(x, row.y + rowHeight - 1), ImVec2(x - 4 * scale, row.y + 0.5f * rowHeight),
                            IM_COL32(255, 190, 90, 255));
      }
      ImGui::Dummy(ImVec2(1, rowHeight));
    }
  }
  ImGui::End();
}

}  // namespace

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
