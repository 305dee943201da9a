// Chunk checkpoint files (core/chunk_io.h): exact round trips of both kinds, the label alone, the
// refusals of files that are wrong, and no crash or hang on damaged ones.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "core/chunk_io.h"
#include "core/error.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::filesStartingWith;
using voxflame::test::TemporaryFolder;
namespace fs = std::filesystem;

namespace {

// A label with what JSON text can hold: quotes, backslashes, newlines and non-ASCII.
ChunkLabel testLabel(int chunk = 2, int chunks = 5) {
  ChunkLabel label;
  label.presetJson = "{\"schema_version\": 2, \"name\": \"Zürich \\\"flame\\\" ✓\",\n \"layers\": []}";
  label.width = 1280;
  label.height = 720;
  label.chunk = chunk;
  label.chunks = chunks;
  return label;
}

glm::ivec3 colourCells(const glm::ivec3& size, int shift) {
  const int span = 1 << shift;
  return (size + (span - 1)) / span;
}

// Sums of this shape with about `fraction` of the voxels and colour cells non-zero, some at the
// largest values a chunk file holds. Filled field by field (GridSums::reset is chunk_sums.cpp's).
GridSums randomGridSums(glm::ivec3 size, int shift, double fraction, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  GridSums s;
  s.geometry.size = size;
  s.geometry.origin = glm::dvec3(-1.0 / 3.0, 0.1 + 0.2, 1e-300);
  s.geometry.voxelSize = std::nextafter(0.1, 1.0);
  s.colour.shift = shift;
  s.colour.size = colourCells(size, shift);
  s.hits.assign(s.geometry.voxelCount(), 0);
  for (auto& h : s.hits)
    if (uniform(random) < fraction)
      h = uniform(random) < 0.01 ? 0x7fffffffu : static_cast<std::uint32_t>(random() % 5000 + 1);
  const std::size_t cells = s.colour.cellCount();
  for (auto* v : {&s.red, &s.green, &s.blue, &s.colourPoints}) {
    v->assign(cells, 0);
    for (auto& c : *v)
      if (uniform(random) < fraction)
        c = uniform(random) < 0.01 ? (std::uint64_t{1} << 63) - 1 : random() % (std::uint64_t{1} << 40) + 1;
  }
  s.points = (std::uint64_t{1} << 63) - 1;
  s.iterations = 0x123456789abcdefull;
  s.insideVoxels = seed;
  return s;
}

ImageSums randomImageSums(int width, int height, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  ImageSums s;
  s.width = width;
  s.height = height;
  s.counts.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (auto& c : s.counts) {
    const auto r = random() % 4;
    c = r == 0 ? 0u : r == 1 ? 0xffffffffu : static_cast<std::uint32_t>(random());
  }
  s.unit = 1.0 / 3.0;
  s.points = ~std::uint64_t{0};  // EXR keeps counters as decimal text: the whole 64-bit range
  s.iterations = 18446744073709551557ull;
  return s;
}

std::uint64_t bits(double d) {
  return std::bit_cast<std::uint64_t>(d);
}

void expectSameLabel(const ChunkLabel& expected, const ChunkLabel& found) {
  EXPECT_EQ(found.presetJson, expected.presetJson);
  EXPECT_EQ(found.width, expected.width);
  EXPECT_EQ(found.height, expected.height);
  EXPECT_EQ(found.chunk, expected.chunk);
  EXPECT_EQ(found.chunks, expected.chunks);
}

bool sameGridSums(const GridSums& a, const GridSums& b) {
  return a.geometry.size == b.geometry.size && bits(a.geometry.origin.x) == bits(b.geometry.origin.x) &&
         bits(a.geometry.origin.y) == bits(b.geometry.origin.y) &&
         bits(a.geometry.origin.z) == bits(b.geometry.origin.z) &&
         bits(a.geometry.voxelSize) == bits(b.geometry.voxelSize) && a.colour.shift == b.colour.shift &&
         a.colour.size == b.colour.size && a.hits == b.hits && a.red == b.red && a.green == b.green &&
         a.blue == b.blue && a.colourPoints == b.colourPoints && a.points == b.points && a.iterations == b.iterations &&
         a.insideVoxels == b.insideVoxels;
}

bool sameImageSums(const ImageSums& a, const ImageSums& b) {
  return a.width == b.width && a.height == b.height && a.counts == b.counts && bits(a.unit) == bits(b.unit) &&
         a.points == b.points && a.iterations == b.iterations;
}

// The message of the core::Error that `read` throws ("" when it throws none).
std::string errorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
// A new file each time: ext4 flushes a file truncated and rewritten to disk when it is closed,
// which would make the thousands of writes of the damage test wait for the disk.
void writeBytes(const fs::path& path, const std::string& bytes) {
  fs::remove(path);
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A copy of a chunk file rewritten by OpenVDB itself with `change` made to its metadata and grids,
// then sealed as voxflame would: intact, but wrong in that one way. (OpenVDB reads the chunk file
// despite its trailer, as any other program would.)
void tamperVdb(const fs::path& good, const fs::path& out,
               const std::function<void(openvdb::MetaMap&, openvdb::GridPtrVec&)>& change) {
  openvdb::initialize();
  openvdb::io::File in(good.string());
  in.open(false);
  openvdb::MetaMap meta = *in.getMetadata();
  openvdb::GridPtrVec grids = *in.getGrids();
  in.close();
  change(meta, grids);
  openvdb::io::File file(out.string());
  file.write(grids, meta);
  file.close();
  detail::sealChunkFile(out);
}

// `header` less one attribute. (OpenEXR 3.1's Header::erase leaks the attribute it removes.)
Imf::Header without(const Imf::Header& header, const char* name) {
  Imf::Header out;
  for (auto it = header.begin(); it != header.end(); ++it)
    if (std::string(it.name()) != name) out.insert(it.name(), it.attribute());
  return out;
}

// The same for an image chunk, by OpenEXR.
void tamperExr(const fs::path& good, const fs::path& out, const std::function<void(Imf::Header&)>& change) {
  Imf::InputFile in(good.c_str());
  Imf::Header header = in.header();
  const Imath::Box2i window = header.dataWindow();
  const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
  std::vector<std::uint32_t> pixels(4 * static_cast<std::size_t>(width) * height);
  const auto frameOf = [&](const Imf::ChannelList& channels) {
    Imf::FrameBuffer frame;
    int c = 0;
    for (auto it = channels.begin(); it != channels.end() && c < 4; ++it, ++c)
      frame.insert(it.name(), Imf::Slice(it.channel().type, reinterpret_cast<char*>(pixels.data() + c),
                                         4 * sizeof(std::uint32_t), 4 * sizeof(std::uint32_t) * width));
    return frame;
  };
  in.setFrameBuffer(frameOf(header.channels()));
  in.readPixels(window.min.y, window.max.y);
  change(header);
  {
    Imf::OutputFile file(out.c_str(), header);
    file.setFrameBuffer(frameOf(header.channels()));
    file.writePixels(height);
  }
  detail::sealChunkFile(out);
}

}  // namespace

TEST(ChunkIo, GridRoundTripIsExactWithAColourCellPerVoxel) {
  TemporaryFolder folder;
  const GridSums sums = randomGridSums({20, 16, 12}, 0, 0.3, 1);
  const ChunkLabel label = testLabel();
  writeGridChunk(folder / "chunk.vdb", sums, label);
  ChunkLabel found;
  const GridSums back = readGridChunk(folder / "chunk.vdb", found);
  EXPECT_TRUE(sameGridSums(sums, back));
  EXPECT_EQ(back.colour.size, glm::ivec3(20, 16, 12));
  expectSameLabel(label, found);
  expectSameLabel(label, readChunkLabel(folder / "chunk.vdb"));
  // Written atomically: nothing but the file is left in the folder.
  EXPECT_EQ(filesStartingWith(folder.path(), "chunk"), std::vector<std::string>{"chunk.vdb"});
}

TEST(ChunkIo, GridRoundTripIsExactWithColourCellsOf2x2x2Voxels) {
  TemporaryFolder folder;
  for (const glm::ivec3 size : {glm::ivec3(20, 16, 12), glm::ivec3(21, 15, 13)}) {
    const GridSums sums = randomGridSums(size, 1, 0.3, 2);
    writeGridChunk(folder / "chunk.vdb", sums, testLabel());  // the second replaces the first
    ChunkLabel found;
    const GridSums back = readGridChunk(folder / "chunk.vdb", found);
    EXPECT_TRUE(sameGridSums(sums, back));
    EXPECT_EQ(back.colour.shift, 1);
    EXPECT_EQ(back.colour.size, colourCells(size, 1));
  }
}

TEST(ChunkIo, RandomSparseGridsRoundTrip) {
  TemporaryFolder folder;
  std::mt19937 random(7);
  for (int trial = 0; trial < 12; ++trial) {
    const glm::ivec3 size(1 + static_cast<int>(random() % 40), 1 + static_cast<int>(random() % 40),
                          1 + static_cast<int>(random() % 40));
    const double fraction = trial == 0 ? 0.0 : trial == 1 ? 1.0 : static_cast<double>(random() % 100) / 400.0;
    const GridSums sums = randomGridSums(size, static_cast<int>(random() % 2), fraction, 100 + trial);
    const ChunkLabel label = testLabel(trial, 12);
    writeGridChunk(folder / "random.vdb", sums, label);
    ChunkLabel found;
    EXPECT_TRUE(sameGridSums(sums, readGridChunk(folder / "random.vdb", found))) << "trial " << trial;
    expectSameLabel(label, found);
  }
}

TEST(ChunkIo, GridChunkIsAnOpenVdbFileWithSparseGrids) {
  TemporaryFolder folder;
  GridSums sums = randomGridSums({20, 16, 12}, 1, 0.0, 3);
  sums.hits[sums.geometry.index(3, 4, 5)] = 17;
  sums.colourPoints[2] = 17;
  writeGridChunk(folder / "chunk.vdb", sums, testLabel());
  openvdb::initialize();
  openvdb::io::File file((folder / "chunk.vdb").string());
  file.open(false);
  EXPECT_EQ(file.getMetadata()->metaValue<std::string>("voxflame_preset"), testLabel().presetJson);
  const auto hits = openvdb::gridPtrCast<openvdb::Int32Grid>(file.readGrid("hits"));
  ASSERT_TRUE(hits);
  EXPECT_EQ(hits->activeVoxelCount(), 1u);
  EXPECT_EQ(hits->tree().getValue(openvdb::Coord(3, 4, 5)), 17);
  const auto points = openvdb::gridPtrCast<openvdb::Int64Grid>(file.readGrid("colour_points"));
  ASSERT_TRUE(points);
  EXPECT_EQ(points->activeVoxelCount(), 1u);
  EXPECT_EQ(points->tree().getValue(openvdb::Coord(2, 0, 0)), 17);
}

TEST(ChunkIo, ImageRoundTripIsExact) {
  TemporaryFolder folder;
  const ImageSums sums = randomImageSums(37, 23, 4);
  const ChunkLabel label = testLabel(0, 1);
  writeImageChunk(folder / "chunk.exr", sums, label);
  ChunkLabel found;
  EXPECT_TRUE(sameImageSums(sums, readImageChunk(folder / "chunk.exr", found)));
  expectSameLabel(label, found);
  expectSameLabel(label, readChunkLabel(folder / "chunk.exr"));
  EXPECT_EQ(filesStartingWith(folder.path(), "chunk"), std::vector<std::string>{"chunk.exr"});

  // An ordinary OpenEXR file to other programs: four UINT channels, ZIP.
  Imf::InputFile file((folder / "chunk.exr").c_str());
  EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
  for (const char* name : {"R", "G", "B", "D"}) {
    const Imf::Channel* channel = file.header().channels().findChannel(name);
    ASSERT_NE(channel, nullptr) << name;
    EXPECT_EQ(channel->type, Imf::UINT);
  }
}

TEST(ChunkIo, LargePresetsRoundTrip) {
  TemporaryFolder folder;
  ChunkLabel label = testLabel();
  label.presetJson = "{\"notes\": \"" + std::string(200000, 'x') + "\"}";
  writeGridChunk(folder / "big.vdb", randomGridSums({8, 8, 8}, 0, 0.5, 5), label);
  writeImageChunk(folder / "big.exr", randomImageSums(5, 3, 5), label);
  expectSameLabel(label, readChunkLabel(folder / "big.vdb"));
  expectSameLabel(label, readChunkLabel(folder / "big.exr"));
}

TEST(ChunkIo, WritersRefuseSumsThatDoNotMatchTheirShape) {
  TemporaryFolder folder;
  const fs::path path = folder / "bad.vdb";
  const auto refusal = [&](const GridSums& sums, const ChunkLabel& label = testLabel()) {
    return errorOf([&] { writeGridChunk(path, sums, label); });
  };
  GridSums sums = randomGridSums({20, 16, 12}, 0, 0.1, 6);
  sums.hits.pop_back();
  EXPECT_NE(refusal(sums).find("3839 hit counts for 3840 voxels"), std::string::npos) << refusal(sums);
  sums = randomGridSums({20, 16, 12}, 1, 0.1, 6);
  sums.colour.size = glm::ivec3(20, 16, 12);
  EXPECT_NE(refusal(sums).find("do not cover"), std::string::npos) << refusal(sums);
  sums = randomGridSums({20, 16, 12}, 0, 0.1, 6);
  sums.blue.resize(5);
  EXPECT_NE(refusal(sums).find("5 colour sums"), std::string::npos) << refusal(sums);
  sums = randomGridSums({20, 16, 12}, 0, 0.1, 6);
  sums.hits[7] = 0x80000000u;
  EXPECT_NE(refusal(sums).find("2^31"), std::string::npos) << refusal(sums);
  sums = randomGridSums({20, 16, 12}, 0, 0.1, 6);
  EXPECT_NE(refusal(sums, testLabel(5, 5)).find("chunk 5 of 5"), std::string::npos);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(filesStartingWith(folder.path(), "bad").empty());

  ImageSums image = randomImageSums(37, 23, 6);
  image.counts.pop_back();
  const std::string message = errorOf([&] { writeImageChunk(folder / "bad.exr", image, testLabel()); });
  EXPECT_NE(message.find("3403 counts for 851 pixels"), std::string::npos) << message;
  EXPECT_NE(message.find("bad.exr"), std::string::npos) << message;
  image = randomImageSums(37, 23, 6);
  image.unit = 0.0;
  EXPECT_NE(errorOf([&] { writeImageChunk(folder / "bad.exr", image, testLabel()); }).find("unit"), std::string::npos);
}

TEST(ChunkIo, ReadersRefuseFilesThatAreNotChunks) {
  TemporaryFolder folder;
  ChunkLabel label;
  const std::string missing = errorOf([&] { readGridChunk(folder / "missing.vdb", label); });
  EXPECT_NE(missing.find("missing.vdb"), std::string::npos) << missing;
  EXPECT_NE(missing.find("No such file"), std::string::npos) << missing;

  writeBytes(folder / "text.vdb", "this is not a chunk file, nor anything else; long enough for a trailer");
  const std::string text = errorOf([&] { readGridChunk(folder / "text.vdb", label); });
  EXPECT_NE(text.find("text.vdb"), std::string::npos) << text;
  EXPECT_NE(text.find("trailer"), std::string::npos) << text;
  EXPECT_NE(errorOf([&] { readChunkLabel(folder / "text.vdb"); }).find("trailer"), std::string::npos);
  writeBytes(folder / "empty.exr", "");
  EXPECT_NE(errorOf([&] { readChunkLabel(folder / "empty.exr"); }).find("too short"), std::string::npos);

  writeImageChunk(folder / "image.exr", randomImageSums(4, 4, 8), testLabel());
  writeGridChunk(folder / "grid.vdb", randomGridSums({4, 4, 4}, 0, 0.5, 8), testLabel());
  const std::string swapped = errorOf([&] { readGridChunk(folder / "image.exr", label); });
  EXPECT_NE(swapped.find("holds a points-method chunk (.exr), not a volume-method chunk"), std::string::npos)
      << swapped;
  EXPECT_NE(errorOf([&] { readImageChunk(folder / "grid.vdb", label); }).find("holds a volume-method chunk"),
            std::string::npos);
  fs::copy_file(folder / "grid.vdb", folder / "grid.exr");
  EXPECT_NE(errorOf([&] { readChunkLabel(folder / "grid.exr"); }).find("holds a volume-method chunk"),
            std::string::npos);
  fs::copy_file(folder / "grid.vdb", folder / "grid.txt");
  EXPECT_NE(errorOf([&] { readChunkLabel(folder / "grid.txt"); }).find(".vdb"), std::string::npos);
}

TEST(ChunkIo, GridReaderRefusesIntactFilesWithWrongContent) {
  TemporaryFolder folder;
  const fs::path good = folder / "good.vdb", bad = folder / "bad.vdb";
  writeGridChunk(good, randomGridSums({20, 16, 12}, 1, 0.2, 9), testLabel());
  const auto refusal = [&](const std::function<void(openvdb::MetaMap&, openvdb::GridPtrVec&)>& change) {
    tamperVdb(good, bad, change);
    ChunkLabel label;
    const std::string message = errorOf([&] { readGridChunk(bad, label); });
    if (!message.empty()) {
      EXPECT_NE(message.find("'" + bad.string() + "'"), std::string::npos) << message;
    }
    return message;
  };
  const auto grid = [](openvdb::GridPtrVec& grids, const std::string& name) {
    for (auto& g : grids)
      if (g->getName() == name) return g;
    return openvdb::GridBase::Ptr();
  };
  using openvdb::GridPtrVec;
  using openvdb::MetaMap;

  // The sealed but unchanged copy reads: the refusals below are the changes'.
  EXPECT_EQ(refusal([](MetaMap&, GridPtrVec&) {}), "");
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_chunks");
            }).find("its metadata has no 'voxflame_chunks'"),
            std::string::npos);
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_chunk");
              m.insertMeta("voxflame_chunk", openvdb::StringMetadata("2"));
            }).find("'voxflame_chunk' is a string, not a int32"),
            std::string::npos);
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_chunk");
              m.insertMeta("voxflame_chunk", openvdb::Int32Metadata(5));
            }).find("chunk index 5 is not one of its 5 chunks (0 to 4)"),
            std::string::npos);
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_width");
              m.insertMeta("voxflame_width", openvdb::Int32Metadata(0));
            }).find("image size 0×720"),
            std::string::npos);
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_points");
              m.insertMeta("voxflame_points", openvdb::Int64Metadata(-1));
            }).find("'voxflame_points' is negative"),
            std::string::npos);
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_colour_size");
              m.insertMeta("voxflame_colour_size", openvdb::Vec3IMetadata(openvdb::Vec3i(20, 16, 12)));
            }).find("colour cells (20×16×12) do not cover its grid of 20×16×12 voxels at shift 1"),
            std::string::npos);
  // An absurd size is refused before anything is allocated.
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_grid_size");
              m.insertMeta("voxflame_grid_size", openvdb::Vec3IMetadata(openvdb::Vec3i(4000, 4000, 4000)));
              m.removeMeta("voxflame_colour_size");
              m.insertMeta("voxflame_colour_size", openvdb::Vec3IMetadata(openvdb::Vec3i(2000, 2000, 2000)));
            }).find("absurdly large"),
            std::string::npos);
  EXPECT_NE(refusal([](MetaMap& m, GridPtrVec&) {
              m.removeMeta("voxflame_voxel_size");
              m.insertMeta("voxflame_voxel_size", openvdb::DoubleMetadata(-0.5));
            }).find("voxel size"),
            std::string::npos);
  EXPECT_NE(refusal([&](MetaMap&, GridPtrVec& g) {
              g.erase(std::find(g.begin(), g.end(), grid(g, "hits")));
            }).find("it has no grid 'hits'"),
            std::string::npos);
  EXPECT_NE(refusal([&](MetaMap&, GridPtrVec& g) {
              const auto floats = openvdb::FloatGrid::create(0.0f);
              floats->setName("green");
              g.erase(std::find(g.begin(), g.end(), grid(g, "green")));
              g.push_back(floats);
            }).find("grid 'green' is a Tree_float_5_4_3 grid, not a Tree_int64_5_4_3 grid"),
            std::string::npos);
  EXPECT_NE(refusal([&](MetaMap&, GridPtrVec& g) {
              openvdb::gridPtrCast<openvdb::Int32Grid>(grid(g, "hits"))->tree().setValue(openvdb::Coord(20, 0, 0), 3);
            }).find("grid 'hits' has a voxel at (20, 0, 0), outside its 20×16×12 cells"),
            std::string::npos);
  EXPECT_NE(refusal([&](MetaMap&, GridPtrVec& g) {
              openvdb::gridPtrCast<openvdb::Int64Grid>(grid(g, "red"))->tree().setValue(openvdb::Coord(0, 0, -1), 3);
            }).find("outside its 10×8×6 cells"),
            std::string::npos);
  EXPECT_NE(refusal([&](MetaMap&, GridPtrVec& g) {
              openvdb::gridPtrCast<openvdb::Int32Grid>(grid(g, "hits"))->tree().setValue(openvdb::Coord(1, 2, 3), -4);
            }).find("grid 'hits' has a negative value (-4)"),
            std::string::npos);
  // A tile (voxflame writes none) is read where it lies inside the grid and refused where not.
  EXPECT_EQ(refusal([&](MetaMap&, GridPtrVec& g) {
              openvdb::gridPtrCast<openvdb::Int32Grid>(grid(g, "hits"))->tree().addTile(1, openvdb::Coord(0), 5, true);
            }),
            "");
  EXPECT_NE(refusal([&](MetaMap&, GridPtrVec& g) {
              openvdb::gridPtrCast<openvdb::Int32Grid>(grid(g, "hits"))->tree().addTile(2, openvdb::Coord(0), 5, true);
            }).find("tile outside"),
            std::string::npos);
}

TEST(ChunkIo, ImageReaderRefusesIntactFilesWithWrongContent) {
  TemporaryFolder folder;
  const fs::path good = folder / "good.exr", bad = folder / "bad.exr";
  writeImageChunk(good, randomImageSums(37, 23, 10), testLabel());
  const auto refusal = [&](const std::function<void(Imf::Header&)>& change) {
    tamperExr(good, bad, change);
    ChunkLabel label;
    const std::string message = errorOf([&] { readImageChunk(bad, label); });
    if (!message.empty()) {
      EXPECT_NE(message.find("'" + bad.string() + "'"), std::string::npos) << message;
    }
    return message;
  };
  EXPECT_EQ(refusal([](Imf::Header&) {}), "");
  EXPECT_NE(refusal([](Imf::Header& h) { h = without(h, "voxflame_unit"); }).find("its header has no 'voxflame_unit'"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              h = without(h, "voxflame_unit");
              h.insert("voxflame_unit", Imf::StringAttribute("0.5"));
            }).find("'voxflame_unit' is a string, not a double"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) { h.insert("voxflame_unit", Imf::DoubleAttribute(-1.0)); }).find("unit"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              h.insert("voxflame_points", Imf::StringAttribute("12 points"));
            }).find("'voxflame_points' is not a whole number"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              h.insert("voxflame_iterations", Imf::StringAttribute("-3"));
            }).find("'voxflame_iterations' is not a whole number"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              h.insert("voxflame_chunk", Imf::IntAttribute(-1));
            }).find("chunk index -1 is not one of its 5 chunks"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) { h.insert("voxflame_chunks", Imf::IntAttribute(0)); }).find("0 chunks"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              h.insert("voxflame_height", Imf::IntAttribute(-720));
            }).find("image size 1280×-720"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              Imf::ChannelList channels;
              for (const char* name : {"R", "G", "B", "Z"}) channels.insert(name, Imf::Channel(Imf::UINT));
              h.channels() = channels;
            }).find("no channel 'D'"),
            std::string::npos);
  EXPECT_NE(refusal([](Imf::Header& h) {
              Imf::ChannelList channels;
              for (const char* name : {"R", "G", "B"}) channels.insert(name, Imf::Channel(Imf::UINT));
              channels.insert("D", Imf::Channel(Imf::FLOAT));
              h.channels() = channels;
            }).find("channel 'D' is not UINT"),
            std::string::npos);
  // readChunkLabel checks the label as thoroughly.
  tamperExr(good, bad, [](Imf::Header& h) { h = without(h, "voxflame_preset"); });
  EXPECT_NE(errorOf([&] { readChunkLabel(bad); }).find("no 'voxflame_preset'"), std::string::npos);
}

// Every truncation and many flipped bytes of both kinds: each read either gives back exactly what
// was written or throws core::Error (any other exception, a crash or a hang fails the test).
TEST(ChunkIo, DamagedFilesAreRefusedNeverMisread) {
  TemporaryFolder folder;
  const GridSums grid = randomGridSums({20, 16, 12}, 1, 0.2, 11);
  const ImageSums image = randomImageSums(37, 23, 11);
  const ChunkLabel label = testLabel();
  writeGridChunk(folder / "good.vdb", grid, label);
  writeImageChunk(folder / "good.exr", image, label);

  for (const std::string extension : {".vdb", ".exr"}) {
    const std::string good = fileBytes(folder / ("good" + extension));
    const fs::path damaged = folder / ("damaged" + extension);
    int reads = 0, refused = 0;
    const auto check = [&](const std::string& bytes, const std::string& what) {
      writeBytes(damaged, bytes);
      ChunkLabel found;
      try {
        if (extension == ".vdb") {
          EXPECT_TRUE(sameGridSums(grid, readGridChunk(damaged, found))) << what;
        } else {
          EXPECT_TRUE(sameImageSums(image, readImageChunk(damaged, found))) << what;
        }
        expectSameLabel(label, found);
        ++reads;
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(damaged.string()), std::string::npos) << e.what();
        ++refused;
      }
      try {
        expectSameLabel(label, readChunkLabel(damaged));
      } catch (const Error&) {
      }
    };
    // Truncated at every length near either end, and at 300 lengths in between.
    const std::size_t size = good.size();
    for (std::size_t length = 0; length < size; ++length)
      if (length < 256 || size - length < 256 || length % (size / 300 + 1) == 0)
        check(good.substr(0, length), "truncated to " + std::to_string(length));
    // Single bit flips and random bytes at 600 random places, and at every byte of the trailer.
    std::mt19937 random(12);
    for (int trial = 0; trial < 600; ++trial) {
      std::string bytes = good;
      const std::size_t at = random() % size;
      bytes[at] = static_cast<char>(trial % 2 ? bytes[at] ^ (1 << (random() % 8)) : static_cast<char>(random()));
      check(bytes, "byte " + std::to_string(at) + " changed");
    }
    for (std::size_t at = size - 40; at < size; ++at) {
      std::string bytes = good;
      bytes[at] = static_cast<char>(bytes[at] ^ 0x10);
      check(bytes, "trailer byte " + std::to_string(at) + " changed");
    }
    // The only damage a read survives is to the trailer's checksum of the header, which a
    // whole read does not need; a changed random byte may also happen to be the same byte.
    EXPECT_GT(refused, 900) << extension;
    EXPECT_LT(reads, 20) << extension;
  }
}
