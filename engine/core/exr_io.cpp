// OpenEXR output for stills that keep their highlights (linear light, 32-bit float per channel).
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <exception>

#include "error.h"
#include "file_output.h"
#include "image_io.h"

namespace voxflame::core {

void writeExr(const std::filesystem::path& path, const ImageRGBA& image, const TextChunks& text) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot write an empty image to '" + path.string() + "'");
  writeFileAtomicallyWith(path, [&](const std::filesystem::path& temporary) {
    Imf::Header header(image.width, image.height);
    for (const char* channel : {"R", "G", "B", "A"}) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    for (const auto& [key, value] : text) header.insert(key, Imf::StringAttribute(value));
    Imf::FrameBuffer frame;
    const std::size_t pixelStride = 4 * sizeof(float);
    const std::size_t rowStride = pixelStride * static_cast<std::size_t>(image.width);
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), pixelStride, rowStride));
    Imf::OutputFile file(temporary.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  });
}

ImageRGBA readExr(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    ImageRGBA image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    image.pixels.assign(4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), 0.0f);
    Imf::FrameBuffer frame;
    const std::size_t pixelStride = 4 * sizeof(float);
    const std::size_t rowStride = pixelStride * static_cast<std::size_t>(image.width);
    char* base = reinterpret_cast<char*>(image.pixels.data()) -
                 (static_cast<std::ptrdiff_t>(window.min.x) * static_cast<std::ptrdiff_t>(pixelStride) +
                  static_cast<std::ptrdiff_t>(window.min.y) * static_cast<std::ptrdiff_t>(rowStride));
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), pixelStride, rowStride));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw Error("'" + path.string() + "' is not a readable EXR: " + e.what());
  }
}

}  // namespace voxflame::core
