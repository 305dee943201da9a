// Autosave and crash recovery: nothing the user made is lost when the explorer crashes or is
// killed. The explorer calls update(scene) every frame; at most every few seconds, and only when
// the scene differs from what is on disk (or from the scene the session started with), the scene
// is handed to a writer thread, which replaces this session's file atomically in
// $XDG_STATE_HOME/voxflame/autosave/ (else ~/.local/state/voxflame/autosave/).
//
// Each session writes its own file, named after its owner record (process id and the process's
// start time since boot, also stored inside with the boot id), so two explorers never overwrite
// each other and a recycled pid is not mistaken for the session that used it before. A clean
// exit removes the file (finishCleanly). At start, findRecoverable() lists the files whose
// owner is no longer running: sessions that crashed or were killed. A corrupt file is listed
// with its error, never a crash.
//
// Cost on the UI thread (Release, measured by the autosave tests): a frame between checks pays one
// clock read (tens of nanoseconds); a check serialises the scene to compare it (tens of
// microseconds for a one-layer scene). Parsing, writing and fsync happen on the writer thread.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/scene.h"

namespace voxflame::app {

// A running process, told apart from a later one that reuses its pid.
struct SessionOwner {
  pid_t pid = 0;
  std::uint64_t startTicks = 0;  // /proc/PID/stat's start time, clock ticks since boot
  std::string bootId;            // /proc/sys/kernel/random/boot_id

  static SessionOwner current();
  bool alive() const;  // the same process is still running
};

// $XDG_STATE_HOME/voxflame/autosave, else ~/.local/state/voxflame/autosave.
std::filesystem::path defaultAutosaveFolder();

class Autosave {
 public:
  struct Options {
    std::filesystem::path folder;              // empty: defaultAutosaveFolder()
    std::chrono::milliseconds interval{3000};  // between checks for a change
    // What the interval is measured on (empty: std::chrono::steady_clock::now). Tests step a clock
    // of their own through the interval instead of waiting for it.
    std::function<std::chrono::steady_clock::time_point()> clock;
  };

  Autosave() : Autosave(Options{}) {}
  explicit Autosave(Options options);
  // Writes what is pending and stops the writer. The file stays: only finishCleanly() says the
  // session ended well.
  ~Autosave();
  Autosave(const Autosave&) = delete;
  Autosave& operator=(const Autosave&) = delete;

  // Call every frame with the current scene, or (as the explorer does) on every frame after an
  // edit until it returns true; returns at once (see the cost above). Returns whether it looked at
  // this scene: false while the last look is less than the interval ago. The first scene seen is
  // the session's starting point and is not written.
  bool update(const core::Scene& scene);

  // Waits until every scene handed over is on disk (or failed). For tests and shutdown.
  void flush();

  // The session ended as the user wanted: stops autosaving and removes this session's file.
  void finishCleanly();

  // The session ends without the user choosing to (the window was destroyed from outside): writes
  // this scene now, even when unchanged since the start or the last check, waits until it is on
  // disk, and stops autosaving. The file stays, so the next start offers it back. Returns the
  // write's error ("" when it worked).
  std::string saveNow(const core::Scene& scene);

  const std::filesystem::path& file() const { return file_; }
  // The last write's error ("" when it worked), for the window; a failed autosave is retried at
  // the next change.
  std::string lastError() const;

 private:
  void writerLoop(std::stop_token stop);
  void write(const std::string& preset, const std::string& baseDirectory);

  std::filesystem::path file_;
  SessionOwner owner_;
  std::chrono::steady_clock::duration interval_;
  std::function<std::chrono::steady_clock::time_point()> clock_;
  std::chrono::steady_clock::time_point lastCheck_{};
  bool haveBaseline_ = false;
  bool finished_ = false;
  std::string lastHanded_;  // preset text + base directory of the last scene handed over

  mutable std::mutex mutex_;
  std::condition_variable_any wake_;
  std::condition_variable idle_;
  std::optional<std::pair<std::string, std::string>> pending_;  // preset text, base directory
  bool writing_ = false;
  std::string lastError_;
  std::jthread writer_;  // last: started after everything it uses, stopped first
};

struct Recoverable {
  std::filesystem::path file;
  std::optional<core::Scene> scene;  // empty when the file could not be read back
  std::string error;                 // why not, naming the file
  std::chrono::system_clock::time_point savedAt;
};

// The autosaves left by sessions that are no longer running, newest first. Never throws.
std::vector<Recoverable> findRecoverable(const std::filesystem::path& folder = defaultAutosaveFolder());

// Removes a recoverable autosave once the user has taken it back (the scene then lives in the
// current session, whose own autosave covers it) or declined it.
void dismissRecoverable(const Recoverable& recoverable);

}  // namespace voxflame::app
