#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "core/image_io.h"
#include "test_support.h"

using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

namespace {

// A private X server for the duration of a test, on a display number nobody else uses.
class XvfbServer {
 public:
  XvfbServer() {
    for (int candidate = 90 + static_cast<int>(getpid() % 50); candidate < 400; ++candidate) {
      if (std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(candidate)) ||
          std::filesystem::exists("/tmp/.X" + std::to_string(candidate) + "-lock"))
        continue;
      display_ = candidate;
      break;
    }
    pid_ = fork();
    if (pid_ == 0) {
      const std::string display = ":" + std::to_string(display_);
      execlp("Xvfb", "Xvfb", display.c_str(), "-screen", "0", "1280x720x24", "-nolisten", "tcp", nullptr);
      _exit(127);
    }
    for (int i = 0; i < 100 && !std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(display_)); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ~XvfbServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool running() const { return std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(display_)); }
  std::string environment() const { return "DISPLAY=:" + std::to_string(display_); }

 private:
  int display_ = 99;
  pid_t pid_ = -1;
};

}  // namespace

TEST(Explorer, WindowUnderXvfbShowsPanelAndLitVolume) {
  XvfbServer server;
  ASSERT_TRUE(server.running()) << "Xvfb did not start (the setup script installs it)";
  TemporaryFolder folder;
  const auto result = runVoxflame("--screenshot shot.png --frames 3", folder.path(),
                                  "env LIBGL_ALWAYS_SOFTWARE=1 " + server.environment());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto png = voxflame::core::readPng(folder / "shot.png");
  ASSERT_EQ(png.image.width, 1280);
  ASSERT_EQ(png.image.height, 720);
  // The Pattern panel sits at the top left: its headers and sliders are a saturated blue-grey,
  // unlike the near-black background.
  int panelPixels = 0;
  for (int y = 30; y < 120; ++y)
    for (int x = 20; x < 300; ++x) {
      const float* p = png.image.at(x, y);
      panelPixels += (p[2] > 0.15f && p[2] > p[0] + 0.03f);
    }
  EXPECT_GT(panelPixels, 1000) << "no ImGui panel in the screenshot";
  // The volume lights up pixels in the middle of the window.
  int lit = 0;
  for (int y = 200; y < 600; ++y)
    for (int x = 400; x < 900; ++x) {
      const float* p = png.image.at(x, y);
      lit += (p[0] + p[1] + p[2] > 0.4f);
    }
  EXPECT_GT(lit, 2000) << "the volume is dark in the screenshot";
}
