// JWildfire variations that a few published flames use: polarplot3d_wf (a formula r(t, u) drawn in
// spherical or cylindrical coordinates), isosfplot3d_wf (an implicit surface F(x, y, z) = 0), sunflower
// (a sunflower's seeds as small polygons) and dc_warping (Jesus Sosa's port of Íñigo Quílez's domain-warping shader, a
// DC_BaseFunc painter). Each variation is a kernel below and one row of the table at the end (see variations.h for the
// notation and variation_kernels.h for what the files share). The formulas follow JWildfire's classes of the same names
// (PolarPlot3DWFFunc, IsoSFPlot3DWFFunc, SunFlowersFunc with its DrawFunc, DC_WarpingFunc).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/flame/dc_base_kernel.h"
#include "core/flame/parplot_formula.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// ---- polarplot3d_wf ----------------------------------------------------------------------------

// The formula when a term gives none: preset 0 of JWildfire's (it picks a preset at random instead;
// every file that uses polarplot3d_wf writes its formula).
constexpr const char* kPolarDefaultFormula = "sin(param_a*u) + param_b";

// The parameters in the catalogue's (and JWildfire's) order.
enum PolarParam : std::size_t {
  kPolarPresetId,
  kTMin,
  kTMax,
  kUMin,
  kUMax,
  kRMin,
  kRMax,
  kCylindrical,
  kPolarDirectColor,
  kPolarColorMode,
  kPolarBlendColormap,
  kPolarDisplAmount,
  kPolarBlendDisplMap,
  kPolarParamA,  // … param_f
};

// A range as JWildfire's init takes it: the bounds swapped where min > max.
struct Range {
  double min, span;
};
inline Range orderedRange(double a, double b) {
  if (a > b) std::swap(a, b);
  return {a, b - a};
}

// This thread's surface texts for the last formula it saw, as `Convert` (polarplotSurfaceFormulas,
// isosfplotSurfaceFormulas) makes them from it: it renames the formula's variables, once per formula, not
// per call.
template <std::array<std::string, 3> (*Convert)(const std::string&)>
const std::array<std::string, 3>& surfaceTexts(const std::string& formula) {
  thread_local std::string lastFormula;
  thread_local std::array<std::string, 3> lastTexts;
  thread_local bool any = false;
  if (!any || formula != lastFormula) {
    lastTexts = Convert(formula);
    lastFormula = formula;
    any = true;
  }
  return lastTexts;
}

// polarplot3d_wf: r = R(t, u) at t = tmin + (tmax − tmin) Ψ₁, u = umin + (umax − umin) Ψ₂ (the bounds
// swapped where min > max); spherical (cylindrical 0): w r (sin u cos t, sin u sin t, cos u), else w (r
// cos t, r sin t, u). With direct_color the colour index becomes (t − tmin)/Δt (color_mode 1), (u −
// umin)/Δu (2), (r − rmin)/Δr (3) or the first two's product (4), clamped to [0, 1]; mode 0 reads a
// colour-map image, which does not travel with the flame, and any other mode leaves the index. The
// formula's NaN and infinities pass through (the chaos game drops the point), as in JWildfire; an
// empty formula, or one that does not compile, adds nothing (the import warned).
void polarplot3dWf(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  static const std::string kDefault = kPolarDefaultFormula;
  const std::string& formula = in.texts ? in.texts[0] : kDefault;
  if (formula.empty()) return;
  const std::array<std::string, 3>& texts = surfaceTexts<&polarplotSurfaceFormulas>(formula);
  ParplotEvaluator& surface = parplotEvaluator(texts[0], texts[1], texts[2]);
  if (!surface.ok()) return;
  surface.setParams(P + kPolarParamA);
  const Range t = orderedRange(P[kTMin], P[kTMax]), u = orderedRange(P[kUMin], P[kUMax]),
              r = orderedRange(P[kRMin], P[kRMax]);
  // Tools.FTOI of the int parameters: half away from 0, as std::round.
  const bool spherical = std::round(P[kCylindrical]) == 0.0;
  const double mode = std::round(P[kPolarColorMode]);
  const bool setsColour = std::round(P[kPolarDirectColor]) > 0.0 && mode >= 1.0 && mode <= 4.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ti = t.min + laneUniform(rnd[i]) * t.span;
    const double ui = u.min + laneUniform(rnd[i]) * u.span;
    const double ri = surface(ti, ui)[0];
    if (setsColour) {
      const double ct = (ti - t.min) / t.span, cu = (ui - u.min) / u.span;
      const double c = mode == 1.0 ? ct : mode == 2.0 ? cu : mode == 3.0 ? (ri - r.min) / r.span : ct * cu;
      // A collapsed range gives 0/0, which JWildfire leaves NaN; the chaos game reads a NaN colour as
      // 0, and so is it here.
      colour[i] = std::isnan(c) ? 0.0 : std::clamp(c, 0.0, 1.0);
    }
    if (spherical) {
      const double s = std::sin(ui);
      outX[i] += w * ri * s * std::cos(ti);
      outY[i] += w * ri * s * std::sin(ti);
      outZ[i] += w * ri * std::cos(ui);
    } else {
      outX[i] += w * ri * std::cos(ti);
      outY[i] += w * ri * std::sin(ti);
      outZ[i] += w * ui;
    }
  }
}

// ---- isosfplot3d_wf ----------------------------------------------------------------------------

// The formula when a term gives none: an octahedron's surface, in a box of ±1.5 by default (JWildfire picks
// a preset at random instead; every file that uses isosfplot3d_wf writes its formula and box).
constexpr const char* kIsosfDefaultFormula = "fabs(x) + fabs(y) + fabs(z) - param_a";
constexpr double kIsosfMaxIterations = 100000.0;

// isosfplot3d_wf: up to max_iter times a point (x, y, z) uniform in the box [xmin, xmax] × [ymin, ymax] ×
// [zmin, zmax] (the bounds swapped where min > max) until |F(x, y, z)| ≤ thickness; the first such adds w (x,
// y, z), and a point with none is hidden (JWildfire's doHide) and adds nothing. With direct_color the colour
// index of a found point becomes x's place in its range (color_mode 3), y's (4), z's (5), x's times y's (6),
// y's times z's (7), z's times x's (8), or all three's (9 and any other above 2), clamped to [0, 1]; modes 0 …
// 2 read a colour-map image, which does not travel with the flame. max_iter is at least 1, thickness at least
// 10⁻¹⁰ (JWildfire's setParameter); max_iter is held to 10⁵ here (JWildfire's Java int would let a
// file stall its render). An empty formula is 0: the first point is found.
void isosfplot3dWf(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  static const std::string kDefault = kIsosfDefaultFormula;
  const std::string& formula = in.texts ? in.texts[0] : kDefault;
  const std::array<std::string, 3>& texts = surfaceTexts<&isosfplotSurfaceFormulas>(formula);
  ParplotEvaluator& surface = parplotEvaluator(texts[0], texts[1], texts[2]);
  if (!surface.ok()) return;
  surface.setParams(P + 12);
  const Range bx = orderedRange(P[1], P[2]), by = orderedRange(P[3], P[4]), bz = orderedRange(P[5], P[6]);
  const double thickness = P[7] < 1e-10 ? 1e-10 : P[7];  // (a NaN stays NaN: nothing is ever found)
  // Tools.FTOI of the int parameters: half away from 0, as std::round (a NaN max_iter is 1).
  const double iterations = std::isnan(P[8]) ? 1.0 : std::clamp(std::round(P[8]), 1.0, kIsosfMaxIterations);
  const double mode = std::round(P[10]);
  const bool setsColour = std::round(P[9]) > 0.0 && mode >= 3.0;
  std::uint8_t* __restrict hidden = in.hidden;
  for (std::size_t i = 0; i < n; ++i) {
    double px = 0.0, py = 0.0, pz = 0.0;
    bool found = false;
    for (double k = 0.0; k < iterations && !found; k += 1.0) {
      px = bx.min + laneUniform(rnd[i]) * bx.span;
      py = by.min + laneUniform(rnd[i]) * by.span;
      pz = bz.min + laneUniform(rnd[i]) * bz.span;
      surface.setThird(pz);
      found = std::abs(surface(px, py)[0]) <= thickness;
    }
    if (hidden) hidden[i] = found ? 0u : 1u;
    if (!found) continue;
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * pz;
    if (setsColour) {
      const double cx = (px - bx.min) / bx.span, cy = (py - by.min) / by.span, cz = (pz - bz.min) / bz.span;
      const double c = mode == 3.0   ? cx
                       : mode == 4.0 ? cy
                       : mode == 5.0 ? cz
                       : mode == 6.0 ? cx * cy
                       : mode == 7.0 ? cy * cz
                       : mode == 8.0 ? cz * cx
                                     : cx * cy * cz;
      colour[i] = std::isnan(c) ? 0.0 : std::clamp(c, 0.0, 1.0);
    }
  }
}

// ---- sunflower ---------------------------------------------------------------------------------

constexpr double kJwfRandMax = 32767.0;  // DrawFunc's RAND_MAX

// A point of JWildfire's DrawFunc polygon (FractalDesire's nBlur): `sides` sectors, the angle spread
// arctan-shaped inside one (Ψ₁; the sector from Ψ₂ as JWildfire's rand(32767) mod sides), the radius
// from a hole of `fill` of the way to the edge out to the edge (√Ψ₃ of the way between), turned by half a
// sector. JWildfire draws a uniform it then overwrites before the last; that draw is not made here.
struct PolygonPoint {
  double x, y;
};
class NBlurPolygon {
 public:
  NBlurPolygon(double sides, double fill) : sides_(sides), fill_(fill) {
    sector_ = kTwoPi / sides;
    edgeTan_ = std::tan(kPi / 2.0 + sector_ / 2.0);
    spread_ = 13.0 / std::pow(sides, 1.3);
    spreadNorm_ = 2.0 * std::atan(spread_ / -2.0);
    turnSin_ = std::sin(sector_ / 2.0);
    turnCos_ = std::cos(sector_ / 2.0);
  }
  PolygonPoint operator()(std::uint32_t& state) const {
    const double spread = laneUniform(state);
    const double edge = std::fmod(std::floor(laneUniform(state) * kJwfRandMax), sides_);
    double angle = (std::atan(spread_ * (spread - 0.5)) / spreadNorm_ + 0.5 + edge) * sector_;
    double px = std::sin(angle), py = std::cos(angle);
    // JWildfire steps the angle back one sector at a time; the same steps give the same rounding.
    for (int k = 0; k < 20 && angle > sector_; ++k) angle -= sector_;
    const double tangent = std::tan(angle);
    const double ex = edgeTan_ / (edgeTan_ - tangent), ey = ex * tangent;
    const double outer = std::sqrt(ex * ex + ey * ey), inner = fill_ * outer;
    const double radius = inner + std::sqrt(laneUniform(state)) * (outer - inner);
    px *= radius;
    py *= radius;
    return {turnCos_ * px - turnSin_ * py, turnSin_ * px + turnCos_ * py};
  }

 private:
  double sides_, fill_, sector_, edgeTan_, spread_, spreadNorm_, turnSin_, turnCos_;
};

// sunflower (Jesus Sosa's, after fronkonstin's "sunflowers"): seed k = 1 … nPoints (Ψ₁ picks which)
// lies at ρ (cos θ, sin θ), ρ = √k / √(nPoints + 1), θ = k · angle (3 − √5) · π/180; it is drawn as an
// nBlur polygon of `shape` sides (with a hole of `F. filling`) scaled by scale · s, s = 1 − ρ (invert: ρ),
// and the colour index becomes s. w (q + seed), z: z + w z (JWildfire's preserved z). The `color`
// parameter is JWildfire's too, which it does not read.
VOXFLAME_VARIATION_TARGETS void sunflower(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double count = jwfLimitedInt(P[0], 10.0, 1000.0);
  const double sides = jwfLimitedInt(P[1], 3.0, 20.0);
  // Tools.limitValue passes a NaN through.
  const auto limited = [](double v, double low, double high) { return std::isnan(v) ? v : std::clamp(v, low, high); };
  const double scale = limited(P[2], 0.0, 100.0), angle = limited(P[3], 0.0, 360.0), fill = limited(P[5], 0.0, 1.0);
  const bool invert = jwfLimitedInt(P[6], 0.0, 1.0) == 1.0;
  const double step = angle * (3.0 - std::sqrt(5.0));
  const double rMax = std::sqrt(count + 1.0) / 30.0;
  const NBlurPolygon polygon(sides, fill);
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::min(std::floor(laneUniform(rnd[i]) * count), count - 1.0) + 1.0;
    const double rho = std::sqrt(k) / 30.0 / rMax;
    const double theta = k * step * kPi / 180.0;
    const double s = invert ? rho : 1.0 - rho;
    const PolygonPoint q = polygon(rnd[i]);
    const double size = scale * s;
    outX[i] += w * (q.x * size + rho * std::cos(theta));
    outY[i] += w * (q.y * size + rho * std::sin(theta));
    outZ[i] += w * z[i];
    colour[i] = s;
  }
}

// ---- dc_warping --------------------------------------------------------------------------------

// dc_warping's value noise (JWildfire's CPU code): hash(p) = 2 fract(43758.5453123 sin(127.1 p_x + 311.7
// p_y)) − 1 at the cell's corners, blended by f³ of the place in the cell (the shader's 3 − 2f became
// (3 − 2) f there); fbm sums four octaves of it, turned by (0.8, 0.6; −0.6, 0.8) and scaled by 2.02, 2.03,
// 2.01 between them, over 0.9375.
struct Vec2 {
  double x, y;
};
inline double fract(double v) {
  return v - std::floor(v);
}
inline double mix(double a, double b, double t) {
  return a * (1.0 - t) + b * t;
}
inline double smoothstep(double e0, double e1, double v) {
  const double t = std::clamp((v - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
inline double warpHash(double x, double y) {
  return -1.0 + 2.0 * fract(std::sin(x * 127.1 + y * 311.7) * 43758.5453123);
}
inline double warpNoise(Vec2 p) {
  const double ix = std::floor(p.x), iy = std::floor(p.y);
  const double fx = p.x - ix, fy = p.y - iy;
  const double ux = fx * fx * fx, uy = fy * fy * fy;
  return mix(mix(warpHash(ix, iy), warpHash(ix + 1.0, iy), ux),
             mix(warpHash(ix, iy + 1.0), warpHash(ix + 1.0, iy + 1.0), ux), uy);
}
inline Vec2 warpTurn(Vec2 p, double scale) {
  const double x = p.x * scale, y = p.y * scale;
  return {0.8 * x - 0.6 * y, 0.6 * x + 0.8 * y};
}
inline double warpFbm(Vec2 p) {
  double f = 0.5 * warpNoise(p);
  p = warpTurn(p, 2.02);
  f += 0.25 * warpNoise(p);
  p = warpTurn(p, 2.03);
  f += 0.125 * warpNoise(p);
  p = warpTurn(p, 2.01);
  f += 0.0625 * warpNoise(p);
  return f / 0.9375;
}
inline Vec2 warpFbm2(Vec2 p) {
  return {warpFbm(p), warpFbm({p.y, p.x})};
}
// The colour of the warped field at p: dark red to orange by fbm(0.7 p), darkened to near black by the
// twice-warped field fbm2(q + fbm2(2 (q + fbm2(4q)))), q = 0.7 p.
inline Rgb warpMap(Vec2 p) {
  p = {p.x * 0.7, p.y * 0.7};
  const Vec2 inner = warpFbm2({p.x * 4.0, p.y * 4.0});
  const Vec2 middle = warpFbm2({(p.x + inner.x) * 2.0, (p.y + inner.y) * 2.0});
  const Vec2 outer = warpFbm2({p.x + middle.x, p.y + middle.y});
  const double bl = smoothstep(-0.8, 0.8, outer.x - outer.y);
  const double ti = smoothstep(-1.0, 1.0, warpFbm(p));
  return {mix(mix(0.5, 1.0, ti), 0.0, bl), mix(mix(0.0, 0.75, ti), 0.0, bl), mix(mix(0.0, 0.35, ti), 0.02, bl)};
}

// dc_warping: at p = zoom · the point + (x0, y0) the map's colour c, with g the grey (c · 0.333) there and
// 0.0045 to the right and above: c + 8 |2g − g_a − g_b| (1, 0.7, 0.6), times 1 + 0.2 n_y², plus 0.05 n_y³
// (n the unit (g_a − g, 0.0045, g_b − g)), times (16 q_x q_y (1 − q_x)(1 − q_y))^0.1, q = (the point + 1)/2
// (unzoomed, as JWildfire's CPU code has it). Square [−½, ½]².
VOXFLAME_VARIATION_TARGETS void dcWarping(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  const double* P = in.params;
  const double zoom = P[1], x0 = P[2], y0 = P[3];
  dcBaseKernel(in, ox, oy, oz, 4, 0.5, [&](double px, double py) {
    const Vec2 p{px * zoom + x0, py * zoom + y0};
    constexpr double e = 0.0045;
    const auto grey = [](const Rgb& c) { return c.r * 0.333 + c.g * 0.333 + c.b * 0.333; };
    const Rgb c = warpMap(p);
    const double gc = grey(c), ga = grey(warpMap({p.x + e, p.y})), gb = grey(warpMap({p.x, p.y + e}));
    const double nx = ga - gc, nz = gb - gc;
    const double ny = e / std::sqrt(nx * nx + e * e + nz * nz);
    const double edge = 8.0 * std::abs(2.0 * gc - ga - gb);
    const double lift = 1.0 + 0.2 * ny * ny, sheen = 0.05 * ny * ny * ny;
    const double qx = (px + 1.0) / 2.0, qy = (py + 1.0) / 2.0;
    const double vignette = std::pow(16.0 * qx * qy * (1.0 - qx) * (1.0 - qy), 0.1);
    return Rgb{((c.r + edge) * lift + sheen) * vignette, ((c.g + 0.7 * edge) * lift + sheen) * vignette,
               ((c.b + 0.6 * edge) * lift + sheen) * vignette};
  });
}

}  // namespace

void variation_kernels::addJwildfireRareVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("polarplot3d_wf",
      "r = R(t, u) with the formula `formula` (a Java expression of t, u, pi and param_a … param_f with JWildfire's "
      "MathLib functions), t = tmin + (tmax − tmin) Ψ, u = umin + (umax − umin) Ψ; cylindrical 0: w r (sin u cos t, "
      "sin u sin t, cos u), 1: w (r cos t, r sin t, u); direct_color 1: the colour index becomes t's place in its "
      "range (color_mode 1), u's (2), r's in [rmin, rmax] (3) or t's times u's (4), clamped to [0, 1]; color_mode 0 "
      "and the displacement map need JWildfire's image files and do nothing; preset_id is not looked up (files carry "
      "the preset's formula); an empty formula adds nothing",
      k3D, kRandom, &polarplot3dWf,
      {count("preset_id", -1.0, -1.0, 60.0),
       {"tmin", -kPi, -10.0, 10.0},
       {"tmax", kPi, -10.0, 10.0},
       {"umin", 0.0, -10.0, 10.0},
       {"umax", kPi, -10.0, 10.0},
       {"rmin", -2.0, -10.0, 10.0},
       {"rmax", 2.0, -10.0, 10.0},
       count("cylindrical", 0.0, 0.0, 1.0),
       count("direct_color", 1.0, 0.0, 1.0),
       count("color_mode", 2.0, 0.0, 4.0),
       count("blend_colormap", 1.0, 0.0, 1.0),
       {"displ_amount", 0.1, -1.0, 1.0},
       count("blend_displ_map", 1.0, 0.0, 1.0),
       {"param_a", 5.0, -10.0, 10.0},
       {"param_b", 2.0, -10.0, 10.0},
       {"param_c", 0.0, -10.0, 10.0},
       {"param_d", 0.0, -10.0, 10.0},
       {"param_e", 0.0, -10.0, 10.0},
       {"param_f", 0.0, -10.0, 10.0}});
  catalogue.back().textParams = {{"formula", kPolarDefaultFormula}};
  catalogue.back().directColour = true;
  add("isosfplot3d_wf",
      "w (x, y, z), the first of up to max_iter points Ψ-uniform in the box [xmin, xmax] × [ymin, ymax] × [zmin, zmax] "
      "where |F(x, y, z)| ≤ thickness, F the formula `formula` (a Java expression of x, y, z, pi and param_a … "
      "param_f with JWildfire's MathLib functions); with none the point is hidden and nothing is added; "
      "direct_color 1: the colour index becomes x's place in its range (color_mode 3), y's (4), z's (5), x's times "
      "y's (6), y's times z's (7), z's times x's (8), the three's (9), clamped to [0, 1]; color_mode 0 … 2 need "
      "JWildfire's colour-map image and do nothing; preset_id is not looked up (files carry the preset's formula)",
      k3D, kRandom, &isosfplot3dWf,
      {count("preset_id", -1.0, -1.0, 60.0),
       {"xmin", -1.5, -10.0, 10.0},
       {"xmax", 1.5, -10.0, 10.0},
       {"ymin", -1.5, -10.0, 10.0},
       {"ymax", 1.5, -10.0, 10.0},
       {"zmin", -1.5, -10.0, 10.0},
       {"zmax", 1.5, -10.0, 10.0},
       {"thickness", 0.05, 0.0, 1.0},
       count("max_iter", 160.0, 1.0, 1000.0),
       count("direct_color", 1.0, 0.0, 1.0),
       count("color_mode", 9.0, 0.0, 9.0),
       count("blend_colormap", 1.0, 0.0, 1.0),
       {"param_a", 1.0, -10.0, 10.0},
       {"param_b", 0.0, -10.0, 10.0},
       {"param_c", 0.0, -10.0, 10.0},
       {"param_d", 0.0, -10.0, 10.0},
       {"param_e", 0.0, -10.0, 10.0},
       {"param_f", 0.0, -10.0, 10.0}});
  catalogue.back().textParams = {{"formula", kIsosfDefaultFormula}};
  catalogue.back().directColour = true;
  catalogue.back().hidesPoints = true;
  add("sunflower",
      "w (scale · s · q + ρ (cos θ, sin θ)), z: seed k = 1 + ⌊nPoints Ψ⌋, ρ = √(k/(nPoints + 1)), θ = k · angle (3 − "
      "√5) π/180, s = 1 − ρ (invert: ρ), q a point of an nBlur polygon of `shape` sides with a hole of fill (the "
      "file's \"F. filling\"); the colour index becomes s; color is JWildfire's unused parameter",
      k2D, kRandom, &sunflower,
      {count("nPoints", 500.0, 10.0, 1000.0),
       count("shape", 10.0, 3.0, 20.0),
       {"scale", 0.02, 0.0, 100.0},
       {"angle", 180.0, 0.0, 360.0},
       {"color", 0.0, 0.0, 1.0},
       {"fill", 0.0, 0.0, 1.0},
       count("invert", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  // The DC_BaseFunc painters' common parameters (as dc_tesla's in variations_jwildfire_holdout.cpp).
  std::vector<VariationParam> dcWarpingParams = {count("randomize", 0.0, 0.0, 10000.0),
                                                 {"zoom", 1.0, -10.0, 10.0},
                                                 {"x0", 0.0, -1.0, 1.0},
                                                 {"y0", 0.0, -1.0, 1.0},
                                                 count("ColorOnly", 0.0, 0.0, 1.0),
                                                 count("Gradient", 0.0, 0.0, 2.0),
                                                 {"scale_z", 0.0, -2.0, 2.0},
                                                 {"offset_z", 0.0, -2.0, 2.0},
                                                 count("reset_z", 1.0, 0.0, 1.0)};
  add("dc_warping",
      "w q, q = Ψ-uniform in [−½, ½]² (ColorOnly: the point); Gradient 2: colour index the grey level of Quílez's "
      "domain-warped fbm colour at zoom q + (x0, y0) (dark red to orange, darkened where the twice-warped field is "
      "high, with its relief's light and a vignette of q); Gradient 0 paints the point that RGB colour, 1 the "
      "palette's entry nearest to it, both leaving the index; z + grey · scale_z + offset_z (reset_z: z = that); "
      "randomize is JWildfire's seed of the shift: a file with x0 (JWildfire since 2020) shifts by (x0, x0), one "
      "without by the seed's first two 2 · java.util.Random(randomize).nextDouble() − 1 (the import sets y0)",
      k3D, kRandom, &dcWarping, std::move(dcWarpingParams));
  VariationInfo& warping = catalogue.back();
  warping.directColour = warping.readsSum = warping.paintsRgb = true;
}

}  // namespace voxflame::core
