#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

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
    const std::string name = "image" + std::to_string(depth) + ".png";
    EXPECT_EQ(voxflame::test::filesStartingWith(folder.path(), name), std::vector<std::string>{name});
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

TEST(ImageIo, ReadPngRefusesImagesLargerThanAskedBeforeDecoding) {
  voxflame::test::TemporaryFolder folder;
  writePng(folder / "big.png", gradientImage(64, 32), 8, {});
  EXPECT_EQ(readPng(folder / "big.png", 64 * 32).image.width, 64);
  try {
    readPng(folder / "big.png", 64 * 32 - 1);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("big.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
  }
}

namespace {
ImageRGBA filled(int width, int height, const std::function<float(int x, int y, int c)>& value) {
  ImageRGBA image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c) image.at(x, y)[c] = value(x, y, c);
  return image;
}
}  // namespace

TEST(Downscale, WholeRatiosAverageBlocks) {
  // 4×2 to 2 wide: each output pixel is the mean of a 2×2 block.
  const ImageRGBA source = filled(4, 2, [](int x, int y, int c) { return static_cast<float>(x + 4 * y + c); });
  const ImageRGBA small = downscaleToWidth(source, 2);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 1);
  for (int c = 0; c < 4; ++c) {
    EXPECT_FLOAT_EQ(small.at(0, 0)[c], (0 + 1 + 4 + 5) / 4.0f + static_cast<float>(c));
    EXPECT_FLOAT_EQ(small.at(1, 0)[c], (2 + 3 + 6 + 7) / 4.0f + static_cast<float>(c));
  }
}

TEST(Downscale, FractionalRatiosWeighByCoveredArea) {
  // 3 pixels [0, 1, 0] to 2: each output covers one and a half source pixels, half of the middle one.
  const ImageRGBA source = filled(3, 3, [](int x, int, int) { return x == 1 ? 1.0f : 0.0f; });
  const ImageRGBA small = downscaleToWidth(source, 2);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) EXPECT_NEAR(small.at(x, y)[0], 1.0f / 3.0f, 1e-6f) << x << "," << y;
  // The mean brightness survives any ratio.
  const ImageRGBA noise =
      filled(97, 41, [](int x, int y, int c) { return static_cast<float>((x * 31 + y * 17 + c) % 13) / 12.0f; });
  const ImageRGBA shrunk = downscaleToWidth(noise, 20);
  EXPECT_EQ(shrunk.height, 41 * 20 / 97);
  const auto mean = [](const ImageRGBA& image) {
    double sum = 0.0;
    for (float v : image.pixels) sum += v;
    return sum / static_cast<double>(image.pixels.size());
  };
  // Rows are cut down to a whole number, so only roughly equal; columns exactly.
  EXPECT_NEAR(mean(shrunk), mean(noise), 0.02);
}

TEST(Downscale, NeverEnlargesNorLosesTheLastRow) {
  const ImageRGBA source = filled(5, 3, [](int x, int y, int) { return static_cast<float>(x * y); });
  const ImageRGBA same = downscaleToWidth(source, 100);
  EXPECT_EQ(same.width, 5);
  EXPECT_EQ(same.height, 3);
  EXPECT_EQ(same.pixels, source.pixels);
  const ImageRGBA strip = downscaleToWidth(filled(4000, 1, [](int, int, int) { return 0.5f; }), 100);
  EXPECT_EQ(strip.width, 100);
  EXPECT_EQ(strip.height, 1);
  EXPECT_NEAR(strip.at(99, 0)[2], 0.5f, 1e-6f);
  EXPECT_EQ(downscaleToWidth(source, 0).width, 1);
}
