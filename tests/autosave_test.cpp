#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

#include "autosave.h"
#include "autosave_helper.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "test_support.h"
#include "wait_for.h"

using voxflame::app::Autosave;
using voxflame::app::findRecoverable;
using voxflame::app::SessionOwner;
using voxflame::test::editedScene;
using voxflame::test::TemporaryFolder;

extern char** environ;

namespace {

Autosave::Options immediate(const std::filesystem::path& folder) {
  Autosave::Options options;
  options.folder = folder;
  options.interval = std::chrono::milliseconds(0);
  return options;
}

std::size_t autosaveFiles(const std::filesystem::path& folder) {
  std::size_t count = 0;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec))
    if (item.path().filename().string().rfind("autosave-", 0) == 0) ++count;
  return count;
}

// A pid that certainly belongs to no running process: a child that has exited and been reaped.
pid_t deadPid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

// Runs an "explorer" in another process (autosave_helper): it autosaves the edited scene and
// then waits to be killed. Returns its pid once the autosave is on disk, which the helper says by
// writing a line into a pipe (its READY_FILE is the pipe's end): this sleeps in poll() until the
// line comes, or the pipe closes because the helper ended early.
pid_t startAutosavingChild(const std::filesystem::path& folder) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    ADD_FAILURE() << "pipe2: " << std::strerror(errno);
    return -1;
  }
  // The helper gets the write end as descriptor 3 (dup2 clears its close-on-exec there); one that
  // is already 3 moves first, as a dup2 onto itself would keep the flag.
  if (fds[1] == 3) {
    const int moved = fcntl(fds[1], F_DUPFD_CLOEXEC, 4);
    close(fds[1]);
    fds[1] = moved;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 3);
  std::string helper = VOXFLAME_AUTOSAVE_HELPER, folderArg = folder.string(), readyArg = "/dev/fd/3";
  char* argv[] = {helper.data(), folderArg.data(), readyArg.data(), nullptr};
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, helper.c_str(), &actions, nullptr, argv, environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);  // only the helper's end is left: the pipe closes if it ends
  pollfd ready{fds[0], POLLIN, 0};
  const int polled = poll(&ready, 1, static_cast<int>(voxflame::test::kEventTimeout.count() * 1000));
  char line[16] = {};
  const ssize_t got = polled == 1 ? read(fds[0], line, sizeof line - 1) : -1;
  close(fds[0]);
  EXPECT_GT(got, 0) << (polled == 1 ? "autosave_helper ended early" : "autosave_helper never got ready");
  return pid;
}

}  // namespace

TEST(Autosave, OwnerRecordTellsLiveFromDead) {
  const SessionOwner me = SessionOwner::current();
  EXPECT_EQ(me.pid, getpid());
  EXPECT_GT(me.startTicks, 0u);
  EXPECT_TRUE(me.alive());
  SessionOwner reused = me;
  reused.startTicks += 1;  // same pid, another process (pid reuse)
  EXPECT_FALSE(reused.alive());
  SessionOwner rebooted = me;
  rebooted.bootId = "another boot";
  EXPECT_FALSE(rebooted.alive());
  SessionOwner gone = me;
  gone.pid = deadPid();
  EXPECT_FALSE(gone.alive());
}

TEST(Autosave, KilledSessionIsRecoveredWithAnEqualScene) {
  TemporaryFolder folder;
  const auto before = std::chrono::system_clock::now();
  const pid_t child = startAutosavingChild(folder.path());
  // While the session runs, its autosave is not for anyone else to take.
  EXPECT_EQ(autosaveFiles(folder.path()), 1u);
  EXPECT_TRUE(findRecoverable(folder.path()).empty());
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);

  const auto found = findRecoverable(folder.path());
  ASSERT_EQ(found.size(), 1u);
  ASSERT_TRUE(found[0].scene.has_value()) << found[0].error;
  EXPECT_EQ(voxflame::core::sceneToJson(*found[0].scene), voxflame::core::sceneToJson(editedScene()));
  EXPECT_TRUE(found[0].scene->embedded);
  EXPECT_GE(found[0].savedAt, before - std::chrono::seconds(1));
  EXPECT_LE(found[0].savedAt, std::chrono::system_clock::now() + std::chrono::seconds(1));
  voxflame::app::dismissRecoverable(found[0]);
  EXPECT_TRUE(findRecoverable(folder.path()).empty());
}

TEST(Autosave, RecordWithDeadPidIsRecoveredWithItsMeshFolder) {
  TemporaryFolder folder;
  voxflame::core::Scene scene = voxflame::core::defaultScene();
  scene.embedded = false;
  scene.meshPath = "meshes/teapot.obj";
  scene.baseDirectory = folder / "project";
  const std::string name = "autosave-" + std::to_string(deadPid()) + "-12345.json";
  std::ofstream(folder / name) << R"({"format": "voxflame-autosave", "version": 1, "saved_at": 1700000000.5,
      "base_directory": ")" + (folder / "project").string() +
                                      R"(", "preset": )" + voxflame::core::sceneToJson(scene) + "}";
  const auto found = findRecoverable(folder.path());
  ASSERT_EQ(found.size(), 1u);
  ASSERT_TRUE(found[0].scene.has_value()) << found[0].error;
  EXPECT_EQ(found[0].scene->resolvedMeshPath(), folder / "project" / "meshes" / "teapot.obj");
  EXPECT_EQ(std::chrono::duration_cast<std::chrono::milliseconds>(found[0].savedAt.time_since_epoch()).count(),
            1'700'000'000'500);
}

TEST(Autosave, CleanExitLeavesNothingToRecover) {
  TemporaryFolder folder;
  {
    Autosave autosave(immediate(folder.path()));
    autosave.update(voxflame::core::defaultScene());
    autosave.update(editedScene());
    autosave.flush();
    EXPECT_TRUE(std::filesystem::exists(autosave.file()));
    EXPECT_EQ(autosave.file().parent_path(), folder.path());
    autosave.finishCleanly();
    EXPECT_FALSE(std::filesystem::exists(autosave.file()));
    autosave.update(voxflame::core::defaultScene());  // ignored once finished
  }
  EXPECT_EQ(autosaveFiles(folder.path()), 0u);
  EXPECT_TRUE(findRecoverable(folder.path()).empty());
}

TEST(Autosave, WritesOnlyChangesAndAtMostOncePerInterval) {
  TemporaryFolder folder;
  Autosave::Options options = immediate(folder.path());
  options.interval = std::chrono::milliseconds(300);
  // The interval passes on a clock of the test's own, stepped instead of waited for.
  auto now = std::chrono::steady_clock::time_point{} + std::chrono::hours(1);
  options.clock = [&now] { return now; };
  Autosave autosave(options);
  autosave.update(voxflame::core::defaultScene());
  autosave.flush();
  EXPECT_FALSE(std::filesystem::exists(autosave.file()));  // the starting scene is not written
  EXPECT_FALSE(autosave.update(editedScene()));            // within the interval: not yet looked at
  now += std::chrono::milliseconds(299);
  EXPECT_FALSE(autosave.update(editedScene()));
  autosave.flush();
  EXPECT_FALSE(std::filesystem::exists(autosave.file()));
  now += std::chrono::milliseconds(51);
  EXPECT_TRUE(autosave.update(editedScene()));
  autosave.flush();
  ASSERT_TRUE(std::filesystem::exists(autosave.file()));
  // Unchanged: not written again. The file goes, so that a write would bring it back (a time
  // stamp might not move within its resolution).
  std::filesystem::remove(autosave.file());
  now += std::chrono::milliseconds(350);
  EXPECT_TRUE(autosave.update(editedScene()));
  autosave.flush();
  EXPECT_FALSE(std::filesystem::exists(autosave.file())) << "an unchanged scene was written again";
  EXPECT_TRUE(autosave.lastError().empty());
}

TEST(Autosave, UpdateCostsTheUiThreadLittle) {
  TemporaryFolder folder;
  const voxflame::core::Scene scene = editedScene();
  {
    // Between checks: a clock read. The scene changes on every call, yet none is looked at (a
    // look would serialise it, find the change and hand it to the writer).
    Autosave::Options options = immediate(folder.path());
    options.interval = std::chrono::seconds(3600);
    Autosave autosave(options);
    voxflame::core::Scene changing = scene;
    autosave.update(changing);
    constexpr int kCalls = 100'000;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kCalls; ++i) {
      changing.tone.brightness = 1.0 + i * 1e-5;
      autosave.update(changing);
    }
    const double perCall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / kCalls;
    std::printf("autosave update between checks: %.1f ns\n", perCall * 1e9);
    autosave.flush();
    EXPECT_FALSE(std::filesystem::exists(autosave.file())) << "a change was looked at between checks";
  }
  {
    // A check that finds a change: serialise, compare, hand over (the write is the thread's).
    Autosave autosave(immediate(folder.path()));
    voxflame::core::Scene changing = scene;
    autosave.update(changing);
    constexpr int kCalls = 200;
    double total = 0.0;
    for (int i = 0; i < kCalls; ++i) {
      changing.tone.brightness = 1.0 + i * 0.01;
      const auto start = std::chrono::steady_clock::now();
      autosave.update(changing);
      total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::printf("autosave update with a changed scene: %.1f us\n", total / kCalls * 1e6);
    autosave.flush();
    // Every check handed its change over: the writer put the last one on disk.
    ASSERT_TRUE(std::filesystem::exists(autosave.file()));
    std::ifstream file(autosave.file());
    const nlohmann::json saved = nlohmann::json::parse(file);
    EXPECT_DOUBLE_EQ(voxflame::core::sceneFromJson(saved.at("preset").dump(), "autosave").tone.brightness,
                     changing.tone.brightness);
    EXPECT_TRUE(autosave.lastError().empty()) << autosave.lastError();
    autosave.finishCleanly();
  }
}

TEST(Autosave, CorruptFilesGiveMessagesNotCrashes) {
  TemporaryFolder folder;
  const pid_t dead = deadPid();
  const auto file = [&](int n) {
    return folder / ("autosave-" + std::to_string(dead) + "-" + std::to_string(n) + ".json");
  };
  std::ofstream(file(1)) << "{ this is not json";
  std::ofstream(file(2))
      << R"({"format": "voxflame-autosave", "preset": {"mesh": {"path": "x.obj"}, "layers": [{"attractor": "no-such-attractor"}]}})";
  std::ofstream(file(3)) << std::string(100000, '[') + std::string(100000, ']');
  std::ofstream(file(4)) << R"({"format": "voxflame-autosave", "owner": {"pid": "seven"}, "preset": {}})";
  std::ofstream(folder / "autosave-garbage.json") << "ignored: not named like an autosave";
  std::ofstream(folder / ("autosave-" + std::to_string(dead) + "-9.json.tmp")) << "half written";
  std::ofstream(folder / ("autosave-" + std::to_string(dead) + "-8.json." + std::to_string(dead) + "-0.part"))
      << "half written";
  const auto found = findRecoverable(folder.path());
  ASSERT_EQ(found.size(), 4u);
  for (const auto& entry : found) {
    EXPECT_FALSE(entry.scene.has_value());
    EXPECT_NE(entry.error.find(entry.file.string()), std::string::npos) << entry.error;
  }
  const auto attractor = std::find_if(found.begin(), found.end(), [&](const auto& e) { return e.file == file(2); });
  ASSERT_NE(attractor, found.end());
  EXPECT_NE(attractor->error.find("no-such-attractor"), std::string::npos) << attractor->error;
  // The dead session's half-written temporary is cleared away.
  EXPECT_FALSE(std::filesystem::exists(folder / ("autosave-" + std::to_string(dead) + "-9.json.tmp")));
  EXPECT_FALSE(std::filesystem::exists(
      folder / ("autosave-" + std::to_string(dead) + "-8.json." + std::to_string(dead) + "-0.part")));
  EXPECT_TRUE(findRecoverable(folder / "no-such-folder").empty());
}

TEST(Autosave, TwoSessionsKeepTheirOwnFiles) {
  TemporaryFolder folder;
  const pid_t other = startAutosavingChild(folder.path());
  {
    Autosave mine(immediate(folder.path()));
    mine.update(voxflame::core::defaultScene());
    mine.update(editedScene());
    mine.flush();
    EXPECT_EQ(autosaveFiles(folder.path()), 2u);
    mine.finishCleanly();  // removes its own file only
  }
  EXPECT_EQ(autosaveFiles(folder.path()), 1u);
  EXPECT_TRUE(findRecoverable(folder.path()).empty());  // the other one is still running
  kill(other, SIGKILL);
  waitpid(other, nullptr, 0);
  EXPECT_EQ(findRecoverable(folder.path()).size(), 1u);
}

TEST(Autosave, DefaultFolderFollowsXdgStateHome) {
  const char* old = std::getenv("XDG_STATE_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_STATE_HOME", "/somewhere/state", 1);
  EXPECT_EQ(voxflame::app::defaultAutosaveFolder(), std::filesystem::path("/somewhere/state/voxflame/autosave"));
  if (old)
    setenv("XDG_STATE_HOME", saved.c_str(), 1);
  else
    unsetenv("XDG_STATE_HOME");
}
