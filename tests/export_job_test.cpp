#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "export_job.h"
#include "test_support.h"

using voxflame::app::ExportFormat;
using voxflame::app::ExportJob;
using voxflame::app::ExportRequest;
using voxflame::app::ExportState;
using voxflame::app::ExportStatus;
using voxflame::test::TemporaryFolder;

namespace {

ExportRequest tinyRequest(const std::filesystem::path& output) {
  ExportRequest request;
  request.scene = voxflame::core::defaultScene();
  request.scene.gridResolution = 48;
  request.output = output;
  request.settings.width = 48;
  request.settings.height = 32;
  request.settings.samples = 1;
  request.settings.points = 50'000;
  request.executable = VOXFLAME_BINARY;
  return request;
}

// Polls like the explorer does until the job ends, a "frame" whenever the child has news (or has
// ended); every status seen goes to `seen`.
ExportStatus pollUntilEnded(ExportJob& job, std::vector<ExportStatus>* seen = nullptr, double timeoutSeconds = 120) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  for (;;) {
    const auto poll0 = std::chrono::steady_clock::now();
    const ExportStatus status = job.poll();
    // poll() must never make a frame wait.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - poll0).count(), 0.05);
    if (seen) seen->push_back(status);
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (status.state != ExportState::Running || left <= std::chrono::milliseconds(0)) return status;
    job.waitForChange(left);
  }
}

// Waits until the child reports the stage (so it is past start-up and has its signal handlers),
// sleeping until the child writes something or ends.
bool waitForStage(ExportJob& job, const std::string& stage, double timeoutSeconds = 60) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  for (;;) {
    const ExportStatus status = job.poll();
    if (status.state != ExportState::Running) return false;
    if (status.stage == stage) return true;
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= std::chrono::milliseconds(0)) return false;
    job.waitForChange(left);
  }
}

bool reaped(pid_t pid) {
  errno = 0;
  return ::waitpid(pid, nullptr, WNOHANG) < 0 && errno == ECHILD;
}

}  // namespace

TEST(ExportJob, TinyExportWritesPngCarryingItsPreset) {
  TemporaryFolder folder;
  ExportJob job;
  auto request = tinyRequest(folder / "tiny.png");
  request.scene.name = "tiny export";
  job.start(request);
  EXPECT_TRUE(job.running());
  const ExportStatus status = pollUntilEnded(job);
  ASSERT_EQ(status.state, ExportState::Done) << status.error;
  EXPECT_EQ(status.output, folder / "tiny.png");
  EXPECT_EQ(status.summary.rfind("wrote " + (folder / "tiny.png").string(), 0), 0u) << status.summary;
  EXPECT_DOUBLE_EQ(status.overall, 1.0);
  const auto png = voxflame::core::readPng(folder / "tiny.png");
  EXPECT_EQ(png.image.width, 48);
  EXPECT_EQ(png.image.height, 32);
  EXPECT_EQ(png.bitDepth, 8);
  ASSERT_TRUE(png.text.count("voxflame:preset"));
  const auto stored = voxflame::core::sceneFromJson(png.text.at("voxflame:preset"), "tiny.png");
  EXPECT_EQ(stored.name, "tiny export");
  EXPECT_EQ(stored.points, 50'000u);
  EXPECT_TRUE(stored.embedded);
  EXPECT_FALSE(job.running());
}

TEST(ExportJob, RelativeMeshPathStillFoundAndProgressRises) {
  TemporaryFolder folder;
  std::filesystem::create_directories(folder / "work" / "meshes");
  std::filesystem::copy_file(voxflame::test::meshPath("bunny.obj"), folder / "work" / "meshes" / "bunny.obj");
  std::ofstream(folder / "work" / "p.json")
      << R"({"name":"relative","mesh":{"path":"meshes/bunny.obj"},"grid":{"resolution":48},
            "layers":[{"attractor":"lorenz84"}]})";
  ExportRequest request = tinyRequest(folder / "out16.png");
  request.scene = voxflame::core::loadScene(folder / "work" / "p.json");
  request.settings.format = ExportFormat::Png16;
  request.settings.points = 4'000'000;  // long enough for several progress reports
  request.settings.threads = 1;
  request.settings.samples = 4;
  ExportJob job;
  job.start(request);
  std::vector<ExportStatus> seen;
  const ExportStatus status = pollUntilEnded(job, &seen);
  ASSERT_EQ(status.state, ExportState::Done) << status.error;
  EXPECT_EQ(voxflame::core::readPng(folder / "out16.png").bitDepth, 16);
  double last = 0.0;
  std::set<std::string> stages;
  std::size_t rises = 0;
  for (const auto& s : seen) {
    EXPECT_GE(s.overall, last) << s.stage << " " << s.fraction;
    EXPECT_GE(s.fraction, 0.0);
    EXPECT_LE(s.fraction, 1.0);
    if (s.overall > last) ++rises;
    last = s.overall;
    stages.insert(s.stage);
  }
  EXPECT_GE(rises, 2u);
  EXPECT_TRUE(stages.count("accumulating")) << seen.size() << " polls";
}

TEST(ExportJob, ExrExport) {
  TemporaryFolder folder;
  ExportJob job;
  auto request = tinyRequest(folder / "linear.exr");
  request.settings.format = ExportFormat::Exr;
  job.start(request);
  const ExportStatus status = pollUntilEnded(job);
  ASSERT_EQ(status.state, ExportState::Done) << status.error;
  EXPECT_EQ(voxflame::core::readExr(folder / "linear.exr").width, 48);
}

TEST(ExportJob, CancelStopsTheChildAndLeavesNoFile) {
  TemporaryFolder folder;
  ExportJob job;
  auto request = tinyRequest(folder / "never.png");
  request.settings.points = 100'000'000'000;
  job.start(request);
  ASSERT_TRUE(waitForStage(job, "accumulating"));
  const pid_t pid = job.processId();
  const auto cancel0 = std::chrono::steady_clock::now();
  job.cancel();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - cancel0).count(), 0.05);
  const ExportStatus status = pollUntilEnded(job, nullptr, 10);
  EXPECT_EQ(status.state, ExportState::Cancelled);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - cancel0).count(), 3.0);
  EXPECT_FALSE(std::filesystem::exists(folder / "never.png"));
  EXPECT_TRUE(voxflame::test::filesStartingWith(folder.path(), "never.png").empty());  // no temporary either
  EXPECT_TRUE(reaped(pid));
  // The job can run again.
  job.start(tinyRequest(folder / "again.png"));
  EXPECT_EQ(pollUntilEnded(job).state, ExportState::Done);
}

TEST(ExportJob, UnwritableOutputGivesTheChildsMessage) {
  TemporaryFolder folder;
  ExportJob job;
  job.start(tinyRequest(folder / "no-such-folder" / "out.png"));
  const ExportStatus status = pollUntilEnded(job);
  ASSERT_EQ(status.state, ExportState::Failed);
  EXPECT_NE(status.error.find("no-such-folder"), std::string::npos) << status.error;
  EXPECT_FALSE(std::filesystem::exists(folder / "no-such-folder"));
}

TEST(ExportJob, MissingMeshGivesTheChildsMessage) {
  TemporaryFolder folder;
  ExportJob job;
  auto request = tinyRequest(folder / "out.png");
  request.scene.embedded = false;
  request.scene.meshPath = "gone/teapot.obj";
  request.scene.baseDirectory = folder.path();
  job.start(request);
  const ExportStatus status = pollUntilEnded(job);
  ASSERT_EQ(status.state, ExportState::Failed);
  EXPECT_NE(status.error.find("teapot.obj"), std::string::npos) << status.error;
  EXPECT_FALSE(std::filesystem::exists(folder / "out.png"));
}

TEST(ExportJob, DestructorWithRunningJobReturnsPromptlyAndReaps) {
  TemporaryFolder folder;
  pid_t pid = -1;
  const auto start = std::chrono::steady_clock::now();
  {
    ExportJob job;
    auto request = tinyRequest(folder / "never.png");
    request.settings.points = 100'000'000'000;
    job.start(request);
    pid = job.processId();
    ASSERT_GT(pid, 0);
    // Destroyed while the child is still starting up: it may not even handle SIGINT yet.
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
  EXPECT_TRUE(reaped(pid));
  // Destroyed while accumulating: the child stops at its next check.
  std::optional<ExportJob> job(std::in_place);
  auto request = tinyRequest(folder / "never.png");
  request.settings.points = 100'000'000'000;
  job->start(request);
  ASSERT_TRUE(waitForStage(*job, "accumulating"));
  pid = job->processId();
  const auto destroy0 = std::chrono::steady_clock::now();
  job.reset();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - destroy0).count(), 1.5);
  EXPECT_TRUE(reaped(pid));
  EXPECT_FALSE(std::filesystem::exists(folder / "never.png"));
}

TEST(ExportJob, RefusesBadRequests) {
  TemporaryFolder folder;
  ExportJob job;
  auto request = tinyRequest(folder / "out.exr");
  EXPECT_THROW(job.start(request), voxflame::core::Error);  // a PNG format with .exr
  request.output = voxflame::app::withExtensionFor(request.output, request.settings.format);
  EXPECT_EQ(request.output, folder / "out.png");
  request.settings.width = 0;
  EXPECT_THROW(job.start(request), voxflame::core::Error);
  request.settings.width = 32;
  request.executable = folder / "no-such-binary";
  EXPECT_THROW(job.start(request), voxflame::core::Error);
  EXPECT_FALSE(job.running());
  EXPECT_EQ(job.poll().state, ExportState::Idle);
  request.executable = VOXFLAME_BINARY;
  request.settings.points = 100'000'000'000;
  job.start(request);
  EXPECT_THROW(job.start(request), voxflame::core::Error);  // one at a time
  job.cancel();
  EXPECT_EQ(pollUntilEnded(job, nullptr, 10).state, ExportState::Cancelled);
}

TEST(ExportJob, RenderProgressFdWritesStagesInOrder) {
  TemporaryFolder folder;
  const auto result = voxflame::test::runVoxflame(
      "render -o p.png --width 32 --height 32 --points 50000 --samples 2 --progress-fd 3 3>progress.txt",
      folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  std::ifstream in(folder / "progress.txt");
  std::vector<std::string> stages;
  for (std::string word, stage; in >> word >> stage;) {
    double fraction = -1.0;
    in >> fraction;
    EXPECT_EQ(word, "progress");
    EXPECT_GE(fraction, 0.0);
    EXPECT_LE(fraction, 1.0);
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
  }
  EXPECT_EQ(stages, (std::vector<std::string>{"loading", "accumulating", "rendering", "writing"}));
  const auto bad = voxflame::test::runVoxflame("render -o q.png --progress-fd 77", folder.path());
  EXPECT_EQ(bad.exitStatus, 2);
  EXPECT_NE(bad.output.find("--progress-fd 77"), std::string::npos) << bad.output;
}

// The job waits on its child's pidfd, not on a timer nor on the pipes: a child that ends while a
// grandchild keeps the pipes open is noticed at once.
TEST(ExportJob, NoticesItsChildsExitWhileItsPipesStayOpen) {
  TemporaryFolder folder;
  const std::filesystem::path script = folder / "ends-early.sh";
  {
    std::ofstream out(script);
    // The background sleep inherits stdout, stderr and the progress descriptor (3).
    out << "#!/bin/sh\nsleep 3 &\nexit 3\n";
  }
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  ExportJob job;
  auto request = tinyRequest(folder / "out.png");
  request.executable = script;
  const auto start = std::chrono::steady_clock::now();
  job.start(request);
  int wakeUps = 0;
  ExportStatus status;
  while ((status = job.poll()).state == ExportState::Running && wakeUps < 100) {
    job.waitForChange(std::chrono::seconds(10));
    ++wakeUps;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(status.state, ExportState::Failed);
  EXPECT_NE(status.error.find("status 3"), std::string::npos) << status.error;
  EXPECT_LT(seconds, 2.0) << "the exit waited for the pipes to close";
  EXPECT_LE(wakeUps, 3);
}

// A real export followed by waiting alone (no sleeps between polls) ends with the child's result.
TEST(ExportJob, WaitingForChangesFollowsAnExportToItsEnd) {
  TemporaryFolder folder;
  ExportJob job;
  job.start(tinyRequest(folder / "out.png"));
  ExportStatus status;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while ((status = job.poll()).state == ExportState::Running && std::chrono::steady_clock::now() < deadline)
    job.waitForChange(std::chrono::seconds(10));
  EXPECT_EQ(status.state, ExportState::Done) << status.error;
  EXPECT_TRUE(std::filesystem::exists(folder / "out.png"));
  EXPECT_FALSE(job.waitForChange(std::chrono::seconds(10))) << "nothing to wait for once it has ended";
}
