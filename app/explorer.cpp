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
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "core/color.h"
#include "core/camera.h"
#include "core/error.h"
#include "pipeline.h"
#include "explorer_session.h"
#include "gl/read_back.h"
#include "explorer_ui.h"
#include "live_view.h"

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

void saveScreenshot(const std::filesystem::path& path, int width, int height) {
  core::ImageRGBA image;
  image.width = width;
  image.height = height;
  glReadBuffer(GL_BACK);  // the frame just drawn, before the swap
  image.pixels = gl::readRgbaFloat(0, {0, 0, width, height}, gl::ReadAlpha::Opaque);
  core::writePng(path, image, 8, {});
}

struct GlfwSession {
  GlfwSession() {
    if (!glfwInit()) throw core::Error("could not initialise GLFW (is the display reachable?)");
  }
  ~GlfwSession() { glfwTerminate(); }
};

unsigned uploadThumbnail(const Thumbnail& thumbnail) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, thumbnail.width, thumbnail.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               thumbnail.rgba.data());
  return texture;
}

// Files dropped onto the window wait here until the frame loop opens the first of them.
void onDrop(GLFWwindow* window, int count, const char** paths) {
  auto* dropped = static_cast<std::vector<std::string>*>(glfwGetWindowUserPointer(window));
  for (int i = 0; i < count; ++i) dropped->emplace_back(paths[i]);
}

// The window's content scale (DPI), unless the user chose one.
float uiScaleFor(GLFWwindow* window, float requested) {
  if (requested > 0.0f) return requested;
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window, &x, &y);
  return std::clamp(std::max(x, y), 1.0f, 4.0f);
}

void openInto(ExplorerState& state, const std::filesystem::path& path, GLFWwindow* window) {
  if (!openFile(state, path)) return;
  const std::string title = "voxflame — " + state.scene.name;
  glfwSetWindowTitle(window, title.c_str());
}

}  // namespace

int runExplorer(const core::Scene& initialScene, const ExplorerOptions& options) {
  if (!haveDisplay()) return renderInsteadOfWindow(initialScene);

  GlfwSession glfw;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  const std::string title = "voxflame — " + initialScene.name;
  // Settings never stop the explorer: a bad file gives defaults and a message in the window.
  SettingsLoad settingsLoad = loadSettings();
  // Scripted runs (screenshots) get a fixed size, so their pictures compare across machines.
  const bool scriptedRun = options.frames > 0;
  const int windowWidth = options.width > 0 ? options.width : (scriptedRun ? 1280 : settingsLoad.settings.window.width);
  const int windowHeight =
      options.height > 0 ? options.height : (scriptedRun ? 720 : settingsLoad.settings.window.height);
  GLFWwindow* window = glfwCreateWindow(windowWidth, windowHeight, title.c_str(), nullptr, nullptr);
  if (!window) throw core::Error("could not open an OpenGL 4.3 window on this display");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 430");

  ExplorerState state;
  state.uiScale = uiScaleFor(window, options.uiScale);
  applyUiScale(state.uiScale);
  resetExplorerState(state, initialScene);
  state.settings = settingsLoad.settings;
  state.notice = settingsLoad.message;
  // Scripted runs (screenshots, tests) neither offer nor leave autosaves.
  const bool scripted = options.frames > 0;
  if (!scripted) state.recoverable = findRecoverable();
  // Software GL (llvmpipe) marches a quarter of the pixels to stay interactive; samples then
  // refine the image while nothing changes.
  const std::string glRenderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (glRenderer.find("llvmpipe") != std::string::npos || glRenderer.find("softpipe") != std::string::npos)
    state.renderScale = 0.5f;
  std::vector<std::string> dropped;
  glfwSetWindowUserPointer(window, &dropped);
  glfwSetDropCallback(window, onDrop);
  {
    ExplorerSession session;
    PresetLibrary presets(findShippedPresetFolder(), state.settings.presetFolder());
    state.presets = &presets;
    std::uint64_t thumbnailsVersion = 0;
    ExportJob exportJob;
    state.exportJob = &exportJob;
    std::optional<Autosave> autosave;
    if (!scripted) autosave.emplace();
    LiveView view(session, &presets, &exportJob);
    std::uint32_t frame = 0;
    int framesWithVolume = 0;
    auto lastFrame = std::chrono::steady_clock::now();

    // The canonical ImGui loop: events, the panels (which only edit state and ask for things),
    // the view under them (app::LiveView), the panels' drawing on top, swap.
    int restingFrames = 0;
    while (!glfwWindowShouldClose(window)) {
      // Frames are drawn only while something moves; at rest the loop sleeps in GLFW until input
      // arrives (or a short timeout, for what other threads finish), so an idle explorer whose
      // volume has converged uses almost no CPU. Scripted runs always draw.
      const double wait = scriptedRun ? 0.0 : frameWaitSeconds(state, view.resting(), restingFrames);
      if (wait > 0.0)
        glfwWaitEventsTimeout(wait);
      else
        glfwPollEvents();
      if (glfwGetWindowAttrib(window, GLFW_ICONIFIED)) {
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      state.session = session.status();
      explorerUiFrame(state);
      ImGui::Render();

      if (state.requests.quit) glfwSetWindowShouldClose(window, GLFW_TRUE);
      if (state.requests.open) openInto(state, *state.requests.open, window);
      if (autosave) autosave->update(state.scene);
      // Thumbnails arrive decoded from the library's thread; only their upload happens here.
      if (presets.version() != thumbnailsVersion) {
        thumbnailsVersion = presets.version();
        if (const PresetLibrary::Entries entries = presets.entries())
          for (const PresetEntry& entry : *entries)
            if (entry.thumbnail && !state.thumbnailTextures.contains(entry.path))
              state.thumbnailTextures[entry.path] = uploadThumbnail(*entry.thumbnail);
      }
      if (!dropped.empty()) {
        openInto(state, dropped.front(), window);
        dropped.clear();
      }

      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      view.frame(state, width, height);
      // Input gets a few frames of its own: ImGui settles hover and layout a frame late.
      const ImGuiIO& io = ImGui::GetIO();
      const bool input = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
                         io.MouseWheelH != 0.0f || ImGui::IsAnyMouseDown() || ImGui::IsAnyItemActive() ||
                         !io.InputQueueCharacters.empty();
      restingFrames = view.resting() && state.session.resting && !input ? restingFrames + 1 : 0;
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      ++frame;
      // Scripted runs count frames from the first one that shows the volume.
      if (view.hasVolume()) ++framesWithVolume;
      if (options.frames > 0 && framesWithVolume >= options.frames) {
        if (!options.screenshotPath.empty()) {
          saveScreenshot(options.screenshotPath, width, height);
          std::cout << "wrote " << options.screenshotPath.string() << std::endl;
        }
        glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
      glfwSwapBuffers(window);
      const auto now = std::chrono::steady_clock::now();
      FrameMetrics& metrics = state.metrics;
      metrics.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame).count();
      metrics.fps = metrics.frameMs > 0.0 ? 0.9 * metrics.fps + 0.1 * (1000.0 / metrics.frameMs) : metrics.fps;
      if (frame > 2) metrics.worstFrameMs = std::max(metrics.worstFrameMs, metrics.frameMs);
      lastFrame = now;
    }
    if (autosave) autosave->finishCleanly();  // a normal close: nothing to recover next time
    if (options.frames > 0) {
      const FrameMetrics& m = state.metrics;
      std::printf("explorer: %u frames, last %.1f ms, worst %.1f ms since the last edit, edit to frame %.0f ms\n",
                  frame, m.frameMs, m.worstFrameMs, m.changeToFrameMs);
    }
  }
  for (const auto& [path, texture] : state.thumbnailTextures) glDeleteTextures(1, &texture);
  // The window's size for next time; a failure to save settings is only worth a line.
  if (!glfwGetWindowAttrib(window, GLFW_ICONIFIED))
    glfwGetWindowSize(window, &state.settings.window.width, &state.settings.window.height);
  state.settings.window.maximized = glfwGetWindowAttrib(window, GLFW_MAXIMIZED) != 0;
  if (!scripted) {
    try {
      saveSettings(state.settings);
    } catch (const core::Error& e) {
      std::cerr << "voxflame: " << e.what() << "\n";
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  return 0;
}

}  // namespace voxflame::app
