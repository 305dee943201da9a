// JWildfire variations that published JWildfire flames use: hopalong (an attractor's orbit), szubieta
// (a grid of coloured discs), dc_gnarly (a colouring gnarly) and dc_triTile (tiles of substitution
// tilings). Each variation is a kernel below and one row of the table at the end (see variations.h
// for the notation and variation_kernels.h for what the files share). The formulas follow
// JWildfire's classes of the same names.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <vector>

#include "core/flame/dc_base_kernel.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

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
  static RecentBuilds<HopalongOrbit> orbits(2);
  return orbits.get(
      last, [&](const HopalongOrbit& orbit) { return sameKey(orbit.key, key); },
      [&] {
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
        return std::shared_ptr<const HopalongOrbit>(std::move(orbit));
      });
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

// hopalong's orbit for a backend of its own: (x, y) pairs, points 1 … kHopalongPoints.
std::vector<double> hopalongTable(const double* params, const std::string*) {
  const double key[5] = {std::clamp(params[1], -1.0, 1.0), std::clamp(params[2], -1.0, 1.0),
                         std::clamp(params[3], -1.0, 1.0), params[4], params[5]};
  const std::shared_ptr<const HopalongOrbit> orbit = hopalongOrbit(key);
  std::vector<double> table(2 * kHopalongPoints);
  for (std::size_t k = 0; k < kHopalongPoints; ++k) {
    table[2 * k] = orbit->x[k];
    table[2 * k + 1] = orbit->y[k];
  }
  return table;
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

// ---- dc_triTile ----------------------------------------------------------------------------------

// dc_triTile (JWildfire's, after eralex61's FiveFold): a random tile of a substitution tiling (type 1
// FiveFold's Penrose triangles, 2 trihex, 3 equithirds, 4 overlapping Robinson triangles, 5 pinwheel,
// 6 golden pinwheel; tilings.math.uni-bielefeld.de), found by subdividing one of its two prototiles
// (t) again and again, one random child each time, and a uniform point of that tile. The colour says
// which kind of tile it is and which path of kinds led to it. The point itself is not used.
struct TilePoint {
  double x, y;
};
struct Tile {
  int type;  // which prototile (1 or 2)
  double col;
  TilePoint a, b, c;
};

inline TilePoint lerp(TilePoint p, TilePoint q, double t) {
  return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
}
inline TilePoint midpoint(TilePoint p, TilePoint q) {
  return {(p.x + q.x) / 2.0, (p.y + q.y) / 2.0};
}

struct TriTiling {
  int tiling;
  double alfa, col1, col2;
  Tile colour(int type, TilePoint a, TilePoint b, TilePoint c) const {
    return {type, type == 1 ? col1 : col2, a, b, c};
  }
};

// The prototile t (1 or 2) of the tiling, and the ratio its subdivision uses (JWildfire's init).
TriTiling triTiling(int tiling, double col1, double col2) {
  const double alfa = tiling == 1 || tiling == 4 ? 2.0 * std::cos(kTwoPi / 5.0)
                      : tiling == 3              ? 1.0 / 3.0
                      : tiling == 6              ? (1.0 / std::numbers::phi) * (1.0 / std::numbers::phi)
                                                 : 0.0;
  return {tiling, alfa, col1, col2};
}

Tile triPrototile(const TriTiling& s, int t) {
  const TilePoint o{0.0, 0.0};
  switch (s.tiling) {
    case 1:
      return t == 1
                 ? s.colour(1, o, {std::cos(kTwoPi / 5.0), std::sin(kTwoPi / 5.0)}, {2.0 * std::cos(kTwoPi / 5.0), 0.0})
                 : s.colour(2, o, {std::cos(kPi / 5.0), std::sin(kPi / 5.0)}, {2.0 * std::cos(kPi / 5.0), 0.0});
    case 2:
      return s.colour(t, o, {std::cos(kPi / 3.0), 0.0}, {0.0, std::sin(kPi / 3.0)});
    case 3:
      return t == 1 ? s.colour(1, o, {std::cos(kPi / 3.0), std::sin(kPi / 3.0)}, {2.0 * std::cos(kPi / 3.0), 0.0})
                    : s.colour(2, o, {std::cos(kPi / 6.0), std::sin(kPi / 6.0)}, {2.0 * std::cos(kPi / 6.0), 0.0});
    case 4:
      return s.colour(t, o, {std::cos(kTwoPi / 5.0), std::sin(kTwoPi / 5.0)}, {2.0 * std::cos(kTwoPi / 5.0), 0.0});
    case 5:
      return t == 1 ? s.colour(1, o, {0.0, 1.0}, {2.0, 0.0}) : s.colour(2, o, {0.0, 2.0}, {1.0, 0.0});
    default: {
      const double inv = 1.0 / std::numbers::phi;
      return t == 1 ? s.colour(1, o, {inv, std::sqrt(inv)}, {inv, 0.0})
                    : s.colour(2, o, {0.0, std::sqrt(inv)}, {1.0, 0.0});
    }
  }
}

// One child of `in`, picked by u (JWildfire's devis for each tiling).
Tile triSubdivide(const TriTiling& s, const Tile& in, double u) {
  const double al = s.alfa;
  const TilePoint a = in.a, b = in.b, c = in.c;
  const bool one = in.type == 1;
  switch (s.tiling) {
    case 1:  // FiveFold: Penrose triangles without rotations
      if (one) {
        const TilePoint p4 = lerp(b, c, al);
        return u < al * al ? s.colour(1, c, a, p4) : s.colour(2, b, p4, a);
      } else {
        const TilePoint p4 = lerp(c, a, al), p5 = lerp(c, b, al);
        return u < al * al         ? s.colour(2, b, p4, a)
               : u < 2.0 * al * al ? s.colour(2, c, p5, p4)
                                   : s.colour(1, b, p4, p5);
      }
    case 2: {  // trihex: two kinds swap places in half the children
      const TilePoint p4 = midpoint(a, c), p5 = midpoint(b, c), p6 = midpoint(a, p5);
      const int other = 3 - in.type;
      return u < 0.25   ? s.colour(in.type, p4, p5, c)
             : u < 0.5  ? s.colour(other, p4, p5, a)
             : u < 0.75 ? s.colour(other, p6, p5, b)
                        : s.colour(in.type, p6, a, b);
    }
    case 3:  // equithirds
      if (one) {
        const TilePoint p4 = lerp(a, c, 0.5), p5 = lerp(p4, b, al);
        return u < al ? s.colour(2, b, p5, a) : u < 2.0 * al ? s.colour(2, c, p5, b) : s.colour(2, a, p5, c);
      } else {
        const TilePoint p4 = lerp(a, c, al), p5 = lerp(c, a, al);
        return u < al ? s.colour(2, b, p4, a) : u < 2.0 * al ? s.colour(2, c, p5, b) : s.colour(1, p4, b, p5);
      }
    case 4: {  // overlapping Robinson triangles
      const TilePoint p4 = lerp(b, a, al), p5 = lerp(a, b, al), p6 = lerp(b, c, al);
      return u < 0.3 ? s.colour(2, p4, b, p6) : u < 0.63 ? s.colour(3 - in.type, p6, a, p5) : s.colour(1, c, a, p6);
    }
    case 5: {  // pinwheel: five children, ⌊5u⌋
      const int k = static_cast<int>(u * 5.0);
      if (one) {
        const TilePoint p4 = lerp(b, c, 0.2), p5 = lerp(b, c, 0.6), p6 = lerp(a, c, 0.5), p7 = lerp(a, p4, 0.5);
        const Tile children[5] = {s.colour(2, p4, a, b), s.colour(2, p7, p6, a), s.colour(1, p7, p4, p6),
                                  s.colour(1, p5, p6, p4), s.colour(2, p5, c, p6)};
        return children[std::clamp(k, 0, 4)];
      }
      const TilePoint p4 = lerp(c, b, 0.2), p5 = lerp(c, b, 0.6), p6 = lerp(a, b, 0.5), p7 = lerp(a, p4, 0.5);
      const Tile children[5] = {s.colour(1, p4, c, a), s.colour(1, p7, a, p6), s.colour(2, p7, p6, p4),
                                s.colour(2, p5, p4, p6), s.colour(1, p5, p6, b)};
      return children[std::clamp(k, 0, 4)];
    }
    default:  // golden pinwheel
      if (one) {
        const TilePoint p4 = lerp(a, b, al), p5 = lerp(b, a, al), p6 = lerp(c, b, al), p7 = lerp(a, c, al);
        return u < 0.146   ? s.colour(1, a, p4, p7)
               : u < 0.382 ? s.colour(2, p4, p7, p6)
               : u < 0.618 ? s.colour(2, c, p6, p7)
               : u < 0.764 ? s.colour(1, p4, p6, p5)
                           : s.colour(2, p5, p6, b);
      } else {
        const TilePoint p4 = lerp(b, a, al), p5 = lerp(b, c, al), p6 = lerp(c, b, al), p7 = lerp(a, c, al);
        const TilePoint p8 = lerp(c, a, al), p9 = lerp(p4, p7, al), p10 = lerp(p7, p4, al);
        return u < 0.146   ? s.colour(2, p4, b, p5)
               : u < 0.236 ? s.colour(1, p4, p5, p9)
               : u < 0.382 ? s.colour(2, p10, a, p4)
               : u < 0.472 ? s.colour(1, p7, a, p10)
               : u < 0.618 ? s.colour(2, p9, p5, p7)
               : u < 0.764 ? s.colour(2, p6, p5, p7)
               : u < 0.854 ? s.colour(1, p7, p6, p8)
                           : s.colour(2, p8, p6, c);
      }
  }
}

// JWildfire's steps and depths have no bound there (a large one makes it subdivide for ever); here a
// walk stops after this many steps, far below where the tiles become smaller than a double resolves.
constexpr double kMaxTileSteps = 64.0;

// A walk of subdivisions (JWildfire's loop): `steps` of them, and then, where the tile is not of kind
// eq, `depth` more (on 0: all at once after the last; on 1: one more per step while the walk is within
// depth of its end). Each child's kind enters `path` as a binary digit when path is not null.
struct TileWalk {
  double steps, on, eq, depth;
};
template <typename Draw>
Tile walkTiles(const TriTiling& s, Tile tile, const TileWalk& walk, std::int32_t* path, Draw&& draw) {
  double left = walk.steps, k = 1.0, taken = 0.0;
  while (left > 0.0 && taken < kMaxTileSteps) {
    tile = triSubdivide(s, tile, draw());
    taken += 1.0;
    if (path) *path = wrapAdd(wrapMul(2, *path), tile.type - 1);
    const bool other = tile.type != walk.eq;
    if (walk.on == 0.0) {
      if (k == walk.steps && other) left += walk.depth;
    } else if (k >= walk.steps && k < walk.steps + walk.depth && other) {
      left += 1.0;
    }
    left -= 1.0;
    k += 1.0;
  }
  return tile;
}

// JWildfire's discretNoise: Hugo Elias' integer hash (Java's wrapping int arithmetic) over [0, 1].
inline double discreteNoise(std::int32_t v) {
  const auto n = static_cast<std::uint32_t>(v);
  const std::uint32_t h = (n << 13) ^ n;
  const std::uint32_t r = h * (h * h * 15731u + 789221u) + 1376312589u;
  return static_cast<double>(r & 0x7fffffffu) / static_cast<double>(0x7fffffff);
}

// A uniform point of the triangle, as JWildfire's tile blur finds it: the corners sorted by x, then two
// draws pick a point of a parallelogram over half the triangle and fold it back in.
template <typename Draw>
TilePoint pointInTile(const Tile& tile, Draw&& draw) {
  TilePoint p1, p2, p3;
  const TilePoint a = tile.a, b = tile.b, c = tile.c;
  if (a.x <= b.x && a.x <= c.x) {
    p1 = a, p2 = b.x <= c.x ? b : c, p3 = b.x <= c.x ? c : b;
  } else if (b.x <= a.x && b.x <= c.x) {
    p1 = b, p2 = a.x <= c.x ? a : c, p3 = a.x <= c.x ? c : a;
  } else {
    p1 = c, p2 = a.x <= b.x ? a : b, p3 = a.x <= b.x ? b : a;
  }
  const double r1 = draw(), r2 = draw();
  TilePoint q;
  if (p1.x == p2.x && p2.x == p3.x) {
    double v1, v2;
    if (p1.y <= p2.y && p1.y <= p3.y) {
      v1 = p1.y, v2 = p3.y > p2.y ? p2.y : p3.y;
    } else if (p2.y <= p1.y && p2.y <= p3.y) {
      v1 = p2.y, v2 = p3.y > p1.y ? p1.y : p3.y;
    } else {
      v1 = p3.y, v2 = p2.y > p1.y ? p1.y : p2.y;
    }
    q = {p1.x, v1 + r1 * (v2 - v1)};
  } else if (p1.x == p2.x) {
    const TilePoint p4 = midpoint(p1, p3);
    const TilePoint p5{p3.x + p2.x - p4.x, p3.y + p2.y - p4.y}, p6{p1.x + p2.x - p4.x, p1.y + p2.y - p4.y};
    q = lerp(lerp(p3, p4, r1), lerp(p5, p2, r1), r2);
    const double edge = p3.y + (p2.y - p3.y) / (p2.x - p3.x) * (q.x - p3.x);
    const bool above = p2.y > p3.y + (p3.y - p1.y) / (p3.x - p1.x) * (p2.x - p3.x);
    if (above ? q.y > edge : q.y < edge) q = lerp(lerp(p2, p6, r1), lerp(p4, p1, r1), r2);
  } else {
    const TilePoint p4 = midpoint(p1, p3);
    const TilePoint p5{p1.x + p2.x - p4.x, p1.y + p2.y - p4.y}, p6{p3.x + p2.x - p4.x, p3.y + p2.y - p4.y};
    q = lerp(lerp(p1, p4, r1), lerp(p5, p2, r1), r2);
    const double edge = p1.y + (p2.y - p1.y) / (p2.x - p1.x) * (q.x - p1.x);
    const bool above = p2.y > p1.y + (p3.y - p1.y) / (p3.x - p1.x) * (p2.x - p1.x);
    if (above ? q.y > edge : q.y < edge) q = lerp(lerp(p2, p6, r1), lerp(p4, p3, r1), r2);
  }
  // Degenerate tiles: a point of the segment.
  if (p1.x == p2.x && p1.y == p2.y) q = lerp(p1, p3, r1);
  if (p1.x == p3.x && p1.y == p3.y) q = lerp(p1, p2, r1);
  if (p2.x == p3.x && p2.y == p3.y) q = lerp(p1, p2, r1);
  return q;
}

// dc_triTile: w · (a uniform point of the tile the walk ends on), z carried. The first walk (itt, on, eq,
// depth) starts from prototile t; from the kind it ends on, a second walk (itt1, … for kind 1; itt2, …
// for kind 2) records the kinds it passes as the binary digits of m. Colour index: (noise(m + 43) for
// kind 1, noise(m + 31) for kind 2) + col1 or col2 of the last tile's kind, mod 1 (Java's fmod).
// JWildfire's t other than 1 or 2 leaves its start triangle a point at the origin; here it is clamped.
VOXFLAME_VARIATION_TARGETS void dcTriTile(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const int tiling = static_cast<int>(jwfLimitedInt(P[0], 1.0, 6.0));
  const int t = jwfRound(P[1]) <= 1.0 ? 1 : 2;
  const TriTiling s = triTiling(tiling, P[2], P[3]);
  const auto limited = [](double v, double low, double high) { return jwfLimitedInt(v, low, high); };
  const TileWalk first{jwfRound(P[5]), limited(P[4], 0.0, 1.0), limited(P[6], 0.0, 2.0), jwfRound(P[7])};
  const TileWalk second[2] = {{jwfRound(P[9]), limited(P[8], 0.0, 1.0), limited(P[10], 0.0, 2.0), jwfRound(P[11])},
                              {jwfRound(P[13]), limited(P[12], 0.0, 1.0), limited(P[14], 0.0, 2.0), jwfRound(P[15])}};
  const Tile start = triPrototile(s, t);
  for (std::size_t i = 0; i < n; ++i) {
    const auto draw = [&] { return laneUniform(rnd[i]); };
    Tile tile = start;
    tile.col = 0.0;  // JWildfire's t2 starts with colour 0, which stays where no step is taken
    tile = walkTiles(s, tile, first, nullptr, draw);
    const int kind = tile.type;
    std::int32_t path = 0;
    tile = walkTiles(s, tile, second[kind == 1 ? 0 : 1], &path, draw);
    const double base = discreteNoise(wrapAdd(path, kind == 1 ? 43 : 31));
    const TilePoint q = pointInTile(tile, draw);
    outX[i] += w * q.x;
    outY[i] += w * q.y;
    outZ[i] += w * z[i];
    colour[i] = std::fmod(base + tile.col, 1.0);
  }
}

// ---- JWildfire's DC_BaseFunc variations: dc_quadtree, dc_ducks -------------------------------------
// (Their common kernel, dcBaseKernel, is in dc_base_kernel.h.)

// dc_quadtree (after Fabrice Neyret's shadertoy lljSDy): the square [0, 1]² (the point / zoom + ½) cut
// into quadrants level by level, each cell kept while a hash of its id, ½ + ½ sin(id + time) sin(2.17 id −
// time) sin(5.7 id + time), is at most 0.7, up to `levels` levels and cells of 1/width; the colour is (0.13
// n, 0.13 n, 1 + 0.13 n) after n levels, less 1 on a cell's border (0.3 r/width from it, r = 2ⁿ).
VOXFLAME_VARIATION_TARGETS void dcQuadtree(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  const double* P = in.params;
  const double zoom = std::isnan(P[0]) ? 0.1 : std::clamp(P[0], 0.1, 50.0), time = P[2];
  const double width = std::isnan(P[3]) ? 100.0 : std::clamp(P[3], 100.0, 1000.0);
  const double levels = jwfLimitedInt(P[4], 1.0, 50.0);
  const auto hash = [time](double p) {
    return 0.5 + 0.5 * std::sin(p + time) * std::sin(p * 2.17 - time) * std::sin(p * 5.7 + time);
  };
  dcBaseKernel(in, ox, oy, oz, 5, 0.5, [&](double px, double py) {
    double ux = px / zoom + 0.5, uy = py / zoom + 0.5, r = 1.0, id = 1.0;
    Rgb o{0.0, 0.0, 1.0};
    for (double level = 0.0; level < levels; level += 1.0) {
      if (std::min(std::min(ux, 1.0 - ux), std::min(uy, 1.0 - uy)) < 0.3 * r / width) {
        o = {o.r - 1.0, o.g - 1.0, o.b - 1.0};
        break;
      }
      if (hash(id) > 0.7) break;
      const double fx = ux < 0.5 ? 0.0 : 1.0, fy = uy < 0.5 ? 0.0 : 1.0;
      id = 4.0 * id + 2.0 * fy + fx;
      ux = ux * 2.0 - fx;
      uy = uy * 2.0 - fy;
      r *= 2.0;
      if (r > width) break;
      o = {o.r + 0.13, o.g + 0.13, o.b + 0.13};
    }
    return o;
  });
}

// JWildfire's G.atan2: a first-order approximation of the angle (exact at multiples of π/4), which
// dc_ducks' picture is made with.
inline double glslAtan2(double y, double x) {
  constexpr double kQuarter = kPi / 4.0, kThreeQuarters = 3.0 * kQuarter;
  const double ay = std::abs(y);
  const double angle =
      x >= 0.0 ? kQuarter - kQuarter * ((x - ay) / (x + ay)) : kThreeQuarters - kQuarter * ((x + ay) / (ay - x));
  return y < 0.0 ? -angle : angle;
}

// dc_ducks (after a shadertoy "ducks" fractal): the point·zoom iterated 50 times through e → (log |e'|, ∠e'
// − 6.2) + (0.1 sin(t/3) − 0.1, 5 + 0.1 cos(t/5)), e' = (e_x, |e_y|), t = time · 30/65, summing c = Σ |e|;
// d = 6 log₂ log₂(0.05 c), the colour (⌊½ + 1.1 f⌋/1.1 of f = (0.1 + 0.7 sin d, 0.1 + 0.5 sin(d − 0.7), 0.7
// + 0.7 cos(d − 0.7))) with its channels turned (b, r, g). Square [−1, 1]².
VOXFLAME_VARIATION_TARGETS void dcDucks(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  const double* P = in.params;
  const double t = P[1] / 65.0 * 30.0, zoom = P[2];
  const double stepX = 0.1 * std::sin(t / 3.0) - 0.1, stepY = 5.0 + 0.1 * std::cos(t / 5.0);
  dcBaseKernel(in, ox, oy, oz, 3, 1.0, [&](double px, double py) {
    double ex = px * zoom, ey = py * zoom, c = 0.0;
    for (int k = 0; k < 50; ++k) {
      const double ay = std::abs(ey);
      const double nx = std::log(std::sqrt(ex * ex + ay * ay)), ny = glslAtan2(ay, ex) - 6.2;
      ex = nx + stepX;
      ey = ny + stepY;
      c += std::sqrt(ex * ex + ey * ey);
    }
    const double d = std::log(std::log(c * 0.05) / std::log(2.0)) / std::log(2.0) * 6.0;
    const auto band = [](double f) { return std::floor(0.5 + f * 1.1) / 1.1; };
    const double fr = band(0.1 + 0.7 * std::sin(d)), fg = band(0.1 + 0.5 * std::sin(d - 0.7)),
                 fb = band(0.7 + 0.7 * std::cos(d - 0.7));
    return Rgb{fb, fr, fg};
  });
}

// dc_inversion (Jesus Sosa's, after a shadertoy of circle inversions): v = the point, 'iterations' times
// v ← inv(|v_x|, v_y) · scale + (sin 0.123t, atan 0.0567t)) with inv the inversion in the circle of radius
// 0.9 about (½, ½) followed by JWildfire's small twist (x += sin(x/1000)/cos(y/1000), then y +=
// sin(x/1000) cos(y/1000) with the new x), l = √(v_x⁴ + v_y⁴) of the last step and m the least l; the colour
// is 1 − e^(−c), c = b · 11 l² ((3 m (1 − m))⁵ + 0.14), b the unit vector of ½ + ½ (sin 1.79s, sin 1.345s,
// sin 1.123s), s = 2.1 + 0.025t. Square [−1, 1]².
VOXFLAME_VARIATION_TARGETS void dcInversion(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  const double* P = in.params;
  const double time = P[1];
  const double iterations = jwfLimitedInt(P[2], 0.0, 100.0);
  // setParameter clamps the scales into [1.1, 3] (a NaN passes, as through Tools.limitValue).
  const double scaleX = std::isnan(P[3]) ? P[3] : std::clamp(P[3], 1.1, 3.0);
  const double scaleY = std::isnan(P[4]) ? P[4] : std::clamp(P[4], 1.1, 3.0);
  const double offsetX = std::sin(time * 0.123), offsetY = std::atan(time * 0.0567);
  const double s = 2.1 + time * 0.025;
  double bx = std::sin(s * 1.790) * 0.5 + 0.5, by = std::sin(s * 1.345) * 0.5 + 0.5,
         bz = std::sin(s * 1.123) * 0.5 + 0.5;
  const double length = std::sqrt(bx * bx + by * by + bz * bz);
  bx /= length, by /= length, bz /= length;
  // Java's Math.min: NaN when either is.
  const auto javaMin = [](double a, double b) { return std::isnan(a) || std::isnan(b) ? a + b : std::min(a, b); };
  dcBaseKernel(in, ox, oy, oz, 5, 1.0, [&](double px, double py) {
    double vx = px, vy = py, l = 0.0, least = 10000.0;
    for (double k = 0.0; k < iterations; k += 1.0) {
      vx = std::abs(vx) * scaleX + offsetX;
      vy = vy * scaleY + offsetY;
      const double dx = vx - 0.5, dy = vy - 0.5;
      const double f = 0.9 * (0.9 / (dx * dx + dy * dy));
      vx = 0.5 - dx * f;
      vy = 0.5 - dy * f;
      vx += std::sin(vx * 0.001) / std::cos(vy * 0.001);
      vy += std::sin(vx * 0.001) * std::cos(vy * 0.001);
      l = std::sqrt(vx * vx * vx * vx + vy * vy * vy * vy);
      least = javaMin(l, least);
    }
    const double brightness = l * l * 11.0 * (std::pow(3.0 * least * (1.0 - least), 5.0) + 0.14);
    return Rgb{1.0 - std::exp(-bx * brightness), 1.0 - std::exp(-by * brightness), 1.0 - std::exp(-bz * brightness)};
  });
}

// dc_portal (Jesus Sosa's, after the shadertoys 4tBBRw and Xt2BzD): at uv = the point · zoom, with t = 1000 +
// time, c = 3 sin(t (1 + √|uv| / waves) + t/8 cos uv_x cos uv_y); the colour is (|c| − 1, |c| − 1.5, |c| − 2)
// where c > 0, else |c| − 1.5 in each channel (the shader's "metal" colour). Square [−½, ½]².
VOXFLAME_VARIATION_TARGETS void dcPortal(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  const double* P = in.params;
  const double t = 1000.0 + P[1], waves = P[2], zoom = P[3];
  dcBaseKernel(in, ox, oy, oz, 4, 0.5, [&](double px, double py) {
    const double ux = px * zoom, uy = py * zoom;
    const double d = 1.0 + std::sqrt(std::sqrt(ux * ux + uy * uy)) / waves;
    const double c = std::sin(d * t + t * 0.125 * std::cos(ux) * std::cos(uy)) * 3.0;
    const double a = std::abs(c);
    return c > 0.0 ? Rgb{a - 1.0, a - 1.5, a - 2.0} : Rgb{a - 1.5, a - 1.5, a - 1.5};
  });
}

// dc_menger (Jesus Sosa's): white inside a Sierpiński carpet, black outside. At q = 1.3 zoom · the point,
// d = the box's distance |max(|q| − 1, 0)| + min(max of |q| − 1, 0), then `level` times a = (s q mod 2) − 1
// (GLSL's mod), s ← 3s, d = max(d, (min |1 − 3|a|| − 1)/s); white where d ≤ 0. Square [−½, ½]².
VOXFLAME_VARIATION_TARGETS void dcMenger(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  const double* P = in.params;
  const double zoom = P[0], level = jwfLimitedInt(P[1], 1.0, 5.0);
  const auto glslMod = [](double v, double m) { return v - m * std::floor(v / m); };
  dcBaseKernel(in, ox, oy, oz, 2, 0.5, [&](double px, double py) {
    const double qx = px * zoom * 1.3, qy = py * zoom * 1.3;
    const double bx = std::abs(qx) - 1.0, by = std::abs(qy) - 1.0;
    const double outX = std::max(bx, 0.0), outY = std::max(by, 0.0);
    double d = std::sqrt(outX * outX + outY * outY) + std::min(std::max(bx, by), 0.0);
    double s = 1.0;
    for (double k = 0.0; k < level; k += 1.0) {
      const double ax = glslMod(qx * s, 2.0) - 1.0, ay = glslMod(qy * s, 2.0) - 1.0;
      const double rx = 1.0 - std::abs(ax) * 3.0, ry = 1.0 - std::abs(ay) * 3.0;
      s *= 3.0;
      d = std::max(d, (std::min(std::abs(rx), std::abs(ry)) - 1.0) / s);
    }
    const double c = d > 0.0 ? 0.0 : 1.0;
    return Rgb{c, c, c};
  });
}

// dc_tesla (Jesus Sosa's, after a shadertoy field): p = (zoom · the point, 1), s = ½, `levels` times m = |p|²
// s^|sin(time/8)|, p ← |p|/m + (−0.9, −0.23456 |sin time|, −1), a += e^(−k/style) e^(−strength |m/m'|^1.2) (m'
// the m before, 0 at first), tw += e^(−2k/style); strength = 20 + 0.03 ln(10⁻⁶ + fract(4500 sin 10 time)), a
// starting at 1.5, tw at 0 (JWildfire's CPU; its GPU code starts tw at 0.01). The grey max(0, 6 a/tw − 2).
// Square [−½, ½]².
VOXFLAME_VARIATION_TARGETS void dcTesla(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  const double* P = in.params;
  const double levels = jwfLimitedInt(P[0], 1.0, 25.0);
  const double style = std::isnan(P[1]) ? P[1] : std::clamp(P[1], 5.0, 100.0);
  const double time = P[3], zoom = P[4];
  const double wave = 4500.0 * std::sin(time * 10.0);
  const double strength = 20.0 + 0.03 * std::log(1e-6 + (wave - std::floor(wave)));
  const double shrink = std::pow(0.5, std::abs(std::sin(time / 8.0))), lift = -0.23456 * std::abs(std::sin(time));
  dcBaseKernel(in, ox, oy, oz, 5, 0.5, [&](double px, double py) {
    double vx = px * zoom, vy = py * zoom, vz = 1.0, accum = 1.5, previous = 0.0, tw = 0.0;
    for (double k = 0.0; k < levels; k += 1.0) {
      const double mag = (vx * vx + vy * vy + vz * vz) * shrink;
      vx = std::abs(vx) / mag - 0.9;
      vy = std::abs(vy) / mag + lift;
      vz = std::abs(vz) / mag - 1.0;
      const double weight = std::exp(-k / style);
      accum += weight * std::exp(-strength * std::pow(std::abs(mag / previous), 1.2));
      tw += weight * weight;
      previous = mag;
    }
    const double grey = std::max(0.0, 6.0 * accum / tw - 2.0);
    return Rgb{grey, grey, grey};
  });
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
      {count("random", 1.0, 0.0, 1000000.0),
       {"a", 0.75, -1.0, 1.0},
       {"b", 0.5, -1.0, 1.0},
       {"c", 0.25, -1.0, 1.0},
       {"startx", 0.0, -1.0, 1.0},
       {"starty", 0.0, -1.0, 1.0}});
  catalogue.back().table = &hopalongTable;
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
  add("dc_triTile",
      "w q, z: q a uniform point of a tile of a substitution tiling (type 1 FiveFold, 2 trihex, 3 equithirds, 4 "
      "overlapping Robinson, 5 pinwheel, 6 golden pinwheel) reached from prototile t by itt random subdivisions (depth "
      "more where the tile is not of kind eq: on 0 after the last, on 1 one per step), then itt1/itt2 more (with on, "
      "eq, depth of the same suffix) recording the kinds in the binary m; colour index (hash(m + 43 or 31) + col1 or "
      "col2 of the tile's kind) mod 1; the point itself is not used (JWildfire draws its defaults at random; these "
      "are in its ranges)",
      k2D, kRandom, &dcTriTile,
      {count("type", 1.0, 1.0, 6.0),
       count("t", 2.0, 1.0, 2.0),
       {"col1", 0.25, 0.0, 1.0},
       {"col2", 0.75, 0.0, 1.0},
       count("on", 0.0, 0.0, 1.0),
       count("itt", 3.0, 0.0, 10.0),
       count("eq", 1.0, 0.0, 2.0),
       count("depth", 1.0, 0.0, 5.0),
       count("on1", 0.0, 0.0, 1.0),
       count("itt1", 2.0, 0.0, 10.0),
       count("eq1", 1.0, 0.0, 2.0),
       count("depth1", 1.0, 0.0, 5.0),
       count("on2", 0.0, 0.0, 1.0),
       count("itt2", 2.0, 0.0, 10.0),
       count("eq2", 2.0, 0.0, 2.0),
       count("depth2", 1.0, 0.0, 5.0)});
  catalogue.back().directColour = true;
  const auto dcBaseParams = [&](std::vector<VariationParam> own) {
    own.push_back(count("ColorOnly", 0.0, 0.0, 1.0));
    own.push_back(count("Gradient", 0.0, 0.0, 2.0));
    own.push_back({"scale_z", 0.0, -2.0, 2.0});
    own.push_back({"offset_z", 0.0, -2.0, 2.0});
    own.push_back(count("reset_z", 1.0, 0.0, 1.0));
    return own;
  };
  // JWildfire's DC_BaseFunc painters: colour index or true colour from a picture, z from its grey level.
  const auto paintsLikeDcBase = [&] {
    VariationInfo& info = catalogue.back();
    info.directColour = info.readsSum = info.paintsRgb = true;
  };
  add("dc_quadtree",
      "w q, q = Ψ-uniform in [−½, ½]² (ColorOnly: the point); Gradient 2: colour index the grey level of Neyret's "
      "quadtree colour at q (cells split while ½ + ½ sin(id + time) sin(2.17 id − time) sin(5.7 id + time) ≤ 0.7, "
      "up to levels, cells of 1/width, zoom); Gradient 0 paints the point that RGB colour, 1 the palette's entry "
      "nearest to it, both leaving the index; z + grey · scale_z + "
      "offset_z (reset_z: z = that); seed is JWildfire's clock-driven time, which time overrides",
      k3D, kRandom, &dcQuadtree,
      dcBaseParams({{"zoom", 1.0, 0.1, 50.0},
                    count("seed", 10000.0, 0.0, 10000.0),
                    {"time", 0.0, 0.0, 100.0},
                    {"width", 1000.0, 100.0, 1000.0},
                    count("levels", 30.0, 1.0, 50.0)}));
  paintsLikeDcBase();
  add("dc_ducks",
      "w q, q = Ψ-uniform in [−1, 1]² (ColorOnly: the point); Gradient 2: colour index the grey level of the "
      "ducks fractal's colour at q·zoom (50 steps of e → (log |e'|, ∠e' − 6.2) + (0.1 sin(t/3) − 0.1, 5 + 0.1 "
      "cos(t/5)), e' = (e_x, |e_y|), t = 30 time/65, JWildfire's approximate angle); Gradient 0 paints the point "
      "that RGB colour, 1 the palette's entry nearest to it, both leaving the index; z + grey · scale_z + offset_z "
      "(reset_z: z = that); seed is JWildfire's "
      "clock-driven time, which time overrides",
      k3D, kRandom, &dcDucks,
      dcBaseParams({count("seed", 10000.0, 0.0, 10000.0), {"time", 10.0, 0.0, 100.0}, {"zoom", 1.0, -10.0, 10.0}}));
  paintsLikeDcBase();
  add("dc_inversion",
      "w q, q = Ψ-uniform in [−1, 1]² (ColorOnly: the point); Gradient 2: colour index the grey level of the "
      "circle-inversion colour at q (iterations steps of v → inv((|v_x|, v_y) · (scaleX, scaleY) + (sin 0.123 "
      "time, atan 0.0567 time)), inv the inversion in the circle of radius 0.9 about (½, ½) plus JWildfire's "
      "small twist; colour 1 − e^(−11 l² ((3m(1 − m))⁵ + 0.14) b), l the last √(v_x⁴ + v_y⁴), m the least, b a "
      "unit colour turning with time); Gradient 0 paints the point that RGB colour, 1 the palette's entry "
      "nearest to it, both leaving the index; z + grey · scale_z + offset_z (reset_z: z = that); seed is "
      "JWildfire's clock-driven time, which time overrides",
      k3D, kRandom, &dcInversion,
      dcBaseParams({count("seed", 10000.0, 0.0, 10000.0),
                    {"time", 0.0, 0.0, 100.0},
                    count("iterations", 50.0, 0.0, 100.0),
                    {"scaleX", 1.5, 1.1, 3.0},
                    {"scaleY", 1.5, 1.1, 3.0}}));
  paintsLikeDcBase();
  add("dc_portal",
      "w q, q = Ψ-uniform in [−½, ½]² (ColorOnly: the point); Gradient 2: colour index the grey level of the "
      "portal's colour at uv = q · zoom (c = 3 sin(t (1 + √|uv|/waves) + t/8 cos uv_x cos uv_y), t = 1000 + time; "
      "(|c| − 1, |c| − 1.5, |c| − 2) where c > 0, else |c| − 1.5 in each channel); Gradient 0 paints the point "
      "that RGB colour, 1 the palette's entry nearest to it, both leaving the index; z + grey · scale_z + offset_z "
      "(reset_z: z = that); seed is JWildfire's clock-driven time, which time overrides",
      k3D, kRandom, &dcPortal,
      dcBaseParams({count("seed", 1000.0, 0.0, 10000.0),
                    {"time", 0.0, 0.0, 100.0},
                    {"waves", 5.0, 0.0, 20.0},
                    {"zoom", 15.0, 0.0, 50.0}}));
  paintsLikeDcBase();
  add("dc_menger",
      "w q, q = Ψ-uniform in [−½, ½]² (ColorOnly: the point); Gradient 2: colour index the grey level of a "
      "Sierpiński carpet at 1.3 zoom · q (white inside, where the box's distance and level crosses' distances "
      "are all ≤ 0, else black); Gradient 0 paints the point that RGB colour, 1 the palette's entry nearest to it, "
      "both leaving the index; z + grey · scale_z + offset_z (reset_z: z = that)",
      k3D, kRandom, &dcMenger, dcBaseParams({{"zoom", 1.0, -10.0, 10.0}, count("level", 3.0, 1.0, 5.0)}));
  paintsLikeDcBase();
  add("dc_tesla",
      "w q, q = Ψ-uniform in [−½, ½]² (ColorOnly: the point); Gradient 2: colour index the grey level of a field "
      "at (zoom q, 1) (levels steps of p → |p|/m + (−0.9, −0.23456 |sin time|, −1), m = |p|² ½^|sin(time/8)|, "
      "summing e^(−k/style) e^(−strength |m/m'|^1.2); grey max(0, 6 a/tw − 2)); Gradient 0 paints the point that "
      "RGB colour, 1 the palette's entry nearest to it, both leaving the index; z + grey · scale_z + offset_z "
      "(reset_z: z = that); seed is JWildfire's clock-driven time, which time overrides",
      k3D, kRandom, &dcTesla,
      dcBaseParams({count("levels", 20.0, 1.0, 25.0),
                    {"style", 10.0, 5.0, 100.0},
                    count("seed", 10000.0, 0.0, 10000.0),
                    {"time", 0.0, 0.0, 100.0},
                    {"zoom", 4.0, -10.0, 10.0}}));
  paintsLikeDcBase();
}

}  // namespace voxflame::core
