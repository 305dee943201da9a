// The option table of the command line (cli/cli.cpp): every flag the hand-written parser took is
// still taken, ranges and choices are checked, negative numbers are values, and every subcommand
// has a generated --help. Parsing runs in-process (cli::usageErrorOf); --help runs the binary.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "test_support.h"

using voxflame::test::runVoxflame;

namespace {

// "render -o x.png" as argv: program name first, split at spaces (the table needs no quoting).
std::vector<std::string> argv(const std::string& line) {
  std::vector<std::string> args = {"voxflame"};
  std::istringstream words(line);
  for (std::string word; words >> word;) args.push_back(word);
  return args;
}

std::string usageErrorOf(const std::string& line) {
  return voxflame::cli::usageErrorOf(argv(line));
}

// Every flag of the usage text the hand-written parser printed (and the README's), each with a
// value it accepted: all must still parse. Only parsing: nothing is rendered or read.
const char* const kOldUsage[] = {
    "",
    "preset.json",
    "preset.json --screenshot shot.png --frames 5",
    "--ui-scale 1.5",
    "--width 800 --height 600",
    "render preset.json -o out.png",
    "render --output out.exr",
    "render -o out.png --width 64",
    "render -o out.png --height 48",
    "render -o out.png --samples 4",
    "render -o out.png --points 100000",
    "render -o out.png --grid 128",
    "render -o out.png --bit-depth 16",
    "render -o out.png --bit-depth 8",
    "render -o out.png --time 1.5",
    "render -o out.png --camera-azimuth 45",
    "render -o out.png --camera-elevation 10",
    "render -o out.png --threads 2",
    "render -o out.png --progress-fd 1",
    "render -o out.png --method volume",
    "render -o out.png --method points",
    "render -o out.png --oversample 4",
    "render -o out.png --stats",
    "animate preset.json -o frames/%04d.png",
    "animate --output frames/%04d.png --frames 2-5",
    "animate -o f/%04d.png --width 64 --height 48",
    "animate -o f/%04d.png --fps 12.5",
    "animate -o f/%04d.png --motion-blur 4 --shutter 0.25",
    "animate -o f/%04d.png --video out.mp4",
    "animate -o f/%04d.png --samples 2 --points 1000 --grid 64 --threads 3",
    "animate -o f/%04d.png --farm slurm --tasks 4 --partition gpu --submit",
    "animate preset.json --status f/%04d.png --frames 0-9 --fps 24",
    "list",
    "list --json",
    "list --variations",
    "list --variations --json",
    "list --variations --markdown",
    "info preset.json",
    "info --attractor lorenz --set classic --param a=1 --param b=2 --integrator rk4 --step 0.01 --json",
    "info --attractor lorenz --integrator euler",
    "search preset.json",
    "search --attractor lorenz --seed 7 --count 3 --strength 0.2 --set classic --param a=1 --json",
    "search flame.json --random -o best.json",
    "search flame.json --output best.json",
    "mask mesh.obj -o out.nrrd --grid 64 --stats",
    "mask mesh.obj --output out.nrrd --method winding-number",
    "mask mesh.obj -o out.nrrd --method exact-winding-number",
    "mask mesh.obj -o out.nrrd --method parity",
    "import f.flame -o p.json --mesh m.obj --depth 0.25 --index 2",
    "import f.flame --output p.json --name Dragon",
    "bench",
    "bench accumulate",
    "bench mask",
    "bench raymarch",
    "bench explorer",
    "bench export --method points",
    "bench quality --method volume --json",
    "bench flame",
    "--help",
    "-h",
    "--version",
    "help",
    "help render",
    "render --help",
};

TEST(CliOptions, EveryFlagOfTheOldUsageIsStillAccepted) {
  for (const char* line : kOldUsage) EXPECT_EQ(usageErrorOf(line), "") << "voxflame " << line;
}

TEST(CliOptions, RepeatedParamsAreAllKeptAndAPresetMayFollowThem) {
  // --param takes one value each time: a positional after it is still the preset.
  EXPECT_EQ(usageErrorOf("info --param a=1 --param b=2 preset.json"), "");
  EXPECT_EQ(usageErrorOf("info --param a=1 b=2 preset.json"), "unexpected argument 'preset.json'");
}

// What a parent process passes its mesh import child (core/mesh.h): after "--", the file and the
// name are positional whatever they look like.
TEST(CliOptions, TheHiddenMeshImportChildTakesAnyFileAndName) {
  EXPECT_EQ(usageErrorOf("__import-mesh -- -x.obj render"), "");
  EXPECT_EQ(usageErrorOf("__import-mesh -- mesh.obj --width"), "");
  EXPECT_EQ(voxflame::cli::usageErrorOf({"voxflame", "__import-mesh", "--", "mesh.obj", ""}), "");
  EXPECT_NE(usageErrorOf("__import-mesh -- mesh.obj"), "");
}

TEST(CliOptions, NegativeNumbersAreValues) {
  EXPECT_EQ(usageErrorOf("render -o out.png --camera-azimuth -30"), "");
  EXPECT_EQ(usageErrorOf("render -o out.png --camera-elevation -89.5"), "");
  // Parsed as numbers, then refused by their range (not taken for unknown options).
  EXPECT_NE(usageErrorOf("render -o out.png --camera-azimuth -3601").find("--camera-azimuth"), std::string::npos);
  EXPECT_NE(usageErrorOf("render -o out.png --time -1").find("--time"), std::string::npos);
  EXPECT_NE(usageErrorOf("search --attractor lorenz --seed -1").find("--seed"), std::string::npos);
}

TEST(CliOptions, RangesAndChoicesNameTheOption) {
  const struct {
    const char* line;
    const char* message;
  } kRefused[] = {
      {"render -o out.png --grid 4096", "--grid: Value 4096 not in range 16 to 1024"},
      {"render -o out.png --samples 0", "--samples"},
      {"render -o out.png --width banana", "--width: 'banana' is not a whole number"},
      {"render -o out.png --width 1.5", "--width: '1.5' is not a whole number"},
      {"render -o out.png --camera-elevation nan", "--camera-elevation: 'nan' is not a number"},
      {"render -o out.png --bit-depth 12", "--bit-depth"},
      {"render -o out.png --method splat", "--method: splat not in {volume,points}"},
      {"render -o out.png --oversample 5", "--oversample"},
      {"render -o out.png --progress-fd -2", "--progress-fd"},
      {"--ui-scale 8", "--ui-scale"},
      {"--width 100", "--width"},
      {"animate -o f/%04d.png --shutter 2", "--shutter"},
      {"animate -o f/%04d.png --farm pbs", "--farm: pbs not in {slurm}"},
      {"animate -o f/%04d.png --farm slurm --tasks 0", "--tasks"},
      {"info --attractor lorenz --integrator leapfrog", "--integrator: leapfrog not in {euler,rk4}"},
      {"info --attractor lorenz --step inf", "--step: 'inf' is not a finite number"},
      {"search --attractor lorenz --count 0", "--count"},
      {"search --attractor lorenz --strength 11", "--strength"},
      {"mask m.obj -o m.nrrd --grid 16", "--grid"},
      {"mask m.obj -o m.nrrd --method flood", "--method"},
      {"import f.flame -o p.json --depth 20", "--depth"},
      {"import f.flame -o p.json --index 0", "--index"},
      {"bench nope", "nope not in {accumulate,"},
      {"bench --method splat", "--method"},
      {"render -o", "--output"},
  };
  for (const auto& refused : kRefused)
    EXPECT_NE(usageErrorOf(refused.line).find(refused.message), std::string::npos)
        << "voxflame " << refused.line << "\ngave: " << usageErrorOf(refused.line);
}

TEST(CliOptions, UnknownOptionsAndExtraArgumentsAreNamed) {
  EXPECT_EQ(usageErrorOf("render -o out.png --frobnicate 3"), "unknown option --frobnicate");
  EXPECT_EQ(usageErrorOf("render -o out.png --frobnicate=3"), "unknown option --frobnicate");
  EXPECT_EQ(usageErrorOf("list --frobnicate"), "unknown option --frobnicate");
  EXPECT_EQ(usageErrorOf("--frobnicate"), "unknown option --frobnicate");
  EXPECT_EQ(usageErrorOf("render a.json b.json"), "unexpected argument 'b.json'");
  EXPECT_EQ(usageErrorOf("a.json b.json"), "unexpected argument 'b.json'");
  EXPECT_EQ(usageErrorOf("list extra"), "unexpected argument 'extra'");
  // The explorer's options and file go without a subcommand.
  EXPECT_NE(usageErrorOf("--width 800 render -o out.png").find("--width goes with the explorer"), std::string::npos);
  EXPECT_NE(usageErrorOf("preset.json render -o out.png").find("'preset.json' goes with the explorer"),
            std::string::npos);
}

TEST(CliOptions, UsageErrorsExitTwoWithAPointerToHelp) {
  auto result = runVoxflame("render -o out.png --grid 4096");
  EXPECT_EQ(result.exitStatus, 2);
  EXPECT_NE(result.output.find("voxflame: --grid"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("voxflame render --help"), std::string::npos) << result.output;
  // A usage error the command finds itself (here: no output) goes the same way.
  result = runVoxflame("mask");
  EXPECT_EQ(result.exitStatus, 2);
  EXPECT_NE(result.output.find("voxflame mask --help"), std::string::npos) << result.output;
  result = runVoxflame("--frobnicate");
  EXPECT_EQ(result.exitStatus, 2);
  EXPECT_NE(result.output.find("unknown option --frobnicate"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("voxflame --help"), std::string::npos) << result.output;
}

TEST(CliOptions, EverySubcommandHasAGeneratedHelpListingItsOptions) {
  const struct {
    const char* subcommand;
    std::vector<std::string> options;
  } kHelp[] = {
      {"render",
       {"-o,--output", "--width", "--samples", "--camera-azimuth", "--progress-fd", "--oversample", "--stats"}},
      {"animate", {"--status", "--frames", "--motion-blur", "--video", "--farm", "--tasks", "--partition", "--submit"}},
      {"list", {"--json", "--variations", "--markdown"}},
      {"info", {"--attractor", "--set", "--param", "--integrator", "--step", "--json"}},
      {"search", {"--seed", "--count", "--strength", "--random", "-o,--output", "--param"}},
      {"mask", {"-o,--output", "--grid", "--stats", "exact-winding-number"}},
      {"import", {"-o,--output", "--mesh", "--depth", "--index", "--name"}},
      {"bench", {"--method", "--json", "accumulate", "flame"}},
  };
  for (const auto& help : kHelp) {
    const auto result = runVoxflame(std::string(help.subcommand) + " --help");
    EXPECT_EQ(result.exitStatus, 0) << result.output;
    EXPECT_NE(result.output.find(std::string("Usage: voxflame ") + help.subcommand), std::string::npos)
        << result.output;
    for (const std::string& option : help.options)
      EXPECT_NE(result.output.find(option), std::string::npos) << help.subcommand << ": " << option;
    // `voxflame help SUB` prints the same.
    EXPECT_EQ(runVoxflame(std::string("help ") + help.subcommand).output, result.output);
  }
  const auto top = runVoxflame("--help");
  EXPECT_EQ(top.exitStatus, 0);
  for (const char* part : {"--screenshot", "--ui-scale", "render", "animate", "bench", "import"})
    EXPECT_NE(top.output.find(part), std::string::npos) << part << "\n" << top.output;
  // `help` and the mesh import child are hidden: they work, but --help does not list them.
  EXPECT_EQ(top.output.find("\n  help "), std::string::npos) << top.output;
  EXPECT_EQ(top.output.find("import-mesh"), std::string::npos) << top.output;
  EXPECT_EQ(runVoxflame("help").output, top.output);
  const auto version = runVoxflame("--version");
  EXPECT_EQ(version.exitStatus, 0);
  EXPECT_EQ(version.output.rfind("voxflame ", 0), 0u) << version.output;
}

}  // namespace
