// The corpus tally (issue 25): every flame of every real flame file in ../shared/data/flames
// (56 files from flam3, Electric Sheep, Apophysis, Fractorium, Fr0st, JWildfire and FLAM3H; see
// its SOURCES.md) goes through the importer, and the test prints how many were imported whole,
// how many lost something (naming what, most common first, then each such flame by file and
// index with what it lost) and how many were refused (why).
//
// The issue's goal is at least 95% of the flames imported whole, nothing refused except truly
// broken XML. The thresholds below are what the importer reaches today; raise them as it gets
// better, never lower them. Before issue 25: 155 of 268 whole (57.8%), 98 lost something (xaos
// in 50, flatten in 36), 15 refused (more than 16 transforms, attribute names that are not XML
// names, a stray closing tag, JWildfire's layered <jwf-flame> files).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"

using namespace voxflame::core;

namespace {

// At least this many flames of the corpus import whole, and at most this many are refused.
constexpr double kWholeShareGoal = 0.98;  // the issue's goal, reported beside the threshold
// 264 of 268. A flame counts as whole only when no warning names a loss, and the import names what
// it used to pass over in silence (chained final transforms, kept since, JWildfire's post symmetry
// and solid rendering); the 3D cameras of Apophysis 3D, Fractorium and JWildfire are kept by the
// flat view. The four left: flower3D and rose (plugins whose source is not public), custom_wf_full
// (Java compiled at load), svg_wf's colours (its SVG's colours per point).
constexpr double kWholeShareThreshold = 0.985;
constexpr std::size_t kRefusedLimit = 0;

const std::filesystem::path kCorpus = VOXFLAME_TEST_FLAMES;

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// How many <flame> elements a file that the importer refuses outright seems to hold, so a refused
// file counts as many flames as it has.
std::size_t roughFlameCount(const std::string& text) {
  static const std::regex flameTag("<flame[\\s>]");
  const auto begin = std::sregex_iterator(text.begin(), text.end(), flameTag);
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::distance(begin, std::sregex_iterator())));
}

// Whether an import warning says something of the file was not kept (as opposed to a value held
// inside voxflame's range, a stand-in for a broken or missing value, or a note on the XML). A flame
// counts as whole only when none of its warnings says so, whatever ImportedFlame::leftOut holds: a
// loss the importer forgot to list still counts.
bool namesALoss(const std::string& warning) {
  static const char* const kLossWords[] = {"left out", "does not support", "not supported", "skipped",
                                           "dropped",  "ignored",          "does not have", "not kept",
                                           "lost",     "partly",           "only the first"};
  return std::any_of(std::begin(kLossWords), std::end(kLossWords),
                     [&](const char* word) { return warning.find(word) != std::string::npos; });
}

struct Tally {
  std::size_t whole = 0, lost = 0, refused = 0;
  std::vector<std::string> unlisted;              // "file #index: warning" for a loss that leftOut does not name
  std::map<std::string, std::size_t> lostThings;  // what → in how many flames
  std::map<std::string, std::size_t> refusals;    // file: reason → flames
  std::vector<std::string> partial;               // "file #index: what it lost", in corpus order
  std::size_t total() const { return whole + lost + refused; }
};

void runLayerBriefly(const PatternLayer& layer, const std::string& file) {
  const ChaosGame game(layer, file);
  constexpr std::size_t kLanes = 64;
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(7);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> x(kLanes), y(kLanes), z(kLanes), color(kLanes);
  for (int step = 0; step < 40; ++step) {
    game.step(lanes, x.data(), y.data(), z.data(), color.data(), kLanes);
    for (std::size_t i = 0; i < kLanes; ++i) {
      if (std::isnan(x[i])) {
        game.seedLane(lanes, i, rng);
        continue;
      }
      if (!std::isfinite(y[i]) || !std::isfinite(z[i]) || !(color[i] >= 0.0 && color[i] <= 1.0))
        throw Error(file + ": the chaos game made a point that is neither finite nor marked as escaped");
    }
  }
}

// An imported flame must also run: a short chaos game on each of its layers, whose points are
// finite or marked as escaped (NaN), never anything else.
void runBriefly(const ImportedFlame& flame, const std::string& file) {
  Scene base;
  base.meshPath = "mesh.obj";
  const Scene scene = sceneFromImportedFlame(flame, base);
  for (const PatternLayer& layer : scene.layers) runLayerBriefly(layer, file);
}

void importFile(const std::filesystem::path& path, Tally& tally) {
  const std::string text = readText(path);
  const std::string file = path.filename().string();
  std::size_t count = 0;
  try {
    count = readFlameXml(text, file).names.size();
  } catch (const Error&) {
    // The first flame may be refused on its own: find the count without importing it.
    FlameImportOptions probe;
    probe.index = 1u << 30;
    try {
      readFlameXml(text, file, probe);
    } catch (const Error& e) {
      const std::string message = e.what();
      const auto holds = message.find(" holds ");
      if (holds != std::string::npos && message.find("there is no flame") != std::string::npos)
        count = std::stoul(message.substr(holds + 7));
      else {
        const std::size_t flames = roughFlameCount(text);
        tally.refused += flames;
        tally.refusals[message.substr(0, 200)] += flames;
        return;
      }
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    FlameImportOptions options;
    options.index = i;
    try {
      const FlameFileContents contents = readFlameXml(text, file, options);
      runBriefly(contents.flame, file);
      const auto& warnings = contents.flame.warnings;
      const bool warnedOfALoss = std::any_of(warnings.begin(), warnings.end(), namesALoss);
      if (warnedOfALoss && contents.flame.leftOut.empty())
        for (const std::string& warning : warnings)
          if (namesALoss(warning)) tally.unlisted.push_back(file + " #" + std::to_string(i) + ": " + warning);
      if (contents.flame.leftOut.empty() && !warnedOfALoss) {
        ++tally.whole;
      } else {
        ++tally.lost;
        std::string line = file + " #" + std::to_string(i) + ":";
        if (contents.flame.leftOut.empty()) ++tally.lostThings["(a loss only a warning names)"];
        for (const std::string& thing : contents.flame.leftOut) {
          ++tally.lostThings[thing];
          line += " " + thing + ";";
        }
        line.pop_back();
        tally.partial.push_back(std::move(line));
      }
    } catch (const Error& e) {
      ++tally.refused;
      ++tally.refusals[std::string(e.what()).substr(0, 200)];
    }
  }
}

TEST(FlameCorpus, TallyOfEveryFlameInTheSharedCorpus) {
  ASSERT_TRUE(std::filesystem::is_directory(kCorpus)) << kCorpus << " is missing";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kCorpus))
    if (isFlameFilePath(entry.path())) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  Tally tally;
  for (const auto& path : files) importFile(path, tally);

  std::vector<std::pair<std::size_t, std::string>> lostByCount;
  for (const auto& [thing, flames] : tally.lostThings) lostByCount.emplace_back(flames, thing);
  std::sort(lostByCount.begin(), lostByCount.end(),
            [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  const double share = static_cast<double>(tally.whole) / static_cast<double>(tally.total());
  std::printf(
      "flame corpus: %zu files, %zu flames: %zu imported whole (%.1f%%; goal %.0f%%), %zu lost something, "
      "%zu refused\n",
      files.size(), tally.total(), tally.whole, 100.0 * share, 100.0 * kWholeShareGoal, tally.lost, tally.refused);
  std::printf("lost (in how many flames):\n");
  for (const auto& [flames, thing] : lostByCount) std::printf("  %4zu  %s\n", flames, thing.c_str());
  std::printf("flames that lost something:\n");
  for (const std::string& line : tally.partial) std::printf("  %s\n", line.c_str());
  std::printf("refused:\n");
  for (const auto& [reason, flames] : tally.refusals) std::printf("  %4zu  %s\n", flames, reason.c_str());

  std::printf("losses a warning names that leftOut does not:\n");
  for (const std::string& line : tally.unlisted) std::printf("  %s\n", line.c_str());

  EXPECT_TRUE(tally.unlisted.empty()) << "an import warns of a loss without listing it in leftOut";
  EXPECT_GE(share, kWholeShareThreshold) << "fewer flames import whole than before";
  EXPECT_LE(tally.refused, kRefusedLimit) << "more flames are refused than before";
}

}  // namespace
