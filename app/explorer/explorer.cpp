#include "explorer.h"

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations, GLFW only the window.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <chrono>
#include <optional>
#include <thread>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "core/error.h"
#include "pipeline.h"
#include "explorer_session.h"
#include "gl/read_back.h"
#include "explorer_ui.h"
#include "input_queue.h"
#include "key_codes.h"
#include "live_view.h"
#include "panel_requests.h"
#include "x11_watch.h"

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

// GLFW, and the X error handlers that keep a window destroyed from outside (or a lost X server)
// from ending the process: installed before the window is made, removed after GLFW is gone.
struct GlfwSession {
  GlfwSession() {
    if (!glfwInit()) throw core::Error("could not initialise GLFW (is the display reachable?)");
    x11.emplace();
  }
  ~GlfwSession() {
    glfwTerminate();
    x11.reset();
  }
  std::optional<X11Watch> x11;
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

// The flat view's newest image into its texture (made on first use, replaced in place after).
void uploadFlatView(ExplorerState& state) {
  state.frame.flatImagePending = false;
  const core::ImageRGBA& image = state.frame.flatImage;
  if (image.width <= 0 || image.height <= 0) return;
  std::vector<std::uint8_t> rgba(image.pixels.size());
  for (std::size_t i = 0; i < rgba.size(); ++i)
    rgba[i] = static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(image.pixels[i], 0.0f, 1.0f)));
  if (!state.frame.flatTexture) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    state.frame.flatTexture = texture;
  }
  glBindTexture(GL_TEXTURE_2D, state.frame.flatTexture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  state.frame.flatTextureWidth = image.width;
  state.frame.flatTextureHeight = image.height;
}

static_assert(kKeyEscape == GLFW_KEY_ESCAPE && kKeyEnter == GLFW_KEY_ENTER && kKeyBackspace == GLFW_KEY_BACKSPACE &&
              kKeyRight == GLFW_KEY_RIGHT && kKeyLeft == GLFW_KEY_LEFT && kKeyF3 == GLFW_KEY_F3 &&
              kKeyLeftShift == GLFW_KEY_LEFT_SHIFT && kKeyLeftControl == GLFW_KEY_LEFT_CONTROL &&
              kKeyLeftAlt == GLFW_KEY_LEFT_ALT && kKeyLeftSuper == GLFW_KEY_LEFT_SUPER &&
              kKeyRightShift == GLFW_KEY_RIGHT_SHIFT && kKeyRightControl == GLFW_KEY_RIGHT_CONTROL &&
              kKeyRightAlt == GLFW_KEY_RIGHT_ALT && kKeyRightSuper == GLFW_KEY_RIGHT_SUPER);

// What the window's callbacks collect between frames (the window's user pointer).
struct WindowInput {
  std::vector<std::string> dropped;  // files dropped onto the window: the loop opens the first
  InputQueue queue;                  // keys, buttons, characters, wheel, pointer: see input_queue.h
  bool closeAsked = false;           // the window's close button: the loop asks first (askToQuit)
};

// SIGTERM, SIGINT or SIGHUP: an end the user did not choose in the window (a logout, a kill, Ctrl+C
// in the terminal). The loop sees it within its longest wait and leaves the scene autosaved, as
// when the window is destroyed from outside. A second signal ends the process at once.
volatile std::sig_atomic_t quitSignal = 0;

void onQuitSignal(int signal) {
  if (quitSignal != 0) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  quitSignal = signal;
}

// Installs onQuitSignal for the explorer's lifetime and puts the previous handlers back after.
class QuitSignals {
 public:
  QuitSignals() {
    quitSignal = 0;
    struct sigaction action {};
    action.sa_handler = onQuitSignal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &action, &previous_[i]);
  }
  ~QuitSignals() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &previous_[i], nullptr);
  }
  QuitSignals(const QuitSignals&) = delete;
  QuitSignals& operator=(const QuitSignals&) = delete;
  static bool received() { return quitSignal != 0; }

 private:
  static constexpr std::array<int, 3> kSignals = {SIGTERM, SIGINT, SIGHUP};
  std::array<struct sigaction, 3> previous_{};
};

WindowInput& inputOf(GLFWwindow* window) {
  return *static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
}

// ImGui's backend is installed without its input callbacks, which would write io.KeysDown and
// io.MouseDown directly (a tap between two frames cancels out); these queue the events instead.
// Focus and pointer enter/leave still go to the backend, which tracks them for io.MousePos.
void installInputCallbacks(GLFWwindow* window) {
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_REPEAT) inputOf(w).queue.key(key, action == GLFW_PRESS);
  });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned codepoint) { inputOf(w).queue.character(codepoint); });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    inputOf(w).queue.mouseButton(button, action == GLFW_PRESS);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double dx, double dy) { inputOf(w).queue.scroll(dx, dy); });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) { inputOf(w).queue.cursor(x, y); });
  glfwSetWindowFocusCallback(window, ImGui_ImplGlfw_WindowFocusCallback);
  glfwSetCursorEnterCallback(window, ImGui_ImplGlfw_CursorEnterCallback);
  glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
    for (int i = 0; i < count; ++i) inputOf(w).dropped.emplace_back(paths[i]);
  });
  // The close button does not close: the loop asks first when changes are unsaved.
  glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
    inputOf(w).closeAsked = true;
    glfwSetWindowShouldClose(w, GLFW_FALSE);
  });
}

// The window's content scale (DPI), unless the user chose one.
float uiScaleFor(GLFWwindow* window, float requested) {
  if (requested > 0.0f) return requested;
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window, &x, &y);
  return std::clamp(std::max(x, y), 1.0f, 4.0f);
}

// What, besides input, calls for a new frame while the explorer rests: work on other threads that
// finished (a volume, a search, an analysis, an export, preset thumbnails) or a resize. While it
// stays the same and no input arrives, the resting loop wakes only to compare it, and draws nothing.
struct RestSignature {
  bool sessionResting = false;
  std::uint64_t requested = 0, applied = 0;
  std::string error;
  bool searchBusy = false, analysisBusy = false;
  ExportState exportState = ExportState::Idle;
  std::uint64_t presetsVersion = 0;
  int width = 0, height = 0;
  bool operator==(const RestSignature&) const = default;
};

RestSignature restSignature(const ExplorerSession& session, const ExplorerState& state, const PresetLibrary& presets,
                            GLFWwindow* window) {
  const SessionStatus status = session.status();
  RestSignature signature;
  signature.sessionResting = status.resting;
  signature.requested = status.requestedGeneration;
  signature.applied = status.appliedGeneration;
  signature.error = status.error;
  signature.searchBusy = state.services.search.busy();
  signature.analysisBusy = state.services.analysis.busy();
  signature.exportState = state.services.exportStatus.state;
  signature.presetsVersion = presets.version();
  glfwGetFramebufferSize(window, &signature.width, &signature.height);
  return signature;
}

}  // namespace

int runExplorer(const core::Scene& initialScene, const ExplorerOptions& options) {
  if (!haveDisplay()) return renderInsteadOfWindow(initialScene);
  // Before the window: a signal that comes while the window, GL and the panels are set up (seconds
  // on a slow machine, with the window already shown) is kept, and the loop's first frame ends with
  // the scene autosaved, instead of the process dying with nothing saved.
  const QuitSignals quitSignals;

  GlfwSession glfw;
  X11Watch& x11 = *glfw.x11;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  std::string title = "voxflame — " + initialScene.name;
  // Settings never stop the explorer: a bad file gives defaults and a message in the window.
  SettingsLoad settingsLoad = loadSettings();
  // Scripted runs (screenshots) get a fixed size, so their pictures compare across machines.
  const bool scriptedRun = options.frames > 0;
  const int windowWidth = options.width > 0 ? options.width : (scriptedRun ? 1280 : settingsLoad.settings.window.width);
  const int windowHeight =
      options.height > 0 ? options.height : (scriptedRun ? 720 : settingsLoad.settings.window.height);
  // Where the GPU refines (the "refine on" setting at start), the context is made through EGL when
  // it can be: the GPU backend's context then shares its textures (gl::currentShareGroup), so the
  // grid reaches the ray-marcher on the GPU. Otherwise, and where EGL cannot make one, the
  // platform's own (GLX) does: Mesa's EGL on X11 crashes when the X server goes away under it,
  // where GLX lets X11Watch end the explorer cleanly with the scene autosaved.
  if (settingsLoad.settings.refinementBackend != BackendChoice::Cpu)
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  GLFWwindow* window = glfwCreateWindow(windowWidth, windowHeight, title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_NATIVE_CONTEXT_API);
    window = glfwCreateWindow(windowWidth, windowHeight, title.c_str(), nullptr, nullptr);
  }
  if (!window) throw core::Error("could not open an OpenGL 4.3 window on this display");
  x11.watch(window);  // from here on a window destroyed from outside ends the loop (x11_watch.h)
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, false);
  ImGui_ImplOpenGL3_Init("#version 430");

  ExplorerState state;
  state.panels.uiScale = uiScaleFor(window, options.uiScale);
  applyUiScale(state.panels.uiScale);
  resetExplorerState(state, initialScene);
  state.services.settings = settingsLoad.settings;
  state.panels.prompts.notice = settingsLoad.message;
  // Scripted runs (screenshots, tests) neither offer nor leave autosaves.
  const bool scripted = options.frames > 0;
  if (!scripted) state.services.recoverable = findRecoverable();
  // Software GL (llvmpipe) marches a quarter of the pixels to stay interactive; samples then
  // refine the image while nothing changes.
  const std::string glRenderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (glRenderer.find("llvmpipe") != std::string::npos || glRenderer.find("softpipe") != std::string::npos)
    state.panels.scene.renderScale = 0.5f;
  std::ofstream inputLog;
  if (!options.inputLog.empty()) {
    inputLog.open(options.inputLog, std::ios::app);
    if (!inputLog) throw core::Error("cannot write the input log " + options.inputLog.string());
    state.frame.recordTyping = true;
  }
  WindowInput input;
  glfwSetWindowUserPointer(window, &input);
  installInputCallbacks(window);
  std::vector<std::string>& dropped = input.dropped;
  {
    ExplorerSession session;
    PresetLibrary presets(findShippedPresetFolder(), state.services.settings.presetFolder());
    state.services.presets = &presets;
    std::uint64_t thumbnailsVersion = 0;
    ExportJob exportJob;
    state.services.exportJob = &exportJob;
    std::optional<Autosave> autosave;
    if (!scripted) autosave.emplace();
    std::optional<std::uint64_t> autosavedRevision;  // the edit count autosave last looked at
    LiveView view(session);
    // The panels' requests for the session, the presets and the export child (save as takes the
    // picture the view just drew).
    PanelRequests requests(session, &presets, &exportJob);
    std::uint32_t frame = 0;
    int framesWithVolume = 0;
    auto lastFrame = std::chrono::steady_clock::now();

    // The canonical ImGui loop: events, the panels (which only edit state and ask for things),
    // the view under them (app::LiveView), the panels' requests served over it
    // (app::PanelRequests), the panels' drawing on top, swap. Once the window is gone
    // (x11.windowGone()), what GLFW read from it is garbage: each read is checked before use.
    int restingFrames = 0;
    std::optional<RestSignature> drawnAtRest;  // what the last frame drawn at rest showed
    while (!glfwWindowShouldClose(window)) {
      x11.rearm();
      // Frames are drawn only while something moves; at rest the loop sleeps in GLFW until input
      // arrives, waking now and then (other threads do not wake GLFW) only to see whether a job
      // finished: it draws again for input, a resize or a finished job, so an idle explorer whose
      // volume rests uses almost no CPU. Scripted runs always draw.
      const double wait = scriptedRun ? 0.0 : frameWaitSeconds(state, view.resting(), restingFrames);
      if (wait > 0.0)
        glfwWaitEventsTimeout(wait);
      else
        glfwPollEvents();
      const bool iconified = glfwGetWindowAttrib(window, GLFW_ICONIFIED) != 0;
      if (x11.windowGone() || QuitSignals::received()) break;
      // The close button quits at once with nothing unsaved, else asks (drawn on this frame).
      const bool closeAsked = std::exchange(input.closeAsked, false);
      if (closeAsked && !hasUnsavedChanges(state)) break;
      if (closeAsked) state.panels.prompts.quitPrompt = true;
      if (iconified) {
        glfwWaitEventsTimeout(0.5);
        continue;
      }
      // (An export's progress is polled by the frames themselves: they go on, throttled.)
      // A wait between the points picture's steps is no rest either: the frame after it draws.
      const bool restingWait =
          wait > 0.0 && state.services.exportStatus.state != ExportState::Running && !state.frame.view.waitingForPoints;
      if (restingWait && !closeAsked && input.queue.pending() == 0 && dropped.empty() &&
          !glfwWindowShouldClose(window)) {
        const RestSignature now = restSignature(session, state, presets, window);
        if (x11.windowGone()) break;
        if (drawnAtRest == now) continue;  // nothing new to show
        drawnAtRest = now;
      } else if (!restingWait) {
        drawnAtRest.reset();
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();  // display size, time, pointer; then the queued input over it
      if (x11.windowGone()) break;
      input.queue.applyTo(ImGui::GetIO(), std::exchange(state.frame.keyboardFocusMoved, false));
      ImGui::NewFrame();
      state.frame.session = session.status();
      if (state.frame.flatImagePending) uploadFlatView(state);
      explorerUiFrame(state);
      ImGui::Render();

      if (state.frame.requests.quit) glfwSetWindowShouldClose(window, GLFW_TRUE);
      // The title follows the document: its name (after an open, a save-as, an undo) and whether
      // it has unsaved changes. Not while a widget or the view is held: a drag's frames would
      // each compare the whole scene, and its edit is one step anyway.
      if (!state.frame.interacting && !ImGui::IsAnyItemActive()) {
        if (std::string now = windowTitle(state); now != title) {
          title = std::move(now);
          glfwSetWindowTitle(window, title.c_str());
        }
      }
      if (state.frame.requests.open) openFile(state, *state.frame.requests.open);
      // Autosave looks at the scene only after an edit (the document's count), until it has.
      if (autosave && autosavedRevision != state.document.revisions().any && autosave->update(state.document.scene))
        autosavedRevision = state.document.revisions().any;
      // Thumbnails arrive decoded from the library's thread; only their upload happens here.
      if (presets.version() != thumbnailsVersion) {
        thumbnailsVersion = presets.version();
        if (const PresetLibrary::Entries entries = presets.entries())
          for (const PresetEntry& entry : *entries)
            if (entry.thumbnail && !state.frame.thumbnailTextures.contains(entry.path))
              state.frame.thumbnailTextures[entry.path] = uploadThumbnail(*entry.thumbnail);
      }
      if (!dropped.empty()) {
        openFile(state, dropped.front());
        dropped.clear();
      }

      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      if (x11.windowGone()) break;
      liveFrame(view, state, width, height);
      // After the picture is drawn and before the panels go over it, so a thumbnail shows the view alone.
      requests.serve(state, view);
      // Save, chosen in the quit prompt, has been served: it asks to quit once it worked.
      if (state.frame.requests.quit) glfwSetWindowShouldClose(window, GLFW_TRUE);
      // Input gets a few frames of its own: ImGui settles hover and layout a frame late.
      const ImGuiIO& io = ImGui::GetIO();
      const bool userActive = input.queue.pending() > 0 || io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f ||
                              io.MouseWheel != 0.0f || io.MouseWheelH != 0.0f || ImGui::IsAnyMouseDown() ||
                              ImGui::IsAnyItemActive() || !io.InputQueueCharacters.empty();
      restingFrames = view.resting() && state.frame.session.resting && !userActive ? restingFrames + 1 : 0;
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
      if (inputLog && !state.frame.typedThisFrame.empty()) {
        const double shownAt =
            std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
        for (const auto& [field, text] : state.frame.typedThisFrame)
          inputLog << std::fixed << shownAt << ' ' << field << '\t' << text << '\n';
        inputLog.flush();  // read by another process while this one runs
      }
      state.frame.typedThisFrame.clear();
      if (options.minFrameMs > 0)
        std::this_thread::sleep_until(lastFrame + std::chrono::milliseconds(options.minFrameMs));
      const auto now = std::chrono::steady_clock::now();
      FrameMetrics& metrics = state.frame.metrics;
      metrics.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame).count();
      metrics.fps = metrics.frameMs > 0.0 ? 0.9 * metrics.fps + 0.1 * (1000.0 / metrics.frameMs) : metrics.fps;
      if (frame > 2) metrics.worstFrameMs = std::max(metrics.worstFrameMs, metrics.frameMs);
      lastFrame = now;
    }
    if (autosave && (x11.windowGone() || QuitSignals::received())) {
      // Not the user's choice: the scene as it is now stays recoverable at the next start.
      if (const std::string error = autosave->saveNow(state.document.scene); !error.empty())
        std::cerr << "voxflame: " << error << "\n";
    } else if (autosave) {
      autosave->finishCleanly();  // a normal close: nothing to recover next time
    }
    if (options.frames > 0) {
      const FrameMetrics& m = state.frame.metrics;
      std::printf("explorer: %u frames, last %.1f ms, worst %.1f ms since the last edit, edit to frame %.0f ms\n",
                  frame, m.frameMs, m.worstFrameMs, m.changeToFrameMs);
    }
  }
  for (const auto& [path, texture] : state.frame.thumbnailTextures) glDeleteTextures(1, &texture);
  if (state.frame.flatTexture) {
    const GLuint texture = state.frame.flatTexture;
    glDeleteTextures(1, &texture);
  }
  // The window's size for next time (a window that is gone keeps last time's); a failure to save
  // settings is only worth a line.
  if (!x11.windowGone()) {
    x11.rearm();
    WindowGeometry geometry = state.services.settings.window;
    if (!glfwGetWindowAttrib(window, GLFW_ICONIFIED)) glfwGetWindowSize(window, &geometry.width, &geometry.height);
    geometry.maximized = glfwGetWindowAttrib(window, GLFW_MAXIMIZED) != 0;
    if (!x11.windowGone()) state.services.settings.window = geometry;  // read while the window still existed
  }
  if (!scripted) {
    try {
      saveSettings(state.services.settings);
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
