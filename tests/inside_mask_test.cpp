#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "test_shapes.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::meshPath;

namespace {

// Fraction of voxels on which two masks of the same grid agree.
double agreement(const InsideMask& a, const InsideMask& b) {
  EXPECT_EQ(a.inside.size(), b.inside.size());
  std::size_t same = 0;
  for (std::size_t v = 0; v < a.inside.size(); ++v) same += a.inside[v] == b.inside[v];
  return static_cast<double>(same) / static_cast<double>(a.inside.size());
}

// Agreement with the exact winding number at the voxel centres. The exact sum costs voxels ×
// triangles, which under the sanitizers takes minutes on the shared meshes, so by default every
// stride-th voxel is checked, the stride chosen to keep to about 2·10⁷ triangle evaluations (an
// odd stride, so the sample walks across rows and slices). VOXFLAME_FULL_REFERENCE=1 checks every
// voxel.
double agreementWithReference(const TriangleMesh& mesh, const InsideMask& mask) {
  const GridGeometry& g = mask.geometry;
  const double work = static_cast<double>(g.voxelCount()) * static_cast<double>(mesh.triangles.size());
  std::size_t stride = std::getenv("VOXFLAME_FULL_REFERENCE") ? 1 : static_cast<std::size_t>(std::ceil(work / 2e7));
  if (stride <= 1) return agreement(mask, buildInsideMask(mesh, g, MaskMethod::ExactWindingNumber));
  stride |= 1;
  const int orientation = meshOrientation(mesh);
  std::size_t same = 0, checked = 0;
  for (std::size_t v = 0; v < g.voxelCount(); v += stride) {
    const int i = static_cast<int>(v % static_cast<std::size_t>(g.size.x));
    const int j = static_cast<int>((v / static_cast<std::size_t>(g.size.x)) % static_cast<std::size_t>(g.size.y));
    const int k = static_cast<int>(v / (static_cast<std::size_t>(g.size.x) * g.size.y));
    const bool reference = orientation * windingNumber(mesh, g.voxelCenter(i, j, k)) >= 0.5;
    same += reference == (mask.inside[v] != 0);
    ++checked;
  }
  return static_cast<double>(same) / static_cast<double>(checked);
}

// Checks the mask against an analytic inside test on every voxel whose centre lies farther
// than `band` from the true surface (the tessellation error); returns how many were checked.
template <class Inside, class Distance>
std::size_t expectAnalytic(const InsideMask& mask, Inside inside, Distance distanceToSurface, double band) {
  const GridGeometry& g = mask.geometry;
  std::size_t checked = 0, wrong = 0;
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i) {
        const glm::dvec3 c = g.voxelCenter(i, j, k);
        if (distanceToSurface(c) <= band) continue;
        ++checked;
        if (mask.at(i, j, k) != inside(c)) {
          if (++wrong < 5) ADD_FAILURE() << "voxel " << i << " " << j << " " << k << " should be " << inside(c);
        }
      }
  EXPECT_EQ(wrong, 0u);
  return checked;
}

}  // namespace

TEST(InsideMask, SphereIsExactlyItsBall) {
  const glm::dvec3 centre(0.1, -0.2, 0.3);
  const auto mesh = voxflame::test::uvSphere(glm::vec3(centre), 1.0f, 64, 32);
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 64));
  // A 64-segment polygon lies within 1 - cos(π/64) ≈ 0.0012 of the sphere.
  const std::size_t checked = expectAnalytic(
      mask, [&](glm::dvec3 p) { return glm::length(p - centre) < 1.0; },
      [&](glm::dvec3 p) { return std::fabs(glm::length(p - centre) - 1.0); }, 0.003);
  EXPECT_GT(checked, mask.inside.size() * 9 / 10);
}

TEST(InsideMask, TorusIsExactlyItsTube) {
  const auto mesh = voxflame::test::torus({0.0f, 0.0f, 0.0f}, 1.0f, 0.35f, 96, 48);
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 80));
  auto tubeDistance = [](glm::dvec3 p) {
    const double ring = std::hypot(p.x, p.y) - 1.0;
    return std::hypot(ring, p.z) - 0.35;
  };
  expectAnalytic(
      mask, [&](glm::dvec3 p) { return tubeDistance(p) < 0.0; },
      [&](glm::dvec3 p) { return std::fabs(tubeDistance(p)); },
      0.35 * (1.0 - std::cos(3.14159265 / 48)) + 1.0 * (1.0 - std::cos(3.14159265 / 96)) + 1e-3);
  // The hole of the torus is outside.
  const GridGeometry& g = mask.geometry;
  EXPECT_FALSE(mask.at(g.size.x / 2, g.size.y / 2, g.size.z / 2));
}

TEST(InsideMask, CubeWithOneFaceRemovedIsStillTheCube) {
  // Every face is open in turn: the winding number inside an open box is > 0.5 everywhere.
  for (int open = 0; open < 6; ++open) {
    const auto mesh = voxflame::test::box({-0.37f, -0.61f, -0.29f}, {0.83f, 0.59f, 0.91f}, open);
    const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 48));
    auto insideBox = [](glm::dvec3 p) {
      return p.x > -0.37 && p.x < 0.83 && p.y > -0.61 && p.y < 0.59 && p.z > -0.29 && p.z < 0.91;
    };
    auto distance = [](glm::dvec3 p) {
      return std::min({std::fabs(p.x + 0.37), std::fabs(p.x - 0.83), std::fabs(p.y + 0.61), std::fabs(p.y - 0.59),
                       std::fabs(p.z + 0.29), std::fabs(p.z - 0.91)});
    };
    SCOPED_TRACE("open face " + std::to_string(open));
    expectAnalytic(mask, insideBox, distance, 1e-4);
    EXPECT_EQ(agreementWithReference(mesh, mask), 1.0);
  }
}

TEST(InsideMask, TwoOverlappingCubesFillTheirUnion) {
  // Where the cubes overlap the winding number is 2: inside, though every ray there has crossed
  // an even number of faces, which single-axis parity reads as outside.
  const auto mesh = voxflame::test::joined(voxflame::test::box({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}),
                                           voxflame::test::box({0.53f, 0.41f, 0.37f}, {1.47f, 1.39f, 1.29f}));
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 64));
  auto inBox = [](glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi) {
    return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z;
  };
  auto inUnion = [&](glm::dvec3 p) {
    return inBox(p, {0, 0, 0}, {1, 1, 1}) || inBox(p, {0.53, 0.41, 0.37}, {1.47, 1.39, 1.29});
  };
  auto nearAFace = [](glm::dvec3 p) {
    double d = 1e9;
    for (double plane : {0.0, 1.0})
      d = std::min({d, std::fabs(p.x - plane), std::fabs(p.y - plane), std::fabs(p.z - plane)});
    d = std::min({d, std::fabs(p.x - 0.53), std::fabs(p.x - 1.47), std::fabs(p.y - 0.41), std::fabs(p.y - 1.39),
                  std::fabs(p.z - 0.37), std::fabs(p.z - 1.29)});
    return d;
  };
  expectAnalytic(mask, inUnion, nearAFace, 1e-4);
  const InsideMask parity = buildInsideMask(mesh, mask.geometry, MaskMethod::Parity);
  EXPECT_LT(agreement(mask, parity), 0.99) << "the overlap should defeat parity";
}

TEST(InsideMask, SphereWithCapCutOffMatchesTheReference) {
  const auto mesh = voxflame::test::uvSphere({0.0f, 0.0f, 0.0f}, 1.0f, 24, 13, 0.6f);
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 64));
  // On the plane of the hole the winding number is exactly 0.5 and either answer is as right;
  // the rim must not sit on a plane of voxel centres for the comparison to mean anything.
  float rim = -2.0f;
  for (const auto& tri : mesh.triangles)
    for (const std::uint32_t v : tri) rim = std::max(rim, mesh.vertices[v].z);
  const double rimInVoxels = (rim - mask.geometry.origin.z) / mask.geometry.voxelSize;
  ASSERT_GT(std::fabs(rimInVoxels - std::floor(rimInVoxels) - 0.5), 0.05);
  EXPECT_GE(agreementWithReference(mesh, mask), 0.995);
  // Well below the cut the ball is inside; above the cut nothing is, though rays along z
  // through the hole cross the surface only once.
  const GridGeometry& g = mask.geometry;
  for (int k = 0; k < g.size.z; ++k) {
    const glm::dvec3 c = g.voxelCenter(g.size.x / 2, g.size.y / 2, k);
    if (c.z > -0.9 && c.z < 0.3) {
      EXPECT_TRUE(mask.at(g.size.x / 2, g.size.y / 2, k)) << c.z;
    }
  }
  const InsideMask parity = buildInsideMask(mesh, mask.geometry, MaskMethod::Parity);
  EXPECT_LT(agreement(mask, parity), 0.99) << "the hole should defeat single-axis parity";
}

TEST(InsideMask, TeapotMatchesTheReferenceAt64) {
  const TriangleMesh mesh = loadMesh(meshPath("teapot.obj"));
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 64));
  EXPECT_GE(agreementWithReference(mesh, mask), 0.995);
}

TEST(InsideMask, BunnyMatchesTheReferenceAt64) {
  const TriangleMesh mesh = loadMesh(meshPath("bunny.obj"));
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 64));
  EXPECT_GE(agreementWithReference(mesh, mask), 0.995);
}

TEST(InsideMask, InsideOutMeshGivesTheSameMask) {
  const auto mesh = voxflame::test::uvSphere({0.0f, 0.0f, 0.0f}, 1.0f, 24, 12, 0.6f);
  const GridGeometry grid = gridOverBox(mesh.bounds(), 48);
  EXPECT_EQ(meshOrientation(mesh), 1);
  EXPECT_EQ(meshOrientation(voxflame::test::insideOut(mesh)), -1);
  EXPECT_EQ(agreement(buildInsideMask(mesh, grid), buildInsideMask(voxflame::test::insideOut(mesh), grid)), 1.0);
}

TEST(InsideMask, ThreadCountDoesNotChangeTheResult) {
  const TriangleMesh mesh = loadMesh(meshPath("teapot.obj"));
  const GridGeometry grid = gridOverBox(mesh.bounds(), 96);
  const InsideMask one = buildInsideMask(mesh, grid, MaskMethod::WindingNumber, 1);
  const InsideMask three = buildInsideMask(mesh, grid, MaskMethod::WindingNumber, 3);
  EXPECT_EQ(one.inside, three.inside);
  EXPECT_GT(one.insideFraction(), 0.1);
}

TEST(WindingNumberTree, AgreesWithTheExactSum) {
  const TriangleMesh mesh = loadMesh(meshPath("teapot.obj"));
  const WindingNumberTree tree(mesh);
  const Box box = mesh.bounds();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  for (int n = 0; n < 300; ++n) {
    const glm::dvec3 p = box.min + glm::dvec3(unit(random), unit(random), unit(random)) * box.extent();
    EXPECT_NEAR(tree(p), windingNumber(mesh, p), 0.02) << p.x << " " << p.y << " " << p.z;
  }
  // Inside a closed mesh the winding number is one, outside zero.
  const auto sphere = voxflame::test::uvSphere({0.0f, 0.0f, 0.0f}, 1.0f, 32, 16);
  EXPECT_NEAR(windingNumber(sphere, {0.1, 0.2, -0.1}), 1.0, 1e-9);
  EXPECT_NEAR(windingNumber(sphere, {1.5, 0.2, -0.1}), 0.0, 1e-9);
  EXPECT_NEAR(WindingNumberTree(sphere)({0.1, 0.2, -0.1}), 1.0, 0.01);
}

TEST(InsideMask, GridCoveringOnlyPartOfTheMeshIsStillRight) {
  // Crossings before the grid's start and beyond its end still count for the columns.
  const auto mesh = voxflame::test::uvSphere({0.0f, 0.0f, 0.0f}, 1.0f, 48, 24);
  GridGeometry grid;
  grid.size = {40, 36, 32};
  grid.voxelSize = 0.02;
  grid.origin = {-0.4, -0.3, -0.2};  // inside the ball throughout
  const InsideMask mask = buildInsideMask(mesh, grid);
  EXPECT_EQ(mask.insideFraction(), 1.0);
  grid.origin = {2.0, 2.0, 2.0};  // entirely outside
  EXPECT_EQ(buildInsideMask(mesh, grid).insideFraction(), 0.0);
}
