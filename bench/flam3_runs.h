// What `bench flame` and `bench fidelity` share to run Debian's flam3-render on flame files: the
// corpus beside the repository, one <flame> of a file as its own document, and one timed run.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace voxflame::bench {

// The real flame files beside the repository ($VOXFLAME_FLAMES when set), sorted by name; empty
// when the folder is not there.
std::vector<std::filesystem::path> corpusFlameFiles();

std::string fileBytes(const std::filesystem::path& path);

// The `index`-th <flame> element of a flame file (0-based) as a document of its own:
// flam3-render renders every flame of a file. Nothing when the file has fewer flames, or that one
// has no transforms.
std::optional<std::string> flameXmlAt(const std::filesystem::path& path, std::size_t index);

// A number as flam3-render reads it back exactly (std::to_string keeps 6 decimals).
std::string exactNumber(double value);

struct Flam3Run {
  bool ok = false;    // it exited with 0 and wrote `out`
  double wall = 0.0;  // seconds
  double cpu = 0.0;   // CPU seconds of the child, all its threads
  // Variations it did not know and skipped ("unrecognized variation"), leaving out the ones that
  // draw nothing in its 2D render: a transform's name attribute, Apophysis' var_color, flatten.
  // With any left, it rendered another flame than the file's.
  std::vector<std::string> skippedVariations;
};

// Runs flam3-render on `genome` writing the PNG `out`, with its size scale (ss), quality scale
// (qs), seed and thread count; arguments reach it through the environment, set by env without a
// shell. Its messages are collected, not printed.
Flam3Run runFlam3(const std::filesystem::path& genome, const std::filesystem::path& out, double sizeScale,
                  double qualityScale, int seed, int threads);

}  // namespace voxflame::bench
