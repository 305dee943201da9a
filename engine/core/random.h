// Small, fast, seedable random numbers (SplitMix64) so that a seed reproduces a render exactly
// on every platform; std::mt19937 distributions differ between standard libraries.
#pragma once

#include <cstdint>

namespace voxflame::core {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double symmetric() { return 2.0 * uniform() - 1.0; }                        // [-1, 1)

 private:
  std::uint64_t state_;
};

inline std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b) {
  return SplitMix64(a * 0x9e3779b97f4a7c15ULL ^ (b + 0x632be59bd9b4e019ULL)).next();
}

}  // namespace voxflame::core
