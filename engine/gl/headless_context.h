// An OpenGL 4.3+ core context with no window, through EGL: the surfaceless platform (Mesa's
// llvmpipe when there is no GPU), or an EGL device (the vendor driver on GPU servers). Used by
// the tests and by every offline render. The context is current on the creating thread only.
//
// A context may share its objects (textures, buffers, syncs) with one current on another thread:
// the GPU refinement backend fills textures on its own thread that the renderer's context then
// reads, with no trip through host memory.
#pragma once

#include <string>

namespace voxflame::gl {

// An EGL context and its display, to share objects with: the renderer's, taken on its thread.
struct ShareGroup {
  void* display = nullptr;
  void* context = nullptr;
  bool empty() const { return context == nullptr; }
};
// The EGL context current on this thread (a HeadlessContext, or a window's made through EGL);
// empty when none is current or the current one is not EGL's (a GLX window).
ShareGroup currentShareGroup();

class HeadlessContext {
 public:
  // Creates and makes current; throws core::Error saying why it could not. With a share group,
  // the context is made on that display and shares that context's objects.
  explicit HeadlessContext(const ShareGroup& shareWith = {});
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;  // GL_RENDERER
  std::string version() const;   // GL_VERSION

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  bool countsDisplay_ = true;  // the display is one this file opened (else a window's: never terminated here)
};

}  // namespace voxflame::gl
