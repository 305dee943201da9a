// `voxflame bench [NAME] [--json]`: each benchmark measures one part of the pipeline on the shared
// test meshes and prints one line per measurement (a JSON object per line with --json).
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace voxflame::bench {

struct BenchOptions {
  bool json = false;
  std::string meshFolder;       // where bunny.obj, dragon.ply, ... are
  std::string method;           // --method volume|points (export), empty: the benchmark's default
  std::vector<int> grids;       // --grid N...: the grids `explorer` runs at, empty: 192, 256 and 512;
                                // `raymarch` keeps only its cases at these grids
  bool print = false;           // --print: `export` renders the 16K print instead of the 4K stills
  std::string backend = "cpu";  // --backend cpu|gpu: what `accumulate` measures; `explorer`, `rest`, `view`: refine on
  std::vector<std::string> presets;  // `rest`'s presets (files or shipped names), empty: every shipped one;
                                     // `fidelity`'s flame files, empty: its default set
};

struct Benchmark {
  const char* name;
  const char* description;
  void (*run)(const BenchOptions& options);
};
const std::vector<Benchmark>& benchmarks();

// Runs the benchmark named `which`, or all of them when it is empty; returns the exit status.
// The command line (voxflame_cli) only lets through names of benchmarks().
int runBenchmarks(BenchOptions options, const std::string& which);

// CPU seconds (user and system, all threads) of this process (RUSAGE_SELF) or of its finished
// children (RUSAGE_CHILDREN): on a shared machine the wall-clock rate depends on what else runs,
// while a rate per CPU second measures the code itself.
double cpuSeconds(int who);
// The presets named on the command line (a path, or a shipped preset's name with or without
// .json), or every shipped preset.
std::vector<std::filesystem::path> presetsToRun(const BenchOptions& options);

// Prints one measurement: the JSON object as one line with --json, else "key=value" pairs.
void report(const BenchOptions& options, const nlohmann::json& measurement);

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void benchAccumulate(const BenchOptions& options);  // bench_accumulate.cpp
void benchRaymarch(const BenchOptions& options);    // bench_raymarch.cpp
void benchExport(const BenchOptions& options);      // bench_export.cpp
void benchMask(const BenchOptions& options);        // bench_mask.cpp
void benchExplorer(const BenchOptions& options);    // bench_explorer.cpp
void benchQuality(const BenchOptions& options);     // bench_quality.cpp
void benchFlame(const BenchOptions& options);       // bench_flame.cpp
void benchRest(const BenchOptions& options);        // bench_rest.cpp
void benchView(const BenchOptions& options);        // bench_view.cpp
void benchFidelity(const BenchOptions& options);    // bench_fidelity.cpp
void benchSearch(const BenchOptions& options);      // bench_search.cpp

}  // namespace voxflame::bench
