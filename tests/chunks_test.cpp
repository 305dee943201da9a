// A still split into chunks (`render --chunks`, `--checkpoint`, `--chunk-range`, `--farm slurm`,
// `--status`): whatever the threads, the interruptions and the farm tasks, the image is the same
// file. The job scripts run under bash as Slurm array tasks would; scripts/test_farm.sh submits
// them to a real one-node cluster.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.h"

using voxflame::test::runShell;
using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

namespace {

// A shipped flame (points method) and a shipped attractor (volume method), small and quick.
const std::string kFlame = std::string(VOXFLAME_SOURCE_DIR) + "/presets/flame-silk-bunny.json";
const std::string kAttractor = std::string(VOXFLAME_SOURCE_DIR) + "/presets/aizawa-orb.json";
const std::string kJulia = std::string(VOXFLAME_SOURCE_DIR) + "/presets/qjulia-loop.json";

// The silk bunny with what the GPU's chaos game does not have (a weighting field that moves a
// parameter of crackle, whose GPU port reads numbers derived from its parameters), written into
// `folder`.
std::string flameTheGpuLacks(const std::filesystem::path& folder) {
  std::ifstream in(kFlame);
  std::stringstream text;
  text << in.rdbuf();
  std::string json = text.str();
  const std::string variations = "\"variations\": [";
  json.insert(json.find(variations) + variations.size(),
              "{\"name\": \"crackle\", \"weight\": 0.1, \"cellsize\": 1.0}, ");
  json.insert(json.find(variations),
              "\"field\": {\"kind\": \"noise\", \"param1_variation\": \"crackle\", "
              "\"param1_name\": \"cellsize\", \"param1_intensity\": 0.5}, ");
  // The mesh path is relative to the preset: the copy names the shipped one.
  const std::string mesh = "\"meshes/bunny.obj\"";
  json.replace(json.find(mesh), mesh.size(), "\"" + std::string(VOXFLAME_SOURCE_DIR) + "/presets/meshes/bunny.obj\"");
  const std::filesystem::path path = folder / "weighting_field.json";
  std::ofstream(path) << json;
  return path.string();
}
const std::string kQuick = " --grid 48 --points 600000";

const std::string kSize = " --width 64 --height 40";

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class Chunks : public ::testing::TestWithParam<const char*> {
 protected:
  bool points() const { return std::string(GetParam()) == "points"; }
  std::string preset() const { return (points() ? kFlame : kAttractor) + kQuick + " --method " + GetParam(); }
  std::string extension() const { return points() ? ".exr" : ".vdb"; }
  void render(const std::string& arguments) {
    const auto result = runVoxflame("render " + preset() + kSize + " " + arguments, folder.path());
    ASSERT_EQ(result.exitStatus, 0) << arguments << "\n" << result.output;
  }
  TemporaryFolder folder;
};

}  // namespace

TEST_P(Chunks, TheSameFileWhateverTheThreadsAndTheResumes) {
  ASSERT_NO_FATAL_FAILURE(render("-o whole.png --chunks 8 --threads 2"));
  ASSERT_NO_FATAL_FAILURE(render("-o single.png --chunks 8 --threads 1"));
  EXPECT_EQ(readBytes(folder / "whole.png"), readBytes(folder / "single.png")) << "threads changed the image";

  // Two ranges as two farm tasks would render them, then the finish.
  ASSERT_NO_FATAL_FAILURE(render("-o resumed.png --chunks 8 --checkpoint ck --chunk-range 5-7 --threads 1"));
  EXPECT_FALSE(std::filesystem::exists(folder / "resumed.png")) << "a chunk range makes no image";
  EXPECT_TRUE(std::filesystem::exists(folder / ("ck/chunk-0005" + extension())));
  EXPECT_FALSE(std::filesystem::exists(folder / ("ck/chunk-0004" + extension())));
  ASSERT_NO_FATAL_FAILURE(render("-o resumed.png --chunks 8 --checkpoint ck --chunk-range 0-1"));
  const auto finish =
      runVoxflame("render " + preset() + kSize + " -o resumed.png --chunks 8 --checkpoint ck", folder.path());
  ASSERT_EQ(finish.exitStatus, 0) << finish.output;
  EXPECT_TRUE(contains(finish.output, "holds 5 of the 8 chunks; rendering 3 more")) << finish.output;
  EXPECT_EQ(readBytes(folder / "whole.png"), readBytes(folder / "resumed.png")) << "resuming changed the image";

  // Every chunk there: the finish only sums them.
  ASSERT_NO_FATAL_FAILURE(render("-o again.png --chunks 8 --checkpoint ck"));
  EXPECT_EQ(readBytes(folder / "whole.png"), readBytes(folder / "again.png"));

  // Another K is another image (its chunks have other seeds) of the same look.
  ASSERT_NO_FATAL_FAILURE(render("-o other.png --chunks 5"));
  EXPECT_NE(readBytes(folder / "whole.png"), readBytes(folder / "other.png"));
}

TEST_P(Chunks, ACheckpointOfAnotherRenderIsRefusedNamingWhatDiffers) {
  ASSERT_NO_FATAL_FAILURE(render("-o a.png --chunks 4 --checkpoint ck --chunk-range 0"));
  const struct {
    std::string arguments, expected;
  } cases[] = {
      {"--chunks 4 --width 80", "it was rendered at 64×40, this render is 80×40"},
      {"--chunks 6", "it is one of 4 chunks, this render has 6 (--chunks)"},
      {"--chunks 4 --points 700000", "another preset (differing in /points)"},
      {"--chunks 4 --method " + std::string(points() ? "volume" : "points"), "method"},
      {"--chunks 4 --camera-azimuth 40", "/camera/azimuth_deg"},
  };
  for (const auto& c : cases) {
    const auto result =
        runVoxflame("render " + preset() + kSize + " -o a.png --checkpoint ck " + c.arguments, folder.path());
    EXPECT_EQ(result.exitStatus, 1) << c.arguments << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, "belongs to another render")) << result.output;
    EXPECT_TRUE(contains(result.output, c.expected)) << c.arguments << "\n" << result.output;
    EXPECT_FALSE(std::filesystem::exists(folder / "a.png"));
  }
}

TEST_P(Chunks, AStillOnTheFarmIsTheLocalStill) {
  const auto written =
      runVoxflame("render " + preset() + kSize + " -o farm.png --chunks 6 --farm slurm --tasks 3", folder.path());
  ASSERT_EQ(written.exitStatus, 0) << written.output;
  EXPECT_TRUE(contains(written.output, "3 tasks: chunks 0-1, 2-3, 4-5")) << written.output;
  const auto scripts = folder / "farm.png.chunks";
  ASSERT_TRUE(std::filesystem::exists(scripts / "farm-render.sbatch"));
  ASSERT_TRUE(std::filesystem::exists(scripts / "farm-finish.sbatch"));
  auto status = runVoxflame("render --status farm.png", folder.path());
  EXPECT_EQ(status.exitStatus, 1);
  EXPECT_TRUE(contains(status.output, "missing 6: 0-5")) << status.output;
  EXPECT_TRUE(contains(status.output, "sbatch --array=0-2 farm.png.chunks/farm-render.sbatch")) << status.output;

  // The finish job refuses to make an image while a chunk is missing.
  auto finish = runShell("bash farm.png.chunks/farm-finish.sbatch", folder.path());
  EXPECT_NE(finish.exitStatus, 0) << finish.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "farm.png"));

  for (int task = 0; task < 3; ++task) {
    const auto ran = runShell(
        "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash farm.png.chunks/farm-render.sbatch", folder.path());
    ASSERT_EQ(ran.exitStatus, 0) << ran.output;
  }
  status = runVoxflame("render --status farm.png", folder.path());
  EXPECT_EQ(status.exitStatus, 0) << status.output;
  EXPECT_TRUE(contains(status.output, "all 6 chunks are in")) << status.output;
  finish = runShell("bash farm.png.chunks/farm-finish.sbatch", folder.path());
  ASSERT_EQ(finish.exitStatus, 0) << finish.output;
  ASSERT_NO_FATAL_FAILURE(render("-o local.png --chunks 6"));
  EXPECT_EQ(readBytes(folder / "farm.png"), readBytes(folder / "local.png"));

  // A lost chunk: --status names it and the one task to run again.
  std::filesystem::remove(scripts / ("chunk-0003" + extension()));
  status = runVoxflame("render --status farm.png", folder.path());
  EXPECT_EQ(status.exitStatus, 1);
  EXPECT_TRUE(contains(status.output, "5 of 6 chunks are in")) << status.output;
  EXPECT_TRUE(contains(status.output, "missing 1: 3")) << status.output;
  EXPECT_TRUE(contains(status.output, "sbatch --array=1 farm.png.chunks/farm-render.sbatch")) << status.output;
  ASSERT_EQ(runShell("SLURM_ARRAY_TASK_ID=1 bash farm.png.chunks/farm-render.sbatch", folder.path()).exitStatus, 0);
  ASSERT_EQ(runShell("bash farm.png.chunks/farm-finish.sbatch", folder.path()).exitStatus, 0);
  EXPECT_EQ(readBytes(folder / "farm.png"), readBytes(folder / "local.png"));
}

INSTANTIATE_TEST_SUITE_P(BothMethods, Chunks, ::testing::Values("points", "volume"),
                         [](const ::testing::TestParamInfo<const char*>& parameter) {
                           return std::string(parameter.param);
                         });

TEST(ChunkOptions, MisusesGiveMessages) {
  TemporaryFolder folder;
  const struct {
    std::string arguments, expected;
  } cases[] = {
      {"-o a.png --chunk-range 0-3", "--chunk-range renders chunks into a checkpoint folder"},
      {"-o a.png --checkpoint ck --chunk-range 3-1", "the first chunk comes after the last"},
      {"-o a.png --checkpoint ck --chunks 4 --chunk-range 2-9", "the render has 4 chunks (0-3)"},
      {"-o a.png --checkpoint ck --chunk-range x", "--chunk-range expects A-B or N"},
      {"-o a.png --until-noise 1 --chunks 8", "--until-noise stops when the grid is smooth enough"},
      {"-o a.vdb --checkpoint ck", "--checkpoint and --farm make an image"},
      {"-o a.png --tasks 3", "--tasks, --partition and --submit go with --farm slurm"},
      {"-o a.png --farm slurm --partition 'a b'", "is not a Slurm partition name"},
      {"--status a.png", "--status needs to know how many chunks to expect"},
      {"--status a.png -o b.png", "--status takes the image itself"},
      {"-o a.png --flat --chunks 4", "render --flat is not split into chunks"},
      {"-o a.png --chunks 0", "--chunks"},
  };
  for (const auto& c : cases) {
    const auto result = runVoxflame("render " + c.arguments, folder.path());
    EXPECT_NE(result.exitStatus, 0) << c.arguments;
    EXPECT_TRUE(contains(result.output, c.expected)) << c.arguments << "\n" << result.output;
  }
}

// The points method on the GPU backend projects its points there (gpu_backend_test.cpp holds its
// picture to the CPU's), in chunks as on the CPU.
TEST(ChunkBackends, ThePointsMethodRendersOnTheGpuBackendInChunks) {
  TemporaryFolder folder;
  const auto result = runVoxflame(
      "render " + kAttractor + kQuick + kSize + " -o p.png --backend gpu --method points --chunks 2", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "points method")) << result.output;
  EXPECT_TRUE(contains(result.output, "on the gpu backend")) << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "p.png"));
}

// A render's chunks come from one refinement backend: a checkpoint the GPU began is refused by a
// render on the CPU, naming the backends, and the GPU's own chunks resume into the same image.
TEST(ChunkBackends, ChunksOfAnotherBackendAreRefusedAndTheirOwnResume) {
  TemporaryFolder folder;
  const std::string render =
      "render " + kAttractor + kQuick + kSize + " --method volume -o a.png --chunks 4 --checkpoint ck ";
  auto result = runVoxflame(render + "--backend gpu --chunk-range 0-1", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  result = runVoxflame(render + "--backend cpu", folder.path());
  EXPECT_EQ(result.exitStatus, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "it was refined by the gpu backend, this render uses the cpu backend"))
      << result.output;
  result = runVoxflame(render + "--backend gpu", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "on the gpu backend")) << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder / "a.png"));
}

TEST(ChunkBackends, TheGpuBackendRefusesWhatItDoesNotRunWithAMessage) {
  TemporaryFolder folder;
  const std::string lacking = flameTheGpuLacks(folder.path());
  auto result =
      runVoxflame("render " + lacking + kQuick + kSize + " -o f.png --method volume --backend gpu", folder.path());
  EXPECT_EQ(result.exitStatus, 1) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "a flame layer needs the CPU backend: the GPU backend does not have a weighting field "
                       "on crackle's parameters"))
      << result.output;
  // auto falls back to the CPU, whatever the machine.
  result =
      runVoxflame("render " + lacking + kQuick + kSize + " -o f.png --method volume --backend auto", folder.path());
  EXPECT_EQ(result.exitStatus, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "on the cpu backend")) << result.output;
  // A flame of the GPU's variations, and a quaternion Julia set, run there (the volume method).
  for (const std::string& preset : {kFlame, kJulia}) {
    result =
        runVoxflame("render " + preset + kQuick + kSize + " -o g.png --method volume --backend gpu", folder.path());
    EXPECT_EQ(result.exitStatus, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "on the gpu backend")) << result.output;
  }
  result = runVoxflame("render " + kAttractor + kQuick + kSize + " -o x.png --backend metal", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_TRUE(contains(result.output, "--backend")) << result.output;
}
