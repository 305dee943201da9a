// What the files of Fractorium's other 2D variations (variations_2d_*.cpp) share: Fractorium's rules
// for the parameter types it declares (a file's value is clamped, wrapped or nudged off 0 when
// Fractorium reads it, so the same file must give the same value here), and the helpers several of
// those variations call. Internal to those files.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/flame/variation_kernels.h"

namespace voxflame::core::variation_kernels {

// Fractorium's REAL parameter with a range: clamped into it (NaN stays NaN).
inline double fractoriumClamp(double value, double low, double high) {
  return std::max(std::min(value, high), low);
}

// REAL_CYCLIC: wrapped into [low, high] the way Fractorium wraps it (fmod from the end it left).
inline double fractoriumCyclic(double value, double low, double high) {
  if (value > high) return low + std::fmod(value - low, high - low);
  if (value < low) return high - std::fmod(high - value, high - low);
  return value;
}

// REAL_NONZERO: clamped, then a value within 10⁻⁶ of 0 becomes ±ε (the double's epsilon).
inline double fractoriumNonzero(double value, double low = -1e300, double high = 1e300) {
  const double v = fractoriumClamp(value, low, high);
  return v > -1e-6 && v < 1e-6 ? kFractoriumEps * signNz(v) : v;
}

// INTEGER_NONZERO: rounded and clamped; 0 becomes ±1 (the sign of the value as given).
inline double fractoriumIntegerNonzero(double value, double low = -2147483647.0, double high = 2147483647.0) {
  const double v = fractoriumInteger(value, low, high);
  return v == 0.0 ? signNz(value) : v;
}

// An INTEGER parameter as an index for a switch: rounded and clamped as Fractorium does, NaN taken as
// the low end (converting it would be undefined behaviour).
inline int wholeIndex(double value, double low, double high) {
  const double v = fractoriumInteger(value, low, high);
  return static_cast<int>(v >= low && v <= high ? v : low);
}

// Whether an integer-valued double is odd (C's `n & 1` without converting, which a NaN or huge
// value would make undefined).
inline bool isOddWhole(double whole) {
  return std::fmod(whole, 2.0) != 0.0;
}

// Fractorium's SafeSqrt: 0 at and below 0.
inline double safeSqrt(double value) {
  return value <= 0.0 ? 0.0 : std::sqrt(value);
}

// The elliptic coordinates of Fractorium's e* variations (eCollide, eMod, ePush, …): half the sum of
// the distances to the foci (±1, 0), √((x + 1)² + y²) and √((x − 1)² + y²), at least 1.
inline double ellipticXmax(double x, double y) {
  const double t = x * x + y * y + 1.0, t2 = 2.0 * x;
  return (safeSqrt(t + t2) + safeSqrt(t - t2)) * 0.5;
}

// The bipolar coordinates of Fractorium's b* variations (bCollide, bMod, bSwirl): τ = ln(d₊/d₋),
// σ = π − atan2(y, x + 1) − atan2(y, 1 − x).
inline double bipolarTau(double x, double y) {
  const double y2 = y * y;
  return 0.5 * (std::log((x + 1.0) * (x + 1.0) + y2) - std::log((x - 1.0) * (x - 1.0) + y2));
}
inline double bipolarSigma(double x, double y) {
  return kPi - std::atan2(y, x + 1.0) - std::atan2(y, 1.0 - x);
}

// Fractorium's HashShadertoy: fract(sin(12.9898 x + 78.233 y + seed) · 43758.5453).
inline double hashShadertoy(double x, double y, double seed) {
  const double v = std::sin(x * 12.9898 + y * 78.233 + seed) * 43758.5453;
  return v - std::floor(v);
}

}  // namespace voxflame::core::variation_kernels
