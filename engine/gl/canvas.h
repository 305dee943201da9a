// An offscreen RGBA8 colour buffer standing in for a window's: what the live view draws into in
// tests and benches, read back through gl/read_back.h. Main (GL) thread only.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace voxflame::gl {

class Canvas {
 public:
  Canvas(int width, int height);  // needs a current GL context
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  bool complete() const { return complete_; }  // the framebuffer can be drawn into
  GLuint framebuffer() const { return framebuffer_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // The picture, 4 bytes a pixel, rows top to bottom (one read-back).
  std::vector<std::uint8_t> pixels() const;

 private:
  int width_, height_;
  GLuint texture_ = 0, framebuffer_ = 0;
  bool complete_ = false;
};

}  // namespace voxflame::gl
