// Fractorium's Truchet tilings and other tile patterns: square tiles of quarter-circle arcs (Truchet_fill,
// Truchet_glyph, Truchet_inv), hexagonal ones (Truchet_hex_fill, Truchet_hex_crop) and turned squares (squares).
// Each is a kernel below and one row of the table at the end (see variations.h for the notation and
// variation_kernels.h for what the files share). They follow Fractorium's formulas (Source/Ember/Variations07.h),
// including where Fractorium leaves the weight out (the square Truchets use it as the tile scale); z is carried as w·z
// (voxflame's rule for 2D variations, where Fractorium writes 0). The ⌊·⌋ are floors, kept as doubles where Fractorium
// converts to an integer, so that huge and NaN inputs stay defined.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

constexpr double kSqrt3 = std::numbers::sqrt3;

// Fractorium's Round: halves away from 0.
inline double roundHalfAway(double r) {
  return r > 0.0 ? std::floor(r + 0.5) : std::ceil(r - 0.5);
}

// The fractional part of the shader hash sin(12.9898 x + 78.233 y + seed) · 43758.5453 (Fractorium's HashShadertoy).
inline double shaderHash(double x, double y, double seed) {
  const double h = std::sin(x * 12.9898 + y * 78.233 + seed) * 43758.5453;
  return h - std::floor(h);
}

// Whether an integer-valued double is odd, as Fractorium's int(v) & 1 (two's complement: −3 is odd too).
inline bool isOdd(double v) {
  return std::fmod(v, 2.0) != 0.0;
}

// Fractorium's wrap of a cyclic parameter into [low, high] when it is set.
inline double wrapInto(double value, double low, double high) {
  if (value > high) return low + std::fmod(value - low, high - low);
  if (value < low) return high - std::fmod(high - value, high - low);
  return value;
}

// The square Truchet tile the point falls in, shared by Truchet_fill, _glyph and _inv: the point's position (x, y) in
// its unit tile (after scaling by `scale`), the tile's orientation, and the distances of the point from the two
// arcs' centre lines, relative to the arcs' half-width (below 1 on an arc).
struct TruchetTile {
  double x, y, r00, r11;
};
[[gnu::always_inline]] inline TruchetTile truchetTile(double px, double py, double scale, double tiletype,
                                                      double exponent, double oneOverExponent, double rmax,
                                                      bool roundAway) {
  const double sx = px * scale, sy = py * scale;
  const double rx = sx - (roundAway ? roundHalfAway(sx) : std::floor(sx + 0.5));
  const double ry = sy - (roundAway ? roundHalfAway(sy) : std::floor(sy + 0.5));
  const double x = rx < 0.0 ? 1.0 + rx : rx, y = ry < 0.0 ? 1.0 + ry : ry;
  const double xval1 = tiletype < 1.0 ? x : x - 1.0, xval2 = tiletype < 1.0 ? x - 1.0 : x;
  const double r0 = std::pow(std::pow(std::abs(xval1), exponent) + std::pow(std::abs(y), exponent), oneOverExponent);
  const double r1 =
      std::pow(std::pow(std::abs(xval2), exponent) + std::pow(std::abs(y - 1.0), exponent), oneOverExponent);
  return {x, y, std::abs(r0 - 0.5) / rmax, std::abs(r1 - 0.5) / rmax};
}

// Fractorium's Truchet_fill: the tiles' arcs filled, each arc's points mapped to twice their tile position, less the
// point itself (no weight; the weight is the tile scale, 1/w). Tile orientation: all one way for seed 0 or 1, else
// by an LCG of the tile's rounded |x|, |y| and the seed.
VOXFLAME_VARIATION_TARGETS void truchetFill(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double exponent = std::clamp(wrapInto(P[0], 0.001, 2.0), 0.001, 2.0);
  const double width = std::clamp(wrapInto(P[1], 0.001, 1.0), 0.001, 1.0);
  const double seed = P[2];
  const double oneOverEx = 1.0 / exponent;
  const double seed2 = std::sqrt(seed * 1.5) / fractoriumZeps(seed * 0.5) * 0.25;
  const double rmax = fractoriumZeps(0.5 * (std::pow(2.0, oneOverEx) - 1.0) * width);
  const double scale = 1.0 / w;
  for (std::size_t i = 0; i < n; ++i) {
    double tiletype = seed == 1.0 ? 1.0 : 0.0;
    if (seed != 0.0 && seed != 1.0) {
      const double xr = roundHalfAway(std::abs(x[i])) * seed2, yr = roundHalfAway(std::abs(y[i])) * seed2;
      const double randint = (seed + xr + yr + xr * yr) * seed2 * 0.5;
      tiletype = std::fmod(std::fmod(randint * 32747.0 + 12345.0, 65535.0), 2.0);
    }
    const TruchetTile t = truchetTile(x[i], y[i], scale, tiletype, exponent, oneOverEx, rmax, true);
    const double cx = 2.0 * (t.x + std::floor(x[i])), cy = 2.0 * (t.y + std::floor(y[i]));
    const double x1 = t.r00 < 1.0 ? cx : 0.0, y1 = t.r00 < 1.0 ? cy : 0.0;
    outX[i] += x1 + (t.r11 < 1.0 ? cx : 0.0) - x[i];
    outY[i] += y1 + (t.r11 < 1.0 ? cy : 0.0) - y[i];
    outZ[i] += w * z[i];
  }
}

// Fractorium's Truchet_glyph: Truchet_fill's map inside diamonds (|u| + |v| < amp·max/2, (u, v) the offset from the
// centre of the point's amp-sized cell turned by angle degrees), the point itself outside; orientation by the shader
// hash of the tile. No weight (it is the tile scale, 1/w).
VOXFLAME_VARIATION_TARGETS void truchetGlyph(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double exponent = std::clamp(P[0], 0.001, 2.0), width = std::clamp(P[1], 0.001, 1.0);
  const double clampedAmp = std::max(P[2], kFractoriumEps), maxSize = std::max(P[3], 0.0);
  const double rads = P[4] * kPi / 180.0, seed = P[5];
  const double oneN = 1.0 / fractoriumZeps(exponent);
  const double rmax = fractoriumZeps(0.5 * (std::pow(2.0, oneN) - 1.0) * width);
  const double scale = 1.0 / w, halfAmpMax = clampedAmp * 0.5 * maxSize, amp = fractoriumZeps(clampedAmp);
  const double c = std::cos(rads), s = std::sin(rads);
  for (std::size_t i = 0; i < n; ++i) {
    double tiletype = seed == 1.0 ? 1.0 : 0.0;
    if (seed != 0.0 && seed != 1.0) {
      const double h = shaderHash(std::floor(std::abs(x[i]) + 0.5), std::floor(std::abs(y[i]) + 0.5), seed);
      tiletype = std::fmod(std::fmod(h * 32747.0 + 12345.0, 65535.0), 2.0);
    }
    const TruchetTile t = truchetTile(x[i], y[i], scale, tiletype, exponent, oneN, rmax, false);
    const double cx = 2.0 * (t.x + std::floor(x[i])), cy = 2.0 * (t.y + std::floor(y[i]));
    const double vx = x[i] - (std::floor(x[i] / amp) + 0.5) * amp, vy = y[i] - (std::floor(y[i] / amp) + 0.5) * amp;
    const double u = c * vx + s * vy, v = -s * vx + c * vy;
    double px = x[i], py = y[i];
    if (std::abs(u) + std::abs(v) < halfAmpMax) {
      const double x1 = t.r00 < 1.0 ? cx : 0.0, y1 = t.r00 < 1.0 ? cy : 0.0;
      px = x1 + (t.r11 < 1.0 ? cx : 0.0) - x[i];
      py = y1 + (t.r11 < 1.0 ? cy : 0.0) - y[i];
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// Fractorium's Truchet_inv: the points between the arcs (off both), at their tile position times size; the points
// on the arcs go to the origin. The tile scale is (cos rotation + sin rotation)/w; orientation by an LCG of the
// tile's rounded x, y and the seed (all one way for seed 0 or 1).
VOXFLAME_VARIATION_TARGETS void truchetInv(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double exponent = std::clamp(P[0], 0.001, 2.0), width = std::clamp(P[1], 0.001, 1.0);
  const double rotation = P[2], size = std::max(P[3], 0.0), seed = P[4];
  const double seed2 = std::sqrt(seed * 1.5) / fractoriumZeps(seed * 0.5) * 0.25, seed2Half = seed2 * 0.5;
  const double oneN = 1.0 / fractoriumZeps(exponent);
  const double rmax = fractoriumZeps(0.5 * (std::pow(2.0, oneN) - 1.0) * width);
  const double scale = (std::cos(rotation) + std::sin(rotation)) / w;
  for (std::size_t i = 0; i < n; ++i) {
    double tiletype = seed == 1.0 ? 1.0 : 0.0;
    if (seed != 0.0 && seed != 1.0) {
      const double xr = std::floor(x[i] + 0.5) * seed2, yr = std::floor(y[i] + 0.5) * seed2;
      const double randint = (xr + yr + xr * yr + seed) * seed2Half;
      tiletype = std::fmod(std::fmod(randint * 32747.0 + 12345.0, 65535.0), 2.0);
    }
    const TruchetTile t = truchetTile(x[i], y[i], scale, tiletype, exponent, oneN, rmax, false);
    const bool off = t.r00 > 1.0 && t.r11 > 1.0;
    outX[i] += off ? (t.x + std::floor(x[i])) * size : 0.0;
    outY[i] += off ? (t.y + std::floor(y[i])) * size : 0.0;
    outZ[i] += w * z[i];
  }
}

// Fractorium's Truchet_hex_fill: a random hexagon of the plane (the cell offsets ⌊spread ln Ψ⌋, either sign, so
// cells near the centre are likelier), filled with an arc of a hexagonal Truchet tile: the point, scaled by 1/3n and
// wrapped round a circle by exp-like polar mapping into one of 3n sectors (at random), moved to the nearest of the
// hexagon's three arc centres and turned ±30°; seed 1 flips the tiles of even cells, seed ≥ 2 those whose shader
// hash is below ½, flipx/flipy mirror the point in flipped tiles. Six Ψ per point.
VOXFLAME_VARIATION_TARGETS void truchetHexFill(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = std::floor(P[0] + 0.5);
  const bool flipX = fractoriumInteger(P[1], 0.0, 1.0) != 0.0, flipY = fractoriumInteger(P[2], 0.0, 1.0) != 0.0;
  const double spreadX = P[3], spreadY = P[4], seed = std::floor(P[5] + 0.5);
  const double sectors = 3.0 * sides, oneOverSectors = 1.0 / fractoriumZeps(sectors);
  for (std::size_t i = 0; i < n; ++i) {
    const double l1 = std::log(laneUniform(rnd[i]));
    const double rx = std::floor(l1 * (laneUniform(rnd[i]) < 0.5 ? spreadX : -spreadX));
    const double l2 = std::log(laneUniform(rnd[i]));
    const double rz = std::floor(l2 * (laneUniform(rnd[i]) < 0.5 ? spreadY : -spreadY));
    const double hx = kSqrt3 * rx + kSqrt3 / 2.0 * (laneUniform(rnd[i]) < 0.5 ? rz : -rz), hy = 1.5 * rz;
    bool keep = true;
    if (seed == 1.0) {
      keep = isOdd(rx) || isOdd(rz);
    } else if (seed >= 2.0) {
      keep = !(shaderHash(hx, hy, seed) < 0.5);
    }
    const double rangle = std::floor(laneUniform(rnd[i]) * sectors) * kTwoPi * oneOverSectors;
    const double yAux = flipY && !keep ? -y[i] : y[i], xAux = flipX && !keep ? -x[i] : x[i];
    const double ang = yAux * oneOverSectors * kPi + rangle, a = 1.0 + xAux * oneOverSectors * kPi;
    const double fx = a * std::cos(ang), fy = a * std::sin(ang);
    double split = std::atan2(fy, fx);
    if (split < 0.0) split += kTwoPi;
    const double centre = (kPi + std::floor(1.5 * split / kPi) * kTwoPi) / 3.0;
    const double nx = fx - std::cos(centre) * 2.0, ny = fy - std::sin(centre) * 2.0;
    const double turn = keep ? 0.5 : -0.5;
    const double tx = kSqrt3 / 2.0 * nx - turn * ny, ty = turn * nx + kSqrt3 / 2.0 * ny;
    outX[i] += w * (tx * 0.5 + hx);
    outY[i] += w * (ty * 0.5 + hy);
    outZ[i] += w * z[i];
  }
}

// Fractorium's Truchet_hex_crop: the point's hexagon (of the grid with unit circumradius) and the arc of its Truchet
// tile nearest to it (three arcs round alternate corners, turned by π/3 for flipped tiles: seed 1 flips even cells,
// seed ≥ 2 those whose shader hash is below ½). The points on the arc band |d − 1| < wd (or off it with inv) are
// cropped: mode 0 to the hexagon's centre, 1 to the arc's centre, 2 to the band's inner or outer edge (Ψ < ½ outer).
// One Ψ per point, drawn whatever the mode.
VOXFLAME_VARIATION_TARGETS void truchetHexCrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double wd = std::clamp(P[0], 0.0, 5.0), mode = fractoriumInteger(P[1], 0.0, 2.0);
  const bool inv = fractoriumInteger(P[2], 0.0, 1.0) != 0.0;
  const double seed = std::floor(P[3] + 0.5);
  const double d1 = 0.5 + wd, d2 = 0.5 - wd;
  constexpr double kCoef = 1.5 / kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    // Cube coordinates of the hexagon, rounded, the coordinate with the largest rounding error recomputed.
    const double yOver3 = y[i] / 3.0;
    const double cx = kSqrt3 / 3.0 * x[i] - yOver3, cz = 2.0 * yOver3, cy = -cx - cz;
    double rx = std::round(cx), ry = std::round(cy), rz = std::round(cz);
    const double dx = std::abs(rx - cx), dy = std::abs(ry - cy), dz = std::abs(rz - cz);
    if (dx > dy && dx > dz) {
      rx = -ry - rz;
    } else if (dy > dz) {
      ry = -rx - rz;
    } else {
      rz = -rx - ry;
    }
    const double hx = kSqrt3 * rx + kSqrt3 / 2.0 * rz, hy = 1.5 * rz;
    double fx = x[i] - hx, fy = y[i] - hy;
    double add = 0.0;
    if (seed == 1.0) {
      if (!isOdd(rx) && !isOdd(rz)) add = kPi / 3.0;
    } else if (seed >= 2.0) {
      if (shaderHash(hx, hy, seed) < 0.5) add = kPi / 3.0;
    }
    const double angle = std::atan2(fy, fx) + kPi / 6.0 - add;
    const double angle2 = std::floor(angle * kCoef) / kCoef + kPi / 6.0 + add;
    const double x0 = std::cos(angle2), y0 = std::sin(angle2);
    const double dist = std::sqrt((fx - x0) * (fx - x0) + (fy - y0) * (fy - y0));
    const bool crop = inv ? (dist > d1 || dist < d2) : (dist < d1 && dist > d2);
    if (crop) {
      if (mode < 0.5) {
        fx = 0.0;
        fy = 0.0;
      } else if (mode < 1.5) {
        fx = x0;
        fy = y0;
      } else {
        const double rangle = std::atan2(fy - y0, fx - x0), d = u < 0.5 ? d1 : d2;
        fx = x0 + std::cos(rangle) * d;
        fy = y0 + std::sin(rangle) * d;
      }
    }
    outX[i] += (fx + hx) * w;
    outY[i] += (fy + hy) * w;
    outZ[i] += w * z[i];
  }
}

// Fractorium's squares: a grid of cellsize squares, each made of num concentric rings of which those from min to a
// hashed maximum (between max and num) turn by a quarter per ring, unless the cell's second hash is below zero.
// cellsize 0 leaves the point.
VOXFLAME_VARIATION_TARGETS void squares(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cell = P[0], minRing = std::max(P[1], 0.0), maxRing = std::max(P[2], 0.0), rings = P[3];
  const double seed = P[4], zero = P[5], zeroSeed = P[6];
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    if (cell != 0.0) {
      const double cx = (std::floor(x[i] / cell) + 0.5) * cell, cy = (std::floor(y[i] / cell) + 0.5) * cell;
      const double lx = x[i] - cx, ly = y[i] - cy;
      const double ax = std::abs(std::floor(lx * rings * 2.0 / cell + 0.5));
      const double ay = std::abs(std::floor(ly * rings * 2.0 / cell + 0.5));
      const double m = std::max(ax, ay);
      const double top = maxRing + std::floor(shaderHash(cx * cx, cy * cy, seed) * (rings - maxRing));
      const double level = m > top || m < minRing ? 0.0 : m - minRing;
      const double angle = shaderHash(cx * cx, cy * cy, zeroSeed) < zero ? 0.0 : level * kPi / 2.0;
      const double c = std::cos(angle), s = std::sin(angle);
      px = cx + lx * c - ly * s;
      py = cy + lx * s + ly * c;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractoriumTruchetVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("squares",
      "c + ρ(l), z: c the centre of the point's cell of side cellsize, l = p − c, ρ a turn by π/2 (m − min) where min "
      "≤ "
      "m ≤ max + ⌊h(c, seed)(num − max)⌋, m = max(|⌊2 num l/cellsize⌉|), unless h(c, zero_seed) < zero; h the shader "
      "hash fract(43758.5453 sin(12.9898 c_x² + 78.233 c_y² + seed)); p where cellsize is 0 (Fractorium's)",
      k2D, kFixed, &squares,
      {{"cellsize", 0.0, 0.0, 4.0},
       {"min", 0.0, 0.0, 20.0},
       {"max", 10.0, 0.0, 20.0},
       {"num", 10.0, 0.0, 20.0},
       {"seed", 1.0, 0.0, 100.0},
       {"zero", 0.5, 0.0, 1.0},
       {"zero_seed", 1.0, 0.0, 100.0}});
  add("Truchet_fill",
      "for the point's tile of side w (t its position in the tile, k its cell): 2(t + ⌊p⌋) per arc of the tile it lies "
      "on (arcs of the superellipse |·|^exponent = ½ ± arc_width (2^(1/exponent) − 1)/2 round two opposite corners), "
      "less p; no weight (w the weight; orientation by an LCG of the rounded |x|, |y| and seed, one way for seed 0 or "
      "1; Fractorium's)",
      k2D, kFixed, &truchetFill,
      {{"exponent", 2.0, 0.001, 2.0}, {"arc_width", 0.5, 0.001, 1.0}, {"seed", 0.0, 0.0, 100.0}});
  add("Truchet_glyph",
      "Truchet_fill inside the diamonds |u| + |v| < amp·max/2 ((u, v) the offset from the centre of the point's "
      "amp-sized cell turned by angle degrees), p elsewhere; orientation by the shader hash of the rounded |x|, |y| "
      "and seed; no weight (Fractorium's)",
      k2D, kFixed, &truchetGlyph,
      {{"exponent", 2.0, 0.0, 2.0},
       {"arc_width", 0.5, 0.0, 1.0},
       {"amp", 6.0, 0.01, 12.0},
       {"max", 0.9, 0.0, 2.0},
       {"angle", 45.0, -180.0, 180.0},
       {"seed", 1.0, 0.0, 100.0}});
  add("Truchet_inv",
      "size (t + ⌊p⌋) for the points off both arcs of their tile (as Truchet_fill, the tile side w/(cos rotation + sin "
      "rotation)), the origin on them; no weight (Fractorium's)",
      k2D, kFixed, &truchetInv,
      {{"exponent", 2.0, 0.0, 2.0},
       {"arc_width", 0.5, 0.0, 1.0},
       {"rotation", 0.0, -kPi, kPi},
       {"size", 1.0, 0.0, 4.0},
       {"seed", 1.0, 0.0, 100.0}});
  add("Truchet_hex_crop",
      "p with the points of the band |d − 1| < wd (d the distance from the nearest arc centre, a corner of its "
      "hexagon: alternate corners, turned by π/3 in flipped tiles) cropped (off it with inv): mode 0 to the hexagon's "
      "centre, 1 to the corner, 2 to the band's outer edge where Ψ < ½, else its inner; seed 1 flips even cells, seed "
      "≥ "
      "2 cells of shader hash < ½ (Fractorium's)",
      k2D, kRandom, &truchetHexCrop,
      {{"wd", 0.2, 0.0, 5.0},
       count("mode", 0.0, 0.0, 2.0),
       count("inv", 0.0, 0.0, 1.0),
       count("seed", 0.0, 0.0, 100.0)});
  add("Truchet_hex_fill",
      "a random hexagon h = (√3 a ± (√3/2) b, 1.5 b), a = ⌊±spreadx ln Ψ₁⌋, b = ⌊±spready ln Ψ₃⌋ (signs by Ψ₂, Ψ₄, "
      "Ψ₅), "
      "plus half the point mapped onto one arc of its Truchet tile: q = (1 + πx/3n)(cos, sin)(πy/3n + 2π⌊3n Ψ₆⌋/3n), "
      "moved by −2(cos, sin)((π + 2π⌊1.5 ∠q/π⌋)/3) and turned by ±30°; flipped tiles (seed 1 even cells, seed ≥ 2 "
      "hash < ½) turn the other way and mirror x, y by flipx, flipy (Fractorium's)",
      k2D, kRandom, &truchetHexFill,
      {count("n", 3.0, 1.0, 12.0),
       count("flipx", 1.0, 0.0, 1.0),
       count("flipy", 1.0, 0.0, 1.0),
       {"spreadx", 1.0, 0.0, 4.0},
       {"spready", 1.0, 0.0, 4.0},
       count("seed", 0.0, 0.0, 100.0)});
}

}  // namespace voxflame::core
