// `voxflame bench fidelity [FILE...]`: how close voxflame's flat view (core/flame/flat_render.h) comes to
// flam3-render on the same flames. Each flame (the first of its file) is rendered at the same size
// (its own, shrunk to at most 640 pixels wide) and quality 400 by both, then compared: SSIM of the
// luma against flam3's render, and the ratio of mean linear luminance. flam3-render against itself
// with another seed is the ceiling: the SSIM two renders of one flame reach when only the noise of
// the chaos game differs. Goals: SSIM within 0.05 of the ceiling, luminance ratio 0.98–1.02 (the
// count within 0.9–1.1 is reported too, as before).
//
// Without FILEs: flam3's own test.flam3 and the corpus flames beside the repository (or in
// $VOXFLAME_FLAMES) that flam3-render renders, up to 20 in all. A flame with a variation flam3-render
// does not know is skipped and named: flam3-render leaves the variation out, so its picture is of
// another flame.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "bench.h"
#include "flam3_runs.h"
#include "core/error.h"
#include "core/flame/xml.h"
#include "core/flame/flat_render.h"
#include "core/image_io.h"
#include "core/image_metrics.h"
#include "programs.h"

namespace voxflame::bench {

namespace {

constexpr int kMaxWidth = 640;
constexpr double kQuality = 400.0;
constexpr std::size_t kMaxDefaultFlames = 20;
constexpr const char* kFlam3Test = "/usr/share/flam3/test.flam3";

std::vector<std::filesystem::path> defaultFlames() {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::exists(kFlam3Test)) files.emplace_back(kFlam3Test);
  const std::vector<std::filesystem::path> found = corpusFlameFiles();
  // The corpus holds a copy of test.flam3: each flame file once.
  const std::string test = files.empty() ? std::string() : fileBytes(files.front());
  for (const std::filesystem::path& file : found)
    if (test.empty() || fileBytes(file) != test) files.push_back(file);
  return files;
}

// flam3-render's picture of `genome`; nothing when it fails (a flame it refuses). `skipped` gets the
// variations it left out (Flam3Run::skippedVariations).
std::optional<core::ImageRGBA> flam3Image(const std::filesystem::path& genome, const std::filesystem::path& out,
                                          double sizeScale, double qualityScale, int seed,
                                          std::vector<std::string>* skipped = nullptr) {
  Flam3Run run = runFlam3(genome, out, sizeScale, qualityScale, seed, 2);
  if (skipped) *skipped = std::move(run.skippedVariations);
  if (!run.ok) return std::nullopt;
  try {
    return core::readPng(out).image;
  } catch (const core::Error&) {
    return std::nullopt;
  }
}

}  // namespace

void benchFidelity(const BenchOptions& options) {
  if (!app::findOnPath("flam3-render")) {
    report(options, {{"bench", "fidelity"}, {"skipped", "flam3-render is not installed"}});
    return;
  }
  const bool chosen = !options.presets.empty();
  std::vector<std::filesystem::path> files;
  for (const std::string& file : options.presets) files.emplace_back(file);
  if (!chosen) files = defaultFlames();
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("voxflame-bench-fidelity-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::size_t rendered = 0, metSsim = 0, metLuminance = 0, metLuminanceGoal = 0;
  double ssimGapSum = 0.0;
  for (const std::filesystem::path& file : files) {
    if (!chosen && rendered >= kMaxDefaultFlames) break;
    const std::string name = file.filename().string();
    core::Scene scene;
    try {
      core::FlameImportOptions import;
      import.depth = 0.0;
      const core::ImportedFlame flame = core::loadFlameFile(file, import).flame;
      // flam3 draws a flame without a palette with its all-black one; voxflame lends it one.
      if (std::any_of(flame.warnings.begin(), flame.warnings.end(),
                      [](const std::string& w) { return w.find("has no palette") != std::string::npos; })) {
        report(options, {{"bench", "fidelity"},
                         {"flame", name},
                         {"skipped", "the file has no palette: flam3-render draws it black, voxflame lends it one"}});
        continue;
      }
      scene = core::sceneFromImportedFlame(flame, core::Scene{});
    } catch (const core::Error& e) {
      if (chosen) report(options, {{"bench", "fidelity"}, {"flame", name}, {"skipped", e.what()}});
      continue;
    }
    const std::optional<std::string> xml = flameXmlAt(file, 0);
    if (!xml) continue;
    const std::filesystem::path genome = folder / "genome.flam3";
    std::ofstream(genome) << *xml;
    // flam3-render's ss scales the size and truncates it (flam3-render.c); voxflame renders the
    // size that comes out, with the framing scaled by the same factor.
    // A hair over the exact ratio, so flam3's truncation of width · ss keeps the width it aims at.
    const double sizeScale = std::min(1.0, (kMaxWidth + 1e-6) / scene.flat.width);
    const double qualityScale = kQuality / scene.flat.quality;
    auto start = std::chrono::steady_clock::now();
    std::vector<std::string> unknown;
    const std::optional<core::ImageRGBA> reference =
        flam3Image(genome, folder / "flam3-a.png", sizeScale, qualityScale, 1, &unknown);
    const double flam3Seconds = secondsSince(start);
    if (!reference) {
      if (chosen) report(options, {{"bench", "fidelity"}, {"flame", name}, {"skipped", "flam3-render failed"}});
      continue;
    }
    if (!unknown.empty()) {
      // flam3-render drew the flame without them: not the flame its author saw, so no reference.
      std::string names;
      for (const std::string& variation : unknown) names += (names.empty() ? "" : ", ") + variation;
      report(options, {{"bench", "fidelity"},
                       {"flame", name},
                       {"skipped", "flam3-render does not know " + names + " and left it out"}});
      continue;
    }
    const std::optional<core::ImageRGBA> again = flam3Image(genome, folder / "flam3-b.png", sizeScale, qualityScale, 2);
    core::FlatRenderOptions flat;
    flat.width = reference->width;
    flat.height = reference->height;
    flat.quality = kQuality;
    start = std::chrono::steady_clock::now();
    core::FlatRenderResult ours;
    try {
      ours = core::renderFlat(scene, flat);
    } catch (const core::Error& e) {
      report(options, {{"bench", "fidelity"}, {"flame", name}, {"skipped", e.what()}});
      continue;
    }
    const double voxflameSeconds = secondsSince(start);
    if (const char* keep = std::getenv("VOXFLAME_FIDELITY_KEEP")) {
      // For looking at the pairs side by side.
      const std::filesystem::path stem = std::filesystem::path(keep) / file.stem();
      core::writePng(stem.string() + "-voxflame.png", ours.image, 8, {});
      core::writePng(stem.string() + "-flam3.png", *reference, 8, {});
    }
    ++rendered;
    const double ssim = core::ssimLuma(ours.image, *reference);
    const double ceiling = again ? core::ssimLuma(*again, *reference) : 1.0;
    const double referenceLuminance = core::meanLinearLuminance(*reference);
    const double ourLuminance = core::meanLinearLuminance(ours.image);
    // flam3 renders some flames black (fr0st's test_methods draws outside its frame): no ratio
    // then, and the goal is met when voxflame's is black too.
    const nlohmann::json ratio = referenceLuminance > 0.0 ? nlohmann::json(ourLuminance / referenceLuminance) : nullptr;
    ssimGapSum += ceiling - ssim;
    metSsim += ceiling - ssim <= 0.05;
    metLuminance += ratio.is_number() ? ratio.get<double>() >= 0.9 && ratio.get<double>() <= 1.1 : ourLuminance == 0.0;
    metLuminanceGoal +=
        ratio.is_number() ? ratio.get<double>() >= 0.98 && ratio.get<double>() <= 1.02 : ourLuminance == 0.0;
    report(options, {{"bench", "fidelity"},
                     {"flame", name},
                     {"size", std::to_string(reference->width) + "x" + std::to_string(reference->height)},
                     {"ssim", ssim},
                     {"ssim_ceiling", ceiling},
                     {"luminance_ratio", ratio},
                     {"voxflame_seconds", voxflameSeconds},
                     {"flam3_seconds", flam3Seconds}});
  }
  std::error_code ignored;
  std::filesystem::remove_all(folder, ignored);
  report(options, {{"bench", "fidelity"},
                   {"flames", rendered},
                   {"ssim_within_0.05_of_ceiling", metSsim},
                   {"luminance_ratio_0.9_to_1.1", metLuminance},
                   {"luminance_ratio_0.98_to_1.02", metLuminanceGoal},
                   {"mean_ssim_gap", rendered ? ssimGapSum / static_cast<double>(rendered) : 0.0}});
}

}  // namespace voxflame::bench
