#include "flam3_runs.h"

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

#include "bench.h"
#include "core/error.h"
#include "core/flame/xml.h"
#include "programs.h"

namespace voxflame::bench {

std::vector<std::filesystem::path> corpusFlameFiles() {
  std::filesystem::path corpus = std::filesystem::path(VOXFLAME_SOURCE_DIR) / "../shared/data/flames";
  if (const char* env = std::getenv("VOXFLAME_FLAMES")) corpus = env;
  std::vector<std::filesystem::path> found;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(corpus, error))
    if (core::isFlameFilePath(entry.path())) found.push_back(entry.path());
  std::sort(found.begin(), found.end());
  return found;
}

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<std::string> flameXmlAt(const std::filesystem::path& path, std::size_t index) {
  const std::string xml = fileBytes(path);
  // "<flame" followed by a space or ">": not the "<flames>" root many files have. Flames do not
  // nest, so the text up to the next </flame> is the element.
  const auto nextFlame = [&](std::size_t from) {
    std::size_t start = xml.find("<flame", from);
    while (start != std::string::npos && start + 6 < xml.size() && xml[start + 6] != '>' &&
           !std::isspace(static_cast<unsigned char>(xml[start + 6])))
      start = xml.find("<flame", start + 6);
    return start;
  };
  std::size_t start = nextFlame(0);
  for (std::size_t skipped = 0; skipped < index && start != std::string::npos; ++skipped) start = nextFlame(start + 6);
  if (start == std::string::npos) return std::nullopt;
  const std::size_t end = xml.find("</flame>", start);
  const std::size_t selfClosing = xml.find("/>", start);
  if (end == std::string::npos) return std::nullopt;
  if (selfClosing != std::string::npos && selfClosing < xml.find('>', start)) return std::nullopt;  // no transforms
  return "<flames>\n" + xml.substr(start, end + 8 - start) + "\n</flames>\n";
}

std::string exactNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

Flam3Run runFlam3(const std::filesystem::path& genome, const std::filesystem::path& out, double sizeScale,
                  double qualityScale, int seed, int threads) {
  Flam3Run run;
  const std::optional<std::string> env = app::findOnPath("env");
  if (!env) return run;
  std::error_code ignored;
  std::filesystem::remove(out, ignored);
  const std::vector<std::string> command = {"env",
                                            "in=" + genome.string(),
                                            "out=" + out.string(),
                                            "format=png",
                                            "ss=" + exactNumber(sizeScale),
                                            "qs=" + exactNumber(qualityScale),
                                            "isaac_seed=" + std::to_string(seed),
                                            "nthreads=" + std::to_string(threads),
                                            "verbose=0",
                                            "flam3-render"};
  const double cpuBefore = cpuSeconds(RUSAGE_CHILDREN);
  const auto start = std::chrono::steady_clock::now();
  std::string messages;
  int status = -1;
  try {
    status = app::runProgram(*env, command, &messages, true);
  } catch (const core::Error&) {
    status = -1;  // a run that failed
  }
  run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.cpu = cpuSeconds(RUSAGE_CHILDREN) - cpuBefore;
  run.ok = status == 0 && std::filesystem::exists(out);
  // flam3's words: "Warning: unrecognized variation NAME.  Ignoring."
  constexpr std::string_view kSkipped = "unrecognized variation ";
  for (std::size_t at = messages.find(kSkipped); at != std::string::npos; at = messages.find(kSkipped, at + 1)) {
    const std::size_t begin = at + kSkipped.size();
    const std::size_t end = messages.find_first_of(". \n", begin);
    const std::string name = messages.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    const bool drawsNothingIn2D = name == "name" || name == "var_color" || name == "flatten";
    // Its parameters (crackle_cellsize) come as unrecognised variations of their own.
    const bool parameterOfOne = std::any_of(run.skippedVariations.begin(), run.skippedVariations.end(),
                                            [&](const std::string& v) { return name.rfind(v + "_", 0) == 0; });
    if (!drawsNothingIn2D && !parameterOfOne &&
        std::find(run.skippedVariations.begin(), run.skippedVariations.end(), name) == run.skippedVariations.end())
      run.skippedVariations.push_back(name);
  }
  return run;
}

}  // namespace voxflame::bench
