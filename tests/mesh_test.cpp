#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/scene_io.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::meshPath;
using voxflame::test::TemporaryFolder;

TEST(Mesh, LoadsTheBunny) {
  const TriangleMesh mesh = loadMesh(meshPath("bunny.obj"));
  EXPECT_EQ(mesh.triangles.size(), 3674u);
  const Box box = mesh.bounds();
  EXPECT_GT(box.extent().x, 0.0);
  EXPECT_GT(box.extent().y, 0.0);
}

TEST(Mesh, EmbeddedBunnyMatchesTheSharedOne) {
  const TriangleMesh embedded = loadSceneMesh(defaultScene());
  const TriangleMesh shared = loadMesh(meshPath("bunny.obj"));
  EXPECT_EQ(embedded.triangles.size(), shared.triangles.size());
  EXPECT_EQ(embedded.vertices.size(), shared.vertices.size());
}

TEST(Mesh, MissingFileNamesIt) {
  try {
    loadMesh("/nonexistent/missing-mesh.obj");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing-mesh.obj"), std::string::npos);
  }
}

TEST(Mesh, EmptyCorruptAndFlatFilesAreRefused) {
  TemporaryFolder folder;
  std::ofstream(folder / "empty.obj").close();
  std::ofstream(folder / "garbage.ply") << "ply\nformat binary_little_endian 1.0\nelement vertex 99\n";
  std::ofstream(folder / "lines.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n";
  std::ofstream(folder / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
  for (const char* name : {"empty.obj", "garbage.ply", "lines.obj", "flat.obj"}) {
    try {
      loadMesh(folder / name);
      ADD_FAILURE() << name << " loaded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(InsideMask, BunnyIsMostlySolidInsideItsBox) {
  const TriangleMesh mesh = loadMesh(meshPath("bunny.obj"));
  const GridGeometry grid = gridOverBox(mesh.bounds(), 64);
  const InsideMask mask = buildInsideMask(mesh, grid);
  // The bunny fills roughly a third of its bounding grid; the centre of its body is inside and
  // the grid corners are outside.
  EXPECT_GT(mask.insideFraction(), 0.15);
  EXPECT_LT(mask.insideFraction(), 0.6);
  EXPECT_FALSE(mask.at(0, 0, 0));
  EXPECT_FALSE(mask.at(grid.size.x - 1, grid.size.y - 1, grid.size.z - 1));
}
