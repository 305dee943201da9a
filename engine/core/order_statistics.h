// Exact order statistics of large arrays: the value std::nth_element would put at an index, for
// several indices at once and without reordering the input. The probe of every pattern edit takes
// a dozen percentiles of 10⁵ samples (the attractor's robust box, its colour references), and
// nth_element over the whole array each time was most of the probe's cost: tens of milliseconds
// of every frame of a slider drag.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace voxflame::core {

// For each fraction f, the element at index ⌊f·(n − 1)⌋ of `values` sorted. `values` must be
// non-empty and hold no NaN. A sorted subsample brackets each rank, one branch-light pass counts
// the values below the bracket and gathers those inside it, and only those few are selected from;
// a bracket that misses its rank (a freak subsample) falls back to selecting from the whole array,
// so the answer is always exact.
template <std::size_t N>
std::array<double, N> percentiles(const std::vector<double>& values, const std::array<double, N>& fractions) {
  std::array<double, N> result{};
  const std::size_t n = values.size();
  constexpr std::size_t kSubsample = 1024;
  std::vector<double> scratch;
  auto select = [&](const std::vector<double>& from, std::size_t index) {
    scratch.assign(from.begin(), from.end());
    std::nth_element(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(index), scratch.end());
    return scratch[index];
  };
  auto rankOf = [n](double fraction) { return static_cast<std::size_t>(fraction * static_cast<double>(n - 1)); };
  if (n < 8 * kSubsample) {
    for (std::size_t f = 0; f < N; ++f) result[f] = select(values, rankOf(fractions[f]));
    return result;
  }
  std::vector<double> subsample(kSubsample);
  for (std::size_t i = 0; i < kSubsample; ++i) subsample[i] = values[i * n / kSubsample];
  std::sort(subsample.begin(), subsample.end());
  // The subsample entry at a rank's position is one standard deviation of at most
  // sqrt(kSubsample)/2 = 16 entries away from where that rank really falls; ±64 entries of margin
  // miss about once in 10⁴ brackets, and a miss only costs the fallback.
  constexpr std::ptrdiff_t kMargin = 64;
  std::vector<double> inside;
  for (std::size_t f = 0; f < N; ++f) {
    const std::size_t rank = rankOf(fractions[f]);
    const auto centre = static_cast<std::ptrdiff_t>(static_cast<double>(rank) / static_cast<double>(n) * kSubsample);
    const std::ptrdiff_t lowEntry = centre - kMargin, highEntry = centre + kMargin;
    const double low =
        lowEntry >= 0 ? subsample[static_cast<std::size_t>(lowEntry)] : -std::numeric_limits<double>::infinity();
    const double high = highEntry < static_cast<std::ptrdiff_t>(kSubsample)
                            ? subsample[static_cast<std::size_t>(highEntry)]
                            : std::numeric_limits<double>::infinity();
    std::size_t below = 0;
    inside.clear();
    for (const double value : values) {
      below += value < low ? 1 : 0;
      if (value >= low && value <= high) inside.push_back(value);
    }
    // In sorted order the values below the bracket come first, then exactly those inside it.
    if (below <= rank && rank < below + inside.size()) {
      const auto at = inside.begin() + static_cast<std::ptrdiff_t>(rank - below);
      std::nth_element(inside.begin(), at, inside.end());
      result[f] = *at;
    } else {
      result[f] = select(values, rank);
    }
  }
  return result;
}

}  // namespace voxflame::core
