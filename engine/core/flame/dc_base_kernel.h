// What JWildfire's DC_BaseFunc variations share (Jesus Sosa's shader-like direct-colour variations:
// dc_quadtree, dc_ducks, dc_inversion, dc_portal, dc_menger, dc_tesla in variations_jwildfire_holdout.cpp,
// dc_warping in variations_jwildfire_rare.cpp): the point they draw, the colour and z. Internal to
// those files.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/flame/variation_kernels.h"

namespace voxflame::core::variation_kernels {

// JWildfire's Tools.limitValue followed by a cast to int, as its setParameter does for its counts:
// clamped into [low, high], then truncated; a NaN (which limitValue passes through and Java's (int)
// makes 0) is taken as low, so no count is ever 0 where JWildfire would divide or index by it.
inline double jwfLimitedInt(double value, double low, double high) {
  return std::isnan(value) ? low : std::trunc(std::clamp(value, low, high));
}

// Jesus Sosa's shader-like direct-colour variations (DC_BaseFunc): a random point of a square (or with
// ColorOnly the point itself) and an RGB colour from a pattern at it. Gradient 0 paints the point that
// RGB colour (R, G, B = ⌊256 c⌋ clamped into 0 … 255) and 1 the palette's entry nearest to it
// (VariationInput::rgb, JWildfire's XYZPoint.rgbColor), both leaving the colour index alone; Gradient 2
// sets the index to the colour's grey level ⌊0.299 R⌋ + ⌊0.587 G⌋ + ⌊0.114 B⌋ over 255, which z uses in
// every case: dz = grey · scale_z + offset_z is added to z, or with reset_z replaces the sum's z.
struct Rgb {
  double r, g, b;
};

inline double greyLevel(const Rgb& c) {
  return (std::trunc(rgbByte(c.r) * 0.299) + std::trunc(rgbByte(c.g) * 0.587) + std::trunc(rgbByte(c.b) * 0.114)) /
         255.0;
}

// The common tail of the DC_BaseFunc kernels: the point (half-width `half` of the square, or the point
// itself), the colour and z. P[k …] are ColorOnly, Gradient, scale_z, offset_z, reset_z.
template <typename Pattern>
void dcBaseKernel(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz,
                  std::size_t k, double half, Pattern&& pattern) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const bool colourOnly = jwfLimitedInt(P[k], 0.0, 1.0) == 1.0;
  const double gradient = jwfLimitedInt(P[k + 1], 0.0, 2.0);
  const bool grey = gradient == 2.0;
  std::uint32_t* __restrict rgb = grey ? nullptr : in.rgb;
  const std::uint32_t* palette = gradient == 1.0 ? in.palette : nullptr;
  const double scaleZ = P[k + 2], offsetZ = P[k + 3];
  const bool reset = jwfLimitedInt(P[k + 4], 0.0, 1.0) == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    double u, v;
    if (colourOnly) {
      u = x[i], v = y[i];
    } else {
      u = half * (2.0 * laneUniform(rnd[i]) - 1.0);
      v = half * (2.0 * laneUniform(rnd[i]) - 1.0);
    }
    const Rgb c = pattern(u, v);
    const double level = greyLevel(c);
    if (grey) colour[i] = level;
    if (rgb) {
      const auto r = static_cast<std::uint32_t>(rgbByte(c.r)), g = static_cast<std::uint32_t>(rgbByte(c.g)),
                 b = static_cast<std::uint32_t>(rgbByte(c.b));
      // Gradient 1 without a palette at hand (a single evaluation) paints nothing, as one without rgb.
      rgb[i] = !palette ? (gradient == 0.0 ? paintedRgb(r, g, b) : 0u)
                        : kRgbPainted | palette[nearestPaletteEntry(palette, r, g, b)];
    }
    outX[i] += w * u;
    outY[i] += w * v;
    const double dz = level * scaleZ + offsetZ;
    outZ[i] = reset ? dz : outZ[i] + w * z[i] + dz;
  }
}

}  // namespace voxflame::core::variation_kernels
