// `voxflame list`, `voxflame info` and `voxflame search`: the attractor and flame-variation
// catalogues, the chaos diagnostics of one parameter set, and the chaos search, from the command
// line. A flame or quaternion Julia preset gets the fill test and the search of flame/search.h instead.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/attractor.h"
#include "core/file_output.h"
#include "core/flame/search.h"
#include "core/flame/variations.h"
#include "core/lyapunov.h"
#include "core/scene.h"
#include "usage_error.h"

namespace voxflame::app {

namespace {

using nlohmann::json;

json paramsJson(const core::AttractorInfo& info, const std::vector<double>& values) {
  json params = json::object();
  for (std::size_t i = 0; i < info.params.size() && i < values.size(); ++i) params[info.params[i].name] = values[i];
  return params;
}

json lyapunovJson(const core::OrbitAnalysis& analysis) {
  // Non-finite exponents cannot occur for a bounded orbit; an escaped one reports nulls.
  json exponents = json::array();
  for (double value : analysis.lyapunov) exponents.push_back(analysis.bounded ? json(value) : json(nullptr));
  return exponents;
}

double parseNumber(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value))
    throw UsageError(what + " expects a finite number, not '" + text + "'");
  return value;
}

// The parameter set a command works on (OrbitArguments).
core::OrbitSpec specFromArguments(const OrbitArguments& arguments) {
  core::OrbitSpec spec;
  if (arguments.attractor) {
    spec = core::defaultOrbitSpec(core::attractorOrThrow(*arguments.attractor));
  } else if (arguments.preset) {
    const core::Scene scene = sceneFromArgument(arguments.preset);
    spec = core::orbitSpecOf(scene.layers.front());
  } else {
    throw UsageError("name a preset or an attractor (--attractor ID; `voxflame list` shows them)");
  }
  const core::AttractorInfo& info = *spec.info;
  if (arguments.set) {
    const core::NamedParams* set = info.alternative(*arguments.set);
    if (!set) {
      std::string known;
      for (const auto& s : info.alternatives) known += (known.empty() ? "" : ", ") + s.name;
      throw UsageError("attractor '" + info.id + "' has no parameter set '" + *arguments.set + "'" +
                       (known.empty() ? std::string(" (it has none)") : " (it has: " + known + ")"));
    }
    spec.params = set->values;
    spec.start = set->start;
  }
  for (const std::string& assignment : arguments.params) {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos) throw UsageError("--param expects NAME=VALUE, not '" + assignment + "'");
    const std::string name = assignment.substr(0, equals);
    const int index = info.paramIndex(name);
    if (index < 0) {
      std::string known;
      for (const auto& p : info.params) known += (known.empty() ? "" : ", ") + p.name;
      throw UsageError("attractor '" + info.id + "' has no parameter '" + name + "' (it has: " + known + ")");
    }
    spec.params[static_cast<std::size_t>(index)] = parseNumber(assignment.substr(equals + 1), "--param " + name);
  }
  if (arguments.integrator) spec.integrator = *arguments.integrator;
  if (arguments.step) spec.step = *arguments.step;
  core::validateOrbitSpec(spec);
  return spec;
}

std::string formatParams(const core::AttractorInfo& info, const std::vector<double>& values) {
  std::ostringstream out;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << info.params[i].name << "=" << values[i];
  return out.str();
}

// `text` padded with spaces to `columns` characters as a terminal shows them: printf's %-32s
// counts bytes, so names with letters outside ASCII (Lü–Chen, Rössler, Nosé–Hoover) came out
// short by their extra UTF-8 bytes and pushed the next column left.
std::string padToColumns(const std::string& text, std::size_t columns) {
  std::size_t shown = 0;
  for (const char c : text)
    if ((static_cast<unsigned char>(c) & 0xC0u) != 0x80u) ++shown;  // continuation bytes take no column
  return text + std::string(columns > shown ? columns - shown : 1, ' ');
}

// A preset whose first layer is a flame or a quaternion Julia set, or nothing (no preset named,
// --attractor given, or an attractor preset): the attractor path handles those.
std::optional<core::Scene> chaosPreset(const OrbitArguments& arguments) {
  if (!arguments.preset) return std::nullopt;
  core::Scene scene = sceneFromArgument(arguments.preset);
  if (scene.layers.empty() || !scene.layers.front().isChaosGame()) return std::nullopt;
  const std::pair<const char*, bool> attractorOptions[] = {{"--attractor", arguments.attractor.has_value()},
                                                           {"--set", arguments.set.has_value()},
                                                           {"--integrator", arguments.integrator.has_value()},
                                                           {"--step", arguments.step.has_value()},
                                                           {"--param", !arguments.params.empty()}};
  for (const auto& [option, given] : attractorOptions)
    if (given)
      throw UsageError(std::string(option) + " applies to attractors; the first layer of '" + *arguments.preset +
                       "' is a " + scene.layers.front().patternName());
  return scene;
}

json fillJson(const core::FillReport& fill) {
  return {{"passes", fill.passes},
          {"score", fill.score},
          {"occupancy", fill.occupancy},
          {"extent_ratio", fill.extentRatio},
          {"escaped_fraction", fill.badFraction},
          {"box", {{"low", {fill.low.x, fill.low.y, fill.low.z}}, {"high", {fill.high.x, fill.high.y, fill.high.z}}}}};
}

// The layer as the preset writes it ("flame" or "julia" block), so a result pastes into a preset.
json patternJson(const core::Scene& scene, const core::PatternLayer& layer) {
  core::Scene one = scene;
  one.layers = {layer};
  one.keyframes.clear();
  const json document = core::sceneToDocument(one, false);
  const json& written = document.at("layers").at(0);
  return layer.kind == core::PatternKind::Flame ? written.at("flame") : written.at("julia");
}

std::string describeFlame(const core::FlameGenome& genome) {
  std::string text = std::to_string(genome.xforms.size()) + " transforms:";
  const auto terms = [](const core::FlameXform& x) {
    std::string names;
    for (const auto& term : x.variations) names += (names.empty() ? "" : "+") + term.name;
    return names.empty() ? std::string("linear") : names;
  };
  for (std::size_t i = 0; i < genome.xforms.size(); ++i) text += (i ? " | " : " ") + terms(genome.xforms[i]);
  if (genome.hasFinal) text += " | final " + terms(genome.finalXform);
  if (genome.symmetry.rotational > 1) text += "  symmetry " + std::to_string(genome.symmetry.rotational);
  if (genome.symmetry.mirror) text += " mirrored";
  return text;
}

std::string describeJulia(const core::QuaternionJuliaSettings& julia) {
  char text[128];
  std::snprintf(text, sizeof text, "c = (%.4f, %.4f, %.4f, %.4f)", julia.c.x, julia.c.y, julia.c.z, julia.c.w);
  return text;
}

std::string describeFill(const core::FillReport& fill) {
  char text[160];
  std::snprintf(text, sizeof text, "fills %.1f%% of its box, thinnest side %.2f of the longest, %.2f%% escaped",
                100.0 * fill.occupancy, fill.extentRatio, 100.0 * fill.badFraction);
  return text;
}

int chaosInfo(const core::Scene& scene, bool asJson) {
  const core::PatternLayer& layer = scene.layers.front();
  const core::FillReport fill = core::measureFill(layer, scene.seed);
  if (asJson) {
    std::cout << json({{"kind", std::string(core::toString(layer.kind))}, {"fill", fillJson(fill)}}).dump() << "\n";
    return 0;
  }
  std::printf(
      "%s: %s\n", layer.patternName().c_str(),
      layer.kind == core::PatternKind::Flame ? describeFlame(layer.flame).c_str() : describeJulia(layer.julia).c_str());
  std::printf("%s; %s\n", fill.passes ? "fills a volume" : fill.reason.c_str(), describeFill(fill).c_str());
  return 0;
}

int chaosSearch(core::Scene scene, const core::FlameSearchOptions& options, bool fresh, bool asJson,
                const std::optional<std::string>& output) {
  core::PatternLayer base = scene.layers.front();
  std::vector<core::PatternLayer> found;
  std::vector<core::FillReport> fills;
  if (base.kind == core::PatternKind::Flame) {
    for (const auto& c : core::searchFlames(fresh ? std::nullopt : std::optional(base.flame), options)) {
      found.push_back(base);
      found.back().flame = c.genome;
      fills.push_back(c.fill);
    }
  } else {
    core::FlameSearchOptions juliaOptions = options;
    juliaOptions.juliaView = base.julia;
    for (const auto& c : core::searchQuaternionJulia(fresh ? std::nullopt : std::optional(base.julia), juliaOptions)) {
      found.push_back(base);
      found.back().julia = c.julia;
      fills.push_back(c.fill);
    }
  }
  json list = json::array();
  for (std::size_t i = 0; i < found.size(); ++i) {
    if (asJson) {
      json entry = {{"kind", std::string(core::toString(found[i].kind))}, {"fill", fillJson(fills[i])}};
      entry[found[i].kind == core::PatternKind::Flame ? "flame" : "julia"] = patternJson(scene, found[i]);
      list.push_back(entry);
      continue;
    }
    std::printf("%zu. score %.3f  %s\n   %s\n", i + 1, fills[i].score, describeFill(fills[i]).c_str(),
                found[i].kind == core::PatternKind::Flame ? describeFlame(found[i].flame).c_str()
                                                          : describeJulia(found[i].julia).c_str());
  }
  if (asJson) std::cout << list.dump(2) << "\n";
  if (output && !found.empty()) {
    scene.layers.front() = found.front();
    // The written preset finds its mesh from wherever it is written.
    if (!scene.embedded)
      scene.meshPath = std::filesystem::absolute(scene.resolvedMeshPath()).lexically_normal().string();
    core::writeFileAtomically(*output, core::sceneToJson(scene),
                              {.mode = 0644, .createFolder = true, .what = "cannot write preset"});
    if (!asJson) std::printf("wrote the best as %s\n", output->c_str());
  }
  if (static_cast<int>(found.size()) < options.count) {
    std::cerr << "voxflame: found " << found.size() << " of " << options.count << " " << base.patternName()
              << (fresh ? " patterns" : " patterns near this one") << " that fill their box; try another --seed"
              << (fresh ? "" : " or a smaller --strength") << "\n";
    return found.empty() ? 1 : 0;
  }
  return 0;
}

// `voxflame list --variations`: the flame variation catalogue as text, JSON or Markdown (the last
// is presets/VARIATIONS.md).
int listVariations(bool asJson, bool asMarkdown) {
  if (asMarkdown) {
    std::cout << core::variationsMarkdown();
    return 0;
  }
  if (asJson) {
    json list = json::array();
    for (const auto& info : core::variationCatalogue()) {
      json params = json::array();
      for (const auto& p : info.params)
        params.push_back({{"name", p.name},
                          {"default", p.defaultValue},
                          {"min", p.sliderMin},
                          {"max", p.sliderMax},
                          {"integer", p.integer}});
      list.push_back({{"name", info.name},
                      {"dimensions", info.threeD ? "3D" : "2D"},
                      {"random", info.random},
                      {"parameters", params},
                      {"formula", info.formula}});
    }
    std::cout << list.dump(2) << "\n";
    return 0;
  }
  std::cout << padToColumns("NAME", 15) << padToColumns("KIND", 11) << "PARAMETERS (defaults)\n"
            << padToColumns("", 15) << padToColumns("", 11) << "FORMULA\n";
  for (const auto& info : core::variationCatalogue()) {
    std::string params;
    for (const auto& p : info.params) {
      std::ostringstream value;
      value << p.defaultValue;
      params += (params.empty() ? "" : " ") + p.name + "=" + value.str();
    }
    std::cout << padToColumns(info.name, 15)
              << padToColumns(std::string(info.threeD ? "3D" : "2D") + (info.random ? " random" : ""), 11)
              << (params.empty() ? "-" : params) << "\n"
              << padToColumns("", 15) << padToColumns("", 11) << info.formula << "\n";
  }
  return 0;
}

}  // namespace

int listCommand(const ListArguments& arguments) {
  const bool asJson = arguments.json;
  const bool variations = arguments.variations;
  const bool asMarkdown = arguments.markdown;
  if (asMarkdown && !variations) throw UsageError("--markdown lists the variations: use list --variations --markdown");
  if (asMarkdown && asJson) throw UsageError("choose one of --json and --markdown");
  if (variations) return listVariations(asJson, asMarkdown);
  if (asJson) {
    json list = json::array();
    for (const auto& info : core::attractorCatalogue()) {
      json params = json::array();
      for (const auto& p : info.params)
        params.push_back({{"name", p.name}, {"default", p.defaultValue}, {"min", p.sliderMin}, {"max", p.sliderMax}});
      json alternatives = json::array();
      for (const auto& set : info.alternatives)
        alternatives.push_back({{"name", set.name}, {"params", paramsJson(info, set.values)}, {"note", set.note}});
      json entry = {{"id", info.id},
                    {"name", info.name},
                    {"kind", std::string(core::toString(info.kind))},
                    {"parameters", params},
                    {"integrator", std::string(core::toString(info.defaultIntegrator))},
                    {"start", {info.start.x, info.start.y, info.start.z}},
                    {"equations", info.equations},
                    {"citation", info.citation},
                    {"alternatives", alternatives}};
      if (info.kind == core::AttractorKind::Flow) entry["step"] = info.defaultStep;
      if (!info.note.empty()) entry["note"] = info.note;
      list.push_back(entry);
    }
    std::cout << list.dump(2) << "\n";
    return 0;
  }
  std::cout << padToColumns("ID", 23) << padToColumns("KIND", 6) << padToColumns("NAME", 33)
            << "PARAMETERS (defaults)\n";
  for (const auto& info : core::attractorCatalogue())
    std::cout << padToColumns(info.id, 23) << padToColumns(std::string(core::toString(info.kind)), 6)
              << padToColumns(info.name, 33) << formatParams(info, info.defaultParams()) << "\n";
  return 0;
}

int infoCommand(const OrbitArguments& arguments) {
  const bool asJson = arguments.json;
  if (const auto scene = chaosPreset(arguments)) return chaosInfo(*scene, asJson);
  const core::OrbitSpec spec = specFromArguments(arguments);
  const core::AttractorInfo& info = *spec.info;
  const core::OrbitAnalysis analysis = core::analyseOrbit(spec);
  if (asJson) {
    json out = {{"attractor", info.id},
                {"kind", std::string(core::toString(info.kind))},
                {"params", paramsJson(info, spec.params)},
                {"integrator", std::string(core::toString(spec.integrator))},
                {"start", {spec.start.x, spec.start.y, spec.start.z}},
                {"bounded", analysis.bounded},
                {"lyapunov", lyapunovJson(analysis)},
                {"lyapunov_units", info.kind == core::AttractorKind::Flow ? "per unit time" : "per iteration"},
                {"verdict", std::string(core::toString(analysis.verdict))},
                {"steps", analysis.stepsTaken}};
    if (info.kind == core::AttractorKind::Flow) out["step"] = spec.step;
    if (analysis.bounded) {
      out["kaplan_yorke_dimension"] = analysis.kaplanYorkeDimension;
      out["box"] = {{"low", {analysis.low.x, analysis.low.y, analysis.low.z}},
                    {"high", {analysis.high.x, analysis.high.y, analysis.high.z}}};
    }
    std::cout << out.dump() << "\n";
    return 0;
  }
  std::printf("%s (%s): %s\n", info.name.c_str(), info.id.c_str(), formatParams(info, spec.params).c_str());
  if (info.kind == core::AttractorKind::Flow)
    std::printf("integrator %s, step %g\n", std::string(core::toString(spec.integrator)).c_str(), spec.step);
  if (!analysis.bounded) {
    std::printf("escapes: the orbit left every bound after %d steps\n", analysis.stepsTaken);
    return 0;
  }
  std::printf("bounded, %s; Lyapunov exponents %.5g %.5g %.5g (%s); Kaplan-Yorke dimension %.3f\n",
              std::string(core::toString(analysis.verdict)).c_str(), analysis.lyapunov[0], analysis.lyapunov[1],
              analysis.lyapunov[2], info.kind == core::AttractorKind::Flow ? "per unit time" : "per iteration",
              analysis.kaplanYorkeDimension);
  return 0;
}

int searchCommand(const SearchArguments& arguments) {
  const bool asJson = arguments.orbit.json;
  core::SearchOptions options;
  options.seed = arguments.seed;
  options.count = arguments.count;
  options.strength = arguments.strength;
  const bool fresh = arguments.random;
  const std::optional<std::string>& output = arguments.output;
  if (auto scene = chaosPreset(arguments.orbit)) {
    core::FlameSearchOptions flameOptions;
    flameOptions.seed = options.seed;
    flameOptions.count = options.count;
    flameOptions.strength = options.strength;
    flameOptions.maxCandidates = std::max(flameOptions.maxCandidates, 40 * options.count);
    return chaosSearch(std::move(*scene), flameOptions, fresh, asJson, output);
  }
  if (fresh || output)
    throw UsageError(std::string(fresh ? "--random" : "-o") + " applies to flame and quaternion Julia presets");
  const core::OrbitSpec spec = specFromArguments(arguments.orbit);
  const core::AttractorInfo& info = *spec.info;
  const auto found = core::searchChaos(spec, options);
  json list = json::array();
  for (std::size_t i = 0; i < found.size(); ++i) {
    const auto& result = found[i];
    if (asJson) {
      json entry = {{"attractor", info.id},
                    {"params", paramsJson(info, result.params)},
                    {"start", {result.start.x, result.start.y, result.start.z}},
                    {"lyapunov", lyapunovJson(result.analysis)},
                    {"kaplan_yorke_dimension", result.analysis.kaplanYorkeDimension}};
      if (info.id == "sprott_quadratic") entry["code"] = core::paramsToSprottCode(result.params);
      list.push_back(entry);
      continue;
    }
    std::printf("%zu. %s  lyapunov %.4g %.4g %.4g  dimension %.2f  start (%g, %g, %g)\n", i + 1,
                formatParams(info, result.params).c_str(), result.analysis.lyapunov[0], result.analysis.lyapunov[1],
                result.analysis.lyapunov[2], result.analysis.kaplanYorkeDimension, result.start.x, result.start.y,
                result.start.z);
    if (info.id == "sprott_quadratic") std::printf("   code %s\n", core::paramsToSprottCode(result.params).c_str());
  }
  if (asJson) std::cout << list.dump(2) << "\n";
  if (static_cast<int>(found.size()) < options.count) {
    std::cerr << "voxflame: found " << found.size() << " of " << options.count
              << " chaotic sets near these parameters; try another --seed or a larger --strength\n";
    return found.empty() ? 1 : 0;
  }
  return 0;
}

}  // namespace voxflame::app
