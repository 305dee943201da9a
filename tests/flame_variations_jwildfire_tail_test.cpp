// The variations of core/flame/variations_jwildfire_tail.cpp and JWildfire's extra parameters of splits, mask and
// rational3, with a second check of variations_jwildfire_more.cpp and _shapes.cpp (rows for tangent3D, coth2_bs,
// tan2_bs, triangle, rose_wf, mirror_wf, spirograph3D, inversion and minkowskope), each at points whose expected
// values were worked out from JWildfire's published formulas (its variation classes) by a separate Python script in
// double precision, independently of the code under test. The point is (0.3, −0.7, 0.5) with weight 0.8, as in
// flame_variations_more_test.cpp; random variations are replayed from the lane's seed: xorshift32 gives Ψ = 0.879466,
// 0.545326, 0.394069 from 0x2545F491 and Ψ = 0.316594, 0.875707, 0.483300 from 0x9E3779B9. stabilize's fixed points
// come from java.util.Random's published algorithm.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

const std::vector<PointCase>& pointCases() {
  // Notes on the rows: dustpoint takes (x/3, y/3) + (⅔, 0) for Ψ₂ ≥ ¾ and (x/3, y/3) for Ψ₂ in [½, ¾); rose_wf fills
  // (r·Ψ₂) only when Ψ₁ < filled; mirror_wf and stabilize do not apply the weight; stabilize with p = 1000 always
  // jumps, to point ⌊Ψ₂ n⌋; the prepost_ rows are the post_ map, the pre_prepost_ rows its inverse.
  static const std::vector<PointCase> cases = {
      {"tangent3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.30910450451020294, -0.6738307043704636, 0.24746899968769862}},
      {"coth2_bs",
       {2.0, 2.0, 2.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.5015498089910703, -0.7763281911935118, 0.4}},
      {"coth2_bs",
       {1.5, -0.7, 0.9, 1.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.9115742393825871, -1.1540956222816323, 0.4}},
      {"tan2_bs",
       {2.0, 2.0, 2.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.15177367321526955, -0.511868744210544, 0.4}},
      {"tan2_bs",
       {1.5, -0.7, 0.9, 1.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.14370390068176542, -0.22218363268799873, 0.4}},
      {"dustpoint", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.08, -0.18666666666666665, 0.4}},
      {"dustpoint", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.6133333333333333, -0.18666666666666665, 0.4}},
      {"triangle",
       {-0.2, -0.1, 0.0, 0.2, -0.1, 0.0, 0.2, 0.1, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.1400955861718792, 0.0018248904374931541, 0.0}},
      {"triangle",
       {-0.5, -0.5, 0.1, 0.5, -0.5, 0.2, 0.25, -1.0, -0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.04841302990925836, -0.5970923710577766, -0.07207905549581356}},
      {"rose_wf",
       {0.5, 4.0, 0.85},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.007681660519260871, 0.01792387454494203, 0.4}},
      {"rose_wf",
       {0.5, 4.0, 0.85},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.006726883663203821, 0.015696061880808913, 0.4}},
      {"rose_wf", {0.7, 3.0, 0.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.076908442330559, 0.17945303210463764, 0.4}},
      {"mirror_wf",
       {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.5}},
      {"mirror_wf",
       {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.3, -0.7, 0.5}},
      {"mirror_wf",
       {1.0, 1.0, 1.0, 1.844, 2.604, 0.3, 0.9, 1.1, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-1.9296000000000002, -0.77, -0.8}},
      {"stabilize", {4.0, 0.0, 0.1, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3, -0.7, 0.5}},
      {"stabilize",
       {20.0, 35655.0, 1000.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.4927433146838516, -0.9920245064406414, 0.0}},
      {"stabilize",
       {20.0, 35655.0, 1000.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.5605459883556367, -0.39142263144686584, 0.0}},
      {"prepost_affine",
       {1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"prepost_affine",
       {0.768, 0.748, 1.2, 30.0, -20.0, 50.0, 0.1, -0.2, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.07919340471037703, -0.2901118320356755, 0.9321423085314551}},
      {"pre_prepost_affine",
       {1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.37499999999999994, -0.8749999999999999, 0.625}},
      {"pre_prepost_affine",
       {0.768, 0.748, 1.2, 30.0, -20.0, 50.0, 0.1, -0.2, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.02166234743853776, -0.9032091530306756, -0.20226539482334835}},
      {"prepost_circlize",
       {4.0, 45.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24463422195889728, -0.5708131845707602, 0.4}},
      {"prepost_circlize",
       {5.0, 20.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3365823818617944, -0.7853588910108535, 0.4}},
      {"pre_prepost_circlize",
       {4.0, 45.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3719681681374471, -0.8679257256540432, 0.4}},
      {"pre_prepost_circlize",
       {5.0, 20.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.26825621506427755, -0.6259311684833143, 0.4}},
      {"prepost_mobius",
       {1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"prepost_mobius",
       {0.5, 0.0, 0.248, 1.0, 0.064, 0.136, 0.216, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.13735939666542663, -0.11496026243701173, 0.4}},
      {"pre_prepost_mobius",
       {1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.37499999999999994, -0.8749999999999999, 0.4}},
      {"pre_prepost_mobius",
       {0.5, 0.0, 0.248, 1.0, 0.064, 0.136, 0.216, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.7386795897872857, -3.343134718967773, 0.4}},
      {"splits",
       {0.25, 0.4, 0.1, 0.552, 0.428, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.20000000000000007, -0.43840000000000007, 0.4}},
      {"mask",
       {0.2, -0.3, 0.5, 1.5, 0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.5590531459408119, 0.7353984620161436, 0.4}},
      // spirograph3D: t = tmin + Ψ₁ (tmax − tmin), then the blur's draws by mode. The cut_ shapes: a point each kept
      // by the pattern in mode 0, one the default cuts away kept by invert, and a random one of mode 1 (the first of
      // the seeds k · 0x9E3779B1 whose point is kept).
      {"cut_fractal",
       {0.0, 0.0, 0.0, 30.0, 1.0, 0.0},
       {0.1, 0.2, 0.5},
       0.8,
       kHighSeed,
       {0.08000000000000002, 0.16000000000000003, 0.4}},
      {"cut_fractal",
       {0.0, 0.0, 0.0, 30.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"cut_fractal",
       {0.0, 1.0, 0.0, 30.0, 1.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x9E3779B1u,
       {-0.14632229804992677, 0.20054192543029786, 0.4}},
      {"cut_glypho",
       {0.0, 1.0, 0.0, 0.115, 0.75, 1.5},
       {-0.25, 0.05, 0.5},
       0.8,
       kHighSeed,
       {-0.2, 0.04000000000000001, 0.4}},
      {"cut_glypho",
       {0.0, 1.0, 1.0, 0.115, 0.75, 1.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"cut_glypho",
       {1.0, 1.0, 0.0, 0.115, 0.75, 1.5},
       {0.3, -0.7, 0.5},
       0.8,
       0x3C6EF362u,
       {0.10735540390014649, 0.0024466514587402344, 0.4}},
      {"cut_triskel", {0.0, 1.0, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"cut_triskel",
       {0.0, 1.0, 1.0},
       {0.1, 0.2, 0.5},
       0.8,
       kHighSeed,
       {0.08000000000000002, 0.16000000000000003, 0.4}},
      {"cut_triskel",
       {1.0, 1.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x9E3779B1u,
       {-0.29264459609985355, 0.4010838508605957, 0.4}},
      {"cut_web",
       {1000.0, 0.0, 0.0, 0.05, 1.0},
       {0.4, 0.4, 0.5},
       0.8,
       kHighSeed,
       {0.32000000000000006, 0.32000000000000006, 0.4}},
      {"cut_web", {1000.0, 0.0, 0.0, 0.05, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"cut_web",
       {1000.0, 0.0, 1.0, 0.05, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x17156075u,
       {0.5525423049926758, -0.23206024169921877, 0.4}},
      {"spirograph3D",
       {1.0, -0.3, 0.4, 0.0, 1000.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.8098890486908985, -0.28808266560141543, 0.18808586020393545}},
      {"spirograph3D",
       {1.0, -0.3, 0.4, 0.0, 10.0, 0.2, 1.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.6576529902960369, 0.28235492943653345, -0.34217626325369505}},
      {"spirograph3D",
       {0.8, 0.5, 0.3, -2.0, 3.0, 0.2, 2.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.9974590821201972, 0.6996004590332882, -0.09196740468590839}},
      {"spirograph3D",
       {0.8, 0.5, 0.3, -2.0, 3.0, 0.2, 3.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.8597874131781288, -0.1011481153595524, -0.19504174084168027}},
      {"spirograph3D",
       {0.8, 0.5, 0.3, -2.0, 3.0, 0.2, 4.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-1.1647111649449042, 0.7165494355500118, -0.012024224601679871}},
      // inversion: the default is circle inversion, w p / r² (r² = 0.58); the shapes' boundary radius on the ray
      // through p squared over r² otherwise; imode 1 leaves this point inside the circle unweighted (z too);
      // draw_shape draws the ellipse's boundary at angle 2π Ψ₂, jittered by Ψ₃, Ψ₄, z not carried (JWildfire returns
      // before z). minkowskope's rows negate
      // the point or keep it as |y| ≤ t or not, t worked out with 20 Stern–Brocot steps of Minkowski's ?(x).
      {"inversion", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"inversion",
       {0.684, 0.0, 1.0, 0.0, 0.0, 1.712, 1.144, 0.132, 0.924, 0.016, 0.0, 0.0, 1.0,
        2.0,   2.0, 1.0, 1.0, 0.0, 0.0,   0.0,   1.0,   0.0,   1.0,   0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2771700558377401, -0.6467301302880603, 0.4}},
      {"inversion",
       {1.2, 0.25, 3.0, 0.0, 0.0, 5.5, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0,  1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3917185800425878, -0.9140100200993716, 0.4}},
      {"inversion",
       {0.9, 0.0, 4.0, 0.0, 0.0, 3.0, 2.0, 0.2, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.20611511444276215, -0.4809352670331116, 0.4}},
      {"inversion",
       {0.8, 0.0, 5.0, 0.0, 0.0, 1.1, 0.9, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24686467527676678, -0.5760175756457891, 0.4}},
      {"inversion",
       {0.8, 0.0, 6.0, 0.0, 0.0, 1.0, 1.0, 5.0, 2.0, 3.0, 3.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2695997460606534, -0.6290660741415246, 0.4}},
      {"inversion",
       {0.5, 0.0, 2.0, 0.0, 0.0, 0.3, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.11764705882352938, -0.27450980392156854, 0.4}},
      {"inversion",
       {1.0, 0.0, 0.0, 2.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.41379310344827586, -0.9655172413793104, 0.4}},
      {"inversion",
       {1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.5,
        3.0, 1.5, 1.2, 0.8, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.5099909613377092, -1.189978909787988, 0.4}},
      {"inversion",
       {1.0, 0.0, 1.0, 0.0, 0.0, 1.5, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.9, 2.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-1.3755367589562029, -0.4120557014809042, 0.0}},
      {"minkowskope",
       {0.5, -2.0, 2.0, 0.5, 1.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"minkowskope",
       {1.585451060108106, 6.108345289201079, 2.533326589503186, 2.0320358159448872, 1.3750118252207137,
        0.07506350214258628},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"minkowskope",
       {0.1, 3.0, -1.5, 0.5, 0.7, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4}},
      {"minkowskope",
       {1.0, -2.0, 2.0, 0.5, 1.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.24, 0.5599999999999999, 0.4}},
      {"minkowskope",
       {0.6, 3.0, -1.5, 0.5, 0.7, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.24, 0.5599999999999999, 0.4}},
      {"minkowskope", {0.45, -1.1, 2.5, 0.8, 0.3, -0.4}, {1.2, 0.5, -0.25}, 0.8, kHighSeed, {0.96, 0.4, -0.2}},
      {"inversion",
       {1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        2.0, 2.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3, -0.7, 0.5}},
  };
  return cases;
}

class JwildfireTailVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(JwildfireTailVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireTail, JwildfireTailVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// A prepost_ pair's two halves undo each other: the post_ map of the pre_ map's result is the point.
TEST(FlameVariationJwildfireTail, PrepostHalvesAreInverses) {
  // mobius' halves are inverse at weight 1 only: JWildfire's pre_ half is M⁻¹(p)/w, not the inverse M⁻¹(p/w)
  // of its post_ half w·M(p).
  struct Pair {
    std::string name;
    std::vector<double> params;
    double weight;
  };
  const std::vector<Pair> pairs = {
      {"prepost_affine", {0.768, 0.748, 1.2, 30.0, -20.0, 50.0, 0.1, -0.2, 0.3}, 0.8},
      {"prepost_mobius", {0.5, 0.0, 0.248, 1.0, 0.064, 0.136, 0.216, 0.0}, 1.0},
  };
  for (const auto& [name, params, weight] : pairs) {
    const Outputs pre = run(variationOrThrow("pre_" + name), params, {0.3, -0.7, 0.5}, weight, kHighSeed, 1);
    const glm::dvec3 inverse{pre.x[0] - kStartX, pre.y[0] - kStartY, pre.z[0] - kStartZ};
    const Outputs post = run(variationOrThrow(name), params, inverse, weight, kHighSeed, 1);
    EXPECT_NEAR(post.x[0] - kStartX, 0.3, 1e-12) << name;
    EXPECT_NEAR(post.y[0] - kStartY, -0.7, 1e-12) << name;
  }
  // circlize's halves are inverse at full weight (the blend by the weight is not inverted).
  const std::vector<double> circlize = {5.0, 20.0, 0.0};
  const Outputs pre = run(variationOrThrow("pre_prepost_circlize"), circlize, {0.3, -0.7, 0.5}, 1.0, kHighSeed, 1);
  const Outputs post = run(variationOrThrow("prepost_circlize"), circlize,
                           {pre.x[0] - kStartX, pre.y[0] - kStartY, 0.5}, 1.0, kHighSeed, 1);
  EXPECT_NEAR(post.x[0] - kStartX, 0.3, 1e-12);
  EXPECT_NEAR(post.y[0] - kStartY, -0.7, 1e-12);
}

// The colour index (kStartColour = 0.375 before): pre_stabilize with dc sets the jumped-to point's (k = 10 of
// JWildfire's ½, ¼, ¾, ⅛, … table: 7/16), worked out by the same Python script from JWildfire's own loop.
TEST(FlameVariationJwildfireTail, PreStabilizeSetsTheColourIndexWithDc) {
  const Outputs stabilize =
      run(variationOrThrow("stabilize"), {20.0, 35655.0, 1000.0, 1.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
  EXPECT_DOUBLE_EQ(stabilize.colour[0], 0.4375);
  const Outputs plain =
      run(variationOrThrow("stabilize"), {20.0, 35655.0, 1000.0, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
  EXPECT_EQ(plain.colour[0], kStartColour);
}

// What a cut_ shape cuts away is dropped: NaN in x, y and z, the chaos game's escape.
TEST(FlameVariationJwildfireTail, CutShapesDropWhatTheyCutAway) {
  const std::vector<std::pair<std::string, std::vector<double>>> cuts = {
      {"cut_fractal", {0.0, 0.0, 0.0, 30.0, 1.0, 0.0}},
      {"cut_glypho", {0.0, 1.0, 0.0, 0.115, 0.75, 1.5}},
      {"cut_web", {1000.0, 0.0, 0.0, 0.05, 1.0}},
  };
  for (const auto& [name, params] : cuts) {
    const Outputs out = run(variationOrThrow(name), params, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
    EXPECT_TRUE(std::isnan(out.x[0]) && std::isnan(out.y[0]) && std::isnan(out.z[0])) << name;
  }
  const Outputs triskel = run(variationOrThrow("cut_triskel"), {0.0, 1.0, 0.0}, {0.1, 0.2, 0.5}, 0.8, kHighSeed, 5);
  EXPECT_TRUE(std::isnan(triskel.x[0]) && std::isnan(triskel.y[0]) && std::isnan(triskel.z[0]));
}

ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// JWildfire's prepost_ variation is one attribute; it runs as a pre_ term (the inverse) and a post_ term.
TEST(FlameVariationJwildfireTail, PrepostIsImportedAsAPreAndAPostTerm) {
  const ImportedFlame flame =
      importXform(R"(linear="1" prepost_mobius="1.0" prepost_mobius_fx_priority="2" prepost_mobius_re_a="0.5" )"
                  R"(prepost_mobius_im_b="0.136" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 3u);
  EXPECT_EQ(terms.at(1).name, "pre_prepost_mobius");
  EXPECT_EQ(terms.at(2).name, "post_prepost_mobius");
  EXPECT_EQ(variationStage(terms.at(1).name), VariationStage::Pre);
  EXPECT_EQ(variationStage(terms.at(2).name), VariationStage::Post);
  const std::vector<double> params = {0.5, 0.0, 0.0, 1.0, 0.0, 0.136, 0.0, 0.0};
  EXPECT_EQ(terms.at(1).params, params);
  EXPECT_EQ(terms.at(2).params, params);
}

// Files leave pre_stabilize's weight at 0, which JWildfire does not use; mirror_wf comes as post_mirror_wf.
TEST(FlameVariationJwildfireTail, PreStabilizeOfWeightZeroIsKept) {
  const ImportedFlame flame = importXform(
      R"(linear="1" pre_stabilize="0.0" pre_stabilize_n="20" pre_stabilize_seed="35655" pre_stabilize_p="0.5" )"
      R"(pre_stabilize_dc="0" post_mirror_wf="1.0" post_mirror_wf_yaxis="1" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 3u);
  EXPECT_EQ(terms.at(1).name, "pre_stabilize");
  EXPECT_EQ(terms.at(1).weight, 1.0);
  EXPECT_EQ(terms.at(1).params, (std::vector<double>{20.0, 35655.0, 0.5, 0.0}));
  EXPECT_EQ(terms.at(2).name, "post_mirror_wf");
  EXPECT_EQ(variationStage(terms.at(2).name), VariationStage::Post);
}

// JWildfire's rational3 names the coefficients a … h, with defaults of its own for those a file leaves out.
TEST(FlameVariationJwildfireTail, ReadsJwildfiresRational3Names) {
  const ImportedFlame flame =
      importXform(R"(rational3="0.8" rational3_a="0.5" rational3_c="0.25" rational3_h="2" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.params, (std::vector<double>{0.5, 0.0, 0.25, 1.0, 0.0, 0.9, 0.0, 2.0}));
  // At JWildfire's defaults: (0.5 ζ³ + 0.25 ζ + 1) / (0.9 ζ² + 1) · 0.8 at ζ = 0.3 − 0.7i, worked out separately.
  const std::vector<double> defaults = {0.5, 0.0, 0.25, 1.0, 0.0, 0.9, 0.0, 1.0};
  const Outputs out = run(variationOrThrow("rational3"), defaults, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_NEAR(out.x[0] - kStartX, 0.8580360698228365, 1e-12);
  EXPECT_NEAR(out.y[0] - kStartY, 0.3842775537391127, 1e-12);
}

// splits' shears and mask's shifts and scales are read from JWildfire's names; a file without them keeps the
// variation as before.
TEST(FlameVariationJwildfireTail, ReadsSplitsAndMaskExtraParameters) {
  const ImportedFlame flame = importXform(
      R"(splits="1" splits_x="0.1" splits_y="0.2" splits_lshear="0.0" splits_rshear="0.552" splits_ushear="0.428" )"
      R"(splits_dshear="0.3" mask="1.0" mask_xshift="0.2" mask_yshift="-0.3" mask_ushift="0.5" mask_xscale="1.5" )"
      R"(mask_yscale="0.7" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 2u);
  EXPECT_EQ(terms.at(0).params, (std::vector<double>{0.1, 0.2, 0.0, 0.552, 0.428, 0.3}));
  EXPECT_EQ(terms.at(1).params, (std::vector<double>{0.2, -0.3, 0.5, 1.5, 0.7}));
}

}  // namespace
