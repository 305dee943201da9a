// The explorer's frame body without a window, for the benchmarks: app::LiveView, the very code
// the explorer runs under its panels. A headless context has no window: the frame goes to a
// 1280×720 colour buffer standing in for it.
#pragma once

#include <epoxy/gl.h>

#include "core/scene.h"
#include "explorer_session.h"
#include "live_view.h"

namespace voxflame::bench {

struct HeadlessFrameLoop {
  static constexpr int kWidth = 1280, kHeight = 720;
  HeadlessFrameLoop(app::ExplorerSession& session, const core::Scene& scene, float renderScale)
      : view(session, nullptr, nullptr) {
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
};

}  // namespace voxflame::bench
