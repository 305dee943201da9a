// The variation catalogue, checked one variation at a time at points whose expected values were
// worked out from the published formulas (flam3's variations.c for the classics, JWildfire's
// variation classes for the 3D ones), independently of the code under test, in double precision:
// θ = atan2(x, y), φ = atan2(y, x), r² = x² + y², flam3's ε = 1e-10, and the pre-affine below
// (b = 0.2, c = 0.3, e = 0.8, f = −0.4) for waves, popcorn, rings and fan. Random variations are
// replayed from the lane's seed: the comment lists the uniforms Ψ that xorshift32 gives from it, in
// the order the formula draws them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame_variations.h"
#include "core/flame_variations_more.h"
#include "core/random.h"
#include "core/scene.h"

using namespace voxflame::core;

namespace {

// Row-major 3×4: a = 0.9, b = 0.2, c = 0.3 / d = −0.1, e = 0.8, f = −0.4.
constexpr double kAffine[12] = {0.9, 0.2, 0.0, 0.3, -0.1, 0.8, 0.0, -0.4, 0.0, 0.0, 1.0, 0.0};

struct PointCase {
  std::string name;
  std::vector<double> params;  // empty: the catalogue's defaults
  glm::dvec3 point;
  double weight;
  std::uint32_t seed;
  glm::dvec3 expected;  // weight · V(point)
};

// Every variation at (0.3, −0.7, 0.5) with weight 0.8 and default parameters, then second points
// where a branch, a parameter or a guard matters. At the first point r² = 0.58, r = 0.76157731,
// θ = atan2(0.3, −0.7) = 2.73670087, φ = atan2(−0.7, 0.3) = −1.16590454, sin θ = 0.3/r, cos θ = −0.7/r,
// and a 2D variation's z is 0.8 · 0.5 = 0.4. For example spherical: 0.8 · (0.3, −0.7) / 0.58 =
// (0.413793, −0.965517); eyefish: 2 · 0.8 / (r + 1) = 0.908277 times (0.3, −0.7); fisheye swaps
// those two; bubble: 0.8 / (0.58/4 + 1) = 0.698690 times (0.3, −0.7); zcone: 0.8 r = 0.609262.
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      {"linear", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, -0.5599999999999999, 0.4}},
      {"sinusoidal", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.23641616532907164, -0.5153741497901528, 0.4}},
      {"spherical", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.41379310344827586, -0.9655172413793103, 0.4}},
      {"swirl", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5999448287825543, -0.10614236862380433, 0.4}},
      {"horseshoe", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.4201805850959398, -0.4411896143507368, 0.4}},
      {"polar", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.6968951532726748, -0.19073815153088738, 0.4}},
      {"handkerchief", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.2127361403856185, -0.23968381020739876, 0.4}},
      {"heart", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.530711728099089, 0.29924080881136295, 0.4}},
      {"disc", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.4745343649529727, -0.5103724043613875, 0.4}},
      {"spiral", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.24063862992582175, -0.34646953176140327, 0.4}},
      {"hyperbolic", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.41379310339394226, -0.5600000000735317, 0.4}},
      {"diamond", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.2280787905982982, -0.5074150279421055, 0.4}},
      {"ex", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.06303114947312193, 0.011157613215112334, 0.4}},
      {"julia", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.14037357083028548, -0.6838894204384542, 0.4}},  // Ψ =
                                                                                                            // 0.879466
      {"bent", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, -0.27999999999999997, 0.4}},
      {"waves", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.08046433755424637, 0.05061490045485435, 0.4}},
      {"fisheye", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.6357938384362911, 0.27248307361555335, 0.4}},
      {"popcorn", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.4776835404872044, -0.8646843888882142, 0.4}},
      {"exponential", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.2335084144590144, -0.3213967599392771, 0.4}},
      {"power", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.660509229927258, 0.28307538425453915, 0.4}},
      {"cosine", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5902158645155812, 0.49096568515523253, 0.4}},
      {"rings", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.5401724620653459, 0.23150248374229107, 0.4}},
      {"fan", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.5882295440112207, 0.1587009878745286, 0.4}},
      {"blob", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0720998810939358, -0.1682330558858502, 0.4}},
      {"pdj", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-1.2968354387877359, -0.5122062256967207, 0.4}},
      {"fan2", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5027017073627925, -0.3442252074072051, 0.4}},
      {"rings2", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.10486456098661166, -0.2446839756354272, 0.4}},
      {"eyefish", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.27248307361555335, -0.6357938384362911, 0.4}},
      {"bubble", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.20960698689956334, -0.48908296943231444, 0.4}},
      {"cylinder", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.23641616532907164, -0.5599999999999999, 0.4}},
      {"perspective", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.1923867167833076, -0.3174218881112827, 0.4}},
      {"noise",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.09510514250399728, 0.20979372630758195, 0.4}},  // Ψ = 0.879466, 0.545326
      {"julian", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.21476054104636444, -0.7158181685849514, 0.4}},  // Ψ =
                                                                                                             // 0.879466
      {"juliascope",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.2147605410463642, -0.7158181685849514, 0.4}},  // Ψ = 0.879466
      {"blur",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.31701714167999095, -0.29970532329654564, 0.4}},  // Ψ = 0.879466, 0.545326
      {"gaussian_blur",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {-0.06527645736470766, 0.061711810454373565, 0.4}},  // Ψ = 0.879466, 0.545326, 0.394069, 0.000355, 0.947963
      {"radial_blur",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {-0.10370959450476591, 0.044617502613157445, 0.4}},  // Ψ = 0.879466, 0.545326, 0.394069, 0.000355
      {"pie",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.22814616116034042, -0.21756635356832332, 0.4}},  // Ψ = 0.879466, 0.545326, 0.394069
      {"ngon", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5478253198263984, -1.2782590795949293, 0.4}},
      {"curl", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.3229357798165137, -0.25688073394495414, 0.4}},
      {"rectangles", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5599999999999999, -0.24000000000000005, 0.4}},
      {"linear3D", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, -0.5599999999999999, 0.4}},
      {"spherical3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.28915662650602414, -0.674698795180723, 0.48192771084337355}},
      {"julia3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {-0.5688471666662185, -0.4401764648368349, 0.15740691149507838}},  // Ψ = 0.879466
      {"julia3Dz",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {-0.5777871431171079, -0.4470942583330027, 0.15988071142664936}},  // Ψ = 0.879466
      {"bubble3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.2096069868995633, -0.48908296943231433, 0.5973799126637556}},
      {"hemisphere",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.19093374820217518, -0.44551207913840873, 0.636445827340584}},
      {"cylinder3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.12878820508494873, -0.04237244129180909, -0.12175527934299901}},  // Ψ = 0.879466, 0.545326, 0.394069
      {"sinusoidal3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.23641616532907164, -0.5153741497901528, 0.12752947647663945}},
      {"swirl3D", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5550339547063007, -0.251271385404475, 0.4}},
      {"curl3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.21349464039496507, -0.527687586176222, 0.38535782591291196}},
      {"pie3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.25042350476835873, -0.1915041966034909, 0.0977476946030238}},  // Ψ = 0.879466, 0.545326, 0.394069
      {"blur3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.19442242540809745, -0.18380531587106338,
        -0.03835758906902813}},  // Ψ = 0.879466, 0.545326, 0.394069, 0.000355, 0.947963, 0.995473
      {"zblur", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0, 0.0, -0.14462723731994628}},  // Ψ = 0.879466, 0.545326,
                                                                                            // 0.394069, 0.000355
      {"zscale", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0, 0.0, 0.4}},
      {"ztranslate", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0, 0.0, 0.8}},
      {"zcone", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0, 0.0, 0.6092618484691127}},
      {"bent",
       {},
       {-0.6, 0.4, -0.2},
       0.8,
       0x2545F491u,
       {-0.96, 0.32000000000000006, -0.16000000000000003}},  // x < 0 doubles x, y ≥ 0 stays
      {"julian",
       {-3.0, 0.5},
       {1.2, 0.4, 0.1},
       0.8,
       0x2545F491u,
       {-0.31111185905540256, 0.7035545418304362, 0.08000000000000002}},  // Ψ = 0.879466
      {"juliascope",
       {5.0, 1.5},
       {-0.4, -0.9, 0.3},
       0.8,
       0x2545F491u,
       {-0.06653321309356597, -0.7935690279376223, 0.24}},  // Ψ = 0.879466
      {"juliascope",
       {2.0, 1.0},
       {0.5, 0.5, 0.0},
       0.8,
       0x2545F491u,
       {-0.621509589612015, 0.25743770116223313, 0.0}},  // Ψ = 0.879466
      {"blob", {0.2, 1.2, 6.0}, {1.5, 0.5, -1.0}, 0.8, 0x2545F491u, {1.4016000000000002, 0.4672000000000001, -0.8}},
      {"ngon",
       {6.0, 2.0, 0.5, 1.5},
       {-1.1, 0.3, 0.7},
       0.8,
       0x2545F491u,
       {-0.37554654610737886, 0.1024217853020124, 0.5599999999999999}},
      {"curl", {0.4, -0.3}, {0.8, 0.6, -0.3}, 0.8, 0x2545F491u, {0.5019607843137255, 0.40784313725490196, -0.24}},
      {"rectangles",
       {0.0, 0.35},
       {1.7, -0.9, 0.2},
       0.8,
       0x2545F491u,
       {1.36, -0.68, 0.16000000000000003}},  // x size 0: x stays linear
      {"rectangles", {0.45, 0.7}, {-1.3, 2.2, 0.4}, 0.8, 0x2545F491u, {-0.76, 2.1599999999999997, 0.32000000000000006}},
      {"fan2", {-0.8, 0.9}, {-0.2, 0.5, 0.6}, 0.8, 0x2545F491u, {0.25199888305905394, 0.34942318603233724, 0.48}},
      {"rings2",
       {1.3},
       {2.1, -1.4, 0.2},
       0.8,
       0x2545F491u,
       {-1.729063996190658, 1.152709330793772, 0.16000000000000003}},
      {"perspective",
       {-0.3, 3.0},
       {0.9, 1.5, -0.4},
       0.8,
       0x2545F491u,
       {0.5867993377125275, 0.8714033971521256, -0.32000000000000006}},
      {"pie",
       {5.0, 0.7, 0.2},
       {0.0, 0.0, 1.0},
       0.8,
       0x2545F491u,
       {0.28790969361443763, -0.12842817985184304, 0.8}},  // Ψ = 0.879466, 0.545326, 0.394069
      {"pie",
       {2.4, 0.7, 0.2},
       {0.0, 0.0, 1.0},
       0.8,
       0x2545F491u,
       {0.1588707248759932, 0.2722974143002338, 0.8}},  // Ψ = 0.879466, 0.545326, 0.394069; slices 2.4 rounds to 2
      {"julia3D",
       {-1.0},
       {0.4, -0.5, 0.6},
       0.8,
       0x2545F491u,
       {0.41558441558441567, -0.5194805194805195, 0.6233766233766235}},  // Ψ = 0.879466; power −1 is spherical3D
      {"julia3D",
       {-4.0},
       {0.4, -0.5, 0.6},
       0.8,
       0x2545F491u,
       {-0.19214410010782793, 0.8433372653987931, 0.20262355287921652}},  // Ψ = 0.879466
      {"julia3Dz",
       {2.0},
       {0.4, -0.5, 0.6},
       0.8,
       0x2545F491u,
       {-0.5769748483234353, 0.2773084484790379,
        0.5399268024832677}},  // Ψ = 0.879466; power 2: JWildfire's second z term
      {"julia3Dz",
       {-1.0},
       {0.4, -0.5, 0.6},
       0.8,
       0x2545F491u,
       {0.7804878048780488, -0.975609756097561, 1.170731707317073}},  // Ψ = 0.879466
      {"julia3Dz",
       {-5.0},
       {-0.4, 0.8, 0.6},
       0.8,
       0x2545F491u,
       {0.5400553189845502, 0.6144506213642481, 0.10975321246255831}},  // Ψ = 0.879466
      {"curl3D",
       {0.3, -0.2, 0.5},
       {0.4, 0.1, -0.6},
       0.8,
       0x2545F491u,
       {0.5073746312684366, 0.18697526662128433, -0.3040617199909235}},
      {"cylinder3D",
       {0.9, -0.1},
       {0.0, 0.0, 0.0},
       0.8,
       0x2545F491u,
       {0.21464700847491452, -0.0, -0.20292546557166496}},  // Ψ = 0.879466, 0.545326, 0.394069; sizes clamp to [0, 0.5]
      {"radial_blur",
       {0.0},
       {0.6, 0.8, 0.1},
       0.8,
       0x2545F491u,
       {-0.08677634239196774, -0.11570178985595692,
        0.08000000000000002}},  // Ψ = 0.879466, 0.545326, 0.394069, 0.000355; angle 0: a pure zoom blur
      {"exponential", {}, {-0.5, 1.25, 0.0}, 0.8, 0x2545F491u, {-0.1262214794625561, -0.12622147946255605, 0.0}},
      {"julia",
       {},
       {-0.9, -0.2, 0.3},
       0.8,
       0x0BADF00Du,
       {0.48065104039559975, -0.5991873017958345, 0.24}},  // Ψ = 0.000691; first draw < ½: Ω = 0
      {"julia3Dz",
       {2.0},
       {0.4, -0.5, 0.6},
       0.8,
       0x0BADF00Du,
       {0.5769748483234353, -0.2773084484790378, 0.5399268024832677}},  // Ψ = 0.000691; power 2, first root
      // flam3's other variations and the plugins (issue 25), from flam3's formulas worked out
      // separately (the uniforms Ψ are those above: 0.879466, 0.545326, 0.394069, 0.000355, 0.947963).
      // Parameters are set away from their defaults so that each one matters.
      {"arch", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.6418944659152602, -0.8629526954116271, 0.4}},
      {"tangent", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.30910450451020294, -0.6738307043704636, 0.4}},
      {"square", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.3035731315612793, 0.03626041412353516, 0.4}},
      {"rays", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-1.417201830025079, 0.9556700656576113, 0.4}},
      {"blade", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.3288956211839619, 0.08383120162574219, 0.4}},
      {"secant2", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, 0.1755256973087077, 0.4}},
      {"twintrian", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.06622214295129343, -0.31872414711888153, 0.4}},
      {"cross", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5999999998125002, -1.3999999995625003, 0.4}},
      {"disc2", {0.7, 1.3}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-1.0474434605209413, 1.1157167183490482, 0.4}},
      {"super_shape",
       {0.3, 5.0, 2.0, 1.5, 0.8, 0.1},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.18718376537265377, -0.4367621192028588, 0.4}},
      {"flower", {3.0, 0.2}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.20068900992839153, 0.46827435649958027, 0.4}},
      {"conic", {0.6, 0.1}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.119207591792041, -0.27815104751476233, 0.4}},
      {"parabola", {1.2, 0.7}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.402039831674239, 0.22101996398333323, 0.4}},
      {"bent2", {0.5, 1.5}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, -0.8399999999999999, 0.4}},
      {"bipolar", {0.4}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.10179901372062652, -0.7942188632621939, 0.4}},
      {"boarders", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.12, -0.68, 0.4}},
      {"butterfly", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.10008486003408527, -0.4670626801590646, 0.4}},
      {"cell", {0.4}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, -1.0400000000000003, 0.4}},
      {"cpow", {1.5, 0.3, 3.0}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.7107553595854282, -0.3320163247526321, 0.4}},
      {"curve",
       {0.4, -0.3, 0.8, 1.2},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.3888138202028981, -0.7854591350752342, 0.4}},
      {"edisc", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.11943886179623456, -0.06215828800238868, 0.4}},
      {"elliptic", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.12515028302999878, -0.27505931981614523, 0.4}},
      {"escher", {0.9}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5021582932878923, -0.8794830086989103, 0.4}},
      {"foci", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.8685184490593345, -1.8373650578180238, 0.4}},
      {"lazysusan",
       {0.5, 0.3, 0.7, 0.1, 0.2},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.4765664684741061, -0.40927898800629753, 0.4}},
      {"loonie", {}, {0.3, -0.4, 0.5}, 0.8, 0x2545F491u, {0.2997599039231232, -0.3996798718974976, 0.4}},
      {"modulus", {0.2, 0.5}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.08000000000000003, 0.24000000000000005, 0.4}},
      {"oscilloscope", {0.5, 1.2, 0.8, 0.3}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.24, -0.5599999999999999, 0.4}},
      {"polar2", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.6968951532726747, -0.06935681808642258, 0.4}},
      {"popcorn2",
       {0.2, -0.3, 2.5},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.12944765195054783, -0.7526176008671366, 0.4}},
      {"scry", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.21525644732939977, -0.5022650437685995, 0.4}},
      {"separation",
       {0.4, 0.2, 0.6, -0.3},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.35200000000000004, -0.905563556583431, 0.4}},
      {"split", {0.9, 0.8}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.24, -0.5599999999999999, 0.4}},
      {"splits", {0.25, 0.4}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.44000000000000006, -0.8800000000000001, 0.4}},
      {"stripes", {0.3, 0.6}, {0.8, -0.7, 0.5}, 0.8, 0x2545F491u, {0.6880000000000002, -0.5408, 0.4}},
      {"wedge",
       {0.4, 0.1, 3.0, 0.5},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.5548357756273146, -0.40894884501498985, 0.4}},
      {"wedge_julia",
       {0.3, 2.0, 3.0, 1.2},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {-0.5938617710618233, -0.40252285053852327, 0.4}},
      {"wedge_sph",
       {0.3, 2.0, 0.1, 0.4},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.9458910002084988, -0.6190401645573825, 0.4}},
      {"whorl", {0.4, 0.9}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.5994001922103643, 0.10917604855543309, 0.4}},
      {"waves2",
       {2.0, 0.3, 1.5, -0.2, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.003492064802769557, -0.6295944854577968, 0.4}},
      // Apophysis 7X's z part: z + scalez sin(freqz r), freqz 3, scalez 0.4.
      {"waves2",
       {2.0, 0.3, 1.5, -0.2, 3.0, 0.4},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.003492064802769557, -0.6295944854577968, 0.6418530077654515}},
      {"exp", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.8259431703293294, -0.6956823352912321, 0.4}},
      {"log", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.21789087017666886, -0.9327236324078506, 0.4}},
      // JWildfire's base 2: ln r² / (2 ln 2).
      {"log", {2.0}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.3143500778588611, -0.9327236324078506, 0.4}},
      {"sin", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.2967422431511715, -0.5797621523386283, 0.4}},
      {"cos", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.9592870008789945, 0.1793414498700343, 0.4}},
      {"tan", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.15177367321526955, -0.5118687442105441, 0.4}},
      {"sec", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.6446314201075147, -0.12051568863950857, 0.4}},
      {"csc", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.4477226304930666, 0.874741099039063, 0.4}},
      {"cot", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.3407714530859688, 1.149278738918788, 0.4}},
      {"sinh", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.18632797385010147, -0.5387404479620631, 0.4}},
      {"cosh", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.6396151964792279, -0.15694188732916897, 0.4}},
      {"tanh", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.3757641327740465, -0.581629748994816, 0.4}},
      {"sech", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.943780323999479, 0.23157465002072242, 0.4}},
      {"csch", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.3669686400682639, 1.0610368666245116, 0.4}},
      {"coth", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.5015498089910704, -0.7763281911935119, 0.4}},
      {"auger",
       {1.5, 0.6, 0.4, 0.9},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.11509105551446158, -0.31989902517060087, 0.4}},
      {"flux", {0.3}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {1.5583630628062182, -1.64408136770261, 0.4}},
      {"mobius",
       {0.9, 0.2, -0.3, 0.1, 0.4, -0.5, 1.1, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.16210907211165676, -0.40796071336262607, 0.4}},
      {"pre_blur", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.13696553822856855, 0.04644867180618399, 0.4}},
      {"unpolar", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.018684916573602748, 0.060403255671402166, 0.4}},
      {"sineblur", {1.7}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.34445218116155524, -0.3256421774802092, 0.4}},
      {"flatten", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0, 0.0, 0.0}},
      // julian2: power −5, second affine map; Ψ = 0.879466 picks root 4.
      {"julian2",
       {-5.0, 1.4, 0.9, 0.3, -0.2, 1.1, 0.15, -0.1},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.03599907988438836, 0.8099580219849262, 0.4}},
      // crop: beyond the right and top edges, back inside by Ψ · scatter · half the side; with zero to the
      // origin; inside, unchanged.
      {"crop",
       {-0.5, -0.5, 0.2, 0.6, 0.4, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.061499761581420925, -0.3040227088928223, 0.4}},
      {"crop", {-0.5, -0.5, 0.2, 0.6, 0.4, 1.0}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {0.0, 0.0, 0.4}},
      {"crop",
       {-0.5, -0.5, 0.2, 0.6, 0.4, 1.0},
       {0.1, 0.2, 0.5},
       0.8,
       0x2545F491u,
       {0.08000000000000002, 0.16000000000000003, 0.4}},
      // falloff2, types 0 (linear), 1 (radial) and 2 (Gaussian, inverted distance); Ψ as above.
      {"falloff2",
       {10.0, 0.2, 1.0, 0.5, 0.7, 0.0, 0.1, -0.2, 0.3, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.34538294670208614, -0.5273279109821959, 0.4330537910306056}},
      {"falloff2",
       {10.0, 0.2, 1.0, 0.5, 0.7, 0.0, 0.1, -0.2, 0.3, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.2615860635226088, -0.5474781491390402, 0.49876962846656103}},
      {"falloff2",
       {10.0, 0.1, 1.0, 0.5, 0.7, 0.0, 0.25, -0.2, 0.3, 1.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.2707962896356701, -0.5561316410598042, 0.4226076463570449}},
      {"epispiral",
       {6.0, 0.5, 0.3},
       {0.3, -0.7, 0.5},
       0.8,
       0x2545F491u,
       {0.08854269932758177, -0.20659963176435747, 0.4}},
      // glynnia: Ψ = 0.879466 > ½ takes the square-root branch; inside the unit circle it is mirrored.
      {"glynnia", {}, {0.3, -0.7, 0.5}, 0.8, 0x2545F491u, {-0.5828419506072339, 0.3843237429403043, 0.4}},
      {"glynnia", {}, {1.2, 0.5, 0.5}, 0.8, 0x2545F491u, {0.8944271909999161, -0.1788854381999832, 0.4}},
  };
  return cases;
}

// gtest names a failing case by this instead of dumping its bytes.
[[maybe_unused]] void PrintTo(const PointCase& c, std::ostream* os) {
  *os << c.name;
}

std::string caseLabel(const testing::TestParamInfo<PointCase>& info) {
  return info.param.name + "_" + std::to_string(info.index);
}

// Runs `info` over `lanes` copies of one point, each lane seeded alike, adding to a non-zero start
// so that a variation that assigns instead of adding is caught; returns the outputs.
struct Outputs {
  std::vector<double> x, y, z;
  std::vector<std::uint32_t> random;
};
constexpr double kStartX = 0.125, kStartY = -0.25, kStartZ = 0.5;

Outputs run(const VariationInfo& info, const std::vector<double>& params, glm::dvec3 p, double weight,
            std::uint32_t seed, std::size_t lanes) {
  std::vector<double> xs(lanes, p.x), ys(lanes, p.y), zs(lanes, p.z);
  Outputs out{std::vector<double>(lanes, kStartX), std::vector<double>(lanes, kStartY),
              std::vector<double>(lanes, kStartZ), std::vector<std::uint32_t>(lanes, seed)};
  VariationInput in;
  in.x = xs.data();
  in.y = ys.data();
  in.z = zs.data();
  in.random = out.random.data();
  in.count = lanes;
  in.weight = weight;
  in.params = params.data();
  in.affine = kAffine;
  info.apply(in, out.x.data(), out.y.data(), out.z.data());
  return out;
}

class VariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(VariationAtPoint, MatchesTheHandComputedValue) {
  const PointCase& c = GetParam();
  const VariationInfo& info = variationOrThrow(c.name);
  const std::vector<double> params = c.params.empty() ? info.defaultParams() : c.params;
  ASSERT_EQ(params.size(), info.params.size());
  // 37 lanes: a vectorised body and a scalar remainder must agree lane for lane.
  const Outputs out = run(info, params, c.point, c.weight, c.seed, 37);
  const auto near = [](double expected) { return 1e-12 * std::max(1.0, std::abs(expected)); };
  for (std::size_t lane = 0; lane < out.x.size(); ++lane) {
    SCOPED_TRACE("lane " + std::to_string(lane));
    EXPECT_NEAR(out.x[lane] - kStartX, c.expected.x, near(c.expected.x));
    EXPECT_NEAR(out.y[lane] - kStartY, c.expected.y, near(c.expected.y));
    EXPECT_NEAR(out.z[lane] - kStartZ, c.expected.z, near(c.expected.z));
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, VariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

TEST(VariationCatalogue, EveryVariationHasAHandCheckedPoint) {
  std::set<std::string> checked;
  for (const PointCase& c : pointCases()) {
    EXPECT_NE(findVariation(c.name), nullptr) << c.name << " is in the table but not in the catalogue";
    checked.insert(c.name);
  }
  // flame_variations_more_test.cpp checks the entries of flame_variations_more.cpp.
  std::vector<VariationInfo> more;
  addMoreVariations(more);
  for (const VariationInfo& info : more) checked.insert(info.name);
  for (const VariationInfo& info : variationCatalogue())
    EXPECT_TRUE(checked.count(info.name)) << info.name << " has no hand-checked point in pointCases()";
}

TEST(VariationCatalogue, HasTheClassicsAndThe3DSet) {
  for (const char* name :
       {"linear",        "sinusoidal",  "spherical",   "swirl",      "horseshoe",   "polar",      "handkerchief",
        "heart",         "disc",        "spiral",      "hyperbolic", "diamond",     "ex",         "julia",
        "bent",          "waves",       "fisheye",     "popcorn",    "exponential", "power",      "cosine",
        "rings",         "fan",         "blob",        "pdj",        "fan2",        "rings2",     "eyefish",
        "bubble",        "cylinder",    "perspective", "noise",      "julian",      "juliascope", "blur",
        "gaussian_blur", "radial_blur", "pie",         "ngon",       "curl",        "rectangles", "linear3D",
        "spherical3D",   "julia3D",     "julia3Dz",    "bubble3D",   "hemisphere",  "cylinder3D", "sinusoidal3D",
        "swirl3D",       "curl3D",      "pie3D",       "blur3D",     "zblur",       "zscale",     "ztranslate",
        "zcone"})
    EXPECT_NE(findVariation(name), nullptr) << name;
  EXPECT_GE(variationCatalogue().size(), 40u);
}

// flam3 3.1's 99 variations (issue 25), by the names flame files use.
TEST(VariationCatalogue, HasAllOfFlam3sVariations) {
  const std::vector<std::string> flam3 = {
      "linear",        "sinusoidal",  "spherical",   "swirl",      "horseshoe",   "polar",      "handkerchief",
      "heart",         "disc",        "spiral",      "hyperbolic", "diamond",     "ex",         "julia",
      "bent",          "waves",       "fisheye",     "popcorn",    "exponential", "power",      "cosine",
      "rings",         "fan",         "blob",        "pdj",        "fan2",        "rings2",     "eyefish",
      "bubble",        "cylinder",    "perspective", "noise",      "julian",      "juliascope", "blur",
      "gaussian_blur", "radial_blur", "pie",         "ngon",       "curl",        "rectangles", "arch",
      "tangent",       "square",      "rays",        "blade",      "secant2",     "twintrian",  "cross",
      "disc2",         "super_shape", "flower",      "conic",      "parabola",    "bent2",      "bipolar",
      "boarders",      "butterfly",   "cell",        "cpow",       "curve",       "edisc",      "elliptic",
      "escher",        "foci",        "lazysusan",   "loonie",     "pre_blur",    "modulus",    "oscilloscope",
      "polar2",        "popcorn2",    "scry",        "separation", "split",       "splits",     "stripes",
      "wedge",         "wedge_julia", "wedge_sph",   "whorl",      "waves2",      "exp",        "log",
      "sin",           "cos",         "tan",         "sec",        "csc",         "cot",        "sinh",
      "cosh",          "tanh",        "sech",        "csch",       "coth",        "auger",      "flux",
      "mobius"};
  EXPECT_EQ(flam3.size(), 99u);
  for (const std::string& name : flam3) {
    const VariationInfo* info = findVariation(name);
    ASSERT_NE(info, nullptr) << name;
    EXPECT_EQ(info->name, name);  // its own entry, not a pre_ form
  }
  // Every variation has pre_ and post_ forms sharing its entry.
  EXPECT_EQ(findVariation("pre_spherical"), findVariation("spherical"));
  EXPECT_EQ(findVariation("post_mobius"), findVariation("mobius"));
  EXPECT_EQ(variationStage("pre_spherical"), VariationStage::Pre);
  EXPECT_EQ(variationStage("post_spherical"), VariationStage::Post);
  EXPECT_EQ(variationStage("pre_blur"), VariationStage::Pre);  // flam3's own, applied first
  EXPECT_EQ(findVariation("pre_blur")->name, "pre_blur");
  EXPECT_EQ(variationStage("spherical"), VariationStage::Normal);
  EXPECT_EQ(findVariation("pre_nothing"), nullptr);
  // A variation whose result ignores the point adds in its pre_/post_ form; the others replace.
  EXPECT_TRUE(findVariation("gaussian_blur")->additive);
  EXPECT_TRUE(findVariation("ztranslate")->additive);
  EXPECT_FALSE(findVariation("spherical")->additive);
  EXPECT_FALSE(findVariation("radial_blur")->additive);
}

TEST(VariationCatalogue, NamesAndParametersAreUniqueAndUsable) {
  std::set<std::string> names;
  for (const VariationInfo& info : variationCatalogue()) {
    SCOPED_TRACE(info.name);
    EXPECT_TRUE(names.insert(info.name).second) << "duplicate variation name";
    EXPECT_FALSE(info.formula.empty());
    EXPECT_NE(info.apply, nullptr);
    std::set<std::string> params;
    for (const VariationParam& p : info.params) {
      EXPECT_TRUE(params.insert(p.name).second) << "duplicate parameter " << p.name;
      // A preset writes parameters beside "name" and "weight" in the same object.
      EXPECT_NE(p.name, "name");
      EXPECT_NE(p.name, "weight");
      EXPECT_LT(p.sliderMin, p.sliderMax) << p.name;
      EXPECT_GE(p.defaultValue, p.sliderMin) << p.name;
      EXPECT_LE(p.defaultValue, p.sliderMax) << p.name;
      if (p.integer) {
        EXPECT_EQ(p.defaultValue, std::round(p.defaultValue)) << p.name;
      }
      EXPECT_EQ(info.paramIndex(p.name), static_cast<int>(&p - info.params.data()));
    }
    EXPECT_EQ(info.paramIndex("no_such_parameter"), -1);
    EXPECT_EQ(info.defaultParams().size(), info.params.size());
  }
}

TEST(VariationCatalogue, RandomFlagMatchesWhetherTheLaneGeneratorAdvances) {
  for (const VariationInfo& info : variationCatalogue()) {
    const Outputs out = run(info, info.defaultParams(), {0.3, -0.7, 0.5}, 1.0, 0x2545F491u, 3);
    EXPECT_EQ(out.random[0] != 0x2545F491u, info.random) << info.name;
  }
}

TEST(VariationCatalogue, UnknownNamesSuggestCloseOnes) {
  const auto messageOf = [](const std::string& name) {
    try {
      variationOrThrow(name);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(messageOf("Julia3d").find("julia3D"), std::string::npos) << messageOf("Julia3d");
  EXPECT_NE(messageOf("julain").find("julian"), std::string::npos) << messageOf("julain");
  EXPECT_NE(messageOf("bnet").find("bent"), std::string::npos) << messageOf("bnet");
  EXPECT_NE(messageOf("spherical_3d").find("spherical3D"), std::string::npos) << messageOf("spherical_3d");
  const std::string unknown = messageOf("xyzzy");
  EXPECT_NE(unknown.find("'xyzzy' is not a known variation"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("voxflame list --variations"), std::string::npos) << unknown;
  EXPECT_EQ(messageOf("").find("did you mean"), std::string::npos);
}

// Points and parameters that break naive formulas: the origin, signed zeros, ±1, huge values
// (whose squares overflow), NaN, infinities and denormals. Nothing may trap or hit undefined
// behaviour (the sanitizer build runs this), lane generators must stay usable (never 0), and the
// lanes around an odd one must not be disturbed.
TEST(VariationCatalogue, OddInputsNeverTrapOrDisturbOtherLanes) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double denormal = std::numeric_limits<double>::denorm_min();
  const std::vector<double> values = {0.0, -0.0, 1.0,      -1.0,      1e300,  -1e300, nan,
                                      inf, -inf, denormal, -denormal, 1e-310, 0.5};
  std::vector<double> xs, ys, zs;
  for (double a : values)
    for (double b : values) {
      xs.push_back(a);
      ys.push_back(b);
      zs.push_back(a == b ? -b : b);
    }
  // A well-behaved lane after every odd one: its result must equal a run of that lane alone.
  const std::size_t oddCount = xs.size();
  for (std::size_t i = 0; i < oddCount; ++i) {
    xs.insert(xs.begin() + static_cast<std::ptrdiff_t>(2 * i + 1), 0.3);
    ys.insert(ys.begin() + static_cast<std::ptrdiff_t>(2 * i + 1), -0.7);
    zs.insert(zs.begin() + static_cast<std::ptrdiff_t>(2 * i + 1), 0.5);
  }
  const std::size_t lanes = xs.size();
  for (const VariationInfo& info : variationCatalogue()) {
    SCOPED_TRACE(info.name);
    std::vector<std::vector<double>> paramSets = {info.defaultParams()};
    // Parameters at the limits a preset may give (±1e6) and at 0, where counts and divisors break.
    for (double extreme : {0.0, 1e6, -1e6, 0.49, -2.5}) paramSets.emplace_back(info.params.size(), extreme);
    for (const std::vector<double>& params : paramSets) {
      std::vector<double> ox(lanes, 0.0), oy(lanes, 0.0), oz(lanes, 0.0);
      std::vector<std::uint32_t> random(lanes);
      for (std::size_t i = 0; i < lanes; ++i) random[i] = 0x9E3779B9u ^ static_cast<std::uint32_t>(i * 7919u + 1u);
      const std::vector<std::uint32_t> seeds = random;
      VariationInput in;
      in.x = xs.data();
      in.y = ys.data();
      in.z = zs.data();
      in.random = random.data();
      in.count = lanes;
      in.weight = 0.7;
      in.params = params.data();
      in.affine = kAffine;
      info.apply(in, ox.data(), oy.data(), oz.data());
      for (std::size_t i = 0; i < lanes; ++i) EXPECT_NE(random[i], 0u) << "lane " << i;
      for (std::size_t i = 1; i < lanes; i += 2) {
        const Outputs alone = run(info, params, {0.3, -0.7, 0.5}, 0.7, seeds[i], 1);
        // `alone` started from kStart: compare what each added, to rounding.
        const auto same = [](double added, double withStart, double start) {
          const double expected = withStart - start;
          return (std::isnan(added) && std::isnan(expected)) || added == expected ||
                 std::abs(added - expected) <= 1e-12 * std::max(1.0, std::abs(expected));
        };
        EXPECT_TRUE(same(ox[i], alone.x[0], kStartX) && same(oy[i], alone.y[0], kStartY) &&
                    same(oz[i], alone.z[0], kStartZ))
            << "lane " << i << " beside odd input (" << xs[i - 1] << ", " << ys[i - 1] << ", " << zs[i - 1] << ")";
      }
    }
  }
}

// Ordinary points (inside the unit cube, away from the origin) give finite results for every
// variation at its default parameters: no variation is NaN by construction.
TEST(VariationCatalogue, DefaultsGiveFiniteResultsInTheUnitCube) {
  std::uint32_t state = 12345u;
  const std::size_t lanes = 4096;
  std::vector<double> xs(lanes), ys(lanes), zs(lanes);
  for (std::size_t i = 0; i < lanes; ++i) {
    xs[i] = 2.0 * laneUniform(state) - 1.0;
    ys[i] = 2.0 * laneUniform(state) - 1.0;
    zs[i] = 2.0 * laneUniform(state) - 1.0;
    if (std::abs(xs[i]) + std::abs(ys[i]) < 1e-3) xs[i] = 0.5;
  }
  for (const VariationInfo& info : variationCatalogue()) {
    std::vector<double> ox(lanes, 0.0), oy(lanes, 0.0), oz(lanes, 0.0);
    std::vector<std::uint32_t> random(lanes, 77u);
    const std::vector<double> params = info.defaultParams();
    VariationInput in;
    in.x = xs.data();
    in.y = ys.data();
    in.z = zs.data();
    in.random = random.data();
    in.count = lanes;
    in.weight = 1.0;
    in.params = params.data();
    in.affine = kAffine;
    info.apply(in, ox.data(), oy.data(), oz.data());
    std::size_t bad = 0;
    for (std::size_t i = 0; i < lanes; ++i)
      if (!std::isfinite(ox[i]) || !std::isfinite(oy[i]) || !std::isfinite(oz[i])) ++bad;
    EXPECT_EQ(bad, 0u) << info.name;
  }
}

// Runs a flame layer whose transforms (and final transform) use `name` at `weight` through the
// chaos game the way the accumulator does: a lane whose drawn point is not finite (NaN is the
// game's escape signal; a final transform may also overflow) starts again from a fresh seed.
struct ChaosRun {
  double finiteShare = 0.0;      // of all drawn points
  bool statesStayUsable = true;  // after each step's reseeding: every lane finite, generator ≠ 0
};

ChaosRun runInTheChaosGame(const std::string& name, double weight) {
  const VariationInfo& info = variationOrThrow(name);
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  FlameXform a, b;
  a.affine.m = {0.5, -0.2, 0.0, 0.3, 0.2, 0.5, 0.0, 0.1, 0.0, 0.0, 0.5, -0.2};
  a.variations = {{name, weight, info.defaultParams()}};
  a.color = 0.0;
  b.affine.m = {0.4, 0.1, 0.1, -0.4, -0.1, 0.4, 0.0, 0.2, 0.0, 0.1, 0.4, 0.3};
  b.variations = {{name, 0.5 * weight, info.defaultParams()}, {"linear3D", 0.5, {}}};
  b.color = 1.0;
  layer.flame.xforms = {a, b};
  layer.flame.hasFinal = true;
  layer.flame.finalXform.variations = {{name, 0.3 * weight, info.defaultParams()}, {"linear3D", 0.7, {}}};
  const ChaosGame game(layer, "layers[0]");
  constexpr std::size_t kLanes = 128;
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(7);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> x(kLanes), y(kLanes), z(kLanes), color(kLanes);
  std::size_t finite = 0, drawn = 0;
  ChaosRun run;
  for (int step = 0; step < 200; ++step) {
    game.step(lanes, x.data(), y.data(), z.data(), color.data(), kLanes);
    for (std::size_t i = 0; i < kLanes; ++i) {
      ++drawn;
      if (std::isfinite(x[i]) && std::isfinite(y[i]) && std::isfinite(z[i]))
        ++finite;
      else
        game.seedLane(lanes, i, rng);
      run.statesStayUsable = run.statesStayUsable && std::isfinite(lanes.x[i]) && std::isfinite(lanes.y[i]) &&
                             std::isfinite(lanes.z[i]) && lanes.random[i] != 0u;
    }
  }
  run.finiteShare = static_cast<double>(finite) / static_cast<double>(drawn);
  return run;
}

// At its defaults every variation draws points; at weight 1e6 most overflow or turn NaN, and
// reseeding keeps every lane usable: the game never sticks on a bad state.
TEST(VariationCatalogue, EveryVariationRunsInTheChaosGameAndEscapesReseed) {
  for (const VariationInfo& info : variationCatalogue()) {
    const ChaosRun normal = runInTheChaosGame(info.name, 1.0);
    EXPECT_GT(normal.finiteShare, 0.5) << info.name;
    EXPECT_TRUE(normal.statesStayUsable) << info.name;
    const ChaosRun wild = runInTheChaosGame(info.name, 1e6);
    EXPECT_TRUE(wild.statesStayUsable) << info.name << " at weight 1e6";
  }
}

TEST(VariationCatalogue, CommittedMarkdownMatchesTheCatalogue) {
  std::ifstream file(std::string(VOXFLAME_SOURCE_DIR) + "/presets/VARIATIONS.md", std::ios::binary);
  ASSERT_TRUE(file) << "presets/VARIATIONS.md is missing";
  std::ostringstream text;
  text << file.rdbuf();
  EXPECT_TRUE(text.str() == variationsMarkdown()) << "presets/VARIATIONS.md is out of date: regenerate it with "
                                                     "`voxflame list --variations --markdown > presets/VARIATIONS.md`";
}

}  // namespace
