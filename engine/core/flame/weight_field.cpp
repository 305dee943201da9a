// The noises of JWildfire's weighting fields (flame.h). JWildfire draws them with FastNoise
// (Jordan Peck's library): lattice noises hashed from (seed, lattice point), a fractal sum whose
// octave k uses seed + k, and cellular noise from points jittered about the lattice points. These
// follow FastNoise's behaviour (its interpolation, ranges, fractal sums and cellular return
// values) with voxflame's own hash and tables, so each family has FastNoise's character and
// scale but not its very values.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "core/flame/flame.h"
#include "core/flame/noise.h"
#include "core/flame/variations.h"

namespace voxflame::core {

namespace {

// A 32-bit hash of a seed and a lattice point (murmur3's finaliser over a mix of the four).
std::uint32_t latticeHash(std::int32_t seed, std::int32_t x, std::int32_t y, std::int32_t z) {
  std::uint32_t h = static_cast<std::uint32_t>(seed) * 0x9E3779B1u;
  h ^= static_cast<std::uint32_t>(x) * 0x85EBCA77u;
  h ^= static_cast<std::uint32_t>(y) * 0xC2B2AE3Du;
  h ^= static_cast<std::uint32_t>(z) * 0x27D4EB2Fu;
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  h *= 0xC2B2AE35u;
  h ^= h >> 16;
  return h;
}

// A lattice point's value, uniform in [−1, 1) (FastNoise's ValCoord).
double latticeValue(std::int32_t seed, std::int32_t x, std::int32_t y, std::int32_t z) {
  return static_cast<double>(latticeHash(seed, x, y, z)) * (2.0 / 4294967296.0) - 1.0;
}

// Lattice coordinates of a point far from the origin stay in range: the noise repeats past ±2³⁰
// (well past any flame's extent at any sensible frequency); a point that is not finite (an
// escaped one, which the chaos game reseeds) reads the cell at 0.
std::int32_t cell(double v) {
  const double f = std::floor(v);
  if (!std::isfinite(f)) return 0;
  return static_cast<std::int32_t>(std::fmod(f, 1073741824.0));
}

double quintic(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
double lerp(double a, double b, double t) {
  return a + t * (b - a);
}

// Value noise: the lattice values blended by the quintic fade, in [−1, 1].
double valueNoise(std::int32_t seed, double x, double y, double z) {
  const std::int32_t x0 = cell(x), y0 = cell(y), z0 = cell(z);
  const double u = quintic(x - std::floor(x)), v = quintic(y - std::floor(y)), w = quintic(z - std::floor(z));
  const auto at = [&](int i, int j, int k) { return latticeValue(seed, x0 + i, y0 + j, z0 + k); };
  const double a = lerp(lerp(at(0, 0, 0), at(1, 0, 0), u), lerp(at(0, 1, 0), at(1, 1, 0), u), v);
  const double b = lerp(lerp(at(0, 0, 1), at(1, 0, 1), u), lerp(at(0, 1, 1), at(1, 1, 1), u), v);
  return lerp(a, b, w);
}

// Perlin's gradient noise: at each lattice point one of the 12 cube-edge directions (Perlin's
// improved noise, as FastNoise picks them), dotted with the offset, blended by the quintic fade.
double gradientDot(std::uint32_t hash, double dx, double dy, double dz) {
  switch (hash % 12u) {
    case 0:
      return dx + dy;
    case 1:
      return -dx + dy;
    case 2:
      return dx - dy;
    case 3:
      return -dx - dy;
    case 4:
      return dx + dz;
    case 5:
      return -dx + dz;
    case 6:
      return dx - dz;
    case 7:
      return -dx - dz;
    case 8:
      return dy + dz;
    case 9:
      return -dy + dz;
    case 10:
      return dy - dz;
    default:
      return -dy - dz;
  }
}

double perlinNoise(std::int32_t seed, double x, double y, double z) {
  const std::int32_t x0 = cell(x), y0 = cell(y), z0 = cell(z);
  const double fx = x - std::floor(x), fy = y - std::floor(y), fz = z - std::floor(z);
  const double u = quintic(fx), v = quintic(fy), w = quintic(fz);
  const auto at = [&](int i, int j, int k) {
    return gradientDot(latticeHash(seed, x0 + i, y0 + j, z0 + k), fx - i, fy - j, fz - k);
  };
  const double a = lerp(lerp(at(0, 0, 0), at(1, 0, 0), u), lerp(at(0, 1, 0), at(1, 1, 0), u), v);
  const double b = lerp(lerp(at(0, 0, 1), at(1, 0, 1), u), lerp(at(0, 1, 1), at(1, 1, 1), u), v);
  return lerp(a, b, w);
}

// Cubic noise: lattice values through a cubic through four neighbours per axis, scaled by
// 1/1.5³ as FastNoise scales it into about [−1, 1].
double cubicBlend(double a, double b, double c, double d, double t) {
  const double p = (d - c) - (a - b);
  return ((p * t + ((a - b) - p)) * t + (c - a)) * t + b;
}

double cubicNoise(std::int32_t seed, double x, double y, double z) {
  const std::int32_t x1 = cell(x), y1 = cell(y), z1 = cell(z);
  const double u = x - std::floor(x), v = y - std::floor(y), w = z - std::floor(z);
  std::array<double, 4> planes{};
  for (int k = 0; k < 4; ++k) {
    std::array<double, 4> rows{};
    for (int j = 0; j < 4; ++j) {
      std::array<double, 4> row{};
      for (int i = 0; i < 4; ++i) row[i] = latticeValue(seed, x1 - 1 + i, y1 - 1 + j, z1 - 1 + k);
      rows[j] = cubicBlend(row[0], row[1], row[2], row[3], u);
    }
    planes[k] = cubicBlend(rows[0], rows[1], rows[2], rows[3], v);
  }
  return cubicBlend(planes[0], planes[1], planes[2], planes[3], w) / (1.5 * 1.5 * 1.5);
}

// Simplex noise from voxflame's shared table, moved by the seed (weightFieldSimplexOffset).
double simplexNoise(std::int32_t seed, double x, double y, double z) {
  const std::array<double, 3> offset = weightFieldSimplexOffset(seed);
  return simplexNoise3D(x + offset[0], y + offset[1], z + offset[2]);
}

// White noise: a value per point, hashed from the coordinates' single-precision bits as
// FastNoise hashes them (so it is the same at the same point and unrelated anywhere else).
double whiteNoise(std::int32_t seed, double x, double y, double z) {
  const auto bits = [](double v) {
    const auto b = std::bit_cast<std::int32_t>(static_cast<float>(v));
    return b ^ (b >> 16);
  };
  return latticeValue(seed, bits(x), bits(y), bits(z));
}

// Cellular (Worley) noise as FastNoise makes it: a feature point 0.45 from each lattice point in
// a direction drawn from the hash, the nearest (and second nearest) of the 27 about the lattice
// point nearest p, at the distance function's distance (Euclidean: squared, as FastNoise has it).
double cellularNoise(std::int32_t seed, CellDistance metric, CellReturn kind, double x, double y, double z) {
  const auto round = [](double v) { return cell(v + 0.5); };
  const std::int32_t xr = round(x), yr = round(y), zr = round(z);
  double nearest = std::numeric_limits<double>::max(), second = nearest;
  std::int32_t cx = 0, cy = 0, cz = 0;
  for (std::int32_t i = xr - 1; i <= xr + 1; ++i)
    for (std::int32_t j = yr - 1; j <= yr + 1; ++j)
      for (std::int32_t k = zr - 1; k <= zr + 1; ++k) {
        // The direction: uniform on the sphere from the hash's two halves.
        const std::uint32_t h = latticeHash(seed, i, j, k);
        const double cosTheta = static_cast<double>(h & 0xFFFFu) * (2.0 / 65535.0) - 1.0;
        const double phi = static_cast<double>(h >> 16) * (2.0 * std::numbers::pi / 65536.0);
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const double dx = i - x + 0.45 * sinTheta * std::cos(phi);
        const double dy = j - y + 0.45 * sinTheta * std::sin(phi);
        const double dz = k - z + 0.45 * cosTheta;
        const double manhattan = std::abs(dx) + std::abs(dy) + std::abs(dz);
        const double squared = dx * dx + dy * dy + dz * dz;
        const double d = metric == CellDistance::Euclidean   ? squared
                         : metric == CellDistance::Manhattan ? manhattan
                                                             : manhattan + squared;
        if (d < nearest) {
          second = nearest;
          nearest = d;
          cx = i;
          cy = j;
          cz = k;
        } else if (d < second) {
          second = d;
        }
      }
  switch (kind) {
    case CellReturn::CellValue:
      return latticeValue(0, cx, cy, cz);  // FastNoise reads the cell's value with seed 0
    case CellReturn::Distance:
      return nearest - 1.0;
    case CellReturn::Distance2:
      return second - 1.0;
    case CellReturn::Distance2Add:
      return second + nearest - 1.0;
    case CellReturn::Distance2Sub:
      return second - nearest - 1.0;
    case CellReturn::Distance2Mul:
      return second * nearest - 1.0;
    case CellReturn::Distance2Div:
      return nearest / second - 1.0;
  }
  return 0.0;
}

double single(const FlameXform& f, std::int32_t seed, double x, double y, double z) {
  switch (f.fieldNoise) {
    case WeightFieldNoise::Simplex:
      return simplexNoise(seed, x, y, z);
    case WeightFieldNoise::Perlin:
      return perlinNoise(seed, x, y, z);
    case WeightFieldNoise::Value:
      return valueNoise(seed, x, y, z);
    case WeightFieldNoise::Cubic:
      return cubicNoise(seed, x, y, z);
    case WeightFieldNoise::Cellular:
      return cellularNoise(seed, f.fieldCellDistance, f.fieldCellReturn, x, y, z);
    case WeightFieldNoise::White:
      return whiteNoise(seed, x, y, z);
  }
  return 0.0;
}

}  // namespace

double weightFieldNoise(const FlameXform& xform, double x, double y, double z) {
  if (xform.fieldKind == WeightFieldKind::None) return 0.0;
  double frequency = xform.fieldFrequency;
  const std::int32_t seed = xform.fieldSeed;
  if (xform.fieldKind == WeightFieldKind::Noise)
    return single(xform, seed, frequency * x, frequency * y, frequency * z);
  // FastNoise's fractal sums: octave k at seed + k. fbm and billow are scaled by 1 / (the sum of
  // the amplitudes); rigid is 1 − |n₀| less each further octave's amplitude · (1 − |nₖ|), unscaled.
  double sum = 0.0, amplitude = 1.0, bound = 0.0;
  for (int octave = 0; octave < xform.fieldOctaves; ++octave) {
    const double n = single(xform, static_cast<std::int32_t>(static_cast<std::uint32_t>(seed) + octave), frequency * x,
                            frequency * y, frequency * z);
    switch (xform.fieldFractal) {
      case WeightFieldFractal::Fbm:
        sum += amplitude * n;
        break;
      case WeightFieldFractal::Billow:
        sum += amplitude * (2.0 * std::abs(n) - 1.0);
        break;
      case WeightFieldFractal::Rigid:
        sum += (octave == 0 ? 1.0 : -amplitude) * (1.0 - std::abs(n));
        break;
    }
    bound += amplitude;
    amplitude *= xform.fieldGain;
    frequency *= xform.fieldLacunarity;
  }
  if (xform.fieldFractal == WeightFieldFractal::Rigid) return sum;
  return bound != 0.0 ? sum / bound : 0.0;
}

std::array<double, 3> weightFieldSimplexOffset(std::int32_t seed) {
  // Irrational steps: no two seeds align.
  const double s = static_cast<double>(seed);
  return {std::fmod(s * 0.7548776662466927, 1.0) * 4096.0, std::fmod(s * 0.5698402909980532, 1.0) * 4096.0,
          std::fmod(s * 0.4301597090019468, 1.0) * 4096.0};
}

WeightFieldTerm weightFieldTerm(const FlameXform& xform, const VariationTerm& term, const VariationInfo& info) {
  WeightFieldTerm bound;
  if (!xform.hasWeightField()) return bound;
  bool weightSet = false;
  for (const FlameXform::FieldParam& p : xform.fieldParams()) {
    if (p.intensity == 0.0 || p.variation != term.name) continue;
    if (p.name == "amount") {
      if (!weightSet) bound.weight = p.intensity;
      weightSet = true;
      continue;
    }
    const int index = info.paramIndex(p.name);
    if (index < 0 || static_cast<std::size_t>(index) >= term.params.size()) continue;
    const auto at = static_cast<std::size_t>(index);
    if (std::none_of(bound.params.begin(), bound.params.end(),
                     [&](const WeightFieldTerm::Param& q) { return q.index == at; }))
      bound.params.push_back({at, p.intensity, info.params[at].integer || info.params[at].jwildfireInt});
  }
  return bound;
}

}  // namespace voxflame::core
