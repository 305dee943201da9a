// The variations of core/flame/variations_fractorium.cpp and variations_jwildfire.cpp, each at points whose expected
// values were worked out from the published formulas (JWildfire's and Fractorium's variation classes), independently of
// the code under test, in double precision. The main point is (0.3, −0.7, 0.5) with weight 0.8, as in
// flame_variations_test.cpp: r² = 0.58, φ = atan2(−0.7, 0.3) = −1.16590454, and a 2D variation's z is 0.8 · 0.5 = 0.4.
// Random variations are replayed from the lane's seed: xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ
// = 0.316594 first from 0x9E3779B9.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // mirror: Ψ ≥ ½ keeps the sign of |x|; Ψ < ½ negates it. The weight is not applied.
      {"mirror_x", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3, -0.7, 0.5}},
      {"mirror_x", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.3, -0.7, 0.5}},
      {"mirror_y", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3, 0.7, 0.5}},
      {"mirror_y", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.3, -0.7, 0.5}},
      {"mirror_z", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.3, -0.7, -0.5}},
      // axis x, centre (0.25, 0.5), 30°: Ψ ≥ ½ mirrors x to 0.25 − 0.05 − 0.4 = −0.2, then turns
      // (−0.45, −1.2) by −30°: (0.25 − 0.45 cos 30° + 1.2 sin 30°, 0.5 − 1.2 cos 30° − 0.45 sin 30°).
      {"axis_symmetry_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.46028856829700243, -0.7642304845413265, 0.5}},
      // Ψ < ½ keeps the side: x = 0.7, (0.45, −1.2) turned by +30°.
      {"axis_symmetry_wf", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.03971143170299751, -0.7642304845413265, 0.5}},
      // axis y without rotation: y = 2·0.42 + 0.7 − 0.4 = 1.14, or −0.7 + 0.4 = −0.3.
      {"axis_symmetry_wf",
       {1.0, 0.41, 0.42, 0.5, 0.0, 0, 0, 0, 0, 0, 0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3, 1.14, 0.5}},
      {"axis_symmetry_wf",
       {1.0, 0.41, 0.42, 0.5, 0.0, 0, 0, 0, 0, 0, 0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.3, -0.3, 0.5}},
      // axis z, centre (0.1, 0.2, −0.3), 40°: z mirrored to −0.3 − 0.8 − 0.4 = −1.5, then (0.2, −1.2)
      // turned in the x–z plane, about z = centre_y as JWildfire does.
      {"axis_symmetry_wf",
       {2.0, 0.1, 0.2, -0.3, 40.0, 0, 0, 0, 0, 0, 0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {1.0245540202476426, -0.7, -0.5906958098054658}},
      {"axis_symmetry_wf",
       {2.0, 0.1, 0.2, -0.3, 40.0, 0, 0, 0, 0, 0, 0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {1.0245540202476426, -0.7, 0.9906958098054657}},
      // octagon: x⁴ + y⁴ + 2z² = 0.7982, so s = 1/(0.7982 + 1e-8) (w s ≈ 1.0023 < 2); t = 1/(0.3 + 0.7
      // + 2√0.5); plus w p.
      {"octagon", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6601810979048697, -1.5404225617780294, 1.1003018298414495}},
      // Near the origin w s ≥ 2, so s = 1; the offsets push each coordinate away from 0.
      {"octagon",
       {0.164, 0.04, 0.1},
       {0.05, -0.1, 0.2},
       0.8,
       kHighSeed,
       {0.24949850463651727, -0.26859700927303454, 0.5531940185460691}},
      // Below z = 0, √z counts as 0: t = 1/(0.3 + 0.7).
      {"octagon", {}, {0.3, -0.7, -0.5}, 0.8, kHighSeed, {0.8007698409471018, -1.8684629622099043, -1.334616401578503}},
      {"bcircle", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.56, 0.4}},
      // Scaled by 2 the point is outside: radius 0.2·0.5·Ψ + 1 = 1.0879466 along its angle.
      {"bcircle", {2.0, 0.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3428505423117109, -0.7999845987273255, 0.4}},
      {"bcircle", {2.0, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      // waves23: 7·(−0.7)/2π = −0.779859 → 0.220141; 13·0.3/2π = 0.620704 → 0.5 − 0.620704.
      {"waves23", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.2488056311539885, -0.5648281711223356, 0.4}},
      // wdisc: φ/π = −0.371118, a = π/(r + 1); with y > 0, φ > 0 and a = π − π/(r + 1).
      {"wdisc", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.06264584669280625, -0.29021066474019597, 0.4}},
      {"wdisc", {}, {0.3, 0.7, 0.5}, 0.8, kHighSeed, {0.06264584669280629, 0.29021066474019597, 0.4}},
      // pow_block: q = 3/2, a = 3 (φ + 2π⌊2Ψ⌋)/2; Ψ = 0.879 takes root 1, Ψ = 0.317 root 0.
      {"pow_block", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.09417403487604283, 0.523286488307155, 0.4}},
      {"pow_block", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.09417403487604287, -0.523286488307155, 0.4}},
      // correctd −1.5: q = 4/(2·1/−1.5) = −3.
      {"pow_block",
       {4.0, 2.0, 1.0, 1.0, -1.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-1.2490504909367197, -1.3115030154835543, 0.4}},
      // depth: 1 + |z| = 1.5; with power 2.5, 1 + 0.5^2.5 = 1.1767767.
      {"depth", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.36, -0.84, 0.6}},
      {"depth",
       {2.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.28242640687119286, -0.6589949493661167, 0.4707106781186548}},
      // poincare3D with r = 0 is the identity; r = 0.4, a = 0.3, b = −0.6 moves the centre to c =
      // (−0.4 cos 0.15π cos 0.3π, 0.4 sin 0.15π cos 0.3π, 0.4 sin 0.3π).
      {"poincare3D", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.56, 0.4}},
      {"poincare3D",
       {0.4, 0.3, -0.6},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.46127110635659024, -0.5741166807671129, -0.11547311064267012}},
      // falloff from 0x2545F491: a = (0.379466, 0.045326, −0.105931) (Ψ − ½). Defaults: D = (|p| −
      // 0.5) · 0.04 = 0.0104631, mul_z 0.
      {"falloff", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24499126877478192, -0.5594038159047717, 0.4}},
      // scatter 10, mindist 0.1, centre (0.25, −0.2, 0.3): D = (0.540833 − 0.1) · 0.4.
      {"falloff",
       {10.0, 0.1, 1.0, 0.5, 0.7, 0.25, -0.2, 0.3, 0.0, 0.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2935299842393909, -0.5568030448107117, 0.3895396718938281}},
      // Radial, inverted: D = (1 − 0.540833 − 0.1) · 0.4 moves |p|, φ and asin(z/|p|).
      {"falloff",
       {10.0, 0.1, 1.0, 0.5, 0.7, 0.25, -0.2, 0.3, 1.0, 1.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.07391622418857141, -0.1709319387449237, 0.43836160163777754}},
      // Box with boxpow 3: s = min(D, 0.9) + 0.1; mul a³ D/s is added outside the weight.
      {"falloff",
       {10.0, 0.1, 1.0, 0.5, 0.7, 0.25, -0.2, 0.3, 0.0, 2.0, 3.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3884061388549968, -0.721313296176355, 0.44595175744758575}},
      // falloff3 with the same a; strength 10, min_distance 0.1, centre (0.25, −0.2, 0.3).
      {"falloff3",
       {0.0, 0.0, 10.0, 0.1, 0.0, 1.0, 0.5, 0.7, 0.0, 0.25, -0.2, 0.3, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2933704764580591, -0.5615677512367295, 0.4018809143995905}},
      // Radial blur, square distance (largest coordinate offset 0.5).
      {"falloff3",
       {1.0, 1.0, 10.0, 0.1, 0.0, 1.0, 0.5, 0.7, 0.0, 0.25, -0.2, 0.3, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.26015118378828733, -0.6009912388390419, 0.4189171559551912}},
      // Log blur, inverted distance, alpha 0.35.
      {"falloff3",
       {2.0, 0.0, 10.0, 0.1, 1.0, 1.0, 0.5, 0.7, 0.0, 0.25, -0.2, 0.3, 0.35},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.33002026551534563, -0.5021307399220915, 0.3322238088964703}},
      // Voron: the nearest seed of the cells around (1, −3) (side 0.25) by the integer hash.
      {"Voron", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.2408772493396314, -0.5595477927664051, 0.4}},
      {"Voron",
       {0.5, 0.3, 4.0, 11.0, -5.0},
       {-1.3, 2.2, 0.5},
       0.8,
       kHighSeed,
       {-1.0115818009952, 1.7160062089916348, 0.4}},
      // smartshape: a square (power 4); then a rounded pentagon and a compensated triangle.
      {"smartshape", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.2611122207724771, -0.6092618484691128, 0.4}},
      {"smartshape",
       {5.0, 0.3, 1.5, 0.7, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2626795001681816, -0.6129188337257571, 0.4}},
      {"smartshape",
       {3.0, 0.5, 1.0, 1.2, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2014735546436822, -0.5887290858749594, 0.4}},
      // lazyTravis inside the weight's square: s = 0.7, position 7s + x + 4s·spin_in = 8.0, which
      // mod 8s is 2.4, on the second side: (3s − 2.4, s).
      {"lazyTravis", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.24, 0.56, 0.4}},
      // Outside (s = 0.7 > 0.1): spin_out 0.25, space 0.
      {"lazyTravis", {0.25, 0.25, 0.0}, {0.3, -0.7, 0.5}, 0.1, kHighSeed, {0.07, -0.04, 0.05}},
      {"lazyTravis", {0.3, 0.6, 0.2}, {-0.2, 0.9, 0.5}, 0.4, kHighSeed, {-0.44, -0.27377777777777806, 0.2}},
      {"waves4_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.20327139704259314, -0.5388036045202355, 0.4}},
      // sin·cos·sin for x, cos·sin·cos for y, damped by e^0.3 and e^−0.2.
      {"waves4_wf",
       {1.04, 0.56, 1.79, 2.51, 0.0, 1.0, 0.3, -0.2},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.7514243908131175, -0.34916235295840825, 0.4}},
      // y: the default square hypergon (d = √2: u = tan² t + 1 < 2, so (√2 − √(2 − u))/√u); with every
      // shape at 0 the radius is 0; then the four shapes of a Fractorium flame (star_slope 1.5708 is
      // within 10⁻⁶ of π/2, so tan(1.5208) is used), a hypergon alone, and a star with a lituus.
      {"y", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.08836042353276663, -0.20617432157645546, 0.4}},
      {"y",
       {0.0, 4.0, 1.0, 0.0, 5.0, 2.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.0, 0.0, 0.4}},
      {"y",
       {-2.752, 5.0, 0.683, 0.473, 10.0, 1.5708, -0.302, 0.787, 0.178, 10.0, 10.0, 1.0, 5.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {1.4187788646854993, -3.310484017599498, 0.4}},
      {"y",
       {1.1, 6.0, 0.2, 0.0, 5.0, 0.9, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0},
       {-0.4, 0.25, 0.5},
       0.8,
       kHighSeed,
       {-1.1769547867226646, 0.7355967417016657, 0.4}},
      {"y",
       {0.0, 4.0, 1.0, 0.6, 7.0, 0.9, 0.5, -0.4, 0.0, 1.0, 1.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3719518707120569, -0.8678876983281326, 0.4}},
      // pixel_flow: Ψ⁴ = 0.879466⁴ fades the streak; blocks (60, −140) at width 200 shift by the
      // hash; then the corpus flame's parameters, and a point left of the y axis with another seed.
      {"pixel_flow", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {9.306663919239146e-12, 0.005185069273106876, 0.4}},
      {"pixel_flow",
       {130.0, 1.2, 100.0, 42.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.18182395695878292, 0.21668935506624784, 0.4}},
      {"pixel_flow",
       {-30.0, 2.0, 37.5, 977.0, 0.0},
       {-0.61, 0.43, 0.5},
       0.8,
       kHighSeed,
       {0.4316432019523141, -0.24920931849670502, 0.4}},
      // vibration2 at its defaults (two unmodulated waves across x and y), then with every
      // modulation set.
      {"vibration2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.04978757015123077, -0.3697900941156558, 0.4}},
      {"vibration2",
       {0.3, 1.1, 2.0, 0.4, 0.2, -0.7, 0.5, 1.5, 0.3, -0.1, 0.2, 0.5,  0.3,
        0.7, 0.4, 0.9, 0.5, 0.3, -0.2, 0.6, 0.1, 0.4, -0.3, 0.8, 0.25, 0.35},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.08391366308572422, -0.5712179840009245, 0.4}},
      // truchet: the point scaled by 1/w = 1.25 (rotation 0), its place in the unit cell; at the main
      // point neither arc is near, so nothing is added; at (0.35, 0.12) the cell (0.4375, 0.15) is on
      // the first arc only (tile 1.33 of the fast hash: arcs round (1, 0) and (0, 1)).
      {"truchet", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.0}},
      {"truchet", {}, {0.35, 0.12, 0.5}, 0.8, kHighSeed, {0.4375, 0.15, 0.0}},
      {"truchet", {}, {-0.62, 0.41, 0.5}, 0.8, kHighSeed, {-0.775, 0.5125, 0.0}},
      {"truchet", {0.0, 2.0, 0.5, 0.0, 1.0, 1.0, 0.0}, {0.35, 0.12, 0.5}, 0.8, kHighSeed, {0.4375, 0.15, 0.0}},
      // Extended (the congruence iterated), exponent 1.5, arc_width 0.8, rotation 0.3, size 2,
      // seed 37.6 (⌊⌋ = 37): the second arc adds z.
      {"truchet",
       {1.0, 1.5, 0.8, 0.3, 2.0, 37.6, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.9381425218402091, -0.18899921762715444, 0.4}},
      {"truchet",
       {1.0, 1.5, 0.8, 0.3, 2.0, 37.6, 0.0},
       {2.4, -3.3, 0.5},
       0.8,
       kHighSeed,
       {5.505140174721673, -6.3195677402423005, 0.4}},
      // nBlur replayed from the lane's draws: the default triangle; the corpus flame's 3 sides with
      // −15 stripes and a hole; 4 stripes of ratio 0.6 on a pentagon; exactCalc on a hexagon with
      // wide stripes; and the circumcircle of a square with −2 stripes.
      {"nBlur", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.43745605638034324, 0.17780636306596492, 0.4}},
      {"nBlur",
       {3.0, -15.0, 0.45, 0.6, 0.0, 0.0, 0.0, 0.0, 0.1},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.33824696804133264, 0.10574729432217148, 0.4}},
      {"nBlur",
       {5.0, 4.0, 0.6, 0.3, 0.0, 1.0, 1.0, 0.0, 1.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.49188529518430196, -0.17066796213536645, 0.4}},
      {"nBlur",
       {5.0, 4.0, 0.6, 0.3, 0.0, 1.0, 1.0, 0.0, 1.5},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.40509341919178243, 0.284223212240704, 0.4}},
      {"nBlur",
       {6.0, 3.0, 1.6, 0.2, 0.0, 1.0, 0.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.42222563921427075, 0.10976638156256624, 0.4}},
      {"nBlur",
       {6.0, 3.0, 1.6, 0.2, 0.0, 1.0, 0.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.7002778646617289, 0.02007583911894626, 0.4}},
      {"nBlur",
       {4.0, -2.0, 0.5, 0.5, 1.0, 1.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2789933584132139, -0.6531239498192722, 0.4}},
      {"nBlur",
       {4.0, -2.0, 0.5, 0.5, 1.0, 1.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.7646756130925147, 0.18410702872450752, 0.4}},
      // shredlin: 0.3 is in strip 0, narrowed to half about 0.5 → 0.4; −0.7 → −0.6. Then strips of
      // 0.3 and 0.45 with a negative width.
      {"shredlin", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.32, -0.48, 0.4}},
      {"shredlin", {0.3, 0.2, 0.45, -0.6}, {1.37, -2.21, 0.5}, 0.8, kHighSeed, {1.0832, -1.5312, 0.4}},
      // crop_trapezoid's default trapezoid is 0.5 wide each side at y = −0.5 and 0.2 at y = 0.5, so
      // 0.35 − 0.3y at height y: at y = −0.2 it reaches 0.41 > 0.3 and the point is kept, w·p.
      {"crop_trapezoid", {}, {0.3, -0.2, 0.5}, 0.8, kHighSeed, {0.24, -0.16, 0.4}},
      // At y = 0.2 it reaches only 0.29 < 0.3: the point is outside, which invert keeps.
      {"crop_trapezoid", {0.5, 0.2, 0.5, 1.0}, {0.3, 0.2, 0.5}, 0.8, kHighSeed, {0.24, 0.16, 0.4}},
      // Bases 1 and 0.6, height 0.25: at y = 0.1 the width is 0.8 − 0.8·0.1 = 0.72 > |−0.7|.
      {"crop_trapezoid", {1.0, 0.6, 0.25, 0.0}, {-0.7, 0.1, 0.5}, 0.8, kHighSeed, {-0.56, 0.08, 0.4}},
  };
  return cases;
}

class MoreVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(MoreVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(More, MoreVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// The pre_/post_ forms of a variation that ignores its weight replace the point by its own result.
TEST(FlameVariationMore, PrePostFormsReplaceThePointUnlessTheVariationIsABlur) {
  for (const char* name : {"pre_mirror_x", "post_mirror_y", "post_axis_symmetry_wf"}) {
    const VariationInfo* info = findVariation(name);
    ASSERT_NE(info, nullptr) << name;
    EXPECT_FALSE(info->additive) << name;
  }
  // Only nBlur, a blur, ignores the point (its pre_/post_ forms add); every other form replaces it.
  std::set<std::string> names;
  for (const PointCase& c : pointCases()) names.insert(c.name);
  for (const std::string& name : names) EXPECT_EQ(findVariation(name)->additive, name == "nBlur") << name;
  EXPECT_EQ(variationStage("post_axis_symmetry_wf"), VariationStage::Post);
  EXPECT_EQ(variationStage("pre_mirror_x"), VariationStage::Pre);
}

// crop_trapezoid drops what lies outside its trapezoid (NaN, the chaos game's escape, where
// JWildfire hides the point): beside the slanted side at y = 0.2 (width 0.29), above the top
// (|y| > height) and beyond the wide base; invert drops the inside instead.
TEST(FlameVariationMore, CropTrapezoidDropsThePointsItCrops) {
  const VariationInfo& info = variationOrThrow("crop_trapezoid");
  const std::vector<double> defaults = info.defaultParams(), inverted = {0.5, 0.2, 0.5, 1.0};
  for (const glm::dvec3 p : {glm::dvec3{0.3, 0.2, 0.5}, glm::dvec3{0.0, 0.7, 0.5}, glm::dvec3{-0.52, -0.45, 0.5}}) {
    const Outputs out = run(info, defaults, p, 0.8, kHighSeed, 5);
    for (std::size_t lane = 0; lane < out.x.size(); ++lane) {
      EXPECT_TRUE(std::isnan(out.x[lane]) && std::isnan(out.y[lane]) && std::isnan(out.z[lane])) << p.x << ", " << p.y;
    }
  }
  const Outputs inside = run(info, inverted, {0.3, -0.2, 0.5}, 0.8, kHighSeed, 5);
  EXPECT_TRUE(std::isnan(inside.x[0]));
}

// One flame of one transform whose attributes are `xform`, as a flame file writes it.
ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// Apophysis writes FracFx's octagon offsets as octa_x, octa_y, octa_z.
TEST(FlameVariationMore, OctagonReadsApophysisOffsetNames) {
  const ImportedFlame flame = importXform(R"(octagon="1" coefs="1 0 0 1 0 0" octa_x="0.124" octa_y="0.04" octa_z="0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "octagon");
  EXPECT_EQ(term.params, (std::vector<double>{0.124, 0.04, 0.0}));
}

// bezo97's pixel_flow plugin writes its parameters without the variation's name.
TEST(FlameVariationMore, PixelFlowReadsItsBareParameterNames) {
  const ImportedFlame flame = importXform(
      R"(linear="1" pixel_flow="0.096" coefs="1 0 0 1 0 0" angle="130" len="1.2" width="100" seed="42" enable_dc="0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  const auto term =
      std::find_if(terms.begin(), terms.end(), [](const VariationTerm& t) { return t.name == "pixel_flow"; });
  ASSERT_NE(term, terms.end());
  EXPECT_EQ(term->params, (std::vector<double>{130.0, 1.2, 100.0, 42.0, 0.0}));
  const ImportedFlame direct = importXform(R"(linear="1" pixel_flow="0.096" coefs="1 0 0 1 0 0" enable_dc="1")");
  EXPECT_TRUE(direct.leftOut.empty());  // its direct colour is applied (flame_variations_colour_test.cpp)
}

// JWildfire's shredlin and crop_trapezoid replace the x and y of the ordinary terms before them,
// Fractorium's mirror_x all of the sum: the chaos game does so (chaos_game_test.cpp), so nothing
// is lost wherever they come.
TEST(FlameVariationMore, ShredlinAndMirrorsAfterOtherVariationsAreWhole) {
  const ImportedFlame first = importXform(R"(shredlin="1" linear="0.5" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(first.leftOut.empty()) << first.leftOut.front();
  const ImportedFlame after = importXform(R"(poincare3D="1.5" shredlin="3.7" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(after.leftOut.empty()) << after.leftOut.front();
  const ImportedFlame mirror = importXform(R"(linear="1" mirror_x="1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(mirror.leftOut.empty()) << mirror.leftOut.front();
  EXPECT_EQ(variationOrThrow("shredlin").replaces, VariationInfo::Replaces::XY);
  EXPECT_EQ(variationOrThrow("crop_trapezoid").replaces, VariationInfo::Replaces::XY);
  EXPECT_EQ(variationOrThrow("mirror_x").replaces, VariationInfo::Replaces::XYZ);
  EXPECT_EQ(variationOrThrow("linear").replaces, VariationInfo::Replaces::Nothing);
}

// JWildfire writes crop_trapezoid's bases as "Base Sup." and "Base Inf.", which are not XML names:
// they are read into base_sup and base_inf.
TEST(FlameVariationMore, CropTrapezoidReadsJwildfiresBaseNames) {
  const ImportedFlame flame = importXform(
      R"(crop_trapezoid="0.2" crop_trapezoid_fx_priority="0" crop_trapezoid_Base Sup.="0.7" )"
      R"(crop_trapezoid_Base Inf.="0.3" crop_trapezoid_height="0.4" crop_trapezoid_invert="1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 1u);
  EXPECT_EQ(terms[0].name, "crop_trapezoid");
  EXPECT_EQ(terms[0].params, (std::vector<double>{0.7, 0.3, 0.4, 1.0}));
}

// JWildfire's zxCoefs and yzCoefs compose with coefs into one 3D affine map: (x, y, z) = (1, 2, 3)
// goes through coefs (x' = 2x, y' = x + y; its translation (0.5, −1) waits for the end) to
// (2, 3, 3), the y–z map (y' = y − z, z' = 2z) to (2, 0, 6), the z–x map (x' = x + z, z' = 0.5x +
// 3z; each written "00 01 10 11 20 21") to (8, 0, 19), and then all the translations are added.
TEST(FlameVariationMore, JwildfirePlaneCoefficientsBecomeOneAffineMap) {
  const ImportedFlame flame =
      importXform(R"(linear3D="1" coefs="2 1 0 1 0.5 -1" yzCoefs="1 0 -1 2 0.25 0.75" zxCoefs="1 0.5 1 3 0.1 0.2" )"
                  R"(zxPost="1 0 0 2 0 0.3")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const FlameXform& x = flame.genome.xforms.at(0);
  // + (0.5 + 0.1, −1 + 0.25, 0.75 + 0.2).
  const glm::dvec3 p = x.affine.apply({1.0, 2.0, 3.0});
  EXPECT_NEAR(p.x, 8.6, 1e-12);
  EXPECT_NEAR(p.y, -0.75, 1e-12);
  EXPECT_NEAR(p.z, 19.95, 1e-12);
  // zxPost alone: x' = x, z' = 2z, then z + 0.3.
  ASSERT_TRUE(x.hasPost);
  const glm::dvec3 q = x.post.apply({1.0, 2.0, 3.0});
  EXPECT_NEAR(q.x, 1.0, 1e-12);
  EXPECT_NEAR(q.y, 2.0, 1e-12);
  EXPECT_NEAR(q.z, 6.3, 1e-12);
}

// Fractorium's post_depth adds the transform's affine point (chaos_game_test.cpp): kept, as is
// pre_depth.
TEST(FlameVariationMore, PostAndPreDepthAreKept) {
  const ImportedFlame post = importXform(R"(linear="1" post_depth="1" post_depth_power="1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(post.leftOut.empty()) << post.leftOut.front();
  const auto& postTerms = post.genome.xforms.at(0).variations;
  EXPECT_TRUE(
      std::any_of(postTerms.begin(), postTerms.end(), [](const VariationTerm& t) { return t.name == "post_depth"; }));
  const ImportedFlame pre = importXform(R"(linear="1" pre_depth="1.06" pre_depth_power="1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(pre.leftOut.empty());
  const auto& terms = pre.genome.xforms.at(0).variations;
  EXPECT_TRUE(std::any_of(terms.begin(), terms.end(), [](const VariationTerm& t) { return t.name == "pre_depth"; }));
}

// axis_symmetry_wf's colour shifts are read and kept (their effect is checked in flame_variations_jwildfire_test.cpp).
TEST(FlameVariationMore, AxisSymmetryColourShiftIsKept) {
  const ImportedFlame plain =
      importXform(R"(linear3D="1" post_axis_symmetry_wf="0.36" post_axis_symmetry_wf_axis="1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(plain.leftOut.empty()) << plain.leftOut.front();
  const ImportedFlame shifted = importXform(
      R"(linear3D="1" post_axis_symmetry_wf="0.36" post_axis_symmetry_wf_x2colorshift="0.2" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(shifted.leftOut.empty()) << shifted.leftOut.front();
  EXPECT_EQ(shifted.genome.xforms.at(0).variations.back().params.at(8), 0.2);
}

}  // namespace
