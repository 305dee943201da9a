#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "core/image_io.h"
#include "test_support.h"

using namespace voxflame::core;

namespace {
ImageRGBA gradientImage(int width, int height) {
  ImageRGBA image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width * height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = image.at(x, y);
      p[0] = static_cast<float>(x) / static_cast<float>(width - 1);
      p[1] = static_cast<float>(y) / static_cast<float>(height - 1);
      p[2] = 0.25f;
      p[3] = 1.0f;
    }
  return image;
}
}  // namespace

TEST(ImageIo, PngRoundTripsPixelsAndText8And16Bit) {
  voxflame::test::TemporaryFolder folder;
  const ImageRGBA image = gradientImage(37, 21);
  const TextChunks text{{"voxflame:preset", "{\"name\": \"bunny — ünïcode\"}"}, {"Software", "voxflame"}};
  for (int depth : {8, 16}) {
    const auto path = folder / ("image" + std::to_string(depth) + ".png");
    writePng(path, image, depth, text);
    const PngInfo read = readPng(path);
    EXPECT_EQ(read.bitDepth, depth);
    ASSERT_EQ(read.image.width, 37);
    ASSERT_EQ(read.image.height, 21);
    const float tolerance = depth == 8 ? 0.5f / 255.0f : 0.5f / 65535.0f;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      ASSERT_NEAR(read.image.pixels[i], image.pixels[i], tolerance + 1e-6f) << i;
    EXPECT_EQ(read.text.at("voxflame:preset"), text.at("voxflame:preset"));
    EXPECT_FALSE(std::filesystem::exists(folder / ("image" + std::to_string(depth) + ".png.part")));
  }
}

TEST(ImageIo, UnwritablePathIsAnErrorAndLeavesNothing) {
  const ImageRGBA image = gradientImage(4, 4);
  EXPECT_THROW(writePng("/nonexistent/folder/out.png", image, 8, {}), Error);
}

TEST(ImageIo, CorruptPngIsAnError) {
  voxflame::test::TemporaryFolder folder;
  const ImageRGBA image = gradientImage(16, 16);
  writePng(folder / "ok.png", image, 8, {});
  std::filesystem::resize_file(folder / "ok.png", 60);
  EXPECT_THROW(readPng(folder / "ok.png"), Error);
  EXPECT_THROW(readPng(folder / "missing.png"), Error);
}
