// JWildfire variations that published JWildfire flames use: hopalong (an attractor's orbit),
// szubieta (a grid of coloured discs) and dc_gnarly (a colouring gnarly). Each variation is a
// kernel below and one row of the table at the end (see variations.h for the notation and
// variation_kernels.h for what the files share). The formulas follow JWildfire's classes of the same
// names.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// JWildfire's Tools.limitValue followed by a cast to int, as its setParameter does for its counts:
// clamped into [low, high], then truncated; a NaN (which limitValue passes through and Java's (int)
// makes 0) is taken as low, so no count is ever 0 where JWildfire would divide or index by it.
inline double jwfLimitedInt(double value, double low, double high) {
  return std::isnan(value) ? low : std::trunc(std::clamp(value, low, high));
}

// Tools.FTOI: rounds half away from 0 (std::round does the same); kept a double (see countParam).
inline double jwfRound(double value) {
  return std::round(value);
}

// ---- hopalong ----------------------------------------------------------------------------------

// Barry Martin's hopalong map: (x, y) → (y − sign(x) √|b x − c|, a − x), sign(0) = 0 (Java's
// Math.signum).
struct HopalongStep {
  double x, y;
};
inline HopalongStep hopalongStep(double x, double y, double a, double b, double c) {
  const double sign = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
  return {y - sign * std::sqrt(std::abs(b * x - c)), a - x};
}

// JWildfire's hopalong ignores the point: each call adds the next point of one orbit of the map that
// the variation keeps from call to call (one per render thread, each from (startx, starty)). Its
// picture is thus the orbit's first points, as many as a thread makes calls. A variation here keeps
// nothing from one call to the next, so it draws a point of the orbit's first kHopalongPoints
// instead (Ψ picks which): the same points with the same weights as a thread of JWildfire's with
// that many calls, and the same for every lane, chunk and thread, so renders stay reproducible.
constexpr std::size_t kHopalongPoints = std::size_t{1} << 20;

struct HopalongOrbit {
  double key[5];  // a, b, c, startx, starty as used
  std::vector<double> x, y;
};

bool sameKey(const double (&key)[5], const double (&other)[5]) {
  // Bitwise, so that a NaN parameter finds its orbit again instead of building one per call.
  for (int k = 0; k < 5; ++k)
    if (std::bit_cast<std::uint64_t>(key[k]) != std::bit_cast<std::uint64_t>(other[k])) return false;
  return true;
}

// The orbit for these parameters: points 1 … kHopalongPoints of the orbit of the start point (the
// start itself is never drawn, as JWildfire adds the point after it first). The orbit depends on the
// parameters alone, so it is built once and shared: each thread keeps the last one it used, and a
// few recent ones are kept for all threads (an animation changes them every frame).
std::shared_ptr<const HopalongOrbit> hopalongOrbit(const double (&key)[5]) {
  thread_local std::shared_ptr<const HopalongOrbit> last;
  if (last && sameKey(last->key, key)) return last;
  static std::mutex mutex;
  static std::vector<std::shared_ptr<const HopalongOrbit>> recent;
  const std::scoped_lock lock(mutex);
  for (const auto& orbit : recent)
    if (sameKey(orbit->key, key)) return last = orbit;
  auto orbit = std::make_shared<HopalongOrbit>();
  std::copy(std::begin(key), std::end(key), std::begin(orbit->key));
  orbit->x.resize(kHopalongPoints);
  orbit->y.resize(kHopalongPoints);
  double px = key[3], py = key[4];
  for (std::size_t k = 0; k < kHopalongPoints; ++k) {
    const HopalongStep next = hopalongStep(px, py, key[0], key[1], key[2]);
    px = orbit->x[k] = next.x;
    py = orbit->y[k] = next.y;
  }
  constexpr std::size_t kKept = 2;
  if (recent.size() >= kKept) recent.erase(recent.begin());
  recent.push_back(orbit);
  return last = orbit;
}

// hopalong: w · (point k of the orbit of (startx, starty) under the hopalong map), k = 1 + ⌊Ψ 2²⁰⌋;
// z carried. a, b and c are clamped into [−1, 1] as JWildfire's setParameter does. `random` is
// JWildfire's seed for drawing a, b, c and the start when it is set; JWildfire writes all five after
// it, and reads them after it, so in a file they always win and the seed changes nothing.
VOXFLAME_VARIATION_TARGETS void hopalong(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double key[5] = {std::clamp(P[1], -1.0, 1.0), std::clamp(P[2], -1.0, 1.0), std::clamp(P[3], -1.0, 1.0), P[4],
                         P[5]};
  const std::shared_ptr<const HopalongOrbit> orbit = hopalongOrbit(key);
  const double* __restrict hx = orbit->x.data();
  const double* __restrict hy = orbit->y.data();
  constexpr double kPoints = static_cast<double>(kHopalongPoints);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(std::min(std::floor(laneUniform(rnd[i]) * kPoints), kPoints - 1.0));
    outX[i] += w * hx[k];
    outY[i] += w * hy[k];
    outZ[i] += w * z[i];
  }
}

// ---- szubieta ----------------------------------------------------------------------------------

// szubieta (Jesus Sosa's, after Paul Bourke's CircleSquares and Square Tile patterns): a disc of
// radius `scale` at every cell (i, j) of a width × height grid centred on the origin, coloured by the
// pattern's value at (i, j). JWildfire draws each disc as a 20-sided nBlur polygon (its DrawFunc's
// plotPolygon with no hole), and so does this port: Ψ₁ picks the cell, Ψ₂ the place along the
// polygon's edge (nBlur's arctan-shaped spread inside one of 20 sectors, the sector from Ψ₃ as
// JWildfire's rand(32767) mod 20), Ψ₄ the radius (√Ψ₄ of the way to the edge). The result is
// w · 0.1 (q scale + (i − width/2, j − height/2)), q the polygon's point turned by half a sector.
// Colour: type 0 |(i² − 2 (i | j) + j²) mod 255| / 255, type 1 |(i & (2j − 2 (i ^ j)) & i) mod 256| / 255
// (Java's int arithmetic). JWildfire sets the colour index outright: its direct colour.
constexpr double kSzubietaSides = 20.0;
constexpr double kJwfRandMax = 32767.0;  // DrawFunc's RAND_MAX

VOXFLAME_VARIATION_TARGETS void szubieta(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double width = jwfLimitedInt(P[0], 32.0, 256.0), height = jwfLimitedInt(P[1], 32.0, 256.0);
  const bool squareTile = jwfLimitedInt(P[2], 0.0, 1.0) == 1.0;
  const double scale = std::isnan(P[3]) ? 0.0 : std::clamp(P[3], 0.0, 1.0);
  const double cells = width * height;
  // nBlur's constants for 20 sides.
  const double sector = kTwoPi / kSzubietaSides;
  const double edgeTan = std::tan(kPi / 2.0 + sector / 2.0);
  const double spread = 13.0 / std::pow(kSzubietaSides, 1.3);
  const double spreadNorm = 2.0 * std::atan(spread / -2.0);
  const double turnSin = std::sin(sector / 2.0), turnCos = std::cos(sector / 2.0);
  const double halfW = width / 2.0, halfH = height / 2.0, w10 = 0.1 * w;
  for (std::size_t i = 0; i < n; ++i) {
    const double cell = std::min(std::floor(laneUniform(rnd[i]) * cells), cells - 1.0);
    const double ci = std::floor(cell / height), cj = cell - ci * height;
    const double u = laneUniform(rnd[i]);
    const double edge = std::fmod(std::floor(laneUniform(rnd[i]) * kJwfRandMax), kSzubietaSides);
    double angle = (std::atan(spread * (u - 0.5)) / spreadNorm + 0.5 + edge) * sector;
    double px = std::sin(angle), py = std::cos(angle);
    // JWildfire steps the angle back one sector at a time; the same steps give the same rounding.
    for (int k = 0; k < static_cast<int>(kSzubietaSides) && angle > sector; ++k) angle -= sector;
    const double t = std::tan(angle);
    const double ex = edgeTan / (edgeTan - t), ey = ex * t;
    const double radius = std::sqrt(laneUniform(rnd[i])) * std::sqrt(ex * ex + ey * ey);
    px *= radius;
    py *= radius;
    const double qx = turnCos * px - turnSin * py, qy = turnSin * px + turnCos * py;
    outX[i] += w10 * (qx * scale + (ci - halfW));
    outY[i] += w10 * (qy * scale + (cj - halfH));
    outZ[i] += w * z[i];
    const auto gi = static_cast<std::int32_t>(ci), gj = static_cast<std::int32_t>(cj);
    const std::int32_t value =
        squareTile ? (gi & (gj - 2 * (gi ^ gj) + gj) & gi) % 256 : (gi * gi - 2 * (gi | gj) + gj * gj) % 255;
    colour[i] = static_cast<double>(value < 0 ? -value : value) / 255.0;
  }
}

// ---- dc_gnarly ---------------------------------------------------------------------------------

// dc_gnarly (JWildfire's): the point p₀, blurred (blur > 0: by blur (Ψ₂ + … + Ψ₇ − 3) in the
// direction 2πΨ₁; blur < 0: by a uniform step in [blur, −blur)² from Ψ₁, Ψ₂), gives a gnarly offset
// g = (scalex f(freqx…, y₀, x₀), scaley f(freqy…, x₀, y₀)) by mode (one of nine wave forms, see the
// table row); the result is w (p₀ + g)/2. With dc the colour index becomes |cos(x₀ + g_x color1 + s)
// + sin(y₀ + g_y color2 + s)| mod fmag, s = distort · log |g|. z: dz = colour · scale_z + offset_z is
// added, or with reset_z replaces the sum's z (JWildfire's pVarTP.z = dz), so an ordinary term reads
// and writes the running sum. JWildfire's CPU code keeps a ring of six uniforms from call to call for
// the blur; its GPU code draws six new ones each call, and so does this port.
VOXFLAME_VARIATION_TARGETS void dcGnarly(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double mode = std::clamp(jwfRound(P[0]), 0.0, 8.0);
  const double sx = P[1], sy = P[2], fx1 = P[3], fy1 = P[4], fx2 = P[5], fy2 = P[6], fx3 = P[7], fy3 = P[8];
  const bool dc = std::clamp(jwfRound(P[9]), 0.0, 1.0) != 0.0;
  const double colour1 = P[10], colour2 = P[11];
  const double fmag = std::isnan(P[12]) ? 1.0 : std::clamp(P[12], 0.05, 1.0);
  const double distort = P[13], blur = P[14], scaleZ = P[15], offsetZ = P[16];
  const bool reset = std::clamp(jwfRound(P[17]), 0.0, 1.0) > 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double x0 = x[i], y0 = y[i];
    if (blur > 0.0) {
      const double turn = laneUniform(rnd[i]) * kTwoPi;
      double sum = 0.0;
      for (int k = 0; k < 6; ++k) sum += laneUniform(rnd[i]);
      const double r = blur * (sum - 3.0);
      x0 += r * std::cos(turn);
      y0 += r * std::sin(turn);
    } else if (blur < 0.0) {
      x0 += laneUniform(rnd[i]) * blur * 2.0 - blur;
      y0 += laneUniform(rnd[i]) * blur * 2.0 - blur;
    }
    double x1, y1;
    if (mode == 1.0) {
      x1 = std::cos(fx1 * y0 + std::sin(fx2 * (y0 + std::sin(fx3 * y0))));
      y1 = std::cos(fy1 * x0 + std::sin(fy2 * (x0 + std::sin(fy3 * x0))));
    } else if (mode == 2.0) {
      x1 = std::sin(fx1 * y0 + std::sin(fx2 * (y0 + std::cos(fx3 * y0))));
      y1 = std::sin(fy1 * x0 + std::sin(fy2 * (x0 + std::cos(fy3 * x0))));
    } else if (mode == 3.0) {
      x1 = std::cos(fx1 * y0 + std::sin(fx2 * (x0 + std::sin(fx3 * y0))));
      y1 = std::cos(fy1 * x0 + std::sin(fy2 * (y0 + std::sin(fy3 * x0))));
    } else if (mode == 4.0) {
      x1 = std::sin(fx1 * y0 + std::sin(std::sqrt(std::abs(fx2 * (y0 + std::cos(fx3 * y0))))));
      y1 = std::sin(fy1 * x0 + std::sin(std::sqrt(std::abs(fy2 * (x0 + std::cos(fy3 * x0))))));
    } else if (mode == 5.0) {
      // JWildfire writes asinh as log(v + √(v² + 1)), which loses everything for large negative v;
      // std::asinh is the same function without that loss.
      x1 = std::cos(fx1 * y0 + std::asinh(fx2 * (y0 + std::sin(fx3 * y0))));
      y1 = std::cos(fy1 * x0 + std::asinh(fy2 * (x0 + std::sin(fy3 * x0))));
    } else if (mode == 6.0) {
      x1 = std::cos(fx1 * y0 + std::tan(fx2 * (y0 + std::sin(fx3 * y0))));
      y1 = std::cos(fy1 * x0 + std::tan(fy2 * (x0 + std::sin(fy3 * x0))));
    } else if (mode == 7.0) {
      const double vx = fx2 * (y0 + std::cos(fx3 * y0)), vy = fy2 * (x0 + std::cos(fy3 * x0));
      x1 = std::sin(fx1 * y0 + std::sin(vx * vx));
      y1 = std::sin(fy1 * x0 + std::sin(vy * vy));
    } else if (mode == 8.0) {
      const double vx = fx2 * (x0 + std::cos(fx3 * y0)), vy = fy2 * (y0 + std::cos(fy3 * x0));
      x1 = std::sin(fx1 * y0 + std::sin(vx * vx));
      y1 = std::sin(fy1 * x0 + std::sin(vy * vy));
    } else {
      x1 = std::sin(fx1 * y0);
      y1 = std::sin(fy1 * x0);
    }
    x1 *= sx;
    y1 *= sy;
    outX[i] += w * (x0 + x1) / 2.0;
    outY[i] += w * (y0 + y1) / 2.0;
    if (dc) {
      // distort 0 adds nothing; JWildfire's 0 · log 0 would make the colour NaN where g = 0.
      const double s = distort == 0.0 ? 0.0 : std::log(std::sqrt(x1 * x1 + y1 * y1)) * distort;
      colour[i] = std::fmod(std::abs(std::cos(x0 + x1 * colour1 + s) + std::sin(y0 + y1 * colour2 + s)), fmag);
    }
    const double dz = colour[i] * scaleZ + offsetZ;
    // z is carried as a 2D variation's is here (JWildfire's own leaves z out); reset_z replaces the
    // running sum's z (a pre_/post_ term's arrays start at 0, so there it is dz as well).
    outZ[i] = reset ? dz : outZ[i] + w * z[i] + dz;
  }
}

}  // namespace

void variation_kernels::addJwildfireHoldoutVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("hopalong",
      "w · h_k, z: h_k point k = 1 + ⌊2²⁰ Ψ⌋ of the orbit of (startx, starty) under Martin's hopalong map (x, y) → "
      "(y − sign x √|b x − c|, a − x), a, b, c clamped into [−1, 1]; the point itself is not used. JWildfire "
      "adds the orbit's next point each call; a variation here keeps nothing between calls, so it draws one of the "
      "orbit's first 2²⁰ points. random (JWildfire's seed for a, b, c and the start) is overridden by them in files",
      k2D, kRandom, &hopalong,
      {count("random", 1.0, 0.0, 10000000.0),
       {"a", 0.75, -1.0, 1.0},
       {"b", 0.5, -1.0, 1.0},
       {"c", 0.25, -1.0, 1.0},
       {"startx", 0.0, -1.0, 1.0},
       {"starty", 0.0, -1.0, 1.0}});
  add("szubieta",
      "w · 0.1 (scale q + (i − width/2, j − height/2)), z: cell (i, j) of the width × height grid from Ψ₁, q a "
      "point of a 20-sided nBlur polygon of radius 1 (Ψ₂, Ψ₃, Ψ₄); the colour index becomes Paul Bourke's "
      "CircleSquares value |(i² − 2 (i | j) + j²) mod 255| / 255 (type 0) or Square Tile value |(i & (2j − 2 (i ^ "
      "j)) & i) mod 256| / 255 (type 1)",
      k2D, kRandom, &szubieta,
      {count("width", 128.0, 32.0, 256.0),
       count("height", 128.0, 32.0, 256.0),
       count("type", 0.0, 0.0, 1.0),
       {"scale", 0.5, 0.0, 1.0}});
  catalogue.back().directColour = true;
  add("dc_gnarly",
      "w (p₀ + g)/2 with p₀ = p blurred (blur > 0: blur (Ψ₂ + … + Ψ₇ − 3) along 2πΨ₁; blur < 0: uniform in ±blur), "
      "g = (scalex X, scaley Y), mode 1: X = cos(fx1 y₀ + sin(fx2 (y₀ + sin fx3 y₀))), Y likewise with x₀ and the "
      "fy's; 2: sin(· + sin(fx2 (y₀ + cos fx3 y₀))); 3: mode 1 with x₀ inside the inner sine; 4: mode 2 with √|·|; "
      "5: mode 1 with asinh; 6: mode 1 with tan; 7: mode 2 with (·)²; 8: mode 7 with x₀ inside; else X = sin(fx1 "
      "y₀); with dc the colour index |cos(x₀ + g_x color1 + s) + sin(y₀ + g_y color2 + s)| mod fmag, s = distort "
      "log |g|; z + colour · scale_z + offset_z (reset_z: z = colour · scale_z + offset_z)",
      k3D, kRandom, &dcGnarly,
      {count("mode", 1.0, 0.0, 8.0),
       {"scalex", 0.05, -1.0, 1.0},
       {"scaley", 0.05, -1.0, 1.0},
       {"freqx1", 3.5, -10.0, 10.0},
       {"freqy1", 3.5, -10.0, 10.0},
       {"freqx2", 2.0, -10.0, 10.0},
       {"freqy2", 2.0, -10.0, 10.0},
       {"freqx3", 5.0, -10.0, 10.0},
       {"freqy3", 5.0, -10.0, 10.0},
       count("dc", 1.0, 0.0, 1.0),
       {"color1", 5.0, -30.0, 30.0},
       {"color2", 5.0, -30.0, 30.0},
       {"fmag", 1.0, 0.05, 1.0},
       {"distort", 0.0, -2.0, 2.0},
       {"blur", 5.0, -20.0, 20.0},
       {"scale_z", 0.0, -2.0, 2.0},
       {"offset_z", 0.0, -2.0, 2.0},
       count("reset_z", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().readsSum = true;
}

}  // namespace voxflame::core
