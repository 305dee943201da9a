#include "read_back.h"

#include <algorithm>
#include <atomic>

namespace voxflame::gl {

namespace {

std::atomic<std::uint64_t> readBacks{0};

template <typename T>
std::vector<T> readRgba(GLuint framebuffer, PixelRegion region, GLenum type, T opaque, ReadAlpha alpha) {
  if (region.width <= 0 || region.height <= 0) return {};
  readBacks.fetch_add(1, std::memory_order_relaxed);
  const std::size_t row = 4 * static_cast<std::size_t>(region.width);
  std::vector<T> pixels(row * static_cast<std::size_t>(region.height));
  GLint previousFramebuffer = 0, previousAlignment = 4;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousFramebuffer);
  glGetIntegerv(GL_PACK_ALIGNMENT, &previousAlignment);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(region.x, region.y, region.width, region.height, GL_RGBA, type, pixels.data());
  glPixelStorei(GL_PACK_ALIGNMENT, previousAlignment);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
  // GL's rows run bottom to top.
  for (std::size_t top = 0, bottom = static_cast<std::size_t>(region.height) - 1; top < bottom; ++top, --bottom)
    std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(top * row),
                     pixels.begin() + static_cast<std::ptrdiff_t>((top + 1) * row),
                     pixels.begin() + static_cast<std::ptrdiff_t>(bottom * row));
  if (alpha == ReadAlpha::Opaque)
    for (std::size_t i = 3; i < pixels.size(); i += 4) pixels[i] = opaque;
  return pixels;
}

}  // namespace

std::vector<float> readRgbaFloat(GLuint framebuffer, PixelRegion region, ReadAlpha alpha) {
  return readRgba<float>(framebuffer, region, GL_FLOAT, 1.0f, alpha);
}

std::vector<std::uint8_t> readRgba8(GLuint framebuffer, PixelRegion region, ReadAlpha alpha) {
  return readRgba<std::uint8_t>(framebuffer, region, GL_UNSIGNED_BYTE, 255, alpha);
}

std::uint64_t readBackCount() {
  return readBacks.load(std::memory_order_relaxed);
}

}  // namespace voxflame::gl
