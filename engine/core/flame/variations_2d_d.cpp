// Fractorium's other 2D variations, fourth part: the two large random ones, synth (Joel Faber's
// Apophysis plugin: 27 base shapes whose radius or angle is modulated by a sum of up to five waves)
// and xtrb (a trilinear tiling of hexagons, then a random power root). Each is a kernel below and one
// row of the table at the end (see variations.h for the notation, variation_kernels.h and
// variations_2d_shared.h for what the files share). Fractorium writes z = 0 for both; here z is carried
// as w·z, as for every 2D variation.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/flame/variations_2d_shared.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// ---- synth ---------------------------------------------------------------------------------------

// One of synth's five waves (b … f): amplitude, wave shape, skew, frequency, phase, and how it is
// layered onto the sum (add, multiply, max, min).
struct SynthWave {
  double amplitude, type, skew, frequency, phase, layer;
};

struct SynthParams {
  double a, mix;
  SynthWave waves[5];
};

// The wave's value at t, layered onto `factor`.
inline void synthLayer(const SynthWave& wave, double a, double t, double& factor) {
  if (wave.amplitude == 0.0) return;
  double v = wave.phase + t * wave.frequency;  // Fractorium reuses one temporary for this and the skew
  double y = v / kTwoPi;
  y -= std::floor(y);
  if (wave.skew != 0.0) {
    v = 0.5 + 0.5 * wave.skew;
    y = y > v ? 0.5 + 0.5 * (y - v) / fractoriumZeps(1.0 - v) : 0.5 - 0.5 * (v - y) / fractoriumZeps(v);
  }
  double x;
  switch (wholeIndex(wave.type, 0.0, 8.0)) {
    case 0:  // sine
      x = std::sin(y * kTwoPi);
      break;
    case 1:  // cosine
      x = std::cos(y * kTwoPi);
      break;
    case 2:  // square
      x = y > 0.5 ? 1.0 : -1.0;
      break;
    case 3:  // saw
      x = 1.0 - 2.0 * y;
      break;
    case 4:  // triangle
      x = y > 0.5 ? 3.0 - 4.0 * y : 2.0 * y - 1.0;
      break;
    case 5:  // concave
      x = 8.0 * (y - 0.5) * (y - 0.5) - 1.0;
      break;
    case 6:  // convex
      x = 2.0 * std::sqrt(y) - 1.0;
      break;
    case 7:  // n-gon
      x = 1.0 / fractoriumZeps(std::cos((y - 0.5) * (kTwoPi / wave.frequency))) - 1.0;
      break;
    default: {  // inverted n-gon
      const double c = std::cos((y - 0.5) * (kTwoPi / wave.frequency));
      x = c / fractoriumZeps(1.0 - c);
      break;
    }
  }
  switch (wholeIndex(wave.layer, 0.0, 3.0)) {
    case 0:
      factor += wave.amplitude * x;
      break;
    case 1:
      factor *= 1.0 + wave.amplitude * x;
      break;
    case 2: {
      const double v2 = a + wave.amplitude * x;
      factor = factor > v2 ? factor : v2;
      break;
    }
    default: {
      const double v2 = a + wave.amplitude * x;
      factor = factor < v2 ? factor : v2;
      break;
    }
  }
}

// The modulation at t: a plus the layered waves, mixed with 1 by mix.
inline double synthValue(const SynthParams& s, double t) {
  double factor = s.a;
  for (const SynthWave& wave : s.waves) synthLayer(wave, s.a, t, factor);
  return factor * s.mix + (1.0 - s.mix);
}

// A quadratic Bézier map of x whose slope at 0 is m, joining the identity further out (synth's
// smooth interpolation).
inline double bezierQuadMap(double x, double m) {
  double sign = 1.0, t = 0.0;
  if (m < 0.0) {
    m = -m;
    sign = -1.0;
  }
  if (x < 0.0) {
    x = -x;
    sign = -sign;
  }
  const double iM = m > 1.0e-10 ? 1.0 / m : 1e10;
  const double limit = iM < m * 2.0 ? m * 2.0 : iM;
  if (x > limit || m == 1.0) return sign * x;
  if (m < 1.0 && x <= 1.0) {
    t = x;
    if (std::abs(m - 0.5) > 1e-10) t = (-m + std::sqrt(m * m + (1.0 - 2.0 * m) * x)) / (1.0 - 2.0 * m);
    return sign * (x + (m - 1.0) * t * t);
  }
  if (1.0 < m && x <= 1.0) {
    t = x;
    if (std::abs(m - 2.0) > 1e-10) t = (-iM + std::sqrt(iM * iM + (1.0 - 2.0 * iM) * x)) / (1.0 - 2.0 * iM);
    return sign * (x + (m - 1.0) * t * t);
  }
  if (m < 1.0) {
    t = std::sqrt((x - 1.0) / (limit - 1.0));
    return sign * (x + (m - 1.0) * t * t + 2.0 * (1.0 - m) * t + (m - 1.0));
  }
  t = (1.0 - m) + std::sqrt((m - 1.0) * (m - 1.0) + (x - 1.0));
  return sign * (x + (m - 1.0) * t * t - 2.0 * (m - 1.0) * t + (m - 1.0));
}

inline double synthInterpolate(double x, double m, bool bezier) {
  return bezier ? bezierQuadMap(x, m) : x * m;
}

// sin t and cos t modulated: multiplied by the modulation at t and t + π/2 (smooth 0), or mixed
// with it (smooth 1).
inline void synthSinCos(const SynthParams& s, double t, double& sn, double& cs, bool mixIn) {
  sn = std::sin(t);
  cs = std::cos(t);
  if (!mixIn) {
    sn *= synthValue(s, t);
    cs *= synthValue(s, t + kPi / 2.0);
  } else {
    sn = (1.0 - s.mix) * sn + (synthValue(s, t) - 1.0);
    cs = (1.0 - s.mix) * cs + (synthValue(s, t + kPi / 2.0) - 1.0);
  }
}

// The synth modes that draw random numbers (the blurs and julia's branch): the others leave the
// lane's generator alone.
inline bool synthModeDraws(int mode) {
  return mode == 2 || mode == 3 || mode == 4 || mode == 15 || mode == 19 || mode == 20;
}

VOXFLAME_VARIATION_TARGETS void synth(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  SynthParams s{};
  s.a = P[0];
  const int mode = wholeIndex(P[1], 0.0, 26.0);
  const double power = P[2];
  s.mix = P[3];
  const bool smooth = fractoriumInteger(P[4], 0.0, 1.0) != 0.0;
  for (int k = 0; k < 5; ++k) {
    const double* q = P + 5 + 6 * k;
    s.waves[k] = SynthWave{q[0], q[1], q[2], q[3], q[4], q[5]};
  }
  const bool draws = synthModeDraws(mode);
  for (std::size_t i = 0; i < n; ++i) {
    const double vx = x[i], vy = y[i], r2 = vx * vx + vy * vy;
    const double theta0 = std::atan2(vx, vy);  // flam3's θ
    double px = 0.0, py = 0.0;
    double u1 = 0.0, u2 = 0.0, u3 = 0.0;
    if (draws) {
      u1 = laneUniform(rnd[i]);
      if (mode != 15) u2 = laneUniform(rnd[i]);
      if (mode == 2 || mode == 3 || mode == 4 || mode == 19) u3 = laneUniform(rnd[i]);
    }
    switch (mode) {
      case 0: {  // spherical
        const double r =
            synthInterpolate(std::pow(fractoriumZeps(r2), (power + 1.0) / 2.0), synthValue(s, theta0), smooth);
        px = r * std::sin(theta0);
        py = r * std::cos(theta0);
        break;
      }
      case 1: {  // bubble
        const double r = synthInterpolate(std::sqrt(r2) / (r2 / 4.0 + 1.0), synthValue(s, theta0), smooth);
        px = r * std::sin(theta0);
        py = r * std::cos(theta0);
        break;
      }
      case 2: {  // the legacy blur
        const double r0 = (u1 + u2 + 0.002 * u3) / 2.002;
        const double t = kTwoPi * laneUniform(rnd[i]) - kPi;
        const double bx = r0 * std::sin(t), by = r0 * std::cos(t);
        const double r = synthInterpolate(std::pow(fractoriumZeps(r0 * r0), power / 2.0), synthValue(s, t), smooth);
        px = bx * r;
        py = by * r;
        break;
      }
      case 3: {  // blur
        const double r0 = 0.5 * (u1 + u2), t = kTwoPi * u3 - kPi;
        const double r = synthInterpolate(std::pow(fractoriumZeps(r0 * r0), -power / 2.0), synthValue(s, t), smooth);
        px = r * std::sin(t);
        py = r * std::cos(t);
        break;
      }
      case 4: {  // zigzag blur
        const double v = 1.0 + 0.1 * (u1 + u2 - 1.0) * power;
        const double t = 2.0 * std::asin((u3 - 0.5) * 2.0);
        px = t / kPi;
        py = synthInterpolate(v, synthValue(s, t), smooth) - 1.0;
        break;
      }
      case 5: {  // raw circle
        const double r = synthInterpolate(std::sqrt(r2), synthValue(s, theta0), smooth);
        px = r * std::sin(theta0);
        py = r * std::cos(theta0);
        break;
      }
      case 6:  // raw x
        px = synthInterpolate(vx, synthValue(s, vy), smooth);
        py = vy;
        break;
      case 7:  // raw y
        px = vx;
        py = synthInterpolate(vy, synthValue(s, vx), smooth);
        break;
      case 8:  // raw xy
        px = synthInterpolate(vx, synthValue(s, vy), smooth);
        py = synthInterpolate(vy, synthValue(s, vx), smooth);
        break;
      case 9:  // shift x
        px = vx + synthValue(s, vy) - 1.0;
        py = vy;
        break;
      case 10:  // shift y
        px = vx;
        py = vy + synthValue(s, vx) - 1.0;
        break;
      case 11:  // shift xy
        px = vx + synthValue(s, vy) - 1.0;
        py = vy + synthValue(s, vx) - 1.0;
        break;
      case 12:  // sinusoidal
        px = synthValue(s, vx) - 1.0 + (1.0 - s.mix) * std::sin(vx);
        py = synthValue(s, vy) - 1.0 + (1.0 - s.mix) * std::sin(vy);
        break;
      case 13: {  // swirl
        double sn, cs;
        synthSinCos(s, std::pow(fractoriumZeps(r2), power / 2.0), sn, cs, smooth);
        px = sn * vx - cs * vy;
        py = cs * vx + sn * vy;
        break;
      }
      case 14: {  // hyperbolic
        const double r = std::pow(fractoriumZeps(r2), power / 2.0);
        double sn, cs;
        synthSinCos(s, theta0, sn, cs, smooth);
        px = sn / r;
        py = cs * r;
        break;
      }
      case 15: {  // julia
        const double r = std::pow(fractoriumZeps(r2), power / 4.0);
        const double t = theta0 / 2.0 + (u1 < 0.5 ? kPi : 0.0);
        double sn, cs;
        synthSinCos(s, t, sn, cs, smooth);
        px = r * cs;
        py = r * sn;
        break;
      }
      case 16: {  // disc
        const double t = theta0 / kPi, r = kPi * std::pow(fractoriumZeps(r2), power / 2.0);
        double sn, cs;
        synthSinCos(s, r, sn, cs, smooth);
        px = sn * t;
        py = cs * t;
        break;
      }
      case 17: {  // rings
        double r = std::sqrt(r2);
        const double mu = fractoriumZeps(power * power);
        r += -2.0 * mu * std::trunc((r + mu) / (2.0 * mu)) + r * (1.0 - mu);
        double sn, cs;
        synthSinCos(s, r, sn, cs, smooth);
        px = sn * theta0;
        py = cs * theta0;
        break;
      }
      case 18: {  // cylinder
        const double r = std::pow(fractoriumZeps(r2), power / 2.0);
        double sn, cs;
        synthSinCos(s, vx, sn, cs, smooth);
        px = r * sn;
        py = r * vy;
        break;
      }
      case 19: {  // ring blur
        const double r0 = 1.0 + 0.1 * (u1 + u2 - 1.0) * power, t = kTwoPi * u3 - kPi;
        const double r = synthInterpolate(r0, synthValue(s, t), smooth);
        px = r * std::sin(t);
        py = r * std::cos(t);
        break;
      }
      case 20: {  // ring blur 2: the angle drawn first, then the radius
        const double t = kTwoPi * u1 - kPi;
        const double r = synthValue(s, t) + 0.1 * std::pow(fractoriumZeps(u2), power);
        px = r * std::sin(t);
        py = r * std::cos(t);
        break;
      }
      case 21:    // shift θ
      case 22: {  // shift and stretch (the same in Fractorium)
        const double r = std::pow(fractoriumZeps(r2), power / 2.0);
        const double t = theta0 - 1.0 + synthValue(s, r);
        px = r * std::sin(t);
        py = r * std::cos(t);
        break;
      }
      case 23: {  // shift along the tangent
        const double r = std::pow(fractoriumZeps(r2), power / 2.0);
        const double mu = synthValue(s, r) - 1.0;
        px = vx + mu * std::cos(theta0);
        py = vy - mu * std::sin(theta0);
        break;
      }
      case 24:  // mirror in the curve y = synth(x) − 1
        px = vx;
        py = 2.0 * (synthValue(s, vx) - 1.0) - vy;
        break;
      case 25:  // mirror in both
        px = 2.0 * (synthValue(s, vy) - 1.0) - vx;
        py = 2.0 * (synthValue(s, vx) - 1.0) - vy;
        break;
      default: {  // spherical 2
        double r = synthInterpolate(std::sqrt(r2), synthValue(s, theta0), smooth);
        r = std::pow(r, power);
        px = r * std::sin(theta0);
        py = r * std::cos(theta0);
        break;
      }
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// ---- xtrb ------------------------------------------------------------------------------------------

// The triangle of xtrb's tiling (angles 0.047 + a, 0.047 + b and the rest of π, inradius radius) and
// the hexagon's width: Fractorium's precalc.
struct Xtrb {
  double radius, width, power, absN, cn, sinC, cosC;
  double ha, hb, hc, ab, ac, ba, bc, ca, cb, s2a, s2b, s2c, s2ab, s2ac, s2bc, width1, width2, width3;
};

Xtrb xtrbSetup(const double* P) {
  Xtrb t{};
  t.power = fractoriumIntegerNonzero(P[0]);
  t.radius = P[1];
  t.width = P[2];
  const double dist = P[3];
  const double br = 0.047 + P[4], cr = 0.047 + P[5], ar = kPi - br - cr;
  const double tanA2 = std::sin(ar / 2.0) / std::cos(ar / 2.0), tanB2 = std::sin(br / 2.0) / std::cos(br / 2.0),
               tanC2 = std::sin(cr / 2.0) / std::cos(cr / 2.0);
  t.sinC = std::sin(cr);
  t.cosC = std::cos(cr);
  const double a = t.radius * (tanC2 + tanB2), b = t.radius * (tanC2 + tanA2), c = t.radius * (tanB2 + tanA2);
  t.width1 = 1.0 - t.width;
  t.width2 = 2.0 * t.width;
  t.width3 = 1.0 - t.width * t.width;
  const double s2 = t.radius * (a + b + c);
  t.ha = s2 / a / 6.0;
  t.hb = s2 / b / 6.0;
  t.hc = s2 / c / 6.0;
  t.ab = a / b;
  t.ac = a / c;
  t.ba = b / a;
  t.bc = b / c;
  t.ca = c / a;
  t.cb = c / b;
  t.s2a = 6.0 * t.ha;
  t.s2b = 6.0 * t.hb;
  t.s2c = 6.0 * t.hc;
  t.s2bc = s2 / (b + c) / 6.0;
  t.s2ab = s2 / (a + b) / 6.0;
  t.s2ac = s2 / (a + c) / 6.0;
  t.absN = std::trunc(std::min(std::abs(t.power), 4294967296.0));
  t.cn = dist / t.power / 2.0;
  return t;
}

// The trilinear point (al, be, ga) of a triangle moved into the hexagon around its nearest corner, or
// kept scaled by width (with chance 1 − width3 = width²), by Ψ.
void xtrbHex(const Xtrb& t, double al, double be, double ga, double u, double& al1, double& be1) {
  double ga1, de1;
  const bool keep = u >= t.width3;
  if (be < al) {
    if (ga < be) {
      if (keep) {
        de1 = t.width * be;
        ga1 = t.width * ga;
      } else {
        ga1 = t.width1 * ga + t.width2 * t.hc * ga / be;
        de1 = t.width1 * be + t.width2 * t.s2ab * (3.0 - ga / be);
      }
      al1 = t.s2a - t.ba * de1 - t.ca * ga1;
      be1 = de1;
    } else if (ga < al) {
      if (keep) {
        ga1 = t.width * ga;
        de1 = t.width * be;
      } else {
        de1 = t.width1 * be + t.width2 * t.hb * be / ga;
        ga1 = t.width1 * ga + t.width2 * t.s2ac * (3.0 - be / ga);
      }
      al1 = t.s2a - t.ba * de1 - t.ca * ga1;
      be1 = de1;
    } else if (keep) {
      al1 = t.width * al;
      be1 = t.width * be;
    } else {
      be1 = t.width1 * be + t.width2 * t.hb * be / al;
      al1 = t.width1 * al + t.width2 * t.s2ac * (3.0 - be / al);
    }
  } else {
    if (ga < al) {
      if (keep) {
        de1 = t.width * al;
        ga1 = t.width * ga;
      } else {
        ga1 = t.width1 * ga + t.width2 * t.hc * ga / al;
        de1 = t.width1 * al + t.width2 * t.s2ab * (3.0 - ga / al);
      }
      be1 = t.s2b - t.ab * de1 - t.cb * ga1;
      al1 = de1;
    } else if (ga < be) {
      if (keep) {
        ga1 = t.width * ga;
        de1 = t.width * al;
      } else {
        de1 = t.width1 * al + t.width2 * t.ha * al / ga;
        ga1 = t.width1 * ga + t.width2 * t.s2bc * (3.0 - al / ga);
      }
      be1 = t.s2b - t.ab * de1 - t.cb * ga1;
      al1 = de1;
    } else if (keep) {
      be1 = t.width * be;
      al1 = t.width * al;
    } else {
      al1 = t.width1 * al + t.width2 * t.ha * al / be;
      be1 = t.width1 * be + t.width2 * t.s2bc * (3.0 - al / be);
    }
  }
}

// The plane in trilinear coordinates of the tiling's triangles, each triangle's point pushed into
// hexagons (xtrbHex, Ψ₁), back to the plane, then a random power root as julian's (angle (∠ + 2π
// ⌊Ψ₂|power|⌋)/power, radius^(dist/power)). The weight enters twice, as in Fractorium.
VOXFLAME_VARIATION_TARGETS void xtrb(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const Xtrb t = xtrbSetup(P);
  for (std::size_t i = 0; i < n; ++i) {
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]);
    double alpha = y[i] + t.radius, beta = x[i] * t.sinC - y[i] * t.cosC + t.radius;
    const double m = std::floor(alpha / t.s2a), k = std::floor(beta / t.s2b);
    double offAl = alpha - m * t.s2a, offBe = beta - k * t.s2b;
    double offGa = t.s2c - t.ac * offAl - t.bc * offBe;
    if (offGa > 0.0) {
      xtrbHex(t, offAl, offBe, offGa, u1, alpha, beta);
    } else {
      offAl = t.s2a - offAl;
      offBe = t.s2b - offBe;
      offGa = -offGa;
      xtrbHex(t, offAl, offBe, offGa, u1, alpha, beta);
      alpha = t.s2a - alpha;
      beta = t.s2b - beta;
    }
    alpha += m * t.s2a;
    beta += k * t.s2b;
    const double px = (beta - t.radius + (alpha - t.radius) * t.cosC) / t.sinC, py = alpha - t.radius;
    const double angle = (std::atan2(py, px) + kTwoPi * std::floor(u2 * t.absN)) / t.power;
    const double r = w * std::pow(px * px + py * py, t.cn);
    outX[i] += w * r * std::cos(angle);
    outY[i] += w * r * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractorium2DVariationsD(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  std::vector<VariationParam> synthParams = {{"a", 0.0, -2.0, 2.0},
                                             count("mode", 3.0, 0.0, 26.0),
                                             {"power", -2.0, -4.0, 4.0},
                                             {"mix", 0.0, -2.0, 2.0},
                                             count("smooth", 0.0, 0.0, 1.0)};
  for (const char* wave : {"b", "c", "d", "e", "f"}) {
    const std::string p = wave;
    synthParams.push_back({p, 0.0, -2.0, 2.0});
    synthParams.push_back(count(p + "_type", 0.0, 0.0, 8.0));
    synthParams.push_back({p + "_skew", 0.0, -1.0, 1.0});
    synthParams.push_back({p + "_frq", 1.0, -10.0, 10.0});
    synthParams.push_back({p + "_phs", 0.0, -kPi, kPi});
    synthParams.push_back(count(p + "_layer", 0.0, 0.0, 3.0));
  }
  add("synth",
      "a base shape by mode (0 spherical, 1 bubble, 2 legacy blur, 3 blur, 4 zigzag blur, 5 raw circle, 6–8 raw x, "
      "y, xy, 9–11 shift x, y, xy, 12 sinusoidal, 13 swirl, 14 hyperbolic, 15 julia, 16 disc, 17 rings, 18 "
      "cylinder, 19, 20 ring blurs, 21, 22 shift θ, 23 shift along the tangent, 24, 25 mirrors, 26 spherical 2) "
      "whose radius, angle or coordinate is modulated by S(t) = (a + layered waves b … f)·mix + 1 − mix; each wave "
      "amplitude·shape(frq t + phs, skewed) (sine, cosine, square, saw, triangle, concave, convex, n-gon, inverted "
      "n-gon) added, multiplied, max'ed or min'ed (layer); smooth picks linear or Bézier interpolation (Joel "
      "Faber's, as in Fractorium; the blurs and julia draw Ψ, mode 3 by default); z",
      k2D, kRandom, &synth, std::move(synthParams));
  add("xtrb",
      "p in trilinear coordinates of a tiling of triangles (angles 0.047 + a, 0.047 + b, inradius radius), moved "
      "into hexagons round the corners (kept, scaled by width, with chance width²; Ψ₁), back to the plane as q, "
      "then w |q|^(dist/power) (cos α, sin α), α = (∠q + 2π ⌊Ψ₂|power|⌋)/power (the weight w enters twice, as in "
      "Fractorium); z",
      k2D, kRandom, &xtrb,
      {count("power", 2.0, -6.0, 6.0),
       {"radius", 1.0, 0.1, 4.0},
       {"width", 0.5, 0.0, 1.0},
       {"dist", 1.0, -2.0, 4.0},
       {"a", 1.0, -1.0, 2.0},
       {"b", 1.0, -1.0, 2.0}});
}

}  // namespace voxflame::core
