// JWildfire variations that flame files in public repositories use and the other families lacked, so
// that those files imported with parts left out: mandelbrot (points near the Mandelbrot set's edge,
// found by a walk kept per lane), invsquircular, sph3D, colorscale_wf (z from the colour index),
// bubble_wf, bwraps2 (which files use as pre_bwraps2), invpolar, threeply (points of an orbit),
// spligon, lazysensen, disc3 and cpow3_wf. Each is a kernel below and one row of the table at the end
// (see variations.h for the notation and variation_kernels.h for what the files share). Each follows
// its JWildfire class (…/tina/variation/<Name>Func.java), quirks included where noted; random numbers
// come from the lane's own stream (laneUniform), where JWildfire draws from its own generators.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// JWildfire's Tools.FTOI: a parameter rounded half away from 0 (its int parameters are set so); NaN as 0.
inline double wildFtoi(double value) {
  return value > 0.0 ? std::trunc(value + 0.5) : (value < 0.0 ? std::trunc(value - 0.5) : 0.0);
}
// The same held in Java's int range, as JWildfire's int fields hold it.
inline double wildJavaInt(double value) {
  return std::clamp(wildFtoi(value), -2147483648.0, 2147483647.0);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- mandelbrot ------------------------------------------------------------------------------------
// JWildfire's MandelbrotFunc: a start c is drawn in [xmin, xmax) × [ymin, ymax) and iterated (z ← z² + c, at
// most iter times, while |z| < 2); without invert it is kept when it escapes, but not too fast (in at least
// 0.1 iter (1 − skin) steps), so the points lie on a skin outside the set; with invert when it stays. A start
// that was kept is the next call's seed: the next start is drawn within (skin + 0.001)/2 of it, so the lane
// walks along the set's edge; a start that stays (or escapes too fast, or skin = 1) makes the next call draw
// afresh. Up to ten starts per call; when the tenth is reached (JWildfire's k ≥ 10, which also counts the
// case where the tenth test found one) the point goes far away, (u, u), u = 50000 − 100000 Ψ. The result is
// w (c + (cx, cy)·z), and z gets the start's height Ψ rnd_z_range, unweighted (JWildfire adds its _z0 so).
// The walk (c and its height) is the lane's memory. With max_points > 0 (at least 100) a fresh start is
// one of max_points fixed starts picked by Ψ, start k made from seed and k by a hash (JWildfire records its
// first max_points starts from a generator seeded with seed and then cycles through them); seed is not used
// otherwise. iter is held at 10000 at most (JWildfire takes any).
constexpr std::size_t kMandelbrotState = 3;
constexpr double kMandelbrotMaxIter = 10000.0;

// Start k of max_points' fixed starts: three numbers in [0, 1) from seed and k, as laneUniform makes them
// from a state (the lowbias32 hash of both); the GPU makes the same.
inline void mandelbrotFixedStart(std::uint32_t seed, std::uint32_t k, double& u, double& v, double& t) {
  std::uint32_t h = seed * 0x9E3779B1u ^ (k + 1u) * 0x85EBCA77u;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  if (h == 0u) h = 0x6D2B79F5u;
  u = laneUniform(h);
  v = laneUniform(h);
  t = laneUniform(h);
}

VOXFLAME_VARIATION_TARGETS void mandelbrot(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double iter = std::min(wildJavaInt(P[0]), kMandelbrotMaxIter);
  const double xmin = P[1], xmax = P[2], ymin = P[3], ymax = P[4];
  const double invert = wildJavaInt(P[5]), skin = P[6], cx = P[7], cy = P[8];
  double maxPoints = wildJavaInt(P[9]);
  if (maxPoints > 0.0 && maxPoints < 100.0) maxPoints = 100.0;
  const auto seed = static_cast<std::uint32_t>(static_cast<std::int32_t>(wildJavaInt(P[10])));
  const double zRange = P[11];
  for (std::size_t i = 0; i < n; ++i) {
    double scratch[kMandelbrotState] = {0.0, 0.0, 0.0};
    double* memory = in.state ? in.state + kMandelbrotState * (in.lanes ? in.lanes[i] : i) : scratch;
    double x0 = memory[0], y0 = memory[1], z0 = memory[2];
    double x1 = x0, zx = x0, y1 = y0, zy = y0;
    const bool inverted = laneUniform(rnd[i]) < invert;
    double steps = inverted ? 0.0 : iter;
    int k = 0;
    while (k++ < 10 &&
           (inverted ? steps < iter : (steps >= iter || (skin < 1.0 && steps < 0.1 * iter * (1.0 - skin))))) {
      if (x0 == 0.0 && y0 == 0.0) {
        if (maxPoints > 0.0) {
          const double pick = std::min(std::floor(laneUniform(rnd[i]) * maxPoints), maxPoints - 1.0);
          double u = 0.0, v = 0.0, t = 0.0;
          mandelbrotFixedStart(seed, static_cast<std::uint32_t>(pick), u, v, t);
          x0 = (xmax - xmin) * u + xmin;
          y0 = (ymax - ymin) * v + ymin;
          z0 = t * zRange;
        } else {
          x0 = (xmax - xmin) * laneUniform(rnd[i]) + xmin;
          y0 = (ymax - ymin) * laneUniform(rnd[i]) + ymin;
          z0 = laneUniform(rnd[i]) * zRange;
        }
      } else {
        x0 = (skin + 0.001) * (laneUniform(rnd[i]) - 0.5) + x0;
        y0 = (skin + 0.001) * (laneUniform(rnd[i]) - 0.5) + y0;
      }
      x1 = zx = x0;
      y1 = zy = y0;
      steps = 0.0;
      while (zx * zx + zy * zy < 4.0 && steps < iter) {
        const double next = zx * zx - zy * zy + x0;
        zy = 2.0 * zx * zy + y0;
        zx = next;
        steps += 1.0;
      }
      if (steps >= iter || skin == 1.0 || steps < 0.1 * (iter * (1.0 - skin))) x0 = y0 = 0.0;
    }
    if (k >= 10) x1 = y1 = 50000.0 - laneUniform(rnd[i]) * 100000.0;
    memory[0] = x0;
    memory[1] = y0;
    memory[2] = z0;
    outX[i] += w * (x1 + cx * zx);
    outY[i] += w * (y1 + cy * zy);
    outZ[i] += z0;
  }
}

// ---- the plain maps --------------------------------------------------------------------------------

// invsquircular: the inverse of squircular (the disc onto the square): ρ = √(r² − √(r² (w² r² − 4x²y²)/w)) / √2,
// (ρ/x, ρ/y); the weight enters the formula instead of scaling the result, and weight 0 adds nothing. Where
// JWildfire's result is not finite (the origin, an axis, or w² r² < 4x²y², outside the square's image) the
// point is dropped (NaN in x, y and z, the chaos game's escape), as JWildfire resets such a point.
VOXFLAME_VARIATION_TARGETS void invsquircular(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0;
    if (w != 0.0) {
      const double u = x[i], v = y[i];
      const double r = u * u + v * v;
      const double r2 = std::sqrt(r * (w * w * r - 4.0 * u * u * v * v) / w);
      const double rho = std::sqrt(r - r2) / std::numbers::sqrt2;
      px = rho / u;
      py = rho / v;
    }
    const bool drop = !std::isfinite(px) || !std::isfinite(py);
    outX[i] += drop ? kNaN : px;
    outY[i] += drop ? kNaN : py;
    outZ[i] += drop ? kNaN : w * z[i];
  }
}

// sph3D (xyrus02's): w p / (|(x·px, y·py, z·px)|² + 10⁻²⁹). JWildfire scales z by the x parameter, not by z
// (its z parameter is unused), which is kept.
VOXFLAME_VARIATION_TARGETS void sph3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double px = P[0], py = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double xx = px * x[i], yy = py * y[i], zz = px * z[i];
    const double r = w / (xx * xx + yy * yy + zz * zz + 1e-29);
    outX[i] += x[i] * r;
    outY[i] += y[i] * r;
    outZ[i] += z[i] * r;
  }
}

// colorscale_wf: (w scale_x x, w scale_y y) and dz = colour · scale_z · w + offset_z, the colour index as the
// transform's blend left it: z of the sum becomes dz where reset_z > 0, else dz (times Ψ where sides > 0) is
// added. Ψ is drawn at every point (JWildfire draws it only where sides uses it).
VOXFLAME_VARIATION_TARGETS void colorscaleWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], sz = P[2], offsetZ = P[3];
  const bool reset = P[4] > 0.0, sides = P[5] > 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double draw = laneUniform(rnd[i]);
    const double dz = colour[i] * sz * w + offsetZ;
    outX[i] += w * sx * x[i];
    outY[i] += w * sy * y[i];
    outZ[i] = reset ? dz : outZ[i] + (sides ? dz * draw : dz);
  }
}

// bubble_wf: flam3's bubble (w p / (r²/4 + 1)) with z = ±w (2/(r²/4 + 1) − 1), the lower half where Ψ < ½: the
// whole sphere where bubble3D gives its upper half.
VOXFLAME_VARIATION_TARGETS void bubbleWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r = (x[i] * x[i] + y[i] * y[i]) / 4.0 + 1.0;
    const double t = w / r;
    const double side = laneUniform(rnd[i]) < 0.5 ? -1.0 : 1.0;
    outX[i] += t * x[i];
    outY[i] += t * y[i];
    outZ[i] += side * (w * (2.0 / r - 1.0));
  }
}

// bwraps2 (Xyrus02's, after slobo777's Bubble Wrap): bwraps as JWildfire's pre_bwraps2 and post_bwraps2 have
// it, which differ from Fractorium's bwraps (the `bwraps` entry) in the bubble's gain, g = gain²/cellsize +
// 10⁻⁶, and the default gain 2. |cellsize| < 10⁻³⁰⁰ leaves the point; z is carried. Where the bubble's radius
// squares to 0 its centre stays put (JWildfire's 0/0 there).
VOXFLAME_VARIATION_TARGETS void bwraps2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cellsize = P[0], space = P[1], gain = P[2], innerTwist = P[3], outerTwist = P[4];
  const bool cells = std::abs(cellsize) >= 1e-300;
  const double radius = 0.5 * (cellsize / (1.0 + space * space));
  const double g2 = gain * gain / cellsize + 1e-6;
  double maxBubble = g2 * radius;
  maxBubble = maxBubble > 2.0 ? 1.0 : maxBubble * (1.0 / (maxBubble * maxBubble / 4.0 + 1.0));
  const double r2 = radius * radius, rfactor = radius / maxBubble;
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    if (cells) {
      const double cx = (std::floor(x[i] / cellsize) + 0.5) * cellsize;
      const double cy = (std::floor(y[i] / cellsize) + 0.5) * cellsize;
      double lx = x[i] - cx, ly = y[i] - cy;
      if (!(lx * lx + ly * ly > r2)) {
        lx *= g2;
        ly *= g2;
        const double k = rfactor / ((lx * lx + ly * ly) / 4.0 + 1.0);
        lx *= k;
        ly *= k;
        const double t = r2 > 0.0 ? (lx * lx + ly * ly) / r2 : 0.0;
        const double theta = innerTwist * (1.0 - t) + outerTwist * t;
        const double s = std::sin(theta), c = std::cos(theta);
        px = cx + c * lx + s * ly;
        py = cy - s * lx + c * ly;
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// invpolar: the inverse of polar: ((1 + y) sin πx, (1 + y) cos πx).
VOXFLAME_VARIATION_2D(invpolar, {
  const double ny = 1.0 + y[i];
  outX[i] += w * ny * std::sin(x[i] * kPi);
  outY[i] += w * ny * std::cos(x[i] * kPi);
})

// threeply (James Henderson's orbit, as JWildfire has it): the point is ignored; JWildfire's variation keeps the
// orbit x′ = y − sgn(x) |sin x cos b + c − x sin(a + b + c)|, y′ = a − x from (0, 0) per render thread and adds
// 0.001 w (x′, y′) of its next point each call, assigning it (the terms before it are discarded). Lanes here that
// kept their own orbits would all step the same orbit in step with one another, so, as hopalong does, it draws
// one of the orbit's first 2²⁰ points instead (Ψ picks which): the same points with the same weights as a thread
// of JWildfire's with that many calls. An orbit that overflows starts again from (0, 0) (JWildfire's stays NaN).
constexpr std::size_t kThreeplyPoints = std::size_t{1} << 20;

struct ThreeplyOrbit {
  double a, b, c;
  std::vector<double> xy;  // (x, y) pairs, points 1 … kThreeplyPoints
};

std::shared_ptr<const ThreeplyOrbit> threeplyOrbit(double a, double b, double c) {
  thread_local std::shared_ptr<const ThreeplyOrbit> last;
  static RecentBuilds<ThreeplyOrbit> orbits(2);
  // Bitwise, so that a NaN parameter finds its orbit again instead of building one per call.
  const auto same = [&](const ThreeplyOrbit& orbit) {
    return std::bit_cast<std::uint64_t>(orbit.a) == std::bit_cast<std::uint64_t>(a) &&
           std::bit_cast<std::uint64_t>(orbit.b) == std::bit_cast<std::uint64_t>(b) &&
           std::bit_cast<std::uint64_t>(orbit.c) == std::bit_cast<std::uint64_t>(c);
  };
  return orbits.get(last, same, [&] {
    auto orbit = std::make_shared<ThreeplyOrbit>();
    orbit->a = a;
    orbit->b = b;
    orbit->c = c;
    orbit->xy.resize(2 * kThreeplyPoints);
    const double cosB = std::cos(b), sinABC = std::sin(a + b + c);
    double x0 = 0.0, y0 = 0.0;
    for (std::size_t k = 0; k < kThreeplyPoints; ++k) {
      const double sgn = x0 > 0.0 ? 1.0 : (x0 < 0.0 ? -1.0 : 0.0);
      const double xn = y0 - sgn * std::abs(std::sin(x0) * cosB + c - x0 * sinABC);
      const double yn = a - x0;
      orbit->xy[2 * k] = xn;
      orbit->xy[2 * k + 1] = yn;
      const bool finite = std::isfinite(xn) && std::isfinite(yn);
      x0 = finite ? xn : 0.0;
      y0 = finite ? yn : 0.0;
    }
    return std::shared_ptr<const ThreeplyOrbit>(std::move(orbit));
  });
}

VOXFLAME_VARIATION_TARGETS void threeply(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const std::shared_ptr<const ThreeplyOrbit> orbit = threeplyOrbit(P[0], P[1], P[2]);
  const double* __restrict xy = orbit->xy.data();
  constexpr double kPoints = static_cast<double>(kThreeplyPoints);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(std::min(std::floor(laneUniform(rnd[i]) * kPoints), kPoints - 1.0));
    outX[i] += 0.001 * xy[2 * k] * w;
    outY[i] += 0.001 * xy[2 * k + 1] * w;
    outZ[i] += w * z[i];
  }
}

// threeply's orbit for a backend of its own: (x, y) pairs, points 1 … kThreeplyPoints.
std::vector<double> threeplyTable(const double* params, const std::string*) {
  return threeplyOrbit(params[0], params[1], params[2])->xy;
}

// spligon (DarkBeam's): the point moved by r along the angle t = ⌊φ n/2π⌋ 2π/n − π i/(2n) of its sector of n
// (sides, a real number; one that rounds to 0 taken as 1): (x + r cos t, y + r sin t).
VOXFLAME_VARIATION_TARGETS void spligon(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = wildFtoi(P[0]) == 0.0 ? 1.0 : P[0], r = P[1];
  const double th = sides / kTwoPi, thi = 1.0 / th;
  const double j = kPi * P[2] / (-2.0 * sides);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = thi * std::floor(std::atan2(y[i], x[i]) * th) + j;
    outX[i] += w * (x[i] + std::cos(t) * r);
    outY[i] += w * (y[i] + std::sin(t) * r);
    outZ[i] += w * z[i];
  }
}

// lazysensen (bezo97's): each coordinate v with a scale s ≠ 0 is negated in every other band of width 1/s:
// where m = ⌊v s⌋ (Java's int) is odd and not negative, or even and negative. JWildfire also leaves the
// negated point for the transform's later variations; here it is this term's alone.
inline double lazysensenFlip(double v, double s) {
  if (s == 0.0) return v;
  const double m = static_cast<double>(javaInt(std::floor(v * s)));
  const double odd = std::fmod(m, 2.0);
  return (m >= 0.0 ? odd == 1.0 : odd == 0.0) ? -v : v;
}

VOXFLAME_VARIATION_TARGETS void lazysensen(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], sz = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * lazysensenFlip(x[i], sx);
    outY[i] += w * lazysensenFlip(y[i], sy);
    outZ[i] += w * lazysensenFlip(z[i], sz);
  }
}

// disc3 (Brad Stefanov's disc with coefficients): ρ = π √(d e x² + f g y²), (a h sin ρ, b h cos ρ) θ c/π.
VOXFLAME_VARIATION_2D(disc3, {
  const double rho = kPi * std::sqrt(x[i] * P[3] * x[i] * P[4] + y[i] * P[5] * y[i] * P[6]);
  const double sinr = std::sin(rho) * P[0], cosr = std::cos(rho) * P[1];
  const double r = w * std::atan2(x[i], y[i]) / kPi * P[2];
  outX[i] += sinr * P[7] * r;
  outY[i] += cosr * P[7] * r;
})

// cpow3_wf (Cozyg's, after cpow2): the angle φ moved by 2π n, n = Ψ₁ spread (truncated when discrete_spread ≥ 1,
// plus 1 where φ < 0), less 2π spread where cos(φ′/(2 spread)) < 2Ψ₂ − 1; then w e^{c/2 ln r² − d φ′} (cos α,
// sin α), c, d = r (cos, sin)(π a/2)/divisor. JWildfire multiplies where cpow2 adds: α = c φ′ · d/2 ln r² ·
// 2π/divisor · (Ψ₃ spread2 + offset2), which is kept.
VOXFLAME_VARIATION_TARGETS void cpow3Wf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double divisor = P[2], spread = P[3], spread2 = P[5], offset2 = P[6];
  const bool discrete = P[4] >= 1.0;
  const double ang = kTwoPi / divisor;
  const double c = P[0] * std::cos(kPi / 2.0 * P[1]) / divisor, d = P[0] * std::sin(kPi / 2.0 * P[1]) / divisor;
  const double halfC = c / 2.0, halfD = d / 2.0, invSpread = 0.5 / spread, fullSpread = kTwoPi * spread;
  for (std::size_t i = 0; i < n; ++i) {
    double a = std::atan2(y[i], x[i]);
    double turns = laneUniform(rnd[i]) * spread;
    if (discrete) turns = std::trunc(std::clamp(turns, -2147483648.0, 2147483647.0));
    if (a < 0.0) turns += 1.0;
    a += kTwoPi * turns;
    if (std::cos(a * invSpread) < laneUniform(rnd[i]) * 2.0 - 1.0) a -= fullSpread;
    const double lnr2 = std::log(x[i] * x[i] + y[i] * y[i]);
    const double r = w * std::exp(halfC * lnr2 - d * a);
    const double alpha = c * a * halfD * lnr2 * ang * (laneUniform(rnd[i]) * spread2 + offset2);
    outX[i] += r * std::cos(alpha);
    outY[i] += r * std::sin(alpha);
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addJwildfireWildVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  const auto count = &CatalogueAdder::count;

  add("mandelbrot",
      "w (c + (cx, cy)·z), Ψ rnd_z_range: c a start whose orbit z ← z² + c escapes |z| < 2 within iter steps but not "
      "before 0.1 iter (1 − skin) (stays, with invert), drawn in [xmin, xmax) × [ymin, ymax) or within (skin + "
      "0.001)/2 of the lane's last kept start, up to ten tries, else (u, u), u = 50000 − 100000 Ψ; z = the start's "
      "height, unweighted (JWildfire's; max_points > 0: fresh starts are max_points fixed ones made from seed; the "
      "point is not used)",
      k3D, kRandom, &mandelbrot,
      {count("iter", 100.0, 1.0, 1000.0),
       {"xmin", -1.6, -3.0, 1.0},
       {"xmax", 1.6, -1.0, 3.0},
       {"ymin", -1.2, -2.0, 1.0},
       {"ymax", 1.2, -1.0, 2.0},
       count("invert", 0.0, 0.0, 1.0),
       {"skin", 0.012, 0.0, 1.0},
       {"cx", 0.0, -1.5, 1.5},
       {"cy", 0.0, -1.5, 1.5},
       count("max_points", -1.0, -1.0, 100000.0),
       count("seed", 1234.0, 0.0, 1000000.0),
       {"rnd_z_range", 0.0, -1.0, 1.0}});
  catalogue.back().laneState = kMandelbrotState;
  add("invsquircular",
      "(ρ/x, ρ/y), ρ = √(r² − √(r² (w² r² − 4x²y²)/w)) / √2, not scaled by w; z; dropped where not finite "
      "(JWildfire's)",
      k2D, kFixed, &invsquircular);
  add("sph3D", "p / (|(x·px, y·py, z·px)|² + 10⁻²⁹) (xyrus02's, as JWildfire has it: z scaled by px, pz unused)", k3D,
      kFixed, &sph3D, {{"x", 0.75, -2.0, 2.0}, {"y", 1.0, -2.0, 2.0}, {"z", 0.5, -2.0, 2.0}});
  add("colorscale_wf",
      "(scale_x x, scale_y y), and dz = colour · scale_z · w + offset_z: z of the sum becomes dz where reset_z > 0, "
      "else dz (dz Ψ where sides > 0) is added; the colour index is the transform's (JWildfire's)",
      k3D, kRandom, &colorscaleWf,
      {{"scale_x", 0.0, -1.0, 1.0},
       {"scale_y", 0.0, -1.0, 1.0},
       {"scale_z", 0.5, -1.0, 1.0},
       {"offset_z", 0.0, -1.0, 1.0},
       {"reset_z", 0.0, 0.0, 1.0},
       {"sides", 0.0, 0.0, 1.0}});
  catalogue.back().directColour = true;
  catalogue.back().readsSum = true;
  add("bubble_wf", "(x, y) / (r²/4 + 1), ±(2/(r²/4 + 1) − 1), − where Ψ < ½: the whole sphere (JWildfire's)", k3D,
      kRandom, &bubbleWf);
  add("bwraps2",
      "bwraps with the bubble's gain g = gain²/cellsize + 10⁻⁶: in the bubble of radius ρ = cellsize/(2(1 + space²)) "
      "at the centre C of the point's cell, C + R(θ)·q, q = (p − C)·g·k/(|p − C|²g²/4 + 1), k = ρ/b, b = gρ/((gρ)²/4 "
      "+ 1) (1 when gρ > 2), θ = inner_twist (1 − |q|²/ρ²) + outer_twist |q|²/ρ²; elsewhere p; z (Xyrus02's, as "
      "JWildfire's pre_bwraps2 and post_bwraps2 have it)",
      k2D, kFixed, &bwraps2,
      {{"cellsize", 1.0, 0.0, 5.0},
       {"space", 0.0, -2.0, 2.0},
       {"gain", 2.0, -5.0, 5.0},
       {"inner_twist", 0.0, -kPi, kPi},
       {"outer_twist", 0.0, -kPi, kPi}});
  add("invpolar", "((1 + y) sin πx, (1 + y) cos πx) (JWildfire's)", k2D, kFixed, &invpolar);
  add("threeply",
      "0.001 w h_k, z: h_k point k = 1 + ⌊2²⁰ Ψ⌋ of the orbit of (0, 0) under x′ = y − sgn(x) |sin x cos b + c − x "
      "sin(a + b + c)|, y′ = a − x; the point is not used, the terms before it are discarded. JWildfire adds the "
      "orbit's next point each call; here one of its first 2²⁰ points is drawn (James Henderson's)",
      k2D, kRandom, &threeply, {{"a", -55.0, -100.0, 100.0}, {"b", -1.0, -10.0, 10.0}, {"c", -42.0, -100.0, 100.0}});
  catalogue.back().table = &threeplyTable;
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("spligon",
      "(x + r cos t, y + r sin t), t = ⌊φ n/2π⌋ 2π/n − π i/(2n), n = sides (1 where it rounds to 0) (DarkBeam's)", k2D,
      kFixed, &spligon, {{"sides", 3.0, 1.0, 12.0}, {"r", 1.0, -1.5, 1.5}, {"i", 1.0, -10.0, 10.0}});
  add("lazysensen",
      "p with each coordinate v negated where m = ⌊v·scale⌋ is odd and ≥ 0 or even and < 0 (scale 0: kept) "
      "(bezo97's)",
      k3D, kFixed, &lazysensen,
      {{"scale_x", 1.0, -5.0, 5.0}, {"scale_y", 1.0, -5.0, 5.0}, {"scale_z", 0.0, -5.0, 5.0}});
  add("disc3", "(a h sin ρ, b h cos ρ) c θ/π, ρ = π √(d e x² + f g y²) (Brad Stefanov's)", k2D, kFixed, &disc3,
      {{"a", 1.0, -2.0, 2.0},
       {"b", 1.0, -2.0, 2.0},
       {"c", 1.0, -2.0, 2.0},
       {"d", 1.0, -2.0, 2.0},
       {"e", 1.0, -2.0, 2.0},
       {"f", 1.0, -2.0, 2.0},
       {"g", 1.0, -2.0, 2.0},
       {"h", 1.0, -2.0, 2.0}});
  add("cpow3_wf",
      "e^{c/2 ln r² − d φ′} (cos α, sin α), φ′ = φ + 2π n − (2π spread where cos(φ′/(2 spread)) < 2Ψ₂ − 1), n = "
      "Ψ₁ spread (whole when discrete_spread ≥ 1; + 1 where φ < 0), c, d = r (cos, sin)(π a/2)/divisor, α = c φ′ · d/2 "
      "ln r² · 2π/divisor · (Ψ₃ spread2 + offset2) (Cozyg's, as JWildfire has it, a product where cpow2 has a sum)",
      k2D, kRandom, &cpow3Wf,
      {{"r", 1.0, 0.0, 3.0},
       {"a", 0.1, -1.0, 1.0},
       {"divisor", 1.0, -5.0, 5.0},
       {"spread", 1.0, 0.0, 5.0},
       {"discrete_spread", 1.0, 0.0, 1.0},
       {"spread2", 0.0, -1.0, 1.0},
       {"offset2", 1.0, -2.0, 2.0}});
}

}  // namespace voxflame::core
