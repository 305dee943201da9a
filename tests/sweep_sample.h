// Sweeps over a whole catalogue in a sanitizer build: every kSweepStride-th entry.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace voxflame::test {

// Whether this program is built with AddressSanitizer or ThreadSanitizer (GCC's macros; UBSan comes
// only with ASan here). There our code runs several times slower, while what the GL tests spend in
// llvmpipe (its LLVM compiles of our shaders) does not change.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// The suites that sweep a whole catalogue (every variation on the GPU, every shipped preset on both
// backends) check every kSweepStride-th entry in a sanitizer build: each kind of entry still runs
// instrumented through the same code, and the Release suite checks them all.
inline constexpr std::size_t kSweepStride = kSanitized ? 4 : 1;

// Every kSweepStride-th of `all`, the first included.
template <class T>
std::vector<T> sweepSample(std::vector<T> all) {
  if (kSweepStride == 1) return all;
  std::vector<T> kept;
  for (std::size_t i = 0; i < all.size(); i += kSweepStride) kept.push_back(std::move(all[i]));
  return kept;
}

}  // namespace voxflame::test
