// Which instruction-set extensions this CPU has, so hot loops built twice (baseline x86-64 and
// AVX2) can pick the faster build at run time while the binary still runs everywhere. Vector
// add, multiply, divide and sqrt round exactly like their scalar forms, and FMA contraction is
// off (-std=c++20 implies -ffp-contract=off), so both builds give bit-identical results.
#pragma once

namespace voxflame::core {

inline bool cpuHasAvx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

}  // namespace voxflame::core
