// What surrounds the mask: the memory refusal, the NRRD file and the on-disk cache.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mask_cache.h"
#include "core/nrrd.h"
#include "test_shapes.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::TemporaryFolder;

namespace {
std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(GridMemory, TooLargeGridIsRefusedSayingHowMuchItNeeds) {
  const GridGeometry grid = gridOverBox({{0, 0, 0}, {1, 1, 1}}, 1024);
  try {
    checkGridFitsInMemory(grid, 33.0, 1024.0 * 1024.0 * 1024.0);  // pretend 1 GiB is all there is
    FAIL() << "expected a refusal";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("1024×1024×1024"), std::string::npos) << message;
    EXPECT_NE(message.find("33.0 GiB"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(checkGridFitsInMemory(gridOverBox({{0, 0, 0}, {1, 1, 1}}, 64), 33.0, 1024.0 * 1024.0 * 1024.0));
  EXPECT_GT(physicalMemoryBytes(), 0.0);
}

TEST(Grid, ResolutionRangeIs32To1024) {
  const Box box{{0, 0, 0}, {1, 2, 3}};
  EXPECT_THROW(gridOverBox(box, 31), Error);
  EXPECT_THROW(gridOverBox(box, 1025), Error);
  EXPECT_EQ(gridOverBox(box, 32).size.z, 32);
  EXPECT_EQ(gridOverBox(box, 1024).size.z, 1024);
}

TEST(Nrrd, HeaderFieldsAndByteCount) {
  TemporaryFolder folder;
  const auto mesh = voxflame::test::box({-1.0f, 0.0f, 2.0f}, {1.0f, 0.5f, 2.25f});
  const InsideMask mask = buildInsideMask(mesh, gridOverBox(mesh.bounds(), 40));
  writeNrrdMask(folder / "m.nrrd", mask);
  const std::string file = readAll(folder / "m.nrrd");
  const std::size_t end = file.find("\n\n");
  ASSERT_NE(end, std::string::npos);
  const std::string header = file.substr(0, end + 1);
  const GridGeometry& g = mask.geometry;
  EXPECT_EQ(header.rfind("NRRD0004\n", 0), 0u);
  for (const std::string field : {"type: uchar\n", "dimension: 3\n", "encoding: raw\n", "space: 3D-right-handed\n"})
    EXPECT_NE(header.find(field), std::string::npos) << field;
  EXPECT_NE(header.find("sizes: " + std::to_string(g.size.x) + " " + std::to_string(g.size.y) + " " +
                        std::to_string(g.size.z) + "\n"),
            std::string::npos)
      << header;
  // Origin: the centre of the first voxel, in the mesh's coordinates; directions: voxel edges.
  double ox = 0, oy = 0, oz = 0, d[9] = {};
  ASSERT_EQ(std::sscanf(header.c_str() + header.find("space origin:"), "space origin: (%lf,%lf,%lf)", &ox, &oy, &oz),
            3);
  EXPECT_NEAR(ox, g.origin.x + 0.5 * g.voxelSize, 1e-12);
  EXPECT_NEAR(oy, g.origin.y + 0.5 * g.voxelSize, 1e-12);
  EXPECT_NEAR(oz, g.origin.z + 0.5 * g.voxelSize, 1e-12);
  EXPECT_LT(ox, -1.0);  // the grid's margin lies outside the mesh
  ASSERT_EQ(std::sscanf(header.c_str() + header.find("space directions:"),
                        "space directions: (%lf,%lf,%lf) (%lf,%lf,%lf) (%lf,%lf,%lf)", &d[0], &d[1], &d[2], &d[3],
                        &d[4], &d[5], &d[6], &d[7], &d[8]),
            9);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[3 * r + c], r == c ? g.voxelSize : 0.0, 1e-15);
  // The data: one byte per voxel, 0 or 1, x fastest.
  const std::string data = file.substr(end + 2);
  ASSERT_EQ(data.size(), g.voxelCount());
  std::size_t ones = 0;
  for (std::size_t v = 0; v < data.size(); ++v) {
    ASSERT_TRUE(data[v] == 0 || data[v] == 1);
    EXPECT_EQ(data[v], static_cast<char>(mask.inside[v]));
    ones += data[v] == 1;
  }
  EXPECT_GT(ones, 0u);
  EXPECT_EQ(voxflame::test::filesStartingWith(folder.path(), "m.nrrd"), std::vector<std::string>{"m.nrrd"});
  EXPECT_THROW(writeNrrdMask(folder / "no-such-folder" / "m.nrrd", mask), Error);
}

TEST(MaskCache, SecondRequestIsACacheHitAndCorruptEntriesAreRebuilt) {
  TemporaryFolder folder;
  const auto mesh = voxflame::test::torus({0.0f, 0.0f, 0.0f}, 1.0f, 0.4f, 32, 16);
  const GridGeometry grid = gridOverBox(mesh.bounds(), 48);
  bool hit = true;
  const InsideMask built = cachedInsideMask(mesh, grid, MaskMethod::WindingNumber, folder.path(), &hit);
  EXPECT_FALSE(hit);
  const auto entry = maskCacheEntry(folder.path(), mesh, grid, MaskMethod::WindingNumber);
  ASSERT_TRUE(std::filesystem::exists(entry));
  EXPECT_LT(std::filesystem::file_size(entry), grid.voxelCount() / 4);  // bit-packed

  const InsideMask cached = cachedInsideMask(mesh, grid, MaskMethod::WindingNumber, folder.path(), &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(cached.inside, built.inside);

  // Another grid, another method or another mesh are other entries.
  cachedInsideMask(mesh, gridOverBox(mesh.bounds(), 40), MaskMethod::WindingNumber, folder.path(), &hit);
  EXPECT_FALSE(hit);
  cachedInsideMask(mesh, grid, MaskMethod::Parity, folder.path(), &hit);
  EXPECT_FALSE(hit);
  auto moved = mesh;
  moved.vertices[0].x += 0.01f;
  EXPECT_NE(meshContentHash(moved), meshContentHash(mesh));

  // A flipped bit in the data, a truncated file, garbage: each ignored and rebuilt.
  const std::string good = readAll(entry);
  std::string flipped = good;
  flipped[flipped.size() - 3] = static_cast<char>(flipped[flipped.size() - 3] ^ 0x10);
  for (const std::string& bad : {flipped, good.substr(0, good.size() / 2), std::string("garbage")}) {
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << bad;
    const InsideMask rebuilt = cachedInsideMask(mesh, grid, MaskMethod::WindingNumber, folder.path(), &hit);
    EXPECT_FALSE(hit);
    EXPECT_EQ(rebuilt.inside, built.inside);
    EXPECT_EQ(readAll(entry), good);  // and the entry is whole again
  }
}

TEST(MaskCache, PruningKeepsTheNewestEntries) {
  TemporaryFolder folder;
  const auto mesh = voxflame::test::box({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
  std::vector<std::filesystem::path> entries;
  for (int resolution : {32, 33, 34, 35}) {
    const GridGeometry grid = gridOverBox(mesh.bounds(), resolution);
    cachedInsideMask(mesh, grid, MaskMethod::WindingNumber, folder.path());
    entries.push_back(maskCacheEntry(folder.path(), mesh, grid, MaskMethod::WindingNumber));
    // Distinct modification times, oldest first, whatever the file system's resolution.
    std::filesystem::last_write_time(
        entries.back(), std::filesystem::file_time_type::clock::now() + std::chrono::seconds(10 * resolution));
  }
  std::ofstream(folder / "unrelated.txt") << "kept";
  pruneMaskCache(folder.path(), 2);
  EXPECT_FALSE(std::filesystem::exists(entries[0]));
  EXPECT_FALSE(std::filesystem::exists(entries[1]));
  EXPECT_TRUE(std::filesystem::exists(entries[2]));
  EXPECT_TRUE(std::filesystem::exists(entries[3]));
  EXPECT_TRUE(std::filesystem::exists(folder / "unrelated.txt"));
}

TEST(MaskCache, FolderFollowsXdgAndTestsUseAPrivateOne) {
  const std::filesystem::path folder = defaultMaskCacheFolder();
  ASSERT_FALSE(folder.empty());
  EXPECT_EQ(folder.filename(), "voxflame");
  // test_support points XDG_CACHE_HOME at a temporary folder for every test process.
  EXPECT_EQ(folder.parent_path().string(), std::getenv("XDG_CACHE_HOME"));
  EXPECT_EQ(folder.parent_path().string().find(std::getenv("HOME") ? std::getenv("HOME") : "/nonexistent"),
            std::string::npos);
}
