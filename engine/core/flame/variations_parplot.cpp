// JWildfire's parplot2d_wf (ParPlot2DWFFunc): points of a parametric surface (X(u, v), Y(u, v), Z(u, v))
// whose formulas are text parameters (parplot_formula.h evaluates them), at (u, v) drawn uniformly
// from [umin, umax] × [vmin, vmax] (solid = 1) or read from the point's x and y (solid = 0), with the
// colour index set from u and v (direct_color). See variations.h for the notation.
//
// What of JWildfire's it does not do: preset_id is not looked up (a file whose preset_id ≥ 0
// carries the preset's formulas, which JWildfire writes beside it, and those are used); the colour
// map and displacement map (colormap_filename, displ_map_filename) are image files that do not
// travel with the flame, so color_mode 0, blend_colormap, displ_amount and blend_displ_map do
// nothing here (the import says so where a file names an image).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/flame/parplot_formula.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// The surface when a term gives no formulas: a torus of radii 1 and 0.4 over u, v in [0, 2π] (JWildfire
// picks one of its presets at random instead; every file that uses parplot2d_wf writes its formulas).
constexpr const char* kDefaultX = "(1 + 0.4*cos(v))*cos(u)";
constexpr const char* kDefaultY = "(1 + 0.4*cos(v))*sin(u)";
constexpr const char* kDefaultZ = "0.4*sin(v)";

// The parameters in the catalogue's (and JWildfire's) order.
enum Param : std::size_t {
  kPresetId,
  kUMin,
  kUMax,
  kVMin,
  kVMax,
  kDirectColor,
  kColorMode,
  kBlendColormap,
  kDisplAmount,
  kBlendDisplMap,
  kSolid,
  kParamA,  // … param_f
};

// JWildfire's colour modes: the colour map's pixel (0), u (1), v (2), u · v (3 and any other).
constexpr double kColourMap = 0.0, kColourU = 1.0, kColourV = 2.0;

// parplot2d_wf: w (X(u, v), Y(u, v), Z(u, v)), u = umin + (umax − umin) s, v = vmin + (vmax − vmin) t
// (the bounds swapped where min > max), (s, t) = (Ψ₁, Ψ₂) or with solid = 0 (x, y). The formulas'
// NaN and infinities pass through, so the chaos game drops the point and starts it afresh, as
// JWildfire does; a formula that does not compile adds nothing (the import warned).
void parplot2dWf(const VariationInput& in, double* __restrict ox, double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  static const std::array<std::string, 3> kDefaults = {kDefaultX, kDefaultY, kDefaultZ};
  const std::string* texts = in.texts ? in.texts : kDefaults.data();
  ParplotEvaluator& surface = parplotEvaluator(texts[0], texts[1], texts[2]);
  if (!surface.ok()) return;
  surface.setParams(P + kParamA);
  double uMin = P[kUMin], uMax = P[kUMax], vMin = P[kVMin], vMax = P[kVMax];
  if (uMin > uMax) std::swap(uMin, uMax);
  if (vMin > vMax) std::swap(vMin, vMax);
  const double du = uMax - uMin, dv = vMax - vMin;
  // Tools.FTOI of the int parameters: half away from 0, as std::round.
  const bool solid = std::round(P[kSolid]) != 0.0;
  const double mode = std::round(P[kColorMode]);
  const bool setsColour = std::round(P[kDirectColor]) > 0.0 && mode != kColourMap;
  for (std::size_t i = 0; i < n; ++i) {
    double s, t;
    if (solid) {
      s = laneUniform(rnd[i]);
      t = laneUniform(rnd[i]);
    } else {
      s = x[i];
      t = y[i];
    }
    const double u = uMin + s * du, v = vMin + t * dv;
    const std::array<double, 3> q = surface(u, v);
    if (setsColour) {
      const double cu = (u - uMin) / du, cv = (v - vMin) / dv;
      const double c = mode == kColourU ? cu : mode == kColourV ? cv : cv * cu;
      // A collapsed range (umin = umax) gives 0/0, which JWildfire leaves NaN; the chaos game reads
      // a NaN colour as 0, and so is it here.
      colour[i] = std::isnan(c) ? 0.0 : std::clamp(c, 0.0, 1.0);
    }
    outX[i] += w * q[0];
    outY[i] += w * q[1];
    outZ[i] += w * q[2];
  }
}

}  // namespace

void variation_kernels::addParplotVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k3D = CatalogueAdder::k3D, kRandom = CatalogueAdder::kRandom;
  const auto count = &CatalogueAdder::count;
  add("parplot2d_wf",
      "w (X(u, v), Y(u, v), Z(u, v)) with the formulas xformula, yformula, zformula (Java expressions of u, v, pi "
      "and param_a … param_f with JWildfire's MathLib functions; empty: 0), u = umin + (umax − umin) s, v = vmin "
      "+ (vmax − vmin) t, (s, t) = (Ψ, Ψ), with solid = 0 (x, y); direct_color 1: the colour index becomes s "
      "(color_mode 1), t (2) or s t (3), clamped to [0, 1]; color_mode 0 and the displacement map need JWildfire's "
      "image files and do nothing; preset_id is not looked up (files carry the preset's formulas)",
      k3D, kRandom, &parplot2dWf,
      {count("preset_id", -1.0, -1.0, 60.0),
       {"umin", 0.0, -10.0, 10.0},
       {"umax", kTwoPi, -10.0, 10.0},
       {"vmin", 0.0, -10.0, 10.0},
       {"vmax", kTwoPi, -10.0, 10.0},
       count("direct_color", 1.0, 0.0, 1.0),
       count("color_mode", 3.0, 0.0, 3.0),
       count("blend_colormap", 1.0, 0.0, 1.0),
       {"displ_amount", 0.1, -1.0, 1.0},
       count("blend_displ_map", 1.0, 0.0, 1.0),
       count("solid", 1.0, 0.0, 1.0),
       {"param_a", 0.0, -2.5, 2.5},
       {"param_b", 0.0, -2.5, 2.5},
       {"param_c", 0.0, -2.5, 2.5},
       {"param_d", 0.0, -2.5, 2.5},
       {"param_e", 0.0, -2.5, 2.5},
       {"param_f", 0.0, -2.5, 2.5}});
  catalogue.back().textParams = {{"xformula", kDefaultX}, {"yformula", kDefaultY}, {"zformula", kDefaultZ}};
  catalogue.back().directColour = true;
}

}  // namespace voxflame::core
