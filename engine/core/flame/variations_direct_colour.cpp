// Fractorium's direct-colour variations (its VariationsDC.h, after the Apophysis 7X plugins of the same
// names): besides moving the point they set its colour index (VariationInput::colour) from where
// the point is, which the transform then blends in by its direct_color (flame.h). Each variation is
// a kernel below and one row of the table at the end (see variations.h for the notation and
// variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/flame/noise.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// The colour of dc_bubble, dc_cylinder and dc_linear is taken at the sum of the transform's
// ordinary terms up to and including this one (Fractorium's outPoint plus the term's own result);
// for a pre_ or post_ term, at the term's input point plus its result. An ordinary term's output
// arrays hold that running sum; a pre_/post_ term's start from 0 (chaos_game.cpp), so the input
// point is added instead.
inline double sumWeight(const VariationInput& in) {
  return in.stage == VariationStage::Normal ? 0.0 : 1.0;
}

// Fractorium's 1 / scale with a zero scale taken as 1e-5 ("10E-6" in its source).
inline double inverseScale(double scale) {
  return 1.0 / (scale == 0.0 ? 1e-5 : scale);
}

// dc_bubble: flam3's bubble with z = w (2/s − 1), s = w / (r²/4 + 1), Fractorium's; the colour is
// the squared distance of the running sum from (−centerx, −centery) over scale, mod 1.
VOXFLAME_VARIATION_TARGETS void dcBubble(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1], inv = inverseScale(P[2]), sum = sumWeight(in);
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double s = w / fractoriumZeps(r2 / 4.0 + 1.0);
    outX[i] += s * x[i];
    outY[i] += s * y[i];
    outZ[i] += w * (2.0 / s - 1.0);
    const double tx = outX[i] + sum * x[i] + cx, ty = outY[i] + sum * y[i] + cy;
    colour[i] = laneFmod(std::abs(inv * (tx * tx + ty * ty)), 1.0);
  }
}

// dc_carpet: p + (±1, ±1) (two random signs) through the transform's own 2D affine map read in
// Apophysis' order, which is Fractorium's (x' = a x + b y + e, y' = c x + d y + f in flam3's
// letters); the colour halves and moves towards 0 or 1 by which quadrant was taken, so the
// carpet's levels get their own colours.
VOXFLAME_VARIATION_TARGETS void dcCarpet(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double* a = in.affine;
  const double ca = a[0], cb = a[kAffineB], cc = a[kAffineC], cd = a[4], ce = a[kAffineE], cf = a[kAffineF];
  const double h0 = 0.1 * P[0];
  for (std::size_t i = 0; i < n; ++i) {
    // Fractorium's x0, y0 = ±1 and their integer xor: 0 when the signs agree, −2 when they differ.
    const double x0 = laneUniform(rnd[i]) < 0.5 ? 1.0 : -1.0;
    const double y0 = laneUniform(rnd[i]) < 0.5 ? 1.0 : -1.0;
    const double px = x[i] + x0, py = y[i] + y0;
    const double xr = x0 == y0 ? 0.0 : -2.0;
    const double h = -h0 + (1.0 - xr) * h0;
    outX[i] += w * (ca * px + cb * py + ce);
    outY[i] += w * (cc * px + cd * py + cf);
    outZ[i] += w * z[i];
    colour[i] = laneFmod(std::abs(colour[i] * 0.5 * (1.0 + h) + xr * (1.0 - h) * 0.5), 1.0);
  }
}

// dc_cube: a random point on one of the cube's six faces (scaled by x, y, z), coloured c1…c6 by
// the face (each clamped into [0, 1]).
VOXFLAME_VARIATION_TARGETS void dcCube(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  double face[6];
  for (int k = 0; k < 6; ++k) face[k] = std::clamp(P[k], 0.0, 1.0);
  const double sx = P[6], sy = P[7], sz = P[8];
  for (std::size_t i = 0; i < n; ++i) {
    const double p = 2.0 * laneUniform(rnd[i]) - 1.0;
    const double q = 2.0 * laneUniform(rnd[i]) - 1.0;
    const double axis = std::floor(3.0 * laneUniform(rnd[i]));  // Fractorium's Rand(3)
    const bool negative = laneUniform(rnd[i]) < 0.5;            // its RandBit
    const double side = negative ? -1.0 : 1.0;
    double px, py, pz, c;
    if (axis == 0.0) {
      px = side, py = p, pz = q;
      c = negative ? face[0] : face[1];
    } else if (axis == 1.0) {
      px = p, py = side, pz = q;
      c = negative ? face[2] : face[3];
    } else {
      px = p, py = q, pz = side;
      c = negative ? face[4] : face[5];
    }
    outX[i] += w * px * sx;
    outY[i] += w * py * sy;
    outZ[i] += w * pz * sz;
    colour[i] = c;
  }
}

// dc_cylinder: a blurred cylinder, w (sin(x + ρ sin τ) x_scale, ·, cos(x + ρ cos τ)) with
// y' = ρ + y·y_scale, τ = 2πΨ, ρ = blur (Ψ₁ + Ψ₂ + Ψ₃ + Ψ₄ − 2); Fractorium leaves the weight off
// y', and so does this port. The colour is dc_linear's.
VOXFLAME_VARIATION_TARGETS void dcCylinder(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double offset = P[0], sina = std::sin(P[1]), cosa = std::cos(P[1]), inv = inverseScale(P[2]);
  const double sx = P[3], sy = P[4], blur = P[5], sum = sumWeight(in);
  for (std::size_t i = 0; i < n; ++i) {
    const double turn = laneUniform(rnd[i]) * kTwoPi;
    const double r = blur * laneGauss(rnd[i]);
    const double px = w * std::sin(x[i] + r * std::sin(turn)) * sx;
    const double py = r + y[i] * sy;
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * std::cos(x[i] + r * std::cos(turn));
    const double tx = outX[i] + sum * x[i], ty = outY[i] + sum * y[i];
    colour[i] = laneFmod(std::abs(0.5 * (inv * (cosa * tx + sina * ty + offset) + 1.0)), 1.0);
  }
}

// dc_gridout: gridout's step of one unit along the square spiral, by the rounded point's octant; a
// horizontal step adds ¼ to the colour, a vertical one ¾ (mod 1).
VOXFLAME_VARIATION_TARGETS void dcGridout(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = apophysisRound(x[i]), ry = apophysisRound(y[i]);
    // Fractorium's four quadrant cases, each splitting on a diagonal.
    bool alongX;
    double step;
    if (ry <= 0.0) {
      if (rx > 0.0) {
        alongX = -ry >= rx;
        step = 1.0;
      } else {
        alongX = ry <= rx;
        step = alongX ? 1.0 : -1.0;
      }
    } else if (rx > 0.0) {
      alongX = ry >= rx;
      step = alongX ? -1.0 : 1.0;
    } else {
      alongX = ry > -rx;
      step = -1.0;
    }
    const double dx = alongX ? step : 0.0, dy = alongX ? 0.0 : step;
    outX[i] += w * (x[i] + dx);
    outY[i] += w * (y[i] + dy);
    outZ[i] += w * z[i];
    colour[i] = laneFmod(colour[i] + (alongX ? 0.25 : 0.75), 1.0);
  }
}

// dc_linear: linear (w p), coloured by the running sum's position along the direction `angle`:
// ½ (⟨(cos angle, sin angle), s⟩ + offset) / scale + ½, mod 1.
VOXFLAME_VARIATION_TARGETS void dcLinear(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double offset = P[0], sina = std::sin(P[1]), cosa = std::cos(P[1]), inv = inverseScale(P[2]);
  const double sum = sumWeight(in);
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * x[i];
    outY[i] += w * y[i];
    outZ[i] += w * z[i];
    const double tx = outX[i] + sum * x[i], ty = outY[i] + sum * y[i];
    colour[i] = laneFmod(std::abs(0.5 * (inv * (cosa * tx + sina * ty + offset) + 1.0)), 1.0);
  }
}

// Fractorium's PerlinNoise3D: octaves of simplex noise, the amplitude divided by amps and the
// frequency multiplied by freqs each octave. Fractorium scales x twice and z never from one octave
// to the next; flames made with it look that way, so this does too. The noise is voxflame's
// (noise.h), whose gradients are not Fractorium's: the same kind of texture, not the same one.
double perlinNoise(double x, double y, double z, double amps, double freqs, int octaves) {
  double total = 0.0, a = 1.0;
  for (int k = 0; k < octaves; ++k) {
    total += simplexNoise3D(x, y, z) / fractoriumZeps(a);
    a *= amps;
    x *= freqs;
    y *= freqs;
    x *= freqs;
  }
  return total;
}

// dc_perlin: a random point of a square, disc or blur (shape) in the unit square about the origin,
// mapped (flat, spherical, ...) into noise space; points whose noise (with the edge effect) falls
// outside the notch select_centre ± select_range are drawn again, up to select_bailout times; the
// colour is centre + range · noise + color_seed, mod 1. color_seed is pyr3's (a web renderer whose
// dc_perlin colours by a hue from the noise, turned round the hue circle by color_seed): here it
// turns the index round the palette the same way; its default 0 is Fractorium's and JWildfire's.
void dcPerlin(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shape = fractoriumInteger(P[0], 0.0, 2.0), map = fractoriumInteger(P[1], 0.0, 5.0);
  const double selectCentre = std::clamp(P[2], -1.0, 1.0), selectRange = std::clamp(P[3], 0.1, 2.0);
  const double centre = P[4], range = P[5], edge = P[6], scale = P[7];
  const int octaves = static_cast<int>(fractoriumInteger(P[8], 1.0, 5.0));
  const double amps = P[9], freqs = P[10], z0 = P[11];
  const int bailout = static_cast<int>(fractoriumInteger(P[12], 2.0, 1000.0));
  // A non-finite seed would make every colour NaN: it turns nothing then.
  const double seed = std::isfinite(P[13]) ? P[13] : 0.0;
  double bottom = selectCentre - selectRange, top = selectCentre + selectRange;
  bottom = bottom > 0.75 ? 0.75 : (bottom < -2.0 ? -3.0 : bottom);
  top = top < -0.75 ? -0.75 : (top > 3.0 ? 3.0 : top);
  for (std::size_t i = 0; i < n; ++i) {
    double vx = 0.0, vy = 0.0, p = 0.0, e = 0.0;
    int tries = 0;
    do {
      e = 0.0;
      double r;
      if (shape == 0.0) {
        vx = (1.0 + edge) * (laneUniform(rnd[i]) - 0.5);
        vy = (1.0 + edge) * (laneUniform(rnd[i]) - 0.5);
        r = std::max(std::abs(vx), std::abs(vy));
        if (r > 1.0 - edge) e = 0.5 * (r - 1.0 + edge) / edge;
      } else {
        if (shape == 1.0) {
          r = laneUniform(rnd[i]) + laneUniform(rnd[i]);
          r = (r > 1.0 ? 2.0 - r : r) * (1.0 + edge);
        } else {
          r = (1.0 + edge) * laneUniform(rnd[i]);
        }
        if (r > 1.0 - edge) e = 0.5 * (r - 1.0 + edge) / edge;
        const double theta = laneUniform(rnd[i]) * kTwoPi;
        vx = 0.5 * r * std::sin(theta);
        vy = 0.5 * r * std::cos(theta);
      }
      const double r2 = vx * vx + vy * vy;
      double nx = scale * vx, ny = scale * vy, nz = scale * z0;
      if (map == 1.0 || map == 2.0 || map == 3.0) {
        const double f = map == 1.0 ? 1.0 / fractoriumZeps(r2) : 1.0 / (r2 + (map == 2.0 ? 0.5 : 0.25));
        nx *= f;
        ny *= f;
      } else if (map == 4.0 || map == 5.0) {
        const double lift = std::sqrt(std::abs(0.25 - r2));
        nz = scale * ((map == 4.0 ? 1.0 : 2.0) * lift + z0);
      }
      p = perlinNoise(nx, ny, nz, amps, freqs, octaves);
      e = p > 0.0 ? p * (1.0 + e * e * 20.0) + 2.0 * e : p * (1.0 + e * e * 20.0) - 2.0 * e;
    } while ((e < bottom || e > top) && tries++ < bailout);
    outX[i] += w * vx;
    outY[i] += w * vy;
    outZ[i] += w * z[i];
    const double c = centre + range * p + seed;
    colour[i] = c - std::floor(c);
  }
}

// dc_triangle: the point in barycentric coordinates (u, v) of the triangle the transform's affine
// map spans (origin (e, f), edges (a, b) and (−c, −d), Apophysis' reading as in dc_carpet); a point
// outside is moved onto its edge and, by scatter_area, scattered back in (or sent to the origin
// with zero_edges). The colour is u + v, mod 1. Fractorium draws only for points outside; here
// every lane draws its two numbers, so the loop has no branch on the draw.
VOXFLAME_VARIATION_TARGETS void dcTriangle(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double* a = in.affine;
  const double xx = a[0], xy = a[kAffineB], yx = -a[kAffineC], yy = -a[4], cx = a[kAffineE], cy = a[kAffineF];
  const double spread = std::clamp(P[0], -1.0, 1.0);
  const bool zeroEdges = fractoriumInteger(P[1], 0.0, 1.0) != 0.0;
  const double dot00 = xx * xx + xy * xy, dot01 = xx * yx + xy * yy, dot11 = yx * yx + yy * yy;
  // A degenerate triangle (an identity affine read this way has a zero edge) puts every point at
  // the origin corner instead of Fractorium's 0/0.
  const double denom = fractoriumZeps(dot00 * dot11 - dot01 * dot01);
  // Onto the edge u + v = 1 from beyond it.
  const auto ontoEdge = [](double& u, double& v) {
    if (u > v) {
      u = std::min(u, 1.0);
      v = 1.0 - u;
    } else {
      v = std::min(v, 1.0);
      u = 1.0 - v;
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double ru = laneUniform(rnd[i]), rv = laneUniform(rnd[i]);
    const double px = x[i] - cx, py = y[i] - cy;
    const double dot02 = xx * px + xy * py, dot12 = yx * px + yy * py;
    double u = (dot11 * dot02 - dot01 * dot12) / denom;
    double v = (dot00 * dot12 - dot01 * dot02) / denom;
    bool inside = false;
    double f = 1.0;
    if (u + v > 1.0) {
      f = -1.0;
      ontoEdge(u, v);
    } else if (u < 0.0 || v < 0.0) {
      u = std::clamp(u, 0.0, 1.0);
      v = std::clamp(v, 0.0, 1.0);
    } else {
      inside = true;
    }
    if (!inside) {
      if (zeroEdges) {
        u = v = 0.0;
      } else {
        u = std::clamp(u + ru * spread * f, -1.0, 1.0);
        v = std::clamp(v + rv * spread * f, -1.0, 1.0);
        if (u + v > 1.0 && spread > 0.0) ontoEdge(u, v);
      }
    }
    outX[i] += w * (cx + u * xx + v * yx);
    outY[i] += w * (cy + u * xy + v * yy);
    outZ[i] += w * z[i];
    colour[i] = laneFmod(std::abs(u + v), 1.0);
  }
}

// dc_ztransl: z from the colour index: zf = factor (c − x0) / (x1 − x0) (x0 ≤ x1 sorted, clamped
// into [0, 1] with clamp), and z' = w zf (overwrite) or w z zf; x and y as linear.
VOXFLAME_VARIATION_TARGETS void dcZtransl(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double a = std::clamp(P[0], 0.0, 1.0), b = std::clamp(P[1], 0.0, 1.0);
  const double low = std::min(a, b), span = fractoriumZeps(std::max(a, b) - low);
  const double factor = P[2];
  const bool overwrite = fractoriumInteger(P[3], 0.0, 1.0) != 0.0;
  const bool clamp = fractoriumInteger(P[4], 0.0, 1.0) != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double zf = factor * (colour[i] - low) / span;
    if (clamp) zf = std::clamp(zf, 0.0, 1.0);
    outX[i] += w * x[i];
    outY[i] += w * y[i];
    outZ[i] += overwrite ? w * zf : w * z[i] * zf;
  }
}

// Bob Jenkins' 32-bit integer hash as Fractorium's VarFuncs::Hash has it, over INT_MAX: in [−1, 1].
inline double jenkinsHash(std::int32_t a) {
  a = (a ^ 61) ^ (a >> 16);
  a = wrapAdd(a, wrapMul(a, 8));
  a = a ^ (a >> 4);
  a = wrapMul(a, 0x27d4eb2d);
  a = a ^ (a >> 15);
  return static_cast<double>(a) / 2147483647.0;
}

// randCubes: blocks of a city: a random block (x and y each ⌊±spread ln Ψ⌋) whose height is
// hashed from its indices and seed; the point lies in the block (density spreads the blocks) at a
// height fading downwards, and the colour is half the height. Fractorium ignores the weight and
// discards the terms summed before it (as mirror_x does).
VOXFLAME_VARIATION_TARGETS void randCubes(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double size = P[0], height = P[1], spread = P[2], seed = fractoriumInteger(P[3], -1e6, 1e6), density = P[4];
  for (std::size_t i = 0; i < n; ++i) {
    // 1 − Ψ is in (0, 1], so the logarithm is finite.
    const double lx = std::log(1.0 - laneUniform(rnd[i]));
    const double bx = std::floor(lx * (laneUniform(rnd[i]) < 0.5 ? spread : -spread));
    const double ly = std::log(1.0 - laneUniform(rnd[i]));
    const double by = std::floor(ly * (laneUniform(rnd[i]) < 0.5 ? spread : -spread));
    const double h = jenkinsHash(javaInt(bx * seed)) + jenkinsHash(javaInt(bx + by * seed));
    outX[i] += (bx * density + laneUniform(rnd[i])) * size;
    outY[i] += (by * density + laneUniform(rnd[i])) * size;
    outZ[i] += height * h * std::pow(laneUniform(rnd[i]), 0.125);
    colour[i] = h / 2.0;
  }
}

// Fractorium's Powq4c: |v|^p with v's sign (SignNz: 0 counts as +), or v itself when p is 1.
inline double powq4c(double v, double p) {
  return p == 1.0 ? v : std::pow(std::abs(v), p) * (v < 0.0 ? -1.0 : 1.0);
}
// Fractorium's Spread: the length of (a, b) with a's sign (+ only for a > 0).
inline double spreadOf(double a, double b) {
  return std::hypot(a, b) * (a > 0.0 ? 1.0 : -1.0);
}

// curl_sp: curl on the signed powers of the coordinates, its denominator spread by sx, sy and
// taken to the 1/pow; the colour moves by 0.1 dc times that denominator, clamped into [0, 1]
// (Fractorium's flam3-compatible branch; without it, the colour is left alone).
VOXFLAME_VARIATION_TARGETS void curlSp(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = fractoriumZeps(P[0]), inversePower = 1.0 / power;
  const double c1 = P[1], c2 = P[2], sx = P[3], sy = P[4], dcAdjust = 0.1 * P[5];
  for (std::size_t i = 0; i < n; ++i) {
    const double px = powq4c(x[i], power), py = powq4c(y[i], power), pz = powq4c(z[i], power);
    const double d = px * px - py * py;
    const double re = spreadOf(c1 * px + c2 * d, sx) + 1.0;
    const double im = spreadOf(c1 * py + 2.0 * c2 * px * py, sy);
    const double c = fractoriumZeps(powq4c(re * re + im * im, inversePower));
    const double r = w / c;
    outX[i] += (px * re + py * im) * r;
    outY[i] += (py * re - px * im) * r;
    outZ[i] += pz * w / c;
    colour[i] = std::clamp(colour[i] + dcAdjust * c, 0.0, 1.0);
  }
}

}  // namespace

void variation_kernels::addDirectColourVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  const auto direct = [&] { catalogue.back().directColour = true; };
  // Its colour is taken at the sum so far with its own value added: it reads the output arrays.
  const auto readsSum = [&] { catalogue.back().readsSum = true; };

  add("dc_bubble",
      "(s x, s y, w (2/s − 1)), s = w / (r²/4 + 1); colour |(Sx + centerx)² + (Sy + centery)²| / scale mod 1, S "
      "the sum of the transform's terms up to this one (a pre_/post_ term's input plus its result) (Fractorium's)",
      k3D, kFixed, &dcBubble, {{"centerx", 0.0, -2.0, 2.0}, {"centery", 0.0, -2.0, 2.0}, {"scale", 1.0, -2.0, 2.0}});
  direct();
  readsSum();
  add("dc_carpet",
      "q = p + (±1, ±1), signs Ψ < ½, through the transform's affine read as (a qx + b qy + e, c qx + d qy + f), "
      "z; colour |c (1 + h)/2 + k (1 − h)/2| mod 1 from the colour index c: k = h = 0 for equal signs, else k = −2, "
      "h = 0.2 origin (Fractorium's)",
      k2D, kRandom, &dcCarpet, {{"origin", 0.0, -1.0, 1.0}});
  direct();
  add("dc_cube",
      "a random point (2Ψ − 1) on one of the faces ±1 of the cube (x, y or z by Ψ), scaled by (x, y, z); colour c1…c6 "
      "(−x, +x, −y, +y, −z, +z), each clamped into [0, 1] (Fractorium's)",
      k3D, kRandom, &dcCube,
      {{"c1", 0.0, 0.0, 1.0},
       {"c2", 0.0, 0.0, 1.0},
       {"c3", 0.0, 0.0, 1.0},
       {"c4", 0.0, 0.0, 1.0},
       {"c5", 0.0, 0.0, 1.0},
       {"c6", 0.0, 0.0, 1.0},
       {"x", 1.0, -2.0, 2.0},
       {"y", 1.0, -2.0, 2.0},
       {"z", 1.0, -2.0, 2.0}});
  direct();
  add("dc_cylinder",
      "(w sin(x + ρ sin τ) x_scale, ρ + y y_scale, w cos(x + ρ cos τ)), τ = 2πΨ, ρ = blur (Ψ₁ + Ψ₂ + Ψ₃ + Ψ₄ − 2) "
      "(no weight on y, as Fractorium has it); colour as dc_linear's (Fractorium's; x_scale, y_scale are its x, y)",
      k3D, kRandom, &dcCylinder,
      {{"offset", 0.0, -2.0, 2.0},
       {"angle", 0.0, -kPi, kPi},
       {"scale", 0.5, -2.0, 2.0},
       {"x", 0.125, -1.0, 1.0},
       {"y", 0.125, -1.0, 1.0},
       {"blur", 1.0, 0.0, 2.0}});
  direct();
  readsSum();
  add("dc_gridout",
      "p + one unit step along gridout's square spiral, chosen by the rounded point's octant; z; colour + ¼ for a step "
      "in x, + ¾ for one in y, mod 1 (Fractorium's)",
      k2D, kFixed, &dcGridout);
  direct();
  add("dc_linear",
      "w p; colour |½ ((cos angle Sx + sin angle Sy + offset) / scale + 1)| mod 1, S the sum of the transform's terms "
      "up to this one (a pre_/post_ term's input plus its result) (Fractorium's)",
      k2D, kFixed, &dcLinear, {{"offset", 0.0, -2.0, 2.0}, {"angle", 0.0, -kPi, kPi}, {"scale", 1.0, -2.0, 2.0}});
  direct();
  readsSum();
  add("dc_perlin",
      "a random (vx, vy) in a square, disc or blur (shape 0–2) of size 1 + edge, mapped into noise space (map 0–5: "
      "flat, spherical, half/quarter sphere, bubbles) times scale, with octaves of simplex noise N (amps, freqs); "
      "redrawn while N with its edge effect is outside select_centre ± select_range (at most select_bailout "
      "times); w (vx, vy), z; colour centre + range N + color_seed mod 1 (Fractorium's, with voxflame's own noise; "
      "color_seed is pyr3's turn of the colour cycle)",
      k2D, kRandom, &dcPerlin,
      {count("shape", 0.0, 0.0, 2.0),
       count("map", 0.0, 0.0, 5.0),
       {"select_centre", 0.0, -1.0, 1.0},
       {"select_range", 1.0, 0.1, 2.0},
       {"centre", 0.25, -1.0, 1.0},
       {"range", 0.25, -1.0, 1.0},
       {"edge", 0.0, -1.0, 1.0},
       {"scale", 1.0, 0.0, 4.0},
       count("octaves", 2.0, 1.0, 5.0),
       {"amps", 2.0, 0.0, 4.0},
       {"freqs", 2.0, 0.0, 4.0},
       {"z", 0.0, -2.0, 2.0},
       count("select_bailout", 10.0, 2.0, 1000.0),
       {"color_seed", 0.0, 0.0, 1.0}});
  direct();
  add("dc_triangle",
      "the point in barycentric coordinates (u, v) of the triangle (e, f) + u (a, b) − v (c, d) of the transform's "
      "affine; a point outside moved onto the triangle, then by Ψ scatter_area back in (or to (e, f) with "
      "zero_edges); w ((e, f) + u (a, b) − v (c, d)), z; colour |u + v| mod 1 (Fractorium's)",
      k2D, kRandom, &dcTriangle, {{"scatter_area", 0.0, -1.0, 1.0}, count("zero_edges", 0.0, 0.0, 1.0)});
  direct();
  add("dc_ztransl",
      "(w x, w y, w zf) (or w z zf without overwrite), zf = factor (c − x0)/(x1 − x0) from the colour index c "
      "(clamped into [0, 1] with clamp) (Fractorium's)",
      k3D, kFixed, &dcZtransl,
      {{"x0", 0.0, 0.0, 1.0},
       {"x1", 1.0, 0.0, 1.0},
       {"factor", 1.0, -2.0, 2.0},
       count("overwrite", 1.0, 0.0, 1.0),
       count("clamp", 0.0, 0.0, 1.0)});
  direct();
  add("randCubes",
      "blocks bx, by = ⌊±spread ln(1 − Ψ)⌋ of height h = H(bx seed) + H(bx + by seed) (Jenkins' hash over 2³¹ − 1): "
      "((bx density + Ψ) blockSize, (by density + Ψ) blockSize, blockHeight h Ψ^⅛); colour h/2 (Fractorium's; the "
      "weight is not applied, and the terms before it are discarded)",
      k3D, kRandom, &randCubes,
      {{"blockSize", 1.0, 0.0, 4.0},
       {"blockHeight", 1.0, 0.0, 4.0},
       {"spread", 3.0, 0.0, 10.0},
       count("seed", 1.0, 0.0, 100.0),
       {"density", 1.0, 0.0, 4.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  direct();
  add("curl_sp",
      "w (qx re + qy im, qy re − qx im, qz) / D for q = (x, y, z) to the signed power pow: re = S(c1 qx + c2 (qx² − "
      "qy²), sx) + 1, im = S(c1 qy + 2 c2 qx qy, sy), S(a, b) = |(a, b)| with a's sign (− for a ≤ 0), D = (re² + "
      "im²)^(1/pow); colour c + 0.1 dc D clamped into [0, 1] (Fractorium's flam3-compatible branch)",
      k3D, kFixed, &curlSp,
      {{"pow", 1.0, 0.1, 4.0},
       {"c1", 0.0, -2.0, 2.0},
       {"c2", 0.0, -2.0, 2.0},
       {"sx", 0.0, -2.0, 2.0},
       {"sy", 0.0, -2.0, 2.0},
       {"dc", 0.0, -1.0, 1.0}});
  direct();
}

}  // namespace voxflame::core
