// The direct-colour variations of core/flame/variations_direct_colour.cpp (Fractorium's dc_ ones, randCubes and
// curl_sp; falloff3's colour shift and pixel_flow's enable_dc too): where they move the point (the PointCase table) and
// the colour index they set, each worked out from Fractorium's published formulas by a separate Python script in double
// precision, independently of the code under test. The point is (0.3, −0.7, 0.5) with weight 0.8 unless a row says
// otherwise; the harness (variation_point_case.h) starts the outputs at (0.125, −0.25, 0.5), which is the running sum
// an ordinary dc term colours by, and the colour at 0.375. Random variations are replayed from the lane's seed:
// xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594 first from 0x9E3779B9. Then the chaos
// game's part: the transform's direct_color blend.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame/flame.h"
#include "core/flame/noise.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

// dc_perlin with select_range 2: the notch is [−2, 2], wider than the noise (|N| < 1.5 for two octaves), so the first
// draw is kept and the point is w (vx, vy) of it.
std::vector<double> perlinParams(double shape) {
  return {shape, 0.0, 0.0, 2.0, 0.25, 0.25, 0.0, 1.0, 2.0, 2.0, 2.0, 0.0, 10.0, 0.0};
}

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // dc_bubble: s = 0.8 / (0.58/4 + 1); (s x, s y, 0.8 (2/s − 1) = 2·1.145 − 0.8).
      {"dc_bubble", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.20960698689956334, -0.48908296943231444, 1.49}},
      {"dc_bubble",
       {0.2, -0.1, 0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.20960698689956334, -0.48908296943231444, 1.49}},
      // dc_carpet: Ψ₁ = 0.879 → x0 = −1, Ψ₂ = 0.545 → y0 = −1; q = (−0.7, −1.7) through (a qx + b qy + e, c qx + d qy
      // + f) of the test affine (a 0.9, b 0.2, c 0.3, d −0.1, e 0.8, f −0.4).
      {"dc_carpet", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.13599999999999995, -0.35200000000000004, 0.4}},
      // Ψ₁ = 0.317 → x0 = +1, then Ψ₂ ≥ ½ → y0 = −1: q = (1.3, −1.7).
      {"dc_carpet", {0.6}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {1.3040000000000003, 0.12800000000000003, 0.4}},
      // dc_cube: p, q = 2Ψ − 1, the face axis ⌊3Ψ₃⌋ = 1 (y), Ψ₄ < ½: the −y face.
      {"dc_cube", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6071462631225586, -0.8, 0.07252082824707032}},
      {"dc_cube",
       {0.1, 0.2, 0.3, 0.4, 0.5, 1.5, 0.5, 2.0, 3.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.14672517776489258, -1.6, 1.8033934593200684}},
      // dc_cylinder: τ = 2πΨ₁, ρ = blur (Ψ₂ + … + Ψ₅ − 2); (w sin(x + ρ sin τ) X, ρ + y Y, w cos(x + ρ cos τ)).
      {"dc_cylinder",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.03682627549056853, -0.19978704452514648, 0.7809955263610336}},
      {"dc_cylinder",
       {0.3, 0.7, 0.9, 0.5, -0.25, 0.4},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.15449274146413394, 0.28065779209136965, 0.7737113686073505}},
      // dc_gridout: one row per branch (the rounded point's quadrant and side of the diagonal).
      {"dc_gridout", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {1.04, -0.5599999999999999, 0.4}},  // (0, −1): +x
      {"dc_gridout", {}, {1.6, -0.4, 0.5}, 0.8, kHighSeed, {1.2800000000000002, 0.48, 0.4}},   // (2, 0): +y
      {"dc_gridout", {}, {0.6, -2.4, 0.5}, 0.8, kHighSeed, {1.2800000000000002, -1.92, 0.4}},  // (1, −2): +x
      {"dc_gridout", {}, {-2.6, -1.4, 0.5}, 0.8, kHighSeed, {-2.08, -1.92, 0.4}},              // (−3, −1): −y
      {"dc_gridout", {}, {2.2, 0.6, 0.5}, 0.8, kHighSeed, {1.7600000000000002, 1.2800000000000002, 0.4}},    // +y
      {"dc_gridout", {}, {0.6, 2.4, 0.5}, 0.8, kHighSeed, {-0.32000000000000006, 1.92, 0.4}},                // −x
      {"dc_gridout", {}, {-0.6, 2.3, 0.5}, 0.8, kHighSeed, {-1.2800000000000002, 1.8399999999999999, 0.4}},  // −x
      {"dc_gridout", {}, {-2.4, 0.6, 0.5}, 0.8, kHighSeed, {-1.92, -0.32000000000000006, 0.4}},              // −y
      // dc_linear: w p.
      {"dc_linear", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"dc_linear", {0.25, 0.6, 2.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      // dc_perlin: shape 0 (square), 1 (disc), 2 (blur), from the first draws.
      {"dc_perlin",
       perlinParams(0.0),
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3035731315612793, 0.03626041412353516, 0.4}},
      {"dc_perlin",
       perlinParams(1.0),
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.03383802763268992, -0.3213028873903812, 0.4}},
      {"dc_perlin",
       perlinParams(2.0),
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.09883605318387707, -0.3376169759576229, 0.4}},
      // dc_triangle on the test affine's triangle (origin (0.8, −0.4), edges (0.9, 0.2) and (−0.3, 0.1)): (0.3, −0.7)
      // is outside (u, v < 0), clamped to the origin corner; (0.75, −0.3) is inside, u = 1/6, v = 2/3.
      {"dc_triangle", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6400000000000001, -0.32000000000000006, 0.4}},
      {"dc_triangle", {}, {0.75, -0.3, 0.5}, 0.8, kHighSeed, {0.6000000000000001, -0.24000000000000005, 0.4}},
      // scatter_area 0.5: (u, v) = (0, 0) + 0.5 (Ψ₁, Ψ₂); and −0.5.
      {"dc_triangle", {0.5, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.8911688470840455, -0.22782966613769534, 0.4}},
      {"dc_triangle", {-0.5, 0.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.6311111664772034, -0.380355761051178, 0.4}},
      // (1.2, −0.2) is beyond the edge u + v = 1: (2/3, 1/3) on it, then scattered inwards (f = −1).
      {"dc_triangle", {}, {1.2, -0.2, 0.5}, 0.8, kHighSeed, {1.0399999999999996, -0.18666666666666673, 0.4}},
      {"dc_triangle", {0.5, 0.0}, {1.2, -0.2, 0.5}, 0.8, kHighSeed, {0.7888311529159542, -0.2788370005289714, 0.4}},
      // zero_edges: an outside point goes to the origin corner whatever the scatter.
      {"dc_triangle", {0.5, 1.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.6400000000000001, -0.32000000000000006, 0.4}},
      // dc_ztransl at the harness's colour 0.375: overwrite → w·0.375; x0 0.8, x1 0.2 (sorted), factor 2: zf =
      // 2 (0.375 − 0.2)/0.6, times w z without overwrite; clamp leaves it (it is in [0, 1]).
      {"dc_ztransl", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.30000000000000004}},
      {"dc_ztransl",
       {0.8, 0.2, 2.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.2333333333333333}},
      {"dc_ztransl",
       {0.8, 0.2, 2.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.2333333333333333}},
      // randCubes: block (6, −2) (and (1, −2)) with the Jenkins-hash height; the weight is not applied.
      {"randCubes",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {6.9479634165763855, -1.0045270323753357, 1.1948815209519918}},
      {"randCubes", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {1.899222195148468, -1.0252407789230347, 0.7726046903354913}},
      {"randCubes",
       {0.5, 2.0, 1.5, 7.0, 1.25},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {2.3489817082881927, -0.12726351618766785, 3.3557543781373393}},
      // curl_sp: at its defaults linear; then signed powers, spread and the 1/pow-th power of the denominator.
      {"curl_sp", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"curl_sp",
       {1.5, 0.4, -0.3, 0.2, 0.1, 0.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.18866649890616133, -0.40747538071710515, 0.20506767719962415}},
      {"curl_sp",
       {0.5, 0.4, 0.3, -0.2, 0.5, -0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2371527077938141, -0.10551026832314431, 0.12611956659784174}},
      // The blurs (variations_blurs.cpp), each at its defaults and at other parameters, from both seeds: gaussian adds
      // the unweighted point; blur_pixelize's cell is ⌊x · (1/size)⌋ as Fractorium multiplies (0.3 · 10
      // = 3.0000000000000004:
      // cell 3, where 0.3/0.1 would give 2); juliaq's branch is ⌊32767 Ψ⌋, Juliac's ⌊2²⁴ Ψ⌋ mod re.
      {"gaussian", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.23472354263529233, -0.6382881895456264, 0.4}},
      {"gaussian", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.21413893125407663, -0.5069141305214175, 0.4}},
      {"blur_square", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6071462631225586, 0.07252082824707032, 0.4}},
      {"blur_square", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.29345035552978516, 0.6011311531066895, 0.4}},
      {"circleblur", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.720020135481507, -0.21078308696433848, 0.4}},
      {"circleblur", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.3197029247729246, -0.3168752083703041, 0.4}},
      {"blur_pixelize", {0.1, 1.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.31035731315612797, -0.5163739585876466, 0.4}},
      {"blur_pixelize", {0.1, 1.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.26532748222351077, -0.48994344234466564, 0.4}},
      {"blur_pixelize", {0.25, 0.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.33794664144515996, -0.4954674482345581, 0.4}},
      {"blur_pixelize", {0.25, 0.5}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.2816593527793884, -0.46242930293083195, 0.4}},
      {"blur_heart",
       {0.5, -0.6, 0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.6071462631225586, 0.07252082824707032, 0.4}},
      {"blur_heart",
       {0.5, -0.6, 0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.29345035552978516, 0.5463481827476969, 0.4}},
      {"blur_heart",
       {1.5, 0.4, -0.9},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.6071462631225586, -0.44405475590597476, 0.4}},
      {"blur_heart",
       {1.5, 0.4, -0.9},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.29345035552978516, -0.706708319516731, 0.4}},
      {"d_spherical", {0.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"d_spherical", {0.5}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"d_spherical", {0.9}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"d_spherical", {0.9}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"juliaq", {3.0, 2.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.6430061532260809, -0.1779072441616403, 0.4}},
      {"juliaq", {3.0, 2.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.6430061532249889, -0.17790724416558742, 0.4}},
      {"juliaq", {-2.5, 1.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.3541201706579859, 0.872929879357518, 0.4}},
      {"juliaq", {-2.5, 1.5}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.7995845454835694, -0.49806849344824605, 0.4}},
      {"Juliac", {2.0, 1.0, 1.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.5886158801893678, -0.39043543543591874, 0.4}},
      {"Juliac", {2.0, 1.0, 1.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.5886158801893678, -0.39043543543591874, 0.4}},
      {"Juliac", {3.5, -20.0, 0.7}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-6.8916646579113054, -12.053751379686474, 0.4}},
      {"Juliac", {3.5, -20.0, 0.7}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.5741002887670731, -0.17444007773525566, 0.4}},
      {"coth_spiral", {4.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6656377151948157, 0.01386080766934956, 0.4}},
      {"coth_spiral", {4.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.6183516380064221, -0.43166326087102713, 0.4}},
      {"coth_spiral", {-1.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6746905217230302, -0.05283011057197881, 0.4}},
      {"coth_spiral", {-1.5}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.6006228628362837, -0.41628074615740857, 0.4}},
      // depth_gaussian: no blur within the radius; beyond it √(−2 ln(1 − Ψ₁)) blur/10 (r − radius) at 2πΨ₂.
      {"depth_gaussian", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_gaussian", {}, {1.2, -0.9, 0.5}, 0.8, kHighSeed, {0.8810303749356656, -0.7431180497977953, 0.4}},
      {"depth_gaussian", {}, {1.2, -0.9, 0.5}, 0.8, kLowSeed, {0.9847886192434999, -0.7445693682457716, 0.4}},
      {"depth_gaussian", {2.5, 0.4}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0972318767561118, -0.6017948113594453, 0.4}},
      {"depth_gaussian", {2.5, 0.4}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.28481501139607385, -0.6044186304655637, 0.4}},
      // depth_ngon and depth_sine: as depth_gaussian, the blur's radius 1/cos of the angle from the pentagon's (or
      // triangle's) side middle, or acos(2Ψ₂ − 1)/π (power 1), acos(2 (1 − Ψ₂)^power − 1)/π.
      {"depth_ngon", {}, {1.2, -0.9, 0.5}, 0.8, kHighSeed, {0.993108806582446, -0.7513007855921283, 0.4}},
      {"depth_ngon", {}, {1.2, -0.9, 0.5}, 0.8, kLowSeed, {0.9412280490654802, -0.677785309210082, 0.4}},
      {"depth_ngon", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_ngon", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_ngon", {3.0, 2.5, 0.4}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3123154621172781, -0.6283664259867557, 0.4}},
      {"depth_ngon",
       {3.0, 2.5, 0.4},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.21045373403023332, -0.49355584157122756, 0.4}},
      {"depth_sine", {}, {1.2, -0.9, 0.5}, 0.8, kHighSeed, {0.9736935117673604, -0.7329457301569029, 0.4}},
      {"depth_sine", {}, {1.2, -0.9, 0.5}, 0.8, kLowSeed, {0.9562720892540002, -0.7116166092707285, 0.4}},
      {"depth_sine", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_sine", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_sine", {2.5, 2.5, 0.4}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.2797490528956664, -0.5975784182700524, 0.4}},
      {"depth_sine", {2.5, 2.5, 0.4}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.21199876414672222, -0.4970303322544922, 0.4}},
      // bTransform: at power 1 without moves the bipolar round trip gives w p back (to rounding); then on one of three
      // branches. boarders2: the scaled offset from the rounded point, pushed towards the border when Ψ < |c| (1 +
      // |right|) (always for right 0.6, c 0.8).
      {"bTransform", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24000000000000007, -0.56, 0.4}},
      {"bTransform", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.24000000000000007, -0.56, 0.4}},
      {"bTransform",
       {0.7, 3.0, 0.2, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {1.9229976592387403, -1.0740219774923419, 0.4}},
      {"bTransform",
       {0.7, 3.0, 0.2, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.40292267325342335, 0.5901413154247024, 0.4}},
      {"bTransform",
       {0.7, 3.0, 0.2, 0.3},
       {-0.4, 0.9, 0.5},
       0.8,
       kHighSeed,
       {-0.24816614118722494, -0.9799251372143857, 0.4}},
      {"bTransform",
       {0.7, 3.0, 0.2, 0.3},
       {-0.4, 0.9, 0.5},
       0.8,
       kLowSeed,
       {-0.6418062254105855, 1.8016458026441842, 0.4}},
      {"boarders2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.12, -0.68, 0.4}},
      {"boarders2", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.31999999999999995, -0.48, 0.4}},
      {"boarders2", {}, {1.2, -0.9, 0.5}, 0.8, kHighSeed, {0.8800000000000001, -0.76, 0.4}},
      {"boarders2", {}, {1.2, -0.9, 0.5}, 0.8, kLowSeed, {1.08, -0.66, 0.4}},
      {"boarders2", {0.8, -0.3, 0.6}, {2.35, 0.1, 0.5}, 0.8, kHighSeed, {2.0160000000000005, 0.11885714285714287, 0.4}},
      {"boarders2", {0.8, -0.3, 0.6}, {2.35, 0.1, 0.5}, 0.8, kLowSeed, {2.0160000000000005, 0.11885714285714287, 0.4}},
      {"boarders2", {0.8, -0.3, 0.6}, {-0.2, -1.4, 0.5}, 0.8, kHighSeed, {-0.22400000000000003, -1.248, 0.4}},
      {"boarders2", {0.8, -0.3, 0.6}, {-0.2, -1.4, 0.5}, 0.8, kLowSeed, {-0.22400000000000003, -1.248, 0.4}},
      // cpow3: at its defaults (exponent 1) the point itself on a random branch (a whole number of turns); then
      // other exponents, a negative d and divisor. GlynnSim5: 0 within radius + thickness; beyond, w p or w (α², α²).
      {"cpow3", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.23999999999999402, -0.5600000000000026, 0.4}},
      {"cpow3", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.24000000000002478, -0.5599999999999894, 0.4}},
      {"cpow3",
       {1.3, -0.6, 2.5, 0.8},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2463281803653624, -1.0130260619986617, 0.4}},
      {"cpow3",
       {1.3, -0.6, 2.5, 0.8},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.8873254435142856, -0.5473142899859308, 0.4}},
      {"cpow3",
       {0.7, 2.2, -3.0, 2.0},
       {-0.9, -0.4, 0.5},
       0.8,
       kHighSeed,
       {-0.2341294567911553, 1.4198540699711608, 0.4}},
      {"cpow3", {0.7, 2.2, -3.0, 2.0}, {-0.9, -0.4, 0.5}, 0.8, kLowSeed, {1.1272812947206912, 1.4770921679122502, 0.4}},
      {"GlynnSim5", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      {"GlynnSim5", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.0, 0.0, 0.4}},
      {"GlynnSim5", {}, {1.2, -0.9, 0.5}, 0.8, kHighSeed, {0.96, -0.7200000000000001, 0.4}},
      {"GlynnSim5", {}, {1.2, -0.9, 0.5}, 0.8, kLowSeed, {0.96, -0.7200000000000001, 0.4}},
      {"GlynnSim5", {0.5, 0.2, 0.9, 0.5}, {0.6, 0.8, 0.5}, 0.8, kHighSeed, {0.48, 0.6400000000000001, 0.4}},
      {"GlynnSim5", {0.5, 0.2, 0.9, 0.5}, {0.6, 0.8, 0.5}, 0.8, kLowSeed, {0.2, 0.2, 0.4}},
      // GlynnSim4: w (X, Y) within the radius, else w p or w α² p. hex_rand: a hexagon centre of the lattice and a
      // point in it, or 0 where the hexagon's hash is not below density (0.5, second seed).
      {"GlynnSim4", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      {"GlynnSim4", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.0, 0.0, 0.4}},
      {"GlynnSim4", {}, {1.2, -0.9, 0.5}, 0.8, kHighSeed, {0.96, -0.7200000000000001, 0.4}},
      {"GlynnSim4", {}, {1.2, -0.9, 0.5}, 0.8, kLowSeed, {0.96, -0.7200000000000001, 0.4}},
      {"GlynnSim4", {0.5, 0.9, 0.5, 0.3, -0.2}, {0.6, 0.8, 0.5}, 0.8, kHighSeed, {0.48, 0.6400000000000001, 0.4}},
      {"GlynnSim4", {0.5, 0.9, 0.5, 0.3, -0.2}, {0.6, 0.8, 0.5}, 0.8, kLowSeed, {0.12, 0.16000000000000003, 0.4}},
      {"GlynnSim4", {0.5, 0.9, 0.5, 0.3, -0.2}, {0.1, 0.2, 0.5}, 0.8, kHighSeed, {0.24, -0.16000000000000003, 0.4}},
      {"GlynnSim4", {0.5, 0.9, 0.5, 0.3, -0.2}, {0.1, 0.2, 0.5}, 0.8, kLowSeed, {0.24, -0.16000000000000003, 0.4}},
      {"hex_rand", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-1.204345047679583, -2.0773411160007873, 0.4}},
      {"hex_rand", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {5.200467065715616, -0.69315020043363, 0.4}},
      {"hex_rand",
       {3.0, 5.0, 0.7, 2.0, 0.5, 3.25},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.801387085594429, -1.3852831512259813, 0.4}},
      {"hex_rand", {3.0, 5.0, 0.7, 2.0, 0.5, 3.25}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.0, 0.0, 0.4}},
      // checks: cells (0, −1) (even: + (x, y + rnd Ψ₂)), (1, 0), (−1, 0) (odd: + (rnd Ψ₁ − x, −y)), …
      {"checks", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6400000000000001, -0.15999999999999998, 0.4}},
      {"checks", {}, {0.3, -0.2, 0.5}, 0.8, kHighSeed, {-0.16000000000000003, -0.5599999999999999, 0.4}},
      {"checks", {}, {-0.3, 0.0, 0.5}, 0.8, kHighSeed, {-0.6400000000000001, -0.4, 0.4}},
      {"checks", {0.3, -0.2, 0.25, 0.6}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.48, -0.45824375152587893, 0.4}},
      {"checks",
       {0.3, -0.2, 0.25, 0.6},
       {-1.1, 0.4, 0.5},
       0.8,
       kHighSeed,
       {-0.6400000000000001, 0.4217562484741211, 0.4}},
      {"checks", {0.3, -0.2, 0.25, 0.6}, {0.4, -0.2, 0.5}, 0.8, kHighSeed, {0.5021438789367675, 0.0, 0.4}},
      // glynnia2: both branches above the x axis and below it; crackle2 from the cell's hashed point towards a
      // neighbour's (no weight on x, y).
      {"glynnia2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.5828419506072339, 0.3843237429403043, 0.4}},
      {"glynnia2", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.7653089745523847, -0.5046417974878833, 0.4}},
      {"glynnia2", {}, {0.3, 0.7, 0.5}, 0.8, kHighSeed, {0.5828419506072339, -0.3843237429403043, 0.4}},
      {"glynnia2", {}, {0.3, 0.7, 0.5}, 0.8, kLowSeed, {0.7653089745523847, 0.5046417974878833, 0.4}},
      {"glynnia2", {}, {-0.4, 0.2, 0.5}, 0.8, kHighSeed, {0.12291603052485284, -0.5206806608277156, 0.4}},
      {"glynnia2", {}, {-0.4, 0.2, 0.5}, 0.8, kLowSeed, {0.27484859977801007, 1.1642773521802838, 0.4}},
      {"crackle2", {1.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.09872903639878136, -0.4757137757474573, 0.4}},
      {"crackle2", {1.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.19864198701025243, -0.7892204262509634, 0.4}},
      {"crackle2", {1.0}, {2.3, 1.6, 0.5}, 0.8, kHighSeed, {2.07078858534045, 1.209129431249221, 0.4}},
      {"crackle2", {1.0}, {2.3, 1.6, 0.5}, 0.8, kLowSeed, {2.158027889287928, 0.5782566381163528, 0.4}},
      {"crackle2", {0.35}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3548738192995916, 0.1742862242525427, 0.4}},
      {"crackle2", {0.35}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.19864198701025243, 0.17492467088553404, 0.4}},
  };
  return cases;
}

class ColourVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(ColourVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Colour, ColourVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// The colour index a row's variation leaves in every one of 37 lanes (the harness's colour was 0.375).
const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      // |(S + centre)|² / scale mod 1 at the running sum S = (0.125, −0.25) + (s x, s y).
      {"dc_bubble", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.658205471386892},
      {"dc_bubble", {0.2, -0.1, 0.7}, {0.3, -0.7, 0.5}, kHighSeed, 0.41409265719025723},
      // equal signs: |c/2| = 0.1875 (origin does nothing then); different: |c (1 + h)/2 − (1 − h)| mod 1, h = 0.12.
      {"dc_carpet", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.1875},
      {"dc_carpet", {}, {0.3, -0.7, 0.5}, kLowSeed, 0.8125},
      {"dc_carpet", {0.6}, {0.3, -0.7, 0.5}, kLowSeed, 0.6699999999999999},
      // the −y face: c3.
      {"dc_cube", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.0},
      {"dc_cube", {0.1, 0.2, 0.3, 0.4, 0.5, 1.5, 0.5, 2.0, 3.0}, {0.3, -0.7, 0.5}, kLowSeed, 0.3},
      {"dc_cylinder", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.6618262754905685},
      {"dc_cylinder", {0.3, 0.7, 0.9, 0.5, -0.25, 0.4}, {0.3, -0.7, 0.5}, kLowSeed, 0.7963989620158236},
      // + ¼ for a step in x, + ¾ for one in y.
      {"dc_gridout", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.625},
      {"dc_gridout", {}, {1.6, -0.4, 0.5}, kHighSeed, 0.125},
      {"dc_gridout", {}, {-2.4, 0.6, 0.5}, kHighSeed, 0.125},
      // |½ ((cos angle Sx + sin angle Sy + offset) / scale + 1)| mod 1.
      {"dc_linear", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.6825},
      {"dc_linear", {0.25, 0.6, 2.5}, {0.3, -0.7, 0.5}, kHighSeed, 0.5187774191984108},
      // |u + v| mod 1.
      {"dc_triangle", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.0},
      {"dc_triangle", {}, {0.75, -0.3, 0.5}, kHighSeed, 0.8333333333333329},
      {"dc_triangle", {0.5, 0.0}, {0.3, -0.7, 0.5}, kHighSeed, 0.712395966053009},
      {"dc_triangle", {-0.5, 0.0}, {0.3, -0.7, 0.5}, kLowSeed, 0.5961502492427826},
      {"dc_triangle", {0.5, 0.0}, {1.2, -0.2, 0.5}, kHighSeed, 0.28760403394699097},
      // dc_ztransl only reads the colour.
      {"dc_ztransl", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.375},
      // half the block's height.
      {"randCubes", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.6450784465507969},
      {"randCubes", {}, {0.3, -0.7, 0.5}, kLowSeed, 0.40199983301665626},
      {"randCubes", {0.5, 2.0, 1.5, 7.0, 1.25}, {0.3, -0.7, 0.5}, kHighSeed, 0.9058324123759904},
      // c + 0.1 dc D, clamped.
      {"curl_sp", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.375},
      {"curl_sp", {1.5, 0.4, -0.3, 0.2, 0.1, 0.5}, {0.3, -0.7, 0.5}, kHighSeed, 0.4439632604067789},
      {"curl_sp", {0.5, 0.4, 0.3, -0.2, 0.5, -0.7}, {0.3, -0.7, 0.5}, kHighSeed, 0.06102826020871932},
      // falloff3's colour shift: c + mul_c (Ψ₄ − ½) D, D = (|p| − min_distance) 0.04 blur_strength (types 0, 1); its
      // default mul_c 0 leaves the colour; type 2 shifts by L(mul_c) S(Ψ₄ − ½) (D + alpha (L(D) − D)), |p| the largest
      // coordinate (blur_shape 1).
      {"falloff3", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.375},
      {"falloff3", {0, 0, 1, 0.5, 0, 1, 1, 0, 0.5, 0, 0, 0, 0}, {0.3, -0.7, 0.5}, kHighSeed, 0.3708924858519776},
      {"falloff3", {0, 0, 5, 0.1, 0, 1, 1, 0, 1.0, 0, 0, 0, 0}, {0.3, -0.7, 0.5}, kLowSeed, 0.2948551552568862},
      {"falloff3", {2, 1, 5, 0.1, 0, 1, 1, 0, 0.7, 0, 0, 0, 0.3}, {0.3, -0.7, 0.5}, kHighSeed, 0.28643686392816803},
      // falloff2's colour shift: c + mul_c (Ψ₄ − ½) D, D = (|p − centre| − mindist) 0.04 scatter; the fourth
      // draw only with mul_c set (none by default, the colour left alone).
      {"falloff2", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.375},
      {"falloff2",
       {10.0, 0.2, 1.0, 0.5, 0.7, 0.5, 0.1, -0.2, 0.3, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.33758096925139186},
      {"falloff2",
       {10.0, 0.1, 1.0, 0.5, 0.7, 1.0, 0.1, -0.2, 0.3, 0.0, 2.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       0.28123134189556204},
      // pixel_flow with enable_dc: the fade's Ψ, the lane's first draw; without it the colour is left alone.
      {"pixel_flow", {90.0, 0.1, 200.0, 42.0, 1.0}, {0.3, -0.7, 0.5}, kHighSeed, 0.8794664144515991},
      {"pixel_flow", {90.0, 0.1, 200.0, 42.0, 1.0}, {0.3, -0.7, 0.5}, kLowSeed, 0.3165935277938843},
      {"pixel_flow", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.375},
  };
  return cases;
}

class ColourVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(ColourVariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Colour, ColourVariationSetsColour, testing::ValuesIn(colourCases()), colourCaseLabel);

// dc_perlin's colour is centre + range N mod 1, N two octaves of the simplex noise at the drawn point (flat map, z 0):
// N = noise(vx, vy, 0) + noise(4 vx, 2 vy, 0)/2 (Fractorium scales x twice between octaves and z never).
TEST(FlameVariationColour, PerlinColoursByTheNoiseAtTheDrawnPoint) {
  const VariationInfo& info = variationOrThrow("dc_perlin");
  const Outputs out = run(info, perlinParams(0.0), {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
  const double vx = 0.3035731315612793 / 0.8, vy = 0.03626041412353516 / 0.8;
  const double noise = simplexNoise3D(vx, vy, 0.0) + simplexNoise3D(4.0 * vx, 2.0 * vy, 0.0) / 2.0;
  const double c = 0.25 + 0.25 * noise;
  EXPECT_NEAR(out.colour[0], c - std::floor(c), 1e-12);
  EXPECT_GE(out.colour[0], 0.0);
  EXPECT_LT(out.colour[0], 1.0);
}

// As a pre_ or post_ term dc_linear colours by its input point plus its own result (Fractorium's), not by a
// running sum: with the point (0.3, −0.7) that is (0.54, −1.26).
TEST(FlameVariationColour, LinearAsPrePostColoursByItsInputPlusItsResult) {
  const VariationInfo& info = variationOrThrow("dc_linear");
  const std::vector<double> params = {0.25, 0.6, 2.5};
  double x = 0.3, y = -0.7, z = 0.5, ox = 0.0, oy = 0.0, oz = 0.0, colour = 0.375;
  std::uint32_t random = kHighSeed;
  VariationInput in;
  in.x = in.tx = &x;
  in.y = in.ty = &y;
  in.z = in.tz = &z;
  in.random = &random;
  in.count = 1;
  in.weight = 0.8;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = &colour;
  in.stage = VariationStage::Post;
  info.apply(in, &ox, &oy, &oz);
  EXPECT_NEAR(colour, 0.4968463431146964, 1e-12);
}

// Only the variations that read or set the colour say so.
TEST(FlameVariationColour, OnlyColourVariationsAreMarkedDirectColour) {
  for (const VariationInfo& info : variationCatalogue()) {
    const bool colours =
        info.name.starts_with("dc_") || info.name == "randCubes" || info.name == "curl_sp" || info.name == "falloff2" ||
        info.name == "falloff3" || info.name == "pixel_flow" || info.name == "stabilize" || info.name == "szubieta" ||
        info.name == "subflame_wf" || info.name == "glynns3subfl" || info.name == "plane_wf" ||
        info.name == "truchet" || info.name == "spirograph3D" || info.name == "recurrenceplot" ||
        info.name == "parplot2d_wf" || info.name == "polarplot3d_wf" || info.name == "isosfplot3d_wf" ||
        info.name == "sunflower" || info.name == "point_symmetry_wf" || info.name == "mirror_wf" ||
        info.name == "axis_symmetry_wf" || info.name == "glsl_apollonian" || info.name == "fract_mandelbrot_wf" ||
        info.name == "julian2dc" ||         // the index from the result's radius and angle
        info.name == "glsl_circlesblue" ||  // Gradient 1: the index from its bubbles' colour
        info.name == "glsl_mandala" ||      // Gradient 1: the index from its pattern's colour
        info.name == "glsl_acrilic" ||      // Gradient 1: the index from its pattern's colour
        info.name == "colormap_wf" ||       // dc_color 1 sets the index from its picture
        info.name == "smartcrop" ||         // cropmode 2 restores the kept point's colour
        info.name == "colorscale_wf";       // reads the index (z from it), JWildfire's VARTYPE_DC
    EXPECT_EQ(info.directColour, colours) << info.name;
  }
}

// ---- the chaos game's direct colour ----------------------------------------------------------------------------

PatternLayer flameLayer(FlameGenome genome) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = std::move(genome);
  layer.color.mode = ColorMode::Index;
  return layer;
}

// dc_linear's colour at a point (its defaults: angle 0, offset 0, scale 1): |(x + 1)/2| mod 1.
double linearColour(double x) {
  return std::fmod(std::abs(0.5 * (x + 1.0)), 1.0);
}

// One transform, dc_linear (weight 0.7) after a contraction, colour 0.2 at speed 0.5: after each step a lane's colour
// is c + direct_color (dc − c), c = ½ old + 0.1 the plain blend, dc the colour dc_linear takes at the new point.
void expectDirectColourBlend(double directColor) {
  FlameGenome genome;
  FlameXform x;
  x.affine.m = {0.6, 0.2, 0.0, 0.1, -0.2, 0.6, 0.0, -0.1, 0.0, 0.0, 0.6, 0.0};
  x.variations = {{"dc_linear", 0.7, {0.0, 0.0, 1.0}}};
  x.color = 0.2;
  x.colorSpeed = 0.5;
  x.directColor = directColor;
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "layers[0]");
  constexpr std::size_t kLanes = 37;
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(11);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> ox(kLanes), oy(kLanes), oz(kLanes), oc(kLanes);
  for (int step = 0; step < 20; ++step) {
    const std::vector<double> before = lanes.color;
    game.step(lanes, ox.data(), oy.data(), oz.data(), oc.data(), kLanes);
    for (std::size_t i = 0; i < kLanes; ++i) {
      const double blended = 0.5 * before[i] + 0.1;
      const double expected = blended + directColor * (linearColour(lanes.x[i]) - blended);
      EXPECT_NEAR(lanes.color[i], expected, 1e-12) << "step " << step << " lane " << i;
      EXPECT_EQ(oc[i], lanes.color[i]);
    }
  }
}

TEST(FlameDirectColour, LinearColoursFollowThePosition) {
  expectDirectColourBlend(1.0);
}

TEST(FlameDirectColour, DirectColorZeroLeavesTheBlend) {
  expectDirectColourBlend(0.0);
}

TEST(FlameDirectColour, DirectColorBlendsBetween) {
  expectDirectColourBlend(0.25);
}

// A final transform with dc_linear colours what is drawn by where it lands, and never feeds back.
TEST(FlameDirectColour, FinalTransformColoursTheDrawnPoint) {
  FlameGenome genome;
  FlameXform x;
  x.affine.m = {0.5, 0.0, 0.0, 0.2, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0};
  x.color = 0.0;
  x.colorSpeed = 0.5;
  genome.xforms = {x};
  genome.hasFinal = true;
  genome.finalXform.variations = {{"dc_linear", 1.0, {0.0, 0.0, 1.0}}};
  genome.finalXform.colorSpeed = 0.0;
  const ChaosGame game(flameLayer(genome), "layers[0]");
  constexpr std::size_t kLanes = 16;
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(5);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> ox(kLanes), oy(kLanes), oz(kLanes), oc(kLanes);
  for (int step = 0; step < 5; ++step) {
    const std::vector<double> before = lanes.color;
    game.step(lanes, ox.data(), oy.data(), oz.data(), oc.data(), kLanes);
    for (std::size_t i = 0; i < kLanes; ++i) {
      EXPECT_NEAR(oc[i], linearColour(ox[i]), 1e-12);
      EXPECT_NEAR(lanes.color[i], 0.5 * before[i], 1e-12);  // the state's colour: the plain blend towards 0
    }
  }
}

// A colour that is not a number (dc_linear at an escaped point) becomes 0, as in Fractorium.
TEST(FlameDirectColour, NotANumberBecomesZero) {
  FlameGenome genome;
  FlameXform x;
  x.variations = {{"dc_linear", 1.0, {0.0, 0.0, 1.0}}};
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "layers[0]");
  ChaosLanes lanes;
  lanes.resize(4);
  SplitMix64 rng(3);
  for (std::size_t i = 0; i < 4; ++i) game.seedLane(lanes, i, rng);
  lanes.x[2] = std::numeric_limits<double>::infinity();
  std::vector<double> ox(4), oy(4), oz(4), oc(4);
  game.step(lanes, ox.data(), oy.data(), oz.data(), oc.data(), 4);
  EXPECT_EQ(lanes.color[2], 0.0);
  EXPECT_TRUE(std::isnan(ox[2]));
}

TEST(FlameDirectColour, ValidationRefusesDirectColorOutsideTheUnitRange) {
  FlameGenome genome = defaultFlame();
  genome.xforms[0].directColor = 1.5;
  EXPECT_THROW(validateFlame(genome, "layers[0]"), Error);
  genome.xforms[0].directColor = 0.5;
  EXPECT_NO_THROW(validateFlame(genome, "layers[0]"));
}

// Fractorium and Apophysis 7X write the direct colour as var_color; a missing one is 1.
TEST(FlameDirectColour, ImportReadsVarColor) {
  const auto importOne = [](const std::string& attributes) {
    const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + attributes +
                             "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
    return readFlameXml(text, "t.flame").flame;
  };
  const ImportedFlame set = importOne(R"(dc_linear="1" var_color="0.35" coefs="1 0 0 1 0 0")");
  EXPECT_DOUBLE_EQ(set.genome.xforms.at(0).directColor, 0.35);
  EXPECT_TRUE(set.leftOut.empty());
  EXPECT_EQ(set.genome.xforms.at(0).variations.at(0).name, "dc_linear");
  const ImportedFlame unset = importOne(R"(dc_linear="1" coefs="1 0 0 1 0 0")");
  EXPECT_DOUBLE_EQ(unset.genome.xforms.at(0).directColor, 1.0);
  const ImportedFlame clamped = importOne(R"(dc_linear="1" var_color="3" coefs="1 0 0 1 0 0")");
  EXPECT_DOUBLE_EQ(clamped.genome.xforms.at(0).directColor, 1.0);
}

// Fractorium writes d_spherical's parameter as d_spherical_weight; a preset calls it spherical_weight (a preset's
// "weight" is the term's).
TEST(FlameVariationColour, DSphericalReadsFractoriumsWeightName) {
  const std::string text =
      "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" d_spherical=\"0.5\" "
      "d_spherical_weight=\"0.8\" coefs=\"1 0 0 1 0 0\"/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  const ImportedFlame flame = readFlameXml(text, "t.flame").flame;
  EXPECT_TRUE(flame.leftOut.empty());
  const VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "d_spherical");
  EXPECT_DOUBLE_EQ(term.weight, 0.5);
  EXPECT_EQ(term.params, std::vector<double>{0.8});
}

}  // namespace
