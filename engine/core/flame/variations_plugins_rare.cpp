// Rarer plugins that published flame files use: JWildfire's symmetry-group variations sym_bg2, sym_ng11 and sym_ng15
// (Jesús Sosa's, after McGregor and Watt's "The Art of Graphics for the IBM PC": each point goes through one of a fixed
// set of rigid maps picked at random, so the attractor holds every copy) and its glsl_circlesblue, glsl_grid3D,
// glsl_mandala and glsl_acrilic (Sosa's ports of shaders: rising bubbles, a ray-marched grid, a kaleidoscope, an
// acrylic pour), flam3's original secant (before flam3 2.7.10 replaced it by secant2; electric sheep of that time use
// it), and the Apophysis plugins julian2dc (xyrus02's julian2 that also colours the point) and shape (cyberxaos'
// superformula blur). Each is a kernel below and one row of the table at the end (see variations.h for the notation and
// variation_kernels.h for what the files share). Random numbers come from the lane's own stream (laneUniform), where
// the originals draw from their own generators.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/flame/glsl_pixel.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// ---- JWildfire's symmetry groups ---------------------------------------------------------------------
// One of `count` maps (a x + b y + c, d x + e y + f), picked by ⌊count Ψ⌋ (JWildfire's (int)(count ·
// Math.random())). The linear parts are fixed; the translations come from the parameters.
struct SymLinear {
  double a, b, d, e;
};

[[gnu::always_inline]] inline std::size_t symPick(std::uint32_t& state, std::size_t count) {
  const auto k = static_cast<std::size_t>(laneUniform(state) * static_cast<double>(count));
  return std::min(k, count - 1);
}

// sym_bg2, band group 2: the point moved left by stepx/2 + 1 and down by stepy/2, or mirrored in the x axis and
// moved right by stepx/2 and up by stepy/2 + 1.
VOXFLAME_VARIATION_TARGETS void symBg2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double stepX = P[0], stepY = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    double px, py;
    if (symPick(rnd[i], 2) == 0) {
      px = x[i] - stepX / 2.0 - 1.0;
      py = y[i] - stepY / 2.0;
    } else {
      px = x[i] + stepX / 2.0;
      py = -y[i] + stepY / 2.0 + 1.0;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// sym_ng11, net group 11: the point shifted by (space, space), then one of the eight maps of the square's
// symmetry group (the four quarter turns and the four mirrors), each with its own translation made of
// ±spacex ± stepx/2 and ±spacey ± stepy/2 (JWildfire's table).
constexpr SymLinear kSymNg11Linear[8] = {{1.0, 0.0, 0.0, 1.0},  {-1.0, 0.0, 0.0, -1.0}, {0.0, 1.0, -1.0, 0.0},
                                         {0.0, -1.0, 1.0, 0.0}, {-1.0, 0.0, 0.0, 1.0},  {0.0, -1.0, -1.0, 0.0},
                                         {0.0, 1.0, 1.0, 0.0},  {1.0, 0.0, 0.0, -1.0}};
// The translations' signs: (of spacex, of stepx/2, of spacey, of stepy/2).
constexpr double kSymNg11Signs[8][4] = {{1, 1, 1, 1},    {-1, 1, -1, 1},   {1, 1, -1, 1},  {-1, 1, 1, 1},
                                        {-1, -1, 1, -1}, {-1, -1, -1, -1}, {1, -1, 1, -1}, {1, -1, -1, -1}};

VOXFLAME_VARIATION_TARGETS void symNg11(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double space = P[0], spaceX = P[1], spaceY = P[2], halfX = P[3] / 2.0, halfY = P[4] / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = symPick(rnd[i], 8);
    const SymLinear& m = kSymNg11Linear[k];
    const double* s = kSymNg11Signs[k];
    const double qx = x[i] + space, qy = y[i] + space;
    const double c = s[0] * spaceX + s[1] * halfX, f = s[2] * spaceY + s[3] * halfY;
    outX[i] += w * (m.a * qx + m.b * qy + c);
    outY[i] += w * (m.d * qx + m.e * qy + f);
    outZ[i] += w * z[i];
  }
}

// sym_ng15, net group 15: the point shifted by (ρ, ρ), ρ = √(radius²/2), then one of twelve maps: six rotations
// and reflections at multiples of 60° (JWildfire writes cos 30° as 0.866), each once moved by −(stepx, stepy)/2
// and once by +(stepx, stepy)/2.
constexpr SymLinear kSymNg15Linear[6] = {{0.0, 1.0, -1.0, 0.0},       {0.0, -1.0, -1.0, 0.0},
                                         {0.866, -0.5, 0.5, 0.866},   {0.866, 0.5, 0.5, -0.866},
                                         {-0.866, -0.5, 0.5, -0.866}, {-0.866, 0.5, 0.5, 0.866}};

VOXFLAME_VARIATION_TARGETS void symNg15(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double shift = std::sqrt(P[0] * P[0] / 2.0), halfX = P[1] / 2.0, halfY = P[2] / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = symPick(rnd[i], 12);
    const SymLinear& m = kSymNg15Linear[k % 6];
    const double sign = k < 6 ? -1.0 : 1.0;
    const double qx = x[i] + shift, qy = y[i] + shift;
    outX[i] += w * (m.a * qx + m.b * qy + sign * halfX);
    outY[i] += w * (m.d * qx + m.e * qy + sign * halfY);
    outZ[i] += w * z[i];
  }
}

// ---- flam3's original secant ---------------------------------------------------------------------------
// (w x, 1/cos(w r)): y is not scaled by the weight, as flam3 had it until 2.7.10 (secant2 scales it and closes
// the gap at cos = 0 by ∓1).
VOXFLAME_VARIATION_2D(secant, {
  const double r = w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
  outX[i] += w * x[i];
  outY[i] += 1.0 / std::cos(r);
})

// ---- Apophysis plugins ---------------------------------------------------------------------------------
// xyrus02's julian2dc: julian2 (julian of q = (a x + b y + e, c x + d y + f)) that sets the colour index to
// |ρ col + α/2π (1 − col)| mod 1, ρ the result's radius (with the weight) and α its angle.
VOXFLAME_VARIATION_TARGETS void julian2dc(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double powerN = countParam(P[0]), exponent = P[1] / powerN * 0.5, rootCount = std::abs(powerN);
  const double col = P[2];
  const double a = P[3], b = P[4], c = P[5], d = P[6], e = P[7], f = P[8];
  for (std::size_t i = 0; i < n; ++i) {
    const double px = a * x[i] + b * y[i] + e, py = c * x[i] + d * y[i] + f;
    const double root = std::trunc(rootCount * laneUniform(rnd[i]));
    const double angle = (std::atan2(py, px) + kTwoPi * root) / powerN;
    const double r = w * std::pow(px * px + py * py, exponent);
    outX[i] += r * std::cos(angle);
    outY[i] += r * std::sin(angle);
    outZ[i] += w * z[i];
    colour[i] = laneFmod(std::abs(r * col + angle / kTwoPi * (1.0 - col)), 1.0);
  }
}

// cyberxaos' shape: a blur filling the superformula's curve, R(φ) = (|cos(m φ/4)/a|^n2 + |sin(m φ/4)/b|^n3)^(−1/n1),
// along the point's direction: w (Ψ − holes) R(φ) (x, y)/r. Negative holes leave a hole of holes/(holes − 1) of
// the curve's size; super_shape with rnd 1 is the same blur without a and b. Written from the superformula and the
// plugin's description (its source was not at hand); renders of the published flames that use it match the pictures
// their authors made with Apophysis. The defaults other than holes are ours.
VOXFLAME_VARIATION_TARGETS void shape(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double quarterM = P[0] / 4.0, negInvN1 = -1.0 / P[1], n2 = P[2], n3 = P[3], a = P[4], b = P[5];
  const double holes = P[6];
  for (std::size_t i = 0; i < n; ++i) {
    const double theta = quarterM * std::atan2(y[i], x[i]);
    const double t1 = std::pow(std::abs(std::cos(theta) / a), n2);
    const double t2 = std::pow(std::abs(std::sin(theta) / b), n3);
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double scale = w * (laneUniform(rnd[i]) - holes) * std::pow(t1 + t2, negInvN1) / (r + kEpsilon);
    outX[i] += scale * x[i];
    outY[i] += scale * y[i];
    outZ[i] += w * z[i];
  }
}

// ---- JWildfire's glsl_circlesblue ---------------------------------------------------------------------
// Jesús Sosa's port of a shader of rising bubbles: pixel (i, j) of a resolution × 10⁶ grid drawn at random, the
// point w (i/resolution − ½, j/10⁶ − ½) (JWildfire sets the grid's height from its width once, when the variation
// is made, as glsl_apollonian's), and the bubbles' colour at the pixel's centre uv = 2 (i + ½, j + ½)/size − 1.
// Bubble k (of Bubles) at time t: pha = tan(6k + 1)/2 + ½, siz = (cos(2.4k + 5)/2 + ½)⁴, pox = cos(3.55k + 4.1),
// radius ρ = Radiusy + 0.12 sin k + 0.08, centre (pox + sin(t/15 + pha + siz), −1 − ρ + (2 + 2ρ)((pha + 0.02 t (0.2
// + 0.8 siz)) mod 1)), colour mix((0.1, 0.2, 0.8), (0.2, 0.8, 0.6), ½ + ½ sin(k sin(0.03 t pox) + 1.9)), added
// times (1 − smoothstep(ρ (0.65 + 0.2 sin(pox t)), ρ, distance)) (1 − cos(pox t)); the sum times 0.3. Gradient 0
// paints the point that RGB colour (JWildfire's dbl2int bytes), Gradient 1 makes the colour index sin(r/(r + g + b))
// (left where that is NaN). Seed only draws JWildfire's random time, which the file's time overrides; so it is
// not used here.
constexpr int kCirclesBlueMaxBubbles = 100;

struct CirclesBlueBubble {
  double x, y, inner, radius, r, g, b, fade;
};

// The bubbles at time t with radius parameter `radius` (the part that does not depend on the pixel).
void circlesBlueBubbles(double time, double radius, int count, CirclesBlueBubble* out) {
  for (int k = 0; k < count; ++k) {
    const double kd = k;
    const double pha = std::tan(kd * 6.0 + 1.0) * 0.5 + 0.5;
    const double siz = std::pow(std::cos(kd * 2.4 + 5.0) * 0.5 + 0.5, 4.0);
    const double pox = std::cos(kd * 3.55 + 4.1);
    const double rad = radius + std::sin(kd) * 0.12 + 0.08;
    const double rise = pha + 0.1 * (time / 5.0) * (0.2 + 0.8 * siz);
    const double mix = 0.5 + 0.5 * std::sin(kd * std::sin(time * pox * 0.03) + 1.9);
    CirclesBlueBubble& b = out[k];
    b.x = pox + std::sin(time / 15.0 + pha + siz);
    b.y = -1.0 - rad + (2.0 + 2.0 * rad) * (rise - std::floor(rise));
    b.inner = rad * (0.65 + 0.20 * std::sin(pox * time));
    b.radius = rad;
    b.r = 0.1 * (1.0 - mix) + 0.2 * mix;
    b.g = 0.2 * (1.0 - mix) + 0.8 * mix;
    b.b = 0.8 * (1.0 - mix) + 0.6 * mix;
    b.fade = 1.0 - std::cos(pox * time);
  }
}

VOXFLAME_VARIATION_TARGETS void glslCirclesblue(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                                double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  // JWildfire's (int) Tools.limitValue(v, low, high): clamped, then truncated; NaN passes the clamp and is 0.
  const auto limitedInt = [](double v, double low, double high) {
    return std::isnan(v) ? 0.0 : std::trunc(std::clamp(v, low, high));
  };
  const auto limited = [](double v, double low, double high) { return std::isnan(v) ? v : std::clamp(v, low, high); };
  const double width = glslPixelColumns(P[0]);
  const double time = limited(P[2], 1.0, 1000.0), radius = limited(P[3], 0.0, 1.0);
  const int count = static_cast<int>(limitedInt(P[4], 1.0, kCirclesBlueMaxBubbles));
  const bool index = limitedInt(P[5], 0.0, 1.0) == 1.0;
  std::uint32_t* __restrict rgb = index ? nullptr : in.rgb;
  CirclesBlueBubble bubbles[kCirclesBlueMaxBubbles];
  if (index || rgb) circlesBlueBubbles(time, radius, count, bubbles);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [pi, pj] = addGlslPixel(rnd[i], width, w, z[i], outX[i], outY[i], outZ[i]);
    if (!index && !rgb) continue;
    const double u = 2.0 * (pi + 0.5) / width - 1.0, v = 2.0 * (pj + 0.5) / kGlslPixelRows - 1.0;
    double red = 0.0, green = 0.0, blue = 0.0;
    for (int k = 0; k < count; ++k) {
      const CirclesBlueBubble& b = bubbles[k];
      const double dx = u - b.x, dy = v - b.y;
      const double distance = std::sqrt(dx * dx + dy * dy);
      const double t = std::min(std::max((distance - b.inner) / (b.radius - b.inner), 0.0), 1.0);
      const double cover = 1.0 - t * t * (3.0 - 2.0 * t);
      red += b.r * cover * b.fade;
      green += b.g * cover * b.fade;
      blue += b.b * cover * b.fade;
    }
    red *= 0.3;
    green *= 0.3;
    blue *= 0.3;
    if (rgb) {
      rgb[i] = paintedRgb(static_cast<std::uint32_t>(rgbByte(red)), static_cast<std::uint32_t>(rgbByte(green)),
                          static_cast<std::uint32_t>(rgbByte(blue)));
      continue;
    }
    const double c = std::sin(red / (red + green + blue));
    if (c == c) colour[i] = c;
  }
}

// ---- JWildfire's glsl_grid3D ----------------------------------------------------------------------------
// Sosa's port of kabuto's ray-marched grid: pixel (i, j) of a resolution × 10⁶ grid drawn at random, the point w
// (i/resolution − ½, j/10⁶ − ½), painted the grey level of the march through the pixel's centre (JWildfire's
// GLSLFunc leaves its Gradient at 0 and gives glsl_grid3D no parameter for it, so it always paints). The ray:
// direction (u − ½, v − ½, 1) normalised, turned about x and then y by a = 0.021 t (as the Java writes vec3 ×
// mat3), from (0, 0.1 t, 0); 30 steps each move it by the least component of the field F(p) and add (30 − step)/(F(p)
// + 0.1) to the sum S, F(p) = √(q² + q.yzx²)/8 − 0.05 with q the point scaled by 0.1 and three times rotated (x, y,
// z) → (y, z, x) and folded to 2|fract(q) − ½|; the grey level is the sum of the channels of 1 − 1/(1 + 10⁻⁴ S).
// Seed only draws JWildfire's random time, which the file's time overrides; so it is not used here.
double grid3dGrey(double u, double v, double time) {
  constexpr int kSteps = 30;
  double dx = u - 0.5, dy = v - 0.5, dz = 1.0;
  const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
  dx /= length;
  dy /= length;
  dz /= length;
  const double a = time * 0.021, ca = std::cos(a), sa = std::sin(a);
  const double y1 = dy * ca - dz * sa, z1 = dy * sa + dz * ca;  // about x
  const double x2 = dx * ca - z1 * sa, z2 = dx * sa + z1 * ca;  // about y
  dx = x2;
  dy = y1;
  dz = z2;
  double px = 0.0, py = time * 0.1, pz = 0.0;
  double sx = 0.0, sy = 0.0, sz = 0.0;
  for (int step = 0; step < kSteps; ++step) {
    double qx = px * 0.1, qy = py * 0.1, qz = pz * 0.1, scale = 0.1;
    for (int k = 0; k < 3; ++k) {
      const double rx = qy, ry = qz, rz = qx;
      qx = std::abs(rx - std::floor(rx) - 0.5) * 2.0;
      qy = std::abs(ry - std::floor(ry) - 0.5) * 2.0;
      qz = std::abs(rz - std::floor(rz) - 0.5) * 2.0;
      scale *= 2.0;
    }
    qx *= qx;
    qy *= qy;
    qz *= qz;
    const double fx = std::sqrt(qx + qy) / scale - 0.05, fy = std::sqrt(qy + qz) / scale - 0.05;
    const double fz = std::sqrt(qz + qx) / scale - 0.05;
    const double f = std::min(std::min(fx, fy), fz);
    px += dx * f;
    py += dy * f;
    pz += dz * f;
    const double weight = static_cast<double>(kSteps - step);
    sx += weight / (fx + 0.1);
    sy += weight / (fy + 0.1);
    sz += weight / (fz + 0.1);
  }
  const double k = 0.09 / static_cast<double>(kSteps * kSteps);
  return (1.0 - 1.0 / (1.0 + sx * k)) + (1.0 - 1.0 / (1.0 + sy * k)) + (1.0 - 1.0 / (1.0 + sz * k));
}

VOXFLAME_VARIATION_TARGETS void glslGrid3d(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double width = glslPixelColumns(P[0]);
  const double time = std::isnan(P[2]) ? P[2] : std::clamp(P[2], 1.0, 1000.0);
  std::uint32_t* __restrict rgb = in.rgb;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [pi, pj] = addGlslPixel(rnd[i], width, w, z[i], outX[i], outY[i], outZ[i]);
    if (!rgb) continue;
    const auto grey =
        static_cast<std::uint32_t>(rgbByte(grid3dGrey((pi + 0.5) / width, (pj + 0.5) / kGlslPixelRows, time)));
    rgb[i] = paintedRgb(grey, grey, grey);
  }
}

// ---- JWildfire's glsl_mandala ---------------------------------------------------------------------------
// Sosa's kaleidoscope: pixel (i, j) of a resolution × 10⁶ grid drawn at random, the point w (i/resolution − ½, j/10⁶
// − ½), coloured by the pattern at the pixel's centre uv = (5.5 − scale)(2 (i + ½, j + ½)/size − 1). The pattern:
// s = K(uv), t = K(s), K folding the angle into a wedge of π/⌊sides⌋ (|angle mod 2k − k|, with JWildfire's G.atan2,
// a cheap approximation of the angle, which the pattern's look depends on); v = t·s, u = mix(s, t, cos v); where
// multiply > 0.001 u is folded by JWildfire's mods ((u.y, u.x) mod ⌊multiply⌋, then mod −u); then p = (u, mX v)
// goes through ⌊loops⌋ + 1 (at most 73) folds p → (1.3, 0.999, 0.678)·|p/(p·p) − (1, 1.02, mY/π)| with y and z
// swapped; iR, iG, iB take a channel c to 1 − c. Gradient 0 paints the point that RGB colour (dbl2int bytes),
// Gradient 1 makes the colour index r·g (left where that is NaN).

// JWildfire's G.atan2: π/4 (1 − r) from the octant's ratio r, not the exact angle; 0/0 (the origin) is NaN.
inline double glslAtan2(double y, double x) {
  const double c1 = kPi / 4.0, c2 = 3.0 * c1, ay = std::abs(y);
  const double angle = x >= 0.0 ? c1 - c1 * ((x - ay) / (x + ay)) : c2 - c1 * ((x + ay) / (ay - x));
  return y < 0.0 ? -angle : angle;
}

// G.Kscope: the point's angle folded into [0, k], its length kept.
inline void mandalaKscope(double& x, double& y, double k) {
  const double a = glslAtan2(y, x), m = 2.0 * k;
  const double angle = std::abs(a - m * std::floor(a / m) - k) + 0.1 * 0.0;
  const double length = std::sqrt(x * x + y * y);
  x = length * std::cos(angle);
  y = length * std::sin(angle);
}

struct MandalaColour {
  double r, g, b;
};

MandalaColour mandalaColour(double u0, double v0, const double* P) {
  constexpr double kRcpi = 0.318309886183791;
  const double mX = P[1], mY = P[2], zoom = 5.5 - P[3], sides = P[4], multiply = P[5], loops = P[6];
  double sx = zoom * u0, sy = zoom * v0;
  const double k = kPi / std::floor(sides);
  mandalaKscope(sx, sy, k);
  double tx = sx, ty = sy;
  mandalaKscope(tx, ty, k);
  const double v = tx * sx + ty * sy, c = std::cos(v);
  double ux = sx * (1.0 - c) + tx * c, uy = sy * (1.0 - c) + ty * c;
  if (multiply > 0.001) {
    const double m = std::floor(multiply);
    const double t2x = uy - m * std::floor(uy / m), t2y = ux - m * std::floor(ux / m);
    const double t3x = -ux, t3y = -uy;
    const double t5x = uy + (t2x - t3x * std::floor(t2x / t3x)), t5y = ux + (t2y - t3y * std::floor(t2y / t3y));
    ux = t5y;
    uy = t5x;
  }
  double px = ux, py = uy, pz = mX * v;
  const double last = std::floor(loops);
  for (int l = 0; l < 73; ++l) {
    if (static_cast<double>(l) > last) break;
    const double d = px * px + py * py + pz * pz;
    const double ax = std::abs(std::abs(px) / d - 1.0), ay = std::abs(std::abs(py) / d - 1.02);
    const double az = std::abs(std::abs(pz) / d - mY * kRcpi);
    px = 1.3 * ax;
    py = 0.678 * az;
    pz = 0.999 * ay;
  }
  const auto flag = [](double value) { return !std::isnan(value) && std::trunc(std::clamp(value, 0.0, 1.0)) == 1.0; };
  if (flag(P[7])) px = 1.0 - px;
  if (flag(P[8])) py = 1.0 - py;
  if (flag(P[9])) pz = 1.0 - pz;
  return {px, py, pz};
}

VOXFLAME_VARIATION_TARGETS void glslMandala(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double width = glslPixelColumns(P[0]);
  const bool index = !std::isnan(P[10]) && std::trunc(std::clamp(P[10], 0.0, 1.0)) == 1.0;
  std::uint32_t* __restrict rgb = index ? nullptr : in.rgb;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [pi, pj] = addGlslPixel(rnd[i], width, w, z[i], outX[i], outY[i], outZ[i]);
    if (!index && !rgb) continue;
    const MandalaColour c = mandalaColour(2.0 * (pi + 0.5) / width - 1.0, 2.0 * (pj + 0.5) / kGlslPixelRows - 1.0, P);
    if (rgb) {
      rgb[i] = paintedRgb(static_cast<std::uint32_t>(rgbByte(c.r)), static_cast<std::uint32_t>(rgbByte(c.g)),
                          static_cast<std::uint32_t>(rgbByte(c.b)));
      continue;
    }
    const double grey = c.r * c.g;
    if (grey == grey) colour[i] = grey;
  }
}

// ---- JWildfire's glsl_acrilic ---------------------------------------------------------------------------
// Sosa's acrylic pour: pixel (i, j) of a resolution × 10⁶ grid drawn at random, the point w (i/resolution − ½,
// j/10⁶ − ½), coloured by the pattern at q = 0.7 (i + ½, j + ½)/size. For each channel c = 0, 1, 2 in turn, q is
// warped by steps k = 1 … Steps − 1: x += 0.1/(k + c) sin(k p1 y + t + cos(t/(p2 k) k + c)), then y += 0.1/(k + c)
// cos(k p3 x + t + sin(t/(p4 k) k + c)) (the warps go on from the last channel's q), and the channel is
// cos((sin(p5 x²) + sin(p6 y²)) · its factor). Gradient 0 paints the point that RGB colour (dbl2int bytes),
// Gradient 1 makes the colour index sin(r/(r + g + b)) (left where that is NaN). Seed only draws JWildfire's random
// time, which the file's time overrides; so it is not used here.
struct AcrilicParams {
  double time, steps, p1, p2, p3, p4, p5, p6, factor[3];
  explicit AcrilicParams(const double* P) {
    const auto limited = [](double v, double low, double high) { return std::isnan(v) ? v : std::clamp(v, low, high); };
    time = P[2];
    steps = std::isnan(P[3]) ? 0.0 : std::trunc(std::clamp(P[3], 3.0, 100.0));
    p1 = limited(P[4], 1.0, 100.0);
    p2 = limited(P[5], 1.0, 100.0);
    p3 = limited(P[6], 1.0, 100.0);
    p4 = limited(P[7], 1.0, 100.0);
    p5 = limited(P[8], 1.0, 100.0);
    p6 = limited(P[9], 1.0, 100.0);
    for (int c = 0; c < 3; ++c) factor[c] = limited(P[10 + c], 0.0, 5.0);
  }
};

// The colour at the pixel's centre (px, py) of a width × height grid.
void acrilicColour(double px, double py, double width, double height, const AcrilicParams& a, double out[3]) {
  double x = 0.7 * px / width, y = 0.7 * py / height;
  const int steps = static_cast<int>(a.steps);
  for (int c = 0; c < 3; ++c) {
    for (int k = 1; k < steps; ++k) {
      const double step = 0.1 / static_cast<double>(k + c), kd = k;
      x += step * std::sin(kd * a.p1 * y + a.time + std::cos((a.time / (a.p2 * kd)) * kd + c));
      y += step * std::cos(kd * a.p3 * x + a.time + std::sin((a.time / (a.p4 * kd)) * kd + c));
    }
    out[c] = std::sin(a.p5 * (x * x)) + std::sin(a.p6 * (y * y));
  }
  for (int c = 0; c < 3; ++c) out[c] = std::cos(out[c] * a.factor[c]);
}

VOXFLAME_VARIATION_TARGETS void glslAcrilic(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double width = glslPixelColumns(P[0]);
  const bool index = !std::isnan(P[13]) && std::trunc(std::clamp(P[13], 0.0, 1.0)) == 1.0;
  std::uint32_t* __restrict rgb = index ? nullptr : in.rgb;
  const AcrilicParams params(P);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [pi, pj] = addGlslPixel(rnd[i], width, w, z[i], outX[i], outY[i], outZ[i]);
    if (!index && !rgb) continue;
    double c[3];
    acrilicColour(pi + 0.5, pj + 0.5, width, kGlslPixelRows, params, c);
    if (rgb) {
      rgb[i] = paintedRgb(static_cast<std::uint32_t>(rgbByte(c[0])), static_cast<std::uint32_t>(rgbByte(c[1])),
                          static_cast<std::uint32_t>(rgbByte(c[2])));
      continue;
    }
    const double grey = std::sin(c[0] / (c[0] + c[1] + c[2]));
    if (grey == grey) colour[i] = grey;
  }
}

}  // namespace

void variation_kernels::addPluginsRareVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  const auto count = &CatalogueAdder::count;

  add("sym_bg2",
      "(x − stepx/2 − 1, y − stepy/2) or (x + stepx/2, −y + stepy/2 + 1), one at random (Ψ < ½ the first), z "
      "(JWildfire's band symmetry group 2)",
      k2D, kRandom, &symBg2, {{"stepx", 0.0, -2.0, 2.0}, {"stepy", 0.0, -2.0, 2.0}});
  add("sym_ng11",
      "q = (x + space, y + space) through one of the square's eight rotations and mirrors, picked by ⌊8Ψ⌋, each "
      "moved by its own (±spacex ± stepx/2, ±spacey ± stepy/2), z (JWildfire's net symmetry group 11)",
      k2D, kRandom, &symNg11,
      {{"space", 0.0, -2.0, 2.0},
       {"spacex", 0.0, -2.0, 2.0},
       {"spacey", 0.0, -2.0, 2.0},
       {"stepx", 1.5, -3.0, 3.0},
       {"stepy", 1.5, -3.0, 3.0}});
  add("sym_ng15",
      "q = p + (ρ, ρ), ρ = √(radius²/2), through one of six rotations and mirrors at multiples of 60° (cos 30° as "
      "0.866), moved by ∓(stepx, stepy)/2: twelve maps, picked by ⌊12Ψ⌋, z (JWildfire's net symmetry group 15)",
      k2D, kRandom, &symNg15, {{"radius", 0.0, 0.0, 2.0}, {"stepx", 0.0, -3.0, 3.0}, {"stepy", 0.0, -3.0, 3.0}});
  add("secant", "(w x, 1/cos(w r)), z: y not scaled by the weight (flam3's before 2.7.10; w the weight)", k2D, kFixed,
      &secant);
  add("julian2dc",
      "julian2's |q|^(dist/power) (cos α, sin α), z, q = (a x + b y + e, c x + d y + f), α = (∠q + 2πk)/power, k = "
      "trunc(|power|·Ψ); the colour index becomes |ρ col + α/2π (1 − col)| mod 1, ρ = w |q|^(dist/power) (xyrus02's)",
      k2D, kRandom, &julian2dc,
      {count("power", 2.0, -12.0, 12.0),
       {"dist", 1.0, -3.0, 3.0},
       {"col", 0.0, -1.0, 2.0},
       {"a", 1.0, -2.0, 2.0},
       {"b", 0.0, -2.0, 2.0},
       {"c", 0.0, -2.0, 2.0},
       {"d", 1.0, -2.0, 2.0},
       {"e", 0.0, -2.0, 2.0},
       {"f", 0.0, -2.0, 2.0}});
  catalogue.back().directColour = true;
  add("shape",
      "w (Ψ − holes) R(φ) (x, y)/r, z: a blur filling the superformula's curve R(φ) = (|cos(m φ/4)/a|^n2 + |sin(m "
      "φ/4)/b|^n3)^(−1/n1), with a hole of holes/(holes − 1) of it where holes < 0 (cyberxaos' Apophysis plugin)",
      k2D, kRandom, &shape,
      {{"m", 6.0, 0.0, 20.0},
       {"n1", 1.0, -5.0, 10.0},
       {"n2", 1.0, -5.0, 10.0},
       {"n3", 1.0, -5.0, 10.0},
       {"a", 1.0, -2.0, 2.0},
       {"b", 1.0, -2.0, 2.0},
       {"holes", 1.0, -2.0, 2.0}});
  add("glsl_circlesblue",
      "w (i/Density Pixels − ½, j/10⁶ − ½), z: pixel i = ⌊Ψ₁ Density Pixels⌋, j = ⌊Ψ₂ 10⁶⌋; Gradient 0 paints the "
      "point the colour of Sosa's rising bubbles at the pixel (Bubles of them, radius Radiusy + 0.12 sin k + 0.08, "
      "placed and coloured by k and time), Gradient 1 makes the colour index sin(r/(r + g + b)); Seed is JWildfire's "
      "random time, which time overrides (JWildfire's)",
      k2D, kRandom, &glslCirclesblue,
      {count("Density Pixels", 1000000.0, 100.0, 1000000.0),
       count("Seed", 10000.0, 0.0, 10000.0),
       {"time", 1.0, 1.0, 1000.0},
       {"Radiusy", 0.04, 0.0, 1.0},
       count("Bubles", 40.0, 1.0, 100.0),
       count("Gradient", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().paintsRgb = true;
  add("glsl_grid3D",
      "w (i/Density Pixels − ½, j/10⁶ − ½), z: pixel i = ⌊Ψ₁ Density Pixels⌋, j = ⌊Ψ₂ 10⁶⌋, painted the grey of "
      "kabuto's ray-marched grid through it (30 steps from (0, 0.1 time, 0), turned by 0.021 time); Seed is "
      "JWildfire's random time, which time overrides (JWildfire's)",
      k2D, kRandom, &glslGrid3d,
      {count("Density Pixels", 1000000.0, 100.0, 1000000.0),
       count("Seed", 10000.0, 0.0, 10000.0),
       {"time", 200.0, 1.0, 1000.0}});
  catalogue.back().paintsRgb = true;
  add("glsl_mandala",
      "w (i/Density Pixels − ½, j/10⁶ − ½), z: pixel i = ⌊Ψ₁ Density Pixels⌋, j = ⌊Ψ₂ 10⁶⌋; Gradient 0 paints the "
      "point the colour of Sosa's kaleidoscope at the pixel ((5.5 − scale)·uv folded into wedges of π/⌊sides⌋, "
      "blended, folded by multiply, then ⌊loops⌋ + 1 folds p → (1.3, 0.999, 0.678)·|p/(p·p) − (1, 1.02, mY/π)| of (u, "
      "mX v); iR, iG, iB invert a channel), Gradient 1 makes the colour index r·g (JWildfire's)",
      k2D, kRandom, &glslMandala,
      {count("Density Pixels", 1000000.0, 100.0, 1000000.0),
       {"mX", 0.025, -1.0, 1.0},
       {"mY", -0.001245675, -1.0, 1.0},
       {"scale", 2.0, 0.0, 5.0},
       {"sides", 12.0, 1.0, 24.0},
       {"multiply", 1.5, 0.0, 5.0},
       {"loops", 64.0, 0.0, 72.0},
       count("iR", 0.0, 0.0, 1.0),
       count("iG", 0.0, 0.0, 1.0),
       count("iB", 1.0, 0.0, 1.0),
       count("Gradient", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().paintsRgb = true;
  add("glsl_acrilic",
      "w (i/Density Pixels − ½, j/10⁶ − ½), z: pixel i = ⌊Ψ₁ Density Pixels⌋, j = ⌊Ψ₂ 10⁶⌋; Gradient 0 paints the "
      "point the colour of Sosa's acrylic pour at the pixel (q = 0.7 uv warped Steps − 1 times per channel by sines "
      "and cosines of p1 … p4 and time, the channel cos((sin(p5 x²) + sin(p6 y²)) · its factor)), Gradient 1 makes the "
      "colour index sin(r/(r + g + b)); Seed is JWildfire's random time, which time overrides (JWildfire's)",
      k2D, kRandom, &glslAcrilic,
      {count("Density Pixels", 1000000.0, 100.0, 1000000.0),
       count("Seed", 10000.0, 0.0, 10000.0),
       {"time", 0.0, 0.0, 1000.0},
       count("Steps", 10.0, 3.0, 100.0),
       {"p1", 12.0, 1.0, 100.0},
       {"p2", 12.0, 1.0, 100.0},
       {"p3", 12.0, 1.0, 100.0},
       {"p4", 12.0, 1.0, 100.0},
       {"p5", 75.0, 1.0, 100.0},
       {"p6", 75.0, 1.0, 100.0},
       {"Red Fac.", 1.0, 0.0, 5.0},
       {"Green Fac.", 1.0, 0.0, 5.0},
       {"Blue Fac.", 1.0, 0.0, 5.0},
       count("Gradient", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  catalogue.back().paintsRgb = true;
}

}  // namespace voxflame::core
