// JWildfire's glsl_ variations (glsl_apollonian, glsl_circlesblue, glsl_grid3D, glsl_mandala, glsl_acrilic) draw
// a shader's picture as points: each point is a pixel of a columns × 10⁶ grid drawn at random, placed where
// that pixel lies, and coloured by the shader at the pixel's centre.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/flame/variations.h"

namespace voxflame::core::variation_kernels {

inline constexpr double kGlslPixelRows = 1000000.0;

// The grid's columns from the variation's resolution parameter, as JWildfire's (int) limitValue takes it:
// clamped into [100, 10⁷] and truncated; NaN gives 100.
inline double glslPixelColumns(double resolution) {
  return std::isnan(resolution) ? 100.0 : std::trunc(std::clamp(resolution, 100.0, 10000000.0));
}

// A pixel drawn at random: its column and row.
struct GlslPixel {
  double column, row;
};

// Draws a pixel (column first, as JWildfire does) and adds its point, w (column/columns − ½, row/10⁶ − ½, z).
[[gnu::always_inline]] inline GlslPixel addGlslPixel(std::uint32_t& rnd, double columns, double w, double z,
                                                     double& outX, double& outY, double& outZ) {
  const double column = std::trunc(laneUniform(rnd) * columns), row = std::trunc(laneUniform(rnd) * kGlslPixelRows);
  outX += w * (column / columns - 0.5);
  outY += w * (row / kGlslPixelRows - 0.5);
  outZ += w * z;
  return {column, row};
}

}  // namespace voxflame::core::variation_kernels
