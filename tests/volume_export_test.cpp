#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "core/grid.h"
#include "core/scene.h"
#include "core/volume_export.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::runVoxflame;
using voxflame::test::TemporaryFolder;

namespace {

// A 6×5×4 grid in odd coordinates with three voxels hit: 1, 3 and 12 times.
VolumeSnapshot smallSnapshot() {
  VolumeSnapshot s;
  s.geometry.size = glm::ivec3(6, 5, 4);
  s.geometry.origin = glm::dvec3(-1.5, 2.0, 0.25);
  s.geometry.voxelSize = 0.125;
  const std::size_t voxels = s.geometry.voxelCount();
  s.density.assign(voxels, 0.0f);
  s.rgba.assign(4 * voxels, 0);
  const auto hit = [&](int i, int j, int k, float hits, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const std::size_t v = s.geometry.index(i, j, k);
    s.density[v] = hits;
    s.rgba[4 * v] = r;
    s.rgba[4 * v + 1] = g;
    s.rgba[4 * v + 2] = b;
    s.rgba[4 * v + 3] = 255;
  };
  hit(0, 0, 0, 1.0f, 255, 0, 0);
  hit(5, 4, 3, 12.0f, 0, 255, 51);
  hit(2, 3, 1, 3.0f, 102, 102, 102);
  s.maxDensity = 12.0f;
  return s;
}

// The documented normalisation: log(1 + hits / mean) / log(1 + max / mean), mean over hit voxels.
float expectedDensity(float hits) {
  const double mean = (1.0 + 12.0 + 3.0) / 3.0;
  return static_cast<float>(std::log1p(hits / mean) / std::log1p(12.0 / mean));
}

const std::string kPreset = R"({"schema_version":2,"name":"volume test"})";

}  // namespace

TEST(VolumeExport, VdbReadsBackWithOpenVdb) {
  TemporaryFolder folder;
  const VolumeSnapshot snapshot = smallSnapshot();
  writeVdbVolume(folder / "v.vdb", snapshot, kPreset);
  EXPECT_EQ(voxflame::test::filesStartingWith(folder.path(), "v.vdb"), std::vector<std::string>{"v.vdb"});

  openvdb::initialize();
  openvdb::io::File file((folder / "v.vdb").string());
  file.open();
  EXPECT_EQ(file.getMetadata()->metaValue<std::string>("voxflame_preset"), kPreset);
  const auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
  const auto color = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("color"));
  file.close();
  ASSERT_TRUE(density);
  ASSERT_TRUE(color);
  EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_EQ(density->activeVoxelCount(), 3u);
  EXPECT_EQ(color->activeVoxelCount(), 3u);
  EXPECT_EQ(density->metaValue<std::string>("voxflame_preset"), kPreset);

  auto d = density->getConstAccessor();
  EXPECT_FLOAT_EQ(d.getValue(openvdb::Coord(5, 4, 3)), 1.0f);
  EXPECT_FLOAT_EQ(d.getValue(openvdb::Coord(0, 0, 0)), expectedDensity(1.0f));
  EXPECT_FLOAT_EQ(d.getValue(openvdb::Coord(2, 3, 1)), expectedDensity(3.0f));
  EXPECT_FALSE(d.isValueOn(openvdb::Coord(1, 1, 1)));
  EXPECT_EQ(d.getValue(openvdb::Coord(1, 1, 1)), 0.0f);
  auto c = color->getConstAccessor();
  EXPECT_FLOAT_EQ(c.getValue(openvdb::Coord(5, 4, 3)).y(), 1.0f);
  EXPECT_FLOAT_EQ(c.getValue(openvdb::Coord(5, 4, 3)).z(), 0.2f);
  EXPECT_FLOAT_EQ(c.getValue(openvdb::Coord(0, 0, 0)).x(), 1.0f);

  // Index space to world: voxel (i, j, k)'s centre, in the mesh's coordinates.
  for (const glm::ivec3 ijk : {glm::ivec3(0, 0, 0), glm::ivec3(5, 4, 3), glm::ivec3(2, 3, 1)}) {
    const openvdb::Vec3d world = density->indexToWorld(openvdb::Coord(ijk.x, ijk.y, ijk.z));
    const glm::dvec3 centre = snapshot.geometry.voxelCenter(ijk.x, ijk.y, ijk.z);
    EXPECT_NEAR(world.x(), centre.x, 1e-12);
    EXPECT_NEAR(world.y(), centre.y, 1e-12);
    EXPECT_NEAR(world.z(), centre.z, 1e-12);
  }
  EXPECT_NEAR(density->voxelSize().x(), 0.125, 1e-12);
  EXPECT_NEAR(color->indexToWorld(openvdb::Coord(5, 4, 3)).x(), snapshot.geometry.voxelCenter(5, 4, 3).x, 1e-12);
}

TEST(VolumeExport, NrrdHeaderAndDataReadBack) {
  TemporaryFolder folder;
  const VolumeSnapshot snapshot = smallSnapshot();
  writeNrrdVolume(folder / "v.nrrd", snapshot, kPreset);
  std::ifstream in(folder / "v.nrrd", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t end = bytes.find("\n\n");
  ASSERT_NE(end, std::string::npos);
  const std::string header = bytes.substr(0, end + 1);
  EXPECT_EQ(header.rfind("NRRD0004\n", 0), 0u);
  EXPECT_NE(header.find("type: float\n"), std::string::npos);
  EXPECT_NE(header.find("dimension: 4\n"), std::string::npos);
  EXPECT_NE(header.find("sizes: 4 6 5 4\n"), std::string::npos);
  EXPECT_NE(header.find("kinds: 4-vector domain domain domain\n"), std::string::npos);
  EXPECT_NE(header.find("space directions: none (0.125,0,0) (0,0.125,0) (0,0,0.125)\n"), std::string::npos);
  EXPECT_NE(header.find("space origin: (-1.4375,2.0625,0.3125)\n"), std::string::npos);
  EXPECT_NE(header.find("endian: little\n"), std::string::npos);
  EXPECT_NE(header.find("voxflame_preset:=" + nlohmann::json::parse(kPreset).dump() + "\n"), std::string::npos);

  const std::string data = bytes.substr(end + 2);
  ASSERT_EQ(data.size(), 4 * sizeof(float) * snapshot.geometry.voxelCount());
  const auto sample = [&](int i, int j, int k, int channel) {
    float value = 0.0f;
    std::memcpy(&value, data.data() + sizeof(float) * (4 * snapshot.geometry.index(i, j, k) + channel), sizeof value);
    return value;
  };
  EXPECT_FLOAT_EQ(sample(5, 4, 3, 0), 1.0f);
  EXPECT_FLOAT_EQ(sample(2, 3, 1, 0), expectedDensity(3.0f));
  EXPECT_FLOAT_EQ(sample(2, 3, 1, 1), 0.4f);
  EXPECT_FLOAT_EQ(sample(5, 4, 3, 3), 0.2f);
  EXPECT_FLOAT_EQ(sample(1, 1, 1, 0), 0.0f);
}

TEST(VolumeExport, RenderWritesTheAccumulatedVolume) {
  TemporaryFolder folder;
  auto result = runVoxflame("render -o bunny.vdb --grid 48 --points 200000", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  result = runVoxflame("render -o bunny.nrrd --grid 48 --points 200000", folder.path());
  ASSERT_EQ(result.exitStatus, 0) << result.output;

  openvdb::initialize();
  openvdb::io::File file((folder / "bunny.vdb").string());
  file.open();
  const auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
  const std::string preset = file.getMetadata()->metaValue<std::string>("voxflame_preset");
  file.close();
  ASSERT_TRUE(density);
  EXPECT_GT(density->activeVoxelCount(), 1000u);
  float low = 1e30f, high = 0.0f;
  for (auto value = density->cbeginValueOn(); value; ++value) {
    low = std::min(low, *value);
    high = std::max(high, *value);
  }
  EXPECT_GT(low, 0.0f);
  EXPECT_FLOAT_EQ(high, 1.0f);
  const Scene scene = sceneFromJson(preset, "bunny.vdb");
  EXPECT_EQ(scene.gridResolution, 48);

  // The same accumulation in both formats: the NRRD's non-zero densities are the VDB's active voxels.
  std::ifstream in(folder / "bunny.nrrd", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t end = bytes.find("\n\n");
  ASSERT_NE(end, std::string::npos);
  std::size_t nonZero = 0;
  for (std::size_t at = end + 2; at + 16 <= bytes.size(); at += 16) {
    float value = 0.0f;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    nonZero += value > 0.0f;
  }
  EXPECT_EQ(nonZero, density->activeVoxelCount());

  result = runVoxflame("render -o bunny.obj --grid 48", folder.path());
  EXPECT_NE(result.exitStatus, 0);
  EXPECT_NE(result.output.find(".vdb or .nrrd"), std::string::npos) << result.output;
}
