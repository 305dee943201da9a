// Explore: the Lyapunov analysis of layer 0, Search (F3) and Mutate in the background, and the
// history of what they found (Back, Forward). Changes layer 0's pattern.
#include "explorer_ui.h"

#include <algorithm>
#include <cstdio>

#include "core/attractor.h"
#include "core/error.h"
#include "core/flame/flame.h"
#include "core/flame/search.h"
#include "core/scene_schema.h"
#include "panels.h"

namespace voxflame::app::panels {

// Background analysis, search and the search history.

std::string analysisKey(const core::PatternLayer& layer) {
  std::string key =
      layer.attractor + "/" + std::string(core::toString(layer.integrator)) + "/" + std::to_string(layer.step);
  for (double p : layer.params) {
    key += '/';
    key += std::to_string(p);
  }
  return key;
}

// Keeps the Lyapunov line in step with layer 0; one analysis at a time, never waited for.
void updateAnalysis(const Document& document, ExplorePanelState& explore, Services& services) {
  const bool chaosGame = !document.scene.layers.empty() && document.scene.layers.front().isChaosGame();
  if (services.analysis.ready()) {
    try {
      const core::OrbitAnalysis result = *services.analysis.take();
      char text[160];
      std::snprintf(text, sizeof text, "λ %.3f  %.3f  %.3f  (%s)", result.lyapunov[0], result.lyapunov[1],
                    result.lyapunov[2], std::string(core::toString(result.verdict)).c_str());
      if (!chaosGame) explore.lyapunovText = text;  // an attractor's analysis that finished after a switch is stale
    } catch (const core::Error& e) {
      if (!chaosGame) explore.lyapunovText = e.what();
    }
  }
  if (document.scene.layers.empty()) return;
  const core::PatternLayer& front = document.scene.layers.front();
  if (chaosGame) {
    // A chaos game picks a map at random every step: there is no one orbit whose Lyapunov
    // exponents would mean anything, so the line just says what the layer is.
    explore.lyapunovText =
        front.kind == core::PatternKind::Flame ? "flame (chaos game)" : "quaternion Julia (chaos game)";
    explore.analysedKey.clear();
    explore.analysedRevision = ~std::uint64_t{0};
    return;
  }
  if (services.analysis.busy()) return;
  // Only a pattern edit can change what is analysed: no key is made on the frames between.
  if (explore.analysedRevision == document.revisions().pattern) return;
  explore.analysedRevision = document.revisions().pattern;
  const std::string key = analysisKey(front);
  if (key == explore.analysedKey) return;
  explore.analysedKey = key;
  try {
    const core::OrbitSpec spec = core::orbitSpecOf(document.scene.layers.front());
    core::LyapunovOptions options;
    options.steps = 20'000;
    services.analysis.start([spec, options](std::stop_token) { return core::analyseOrbit(spec, options); });
  } catch (const core::Error& e) {
    explore.lyapunovText = e.what();
  }
}

// The part of a layer that Search changes and the history restores (its kind and pattern);
// colour and placement stay.
void applyVisited(core::PatternLayer& layer, const core::PatternLayer& visited) {
  const bool kindChanges = layer.kind != visited.kind;
  layer.kind = visited.kind;
  layer.attractor = visited.attractor;
  layer.params = visited.params;
  layer.integrator = visited.integrator;
  layer.step = visited.step;
  layer.flame = visited.flame;
  layer.julia = visited.julia;
  // An attractor cannot colour by flam3's index; a chaos layer starts with it.
  if (kindChanges) layer.color.mode = visited.isChaosGame() ? core::ColorMode::Index : core::ColorMode::Speed;
}

std::string fillText(const core::FillReport& fill) {
  char text[128];
  std::snprintf(text, sizeof text, "fills %.0f%% of its box, thinnest side %.2f of the longest", 100.0 * fill.occupancy,
                fill.extentRatio);
  return text;
}

// Search (fresh) draws new patterns near nothing; Mutate (and "Find a nearby one") moves the
// current one by `strength`. Attractors always search near their parameters, as before; flames
// and Julia sets use the fill test of flame/search.h. Whatever a search finds, the live view runs
// bounded: each candidate that passes the search's own test must also pass the probe the
// accumulator makes (core::runsBounded) with the scene's seed, else the view would keep the last
// bounded pattern under the sliders of one that escapes.
void startSearch(const Document& document, ExplorePanelState& explore, Services& services, double strength,
                 bool fresh) {
  if (services.search.busy() || document.scene.layers.empty()) return;  // one at a time
  using Outcome = Services::SearchOutcome;
  try {
    const core::PatternLayer layer = document.scene.layers.front();
    const std::uint64_t seed = explore.searchSeed++;
    const std::uint64_t sceneSeed = document.scene.seed;
    if (layer.isChaosGame()) {
      core::FlameSearchOptions options;
      options.seed = seed;
      options.count = 1;
      options.strength = strength;
      options.juliaView = layer.julia;
      options.acceptFlame = [layer, sceneSeed](const core::FlameGenome& genome) {
        core::PatternLayer candidate = layer;
        candidate.flame = genome;
        return core::runsBounded(candidate, sceneSeed);
      };
      options.acceptJulia = [layer, sceneSeed](const core::QuaternionJuliaSettings& julia) {
        core::PatternLayer candidate = layer;
        candidate.julia = julia;
        return core::runsBounded(candidate, sceneSeed);
      };
      services.searchTried.reset();  // the flame and Julia searches count no tries
      services.searchStrength.reset();
      explore.searchMessage = "searching…";
      services.search.start([layer, options, fresh](std::stop_token stop) mutable {
        options.stop = stop;
        Outcome outcome;
        core::PatternLayer found = layer;
        if (layer.kind == core::PatternKind::Flame) {
          const auto results =
              core::searchFlames(fresh ? std::nullopt : std::optional<core::FlameGenome>(layer.flame), options);
          if (results.empty()) {
            outcome.message = "no flame that fills its box was found; try again or a smaller strength";
            return outcome;
          }
          found.flame = results.front().genome;
          outcome.message = "found a flame: " + fillText(results.front().fill);
        } else {
          const auto results = core::searchQuaternionJulia(
              fresh ? std::nullopt : std::optional<core::QuaternionJuliaSettings>(layer.julia), options);
          if (results.empty()) {
            outcome.message = "no Julia set that fills its box was found; try again or a smaller strength";
            return outcome;
          }
          found.julia = results.front().julia;
          outcome.message = "found a Julia set: " + fillText(results.front().fill);
        }
        outcome.found = found;
        return outcome;
      });
      return;
    }
    const core::OrbitSpec spec = core::orbitSpecOf(layer);
    core::SearchOptions options;
    options.seed = seed;
    options.count = 1;
    options.strength = strength;
    // Nothing nearby: it widens by itself, a few hundred tries at each strength, before giving up.
    options.widenTo = std::max(strength, core::kSearchWidenTo);
    options.maxCandidates = core::kSearchTriesPerStrength;
    // The layer's orbits start at the attractor's start, so the analysis the message quotes is of
    // the orbit the view runs, not of one from a nearby start that the layer cannot hold.
    options.jitterStart = false;
    options.accept = [layer, sceneSeed](const std::vector<double>& params) {
      core::PatternLayer candidate = layer;
      candidate.params = params;
      return core::runsBounded(candidate, sceneSeed);
    };
    services.searchTried = std::make_shared<std::atomic<int>>(0);
    services.searchStrength = std::make_shared<std::atomic<double>>(strength);
    services.searchProgress = std::make_shared<core::ProgressSignal>();
    explore.searchMessage = "searching…";
    services.search.start([layer, spec, options, tried = services.searchTried, strengthNow = services.searchStrength,
                           progress = services.searchProgress](std::stop_token stop) mutable {
      options.stop = stop;
      options.tried = tried.get();
      options.triedSignal = progress.get();
      options.strengthNow = strengthNow.get();
      Outcome outcome;
      const auto results = core::searchChaos(spec, options);
      if (results.empty()) {
        char text[160];
        std::snprintf(text, sizeof text, "no chaotic set within strength %.2g–%.2g after %d tries", options.strength,
                      options.widenTo, tried->load());
        outcome.message = text;
        return outcome;
      }
      core::PatternLayer found = layer;
      found.params = results.front().params;
      outcome.found = found;
      char text[128];
      std::snprintf(text, sizeof text, "found: largest Lyapunov exponent %.3f (strength %.2g, %d tries)",
                    results.front().analysis.lyapunov[0], strengthNow->load(), tried->load());
      outcome.message = text;
      return outcome;
    });
  } catch (const core::Error& e) {
    explore.searchMessage = e.what();
  }
}

void collectSearch(Document& document, ExplorePanelState& explore, Services& services) {
  if (!services.search.ready()) return;
  try {
    const Services::SearchOutcome outcome = *services.search.take();
    explore.searchMessage = outcome.message;
    if (!outcome.found || document.scene.layers.empty()) return;
    core::PatternLayer& layer = document.scene.layers.front();
    if (layer.kind != outcome.found->kind) {
      explore.searchMessage = "the layer changed kind while the search ran; its result was dropped";
      return;
    }
    // The history keeps where the search started from, then each find; a find after going back
    // drops the forward part, as in a browser.
    if (explore.visited.empty()) {
      explore.visited.push_back(layer);
      explore.visitedMessages.assign(1, "where the search started");
    }
    explore.visited.resize(std::min(explore.visited.size(), explore.visitedIndex + 1));
    explore.visitedMessages.resize(explore.visited.size());
    applyVisited(layer, *outcome.found);
    document.edited(core::Affects::Pattern);
    explore.visited.push_back(layer);
    explore.visitedMessages.push_back(outcome.message);
    explore.visitedIndex = explore.visited.size() - 1;
  } catch (const core::Error& e) {
    explore.searchMessage = e.what();
  }
}

void goVisited(Document& document, ExplorePanelState& explore, int direction) {
  if (explore.visited.empty() || document.scene.layers.empty()) return;
  const auto target = static_cast<long long>(explore.visitedIndex) + direction;
  if (target < 0 || target >= static_cast<long long>(explore.visited.size())) return;
  explore.visitedIndex = static_cast<std::size_t>(target);
  applyVisited(document.scene.layers.front(), explore.visited[explore.visitedIndex]);
  document.edited(core::Affects::Pattern);
  // The "found:" line is the one of the pattern now shown.
  if (explore.visitedIndex < explore.visitedMessages.size())
    explore.searchMessage = explore.visitedMessages[explore.visitedIndex];
}

}  // namespace voxflame::app::panels
