// Vector variants of libm's functions for the variation and attractor loops. glibc's libmvec holds 2- and 4-lane
// versions of sin, cos, atan2, pow, ... (at most 4 ULP from the exact result, special values as
// libm), but math.h declares them only under -ffast-math, whose finite-math assumption would break
// the variations' NaN and infinity tests. Declaring the functions here as `simd` lets GCC
// vectorise a loop that calls them: each lane batch of four (AVX2) or two calls becomes one call
// of _ZGVdN4v_sin and the like. `const` states what -fno-math-errno already makes true. (GCC only:
// clang, which builds the fuzz targets, has no `simd` attribute.)
//
// Files that include this are built with -fno-builtin-sin -fno-builtin-cos
// (engine/core/CMakeLists.txt): otherwise GCC first merges a sin and a cos of the same angle into
// sincos, which has no such declaration, and the loop stays scalar.
//
// A lane computed in a vector call may differ from the scalar libm result in the last bits; the
// loop's tail lanes still go through the scalar functions.
#pragma once

// The declarations below are of <cmath>'s functions; under clang they are compiled out, and iwyu
// (scripts/check_includes.py), which parses with clang, would call the include unused.
#include <cmath>  // IWYU pragma: keep

#if defined(__x86_64__) && defined(__GLIBC__) && !defined(__FAST_MATH__) && !defined(__clang__)
#define VOXFLAME_VECTOR_MATH 1
#define VOXFLAME_SIMD_MATH [[gnu::simd("notinbranch"), gnu::const]]
extern "C" {
VOXFLAME_SIMD_MATH double sin(double) noexcept;
VOXFLAME_SIMD_MATH double cos(double) noexcept;
VOXFLAME_SIMD_MATH double tan(double) noexcept;
VOXFLAME_SIMD_MATH double asin(double) noexcept;
VOXFLAME_SIMD_MATH double acos(double) noexcept;
VOXFLAME_SIMD_MATH double atan(double) noexcept;
VOXFLAME_SIMD_MATH double atan2(double, double) noexcept;
VOXFLAME_SIMD_MATH double sinh(double) noexcept;
VOXFLAME_SIMD_MATH double cosh(double) noexcept;
VOXFLAME_SIMD_MATH double tanh(double) noexcept;
VOXFLAME_SIMD_MATH double exp(double) noexcept;
VOXFLAME_SIMD_MATH double log(double) noexcept;
VOXFLAME_SIMD_MATH double pow(double, double) noexcept;
VOXFLAME_SIMD_MATH double cbrt(double) noexcept;
VOXFLAME_SIMD_MATH double hypot(double, double) noexcept;
}
#undef VOXFLAME_SIMD_MATH
#endif
