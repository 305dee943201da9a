// `voxflame bench search`: the explorer's Search (F3) on each shipped attractor preset, as the
// panel runs it: seconds until the first chaotic, volume-filling candidate, how many it tried,
// and the strength it had widened to.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <vector>

#include "bench.h"
#include "core/lyapunov.h"
#include "core/scene.h"
#include "preset_library.h"

namespace voxflame::bench {

namespace {

// The explorer's search from `spec`, as the panel runs it: whether it found a chaotic set, in
// how many seconds, after how many tries, at what strength.
nlohmann::json timeSearch(const core::OrbitSpec& spec) {
  core::SearchOptions search;
  search.seed = 1;
  search.count = 1;
  search.strength = 0.1;
  search.widenTo = core::kSearchWidenTo;
  search.maxCandidates = core::kSearchTriesPerStrength;
  std::atomic<int> tried{0};
  std::atomic<double> strength{0.0};
  search.tried = &tried;
  search.strengthNow = &strength;
  const auto start = std::chrono::steady_clock::now();
  const bool found = !core::searchChaos(spec, search).empty();
  return {{"found", found},
          {"seconds_to_first_chaotic", secondsSince(start)},
          {"tried", tried.load()},
          {"strength", strength.load()}};
}

}  // namespace

void benchSearch(const BenchOptions& options) {
  std::vector<std::filesystem::path> presets;
  for (const auto& entry : std::filesystem::directory_iterator(app::findShippedPresetFolder()))
    if (entry.path().extension() == ".json") presets.push_back(entry.path());
  std::sort(presets.begin(), presets.end());
  double worst = 0.0;
  int searched = 0, foundCount = 0;
  auto run = [&](const std::string& name, const std::string& attractor, const core::OrbitSpec& spec) {
    nlohmann::json measurement = {{"bench", "search"}, {"preset", name}, {"attractor", attractor}};
    measurement.update(timeSearch(spec));
    worst = std::max(worst, measurement["seconds_to_first_chaotic"].get<double>());
    foundCount += measurement["found"].get<bool>();
    ++searched;
    report(options, measurement);
  };
  for (const std::filesystem::path& path : presets) {
    const core::Scene scene = core::loadScene(path);
    if (scene.layers.empty() || scene.layers.front().kind != core::PatternKind::Attractor) continue;
    run(path.stem().string(), scene.layers.front().attractor, core::orbitSpecOf(scene.layers.front()));
  }
  // The hard case: a periodic Thomas (b above the onset of chaos at 0.208), where nothing chaotic
  // lies near and the search must widen.
  core::OrbitSpec periodic = core::defaultOrbitSpec(core::attractorOrThrow("thomas"));
  periodic.params = {0.32};
  run("periodic thomas (b = 0.32)", "thomas", periodic);
  report(options, {{"bench", "search"},
                   {"searches", searched},
                   {"found", foundCount},
                   {"worst_seconds", worst},
                   {"goal_seconds", 5.0}});
}

}  // namespace voxflame::bench
