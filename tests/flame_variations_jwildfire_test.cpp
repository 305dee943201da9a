// The variations of core/flame/variations_jwildfire_shapes.cpp (JWildfire's own), each at points whose expected values
// were worked out from JWildfire's Java classes (thargor6/JWildfire,
// src/org/jwildfire/create/tina/variation/*Func.java) by a separate Python transcription of them, independently of the
// code under test, in double precision. The main point is (0.3, −0.7, 0.5) with weight 0.8, as in
// flame_variations_test.cpp; a 2D variation's z is 0.8 · 0.5 = 0.4. Random variations are replayed from the lane's
// seed: xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594 first from 0x9E3779B9. Where
// voxflame draws differently from JWildfire (Ψ drawn for every point, pairs drawn again by recurrenceplot), the
// transcription draws as voxflame does.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

constexpr glm::dvec3 kPoint{0.3, -0.7, 0.5};

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // bwraps7: (0.3, −0.7) lies in the bubble of the cell centred at (0.5, −0.5); with cellsize 0.25 it lies
      // outside its bubble and is linear.
      {"bwraps7", {}, kPoint, 0.8, kHighSeed, {0.15757572635446104, -0.6424242736455389, 0.4}},
      {"bwraps7", {0.8, 0.3, 1.5, 0.7, -1.2}, kPoint, 0.8, kHighSeed, {0.446277604262205, -0.5505134264088912, 0.4}},
      {"bwraps7", {0.25, 0.0, 2.0, 0.0, 0.0}, kPoint, 0.8, kHighSeed, {0.23899521483024652, -0.5610047851697535, 0.4}},
      // yin_yang: Ψ > ½ takes the yang half (negated), Ψ < ½ the yin half; outside the disc linear or nothing.
      {"yin_yang", {}, kPoint, 0.8, kHighSeed, {-0.52, 0.28, 0.4}},
      {"yin_yang", {}, kPoint, 0.8, kLowSeed, {0.52, -0.28, 0.4}},
      {"yin_yang", {0.3, 0.25, -0.4, 1, 0}, kPoint, 0.8, kHighSeed, {-0.42247172885741036, 0.12039092422824223, 0.4}},
      {"yin_yang",
       {0.3, 0.25, -0.4, 1, 0},
       {0.2, 0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.5976581721210812, 0.03823430491716864, 0.4}},
      {"yin_yang", {0.3, 0.25, -0.4, 1, 1}, {1.2, -0.7, 0.5}, 0.8, kHighSeed, {0.96, -0.56, 0.4}},
      {"yin_yang", {0.3, 0.25, -0.4, 1, 0}, {1.2, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      // affine3D: the identity by default; then scales, turns and shears (JWildfire's sheared branch).
      {"affine3D", {}, kPoint, 0.8, kHighSeed, {0.24, -0.56, 0.4}},
      {"affine3D",
       {0.1, -0.2, 0.3, 1.5, 0.5, -2.0, 30.0, -45.0, 60.0, 0.1, 0.2, -0.3, 0.4, 0.5, -0.6},
       kPoint,
       0.8,
       kHighSeed,
       {0.7396435126640286, 0.20824410705853613, -0.16548577511045087}},
      // plane_wf: (½ − Ψ₁, ½ − Ψ₂)·size in the plane zx at y = position (axis 2), xy (0) or yz (1).
      {"plane_wf", {}, kPoint, 0.8, kHighSeed, {-3.035731315612793, 2.4, -0.36260414123535156}},
      {"plane_wf",
       {-1.5, 4.0, 0, 1, 3, 0, 0, 0, 0, 0},
       kPoint,
       0.8,
       kHighSeed,
       {-1.2142925262451172, -0.14504165649414064, -1.2}},
      {"plane_wf",
       {-1.5, 4.0, 1, 1, 3, 0, 0, 0, 0, 0},
       kPoint,
       0.8,
       kLowSeed,
       {-1.2, 0.5869007110595703, -1.202262306213379}},
      // point_symmetry_wf: k = ⌊3Ψ⌋ = 2 (Ψ = 0.879) turns by 240°, k = 0 keeps the scaled offset.
      {"point_symmetry_wf", {}, kPoint, 0.8, kHighSeed, {1.0613843876330606, 1.014641016151378, 0.4}},
      {"point_symmetry_wf", {}, kPoint, 0.8, kLowSeed, {0.29, -0.46, 0.4}},
      {"point_symmetry_wf", {-0.1, 0.2, 5, 0.0}, kPoint, 0.8, kHighSeed, {0.6836461299324937, 0.2818458492644872, 0.4}},
      // The filled curves: Ψ₁ = 0.879 < 0.85 fails (the curve itself), Ψ₁ = 0.317 passes (scaled by Ψ₂).
      {"cannabiscurve_wf", {}, kPoint, 0.8, kHighSeed, {-0.0943563825718746, -0.040438449673660566, 0.4}},
      {"cannabiscurve_wf", {}, kPoint, 0.8, kLowSeed, {-0.08262854194744164, -0.03541223226318929, 0.4}},
      {"cannabiscurve_wf", {0.95}, kPoint, 0.8, kHighSeed, {-0.05145494317000592, -0.022052118501431118, 0.4}},
      {"cloverleaf_wf", {}, kPoint, 0.8, kHighSeed, {-0.27968932411234654, 0.6526084229288085, 0.4}},
      {"cloverleaf_wf", {}, kPoint, 0.8, kLowSeed, {-0.24492589075322668, 0.5714937450908621, 0.4}},
      {"cloverleaf_wf", {0.0}, kPoint, 0.8, kLowSeed, {-0.27968932411234654, 0.6526084229288085, 0.4}},
      {"japanese_maple_leaf", {}, kPoint, 0.8, kHighSeed, {-0.0005638835773004729, 0.17396670901762498, 0.4}},
      {"japanese_maple_leaf", {}, kPoint, 0.8, kLowSeed, {-0.0005638835773004729, 0.17396670901762498, 0.4}},
      {"japanese_maple_leaf",
       {0.9},
       {-0.4, 0.2, 0.5},
       0.8,
       kHighSeed,
       {0.08680610417396925, -0.09877949163497265, 0.4}},
      {"spherical3D_wf", {}, kPoint, 0.8, kHighSeed, {0.28915662650602414, -0.674698795180723, 0.48192771084337355}},
      {"spherical3D_wf",
       {1, 3.0},
       kPoint,
       0.8,
       kHighSeed,
       {-0.3173906312954902, 0.7405781396894772, -0.5289843854924837}},
      {"waves2_wf", {}, kPoint, 0.8, kHighSeed, {0.3307980999479094, -0.4666218544576379, 0.4}},
      {"waves2_wf",
       {0.3, -0.2, 2.5, 3.5, 0, 1, 0.2, -0.3},
       kPoint,
       0.8,
       kHighSeed,
       {-0.05916762708439205, -0.4585498485203985, 0.4}},
      {"butterfly3D", {}, kPoint, 0.8, kHighSeed, {0.10008486003652638, -0.4670626801704564, 0.08892608495987193}},
      {"cylinder_apo", {}, kPoint, 0.8, kHighSeed, {0.23641616532907164, -0.56, 0.7642691913004849}},
      {"crown_js", {}, kPoint, 0.8, kHighSeed, {-0.18595411995491196, 0.10293405961072394, 0.003985785902038484}},
      {"crown_js",
       {3.0, 0.8},
       kPoint,
       0.8,
       kLowSeed,
       {-0.01084323898295543, -0.33578999973903456, 0.02488320547120025}},
      // flower_db reads the sum so far, the run's start (0.125, −0.25, 0.5): the differences from it. With
      // stem_thickness 2 the third row is held at −stem_length.
      {"flower_db", {}, kPoint, 0.8, kHighSeed, {-0.19402189511665102, 0.08315224076427902, -8.474652636141338}},
      {"flower_db",
       {5.0, 0.5, 1.2, 0.3, 0.4, 0.6, 0.2},
       kPoint,
       0.8,
       kHighSeed,
       {-0.8939250543100212, 0.38311073756143765, 0.031289375372469896}},
      {"flower_db",
       {5.0, 0.5, 1.2, 2.0, 0.4, 0.6, 0.2},
       kPoint,
       0.8,
       kHighSeed,
       {-0.8939250543100212, 0.38311073756143765, -0.9}},
      // recurrenceplot: the first near pair, after 11, 7, 0, 4, 35 and 11 misses; functions 0, 2, a Legendre
      // polynomial (22, degree b = 3), a square wave (23) and a Chebyshev polynomial (29, degree k = 4).
      {"recurrenceplot", {}, kPoint, 0.8, kHighSeed, {0.027428571428571403, -0.022857142857142868, 0.4}},
      {"recurrenceplot", {}, kPoint, 0.8, kLowSeed, {-0.3622857142857143, -0.18857142857142858, 0.4}},
      {"recurrenceplot",
       {2, 0.0, 0.0, 0, 700, 2, 1.0, 0.0, 0.0, 5.0},
       kPoint,
       0.8,
       kHighSeed,
       {0.3028571428571429, 0.03542857142857141, 0.4}},
      {"recurrenceplot", {22, 300.0, 3.0, 0, 500, 0, 1, 0, 0, 20.0}, kPoint, 0.8, kLowSeed, {0.1264, 0.1664, 0.4}},
      {"recurrenceplot", {23, 500.0, 2.0, 5, 600, 0, 1, 0, 0, 5.0}, kPoint, 0.8, kHighSeed, {-0.132, -0.092, 0.4}},
      {"recurrenceplot", {29, 400.0, 0.0, 4, 800, 0, 1, 0, 0, 10.0}, kPoint, 0.8, kHighSeed, {0.027, -0.023, 0.4}},
      // variations_jwildfire_more.cpp. rose_wf: Ψ₁ = 0.879 > 0.85 draws the curve, 0.317 scales it by Ψ₂ = 0.876.
      {"rose_wf", {}, kPoint, 0.8, kHighSeed, {-0.007681660519260871, 0.01792387454494203, 0.4}},
      {"rose_wf", {}, kPoint, 0.8, kLowSeed, {-0.006726883663203821, 0.015696061880808913, 0.4}},
      {"rose_wf", {1.2, 3, 0.0}, kPoint, 0.8, kHighSeed, {-0.13184304399524402, 0.307633769322236, 0.4}},
      // heart_wf: the two sides, then shifted and scaled (t held at 60 in the last row, where x(t) is 0).
      {"heart_wf", {}, kPoint, 0.8, kHighSeed, {0.26927233058526157, 0.08992110077993411, 0.4}},
      {"heart_wf", {}, {-0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.26927233058526157, 0.08992110077993411, 0.4}},
      {"heart_wf",
       {1.5, 10.0, 0.7, 1.4},
       {-0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.6366826043580112, -0.412229152807797, 0.4}},
      {"heart_wf", {1.5, -10.0, 0.7, 1.4}, kPoint, 0.8, kHighSeed, {0.0, 0.24370473938764514, 0.4}},
      {"maple_leaf", {}, kPoint, 0.8, kHighSeed, {0.9145423353838334, -1.0049567201817957, 0.4}},
      {"maple_leaf", {}, kPoint, 0.8, kLowSeed, {0.800871098088272, -0.8800476051066476, 0.4}},
      {"maple_leaf", {0.95}, {-0.4, 0.2, 0.5}, 0.8, kHighSeed, {0.23324664279749552, 0.18569740207703783, 0.4}},
      {"waves3_wf", {}, kPoint, 0.8, kHighSeed, {0.2812214747707527, -0.5382013048376736, 0.4}},
      {"waves3_wf",
       {0.3, -0.2, 2.5, 3.5, 0, 1, 0.2, -0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.6397991314000017, -0.43659790113799263, 0.4}},
      {"tangent3D", {}, kPoint, 0.8, kHighSeed, {0.30910450451020294, -0.6738307043704636, 0.24746899968769862}},
      // acosh and acosech, through JWildfire's Complex (its square root and ε-tamed logarithm); Ψ ≥ ½ negates.
      {"acosh", {}, kPoint, 0.8, kHighSeed, {-0.34139969978441004, 0.6748497169700012, 0.4}},
      {"acosh", {}, kPoint, 0.8, kLowSeed, {0.34139969978441004, -0.6748497169700012, 0.4}},
      {"acosh", {}, {-1.3, 0.4, 0.5}, 0.8, kLowSeed, {-0.45042897846891283, -1.391368851862155, 0.4}},
      {"acosech", {}, kPoint, 0.8, kHighSeed, {-0.6344167017512854, -0.5410062442816109, 0.4}},
      {"acosech", {}, kPoint, 0.8, kLowSeed, {0.6344167017512854, 0.5410062442816109, 0.4}},
      {"zscale_wf", {}, kPoint, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      {"zscale_wf", {0.3}, kPoint, 0.8, kHighSeed, {0.0, 0.0, 0.7}},
      // mirror_wf: the point itself; Ψ₁ = 0.879 keeps x, 0.317 mirrors it; with all three axes (Ψ = 0.317, 0.876,
      // 0.483) x and z are mirrored; from 0x12345678 (Ψ₂, Ψ₃ < ½) y and z are.
      {"mirror_wf", {}, kPoint, 0.8, kHighSeed, {0.3, -0.7, 0.5}},
      {"mirror_wf", {}, kPoint, 0.8, kLowSeed, {-0.3, -0.7, 0.5}},
      {"mirror_wf", {1, 1, 1, 0.1, 0.2, 0.3, 1.5, -0.5, 0, 0, 0}, kPoint, 0.8, kLowSeed, {-0.6, 0.35, -0.8}},
      {"mirror_wf", {0, 1, 1, 0.1, 0.2, 0.3, 1.5, -0.5, 0, 0, 0}, kPoint, 0.8, 0x12345678u, {0.45, -0.25, -0.8}},
      // The *_bs functions; coth2_bs at the origin, where its denominator is 0, adds nothing (z neither).
      {"cos2_bs", {}, kPoint, 0.8, kHighSeed, {0.9592870008789945, 0.1793414498700343, 0.4}},
      {"cos2_bs", {0.5, 1.5, -0.7, 2.0}, kPoint, 0.8, kHighSeed, {1.5494162324944585, -0.06095221730621698, 0.4}},
      {"coth2_bs", {}, kPoint, 0.8, kHighSeed, {0.5015498089910704, -0.7763281911935119, 0.4}},
      {"coth2_bs", {0.5, 1.5, -0.7, 2.0}, kPoint, 0.8, kHighSeed, {0.1290998026899597, 0.40353643041223314, 0.4}},
      {"coth2_bs", {}, {0.0, 0.0, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.0}},
      {"sec2_bs", {}, kPoint, 0.8, kHighSeed, {0.5564681877092988, -0.24689093480859295, 0.4}},
      {"sec2_bs", {0.5, 1.5, -0.7, 2.0}, kPoint, 0.8, kHighSeed, {1.041192453744641, 0.04095928993596859, 0.4}},
      {"tan2_bs", {}, kPoint, 0.8, kHighSeed, {0.15177367321526952, -0.511868744210544, 0.4}},
      {"tan2_bs", {0.5, 1.5, -0.7, 2.0}, kPoint, 0.8, kHighSeed, {0.039179602350708956, 0.13367084168369156, 0.4}},
      // triangle: barycentric (1 − √Ψ₁, √Ψ₁ (1 − Ψ₂), √Ψ₁ Ψ₂) of its corners (it replaces the sum before it in the
      // chaos game; the function adds).
      {"triangle", {}, kPoint, 0.8, kHighSeed, {0.1400955861718792, 0.0018248904374931541, 0.0}},
      {"triangle",
       {0.1, 0.2, 0.3, -0.5, 0.4, -0.2, 0.6, -0.7, 0.9},
       kPoint,
       0.8,
       kLowSeed,
       {0.24352332295533047, -0.18357658520318243, 0.4485366385172935}},
      // chunk: inside the unit circle (mode 0) the point, x and y unweighted; outside nothing; mode 1 the reverse.
      {"chunk", {}, kPoint, 0.8, kHighSeed, {0.3, -0.7, 0.4}},
      {"chunk", {}, {1.2, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.0}},
      {"chunk", {0.5, 0.3, 1.0, -0.2, 0.1, -0.4, 1}, kPoint, 0.8, kHighSeed, {0.0, 0.0, 0.0}},
      {"chunk", {0.5, 0.3, 1.0, -0.2, 0.1, -0.4, 1}, {1.2, -0.7, 0.5}, 0.8, kHighSeed, {1.2, -0.7, 0.4}},
      // spirograph3D: t = tmin + (tmax − tmin)Ψ, then the mode's offsets (modes 0 to 4).
      {"spirograph3D", {}, kPoint, 0.8, kHighSeed, {0.8098890486908985, -0.28808266560141543, 0.18808586020393545}},
      {"spirograph3D",
       {1.2, 0.5, -0.3, -5.0, 20.0, 0.3, 1, 0},
       kPoint,
       0.8,
       kLowSeed,
       {-1.6233265244226827, 0.21290382585564355, 0.17874044363729935}},
      {"spirograph3D",
       {1.2, 0.5, -0.3, -5.0, 20.0, 0.3, 2, 0},
       kPoint,
       0.8,
       kLowSeed,
       {-1.447262687299321, 0.18970950069406792, -0.006547719905297212}},
      {"spirograph3D",
       {1.2, 0.5, -0.3, -5.0, 20.0, 0.3, 3, 0},
       kPoint,
       0.8,
       kLowSeed,
       {-1.5057350226379136, 0.3556428236005621, 0.13769884877451236}},
      {"spirograph3D",
       {1.2, 0.5, -0.3, -5.0, 20.0, 0.3, 4, 0},
       kPoint,
       0.8,
       kLowSeed,
       {-1.7774323602653244, 0.19371746482828422, 0.11203264050730044}},
      // rhodonea: 3/4 closes after 4 cycles, 5/3 after 3 (twice with metacycles 2), 2.5/1.3 after 16; the modes 0–6
      // inside and outside the petal (the drops of modes 5 and 6 are checked below); mode 1 reads the sum so far.
      {"rhodonea", {}, kPoint, 0.8, kHighSeed, {0.03655410867786188, -0.748913446083023, 0.4}},
      {"rhodonea", {}, {0.05, -0.1, 0.5}, 0.8, kHighSeed, {0.2203868598623796, -0.755612090956729, 0.4}},
      {"rhodonea",
       {5, 3, 0, 0, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.024262005806583054, 0.5778546290789098, 0.4}},
      {"rhodonea",
       {5, 3, 0, 0, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       {0.05, -0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.05972441789948013, 0.44201290454106545, 0.4}},
      {"rhodonea",
       {5, 3, 1, 1, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.026956191241430727, 0.6272147285229952, 0.4}},
      {"rhodonea",
       {5, 3, 1, 1, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       {0.05, -0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.04381775277180272, 0.29485886976921766, 0.4}},
      {"rhodonea",
       {5, 3, 2, 2, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.19253764127744832, 0.5671418516315639, 0.4}},
      {"rhodonea",
       {5, 3, 2, 2, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       {0.05, -0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.05341260417164648, 0.2972077427246393, 0.4}},
      {"rhodonea",
       {5, 3, 3, 3, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.2114620058065831, 0.9138546290789098, 0.4}},
      {"rhodonea",
       {5, 3, 3, 3, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       {0.05, -0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.046924417899480125, 0.4100129045410654, 0.4}},
      {"rhodonea",
       {5, 3, 4, 4, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.03278240937784149, 0.6767735081902053, 0.4}},
      {"rhodonea",
       {5, 3, 4, 4, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       {0.05, -0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.024119858415577747, 0.21386907062214924, 0.4}},
      {"rhodonea",
       {5, 3, 5, 5, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       kPoint,
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.4}},
      {"rhodonea",
       {5, 3, 6, 6, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3},
       {0.05, -0.1, 0.5},
       0.8,
       kHighSeed,
       {0.04999999999999999, -0.09999999999999998, 0.4}},
      {"rhodonea",
       {2.5, 1.3, 1, 1, 0.4, 0.6, 0.8, 1.3, 1.0, 0.0, 0.0, 0, 0.0, 1, 0.0},
       kPoint,
       0.8,
       kHighSeed,
       {-0.16073795409298414, -0.033435697615263604, 0.4}},
      // inversion: the circle (scale 1 and 0.684), the holdout's ellipse, a hyperbola, a pentagon in a 1.5-norm, a rose
      // (its farthest crossing, in a 3-norm), a superellipse and a supershape; points imode or the ring leave alone
      // (unweighted); the rose's outline (draw_shape, thickened) and a pass-through.
      {"inversion", {}, kPoint, 0.8, kHighSeed, {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"inversion",
       {0.684, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.19359558620689657, -0.4517230344827587, 0.4}},
      {"inversion",
       {1, 0, 1, 0, 0, 1.712, 1.144, 0.132, 0.924, 0.016, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.5924259939762235, -1.382327319277855, 0.4}},
      {"inversion",
       {1, -0.35, 2, 0, 0, 0.6, 1.3, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.14976402911038006, -0.34944940125755347, 0.4}},
      {"inversion",
       {1, 0.1, 3, 0, 0, 5.5, 1, 0, 0, 0, 0, 0, 1, 1.5, 2, 1.2, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.25597226551973185, -0.5972686195460409, 0.4}},
      {"inversion",
       {1, 0, 4, 0, 0, 5, 3, 0.2, 0, 0, 0, 0, 1, 2, 3, 1, 0.8, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.003878458837314287, -0.00904973728706667, 0.4}},
      {"inversion",
       {1, 0, 5, 0, 0, 1.2, 0.8, 3.0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.3086880410546225, -0.7202720957941192, 0.4}},
      {"inversion",
       {1, 0, 6, 0, 0, 1.0, 1.2, 5, 2.0, 1.5, 1.7, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.5419221316130625, -1.2644849737638124, 0.4}},
      {"inversion",
       {1, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.5}},
      {"inversion",
       {0.5, 0, 0, 2, 0, 1, 1, 0, 0, 0, 0, 2, 0.8, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.5}},
      {"inversion",
       {1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0.8, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.5}},
      {"inversion",
       {1, 0, 4, 0, 0, 5, 3, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0.95, 3.0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {-0.27385716404747074, 0.5796280016773844, 0.0}},
      {"inversion",
       {1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0.5, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kLowSeed,
       {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"inversion",
       {1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0.95, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.0}},
      {"inversion",
       {1.2, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0.5, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.5958620689655173, -1.390344827586207, 0.4}},
      {"inversion",
       {1.1, 0, 0, 2, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 1},
       kPoint,
       0.8,
       kHighSeed,
       {0.5006896551724139, -1.1682758620689657, 0.4}},
      // minkowskope: p outside the band (the main point, at the defaults and with other waves), −p inside it.
      {"minkowskope", {}, kPoint, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"minkowskope", {0.2, 3.1, -2.5, 0.9, 1.4, 0.3}, kPoint, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"minkowskope",
       {0.2, 3.1, -2.5, 0.9, 1.4, 0.3},
       {0.45, 0.1, 0.5},
       0.8,
       kHighSeed,
       {-0.36000000000000004, -0.08000000000000002, 0.4}},
      {"minkowskope",
       {0.1, -1.1, 6.8, 2.2, -3.7, -0.03},
       {-0.6, 0.2, 0.5},
       0.8,
       kHighSeed,
       {-0.48, 0.16000000000000003, 0.4}},
      {"minkowskope", {}, {0.3, 0.1, 0.5}, 0.8, kHighSeed, {-0.24, -0.08000000000000002, 0.4}},
      // maurer_rose: on a chord at the defaults (Ψ₁ = 0.879 and 0.317 below the lines' share 0.952); with shares 0.2,
      // 0.5, 0.3 on the rose (Ψ₁ = 0.879), at a chord's first end (0.317) and second end (0.530), and on a chord
      // (0.0007, from 0x0BADF00D).
      {"maurer_rose", {}, kPoint, 0.8, kHighSeed, {0.35042312984084556, 0.27194415188637117, 0.4}},
      {"maurer_rose", {}, kPoint, 0.8, kLowSeed, {0.6613317155186986, 0.013475340926416913, 0.4}},
      {"maurer_rose",
       {5, 3, 0.2, 53, 120, 0.2, 0.5, 0.3, 1.0, 2.0, 1.5},
       kPoint,
       0.8,
       kHighSeed,
       {0.10976406816349099, 0.6082981500359455, 0.4}},
      {"maurer_rose",
       {5, 3, 0.2, 53, 120, 0.2, 0.5, 0.3, 1.0, 2.0, 1.5},
       kPoint,
       0.8,
       kLowSeed,
       {0.2397903505361456, 0.22202691687245513, 0.4}},
      {"maurer_rose",
       {5, 3, 0.2, 53, 120, 0.2, 0.5, 0.3, 1.0, 2.0, 1.5},
       kPoint,
       0.8,
       0x12345678u,
       {-0.03386612417721127, 0.4818334357814711, 0.4}},
      {"maurer_rose",
       {5, 3, 0.2, 53, 120, 0.2, 0.5, 0.3, 1.0, 2.0, 1.5},
       {-0.6, 0.2, 0.5},
       0.8,
       0x0BADF00Du,
       {0.16898388758735852, -0.1238992897920908, 0.4}},
  };
  return cases;
}

class JwildfireVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(JwildfireVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Jwildfire, JwildfireVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// The colour index JWildfire's direct colour leaves in every one of 37 lanes (the harness's colour was 0.375), from
// the same transcription: plane_wf's (u, v) are ½ − Ψ₁ and ½ − Ψ₂ (swapped on the plane zx), spirograph3D's t is
// tmin + (tmax − tmin) Ψ₁, recurrenceplot colours the running sum (the harness's start (0.125, −0.25) plus the pair
// of its point row above: (0.3028571, 0.0354286)), and truchet the distance to the corner of the arc the point is on.
const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      // plane_wf: color_mode 3 (u + ½)(v + ½), on zx (the default) and on yz; 1: u + ½; 2: v + ½; direct_color 0 and
      // color_mode 0 (a colour image, none here) leave the colour.
      {"plane_wf", {}, kPoint, kHighSeed, 0.05480354561447598},
      {"plane_wf", {-1.5, 4.0, 1, 1, 3, 0, 0, 0, 0, 0}, kPoint, kHighSeed, 0.05480354561447598},
      {"plane_wf", {-1.5, 4.0, 0, 1, 1, 0, 0, 0, 0, 0}, kPoint, kLowSeed, 0.6834064722061157},
      {"plane_wf", {-1.5, 4.0, 0, 1, 2, 0, 0, 0, 0, 0}, kPoint, kLowSeed, 0.12429302930831909},
      {"plane_wf", {-1.5, 4.0, 2, 1, 2, 0, 0, 0, 0, 0}, kPoint, kHighSeed, 0.12053358554840088},
      {"plane_wf", {-1.5, 4.0, 2, 0, 3, 0, 0, 0, 0, 0}, kPoint, kHighSeed, 0.375},
      {"plane_wf", {-1.5, 4.0, 2, 1, 0, 0, 0, 0, 0, 0}, kPoint, kHighSeed, 0.375},
      // spirograph3D: (t/2π) mod 1, negative below t = 0 as JWildfire's fmod; direct_color 0 leaves it.
      {"spirograph3D", {1.0, -0.3, 0.4, 0.0, 1000.0, 0.0, 0, 1}, kPoint, kHighSeed, 0.9714271432775092},
      {"spirograph3D", {1.0, -0.3, 0.4, -50.0, 10.0, 0.0, 0, 1}, kPoint, kLowSeed, -0.9345016606368848},
      {"spirograph3D", {}, kPoint, kHighSeed, 0.375},
      // recurrenceplot: dc 2 |½((x cos a + y sin a + offset)/scale + 1)| mod 1, dc 1 |½ x y/scale + offset| mod 1.
      {"recurrenceplot", {2, 0.0, 0.0, 0, 700, 2, 1.0, 0.0, 0.0, 5.0}, kPoint, kHighSeed, 0.7139285714285715},
      {"recurrenceplot", {2, 0.0, 0.0, 0, 700, 2, 2.0, 0.7, 0.1, 5.0}, kPoint, kHighSeed, 0.5722531208816439},
      {"recurrenceplot", {2, 0.0, 0.0, 0, 700, 1, 0.5, 0.0, 0.3, 5.0}, kPoint, kHighSeed, 0.20819408163265304},
      {"recurrenceplot", {2, 0.0, 0.0, 0, 700, 0, 0.5, 0.0, 0.3, 5.0}, kPoint, kHighSeed, 0.375},
      // truchet (weight 0.8, so the cell coordinates are 1.25 p): (0.35, 0.05) lies on the first arc (‖q‖ =
      // 0.56596), (0.05, 0.4) on the second (1 − ‖q − (1, 1)‖ = 0.49611), (0.45, 0.4) on neither.
      {"truchet", {0, 2.0, 0.5, 0.0, 1.0, 50.0, 1}, {0.35, 0.05, 0.5}, kHighSeed, 0.5659615711335886},
      {"truchet", {0, 2.0, 0.5, 0.0, 1.0, 50.0, 1}, {0.05, 0.4, 0.5}, kHighSeed, 0.4961088907313407},
      {"truchet", {0, 2.0, 0.5, 0.0, 1.0, 50.0, 1}, {0.45, 0.4, 0.5}, kHighSeed, 0.375},
      {"truchet", {0, 2.0, 0.5, 0.0, 1.0, 50.0, 0}, {0.35, 0.05, 0.5}, kHighSeed, 0.375},
      // point_symmetry_wf: k = ⌊3Ψ⌋ = 2 (high seed) moves the colour by 2 · colorshift, k = 0 (low seed) not at all;
      // fmod keeps the sign of a negative sum.
      {"point_symmetry_wf", {0.25, 0.5, 3, 0.3}, kPoint, kHighSeed, 0.975},
      {"point_symmetry_wf", {0.25, 0.5, 3, 0.3}, kPoint, kLowSeed, 0.375},
      {"point_symmetry_wf", {0.25, 0.5, 3, -0.5}, kPoint, kHighSeed, -0.625},
      // mirror_wf with all three axes: Ψ = 0.879, 0.545, 0.394 mirror z alone (+ zcolorshift); Ψ = 0.317, 0.876,
      // 0.483 mirror x and z (+ xcolorshift + zcolorshift).
      {"mirror_wf", {1, 1, 1, 0, 0, 0, 1, 1, 0.1, 0.2, 0.3}, kPoint, kHighSeed, 0.675},
      {"mirror_wf", {1, 1, 1, 0, 0, 0, 1, 1, 0.1, 0.2, 0.3}, kPoint, kLowSeed, 0.775},
      // axis_symmetry_wf: Ψ < ½ keeps the near side (+ the axis' first shift), else mirrors (+ its second).
      {"axis_symmetry_wf", {1, 0.25, 0.5, 0.5, 30, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, kPoint, kHighSeed, 0.875},
      {"axis_symmetry_wf", {1, 0.25, 0.5, 0.5, 30, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, kPoint, kLowSeed, 0.575},
      {"axis_symmetry_wf", {2, 0.25, 0.5, 0.5, 30, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, kPoint, kHighSeed, 0.975},
  };
  return cases;
}

class JwildfireVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(JwildfireVariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Jwildfire, JwildfireVariationSetsColour, testing::ValuesIn(colourCases()), colourCaseLabel);

// A file's parameters as JWildfire writes them (recurrenceplot's capitalised Density, plane_wf's image names) are
// read, and the direct colour is kept.
TEST(FlameVariationJwildfire, ImportReadsTheParametersAndKeepsTheirColour) {
  const auto importXform = [](const std::string& xform) {
    const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                             "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
    return readFlameXml(text, "t.flame").flame;
  };
  const ImportedFlame plot = importXform(
      R"(recurrenceplot="1" recurrenceplot_func_id="2" recurrenceplot_Density="500" recurrenceplot_dc="0" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(plot.leftOut.empty()) << plot.leftOut.front();
  const VariationTerm& term = plot.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "recurrenceplot");
  EXPECT_EQ(term.params.at(0), 2.0);
  EXPECT_EQ(term.params.at(4), 500.0);
  const ImportedFlame coloured = importXform(R"(recurrenceplot="1" recurrenceplot_dc="2" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(coloured.leftOut.empty()) << coloured.leftOut.front();
  for (const char* direct : {"0", "1"}) {
    const ImportedFlame plane = importXform(std::string(R"(plane_wf="1" plane_wf_direct_color=")") + direct +
                                            R"(" plane_wf_color_mode="2" plane_wf_colormap_filename="" )"
                                            R"(plane_wf_displ_map_filename="" coefs="1 0 0 1 0 0")");
    EXPECT_TRUE(plane.leftOut.empty()) << plane.leftOut.front();
    EXPECT_EQ(plane.genome.xforms.at(0).variations.at(0).params.at(3), direct[0] == '1' ? 1.0 : 0.0);
  }
  const ImportedFlame symmetry = importXform(
      R"(linear="1" post_point_symmetry_wf="1" post_point_symmetry_wf_colorshift="0.1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(symmetry.leftOut.empty()) << symmetry.leftOut.front();
  EXPECT_EQ(symmetry.genome.xforms.at(0).variations.back().params.at(3), 0.1);
  // The Apophysis plugin's names for minkowskope's parameters.
  const ImportedFlame scope = importXform(R"(minkowskope="1" mskope_separation="0.7" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(scope.leftOut.empty()) << scope.leftOut.front();
  EXPECT_EQ(scope.genome.xforms.at(0).variations.at(0).params.at(0), 0.7);
  const ImportedFlame mirror =
      importXform(R"(linear="1" post_mirror_wf="1" post_mirror_wf_xcolorshift="0.68" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(mirror.leftOut.empty()) << mirror.leftOut.front();
  EXPECT_EQ(mirror.genome.xforms.at(0).variations.back().params.at(8), 0.68);
  const ImportedFlame zscale =
      importXform(R"(linear3D="1" post_zscale_wf="0.5" post_zscale_wf_ztranslate="0.25" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(zscale.leftOut.empty()) << zscale.leftOut.front();
  EXPECT_EQ(zscale.genome.xforms.at(0).variations.back().name, "post_zscale_wf");
  EXPECT_EQ(variationStage("post_zscale_wf"), VariationStage::Post);
  EXPECT_FALSE(findVariation("zscale_wf")->mapsXY);
}

// rhodonea's mode 5 drops the points inside the petal and mode 6 those beyond it (NaN, the chaos game's escape, where
// JWildfire hides them); z is carried either way.
TEST(FlameVariationJwildfire, RhodoneaMasksDropThePointsTheyHide) {
  const VariationInfo& info = variationOrThrow("rhodonea");
  for (const double mode : {5.0, 6.0}) {
    const std::vector<double> params = {5, 3, mode, mode, 0.4, 0.6, 0.8, 1.3, 1.5, 0.2, 0.1, 0, 0.1, 2, 0.3};
    // (0.05, −0.1) lies inside the petal, (0.3, −0.7) beyond it.
    const glm::dvec3 hidden = mode == 5.0 ? glm::dvec3{0.05, -0.1, 0.5} : kPoint;
    const Outputs out = run(info, params, hidden, 0.8, kHighSeed, 5);
    for (std::size_t lane = 0; lane < 5; ++lane) {
      EXPECT_TRUE(std::isnan(out.x[lane]) && std::isnan(out.y[lane])) << mode;
      EXPECT_NEAR(out.z[lane] - kStartZ, 0.4, 1e-12);
    }
  }
}

// inversion with hide_uninverted drops the points it does not invert (NaN, where JWildfire hides them), with z.
TEST(FlameVariationJwildfire, InversionHidesWhatItDoesNotInvert) {
  const VariationInfo& info = variationOrThrow("inversion");
  std::vector<double> params = info.defaultParams();
  params[3] = 1.0;  // imode 1: only points outside the unit circle invert; (0.3, −0.7) lies inside
  params[4] = 1.0;  // hide_uninverted
  const Outputs out = run(info, params, kPoint, 0.8, kHighSeed, 5);
  for (std::size_t lane = 0; lane < 5; ++lane) {
    EXPECT_TRUE(std::isnan(out.x[lane]) && std::isnan(out.y[lane]));
    EXPECT_NEAR(out.z[lane] - kStartZ, 0.5, 1e-12);
  }
}

}  // namespace
