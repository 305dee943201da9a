// `voxflame bench flame`: voxflame's chaos game against flam3-render (Debian's flam3-utils) on the
// same genomes, on two threads, side by side in one run: the first flame of flam3's own sample
// file (four transforms, spherical each), then the heaviest flame of the corpus beside the
// repository that flam3-render renders (the most variation terms, then transforms, then xaos;
// imported whole by voxflame). Both rates are iterations (samples) per second.
//
// flam3-render's time includes fixed costs (start-up, density estimation, filtering, writing the
// PNG), so it runs twice, at two qualities, and its rate is the difference in samples over the
// difference in time: the marginal rate of its chaos game alone. Its sample count is quality ×
// 4^zoom × width × height, the number flam3 draws (rect.c), gutter excluded, which if anything
// overstates its time per sample by the gutter's share (a few percent at 640×480).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "bench.h"
#include "core/refinement/accumulator.h"
#include "core/error.h"
#include "core/flame/xml.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/scene.h"
#include "flam3_runs.h"
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

std::string sampleXml() {
  std::ostringstream xml;
  xml << "<flame palette=\"15\" size=\"640 480\" center=\"0 0\" scale=\"240\" oversample=\"1\" filter=\"1\" "
         "quality=\"1\" background=\"0 0 0\" brightness=\"4\" gamma=\"4\" vibrancy=\"1\">\n";
  for (const SampleXform& s : kSample)
    xml << "  <xform weight=\"" << s.weight << "\" color=\"" << s.color << "\" spherical=\"1\" coefs=\"" << s.a << " "
        << s.d << " " << s.b << " " << s.e << " " << s.c << " " << s.f << "\"/>\n";
  xml << "</flame>\n";
  return xml.str();
}

constexpr int kThreads = 2;
constexpr int kMaxWidth = 640;

// A genome both programs run: voxflame's layers and flam3's XML, with flam3's size, quality and
// zoom (which fix how many samples a quality scale asks of it).
struct Genome {
  std::string label;
  std::vector<core::PatternLayer> layers;
  std::string xml;
  int width = 640, height = 480;
  double quality = 1.0, zoom = 0.0;
  int highQuality = 400;  // samples per pixel of flam3's long run (its short one: 10)
};

Genome stockGenome() {
  Genome genome;
  genome.label = "flam3 test.flam3 #1 (4 transforms, spherical)";
  genome.layers = {sampleLayer()};
  genome.xml = sampleXml();
  return genome;
}

std::size_t termCount(const core::FlameGenome& genome) {
  std::size_t terms = genome.hasFinal ? genome.finalXform.variations.size() : 0;
  for (const core::FlameXform& x : genome.xforms) terms += x.variations.size();
  return terms;
}

// The heaviest corpus flame that voxflame imports whole and flam3-render renders (tried at a
// small size and quality, heaviest first); nothing without a corpus or flam3-render.
std::optional<Genome> heaviestCorpusGenome(const std::filesystem::path& folder) {
  struct Candidate {
    std::filesystem::path file;
    std::size_t index = 0;
    core::ImportedFlame flame;
    std::tuple<std::size_t, std::size_t, bool> weight;  // terms, transforms, xaos
  };
  std::vector<Candidate> candidates;
  for (const std::filesystem::path& file : corpusFlameFiles()) {
    std::size_t count = 0;
    try {
      count = core::loadFlameFile(file).names.size();
    } catch (const core::Error&) {
      continue;  // refused as a whole
    }
    for (std::size_t index = 0; index < count; ++index) {
      core::FlameImportOptions import;
      import.index = index;
      try {
        core::ImportedFlame flame = core::loadFlameFile(file, import).flame;
        // Whole and clean: a flame whose framing was replaced (Electric Sheep's center="nan nan") is not
        // the one flam3 renders.
        if (!flame.leftOut.empty() || !flame.warnings.empty() || !flame.otherLayers.empty()) continue;
        const std::size_t transforms = flame.genome.xforms.size() + (flame.genome.hasFinal ? 1 : 0);
        const auto weight = std::make_tuple(termCount(flame.genome), transforms, core::hasXaos(flame.genome));
        candidates.push_back({file, index, std::move(flame), weight});
      } catch (const core::Error&) {
        continue;
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.weight > b.weight; });
  for (const Candidate& candidate : candidates) {
    const std::optional<std::string> xml = flameXmlAt(candidate.file, candidate.index);
    if (!xml) continue;
    const std::filesystem::path probe = folder / "probe.flam3";
    std::ofstream(probe) << *xml;
    const core::FlatViewSettings& flat = candidate.flame.flat;
    const double density = flat.quality * std::pow(4.0, flat.zoom);
    // Electric Sheep's edge genomes may frame nothing (center="nan nan"): flam3 would draw no point.
    const bool framed = std::isfinite(flat.centerX) && std::isfinite(flat.centerY) && std::isfinite(flat.scale) &&
                        flat.scale > 0.0 && std::isfinite(density) && density > 0.0;
    if (!framed || flat.width <= 0 || flat.height <= 0) continue;
    // A quick check that flam3-render takes the flame, every variation of it: a quarter of the
    // size, one sample per pixel.
    const Flam3Run check = runFlam3(probe, folder / "probe.png", 0.25, 1.0 / density, 1, kThreads);
    if (!check.ok || !check.skippedVariations.empty()) continue;
    Genome genome;
    genome.label = candidate.file.filename().string() + " #" + std::to_string(candidate.index + 1) + " \"" +
                   candidate.flame.name + "\" (" + std::to_string(std::get<1>(candidate.weight)) + " transforms, " +
                   std::to_string(std::get<0>(candidate.weight)) + " variation terms" +
                   (std::get<2>(candidate.weight) ? ", xaos)" : ")");
    genome.layers = core::sceneFromImportedFlame(candidate.flame, core::Scene{}).layers;
    genome.xml = *xml;
    genome.width = flat.width;
    genome.height = flat.height;
    genome.quality = flat.quality;
    genome.zoom = flat.zoom;
    genome.highQuality = 100;  // real flames iterate slower: a shorter long run
    return genome;
  }
  return std::nullopt;
}

// voxflame's chaos game on the genome in the bunny at 256³, on two threads, for 4 s.
double voxflameRates(const BenchOptions& options, const Genome& genome,
                     const std::shared_ptr<const core::InsideMask>& mask, double& cpuRate) {
  core::Accumulator accumulator(mask, kThreads);
  accumulator.setPattern(genome.layers, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // warm-up
  const auto before = accumulator.stats();
  const double cpuBefore = cpuSeconds(RUSAGE_SELF);
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(4));
  const auto after = accumulator.stats();
  const double cpu = cpuSeconds(RUSAGE_SELF) - cpuBefore;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto samples = static_cast<double>(after.iterations - before.iterations);
  cpuRate = samples / cpu;
  report(options, {{"bench", "flame"},
                   {"renderer", "voxflame"},
                   {"genome", genome.label},
                   {"threads", kThreads},
                   {"samples_per_s", samples / wall},
                   {"samples_per_cpu_s", cpuRate},
                   {"cpu_seconds_per_second", cpu / wall},
                   {"inside_fraction", after.insideFraction()},
                   {"escapes_per_million", 1e6 * static_cast<double>(after.escapes - before.escapes) / samples}});
  return samples / wall;
}

// flam3-render's marginal rates on the genome (see the top of the file); false when it failed.
bool flam3Rates(const BenchOptions& options, const Genome& genome, const std::filesystem::path& folder, double& rate,
                double& cpuRate) {
  const std::filesystem::path file = folder / "genome.flam3";
  std::ofstream(file) << genome.xml;
  // flam3-render truncates width · ss (flam3-render.c): a hair over the exact ratio keeps the width.
  const double sizeScale = std::min(1.0, (kMaxWidth + 1e-6) / genome.width);
  const double width = std::floor(genome.width * sizeScale), height = std::floor(genome.height * sizeScale);
  const double density = genome.quality * std::pow(4.0, genome.zoom);  // flam3's samples per pixel at qs 1
  constexpr int kLowQuality = 10;
  const Flam3Run low = runFlam3(file, folder / "out.png", sizeScale, kLowQuality / density, 1, kThreads);
  const Flam3Run high = runFlam3(file, folder / "out.png", sizeScale, genome.highQuality / density, 1, kThreads);
  if (!low.ok || !high.ok || high.wall <= low.wall || high.cpu <= low.cpu) {
    report(options, {{"bench", "flame"},
                     {"renderer", "flam3-render"},
                     {"genome", genome.label},
                     {"skipped", "flam3-render failed"}});
    return false;
  }
  const double samples = static_cast<double>(genome.highQuality - kLowQuality) * width * height;
  rate = samples / (high.wall - low.wall);
  cpuRate = samples / (high.cpu - low.cpu);
  report(options, {{"bench", "flame"},
                   {"renderer", "flam3-render"},
                   {"genome", genome.label},
                   {"threads", kThreads},
                   {"samples_per_s", rate},
                   {"samples_per_cpu_s", cpuRate},
                   {"cpu_seconds_per_second", (high.cpu - low.cpu) / (high.wall - low.wall)},
                   {"size", std::to_string(static_cast<int>(width)) + "x" + std::to_string(static_cast<int>(height))},
                   {"seconds_quality_10", low.wall},
                   {"seconds_quality_" + std::to_string(genome.highQuality), high.wall}});
  return true;
}

}  // namespace

void benchFlame(const BenchOptions& options) {
  const core::TriangleMesh mesh = core::loadMesh(options.meshFolder + "/bunny.obj");
  const auto mask =
      std::make_shared<const core::InsideMask>(core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), 256)));
  const bool haveFlam3 = app::findOnPath("flam3-render").has_value();
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("voxflame-bench-flame-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::vector<Genome> genomes = {stockGenome()};
  if (haveFlam3) {
    if (std::optional<Genome> heaviest = heaviestCorpusGenome(folder))
      genomes.push_back(std::move(*heaviest));
    else
      report(options, {{"bench", "flame"},
                       {"genome", "heaviest corpus flame"},
                       {"skipped", "no corpus flame that flam3-render renders"}});
  }
  for (const Genome& genome : genomes) {
    double voxflameCpuRate = 0.0;
    const double voxflameRate = voxflameRates(options, genome, mask, voxflameCpuRate);
    if (!haveFlam3) {
      report(options, {{"bench", "flame"}, {"renderer", "flam3-render"}, {"skipped", "flam3-render is not installed"}});
      continue;
    }
    double flam3Rate = 0.0, flam3CpuRate = 0.0;
    if (!flam3Rates(options, genome, folder, flam3Rate, flam3CpuRate)) continue;
    // The goal is about wall-clock rates on two threads; the CPU-second ratio says how much of it
    // is the code itself rather than how well each uses the two cores.
    report(options, {{"bench", "flame"},
                     {"genome", genome.label},
                     {"voxflame_over_flam3", voxflameRate / flam3Rate},
                     {"voxflame_over_flam3_per_cpu_s", voxflameCpuRate / flam3CpuRate},
                     {"goal", 3.0}});
  }
  std::error_code ignored;
  std::filesystem::remove_all(folder, ignored);
}

}  // namespace voxflame::bench
