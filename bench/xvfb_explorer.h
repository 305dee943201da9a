// The real explorer driven as a user drives it: a private X server (Xvfb), the explorer binary in
// the background on it, and xdotool for keys and the mouse. Used by `bench explorer`'s typing
// measurement and by the tests that drive the window (tests/explorer_test.cpp).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace voxflame::bench {

// A private X server for as long as the object lives, on a display number nobody else uses.
class XvfbServer {
 public:
  // Xvfb picks a free display itself (-displayfd) and writes its number to a pipe: servers started
  // at once never share a display (two picking the same free number would, and a key meant for
  // one explorer would reach another).
  explicit XvfbServer(const std::string& screen = "1280x720x24");
  ~XvfbServer();
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;
  void stop();
  bool running() const;
  std::string environment() const { return "DISPLAY=:" + std::to_string(display_); }

  // Runs xdotool on this display (a shell-quoted argument string); its exit status. A window
  // search waits at most two minutes.
  int xdotool(const std::string& arguments) const;
  // Waits until the title of a window on this display contains `text` (true), or `limit` passes
  // (false). Sleeps on the server's events (a title set, a window created), not on a timer.
  bool waitForTitle(const std::string& text, std::chrono::milliseconds limit) const;

 private:
  int display_ = -1;
  pid_t pid_ = -1;
};

bool haveXvfbAndXdotool();

// The xdotool arguments that find the explorer's window once it is shown.
inline constexpr const char* kFindExplorerWindow = "search --sync --onlyvisible --name voxflame";

// The explorer `binary` running in the background on `server`, as a user starts it (not a
// scripted run: settings and autosaves are on), with its settings, state and caches in `folder`,
// its working directory there, and its output in folder/explorer.log. Killed when destroyed.
class BackgroundExplorer {
 public:
  BackgroundExplorer(const XvfbServer& server, const std::filesystem::path& binary, const std::filesystem::path& folder,
                     std::vector<std::string> arguments);
  ~BackgroundExplorer();
  BackgroundExplorer(const BackgroundExplorer&) = delete;
  BackgroundExplorer& operator=(const BackgroundExplorer&) = delete;
  bool started() const { return pid_ > 0 || status_; }
  void signal(int number) const;

  // Waits up to `limit` for the explorer to end: its exit status (128 + N for signal N), or none
  // while it is still running.
  std::optional<int> exitStatus(std::chrono::seconds limit = std::chrono::seconds(120));
  std::string output() const;

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

}  // namespace voxflame::bench
