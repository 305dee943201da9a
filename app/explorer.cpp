#include "explorer.h"

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations, GLFW only the window.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <future>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "core/accumulator.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/lyapunov.h"
#include "core/packed_volume.h"
#include "core/shadow_volume.h"
#include "core/snapshot_publisher.h"
#include "gl/volume_renderer.h"
#include "pipeline.h"
#include "scene_history.h"

namespace voxflame::app {

namespace {

bool haveDisplay() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

int renderInsteadOfWindow(const core::Scene& scene) {
  const std::filesystem::path output = std::filesystem::absolute("voxflame-preview.png");
  std::cout << "voxflame: no display found (DISPLAY is not set); rendering the preset to " << output.string()
            << " instead" << std::endl;
  const StillResult result = renderStill(scene, StillOptions{});
  core::writePng(output, result.image, 8, stillMetadata(scene, result));
  std::cout << output.string() << std::endl;
  return 0;
}

// UI state is plain data owned here; the scene being edited is the single source of truth.
struct ExplorerState {
  core::Scene scene;
  core::CameraSettings initialCamera;
  float renderScale = 1.0f;  // fraction of the window's pixels the volume is marched at
  int samples = 0;
  bool patternDirty = false;
  bool dragging = false;
  double lastMouseX = 0.0, lastMouseY = 0.0;
  double frameMs = 0.0;
  char attractorFilter[64] = "";
  // Search (F3) and Mutate run off the main thread; their result replaces layer 0's parameters.
  std::future<std::vector<core::SearchResult>> search;
  std::uint64_t searchSeed = 1;
  double mutateStrength = 0.1;
  std::string searchMessage;
  // The Lyapunov spectrum of layer 0, analysed off the main thread whenever the pattern changes.
  std::future<core::OrbitAnalysis> analysis;
  std::string lyapunovText = "Lyapunov: …";
  std::optional<SceneHistory> history;  // undo/redo over the whole scene
};

// The part of a scene that the accumulation depends on; other edits only change the drawing.
std::string patternKey(const core::Scene& scene) {
  core::Scene pattern = scene;
  pattern.tone = {};
  pattern.camera = {};
  pattern.render = {};
  return core::sceneToJson(pattern);
}

// Ctrl+Z undoes, Ctrl+Shift+Z (or Ctrl+Y) redoes; an edit is recorded once it settles, so a
// whole slider drag or camera drag is one step.
void handleHistory(ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantTextInput && io.KeyCtrl &&
      (ImGui::IsKeyPressed(GLFW_KEY_Z, false) || ImGui::IsKeyPressed(GLFW_KEY_Y, false))) {
    const bool redo = io.KeyShift || ImGui::IsKeyPressed(GLFW_KEY_Y, false);
    if (auto scene = redo ? state.history->redo() : state.history->undo()) {
      if (patternKey(*scene) != patternKey(state.scene)) state.patternDirty = true;
      state.scene = *scene;
    }
    return;
  }
  const bool mouseHeld = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                         ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (!mouseHeld && !ImGui::IsAnyItemActive()) state.history->record(state.scene);
}

core::OrbitSpec layerSpec(const core::PatternLayer& layer) {
  core::OrbitSpec spec = core::defaultOrbitSpec(core::attractorOrThrow(layer.attractor));
  spec.params = layer.params;
  spec.integrator = layer.integrator;
  spec.step = layer.step;
  return spec;
}

void startAnalysis(ExplorerState& state) {
  if (state.analysis.valid()) state.analysis.wait();  // a short run (tens of ms); keeps one at a time
  const core::OrbitSpec spec = layerSpec(state.scene.layers.front());
  core::LyapunovOptions options;
  options.steps = 20'000;
  state.analysis = std::async(std::launch::async, [spec, options] { return core::analyseOrbit(spec, options); });
}

void collectAnalysis(ExplorerState& state) {
  if (!state.analysis.valid() || state.analysis.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  try {
    const core::OrbitAnalysis result = state.analysis.get();
    char text[128];
    std::snprintf(text, sizeof text, "Lyapunov %.3f %.3f %.3f (%s)", result.lyapunov[0], result.lyapunov[1],
                  result.lyapunov[2], std::string(core::toString(result.verdict)).c_str());
    state.lyapunovText = text;
  } catch (const core::Error& e) {
    state.lyapunovText = e.what();
  }
}

void startSearch(ExplorerState& state, double strength) {
  if (state.search.valid()) return;  // one at a time
  const core::PatternLayer& layer = state.scene.layers.front();
  const core::OrbitSpec spec = layerSpec(layer);
  core::SearchOptions options;
  options.seed = state.searchSeed++;
  options.count = 1;
  options.strength = strength;
  state.searchMessage = "searching…";
  state.search = std::async(std::launch::async, [spec, options] { return core::searchChaos(spec, options); });
}

void collectSearch(ExplorerState& state) {
  if (!state.search.valid() || state.search.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  try {
    const auto results = state.search.get();
    if (results.empty()) {
      state.searchMessage = "no chaotic set found nearby; try a larger strength";
      return;
    }
    state.scene.layers.front().params = results.front().params;
    state.patternDirty = true;
    char text[96];
    std::snprintf(text, sizeof text, "found: largest Lyapunov exponent %.3f", results.front().analysis.lyapunov[0]);
    state.searchMessage = text;
  } catch (const core::Error& e) {
    state.searchMessage = e.what();
  }
}

void onScroll(GLFWwindow* window, double, double yOffset) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  auto* state = static_cast<ExplorerState*>(glfwGetWindowUserPointer(window));
  state->scene.camera.distance = std::clamp(state->scene.camera.distance * std::pow(0.9, yOffset), 0.2, 20.0);
}

void handleMouse(GLFWwindow* window, ExplorerState& state) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  if (pressed && !state.dragging && !ImGui::GetIO().WantCaptureMouse) state.dragging = true;
  if (!pressed) state.dragging = false;
  if (state.dragging) {
    state.scene.camera.azimuthDeg -= 0.3 * (x - state.lastMouseX);
    state.scene.camera.elevationDeg =
        std::clamp(state.scene.camera.elevationDeg + 0.3 * (y - state.lastMouseY), -90.0, 90.0);
  }
  state.lastMouseX = x;
  state.lastMouseY = y;

  // Free flight: W/S move along the view, A/D sideways, Q/E down and up; the orbit target moves
  // with the eye, so the camera turns about itself when dragged afterwards.
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  const core::CameraFrame frame = core::orbitCamera(state.scene.camera, core::Box{{-1, -1, -1}, {1, 1, 1}}, 1.0);
  const double speed = 0.02 * state.scene.camera.distance;
  auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0 : 0.0; };
  const glm::dvec3 move = (held(GLFW_KEY_W) - held(GLFW_KEY_S)) * frame.forward +
                          (held(GLFW_KEY_D) - held(GLFW_KEY_A)) * frame.right +
                          (held(GLFW_KEY_E) - held(GLFW_KEY_Q)) * frame.up;
  state.scene.camera.target += speed * move;
}

bool slider(const char* label, double& value, double min, double max, ImGuiSliderFlags flags = 0) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, "%.3f", flags);
}

void drawPanel(ExplorerState& state, const core::AccumulatorStats& stats) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("voxflame");
  ImGui::TextUnformatted(state.scene.name.c_str());
  for (std::size_t li = 0; li < state.scene.layers.size(); ++li) {
    core::PatternLayer& layer = state.scene.layers[li];
    const core::AttractorInfo& info = core::attractorOrThrow(layer.attractor);
    ImGui::PushID(static_cast<int>(li));
    if (ImGui::CollapsingHeader(info.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      // The picker lists the catalogue, narrowed by the filter text (id or name).
      ImGui::InputTextWithHint("##filter", "filter attractors", state.attractorFilter, sizeof state.attractorFilter);
      if (ImGui::BeginCombo("attractor", info.name.c_str())) {
        std::string filter = state.attractorFilter;
        std::transform(filter.begin(), filter.end(), filter.begin(), [](unsigned char c) { return std::tolower(c); });
        for (const core::AttractorInfo& candidate : core::attractorCatalogue()) {
          std::string haystack = candidate.id + " " + candidate.name;
          std::transform(haystack.begin(), haystack.end(), haystack.begin(),
                         [](unsigned char c) { return std::tolower(c); });
          if (!filter.empty() && haystack.find(filter) == std::string::npos) continue;
          if (ImGui::Selectable(candidate.name.c_str(), candidate.id == layer.attractor) &&
              candidate.id != layer.attractor) {
            layer.attractor = candidate.id;
            layer.params = candidate.defaultParams();
            layer.step = candidate.defaultStep;
            layer.integrator = candidate.defaultIntegrator;
            state.patternDirty = true;
          }
        }
        ImGui::EndCombo();
      }
      if (ImGui::IsItemHovered() && !info.citation.empty()) ImGui::SetTooltip("%s", info.citation.c_str());
      if (layer.params.size() != info.params.size()) {
        ImGui::PopID();
        break;  // the layer changed attractor this frame; its sliders appear on the next one
      }
      for (std::size_t p = 0; p < info.params.size(); ++p) {
        const core::ParamInfo& param = info.params[p];
        if (ImGui::SliderScalar(param.name.c_str(), ImGuiDataType_Double, &layer.params[p], &param.sliderMin,
                                &param.sliderMax, "%.4f"))
          state.patternDirty = true;
      }
      if (info.kind == core::AttractorKind::Flow) {
        const double minStep = 0.001, maxStep = 0.3;
        if (ImGui::SliderScalar("step", ImGuiDataType_Double, &layer.step, &minStep, &maxStep, "%.4f",
                                ImGuiSliderFlags_Logarithmic))
          state.patternDirty = true;
      }
      if (ImGui::Button("Reset parameters")) {
        layer.params = info.defaultParams();
        layer.step = info.defaultStep;
        state.patternDirty = true;
      }
    }
    ImGui::PopID();
  }
  if (ImGui::Button("Search (F3)")) startSearch(state, 0.1);
  ImGui::SameLine();
  if (ImGui::Button("Mutate")) startSearch(state, state.mutateStrength);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  slider("strength", state.mutateStrength, 0.01, 1.0, ImGuiSliderFlags_Logarithmic);
  if (!state.searchMessage.empty()) ImGui::TextWrapped("%s", state.searchMessage.c_str());
  if (!stats.problem.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "This pattern escapes: press Search (F3) for a nearby one.");
  if (ImGui::CollapsingHeader("Tone", ImGuiTreeNodeFlags_DefaultOpen)) {
    core::ToneMapSettings& tone = state.scene.tone;
    slider("brightness", tone.brightness, 0.0, 50.0, ImGuiSliderFlags_Logarithmic);
    slider("gamma", tone.gamma, 0.5, 6.0);
    slider("gamma threshold", tone.gammaThreshold, 0.0, 0.5);
    slider("vibrancy", tone.vibrancy, 0.0, 1.0);
    slider("highlight power", tone.highlightPower, -1.0, 5.0);
    slider("exposure", tone.exposure, -5.0, 5.0);
    slider("contrast", tone.contrast, 0.2, 3.0);
    slider("opacity", tone.opacity, 0.0, 1.0);
    float background[3] = {tone.background.r, tone.background.g, tone.background.b};
    if (ImGui::ColorEdit3("background", background, ImGuiColorEditFlags_Float))
      tone.background = glm::vec3(background[0], background[1], background[2]);
  }
  if (ImGui::CollapsingHeader("Render")) {
    core::RenderSettingsDoc& render = state.scene.render;
    slider("step (voxels)", render.stepVoxels, 0.1, 2.0);
    int meshMode = static_cast<int>(render.meshDisplay);
    if (ImGui::Combo("mesh", &meshMode, "off\0ghost\0silhouette\0"))
      render.meshDisplay = static_cast<core::MeshDisplay>(meshMode);
    slider("mesh strength", render.meshStrength, 0.0, 2.0);
    ImGui::Checkbox("lighting", &render.lighting);
    if (render.lighting) {
      slider("light azimuth", render.lightAzimuthDeg, -180.0, 180.0);
      slider("light elevation", render.lightElevationDeg, -90.0, 90.0);
      slider("light strength", render.lightStrength, 0.0, 1.0);
    }
    ImGui::SliderFloat("render scale", &state.renderScale, 0.25f, 1.0f, "%.2f");
  }
  if (ImGui::CollapsingHeader("Camera")) {
    core::CameraSettings& camera = state.scene.camera;
    slider("azimuth", camera.azimuthDeg, -180.0, 180.0);
    slider("elevation", camera.elevationDeg, -90.0, 90.0);
    slider("roll", camera.rollDeg, -180.0, 180.0);
    slider("distance", camera.distance, 0.2, 20.0, ImGuiSliderFlags_Logarithmic);
    bool orthographic = camera.projection == core::Projection::Orthographic;
    if (ImGui::Checkbox("orthographic", &orthographic))
      camera.projection = orthographic ? core::Projection::Orthographic : core::Projection::Perspective;
    if (ImGui::Button("Front")) camera.azimuthDeg = 0.0, camera.elevationDeg = 0.0, camera.rollDeg = 0.0;
    ImGui::SameLine();
    if (ImGui::Button("Side")) camera.azimuthDeg = 90.0, camera.elevationDeg = 0.0, camera.rollDeg = 0.0;
    ImGui::SameLine();
    if (ImGui::Button("Top")) camera.azimuthDeg = 0.0, camera.elevationDeg = 90.0, camera.rollDeg = 0.0;
    ImGui::SameLine();
    if (ImGui::Button("Reset")) camera = state.initialCamera;
  }
  ImGui::Separator();
  ImGui::Text("%.1f M points inside  %.1f M/s", static_cast<double>(stats.points) * 1e-6, stats.pointsPerSecond * 1e-6);
  ImGui::Text("inside %.1f%%  escapes %llu", 100.0 * stats.insideFraction(),
              static_cast<unsigned long long>(stats.escapes));
  ImGui::Text("%.1f ms/frame  %d samples", state.frameMs, state.samples);
  ImGui::TextUnformatted(state.lyapunovText.c_str());
  if (!stats.problem.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", stats.problem.c_str());
  ImGui::End();
}

void saveScreenshot(const std::filesystem::path& path, int width, int height) {
  core::ImageRGBA image;
  image.width = width;
  image.height = height;
  std::vector<float> rows(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rows.data());
  image.pixels.resize(rows.size());
  const std::size_t stride = 4 * static_cast<std::size_t>(width);
  for (int y = 0; y < height; ++y)
    std::copy_n(&rows[static_cast<std::size_t>(height - 1 - y) * stride], stride,
                &image.pixels[static_cast<std::size_t>(y) * stride]);
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 1.0f;
  core::writePng(path, image, 8, {});
}

struct GlfwSession {
  GlfwSession() {
    if (!glfwInit()) throw core::Error("could not initialise GLFW (is the display reachable?)");
  }
  ~GlfwSession() { glfwTerminate(); }
};

}  // namespace

int runExplorer(const core::Scene& initialScene, const ExplorerOptions& options) {
  if (!haveDisplay()) return renderInsteadOfWindow(initialScene);

  // Load everything that can fail on the user's input before opening a window.
  const SceneShape shape = buildSceneShape(initialScene);
  const auto& mask = shape.mask;
  GlfwSession glfw;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  const std::string title = "voxflame — " + initialScene.name;
  GLFWwindow* window = glfwCreateWindow(1280, 720, title.c_str(), nullptr, nullptr);
  if (!window) throw core::Error("could not open an OpenGL 4.3 window on this display");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 430");

  ExplorerState state;
  state.scene = initialScene;
  state.initialCamera = initialScene.camera;
  state.history.emplace(initialScene);
  // Software GL (llvmpipe) marches a quarter of the pixels to stay interactive; samples then
  // refine the image while nothing changes.
  const std::string glRenderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (glRenderer.find("llvmpipe") != std::string::npos || glRenderer.find("softpipe") != std::string::npos)
    state.renderScale = 0.5f;
  glfwSetWindowUserPointer(window, &state);
  glfwSetScrollCallback(window, onScroll);
  {
    gl::VolumeRenderer renderer;
    renderer.setMesh(shape.mesh);
    gl::FrameTarget target;
    core::Accumulator accumulator(mask);
    accumulator.setTargetPoints(std::uint64_t{4'000'000'000});
    accumulator.setPattern(state.scene.layers, state.scene.seed);
    startAnalysis(state);
    core::SnapshotPublisher publisher(accumulator, std::chrono::milliseconds(100));
    core::PackedVolume incoming, uploading;
    bool uploadInProgress = false;
    constexpr std::size_t kUploadBytesPerFrame = 48u << 20;  // keeps a frame's upload to a few ms
    constexpr int kMaxSamples = 64;
    std::uint32_t frame = 0;
    int framesWithVolume = 0;
    std::string lastView;
    std::string lastShadowKey;
    constexpr int kShadowDownsample = 2;
    auto lastFrame = std::chrono::steady_clock::now();

    while (!glfwWindowShouldClose(window)) {
      glfwPollEvents();
      const bool ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                        glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
      if (ctrl && glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) glfwSetWindowShouldClose(window, GLFW_TRUE);
      if (glfwGetWindowAttrib(window, GLFW_ICONIFIED)) {
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      handleMouse(window, state);
      handleHistory(state);
      if (ImGui::IsKeyPressed(GLFW_KEY_F3, false)) startSearch(state, 0.1);
      collectSearch(state);
      drawPanel(state, accumulator.stats());
      ImGui::Render();

      collectAnalysis(state);
      if (state.patternDirty) {
        state.patternDirty = false;
        startAnalysis(state);
        try {
          accumulator.setPattern(state.scene.layers, state.scene.seed);
          publisher.requestNow();
        } catch (const core::Error& e) {
          std::cerr << "voxflame: " << e.what() << "\n";
        }
      }
      if (!uploadInProgress && publisher.takeIfNewer(incoming)) {
        std::swap(incoming, uploading);
        renderer.beginUpload(uploading);
        uploadInProgress = true;
      }
      if (uploadInProgress && renderer.continueUpload(kUploadBytesPerFrame)) {
        uploadInProgress = false;
        target.samples = 0;  // new content: start refining the image afresh
      }
      // The shadow volume follows the volume, the light and the brightness (extinction).
      const core::RenderSettingsDoc& render = state.scene.render;
      const std::string shadowKey =
          std::to_string(renderer.uploadedVersion()) + "/" + std::to_string(render.lightAzimuthDeg) + "/" +
          std::to_string(render.lightElevationDeg) + "/" + std::to_string(state.scene.tone.brightness);
      if (render.lighting && renderer.hasVolume() && !uploadInProgress && shadowKey != lastShadowKey) {
        core::ShadowVolume shadow;
        core::computeShadowVolume(uploading, core::lightDirection(render.lightAzimuthDeg, render.lightElevationDeg),
                                  state.scene.tone.brightness, kShadowDownsample, shadow);
        renderer.uploadShadow(shadow, kShadowDownsample);
        lastShadowKey = shadowKey;
        target.samples = 0;
      }

      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      gl::RenderSettings settings;
      settings.camera =
          core::orbitCamera(state.scene.camera, mask->geometry.box(), static_cast<double>(width) / std::max(1, height));
      settings.tone = state.scene.tone;
      settings.render = state.scene.render;
      // Anything that changes what a ray sees restarts the sample average; tone alone does not.
      core::Scene marchInputs = state.scene;
      marchInputs.tone = core::ToneMapSettings{};
      marchInputs.tone.brightness = state.scene.tone.brightness;
      marchInputs.tone.opacity = state.scene.tone.opacity;
      const std::string view = core::sceneToJson(marchInputs) + std::to_string(width) + "x" + std::to_string(height) +
                               std::to_string(state.renderScale);
      target.resize(std::max(1, static_cast<int>(static_cast<float>(width) * state.renderScale)),
                    std::max(1, static_cast<int>(static_cast<float>(height) * state.renderScale)));
      if (view != lastView) {
        target.samples = 0;
        renderer.drawMesh(target, settings);
        lastView = view;
      }
      if (target.samples < kMaxSamples) renderer.march(target, settings, static_cast<int>(frame));
      state.samples = target.samples;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      renderer.resolve(target, settings, glm::ivec4(0, 0, width, height), false);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      ++frame;
      // Scripted runs count frames from the first one that shows the volume.
      if (renderer.hasVolume()) ++framesWithVolume;
      if (options.frames > 0 && framesWithVolume >= options.frames) {
        if (!options.screenshotPath.empty()) {
          saveScreenshot(options.screenshotPath, width, height);
          std::cout << "wrote " << options.screenshotPath.string() << std::endl;
        }
        glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
      glfwSwapBuffers(window);
      const auto now = std::chrono::steady_clock::now();
      state.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame).count();
      lastFrame = now;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  return 0;
}

}  // namespace voxflame::app
