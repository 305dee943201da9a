// An OpenGL 4.3+ core context with no window, through EGL: the surfaceless platform (Mesa's
// llvmpipe when there is no GPU), or an EGL device (the vendor driver on GPU servers). Used by
// the tests and by every offline render. The context is current on the creating thread only.
#pragma once

#include <string>

namespace voxflame::gl {

class HeadlessContext {
 public:
  HeadlessContext();  // creates and makes current; throws core::Error saying why it could not
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;  // GL_RENDERER
  std::string version() const;   // GL_VERSION

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace voxflame::gl
