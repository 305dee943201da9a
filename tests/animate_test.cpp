#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/image_io.h"
#include "core/scene.h"
#include "test_support.h"

using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

namespace {

const std::string& kSize = voxflame::test::kTinyFrameSize;

void writeTinyPreset(const TemporaryFolder& folder) {
  std::ofstream(folder / "tiny.json") << voxflame::test::tinyAnimationPreset(300'000);
}

// Mean absolute difference of the colour channels, in [0, 1].
double difference(const voxflame::core::ImageRGBA& a, const voxflame::core::ImageRGBA& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    sum += std::abs(a.pixels[i] - b.pixels[i]);
    ++count;
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}

voxflame::core::PngInfo frame(const std::filesystem::path& path) {
  return voxflame::core::readPng(path);
}

}  // namespace

TEST(Animate, ConsecutiveFramesDifferButOnlyALittle) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  auto result = runVoxflame("animate tiny.json -o 'frames/%04d.png' --frames 0-3" + kSize, folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(std::filesystem::exists(folder / ("frames/000" + std::to_string(i) + ".png")));
  EXPECT_FALSE(std::filesystem::exists(folder / "frames/0004.png"));
  EXPECT_NE(result.output.find("frame 3 (4 of 4"), std::string::npos) << result.output;
  result = runVoxflame("animate tiny.json -o 'far/%04d.png' --frames 19" + kSize, folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;

  std::vector<voxflame::core::PngInfo> frames;
  for (int i = 0; i < 4; ++i) frames.push_back(frame(folder / ("frames/000" + std::to_string(i) + ".png")));
  const double far = difference(frames[0].image, frame(folder / "far/0019.png").image);
  for (int i = 0; i + 1 < 4; ++i) {
    const double step = difference(frames[i].image, frames[i + 1].image);
    EXPECT_GT(step, 0.0) << "frames " << i << " and " << i + 1 << " are identical";
    EXPECT_LT(step, 0.5 * far) << "frames " << i << " and " << i + 1 << " differ as much as frames 0 and 19";
    std::printf("mean difference of frames %d and %d: %.4f (frames 0 and 19: %.4f)\n", i, i + 1, step, far);
  }

  // Each frame carries its preset at its own time, with the fit locked, so it can be rendered alone.
  for (int i = 0; i < 4; ++i) {
    const auto scene = voxflame::core::sceneFromJson(frames[i].text.at("voxflame:preset"), "frame");
    EXPECT_DOUBLE_EQ(scene.animation.time, i / 10.0);
    EXPECT_NEAR(scene.layers[0].transform.rotationDeg.y, 3.0 * i, 1e-9);
    EXPECT_TRUE(scene.layers[0].transform.lockFit);
    EXPECT_EQ(scene.keyframes.size(), 1u);
  }
  result = runVoxflame("render frames/0002.png -o again.png" + kSize, folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_EQ(frame(folder / "again.png").image.pixels, frames[2].image.pixels);
}

TEST(Animate, SplitRendersMatchOneRun) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  ASSERT_EQ(
      runVoxflame("animate tiny.json -o 'whole/%02d.png' --frames 0-3 --threads 2" + kSize, folder.path()).exitStatus,
      0);
  ASSERT_EQ(
      runVoxflame("animate tiny.json -o 'split/%02d.png' --frames 2-3 --threads 1" + kSize, folder.path()).exitStatus,
      0);
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'split/%02d.png' --frames 0-1" + kSize, folder.path()).exitStatus, 0);
  for (int i = 0; i < 4; ++i) {
    const std::string name = "0" + std::to_string(i) + ".png";
    const auto whole = frame(folder / "whole" / name);
    const auto split = frame(folder / "split" / name);
    EXPECT_EQ(whole.image.pixels, split.image.pixels) << "frame " << i;
    EXPECT_EQ(whole.text.at("voxflame:preset"), split.text.at("voxflame:preset")) << "frame " << i;
  }
}

TEST(Animate, MotionBlurAveragesSubFrames) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'sharp/%d.png' --frames 10" + kSize, folder.path()).exitStatus, 0);
  const auto result =
      runVoxflame("animate tiny.json -o 'blur/%d.png' --frames 10 --motion-blur 3 --shutter 1" + kSize, folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto sharp = frame(folder / "sharp/10.png");
  const auto blurred = frame(folder / "blur/10.png");
  EXPECT_GT(difference(sharp.image, blurred.image), 0.0);
  EXPECT_EQ(sharp.text.at("voxflame:preset"), blurred.text.at("voxflame:preset"));
}

TEST(Animate, VideoWithoutFfmpegSaysSoAndKeepsTheFrames) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  std::filesystem::create_directories(folder / "empty-bin");
  const auto result = runVoxflame("animate tiny.json -o 'f/%03d.png' --frames 0-1 --video out.mp4" + kSize,
                                  folder.path(), "env PATH=" + (folder / "empty-bin").string());
  EXPECT_EQ(result.exitStatus, 3) << result.output;
  EXPECT_NE(result.output.find("ffmpeg is not installed"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("-c:v libx264"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "f/000.png"));
  EXPECT_TRUE(std::filesystem::exists(folder / "f/001.png"));
  EXPECT_FALSE(std::filesystem::exists(folder / "out.mp4"));
}

TEST(Animate, VideoRunsFfmpegOnTheFrames) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  std::filesystem::create_directories(folder / "bin");
  // A stand-in ffmpeg that records its arguments, one per line.
  const auto fake = folder / "bin" / "ffmpeg";
  std::ofstream(fake) << "#!/bin/sh\nfor a in \"$@\"; do echo \"$a\"; done > \""
                      << (folder / "ffmpeg-args.txt").string() << "\"\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const auto result = runVoxflame("animate tiny.json -o 'f/%04d.png' --frames 2-3 --fps 12 --video out.mp4" + kSize,
                                  folder.path(), "env PATH=" + (folder / "bin").string() + ":/usr/bin:/bin");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  std::ifstream in(folder / "ffmpeg-args.txt");
  std::vector<std::string> arguments;
  for (std::string line; std::getline(in, line);) arguments.push_back(line);
  const auto after = [&](const std::string& option) {
    for (std::size_t i = 0; i + 1 < arguments.size(); ++i)
      if (arguments[i] == option) return arguments[i + 1];
    return std::string("(missing)");
  };
  EXPECT_EQ(after("-framerate"), "12");
  EXPECT_EQ(after("-start_number"), "2");
  EXPECT_EQ(after("-i"), "f/%04d.png");
  EXPECT_EQ(after("-frames:v"), "2");
  EXPECT_EQ(after("-c:v"), "libx264");
  EXPECT_EQ(after("-pix_fmt"), "yuv420p");
  ASSERT_FALSE(arguments.empty());
  EXPECT_EQ(arguments.back(), "out.mp4");
  // --fps 12 makes two seconds 25 frames; frame 3 is at 0.25 s.
  const auto scene = voxflame::core::sceneFromJson(frame(folder / "f/0003.png").text.at("voxflame:preset"), "f");
  EXPECT_DOUBLE_EQ(scene.animation.time, 0.25);
}

TEST(Animate, BadPatternsAndRangesGiveMessages) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  const auto message = [&](const std::string& arguments) {
    const auto result = runVoxflame("animate tiny.json " + arguments, folder.path());
    EXPECT_NE(result.exitStatus, 0) << arguments;
    return result.output;
  };
  EXPECT_NE(message("-o frames.png").find("has no frame number"), std::string::npos);
  EXPECT_NE(message("-o '%d_%04d.png'").find("has 2 conversions"), std::string::npos);
  EXPECT_NE(message("-o '%s.png'").find("%s is not allowed"), std::string::npos);
  EXPECT_NE(message("-o '%x.png'").find("'%x' is not a frame number"), std::string::npos);
  EXPECT_NE(message("-o 'f/%04d.jpg'").find("must end in .png"), std::string::npos);
  EXPECT_NE(message("").find("animate needs an output pattern"), std::string::npos);
  EXPECT_NE(message("-o 'f/%04d.png' --frames 5-2").find("the first frame comes after the last"), std::string::npos);
  EXPECT_NE(message("-o 'f/%04d.png' --frames 0-100").find("the animation has 21 frames (0-20) at 10 fps"),
            std::string::npos);
  EXPECT_NE(message("-o 'f/%04d.png' --frames x").find("--frames expects A-B or N"), std::string::npos);
  EXPECT_NE(message("-o 'f/%04d.png' --motion-blur 0").find("--motion-blur"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder / "f"));
}

TEST(Animate, RenderShowsThePresetsMoment) {
  TemporaryFolder folder;
  writeTinyPreset(folder);
  const auto result = runVoxflame("render tiny.json --time 1 -o still.png" + kSize, folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto scene = voxflame::core::sceneFromJson(frame(folder / "still.png").text.at("voxflame:preset"), "still");
  EXPECT_DOUBLE_EQ(scene.animation.time, 1.0);
  EXPECT_NEAR(scene.layers[0].transform.rotationDeg.y, 30.0, 1e-9);
}

TEST(Animate, VolumeFramesHoldEachMomentsVolume) {
  // `-o frames/%04d.vdb|.nrrd`: each frame's accumulated volume, with the locked fit and the
  // preset's seed of the PNG frames: a frame rendered alone is the same file as in the whole run.
  TemporaryFolder folder;
  writeTinyPreset(folder);
  auto result = runVoxflame("animate tiny.json -o 'vol/%02d.nrrd' --frames 0-3", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'one/%02d.nrrd' --frames 2", folder.path()).exitStatus, 0);
  auto bytes = [&](const std::filesystem::path& path) {
    std::ifstream in(folder / path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  for (int f = 0; f <= 3; ++f) {
    const std::string frame = bytes("vol/0" + std::to_string(f) + ".nrrd");
    EXPECT_EQ(frame.rfind("NRRD", 0), 0u) << f;
    EXPECT_NE(frame.find("voxflame_preset"), std::string::npos) << "the frame's preset rides along";
  }
  EXPECT_EQ(bytes("one/02.nrrd"), bytes("vol/02.nrrd")) << "the same frame, the same file";
  EXPECT_NE(bytes("vol/00.nrrd"), bytes("vol/03.nrrd")) << "the layer turns between them";
  EXPECT_EQ(runVoxflame("animate tiny.json --status 'vol/%02d.nrrd' --frames 0-3", folder.path()).exitStatus, 0);

  result = runVoxflame("animate tiny.json -o 'vdb/%d.vdb' --frames 0-1", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_EQ(bytes("vdb/0.vdb").substr(0, 4), " BDV");
  const auto status = runVoxflame("animate tiny.json --status 'vdb/%d.vdb' --frames 0-2", folder.path());
  EXPECT_NE(status.exitStatus, 0);
  EXPECT_NE(status.output.find("missing 1: 2"), std::string::npos) << status.output;

  // A volume is one moment, not a picture.
  EXPECT_NE(runVoxflame("animate tiny.json -o 'x/%d.vdb' --video out.mp4", folder.path()).output.find("not a video"),
            std::string::npos);
  EXPECT_NE(runVoxflame("animate tiny.json -o 'x/%d.vdb' --motion-blur 3", folder.path()).output.find("one moment"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder / "x"));
}
