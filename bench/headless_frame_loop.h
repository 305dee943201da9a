// The explorer's frame body without a window, for the benchmarks: app::LiveView, the very code
// the explorer runs under its panels. A headless context has no window: the frame goes to a
// 1280×720 colour buffer standing in for it.
#pragma once

#include <epoxy/gl.h>

#include <chrono>
#include <string>
#include <thread>

#include "core/scene.h"
#include "explorer_session.h"
#include "live_view.h"

namespace voxflame::bench {

// The preview scale the explorer sets for this GL renderer: software GL (llvmpipe) previews at
// half the pixels along each side while something moves; a still view refines at the full
// resolution everywhere.
inline float explorerPreviewScale(const std::string& glRenderer) {
  return glRenderer.find("llvmpipe") != std::string::npos ? 0.5f : 1.0f;
}

struct HeadlessFrameLoop {
  static constexpr int kWidth = 1280, kHeight = 720;
  HeadlessFrameLoop(app::ExplorerSession& session, const core::Scene& scene, float renderScale) : view(session) {
    app::resetExplorerState(state, scene);
    state.panels.scene.renderScale = renderScale;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
    glGenFramebuffers(1, &window);
    glBindFramebuffer(GL_FRAMEBUFFER, window);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  }
  ~HeadlessFrameLoop() {
    glDeleteFramebuffers(1, &window);
    glDeleteRenderbuffers(1, &colour);
  }
  HeadlessFrameLoop(const HeadlessFrameLoop&) = delete;
  HeadlessFrameLoop& operator=(const HeadlessFrameLoop&) = delete;

  app::ExplorerState state;
  app::LiveView view;
  GLuint colour = 0, window = 0;

  // Runs one frame and waits for the GL, so the time is the frame's real cost.
  app::LiveFrame run() {
    const app::LiveFrame frame = app::liveFrame(view, state, kWidth, kHeight, window);
    glFinish();
    return frame;
  }

  // One turn of the window loop with no input arriving: the wait app::frameWaitSeconds asks for
  // (glfwWaitEventsTimeout), then a frame unless the wait was one of rest (true: nothing drawn).
  // Frames also wait between the points picture's steps, and then draw. `frameMs` gets the
  // frame's milliseconds (negative: none was drawn).
  bool step(app::ExplorerSession& session, double* frameMs = nullptr) {
    if (frameMs) *frameMs = -1.0;
    state.frame.session = session.status();
    const double wait = app::frameWaitSeconds(state, view.resting(), restingFrames);
    if (wait > 0.0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));
      if (!state.frame.view.waitingForPoints) return true;
    }
    const auto start = std::chrono::steady_clock::now();
    run();
    if (frameMs) *frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    restingFrames = view.resting() && state.frame.session.resting ? restingFrames + 1 : 0;
    return false;
  }
  int restingFrames = 0;  // frames in a row that found the view and the session at rest
};

}  // namespace voxflame::bench
