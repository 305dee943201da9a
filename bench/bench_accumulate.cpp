#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "bench.h"
#include "core/refinement/accumulator.h"
#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/flame/xml.h"
#include "core/scene.h"
#include "flam3_runs.h"
#include "gl/gpu_accumulator.h"

namespace voxflame::bench {

namespace {

// Iterations per wall-clock and per CPU second of a running accumulator, over a fixed window
// after a warm-up.
struct Rate {
  double perSecond = 0.0;
  double perCpuSecond = 0.0;
  double cpuSecondsPerSecond = 0.0;
  double depositsPerSecond = 0.0;  // points added to the grid (inside the mask) per second
  core::AccumulatorStats stats;
};

// Polls (benchmarks may) until the backend's version moves on, at most `limit` seconds: the GPU
// backend's counts move once a dispatch round, which on a software rasteriser running a heavy flame
// takes longer than the measuring window, so the window starts and ends where a round ends.
void waitForNextVersion(const core::RefinementBackend& accumulator, double limit) {
  const std::uint64_t version = accumulator.version();
  const auto start = std::chrono::steady_clock::now();
  while (accumulator.version() == version &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < limit)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

Rate measureRate(const core::RefinementBackend& accumulator) {
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // warm-up
  waitForNextVersion(accumulator, 120.0);
  const auto before = accumulator.stats();
  const double cpuBefore = cpuSeconds(RUSAGE_SELF);
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  waitForNextVersion(accumulator, 120.0);
  Rate rate;
  rate.stats = accumulator.stats();
  const double cpuUsed = cpuSeconds(RUSAGE_SELF) - cpuBefore;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto iterations = static_cast<double>(rate.stats.iterations - before.iterations);
  rate.perSecond = iterations / seconds;
  rate.depositsPerSecond = static_cast<double>(rate.stats.points - before.points) / seconds;
  rate.perCpuSecond = iterations / cpuUsed;
  rate.cpuSecondsPerSecond = cpuUsed / seconds;
  return rate;
}

// A catalogue attractor with its defaults, coloured by speed along a two-stop gradient.
std::optional<core::PatternLayer> benchLayer(const char* id) {
  const core::AttractorInfo* info = core::findAttractor(id);
  if (!info) return std::nullopt;
  core::PatternLayer layer;
  layer.attractor = id;
  layer.params = info->defaultParams();
  layer.step = info->defaultStep;
  layer.integrator = info->defaultIntegrator;
  layer.color.gradient = {{0.0f, {0.1f, 0.2f, 1.0f}}, {1.0f, {1.0f, 0.6f, 0.1f}}};
  return layer;
}

// A flame layer of `genome`, coloured by its colour index along the benchmarks' two-stop gradient.
core::PatternLayer benchFlameLayer(const core::FlameGenome& genome) {
  core::PatternLayer layer;
  layer.kind = core::PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = genome;
  layer.color.mode = core::ColorMode::Index;
  layer.color.gradient = {{0.0f, {0.1f, 0.2f, 1.0f}}, {1.0f, {1.0f, 0.6f, 0.1f}}};
  return layer;
}

// The heaviest flame of the corpus (most variation terms, then transforms) that imports whole and
// the GPU backend runs: the flame the GPU's goal names, measured on both backends.
std::optional<std::pair<std::string, core::PatternLayer>> heaviestGpuCorpusFlame() {
  std::optional<std::pair<std::string, core::PatternLayer>> best;
  std::size_t bestTerms = 0, bestTransforms = 0;
  for (const std::filesystem::path& file : corpusFlameFiles()) {
    std::size_t count = 0;
    try {
      count = core::loadFlameFile(file).names.size();
    } catch (const core::Error&) {
      continue;
    }
    for (std::size_t index = 0; index < count; ++index) {
      core::FlameImportOptions import;
      import.index = index;
      try {
        const core::ImportedFlame flame = core::loadFlameFile(file, import).flame;
        if (!flame.leftOut.empty() || !flame.otherLayers.empty()) continue;
        core::PatternLayer layer = benchFlameLayer(flame.genome);
        if (!gl::gpuSupports({layer})) continue;
        std::size_t terms = flame.genome.hasFinal ? flame.genome.finalXform.variations.size() : 0;
        for (const core::FlameXform& x : flame.genome.xforms) terms += x.variations.size();
        const std::size_t transforms = flame.genome.xforms.size();
        if (best && std::tie(terms, transforms) <= std::tie(bestTerms, bestTransforms)) continue;
        bestTerms = terms;
        bestTransforms = transforms;
        best.emplace(file.filename().string() + " #" + std::to_string(index), std::move(layer));
      } catch (const core::Error&) {
        continue;
      }
    }
  }
  return best;
}

}  // namespace

void benchAccumulateChaos(const BenchOptions& options, const std::shared_ptr<const core::InsideMask>& mask,
                          int allThreads);
void benchAccumulateGpu(const BenchOptions& options);

// Lorenz-84 (and every other catalogue entry named below) filling the bunny's mask at 256³,
// colour by speed, timed over a fixed wall-clock window after a warm-up. Rows name the deposit.
void benchAccumulate(const BenchOptions& options) {
  if (options.backend == "gpu") return benchAccumulateGpu(options);
  const core::TriangleMesh mesh = core::loadMesh(options.meshFolder + "/bunny.obj");
  const auto mask =
      std::make_shared<const core::InsideMask>(core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), 256)));
  const int allThreads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (const char* id : {"lorenz84", "lorenz", "pickover", "polynomial_a"}) {
    const std::optional<core::PatternLayer> layer = benchLayer(id);
    if (!layer) continue;
    // Lorenz-84 on 2 threads also runs with the old nearest-voxel deposit, right after the
    // jittered one, so the cost of the anti-aliasing jitter reads off adjacent rows.
    std::vector<std::pair<int, core::Deposit>> runs{{1, core::Deposit::Jittered},
                                                    {allThreads, core::Deposit::Jittered}};
    if (std::string(id) == "lorenz84") {
      if (allThreads != 2) runs.emplace_back(2, core::Deposit::Jittered);
      runs.emplace_back(2, core::Deposit::Nearest);
    }
    for (const auto& [threads, deposit] : runs) {
      core::Accumulator accumulator(mask, threads);
      accumulator.setDeposit(deposit);
      accumulator.setPattern({*layer}, 1);
      const Rate rate = measureRate(accumulator);
      report(options, {{"bench", "accumulate"},
                       {"attractor", id},
                       {"grid", 256},
                       {"threads", threads},
                       {"deposit", deposit == core::Deposit::Jittered ? "jittered" : "nearest"},
                       {"points_per_s", rate.perSecond},
                       {"deposits_per_s", rate.depositsPerSecond},
                       {"inside_fraction", rate.stats.insideFraction()},
                       {"cpu_seconds_per_second", rate.cpuSecondsPerSecond},
                       {"points_per_cpu_s", rate.perCpuSecond}});
    }
  }
  benchAccumulateChaos(options, mask, allThreads);
}

// The chaos-game kinds on the same mask: the built-in default flame (three transforms, julia,
// spherical and sinusoidal terms, colour index) and a quaternion Julia set, on one thread and on all.
void benchAccumulateChaos(const BenchOptions& options, const std::shared_ptr<const core::InsideMask>& mask,
                          int allThreads) {
  const core::PatternLayer flame = benchFlameLayer(core::defaultFlame());
  core::PatternLayer julia = flame;
  julia.kind = core::PatternKind::QuaternionJulia;
  std::vector<std::pair<std::string, core::PatternLayer>> patterns{{"flame (default, 3 transforms)", flame},
                                                                   {"quaternion_julia", julia}};
  if (auto heaviest = heaviestGpuCorpusFlame())
    patterns.emplace_back("heaviest corpus flame the GPU runs: " + heaviest->first, heaviest->second);
  for (const auto& [name, layer] : patterns) {
    for (const int threads : {1, allThreads}) {
      core::Accumulator accumulator(mask, threads);
      accumulator.setPattern({layer}, 1);
      const Rate rate = measureRate(accumulator);
      report(options, {{"bench", "accumulate"},
                       {"pattern", name},
                       {"grid", 256},
                       {"threads", threads},
                       {"deposit", "jittered"},
                       {"points_per_s", rate.perSecond},
                       {"deposits_per_s", rate.depositsPerSecond},
                       {"inside_fraction", rate.stats.insideFraction()},
                       {"cpu_seconds_per_second", rate.cpuSecondsPerSecond},
                       {"points_per_cpu_s", rate.perCpuSecond}});
    }
  }
}

// The GPU backend (gl::GpuAccumulator) filling the bunny's mask at 256³ and 512³: deposits (points
// added inside the mask) per second, the figure the GPU's goals name, beside the orbit steps.
void benchAccumulateGpu(const BenchOptions& options) {
  const core::TriangleMesh mesh = core::loadMesh(options.meshFolder + "/bunny.obj");
  for (const int grid : {256, 512}) {
    const auto mask =
        std::make_shared<const core::InsideMask>(core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), grid)));
    std::unique_ptr<gl::GpuAccumulator> backend;
    try {
      backend = std::make_unique<gl::GpuAccumulator>(mask);
    } catch (const core::Error& error) {
      report(options, {{"bench", "accumulate"}, {"backend", "gpu"}, {"grid", grid}, {"error", error.what()}});
      continue;
    }
    gl::GpuAccumulator& accumulator = *backend;
    std::vector<std::pair<std::string, core::PatternLayer>> patterns;
    for (const char* id : {"lorenz84", "lorenz", "pickover", "polynomial_a"})
      if (const std::optional<core::PatternLayer> layer = benchLayer(id)) patterns.emplace_back(id, *layer);
    patterns.emplace_back("flame (default, 3 transforms)", benchFlameLayer(core::defaultFlame()));
    if (auto heaviest = heaviestGpuCorpusFlame())
      patterns.emplace_back("heaviest corpus flame the GPU runs: " + heaviest->first, heaviest->second);
    const bool defaultGroupChoice = accumulator.groupChoice();
    for (const auto& [id, layer] : patterns) {
      // A flame both ways: each orbit drawing its transform, and groups of orbits sharing one
      // (the hardware default, flame_kernel.h).
      const bool isFlame = layer.kind == core::PatternKind::Flame;
      for (const bool groupChoice : isFlame ? std::vector<bool>{false, true} : std::vector<bool>{defaultGroupChoice}) {
        accumulator.setGroupChoice(groupChoice);
        accumulator.setTargetPoints(0);
        accumulator.setPattern({layer}, 1);
        const Rate rate = measureRate(accumulator);
        report(options, {{"bench", "accumulate"},
                         {"backend", "gpu"},
                         {"renderer", accumulator.renderer()},
                         {layer.kind == core::PatternKind::Attractor ? "attractor" : "pattern", id},
                         {"grid", grid},
                         {"orbits", accumulator.orbitsPerLayer()},
                         {"colour_cell_voxels", 1 << (3 * accumulator.colourLayout().shift)},
                         {"transform_draw", isFlame ? (groupChoice ? "group" : "orbit") : "-"},
                         {"deposit", "jittered"},
                         {"points_per_s", rate.perSecond},
                         {"deposits_per_s", rate.depositsPerSecond},
                         {"inside_fraction", rate.stats.insideFraction()},
                         {"cpu_seconds_per_second", rate.cpuSecondsPerSecond}});
      }
    }
  }
}

}  // namespace voxflame::bench
