// The chaos game behind flame and quaternion Julia layers, and their place in the preset schema.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/chaos_game.h"
#include "core/error.h"
#include "core/flame/flame.h"
#include "core/scene.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::presetErrorOf;

namespace {

constexpr std::size_t kLanes = 256;

Affine3 affine(std::array<double, 12> m) {
  Affine3 a;
  a.m = m;
  return a;
}

FlameXform xform(double weight, Affine3 map, double color = 0.0, double colorSpeed = 0.5) {
  FlameXform x;
  x.weight = weight;
  x.affine = map;
  x.variations = {{"linear", 1.0, {}}};
  x.color = color;
  x.colorSpeed = colorSpeed;
  return x;
}

PatternLayer flameLayer(FlameGenome genome) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = std::move(genome);
  layer.color.mode = ColorMode::Index;
  return layer;
}

// The four half-way maps towards the corners of a regular tetrahedron: Sierpiński's.
FlameGenome sierpinskiTetrahedron() {
  FlameGenome g;
  const glm::dvec3 corners[] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 c = corners[i];
    g.xforms.push_back(xform(1.0, affine({0.5, 0, 0, 0.5 * c.x, 0, 0.5, 0, 0.5 * c.y, 0, 0, 0.5, 0.5 * c.z}), i / 3.0));
  }
  return g;
}

struct LaneRun {
  ChaosLanes lanes;
  std::vector<double> x, y, z, color;
  explicit LaneRun(const ChaosGame& game, std::uint64_t seed = 3) : x(kLanes), y(kLanes), z(kLanes), color(kLanes) {
    lanes.resize(kLanes);
    SplitMix64 rng(seed);
    for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  }
  void step(const ChaosGame& game) { game.step(lanes, x.data(), y.data(), z.data(), color.data(), kLanes); }
};

}  // namespace

TEST(ChaosGame, LanesDrawTheirOwnTransformsAndNeverConverge) {
  // All lanes start at one point; were they to share each step's draw they would stay one point.
  const ChaosGame game(flameLayer(sierpinskiTetrahedron()), "test");
  LaneRun run(game);
  for (std::size_t i = 0; i < kLanes; ++i) run.lanes.x[i] = run.lanes.y[i] = run.lanes.z[i] = 0.0;
  for (int s = 0; s < 40; ++s) run.step(game);
  std::set<std::tuple<double, double, double>> distinct;
  for (std::size_t i = 0; i < kLanes; ++i) distinct.insert({run.x[i], run.y[i], run.z[i]});
  EXPECT_GT(distinct.size(), kLanes * 9 / 10);
}

TEST(ChaosGame, SierpinskiPointsStayInTheTetrahedronAndReachEveryCorner) {
  const ChaosGame game(flameLayer(sierpinskiTetrahedron()), "test");
  LaneRun run(game);
  const glm::dvec3 corners[] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  int nearCorner[4] = {0, 0, 0, 0};
  for (int s = 0; s < 200; ++s) {
    run.step(game);
    if (s < 30) continue;
    for (std::size_t i = 0; i < kLanes; ++i) {
      const glm::dvec3 p(run.x[i], run.y[i], run.z[i]);
      // Inside the tetrahedron: on the inner side of each face plane (x + y + z ≥ -1 etc.).
      EXPECT_LE(-p.x - p.y - p.z, 1.0 + 1e-9);
      EXPECT_LE(-p.x + p.y + p.z, 1.0 + 1e-9);
      EXPECT_LE(p.x - p.y + p.z, 1.0 + 1e-9);
      EXPECT_LE(p.x + p.y - p.z, 1.0 + 1e-9);
      for (int c = 0; c < 4; ++c) nearCorner[c] += glm::length(p - corners[c]) < 0.3 ? 1 : 0;
    }
  }
  for (int c = 0; c < 4; ++c) EXPECT_GT(nearCorner[c], 500) << "corner " << c;
}

TEST(ChaosGame, TransformsAreChosenInProportionToTheirWeights) {
  // Colour speed 1: a point's colour is the colour of the transform that made it.
  FlameGenome g;
  g.xforms = {xform(3.0, affine({0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0}), 0.0, 1.0),
              xform(1.0, affine({0.5, 0, 0, 0.5, 0, 0.5, 0, 0, 0, 0, 0.5, 0}), 1.0, 1.0)};
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  std::size_t second = 0, total = 0;
  for (int s = 0; s < 400; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) second += run.color[i] > 0.5 ? 1 : 0;
    total += kLanes;
  }
  EXPECT_NEAR(static_cast<double>(second) / static_cast<double>(total), 0.25, 0.01);
}

TEST(ChaosGame, ColourMovesTowardsTheTransformColourByItsSpeed) {
  FlameGenome g;
  g.xforms = {xform(1.0, affine({0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0}), 1.0, 0.25)};
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  const std::vector<double> start = run.lanes.color;
  for (int s = 1; s <= 5; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < 8; ++i)
      EXPECT_NEAR(run.color[i], 1.0 - std::pow(0.75, s) * (1.0 - start[i]), 1e-12);  // flam3's blend
  }
}

TEST(ChaosGame, OpacityHidesThePointsOfItsTransform) {
  FlameGenome g;
  g.xforms = {xform(1.0, affine({0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0}), 0.0, 1.0),
              xform(1.0, affine({0.5, 0, 0, 0.5, 0, 0.5, 0, 0, 0, 0, 0.5, 0}), 1.0, 1.0)};
  g.xforms[1].opacity = 0.0;
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  std::size_t shown = 0;
  for (int s = 0; s < 50; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      EXPECT_EQ(run.lanes.visible[i], run.color[i] < 0.5 ? 1 : 0);
      shown += static_cast<std::size_t>(run.lanes.visible[i]);
    }
  }
  EXPECT_GT(shown, 50u * kLanes / 3);
}

TEST(ChaosGame, TheFinalTransformBendsWhatIsDrawnButNeverFeedsBack) {
  FlameGenome g = sierpinskiTetrahedron();
  g.hasFinal = true;
  g.finalXform = xform(1.0, affine({1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0}), 0.0, 0.0);
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  for (int s = 0; s < 30; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      EXPECT_NEAR(run.x[i], run.lanes.x[i] + 10.0, 1e-12);
      EXPECT_LE(std::abs(run.lanes.x[i]), 1.0 + 1e-9 + (s < 5 ? 1.0 : 0.0));  // the state stays in the tetrahedron
    }
  }
}

TEST(ChaosGame, RotationalAndMirrorSymmetryMakeTheAttractorSymmetric) {
  // One transform that pulls towards (1, 0, 0): a blob on the +x side. Four-fold symmetry about z
  // copies it to the four sides; the mirror across a plane through the axis needs no more copies.
  FlameGenome g;
  g.xforms = {xform(1.0, affine({0.3, 0, 0, 0.7, 0, 0.3, 0, 0.2, 0, 0, 0.3, 0}))};
  g.symmetry.rotational = 4;
  g.symmetry.mirror = true;
  EXPECT_EQ(expandSymmetry(g).size(), 5u);
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  std::array<double, 4> quadrant{};
  std::size_t above = 0, below = 0;
  for (int s = 0; s < 600; ++s) {
    run.step(game);
    if (s < 30) continue;
    for (std::size_t i = 0; i < kLanes; ++i) {
      const double angle = std::atan2(run.y[i], run.x[i]) + std::numbers::pi / 4.0;
      const int q =
          static_cast<int>(std::floor((angle < 0 ? angle + 2 * std::numbers::pi : angle) / (std::numbers::pi / 2.0))) %
          4;
      quadrant[static_cast<std::size_t>(q)] += 1.0;
      // The mirror (normal x) turns the blob's +y offset into -y on the +x side.
      if (std::abs(run.x[i]) > std::abs(run.y[i])) (run.y[i] * run.x[i] > 0 ? above : below) += 1;
    }
  }
  const double total = quadrant[0] + quadrant[1] + quadrant[2] + quadrant[3];
  for (double q : quadrant) EXPECT_NEAR(q / total, 0.25, 0.02);
  EXPECT_NEAR(static_cast<double>(above) / static_cast<double>(above + below), 0.5, 0.03);
}

TEST(ChaosGame, AnEscapingStateIsReportedAsNaNSoTheLaneIsReseeded) {
  // Spherical near the origin throws points beyond flam3's 1e10 limit.
  FlameGenome g;
  g.xforms = {xform(1.0, affine({1e-12, 0, 0, 0, 0, 1e-12, 0, 0, 0, 0, 1, 0}))};
  g.xforms[0].variations = {{"spherical", 1.0, {}}};
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  run.step(game);
  std::size_t nan = 0;
  for (std::size_t i = 0; i < kLanes; ++i) nan += std::isnan(run.x[i]) ? 1 : 0;
  EXPECT_GT(nan, kLanes / 2);
}

TEST(ChaosGame, QuaternionJuliaStepsAreSquareRootsOfTheLastPointMinusC) {
  PatternLayer layer;
  layer.kind = PatternKind::QuaternionJulia;
  layer.julia.c = {-0.2, 0.6, 0.2, 0.1};
  const ChaosGame game(layer, "test");
  LaneRun run(game);
  std::set<int> signs;
  for (int s = 0; s < 20; ++s) {
    const std::vector<double> a = run.lanes.x, b = run.lanes.y, c = run.lanes.z, d = run.lanes.w;
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      // q² for q = (r, v): (r² − |v|², 2 r v); it must give back the old point minus c.
      const double r = run.lanes.x[i], vx = run.lanes.y[i], vy = run.lanes.z[i], vz = run.lanes.w[i];
      EXPECT_NEAR(r * r - vx * vx - vy * vy - vz * vz, a[i] - layer.julia.c.x, 1e-9);
      EXPECT_NEAR(2 * r * vx, b[i] - layer.julia.c.y, 1e-9);
      EXPECT_NEAR(2 * r * vy, c[i] - layer.julia.c.z, 1e-9);
      EXPECT_NEAR(2 * r * vz, d[i] - layer.julia.c.w, 1e-9);
      signs.insert(r >= 0 ? 1 : -1);
    }
  }
  EXPECT_EQ(signs.size(), 2u);  // both roots are taken
}

TEST(ChaosGame, AQuaternionSliceShowsOnlyPointsNearItsHyperplane) {
  PatternLayer layer;
  layer.kind = PatternKind::QuaternionJulia;
  layer.julia.c = {-0.2, 0.6, 0.2, 0.1};
  layer.julia.view = QuaternionView::Slice;
  layer.julia.sliceW = 0.05;
  layer.julia.thickness = 0.1;
  const ChaosGame game(layer, "test");
  LaneRun run(game);
  std::size_t shown = 0;
  for (int s = 0; s < 40; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      EXPECT_EQ(run.lanes.visible[i], std::abs(run.lanes.w[i] - 0.05) < 0.1 ? 1 : 0);
      shown += static_cast<std::size_t>(run.lanes.visible[i]);
    }
  }
  EXPECT_GT(shown, 0u);
}

TEST(ChaosGame, BadGenomesAreRefusedWithClearMessages) {
  const auto messageOf = [](FlameGenome g) {
    try {
      ChaosGame game(flameLayer(std::move(g)), "layers[0]");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(messageOf({}).find("without transforms"), std::string::npos);
  FlameGenome zero = sierpinskiTetrahedron();
  for (auto& x : zero.xforms) x.weight = 0.0;
  EXPECT_NE(messageOf(zero).find("weight 0"), std::string::npos);
  FlameGenome nan = sierpinskiTetrahedron();
  nan.xforms[2].affine.m[5] = std::nan("");
  EXPECT_NE(messageOf(nan).find("transform 2"), std::string::npos);
  FlameGenome huge = sierpinskiTetrahedron();
  huge.xforms[1].affine.m[0] = 1e300;
  EXPECT_NE(messageOf(huge).find("beyond"), std::string::npos);
  FlameGenome unknown = sierpinskiTetrahedron();
  unknown.xforms[0].variations = {{"sphericle", 1.0, {}}};
  EXPECT_NE(messageOf(unknown).find("spherical"), std::string::npos);  // suggests the close name
  FlameGenome tooMany = sierpinskiTetrahedron();
  while (tooMany.xforms.size() <= kMaxFlameXforms) tooMany.xforms.push_back(tooMany.xforms.front());
  EXPECT_NE(messageOf(tooMany).find("1 to 128"), std::string::npos);
}

// JWildfire's post symmetry, its maps worked out from its PointSymmetryProjector and
// X/YAxisSymmetryProjector by hand: a point is drawn itself and turned by −k · 360°/order (k from 0,
// so itself twice); an axis symmetry draws it moved by distance/2 and turned by −rotation, and its
// mirror image moved the other way and turned by +rotation.
TEST(ChaosGame, PostSymmetryMapsAreJwildfires) {
  const auto at = [](const Affine3& map, double x, double y) { return map.apply({x, y, 0.5}); };
  FlamePostSymmetry post;
  EXPECT_TRUE(postSymmetryMaps(post).empty());
  post.kind = PostSymmetryKind::Point;
  post.order = 1;
  EXPECT_TRUE(postSymmetryMaps(post).empty());
  post.order = 3;
  post.centerX = 1.0;
  post.centerY = 2.0;
  std::vector<Affine3> maps = postSymmetryMaps(post);
  ASSERT_EQ(maps.size(), 4u);
  EXPECT_TRUE(maps[0].isIdentity());
  glm::dvec3 p = at(maps[1], 3.0, 2.0);  // 2 to the right of the centre
  EXPECT_NEAR(p.x, 3.0, 1e-12);
  EXPECT_NEAR(p.y, 2.0, 1e-12);
  p = at(maps[2], 3.0, 2.0);  // turned by −120°
  EXPECT_NEAR(p.x, 1.0 + 2.0 * std::cos(-2.0 * std::numbers::pi / 3.0), 1e-12);
  EXPECT_NEAR(p.y, 2.0 + 2.0 * std::sin(-2.0 * std::numbers::pi / 3.0), 1e-12);
  EXPECT_DOUBLE_EQ(p.z, 0.5);
  p = at(maps[3], 3.0, 2.0);  // −240°
  EXPECT_NEAR(p.x, 1.0 - 1.0, 1e-12);
  EXPECT_NEAR(p.y, 2.0 + std::sqrt(3.0), 1e-12);
  post = {};
  post.kind = PostSymmetryKind::XAxis;
  post.centerX = 1.0;
  post.distance = 0.5;
  post.rotationDeg = 90.0;
  maps = postSymmetryMaps(post);
  ASSERT_EQ(maps.size(), 2u);
  // (2, 1) is (1, 1) from the centre: moved to (1.25, 1), turned by −90° → (1, −1.25); its mirror
  // image (−1, 1), moved to (−1.25, 1), turned by +90° → (−1, −1.25).
  p = at(maps[0], 2.0, 1.0);
  EXPECT_NEAR(p.x, 2.0, 1e-12);
  EXPECT_NEAR(p.y, -1.25, 1e-12);
  p = at(maps[1], 2.0, 1.0);
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, -1.25, 1e-12);
  post.kind = PostSymmetryKind::YAxis;
  post.rotationDeg = 0.0;
  maps = postSymmetryMaps(post);
  ASSERT_EQ(maps.size(), 2u);
  p = at(maps[0], 2.0, 1.0);  // (1, 1) from the centre, moved up by 0.25
  EXPECT_NEAR(p.x, 2.0, 1e-12);
  EXPECT_NEAR(p.y, 1.25, 1e-12);
  p = at(maps[1], 2.0, 1.0);  // mirrored across y = 0, moved down by 0.25
  EXPECT_NEAR(p.x, 2.0, 1e-12);
  EXPECT_NEAR(p.y, -1.25, 1e-12);
}

// The chaos game draws each point through one of the post symmetry's maps: a flame that draws only
// (1, 0) with a 3-fold point symmetry draws (1, 0) half the time (JWildfire draws it twice) and
// each of its two turns a quarter of the time; the iteration itself is left alone.
TEST(ChaosGame, PostSymmetryDrawsEachPointThroughOneOfItsImages) {
  FlameGenome g;
  g.xforms = {xform(1.0, affine({0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0}))};
  g.postSymmetry.kind = PostSymmetryKind::Point;
  const ChaosGame game(flameLayer(g), "test");
  LaneRun run(game);
  std::array<double, 3> images{};
  for (int s = 0; s < 200; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      EXPECT_NEAR(std::hypot(run.x[i], run.y[i]), 1.0, 1e-12);
      const double turns = std::atan2(-run.y[i], run.x[i]) / (2.0 * std::numbers::pi / 3.0);
      const long k = std::lround(turns < -0.1 ? turns + 3.0 : turns);
      ASSERT_LT(std::abs(turns - std::round(turns)), 1e-9);
      images[static_cast<std::size_t>(k % 3)] += 1.0;
    }
    EXPECT_EQ(run.lanes.x[0], 1.0);  // the state is not turned
  }
  const double total = images[0] + images[1] + images[2];
  EXPECT_NEAR(images[0] / total, 0.5, 0.01);
  EXPECT_NEAR(images[1] / total, 0.25, 0.01);
  EXPECT_NEAR(images[2] / total, 0.25, 0.01);
}

TEST(FlamePreset, FlameAndQuaternionLayersRoundTripThroughJson) {
  Scene scene;
  scene.meshPath = "mesh.obj";
  PatternLayer flame = flameLayer(sierpinskiTetrahedron());
  flame.flame.xforms[1].hasPost = true;
  flame.flame.xforms[1].post = affine({0, -1, 0, 0.1, 1, 0, 0, 0, 0, 0, 1, 0.2});
  flame.flame.xforms[2].variations = {{"spherical", 0.25, {}}, {"julia", 0.75, {}}};
  flame.flame.xforms[3].opacity = 0.5;
  flame.flame.hasFinal = true;
  flame.flame.finalXform = xform(1.0, affine({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 0}), 0.3, 0.1);
  flame.flame.symmetry = {3, {0.0, 1.0, 0.0}, true};
  flame.flame.postSymmetry = {PostSymmetryKind::YAxis, 5, 0.25, -0.5, 2.0, -30.0};
  flame.color.gradient = {{0.0f, {0.0f, 0.0f, 0.0f}}, {1.0f, {1.0f, 1.0f, 1.0f}}};
  PatternLayer julia;
  julia.kind = PatternKind::QuaternionJulia;
  julia.attractor.clear();
  julia.julia = {{-0.1, 0.7, 0.3, -0.2}, QuaternionView::Slice, 30.0, 0.1, 0.02};
  julia.color = flame.color;
  scene.layers = {flame, julia};
  const Scene back = sceneFromJson(sceneToJson(scene), "round trip");
  ASSERT_EQ(back.layers.size(), 2u);
  EXPECT_EQ(back.layers[0].kind, PatternKind::Flame);
  EXPECT_EQ(back.layers[0].flame, scene.layers[0].flame);
  EXPECT_EQ(back.layers[0].color.mode, ColorMode::Index);
  EXPECT_EQ(back.layers[1].kind, PatternKind::QuaternionJulia);
  EXPECT_EQ(back.layers[1].julia, scene.layers[1].julia);
  EXPECT_EQ(back.layers[0].patternName(), "flame");
}

TEST(FlamePreset, BadFlameLayersNameTheKeyAndTheReason) {
  const auto preset = [](const std::string& layer) {
    return R"({"mesh": {"path": "m.obj"}, "layers": [)" + layer + "]}";
  };
  const std::string good = R"({"kind": "flame", "flame": {"xforms": [{"affine": [1,0,0,0, 0,1,0,0, 0,0,1,0]}]}})";
  EXPECT_EQ(presetErrorOf(preset(good)), "");
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame"})")).find("'layers[0].flame' is missing"), std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flames"})")).find("known kinds"), std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": []}})")).find("1 to 128"), std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{"weight": 0}]}})")).find("weight"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{"affine": [1, 2]}]}})"))
                .find("'layers[0].flame.xforms[0].affine' must be 12 numbers"),
            std::string::npos);
  EXPECT_NE(
      presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{"affine": [1e9,0,0,0,0,1,0,0,0,0,1,0]}]}})"))
          .find("outside the allowed range"),
      std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{"variations": [{"name": "nope"}]}]}})"))
                .find("'layers[0].flame.xforms[0].variations[0].name'"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(
                preset(R"({"kind": "flame", "flame": {"xforms": [{"variations": [{"name": "linear", "pwr": 2}]}]}})"))
                .find("'layers[0].flame.xforms[0].variations[0].pwr' is not a known key"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{}], "symmetry": {"rotational": 128}}})"))
                .find("rotational"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{}], "post_symmetry": {"order": 65}}})"))
                .find("'layers[0].flame.post_symmetry.order'"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{}], "post_symmetry": {"kind": "line"}}})"))
                .find("x_axis"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "quaternion_julia", "julia": {"c": [1, 2, 3]}})")).find("four numbers"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "quaternion_julia", "julia": {"view": "cut"}})")).find("'slice'"),
            std::string::npos);
}

// Issue 25: xaos (flam3's chaos) in the chaos game. Two transforms of equal weight; transform 0
// may never be followed by itself. Counting each lane's successive choices: 0 → 0 never happens,
// 0 → 1 always follows a 0, and after a 1 both come equally often (its row is the plain weights).
TEST(ChaosGame, XaosForbidsATransitionAndWeighsTheOthers) {
  FlameGenome genome = sierpinskiTetrahedron();
  genome.xforms.resize(3);
  genome.xforms[0].xaos = {0.0, 1.0, 1.0};
  genome.xforms[1].xaos = {1.0, 1.0, 3.0};  // after 1: 2 is three times as likely as 0 or 1
  genome.xforms[2].xaos = {0.0, 0.0, 0.0};  // a dead end: the plain weights choose after 2
  const ChaosGame game(flameLayer(genome), "test");
  LaneRun run(game);
  std::array<std::array<std::size_t, 3>, 3> transitions{};
  std::vector<int> previous(kLanes, -1);
  for (int s = 0; s < 400; ++s) {
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      const int now = run.lanes.choice[i];
      ASSERT_LT(now, 3);
      if (previous[i] >= 0) ++transitions[static_cast<std::size_t>(previous[i])][static_cast<std::size_t>(now)];
      previous[i] = now;
    }
  }
  EXPECT_EQ(transitions[0][0], 0u);
  EXPECT_GT(transitions[0][1], 1000u);
  EXPECT_GT(transitions[0][2], 1000u);
  const auto share = [&](std::size_t from, std::size_t to) {
    const double total = static_cast<double>(transitions[from][0] + transitions[from][1] + transitions[from][2]);
    return static_cast<double>(transitions[from][to]) / total;
  };
  EXPECT_NEAR(share(0, 1), 0.5, 0.03);
  EXPECT_NEAR(share(1, 2), 0.6, 0.03);
  EXPECT_NEAR(share(1, 0), 0.2, 0.03);
  EXPECT_NEAR(share(2, 0), 1.0 / 3.0, 0.03);
  EXPECT_NEAR(share(2, 2), 1.0 / 3.0, 0.03);
  // A fresh lane's first choice is the plain weights: reseeding forgets the previous transform.
  SplitMix64 rng(9);
  game.seedLane(run.lanes, 0, rng);
  EXPECT_EQ(run.lanes.previous[0], 0);
}

TEST(ChaosGame, XaosOfAllOnesChangesNothing) {
  FlameGenome plain = sierpinskiTetrahedron();
  FlameGenome ones = plain;
  for (FlameXform& x : ones.xforms) x.xaos = {1.0, 1.0, 1.0, 1.0};
  const ChaosGame a(flameLayer(plain), "a"), b(flameLayer(ones), "b");
  LaneRun runA(a), runB(b);
  for (int s = 0; s < 50; ++s) {
    runA.step(a);
    runB.step(b);
  }
  EXPECT_EQ(runA.x, runB.x);
  EXPECT_EQ(runA.color, runB.color);
}

TEST(FlamePreset, XaosIsCheckedAndRoundTrips) {
  const auto preset = [](const std::string& layer) {
    return R"({"mesh": {"path": "m.obj"}, "layers": [)" + layer + "]}";
  };
  Scene scene;
  scene.meshPath = "mesh.obj";
  const std::string good =
      R"({"kind": "flame", "flame": {"xforms": [{"xaos": [0, 2]}, {"affine": [0.5,0,0,0, 0,0.5,0,0, 0,0,0.5,0]}]}})";
  EXPECT_EQ(presetErrorOf(preset(good)), "");
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{"xaos": [-1]}]}})")).find("xaos"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{"xaos": 1}]}})")).find("xaos"),
            std::string::npos);
  EXPECT_NE(presetErrorOf(preset(R"({"kind": "flame", "flame": {"xforms": [{}], "final": {"xaos": [1]}}})")), "");
  FlameGenome genome = sierpinskiTetrahedron();
  genome.xforms[1].xaos = {0.5, 0.0, 2.0};
  scene.layers = {flameLayer(genome)};
  scene.layers[0].color.gradient = {{0.0f, {0.0f, 0.0f, 0.0f}}, {1.0f, {1.0f, 1.0f, 1.0f}}};
  const Scene back = sceneFromJson(sceneToJson(scene), "back.json");
  EXPECT_EQ(back.layers.at(0).flame.xforms[1].xaos, genome.xforms[1].xaos);
  EXPECT_TRUE(back.layers.at(0).flame.xforms[0].xaos.empty());
}

// Issue 25: pre_ and post_ forms. One transform (identity affine) with pre_spherical 0.5, linear 1
// and post_sinusoidal 2: the point is mapped by 0.5·spherical (z kept), then linearly, then by
// 2·sinusoidal (z kept). post_ztranslate, a variation whose result ignores the point, adds to it.
TEST(ChaosGame, PreAndPostVariationsWrapTheTransformsOwn) {
  FlameGenome genome;
  FlameXform x = xform(1.0, Affine3{});
  x.variations = {
      {"post_sinusoidal", 2.0, {}}, {"linear", 1.0, {}}, {"pre_spherical", 0.5, {}}, {"post_ztranslate", 0.3, {}}};
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "test");
  LaneRun run(game);
  for (std::size_t i = 0; i < kLanes; ++i) {
    run.lanes.x[i] = 0.3;
    run.lanes.y[i] = -0.7;
    run.lanes.z[i] = 0.5;
  }
  run.step(game);
  const double r2 = 0.3 * 0.3 + 0.7 * 0.7;
  EXPECT_NEAR(run.x[0], 2.0 * std::sin(0.5 * 0.3 / r2), 1e-12);
  EXPECT_NEAR(run.y[0], 2.0 * std::sin(0.5 * -0.7 / r2), 1e-12);
  EXPECT_NEAR(run.z[0], 0.5 + 0.3, 1e-12);
}

// flam3's pre_blur moves the point before the transform's other variations see it: with
// spherical after it, the result is spherical of the blurred point, not spherical plus a blur
// (the lane's random draws are replayed).
TEST(ChaosGame, Flam3sPreBlurActsBeforeTheOtherVariations) {
  FlameGenome genome;
  FlameXform x = xform(1.0, Affine3{});
  x.variations = {{"spherical", 1.0, {}}, {"pre_blur", 0.5, {}}};
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "test");
  LaneRun run(game);
  std::vector<std::uint32_t> states(kLanes);
  for (std::size_t i = 0; i < kLanes; ++i) {
    run.lanes.x[i] = 0.3;
    run.lanes.y[i] = -0.7;
    run.lanes.z[i] = 0.5;
    states[i] = run.lanes.random[i];
  }
  run.step(game);
  for (std::size_t i = 0; i < kLanes; ++i) {
    // The lane's draws: one for the transform, then pre_blur's four for G and one for the angle.
    std::uint32_t r = laneNext(states[i]);
    const double a = laneUniform(r), b = laneUniform(r), c = laneUniform(r), d = laneUniform(r);
    const double g = 0.5 * (a + b + c + d - 2.0), angle = 2.0 * std::numbers::pi * laneUniform(r);
    const double qx = 0.3 + g * std::cos(angle), qy = -0.7 + g * std::sin(angle);
    const double q2 = qx * qx + qy * qy;
    EXPECT_NEAR(run.x[i], qx / q2, 1e-12);
    EXPECT_NEAR(run.y[i], qy / q2, 1e-12);
    EXPECT_NEAR(run.z[i], 0.5, 1e-12);  // a 2D pre_ term keeps z; spherical carries it
  }
}

TEST(ChaosGame, FlattenSetsTheTransformsDepthToZero) {
  FlameGenome genome;
  FlameXform x = xform(1.0, affine({0.5, 0, 0, 0.1, 0, 0.5, 0, 0, 0, 0, 0.5, 0.4}));
  x.variations = {{"linear", 1.0, {}}, {"flatten", 1.0, {}}};
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "test");
  LaneRun run(game);
  for (int s = 0; s < 5; ++s) run.step(game);
  for (std::size_t i = 0; i < kLanes; ++i) EXPECT_EQ(run.z[i], 0.0);
  EXPECT_NE(run.x[0], 0.0);
}

// JWildfire's shredlin assigns its x and y: the terms before it on the transform are discarded in
// x and y (their z is kept and shredlin adds its own), those after it add as usual. (0.3, −0.7, 0.5)
// through shredlin's default strips goes to (0.32, −0.48) at weight 0.8 (see its point case).
TEST(ChaosGame, AnAssigningTermDiscardsTheSumBeforeIt) {
  FlameGenome genome;
  FlameXform x = xform(1.0, Affine3{});
  x.variations = {{"linear3D", 2.0, {}}, {"shredlin", 0.8, {1.0, 0.5, 1.0, 0.5}}, {"linear", 0.5, {}}};
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "test");
  LaneRun run(game);
  for (std::size_t i = 0; i < kLanes; ++i) {
    run.lanes.x[i] = 0.3;
    run.lanes.y[i] = -0.7;
    run.lanes.z[i] = 0.5;
  }
  run.step(game);
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(run.x[i], 0.32 + 0.5 * 0.3, 1e-12);
    EXPECT_NEAR(run.y[i], -0.48 + 0.5 * -0.7, 1e-12);
    EXPECT_NEAR(run.z[i], (2.0 + 0.8 + 0.5) * 0.5, 1e-12);
  }
  // Fractorium's mirror_x discards all three coordinates of the sum before it.
  x.variations = {{"linear3D", 2.0, {}}, {"mirror_x", 1.0, {}}};
  genome.xforms = {x};
  const ChaosGame mirrored(flameLayer(genome), "test");
  LaneRun again(mirrored);
  for (std::size_t i = 0; i < kLanes; ++i) {
    again.lanes.x[i] = 0.3;
    again.lanes.y[i] = -0.7;
    again.lanes.z[i] = 0.5;
  }
  again.step(mirrored);
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(std::abs(again.x[i]), 0.3, 1e-12);
    EXPECT_NEAR(again.y[i], -0.7, 1e-12);
    EXPECT_NEAR(again.z[i], 0.5, 1e-12);
  }
}

// Fractorium's post_depth adds the transform's affine point t, not the sum it maps: with the
// identity map t = (0.3, −0.7, 0.5), linear at 0.5 sums to s = t/2, |s_z| = 0.25, and post_depth
// (weight 1, power 1) gives t + 0.25 s = 1.125 t. A pre_ term before it moves t for both.
TEST(ChaosGame, PostDepthAddsTheTransformsAffinePoint) {
  FlameGenome genome;
  FlameXform x = xform(1.0, Affine3{});
  x.variations = {{"linear", 0.5, {}}, {"post_depth", 1.0, {1.0}}};
  genome.xforms = {x};
  const ChaosGame game(flameLayer(genome), "test");
  LaneRun run(game);
  for (std::size_t i = 0; i < kLanes; ++i) {
    run.lanes.x[i] = 0.3;
    run.lanes.y[i] = -0.7;
    run.lanes.z[i] = 0.5;
  }
  run.step(game);
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(run.x[i], 1.125 * 0.3, 1e-12);
    EXPECT_NEAR(run.y[i], 1.125 * -0.7, 1e-12);
    EXPECT_NEAR(run.z[i], 1.125 * 0.5, 1e-12);
  }
  // pre_ztranslate 0.3 first: t = (0.3, −0.7, 0.8), s = t/2, |s_z| = 0.4: t + 0.4 s = 1.2 t.
  x.variations = {{"pre_ztranslate", 0.3, {}}, {"linear", 0.5, {}}, {"post_depth", 1.0, {1.0}}};
  genome.xforms = {x};
  const ChaosGame moved(flameLayer(genome), "test");
  LaneRun again(moved);
  for (std::size_t i = 0; i < kLanes; ++i) {
    again.lanes.x[i] = 0.3;
    again.lanes.y[i] = -0.7;
    again.lanes.z[i] = 0.5;
  }
  again.step(moved);
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(again.x[i], 1.2 * 0.3, 1e-12);
    EXPECT_NEAR(again.y[i], 1.2 * -0.7, 1e-12);
    EXPECT_NEAR(again.z[i], 1.2 * 0.8, 1e-12);
  }
}

// JWildfire's chained final transforms: each bends what the one before drew, in order, and none
// feeds back into the state.
TEST(ChaosGame, ChainedFinalTransformsApplyInOrder) {
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  FlameXform shrink;
  shrink.affine.m = {0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0};
  shrink.variations = {{"linear", 1.0, {}}};
  layer.flame.xforms = {shrink};
  FlameXform shift;  // x + 1
  shift.affine.m = {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0};
  shift.variations = {{"linear", 1.0, {}}};
  FlameXform twice;  // 2x
  twice.affine.m = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0};
  twice.variations = {{"linear", 1.0, {}}};
  layer.flame.hasFinal = true;
  layer.flame.finalXform = shift;
  layer.flame.chainedFinals = {twice};
  const ChaosGame game(layer, "chain");
  ChaosLanes lanes;
  lanes.resize(1);
  SplitMix64 rng(3);
  game.seedLane(lanes, 0, rng);
  lanes.x[0] = 0.5;
  lanes.y[0] = 0.25;
  lanes.z[0] = 0.0;
  double x = 0.0, y = 0.0, z = 0.0, c = 0.0;
  game.step(lanes, &x, &y, &z, &c, 1);
  // The state moved to (0.25, 0.125); drawn: 2 · (0.25 + 1) = 2.5, and 2 · 0.125 = 0.25.
  EXPECT_NEAR(lanes.x[0], 0.25, 1e-12);
  EXPECT_NEAR(x, 2.5, 1e-12);
  EXPECT_NEAR(y, 0.25, 1e-12);
  layer.flame.chainedFinals = {};
  const ChaosGame single(layer, "single");
  lanes.x[0] = 0.5;
  lanes.y[0] = 0.25;
  single.step(lanes, &x, &y, &z, &c, 1);
  EXPECT_NEAR(x, 1.25, 1e-12);
}

// The chaos game moves no random state through a group whose variations are all marked fixed
// (VariationInfo::random false), so that mark must hold: a fixed variation leaves every lane's
// generator as it was, at points near the origin, ordinary ones and far ones.
TEST(ChaosGame, VariationsMarkedFixedDrawNoRandomNumbers) {
  const std::vector<std::array<double, 3>> points = {{0.0, 0.0, 0.0},   {1e-9, -1e-9, 0.0}, {0.3, -0.4, 0.2},
                                                     {-0.7, 0.9, -0.5}, {1.5, 2.5, -3.0},   {-12.0, 7.0, 4.0},
                                                     {1e5, -3e4, 2e3},  {0.5, 0.5, 0.5}};
  const std::size_t n = points.size();
  for (const VariationInfo& info : variationCatalogue()) {
    if (info.random) continue;
    std::vector<double> x(n), y(n), z(n), ox(n), oy(n), oz(n), colour(n, 0.5);
    std::vector<double> state(n * std::max<std::size_t>(info.laneState, 1), 0.0);
    std::vector<std::uint32_t> random(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = points[i][0];
      y[i] = points[i][1];
      z[i] = points[i][2];
      random[i] = 0x9e3779b9u * static_cast<std::uint32_t>(i + 1) | 1u;
    }
    const std::vector<std::uint32_t> before = random;
    const std::array<double, 12> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    const std::vector<double> params = info.defaultParams();
    const std::vector<std::string> texts = info.defaultTexts();
    VariationInput in;
    in.x = in.tx = x.data();
    in.y = in.ty = y.data();
    in.z = in.tz = z.data();
    in.random = random.data();
    in.count = n;
    in.params = params.data();
    in.affine = identity.data();
    in.colour = colour.data();
    in.texts = texts.empty() ? nullptr : texts.data();
    in.state = info.laneState > 0 ? state.data() : nullptr;
    info.apply(in, ox.data(), oy.data(), oz.data());
    EXPECT_EQ(random, before) << info.name << " is marked fixed but draws random numbers";
  }
}

// Lanes that took a transform of fixed variations keep their generators as the transform draw left
// them; the others, whose transform draws, move on.
TEST(ChaosGame, OnlyTransformsThatDrawMoveTheirLanesGenerators) {
  FlameGenome g;
  g.xforms.push_back(xform(1.0, affine({0.5, 0, 0, 0.5, 0, 0.5, 0, 0, 0, 0, 0.5, 0})));
  g.xforms.push_back(xform(1.0, affine({0.5, 0, 0, -0.5, 0, 0.5, 0, 0, 0, 0, 0.5, 0})));
  g.xforms[1].variations = {{"blur", 1.0, {}}};
  ASSERT_TRUE(variationOrThrow("blur").random);
  const ChaosGame game(flameLayer(g), "layer");
  LaneRun run(game);
  std::size_t fixed = 0, drawn = 0;
  for (int s = 0; s < 20; ++s) {
    const std::vector<std::uint32_t> before = run.lanes.random;
    run.step(game);
    for (std::size_t i = 0; i < kLanes; ++i) {
      EXPECT_EQ(run.lanes.visible[i], 1);
      if (run.lanes.choice[i] == 0) {
        EXPECT_EQ(run.lanes.random[i], laneNext(before[i]));
        ++fixed;
      } else {
        EXPECT_NE(run.lanes.random[i], laneNext(before[i]));
        ++drawn;
      }
    }
  }
  EXPECT_GT(fixed, 1000u);
  EXPECT_GT(drawn, 1000u);
}
