// `voxflame animate --farm slurm` and `--status`, without a Slurm cluster: the job scripts are
// read as text, run by bash as an array task would be, and submitted to a stand-in sbatch.
// scripts/test_farm.sh runs the same on a real one-node cluster.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "farm_job.h"
#include "frame_pattern.h"
#include "test_support.h"

using voxflame::app::FrameRange;
using voxflame::test::runShell;
using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

namespace {

const std::string& kSize = voxflame::test::kTinyFrameSize;

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class Farm : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(folder / "tiny.json") << voxflame::test::tinyAnimationPreset(200'000); }
  TemporaryFolder folder;
};

}  // namespace

TEST(FarmSplit, RangesAreEvenContiguousAndCoverEveryFrame) {
  for (int first : {0, 5})
    for (int count = 1; count <= 40; ++count)
      for (int tasks = 1; tasks <= 12; ++tasks) {
        const FrameRange frames{first, first + count - 1};
        const auto ranges = voxflame::app::splitFrames(frames, tasks);
        ASSERT_EQ(static_cast<int>(ranges.size()), std::min(tasks, count));
        int next = first;
        int smallest = count;
        int largest = 0;
        for (const FrameRange& range : ranges) {
          EXPECT_EQ(range.first, next) << count << " frames in " << tasks << " tasks";
          EXPECT_GE(range.last, range.first);
          smallest = std::min(smallest, range.count());
          largest = std::max(largest, range.count());
          next = range.last + 1;
        }
        EXPECT_EQ(next, frames.last + 1);
        EXPECT_LE(largest - smallest, 1) << count << " frames in " << tasks << " tasks";
      }
  const auto ranges = voxflame::app::splitFrames({0, 20}, 4);
  ASSERT_EQ(ranges.size(), 4u);
  EXPECT_EQ(ranges[0].last, 5);  // 6 + 5 + 5 + 5
  EXPECT_EQ(ranges[1].first, 6);
  EXPECT_EQ(ranges[3].last, 20);
}

TEST(FarmSplit, FramesAreDescribedAsRanges) {
  EXPECT_EQ(voxflame::app::describeFrames({7, 2, 3, 3, 9, 10, 11}), "2-3, 7, 9-11");
  EXPECT_EQ(voxflame::app::describeFrames({4}), "4");
}

TEST_F(Farm, WritesAnArrayJobAndAFinishJob) {
  const auto result = runVoxflame(
      "animate tiny.json -o 'frames/%04d.png' --farm slurm --tasks 4 --partition render "
      "--video out.mp4 --fps 10 --points 100000" +
          kSize,
      folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "4 tasks: frames 0-5, 6-10, 11-15, 16-20")) << result.output;
  EXPECT_TRUE(contains(result.output, "sbatch --dependency=afterany:")) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "frames/0000.png")) << "--farm renders nothing itself";

  const auto render = folder / "frames/farm-render.sbatch";
  const auto finish = folder / "frames/farm-finish.sbatch";
  ASSERT_TRUE(std::filesystem::exists(render));
  ASSERT_TRUE(std::filesystem::exists(finish));
  EXPECT_NE(std::filesystem::status(render).permissions() & std::filesystem::perms::owner_exec,
            std::filesystem::perms::none);
  const std::string script = readText(render);
  EXPECT_EQ(script.rfind("#!/bin/bash\n", 0), 0u);
  EXPECT_TRUE(contains(script, "\n#SBATCH --array=0-3\n")) << script;
  EXPECT_TRUE(contains(script, "\n#SBATCH --partition=render\n")) << script;
  EXPECT_TRUE(contains(script, "\n#SBATCH --chdir=" + std::filesystem::canonical(folder.path()).string() + "\n"))
      << script;
  EXPECT_TRUE(contains(script, "\n#SBATCH --output=frames/farm-render-%A_%a.log\n")) << script;
  EXPECT_TRUE(contains(script, "\n# voxflame-farm frames=0-20 tasks=4\n")) << script;
  EXPECT_TRUE(contains(script, "\nranges=(0-5 6-10 11-15 16-20)\n")) << script;
  EXPECT_TRUE(contains(script, "exec " + std::string(VOXFLAME_BINARY) +
                                   " animate tiny.json -o frames/%04d.png --width 48 --height 32 --fps 10 --points "
                                   "100000 --frames \"${ranges[$task]}\"\n"))
      << script;
  // Every #SBATCH line comes before the first command, or sbatch ignores it.
  EXPECT_LT(script.rfind("#SBATCH"), script.find("\nset -euo pipefail"));

  const std::string after = readText(finish);
  EXPECT_TRUE(contains(after, "\n#SBATCH --partition=render\n")) << after;
  EXPECT_TRUE(contains(after, "animate tiny.json --status frames/%04d.png --frames 0-20 --fps 10\n")) << after;
  EXPECT_TRUE(contains(after, "-c:v libx264")) << after;
  EXPECT_TRUE(contains(after, " out.mp4\n")) << after;
}

TEST_F(Farm, TasksOfTheArrayJobRenderTheFramesOfOneLocalRun) {
  ASSERT_EQ(
      runVoxflame("animate tiny.json -o 'farm/%02d.png' --farm slurm --tasks 3 --frames 0-5" + kSize, folder.path())
          .exitStatus,
      0);
  // Tasks run alone, in any order, as Slurm would start them: task 2 renders frames 4-5.
  for (int task : {2, 0, 1}) {
    const auto result =
        runShell("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash farm/farm-render.sbatch", folder.path());
    ASSERT_EQ(result.exitStatus, 0) << result.output;
  }
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'local/%02d.png' --frames 0-5" + kSize, folder.path()).exitStatus, 0);
  for (int frame = 0; frame <= 5; ++frame) {
    const std::string name = "0" + std::to_string(frame) + ".png";
    ASSERT_TRUE(std::filesystem::exists(folder / "farm" / name)) << name;
    EXPECT_EQ(readBytes(folder / "farm" / name), readBytes(folder / "local" / name)) << "frame " << frame;
  }
  const auto status = runVoxflame("animate --status 'farm/%02d.png'", folder.path());
  EXPECT_EQ(status.exitStatus, 0) << status.output;
  EXPECT_TRUE(contains(status.output, "all 6 frames (0-5) are there")) << status.output;
  // The finish job's check passes; without --video it encodes nothing.
  const auto finish = runShell("bash farm/farm-finish.sbatch", folder.path());
  EXPECT_EQ(finish.exitStatus, 0) << finish.output;
}

TEST_F(Farm, StatusListsMissingFramesAndTheTasksToRunAgain) {
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'f/%03d.png' --farm slurm --tasks 4 --frames 0-7" + kSize, folder.path())
                .exitStatus,
            0);
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'f/%03d.png' --frames 0-2" + kSize, folder.path()).exitStatus, 0);
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'f/%03d.png' --frames 6-7" + kSize, folder.path()).exitStatus, 0);
  // A file that is not a PNG (a task killed while its disk filled, a stray file) is not a frame.
  std::ofstream(folder / "f/005.png") << "not a png";

  auto result = runVoxflame("animate --status 'f/%03d.png'", folder.path());
  EXPECT_EQ(result.exitStatus, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "f/%03d.png: 5 of 8 frames (0-7) are there; missing 3: 3-5")) << result.output;
  EXPECT_TRUE(contains(result.output, "render them again with: sbatch --array=1-2 f/farm-render.sbatch"))
      << result.output;

  // With the preset, the whole animation is expected (21 frames at 10 fps).
  result = runVoxflame("animate tiny.json --status 'f/%03d.png'", folder.path());
  EXPECT_EQ(result.exitStatus, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "5 of 21 frames (0-20) are there; missing 16: 3-5, 8-20")) << result.output;

  result = runVoxflame("animate --status 'f/%03d.png' --frames 6-7", folder.path());
  EXPECT_EQ(result.exitStatus, 0) << result.output;

  // Without a preset, --frames or a job script, it cannot know which frames to expect.
  result = runVoxflame("animate --status 'g/%03d.png'", folder.path());
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "--status needs to know which frames to expect")) << result.output;
}

TEST_F(Farm, SubmitRunsSbatchTwiceWithADependency) {
  std::filesystem::create_directories(folder / "bin");
  // A stand-in sbatch: records its arguments and answers like `sbatch --parsable`.
  const auto fake = folder / "bin" / "sbatch";
  std::ofstream(fake) << "#!/bin/sh\necho \"$*\" >> \"" << (folder / "sbatch-calls.txt").string()
                      << "\"\nn=$(wc -l < \"" << (folder / "sbatch-calls.txt").string()
                      << "\")\necho \"$((4100 + n));cluster\"\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const auto result = runVoxflame("animate tiny.json -o 'f/%04d.png' --farm slurm --tasks 2 --submit" + kSize,
                                  folder.path(), "env PATH=" + (folder / "bin").string() + ":/usr/bin:/bin");
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "submitted job 4101 (2 tasks) and job 4102 (after every task of 4101"))
      << result.output;
  std::istringstream calls(readText(folder / "sbatch-calls.txt"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(calls, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "--parsable f/farm-render.sbatch");
  EXPECT_EQ(lines[1], "--parsable --dependency=afterany:4101 f/farm-finish.sbatch");
}

TEST_F(Farm, SbatchFailingIsAnError) {
  std::filesystem::create_directories(folder / "bin");
  const auto fake = folder / "bin" / "sbatch";
  std::ofstream(fake) << "#!/bin/sh\necho 'sbatch: error: invalid partition specified: nope' >&2\nexit 1\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const auto result = runVoxflame("animate tiny.json -o 'f/%04d.png' --farm slurm --partition nope --submit" + kSize,
                                  folder.path(), "env PATH=" + (folder / "bin").string() + ":/usr/bin:/bin");
  EXPECT_EQ(result.exitStatus, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "invalid partition specified")) << result.output;
  EXPECT_TRUE(contains(result.output, "voxflame: sbatch failed (exit status 1)")) << result.output;
}

TEST_F(Farm, BadFlagsGiveMessages) {
  std::filesystem::create_directories(folder / "empty-bin");
  const auto run = [&](const std::string& arguments, const std::string& environment = "") {
    return runVoxflame("animate tiny.json " + arguments, folder.path(), environment);
  };
  auto result = run("-o 'f/%04d.png' --farm slurm --tasks 0");
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "--tasks: Value 0 not in range 1 to")) << result.output;
  result = run("-o 'f/%04d.png' --farm pbs");
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "--farm: pbs not in {slurm}")) << result.output;
  result = run("-o 'f/%04d.png' --tasks 4");
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "--tasks, --partition and --submit go with --farm slurm")) << result.output;
  result = run("-o 'f/%04d.png' --farm slurm --partition 'a b'");
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "is not a Slurm partition name")) << result.output;
  result = run("-o 'f/%04d.png' --status 'f/%04d.png'");
  EXPECT_EQ(result.exitStatus, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "leave out -o")) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "f"));

  result = run("-o 'f/%04d.png' --farm slurm --submit", "env PATH=" + (folder / "empty-bin").string());
  EXPECT_EQ(result.exitStatus, 3) << result.output;
  EXPECT_TRUE(contains(result.output, "sbatch is not installed (not found on PATH), so nothing was submitted"))
      << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "f/farm-render.sbatch")) << "the scripts are still written";
}

TEST_F(Farm, VolumeFramesSplitAcrossTasksAreTheFilesOfOneLocalRun) {
  // `-o frames/%02d.nrrd` on the farm: each task writes its frames' volumes, the same files a
  // local run writes (the locked fit and the preset's seed), and --status and the finish job know
  // the frames by their kind.
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'vfarm/%02d.nrrd' --farm slurm --tasks 2 --frames 0-3", folder.path())
                .exitStatus,
            0);
  for (int task : {1, 0}) {
    const auto result =
        runShell("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash vfarm/farm-render.sbatch", folder.path());
    ASSERT_EQ(result.exitStatus, 0) << result.output;
  }
  ASSERT_EQ(runVoxflame("animate tiny.json -o 'vlocal/%02d.nrrd' --frames 0-3", folder.path()).exitStatus, 0);
  for (int frame = 0; frame <= 3; ++frame) {
    const std::string name = "0" + std::to_string(frame) + ".nrrd";
    ASSERT_TRUE(std::filesystem::exists(folder / "vfarm" / name)) << name;
    EXPECT_EQ(readBytes(folder / "vfarm" / name), readBytes(folder / "vlocal" / name)) << "frame " << frame;
  }
  const auto status = runVoxflame("animate --status 'vfarm/%02d.nrrd'", folder.path());
  EXPECT_TRUE(contains(status.output, "all 4 frames (0-3) are there")) << status.output;
  EXPECT_EQ(runShell("bash vfarm/farm-finish.sbatch", folder.path()).exitStatus, 0);
}
