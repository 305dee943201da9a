// Images in memory and on disk. Renders come back from GL as linear-light float RGBA; writers
// quantise to 8 or 16 bits per channel and store text chunks (the preset travels inside the PNG
// as an iTXt chunk, so a render can be reopened and reproduced).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace voxflame::core {

// Display-ready (already tone-mapped, sRGB-encoded) RGBA in [0, 1], rows top to bottom.
struct ImageRGBA {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;  // 4 per pixel

  float* at(int x, int y) {
    return &pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
  }
  const float* at(int x, int y) const {
    return &pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
  }
};

using TextChunks = std::map<std::string, std::string>;  // keyword -> UTF-8 text

// Writes a PNG of 8 or 16 bits per channel. The file appears complete or not at all (written to
// a temporary beside it, then renamed). Throws core::Error naming the path on failure.
void writePng(const std::filesystem::path& path, const ImageRGBA& image, int bitDepth, const TextChunks& text);

// Writes a 32-bit float RGBA OpenEXR (linear light expected), complete or not at all.
void writeExr(const std::filesystem::path& path, const ImageRGBA& image, const TextChunks& text);
ImageRGBA readExr(const std::filesystem::path& path);

struct PngInfo {
  ImageRGBA image;
  TextChunks text;
  int bitDepth = 8;
};
// Reads any PNG libpng reads (up to 65536 pixels a side) as RGBA in [0, 1], rows top to bottom.
// Throws core::Error naming the file when it cannot, or when it holds more than `maxPixels`
// (checked before the pixels are decoded).
PngInfo readPng(const std::filesystem::path& path, std::uint64_t maxPixels = UINT64_MAX);
// The same for a PNG held in memory (a picture a flame file inlines); the error names `what`.
PngInfo readPngBytes(std::string_view bytes, const std::string& what, std::uint64_t maxPixels = UINT64_MAX);

// `image` shrunk to at most `maxWidth` pixels wide (never enlarged; at least 1), the height in
// proportion (rounded down, at least 1). Each output pixel is the area average of the source
// pixels it covers, a source pixel straddling two outputs counting in each by the part it gives.
ImageRGBA downscaleToWidth(const ImageRGBA& image, int maxWidth);

}  // namespace voxflame::core
