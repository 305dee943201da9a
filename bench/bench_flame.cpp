// `voxflame bench flame`: voxflame's chaos game against flam3-render (Debian's flam3-utils) on the
// same genome: the first flame of flam3's own sample file (four transforms, spherical each), on
// two threads. Both rates are iterations (samples) per second, side by side in one run.
//
// flam3-render's time includes fixed costs (start-up, density estimation, filtering, writing the
// PNG), so it runs twice, at two qualities, and its rate is the difference in samples over the
// difference in time: the marginal rate of its chaos game alone. Its sample count is quality ×
// width × height, the number flam3 draws for one batch (rect.c), gutter excluded, which if anything
// overstates its time per sample by the gutter's share (a few percent at 640×480).
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench.h"
#include "core/accumulator.h"
#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/scene.h"
#include "programs.h"

namespace voxflame::bench {

namespace {

// flam3's test.flam3, first flame: weight, colour and coefs "a d b e c f" per transform.
struct SampleXform {
  double weight, color, a, d, b, e, c, f;
};
constexpr SampleXform kSample[] = {
    {0.25, 1.0, -0.681206, -0.0779465, 0.20769, 0.755065, -0.0416126, -0.262334},
    {0.25, 0.66, 0.953766, 0.48396, 0.43268, -0.0542476, 0.642503, -0.995898},
    {0.25, 0.33, 0.840613, -0.816191, 0.318971, -0.430402, 0.905589, 0.909402},
    {0.25, 0.0, 0.960492, -0.466555, 0.215383, -0.727377, -0.126074, 0.253509},
};

core::PatternLayer sampleLayer() {
  core::PatternLayer layer;
  layer.kind = core::PatternKind::Flame;
  layer.attractor.clear();
  layer.color.mode = core::ColorMode::Index;
  layer.color.gradient = {{0.0f, {0.1f, 0.2f, 1.0f}}, {1.0f, {1.0f, 0.6f, 0.1f}}};
  for (const SampleXform& s : kSample) {
    core::FlameXform x;
    x.weight = s.weight;
    x.color = s.color;
    // Row-major 3×4: x' = a x + b y + c, y' = d x + e y + f, z carried through.
    x.affine.m = {s.a, s.b, 0.0, s.c, s.d, s.e, 0.0, s.f, 0.0, 0.0, 1.0, 0.0};
    x.variations = {{"spherical", 1.0, {}}};
    layer.flame.xforms.push_back(x);
  }
  return layer;
}

std::string sampleXml(int quality) {
  std::ostringstream xml;
  xml << "<flame palette=\"15\" size=\"640 480\" center=\"0 0\" scale=\"240\" oversample=\"1\" filter=\"1\" quality=\""
      << quality << "\" background=\"0 0 0\" brightness=\"4\" gamma=\"4\" vibrancy=\"1\">\n";
  for (const SampleXform& s : kSample)
    xml << "  <xform weight=\"" << s.weight << "\" color=\"" << s.color << "\" spherical=\"1\" coefs=\"" << s.a << " "
        << s.d << " " << s.b << " " << s.e << " " << s.c << " " << s.f << "\"/>\n";
  xml << "</flame>\n";
  return xml.str();
}

struct Timing {
  double wall = -1.0;  // negative when flam3-render could not run
  double cpu = 0.0;
};

// Wall-clock and CPU seconds of one flam3-render run.
Timing timeFlam3(const std::filesystem::path& folder, int quality) {
  const std::filesystem::path genome = folder / ("genome-" + std::to_string(quality) + ".flam3");
  std::ofstream(genome) << sampleXml(quality);
  // flam3-render reads its arguments from the environment; env sets them without a shell.
  const std::vector<std::string> command = {
      "env",       "in=" + genome.string(), "out=" + (folder / "out.png").string(), "nthreads=2",
      "verbose=0", "flam3-render"};
  const double cpuBefore = cpuSeconds(RUSAGE_CHILDREN);
  const auto start = std::chrono::steady_clock::now();
  std::string ignoredOutput;
  const std::optional<std::string> env = app::findOnPath("env");
  int status = -1;
  try {
    if (env) status = app::runProgram(*env, command, &ignoredOutput);
  } catch (const core::Error&) {
    status = -1;  // reported below as a run that failed
  }
  Timing timing;
  timing.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  timing.cpu = cpuSeconds(RUSAGE_CHILDREN) - cpuBefore;
  if (status != 0) timing.wall = -1.0;
  return timing;
}

}  // namespace

void benchFlame(const BenchOptions& options) {
  const core::TriangleMesh mesh = core::loadMesh(options.meshFolder + "/bunny.obj");
  const auto mask =
      std::make_shared<const core::InsideMask>(core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), 256)));
  double voxflameRate = 0.0, voxflameCpuRate = 0.0;
  {
    core::Accumulator accumulator(mask, 2);
    accumulator.setPattern({sampleLayer()}, 1);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // warm-up
    const auto before = accumulator.stats();
    const double cpuBefore = cpuSeconds(RUSAGE_SELF);
    const auto start = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::seconds(4));
    const auto after = accumulator.stats();
    const double cpu = cpuSeconds(RUSAGE_SELF) - cpuBefore;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto samples = static_cast<double>(after.iterations - before.iterations);
    voxflameRate = samples / wall;
    voxflameCpuRate = samples / cpu;
    report(options, {{"bench", "flame"},
                     {"renderer", "voxflame"},
                     {"genome", "flam3 test.flam3 #1 (4 transforms, spherical)"},
                     {"threads", 2},
                     {"samples_per_s", voxflameRate},
                     {"samples_per_cpu_s", voxflameCpuRate},
                     {"cpu_seconds_per_second", cpu / wall},
                     {"inside_fraction", after.insideFraction()},
                     {"escapes_per_million", 1e6 * static_cast<double>(after.escapes - before.escapes) / samples}});
  }
  if (!app::findOnPath("flam3-render")) {
    report(options, {{"bench", "flame"}, {"renderer", "flam3-render"}, {"skipped", "flam3-render is not installed"}});
    return;
  }
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("voxflame-bench-flame-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  constexpr int kLowQuality = 10, kHighQuality = 400;
  const Timing low = timeFlam3(folder, kLowQuality);
  const Timing high = timeFlam3(folder, kHighQuality);
  std::error_code ignored;
  std::filesystem::remove_all(folder, ignored);
  if (low.wall < 0.0 || high.wall < 0.0 || high.wall <= low.wall || high.cpu <= low.cpu) {
    report(options, {{"bench", "flame"}, {"renderer", "flam3-render"}, {"skipped", "flam3-render failed"}});
    return;
  }
  const double samples = static_cast<double>(kHighQuality - kLowQuality) * 640.0 * 480.0;
  const double flam3Rate = samples / (high.wall - low.wall);
  const double flam3CpuRate = samples / (high.cpu - low.cpu);
  report(options, {{"bench", "flame"},
                   {"renderer", "flam3-render"},
                   {"genome", "flam3 test.flam3 #1 (4 transforms, spherical)"},
                   {"threads", 2},
                   {"samples_per_s", flam3Rate},
                   {"samples_per_cpu_s", flam3CpuRate},
                   {"cpu_seconds_per_second", (high.cpu - low.cpu) / (high.wall - low.wall)},
                   {"seconds_quality_10", low.wall},
                   {"seconds_quality_400", high.wall}});
  // The goal is about wall-clock rates on two threads; the CPU-second ratio says how much of it
  // is the code itself rather than how well each uses the two cores.
  report(options, {{"bench", "flame"},
                   {"voxflame_over_flam3", voxflameRate / flam3Rate},
                   {"voxflame_over_flam3_per_cpu_s", voxflameCpuRate / flam3CpuRate},
                   {"goal", 3.0}});
}

}  // namespace voxflame::bench
