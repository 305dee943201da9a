// Reading pixels back from GL. GL numbers rows from the bottom; everything else in voxflame
// (core::ImageRGBA, core::DensityImage, thumbnails, image files) runs top to bottom, so this is
// the one place that reads a framebuffer and turns its rows over. Every read-back in engine/gl
// and app goes through it, so readBackCount() tells a test whether a path stalls on one.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace voxflame::gl {

// A rectangle of a framebuffer in GL window coordinates: (x, y) is its lower-left pixel.
struct PixelRegion {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

enum class ReadAlpha {
  Keep,    // as stored
  Opaque,  // set to 1 (255): a screenshot or thumbnail of a window, whose alpha means nothing
};

// Reads `region` of `framebuffer` (0: the default framebuffer) from its current read buffer
// (GL_COLOR_ATTACHMENT0 for a framebuffer object, GL_BACK for a double-buffered window unless
// changed) as RGBA, 4 values per pixel, rows top to bottom: the first row returned is the region's
// top row. Empty for an empty region. Restores the GL_READ_FRAMEBUFFER binding and
// GL_PACK_ALIGNMENT it found; must run on the thread that owns the context.
std::vector<float> readRgbaFloat(GLuint framebuffer, PixelRegion region, ReadAlpha alpha = ReadAlpha::Keep);
std::vector<std::uint8_t> readRgba8(GLuint framebuffer, PixelRegion region, ReadAlpha alpha = ReadAlpha::Keep);

// Read-backs made so far in this process (each readRgbaFloat or readRgba8 of a non-empty region).
// A read-back waits for the GPU to finish: the explorer's frames must make none.
std::uint64_t readBackCount();

}  // namespace voxflame::gl
