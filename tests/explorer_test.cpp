#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "autosave.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "test_support.h"
#include "xvfb_explorer.h"

using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

using voxflame::bench::XvfbServer;

namespace {

bool haveXdotool() {
  return voxflame::bench::haveXvfbAndXdotool();
}

constexpr const char* kFindWindow = voxflame::bench::kFindExplorerWindow;

// The explorer built with these tests, in the background on a test's X server, with its files in
// the test's temporary folder.
class BackgroundExplorer : public voxflame::bench::BackgroundExplorer {
 public:
  BackgroundExplorer(const XvfbServer& server, const TemporaryFolder& folder, std::vector<std::string> arguments)
      : voxflame::bench::BackgroundExplorer(server, VOXFLAME_BINARY, folder.path(), std::move(arguments)) {}
};

// Each test's private X server and temporary folder, and the explorer it starts on them.
class Explorer : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(haveXdotool()) << "xdotool or Xvfb is missing (the setup script installs them)";
    ASSERT_TRUE(server.running()) << "Xvfb did not start (the setup script installs it)";
  }
  // The explorer as a user starts it, with its settings, state and caches in `folder`.
  BackgroundExplorer& start(std::vector<std::string> arguments) {
    explorer_.emplace(server, folder, std::move(arguments));
    return *explorer_;
  }

  XvfbServer server;
  TemporaryFolder folder;

 private:
  std::optional<BackgroundExplorer> explorer_;  // last: killed before the server stops
};

}  // namespace

TEST_F(Explorer, WindowUnderXvfbShowsPanelAndLitVolume) {
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

// ImGui 1.86 sees a key only if it is still held when a frame starts; a tap shorter than a frame
// used to be lost. xdotool presses Ctrl and Q and releases them within a few milliseconds (no
// delay between its chained commands), while each frame lasts at least 400 ms.
TEST_F(Explorer, CtrlQTappedFasterThanAFrameStillQuits) {
  BackgroundExplorer& explorer = start({"--min-frame-ms", "400", "--width", "640", "--height", "480"});
  ASSERT_TRUE(explorer.started());
  // In about one full parallel run of the suite in five, the first tap was lost (xdotool had sent
  // it, and the explorer ran on; alone, or under a CPU hog, it never was; the cause is not known),
  // so up to three taps are sent, each given 25 frames. A queue that loses short taps loses them all.
  std::optional<int> status;
  for (int tap = 0; tap < 3 && !status; ++tap) {
    ASSERT_EQ(server.xdotool(std::string(kFindWindow) + " windowfocus --sync keydown ctrl+q keyup ctrl+q"), 0)
        << explorer.output();
    status = explorer.exitStatus(std::chrono::seconds(tap < 2 ? 10 : 120));
  }
  ASSERT_TRUE(status) << "the explorer did not quit on a short Ctrl+Q tap\n" << explorer.output();
  EXPECT_EQ(*status, 0) << explorer.output();
  // The user quit: nothing is left to recover.
  EXPECT_TRUE(voxflame::app::findRecoverable(folder / "STATE" / "voxflame" / "autosave").empty());
}

// `xdotool windowclose` destroys the window under the explorer (XDestroyWindow); Xlib's default
// handler used to print "X Error" and exit(1). The scene must survive, as an autosave the next
// start offers back, since the user did not choose to quit.
TEST_F(Explorer, WindowDestroyedFromOutsideExitsCleanlyWithTheSceneAutosaved) {
  BackgroundExplorer& explorer = start({"--min-frame-ms", "100", "--width", "640", "--height", "480"});
  ASSERT_TRUE(explorer.started());
  ASSERT_EQ(server.xdotool(std::string(kFindWindow) + " windowclose"), 0) << explorer.output();
  const std::optional<int> status = explorer.exitStatus();
  ASSERT_TRUE(status) << "the explorer kept running without its window\n" << explorer.output();
  EXPECT_EQ(*status, 0) << explorer.output();
  EXPECT_EQ(explorer.output().find("X Error"), std::string::npos) << explorer.output();
  const auto recoverable = voxflame::app::findRecoverable(folder / "STATE" / "voxflame" / "autosave");
  ASSERT_EQ(recoverable.size(), 1u) << explorer.output();
  EXPECT_TRUE(recoverable.front().scene) << recoverable.front().error;
}

// The X server going away takes the connection with it: Xlib's default IO error handler used to
// exit(1). The explorer ends with status 0 and the scene autosaved, as when only the window goes.
TEST_F(Explorer, LostXServerExitsCleanlyWithTheSceneAutosaved) {
  BackgroundExplorer& explorer = start({"--min-frame-ms", "100", "--width", "640", "--height", "480"});
  ASSERT_TRUE(explorer.started());
  ASSERT_EQ(server.xdotool(kFindWindow), 0) << explorer.output();
  server.stop();
  const std::optional<int> status = explorer.exitStatus();
  ASSERT_TRUE(status) << "the explorer kept running without its X server\n" << explorer.output();
  EXPECT_EQ(*status, 0) << explorer.output();
  const auto recoverable = voxflame::app::findRecoverable(folder / "STATE" / "voxflame" / "autosave");
  ASSERT_EQ(recoverable.size(), 1u) << explorer.output();
  EXPECT_TRUE(recoverable.front().scene) << recoverable.front().error;
}

namespace {

// An unsaved change as a user makes one: W held flies the camera forward.
void flyForward(const XvfbServer& server) {
  ASSERT_EQ(server.xdotool(std::string(kFindWindow) + " windowfocus --sync keydown w sleep 0.8 keyup w"), 0);
}

// Whether the window's title comes to say the scene has unsaved changes within 30 s (the title
// changes with the frame after the edit, which a loaded machine draws late).
bool titleSaysUnsaved(const XvfbServer& server) {
  return server.waitForTitle("unsaved", std::chrono::seconds(30));
}

// Sleeps until something in `folder` is written or created (inotify), or `limit` passes.
class FolderWatch {
 public:
  explicit FolderWatch(const std::filesystem::path& folder) : fd_(inotify_init1(IN_CLOEXEC | IN_NONBLOCK)) {
    if (fd_ >= 0) inotify_add_watch(fd_, folder.c_str(), IN_MODIFY | IN_CLOSE_WRITE | IN_CREATE | IN_MOVED_TO);
  }
  ~FolderWatch() {
    if (fd_ >= 0) close(fd_);
  }
  FolderWatch(const FolderWatch&) = delete;
  FolderWatch& operator=(const FolderWatch&) = delete;
  // True when something happened (the events are drained), false after `limit`.
  bool waitForChange(std::chrono::milliseconds limit) const {
    pollfd watch{fd_, POLLIN, 0};
    if (fd_ < 0 || poll(&watch, 1, static_cast<int>(limit.count())) <= 0) return false;
    alignas(inotify_event) char events[4096];
    while (read(fd_, events, sizeof events) > 0) {
    }
    return true;
  }

 private:
  int fd_;
};

// Asks to quit and answers the prompt with `key` until the explorer ends: a key sent before a slow
// frame has drawn the prompt only flies the camera, and a Ctrl+Q tap is now and then lost under a
// loaded suite (see CtrlQTappedFasterThanAFrameStillQuits); Ctrl+Q on an open prompt changes
// nothing. Its exit status, or none.
std::optional<int> askAndAnswerUntilItEnds(const XvfbServer& server, BackgroundExplorer& explorer, const char* key) {
  for (int attempt = 0; attempt < 8; ++attempt) {
    if (server.xdotool(std::string(kFindWindow) + " windowfocus --sync key ctrl+q sleep 1 key " + key) != 0) break;
    if (const std::optional<int> status = explorer.exitStatus(std::chrono::seconds(5))) return status;
  }
  return explorer.exitStatus(std::chrono::seconds(30));
}

}  // namespace

// Ctrl+Q with unsaved changes asks instead of quitting. Escape stays; D then quits without saving,
// and nothing is left to recover or saved.
TEST_F(Explorer, QuittingWithUnsavedChangesAsksThenCancelOrDiscard) {
  BackgroundExplorer& explorer = start({"--min-frame-ms", "50", "--width", "640", "--height", "480"});
  ASSERT_TRUE(explorer.started());
  flyForward(server);
  ASSERT_TRUE(titleSaysUnsaved(server)) << explorer.output();
  ASSERT_EQ(server.xdotool(std::string(kFindWindow) + " windowfocus --sync key ctrl+q"), 0);
  EXPECT_FALSE(explorer.exitStatus(std::chrono::seconds(3))) << "quit with unsaved changes without asking";
  ASSERT_EQ(server.xdotool(std::string(kFindWindow) + " windowfocus --sync key Escape"), 0);
  EXPECT_FALSE(explorer.exitStatus(std::chrono::seconds(2))) << "Escape (Cancel) quit";
  EXPECT_TRUE(titleSaysUnsaved(server)) << "Cancel kept the changes";
  const std::optional<int> status = askAndAnswerUntilItEnds(server, explorer, "d");
  ASSERT_TRUE(status) << "D (Discard) did not quit\n" << explorer.output();
  EXPECT_EQ(*status, 0) << explorer.output();
  EXPECT_TRUE(voxflame::app::findRecoverable(folder / "STATE" / "voxflame" / "autosave").empty());
  EXPECT_FALSE(std::filesystem::exists(folder / "DATA" / "voxflame" / "presets")) << "Discard saved something";
}

// S in the prompt saves the scene as the user's preset of its name, then quits.
TEST_F(Explorer, QuittingWithUnsavedChangesCanSaveThem) {
  BackgroundExplorer& explorer = start({"--min-frame-ms", "50", "--width", "640", "--height", "480"});
  ASSERT_TRUE(explorer.started());
  flyForward(server);
  ASSERT_TRUE(titleSaysUnsaved(server)) << explorer.output();
  const std::optional<int> status = askAndAnswerUntilItEnds(server, explorer, "s");
  ASSERT_TRUE(status) << "S (Save) did not quit\n" << explorer.output();
  EXPECT_EQ(*status, 0) << explorer.output();
  EXPECT_TRUE(voxflame::app::findRecoverable(folder / "STATE" / "voxflame" / "autosave").empty());
  std::vector<std::filesystem::path> saved;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder / "DATA" / "voxflame" / "presets", ec))
    if (entry.path().extension() == ".json") saved.push_back(entry.path());
  ASSERT_EQ(saved.size(), 1u) << explorer.output();
  const voxflame::core::Scene scene = voxflame::core::loadScene(saved.front());
  EXPECT_NE(scene.camera.target, voxflame::core::defaultScene().camera.target) << "the flight was saved";
}

// A signal (a logout, kill, Ctrl+C in the terminal) is not the user's choice in the window: the
// explorer ends normally and the scene stays recoverable.
TEST_F(Explorer, ASignalEndsTheExplorerWithTheSceneAutosaved) {
  BackgroundExplorer& explorer = start({"--min-frame-ms", "50", "--width", "640", "--height", "480"});
  ASSERT_TRUE(explorer.started());
  ASSERT_EQ(server.xdotool(kFindWindow), 0) << explorer.output();
  explorer.signal(SIGTERM);
  const std::optional<int> status = explorer.exitStatus();
  ASSERT_TRUE(status) << "the explorer kept running after SIGTERM\n" << explorer.output();
  EXPECT_EQ(*status, 0) << explorer.output();
  const auto recoverable = voxflame::app::findRecoverable(folder / "STATE" / "voxflame" / "autosave");
  ASSERT_EQ(recoverable.size(), 1u) << explorer.output();
  EXPECT_TRUE(recoverable.front().scene) << recoverable.front().error;
}

// Ctrl+F puts the keyboard in the attractor filter, a quick Ctrl+A (xdotool releases Ctrl before
// A) selects what it holds, and what is typed shows in it; --input-log records each change with
// the time of the frame that showed it (what `bench explorer` measures typing with). Enter takes
// the first match: the title then says the scene has unsaved changes.
TEST_F(Explorer, CtrlFTypesIntoTheAttractorFilterAndTheInputLogSaysWhen) {
  BackgroundExplorer& explorer =
      start({"--input-log", (folder / "typed.log").string(), "--width", "1280", "--height", "720"});
  ASSERT_TRUE(explorer.started());
  const auto lastLogged = [&] {
    std::ifstream in(folder / "typed.log");
    std::string last;
    for (std::string line; std::getline(in, line);) last = line;
    return last;
  };
  // A key may be lost while the suite loads the machine: each step is sent again until it shows,
  // the log read again whenever the explorer writes to it (3 s at most a try).
  const FolderWatch logWritten(folder.path());
  const auto sendUntilLogged = [&](const std::string& keys, const std::string& text) {
    const auto logged = [&] {
      const std::string last = lastLogged();
      return last.size() >= text.size() + 1 &&
             last.compare(last.size() - text.size() - 1, std::string::npos, "\t" + text) == 0;
    };
    for (int attempt = 0; attempt < 5; ++attempt) {
      if (server.xdotool(std::string(kFindWindow) + " windowfocus --sync " + keys) != 0) return false;
      const auto tryEnds = std::chrono::steady_clock::now() + std::chrono::seconds(3);
      for (;;) {
        if (logged()) return true;
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(tryEnds - std::chrono::steady_clock::now());
        if (left <= std::chrono::milliseconds(0) || !logWritten.waitForChange(left)) break;
      }
    }
    return false;
  };
  // Each try empties the field first: a try whose first letter came in the frame that gave the
  // field the keyboard (a slow frame under load) left the rest of the word there.
  ASSERT_TRUE(sendUntilLogged("key ctrl+f sleep 0.5 key ctrl+a BackSpace sleep 0.3 type sprott", "sprott"))
      << lastLogged() << explorer.output();
  EXPECT_NE(lastLogged().find(" attractor filter\t"), std::string::npos) << lastLogged();
  ASSERT_TRUE(sendUntilLogged("key ctrl+a sleep 0.3 type lorenz", "lorenz"))
      << "Ctrl+A did not select the filter's text: " << lastLogged();
  ASSERT_EQ(server.xdotool(std::string(kFindWindow) + " windowfocus --sync key Return"), 0);
  EXPECT_TRUE(server.waitForTitle("unsaved", std::chrono::seconds(10)))
      << "Enter did not take the filter's first match";
}
