// Variations that flames of the shared corpus use and the other families lack: dark-beam's juliacomplex
// (an Apophysis plugin), and Jesus Sosa's hamid_js and dc_booleans (JWildfire's HamidFunc and
// DC_BooleansFunc). Each variation is a kernel below and one row of the table at the end (see
// variations.h for the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// juliacomplex (Luca G, dark-beam, 2011): a Julia root for the complex power p = Re_p + i Im_p. With
// d = |p|² and 1/p = (Re_p − i Im_p)/d scaled by dist, the angle is φ Re(1/p) + ½ ln(|logadd| + r²)
// Im(1/p) plus a random multiple of 2π/Re_p (the root's branch), and the radius r^(dist/Re_p)
// e^(−φ Im(1/p)): the plugin raises r to dist/Re_p, not to Re(1/p), which is what gives its blades
// their shape. The plugin's guards are kept: a power near 0 (d < 0.001) is taken as 1, a real part near
// 0 as 1 in the radius and the branch step, and the logarithm and the exponential are skipped (0 and
// 1) while |Im(1/p)| ≤ 0.001, the logarithm also while r² ≤ 0.001. The branch is k 2π/Re_p for a
// random integer k < 32767 (C's rand()), as juliaq draws it: for a whole Re_p that is one of its |Re_p|
// roots.
VOXFLAME_VARIATION_TARGETS void juliacomplex(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double re = P[0], im = P[1], dist = P[2], logAdd = std::abs(P[3]);
  double d = re * re + im * im, b = re;
  if (std::abs(d) < 0.001) {
    d = 1.0;
    b = 1.0;
  } else if (std::abs(b) < 0.001) {
    b = 1.0;
  }
  const double halfInversePower = 0.5 * dist / b;
  const double inverseRe = dist * re / d, inverseIm = -dist * im / d;
  const double branch = kTwoPi / b;
  const bool twists = std::abs(inverseIm) > 0.001;
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = std::atan2(y[i], x[i]);
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double spiral = twists && std::abs(r2) > 0.001 ? 0.5 * std::log(logAdd + r2) * inverseIm : 0.0;
    const double k = std::floor(laneUniform(rnd[i]) * 32767.0);
    const double angle = phi * inverseRe + spiral + k * branch;
    const double radius = w * std::pow(r2, halfInversePower) * (twists ? std::exp(-inverseIm * phi) : 1.0);
    outX[i] += radius * std::cos(angle);
    outY[i] += radius * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

// hamid_js's figures: I = ⌊Ψ N⌋ + 1 (N the number of lines or circles) picks one of them; the
// preset's formula (after Hamid Naderi Yeganeh's drawings) gives a line from (x1, y1) to (x2, y2)
// (presets 0–9) or a circle about (x, y) (presets 10–19). t(k, c) = k c π I / N is the angle the
// formulas use, with JWildfire's parameters a … p as c.
struct HamidLine {
  double x1, y1, x2, y2;
};
struct HamidCircle {
  double x, y, radius;
};

// A point of JWildfire's square path (preset 9): 400 steps round the unit square from the origin,
// along y = 0, x = 1, y = 1 and x = 0; a step count from 400 on goes round again.
inline void hamidSquarePath(double step, double& px, double& py) {
  if (step >= 400.0) step -= 400.0 * std::floor(step / 400.0);
  if (step < 100.0) {
    px = step / 100.0;
    py = 0.0;
  } else if (step < 200.0) {
    px = 1.0;
    py = (step - 100.0) / 100.0;
  } else if (step < 300.0) {
    px = (300.0 - step) / 100.0;
    py = 1.0;
  } else {
    px = 0.0;
    py = (400.0 - step) / 100.0;
  }
}

inline HamidLine hamidLine(int preset, const double* P, double I, double np) {
  const double a = P[3], b = P[4], c = P[5], d = P[6], e = P[7], f = P[8], g = P[9], h = P[10], ii = P[11];
  const double j = P[12], k = P[13];
  const auto t = [&](double times, double c1) { return times * c1 * kPi * I / np; };
  switch (preset) {
    case 0:
      return {-std::sin(t(4.0, a)), -std::cos(t(2.0, b)), -0.5 * e * std::sin(t(8.0, c)),
              -0.5 * f * std::cos(t(4.0, d))};
    case 1:
      return {-std::sin(t(2.0, a)), -std::cos(t(2.0, b)), -0.5 * e * std::sin(t(8.0, c)),
              -0.5 * f * std::cos(t(12.0, d))};
    case 2:
      return {-std::sin(t(8.0, a)), -std::cos(t(2.0, b)), -0.5 * e * std::sin(t(6.0, c)),
              -0.5 * f * std::cos(t(2.0, d))};
    case 3:
      return {-std::sin(t(10.0, a)), -std::cos(t(2.0, b)), -0.5 * e * std::sin(t(12.0, c)),
              -0.5 * f * std::cos(t(2.0, d))};
    case 4: {
      // The figure starts 699 steps along.
      const auto s = [&](double times, double c1) { return times * c1 * kPi * (I + 699.0) / np; };
      return {std::sin(s(10.0, a)), std::cos(s(8.0, b)), std::sin(s(12.0, c)), std::cos(s(10.0, d))};
    }
    case 5:
      // x1 divides by 1000 where the others divide by N: JWildfire's.
      return {-2.0 * a * std::cos(4.0 * b * kPi * I / 1000.0), 0.5 * c * std::pow(std::cos(t(6.0, d)), 3.0 * ii),
              -2.0 * e * std::sin(t(6.0, f)) / 15.0 * j, 4.0 * g * std::sin(t(2.0, h)) / 15.0 * k};
    case 6:
      return {3.0 * a * std::pow(std::sin(t(2.0, b)), 3.0 * h), -std::cos(t(8.0, c)),
              1.5 * d * std::pow(std::sin(t(2.0, e)), 3.0 * ii), -0.5 * f * std::cos(t(6.0, g))};
    case 7:
      return {std::cos(t(6.0, a)), -std::cos(t(8.0, b)), 1.5 * c * std::pow(std::sin(t(2.0, 1.0)), 3.0 * f),
              -0.5 * d * std::cos(t(6.0, e))};
    case 8:
      return {std::pow(std::sin(t(20.0, a)), 3.0), std::pow(std::cos(t(18.0, b)), 3.0 * e),
              std::pow(std::sin(t(16.0, c)), 3.0), std::pow(std::cos(t(14.0, d)), 3.0 * f)};
    default: {
      HamidLine line{};
      hamidSquarePath(I, line.x1, line.y1);
      hamidSquarePath(I + 199.0, line.x2, line.y2);
      return line;
    }
  }
}

inline HamidCircle hamidCircle(int preset, const double* P, double I, double np) {
  const double a = P[3], b = P[4], c = P[5], d = P[6], e = P[7], f = P[8], g = P[9], h = P[10], ii = P[11];
  const double j = P[12], k = P[13], l = P[14], m = P[15], nn = P[16], o = P[17], p = P[18];
  const auto t = [&](double times, double c1) { return times * c1 * kPi * I / np; };
  const auto S = [&](double times, double c1) { return std::sin(t(times, c1)); };
  const auto C = [&](double times, double c1) { return std::cos(t(times, c1)); };
  constexpr double kDot = 1.0 / 150.0;  // the smallest circle's radius
  switch (preset) {
    case 10:
      return {2.0 * a * S(2.0, b) / 3.0 + S(36.0, c) * C(30.0, d) / 3.0 * k + std::pow(S(14.0, 1.0), 3.0 * l) / 3.0 * m,
              2.0 * e * C(2.0, f) / 3.0 * nn + C(36.0, g) * C(30.0, h) / 3.0 * o + std::pow(C(14.0, ii), 3.0) / 5.0 * p,
              kDot + std::pow(S(36.0, j), 4.0) / 9.0};
    case 11:
      return {S(14.0, a), C(32.0, b), std::pow(S(20.0, c), 2.0) / 3.0 * d};
    case 12:
      return {2.0 * a * S(6.0, b) / 3.0 + S(36.0, c) * C(30.0, d) / 4.0 + std::pow(S(14.0, e), 3.0 * k) / 4.0 * l,
              2.0 * f * C(6.0, g) / 3.0 + C(28.0, h) * C(30.0, ii) / 3.0 + std::pow(C(14.0, 1.0), 3.0 * m) / 5.0 * nn,
              kDot + std::pow(S(36.0, j), 4.0 * o) / 20.0 * p};
    case 13:
      return {S(10.0, a), std::pow(C(28.0, b), 3.0 * e), std::pow(S(18.0, c), 2.0) / 3.0 * d};
    case 14:
      return {2.0 * a * S(18.0, b) / 3.0 + std::pow(S(40.0, c), 3.0) * C(30.0, d) / 3.0 +
                  std::pow(S(34.0, e), 3.0 * k) / 4.0 * l,
              2.0 * f * C(18.0, g) / 3.0 + std::pow(C(28.0, h), 3.0) * C(40.0, 1.0) / 3.0 +
                  std::pow(C(34.0, ii), 3.0 * m) / 3.0 * nn,
              kDot + std::pow(S(56.0, j), 4.0 * o) / 8.0 * p};
    case 15:
      return {
          2.0 * a * S(14.0, b) / 3.0 + std::pow(S(10.0, c), 3.0) * C(28.0, d) / 3.0 +
              std::pow(S(46.0, e), 3.0 * m) / 3.0 * nn,
          2.0 * C(14.0, f) / 3.0 + std::pow(C(10.0, g), 3.0) * C(28.0, h) / 3.0 + std::pow(C(34.0, j), 3.0 * o) / 3.0,
          kDot + std::pow(S(72.0, k), 6.0) / 9.0 + std::pow(S(12.0, l), 4.0) / 20.0 * p};
    case 16:
      return {S(38.0, a) * C(26.0, b) / 2.0 + std::pow(S(18.0, c), 3.0 * l) / 2.0 * m,
              2.0 * C(18.0, d) / 3.0 + C(38.0, e) * C(36.0, f) / 3.0 + std::pow(C(18.0, g), 3.0 * nn) / 4.0 * o,
              kDot + std::pow(S(18.0, h), 10.0) * std::pow(S(100.0, ii), 6.0) / 100.0 +
                  std::pow(S(72.0, j), 8.0) * std::pow(C(18.0, k), 6.0) / 20.0 * p};
    case 17:
      return {2.0 * a * S(10.0, b) + std::pow(S(6.0, c), 3.0) * C(28.0, d) / 3.0 + S(126.0, e) / 10.0 * l,
              2.0 * C(6.0, f) / 3.0 + std::pow(C(18.0, g), 3.0) * C(36.0, h) / 3.0 + C(126.0, ii) / 10.0 * m,
              kDot + std::pow(S(48.0, j), 4.0) * (1.0 + std::pow(S(12.0, k), 2.0 * nn)) / 18.0 * o};
    case 18:
      return {2.0 * a * S(18.0, b) / 5.0 + std::pow(S(34.0, c), 3.0 * j) / 3.0 * k +
                  std::pow(S(50.0, d), 3.0 * l) / 3.0 * m,
              2.0 * C(18.0, e) / 3.0 + std::pow(C(34.0, f), 3.0) / 3.0 + std::pow(C(50.0, g), 3.0 * nn) / 10.0 * o,
              kDot + std::pow(S(58.0, ii), 4.0) / 10.0 * p};
    default:
      return {C(10.0, a) * (c - std::pow(S(16.0, b), 2.0 * h) / 2.0 * ii),
              S(10.0, d) * (f - std::pow(C(34.0, e), 2.0 * j) / 2.0 * k),
              1.0 / 200.0 + std::pow(S(52.0, g), 4.0 * l) / 10.0 * m};
  }
}

// hamid_js: a random point of one of the figure's N lines (presets 0–9: at Ψ₂ of its length from
// (x1, y1), JWildfire's walk along the slope, a vertical line taken as slope 10000) or on one of its
// circles (presets 10–19: angle 2πΨ; with filled = 1 the radius is first scaled by Ψ unless Ψ ≤ 0.05,
// so that the rims stay brighter). presetId is rounded and clamped into 0–19 and N, filled truncated
// (Java's int), as JWildfire sets them; N = 0, which JWildfire divides by, is taken as 1.
VOXFLAME_VARIATION_TARGETS void hamidJs(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double presetValue = std::clamp(P[0] > 0.0 ? std::trunc(P[0] + 0.5) : std::trunc(P[0] - 0.5), 0.0, 19.0);
  const int preset = std::isnan(presetValue) ? 0 : static_cast<int>(presetValue);
  const std::int32_t lines = javaInt(P[1]);
  const double np = lines == 0 ? 1.0 : static_cast<double>(lines);
  const bool filled = javaInt(P[2]) == 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double I = std::trunc(laneUniform(rnd[i]) * np + 1.0);
    double px = 0.0, py = 0.0;
    if (preset < 10) {
      const HamidLine line = hamidLine(preset, P, I, np);
      const double xdiff = line.x2 - line.x1, ydiff = line.y2 - line.y1;
      const double slope = xdiff == 0.0 ? 10000.0 : ydiff / xdiff;
      const double along = laneUniform(rnd[i]) * std::sqrt(xdiff * xdiff + ydiff * ydiff);
      double xoffset = along / std::sqrt(1.0 + slope * slope);
      if (line.x2 < line.x1) xoffset = -xoffset;
      double yoffset = std::abs(slope * xoffset);
      if (line.y2 < line.y1) yoffset = -yoffset;
      px = line.x1 + xoffset;
      py = line.y1 + yoffset;
    } else {
      const HamidCircle circle = hamidCircle(preset, P, I, np);
      double radius = circle.radius;
      if (filled && laneUniform(rnd[i]) > 0.05) radius *= laneUniform(rnd[i]);
      const double angle = laneUniform(rnd[i]) * kTwoPi;
      px = circle.x + radius * std::cos(angle);
      py = circle.y + radius * std::sin(angle);
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// java.util.Random's 48-bit linear congruence: its seeding (the seed xor 0x5DEECE66D) and its
// nextDouble (26 and 27 bits of two steps), which dc_booleans' offset comes from.
constexpr std::uint64_t kJavaMultiplier = 0x5DEECE66DULL, kJavaIncrement = 0xBULL, kJavaMask = (1ULL << 48) - 1;
inline std::uint64_t javaRandomSeeded(std::int64_t seed) {
  return (static_cast<std::uint64_t>(seed) ^ kJavaMultiplier) & kJavaMask;
}
inline double javaNextDouble(std::uint64_t& state) {
  state = (state * kJavaMultiplier + kJavaIncrement) & kJavaMask;
  const std::uint64_t high = state >> (48 - 26);
  state = (state * kJavaMultiplier + kJavaIncrement) & kJavaMask;
  const std::uint64_t low = state >> (48 - 27);
  return static_cast<double>((high << 27) + low) * 0x1p-53;
}

// GLSL's fract: x − ⌊x⌋.
inline double fract(double value) {
  return value - std::floor(value);
}

// dc_booleans' colour at (u, v) (after zoom and offset): t = ⌊u⌋ op ⌊v⌋ (Java's int truncation and
// xor, and, or for type 0, 1, 2), the colour of hue sin t, saturation 1, value cos t (Sam Hocevar's
// GLSL hsv2rgb, which JWildfire's follows), in whole steps of 1/256 clamped into 0–255 (`bytes`), and its
// luminance as JWildfire weighs it (each channel's share truncated) over 255.
inline double booleansColour(double u, double v, int type, std::uint32_t (&bytes)[3]) {
  const std::int32_t a = javaInt(u), b = javaInt(v);
  const std::int32_t bits = type == 0 ? (a ^ b) : type == 1 ? (a & b) : (a | b);
  const double t = static_cast<double>(bits);
  const double hue = std::sin(t), value = std::cos(t);
  constexpr double kOffsets[3] = {1.0, 2.0 / 3.0, 1.0 / 3.0};
  constexpr double kShares[3] = {0.299, 0.587, 0.114};
  std::int32_t luminance = 0;
  for (int c = 0; c < 3; ++c) {
    const double channel = value * std::clamp(std::abs(fract(hue + kOffsets[c]) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
    const double level = std::clamp(std::floor(channel * 256.0), 0.0, 255.0);
    bytes[c] = static_cast<std::uint32_t>(level);
    luminance += static_cast<std::int32_t>(level * kShares[c]);
  }
  return static_cast<double>(luminance) / 255.0;
}

// dc_booleans: a uniform point of the square [−½, ½]² (or the point itself with ColorOnly = 1) times
// the weight; its colour from booleansLuminance at the point times zoom plus an offset that
// java.util.Random seeded with randomize draws (randomize · nextDouble for each axis). That luminance
// is JWildfire's colour index for Gradient = 2; for 0 it paints the colour itself and for 1 the palette's
// entry nearest to it (VariationInput::rgb), leaving the index alone. Where nothing keeps a true colour
// (a single evaluation) the luminance stands in as the index, as before true colours were followed.
// z = luminance · scale_z + offset_z, unweighted; with reset_z = 1 it replaces
// the z of the terms before it (an ordinary term rewrites the running sum, VariationInfo::readsSum).
// The integer parameters are clamped and truncated as JWildfire sets them.
VOXFLAME_VARIATION_TARGETS void dcBooleans(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const auto javaLimited = [](double value, double low, double high) {
    return static_cast<int>(std::trunc(std::clamp(std::isnan(value) ? 0.0 : value, low, high)));
  };
  std::uint64_t state = javaRandomSeeded(javaInt(P[0]));
  const double seed = static_cast<double>(javaInt(P[0]));
  const double offsetX = seed * javaNextDouble(state);
  const double offsetY = seed * javaNextDouble(state);
  const int type = javaLimited(P[1], 0.0, 2.0);
  const double zoom = P[2];
  const bool colourOnly = javaLimited(P[3], 0.0, 1.0) == 1;
  const int gradient = javaLimited(P[4], 0.0, 2.0);
  std::uint32_t* __restrict rgb = gradient == 2 ? nullptr : in.rgb;
  const std::uint32_t* palette = gradient == 1 ? in.palette : nullptr;
  const double scaleZ = P[5], offsetZ = P[6];
  const bool resets = javaLimited(P[7], 0.0, 1.0) == 1 && in.stage == VariationStage::Normal;
  for (std::size_t i = 0; i < n; ++i) {
    double u = x[i], v = y[i];
    if (!colourOnly) {
      u = laneUniform(rnd[i]) - 0.5;
      v = laneUniform(rnd[i]) - 0.5;
    }
    std::uint32_t bytes[3];
    const double luminance = booleansColour(u * zoom + offsetX, v * zoom + offsetY, type, bytes);
    if (!rgb) {
      colour[i] = luminance;
    } else if (gradient == 0) {
      rgb[i] = paintedRgb(bytes[0], bytes[1], bytes[2]);
    } else if (palette) {
      rgb[i] = kRgbPainted | palette[nearestPaletteEntry(palette, bytes[0], bytes[1], bytes[2])];
    } else {
      colour[i] = luminance;
    }
    outX[i] += w * u;
    outY[i] += w * v;
    const double dz = luminance * scaleZ + offsetZ;
    outZ[i] = (resets ? 0.0 : outZ[i]) + dz;
  }
}

}  // namespace

void variation_kernels::addJwildfireCorpusVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("juliacomplex",
      "w r^(dist/Re_p) e^(−φ q) (cos β, sin β), β = φ dist Re_p/|p|² + ½ ln(|logadd| + r²) q + 2πk/Re_p, q = −dist "
      "Im_p/|p|², k = ⌊32767 Ψ⌋ (dark-beam's Apophysis plugin)",
      k2D, kRandom, &juliacomplex,
      {{"Re_p", 2.0, -10.0, 10.0}, {"Im_p", 1.0, -10.0, 10.0}, {"dist", 1.0, -4.0, 4.0}, {"logadd", 1.0, -4.0, 4.0}});
  add("hamid_js",
      "w times a random point of one of N lines (presetId 0–9) or circles (10–19, filled or not) of Hamid Naderi "
      "Yeganeh's figures, the figure I = ⌊Ψ N⌋ + 1 of N = number_lines_circles, shaped by a … p (JWildfire's)",
      k2D, kRandom, &hamidJs,
      {count("presetId", 0.0, 0.0, 19.0),
       count("number_lines_circles", 2000.0, 1.0, 10000.0),
       count("filled_circles", 1.0, 0.0, 1.0),
       {"a", 1.0, -4.0, 4.0},
       {"b", 1.0, -4.0, 4.0},
       {"c", 1.0, -4.0, 4.0},
       {"d", 1.0, -4.0, 4.0},
       {"e", 1.0, -4.0, 4.0},
       {"f", 1.0, -4.0, 4.0},
       {"g", 1.0, -4.0, 4.0},
       {"h", 1.0, -4.0, 4.0},
       {"i", 1.0, -4.0, 4.0},
       {"j", 1.0, -4.0, 4.0},
       {"k", 1.0, -4.0, 4.0},
       {"l", 1.0, -4.0, 4.0},
       {"m", 1.0, -4.0, 4.0},
       {"n", 1.0, -4.0, 4.0},
       {"o", 1.0, -4.0, 4.0},
       {"p", 1.0, -4.0, 4.0}});
  add("dc_booleans",
      "w (Ψ₁ − ½, Ψ₂ − ½) (w p with ColorOnly), C = hsv(sin t, 1, cos t), t = ⌊zoom u + x0⌋ op ⌊zoom v + y0⌋ "
      "(xor, and, or by type; (x0, y0) from java.util.Random seeded with randomize); Gradient 0 paints the point C, "
      "1 the palette's entry nearest to C, 2 sets the colour index to C's luminance L; z L scale_z + offset_z "
      "unweighted, replacing the z before it with reset_z (JWildfire's)",
      k3D, kRandom, &dcBooleans,
      {count("randomize", 1000.0, 0.0, 100000.0),
       count("type", 1.0, 0.0, 2.0),
       {"zoom", 1000.0, 0.0, 5000.0},
       count("ColorOnly", 0.0, 0.0, 1.0),
       count("Gradient", 0.0, 0.0, 2.0),
       {"scale_z", 0.0, -2.0, 2.0},
       {"offset_z", 0.0, -2.0, 2.0},
       count("reset_z", 1.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().readsSum = true;
  catalogue.back().paintsRgb = true;
}

}  // namespace voxflame::core
