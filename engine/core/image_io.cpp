#include "image_io.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>

#include "error.h"
#include "file_output.h"

namespace voxflame::core {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void pngError(png_structp png, png_const_charp message) {
  auto* reason = static_cast<std::string*>(png_get_error_ptr(png));
  if (reason) *reason = message;
  png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}

// All libpng work happens in functions that own no C++ objects with destructors across the
// setjmp, so a longjmp out of libpng skips nothing that needs unwinding.
bool writePngFile(std::FILE* file, const ImageRGBA& image, int bitDepth, const std::vector<png_text>& texts,
                  const std::vector<png_bytep>& rows, std::string& reason) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &reason, pngError, pngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), bitDepth,
               PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (!texts.empty()) png_set_text(png, info, texts.data(), static_cast<int>(texts.size()));
  png_write_info(png, info);
  if (bitDepth == 16) png_set_swap(png);  // our 16-bit samples are little-endian in memory
  png_write_image(png, const_cast<png_bytepp>(rows.data()));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void writePng(const std::filesystem::path& path, const ImageRGBA& image, int bitDepth, const TextChunks& text) {
  if (bitDepth != 8 && bitDepth != 16) throw Error("PNG bit depth must be 8 or 16, not " + std::to_string(bitDepth));
  if (image.width <= 0 || image.height <= 0) throw Error("cannot write an empty image to '" + path.string() + "'");

  const std::size_t channels = 4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  const std::size_t bytesPerSample = bitDepth == 16 ? 2 : 1;
  std::vector<std::uint8_t> data(channels * bytesPerSample);
  for (std::size_t i = 0; i < channels; ++i) {
    const float v = std::clamp(image.pixels[i], 0.0f, 1.0f);
    if (bitDepth == 8) {
      data[i] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    } else {
      const auto s = static_cast<std::uint16_t>(std::lround(v * 65535.0f));
      data[2 * i] = static_cast<std::uint8_t>(s & 0xff);
      data[2 * i + 1] = static_cast<std::uint8_t>(s >> 8);
    }
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  const std::size_t stride = 4 * static_cast<std::size_t>(image.width) * bytesPerSample;
  for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = data.data() + y * stride;

  std::vector<std::string> keys, values;
  for (const auto& [key, value] : text) {
    keys.push_back(key);
    values.push_back(value);
  }
  std::vector<png_text> texts(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    texts[i] = png_text{};
    texts[i].compression = PNG_ITXT_COMPRESSION_zTXt;
    texts[i].key = keys[i].data();
    texts[i].text = values[i].data();
    texts[i].itxt_length = values[i].size();
  }

  writeFileAtomicallyWith(path, [&](const std::filesystem::path& temporary) {
    std::string reason;
    FilePtr file(std::fopen(temporary.c_str(), "wb"));
    if (!file) throw Error("cannot write '" + path.string() + "': the folder is missing or not writable");
    const bool ok = writePngFile(file.get(), image, bitDepth, texts, rows, reason);
    const bool closed = std::fclose(file.release()) == 0;
    if (!ok || !closed)
      throw Error("cannot write '" + path.string() + "': " + (reason.empty() ? "disk full?" : reason));
  });
}

namespace {

// `rows` belongs to the caller: libpng reports errors with longjmp, which would skip the
// destructor of a vector made here.
bool readPngFile(std::FILE* file, std::uint64_t maxPixels, PngInfo& out, std::vector<std::uint8_t>& data,
                 std::vector<png_bytep>& rows, std::string& reason) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reason, pngError, pngWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, file);
  png_set_user_limits(png, 1u << 16, 1u << 16);
  png_read_info(png, info);
  if (static_cast<std::uint64_t>(png_get_image_width(png, info)) * png_get_image_height(png, info) > maxPixels)
    png_error(png, "the image is too large");
  const int bitDepth = png_get_bit_depth(png, info);
  png_set_expand(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xffff, PNG_FILLER_AFTER);
  if (bitDepth == 16) png_set_swap(png);
  png_read_update_info(png, info);
  const auto width = png_get_image_width(png, info);
  const auto height = png_get_image_height(png, info);
  const std::size_t rowBytes = png_get_rowbytes(png, info);
  data.resize(rowBytes * height);
  rows.resize(height);
  for (std::size_t y = 0; y < height; ++y) rows[y] = data.data() + y * rowBytes;
  png_read_image(png, rows.data());
  png_read_end(png, info);
  png_textp texts = nullptr;
  const int count = png_get_text(png, info, &texts, nullptr);
  for (int i = 0; i < count; ++i)
    out.text[texts[i].key] =
        std::string(texts[i].text, texts[i].text_length ? texts[i].text_length : texts[i].itxt_length);
  out.bitDepth = bitDepth == 16 ? 16 : 8;
  out.image.width = static_cast<int>(width);
  out.image.height = static_cast<int>(height);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

// The pixels readPngFile decoded, as floats in [0, 1].
PngInfo pngFrom(std::FILE* file, std::uint64_t maxPixels, const std::string& what) {
  PngInfo info;
  std::vector<std::uint8_t> data;
  std::vector<png_bytep> rows;
  std::string reason;
  if (!readPngFile(file, maxPixels, info, data, rows, reason)) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about chained concatenations here.
    std::string message = what;
    message.append(" is not a readable PNG");
    if (!reason.empty()) message.append(": ").append(reason);
    throw Error(message);
  }
  const std::size_t samples =
      4 * static_cast<std::size_t>(info.image.width) * static_cast<std::size_t>(info.image.height);
  info.image.pixels.resize(samples);
  for (std::size_t i = 0; i < samples; ++i)
    info.image.pixels[i] = info.bitDepth == 16 ? static_cast<float>(data[2 * i] | (data[2 * i + 1] << 8)) / 65535.0f
                                               : static_cast<float>(data[i]) / 255.0f;
  return info;
}

}  // namespace

PngInfo readPng(const std::filesystem::path& path, std::uint64_t maxPixels) {
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) throw Error("cannot open image '" + path.string() + "'");
  std::string what = "'";
  what.append(path.string()).append("'");
  return pngFrom(file.get(), maxPixels, what);
}

PngInfo readPngBytes(std::string_view bytes, const std::string& what, std::uint64_t maxPixels) {
  if (bytes.empty()) throw Error(what + " is empty");
  // POSIX's stream over a buffer, so libpng reads it as it reads a file.
  FilePtr file(fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "rb"));
  if (!file) throw Error("cannot read " + what);
  return pngFrom(file.get(), maxPixels, what);
}

namespace {

struct Tap {
  int source;
  float weight;
};

// For each of `to` output cells along an axis of `from` source cells: the source cells it
// covers and the share of each (weights sum to 1).
std::vector<std::vector<Tap>> areaTaps(int from, int to) {
  std::vector<std::vector<Tap>> taps(static_cast<std::size_t>(to));
  const double scale = static_cast<double>(from) / to;
  for (int o = 0; o < to; ++o) {
    const double begin = o * scale, end = (o + 1) * scale;
    for (int s = static_cast<int>(begin); s < from && s < end; ++s) {
      const double covered = std::min(end, s + 1.0) - std::max(begin, static_cast<double>(s));
      if (covered > 1e-9) taps[static_cast<std::size_t>(o)].push_back({s, static_cast<float>(covered / scale)});
    }
  }
  return taps;
}

}  // namespace

ImageRGBA downscaleToWidth(const ImageRGBA& image, int maxWidth) {
  if (image.width <= 0 || image.height <= 0) return image;
  const int width = std::clamp(maxWidth, 1, image.width);
  const int height = std::max(1, static_cast<int>(static_cast<long long>(image.height) * width / image.width));
  if (width == image.width && height == image.height) return image;
  const auto across = areaTaps(image.width, width), down = areaTaps(image.height, height);
  // Rows first, then columns: separable, so a pixel costs the taps of one axis plus the other.
  std::vector<float> rows(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(image.height), 0.0f);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < width; ++x) {
      float* out =
          &rows[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
      for (const Tap& tap : across[static_cast<std::size_t>(x)])
        for (int c = 0; c < 4; ++c) out[c] += tap.weight * image.at(tap.source, y)[c];
    }
  ImageRGBA result;
  result.width = width;
  result.height = height;
  result.pixels.assign(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
  for (int y = 0; y < height; ++y)
    for (const Tap& tap : down[static_cast<std::size_t>(y)])
      for (std::size_t i = 0; i < 4 * static_cast<std::size_t>(width); ++i)
        result.pixels[4 * static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + i] +=
            tap.weight * rows[4 * static_cast<std::size_t>(tap.source) * static_cast<std::size_t>(width) + i];
  return result;
}

}  // namespace voxflame::core
