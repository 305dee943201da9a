// Chunk checkpoint files (chunk_io.h). Like vdb_export.cpp this translation unit includes OpenVDB
// (its headers are heavy): the two are the only ones.
#include "chunk_io.h"

// Header-only: the hash is compiled in, so the binary needs no libxxhash at run time.
#define XXH_INLINE_ALL
#include <xxhash.h>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "error.h"
#include "file_output.h"

namespace voxflame::core {

namespace {

namespace fs = std::filesystem;

// Sizes past this many values are refused before anything is allocated: a damaged size must not
// make a reader ask for terabytes.
constexpr double kMaxValues = 1e9;
// Beyond 2^10 voxels per colour cell along an axis a layout is nonsense (the accumulator uses 0 and 1).
constexpr int kMaxColourShift = 10;
constexpr int kChunkFormat = 1;

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw Error("cannot read chunk file '" + path.string() + "': " + why);
}
[[noreturn]] void refuseToWrite(const fs::path& path, const std::string& why) {
  throw Error("cannot write chunk file '" + path.string() + "': " + why);
}

// ---- The trailer and its checksum -------------------------------------------------------------

// XXH64 (Debian's libxxhash, inlined): fast enough that checking a file costs far less than reading
// it, and any damage short of a deliberate forgery changes it.
std::uint64_t checksum(std::string_view bytes) {
  return XXH64(bytes.data(), bytes.size(), 0);
}

std::uint64_t load64(const char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return v;
}
std::uint32_t load32(const char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  return v;
}
enum class ChunkKind : std::uint32_t { Grid = 1, Image = 2 };
const char* describe(ChunkKind kind) {
  return kind == ChunkKind::Grid ? "a volume-method chunk (.vdb)" : "a points-method chunk (.exr)";
}

constexpr std::size_t kTrailerSize = 40;
constexpr std::string_view kTrailerMagic = "VXFCHUNK";

struct Trailer {
  std::uint64_t labelEnd = 0, labelHash = 0, bodyHash = 0;
  std::uint32_t format = kChunkFormat;
  ChunkKind kind = ChunkKind::Grid;
};

void put64(char* p, std::uint64_t v) {
  for (int b = 0; b < 8; ++b) p[b] = static_cast<char>(v >> (8 * b));
}
void put32(char* p, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) p[b] = static_cast<char>(v >> (8 * b));
}

// The whole content of a file; false (with errno set where the system said why) when it cannot be read.
bool readWholeFile(const fs::path& path, std::string& bytes) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) return false;
  bytes.resize(static_cast<std::size_t>(size));
  in.seekg(0);
  in.read(bytes.data(), size);
  return in.gcount() == size;
}

std::string systemReason(const char* otherwise) {
  return errno ? std::strerror(errno) : otherwise;
}

// Appends the trailer to what a library wrote to `temporary`; `labelEndOf` finds where the
// file's header ends in those bytes.
void appendTrailer(const fs::path& path, const fs::path& temporary, ChunkKind kind,
                   const std::function<std::uint64_t(const std::string&)>& labelEndOf) {
  std::string bytes;
  if (!readWholeFile(temporary, bytes))
    refuseToWrite(path, "reading the written file back failed: " + systemReason("short read"));
  const std::uint64_t labelEnd = labelEndOf(bytes);
  if (labelEnd == 0 || labelEnd > bytes.size()) refuseToWrite(path, "the written file's header was not where expected");
  std::array<char, kTrailerSize> trailer{};
  put64(&trailer[0], labelEnd);
  put64(&trailer[8], checksum(std::string_view(bytes).substr(0, labelEnd)));
  put64(&trailer[16], checksum(bytes));
  put32(&trailer[24], kChunkFormat);
  put32(&trailer[28], static_cast<std::uint32_t>(kind));
  std::memcpy(&trailer[32], kTrailerMagic.data(), 8);
  std::ofstream out(temporary, std::ios::binary | std::ios::app);
  out.write(trailer.data(), static_cast<std::streamsize>(trailer.size()));
  out.close();
  if (!out) refuseToWrite(path, "appending its trailer failed");
}

Trailer parseTrailer(const fs::path& path, const char* p, std::uint64_t fileSize, ChunkKind expected) {
  if (std::string_view(p + 32, 8) != kTrailerMagic)
    refuse(path, "it does not end in a voxflame chunk trailer (an incomplete or damaged file, or not a chunk file)");
  Trailer t;
  t.labelEnd = load64(p);
  t.labelHash = load64(p + 8);
  t.bodyHash = load64(p + 16);
  t.format = load32(p + 24);
  const std::uint32_t kind = load32(p + 28);
  if (t.format != kChunkFormat)
    refuse(path, "it is in chunk format " + std::to_string(t.format) + ", this voxflame reads format " +
                     std::to_string(kChunkFormat));
  if (kind != static_cast<std::uint32_t>(ChunkKind::Grid) && kind != static_cast<std::uint32_t>(ChunkKind::Image))
    refuse(path, "its trailer names an unknown kind of chunk (" + std::to_string(kind) + ")");
  t.kind = static_cast<ChunkKind>(kind);
  if (t.kind != expected) refuse(path, std::string("it holds ") + describe(t.kind) + ", not " + describe(expected));
  if (t.labelEnd == 0 || t.labelEnd > fileSize - kTrailerSize) refuse(path, "its trailer is damaged");
  return t;
}

// The whole file, checked: what precedes the trailer, exactly as the library wrote it.
std::string readCheckedBody(const fs::path& path, ChunkKind kind) {
  std::string bytes;
  if (!readWholeFile(path, bytes)) refuse(path, systemReason("reading it failed"));
  if (bytes.size() <= kTrailerSize)
    refuse(path, "it is too short to be a chunk file (" + std::to_string(bytes.size()) + " bytes)");
  const Trailer t = parseTrailer(path, bytes.data() + bytes.size() - kTrailerSize, bytes.size(), kind);
  bytes.resize(bytes.size() - kTrailerSize);
  if (checksum(bytes) != t.bodyHash) refuse(path, "it is damaged (its checksum does not match its content)");
  return bytes;
}

// Only the file's header (with the label), checked, and nothing of the sums.
std::string readCheckedLabelPart(const fs::path& path, ChunkKind kind) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, systemReason("it cannot be opened"));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) refuse(path, "its size cannot be told");
  if (static_cast<std::uint64_t>(size) <= kTrailerSize)
    refuse(path, "it is too short to be a chunk file (" + std::to_string(size) + " bytes)");
  std::array<char, kTrailerSize> trailer{};
  in.seekg(size - static_cast<std::streamoff>(kTrailerSize));
  in.read(trailer.data(), static_cast<std::streamsize>(kTrailerSize));
  if (!in) refuse(path, "reading its trailer failed");
  const Trailer t = parseTrailer(path, trailer.data(), static_cast<std::uint64_t>(size), kind);
  std::string bytes(static_cast<std::size_t>(t.labelEnd), '\0');
  in.seekg(0);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!in) refuse(path, "reading its header failed");
  if (checksum(bytes) != t.labelHash) refuse(path, "its header is damaged (its checksum does not match)");
  return bytes;
}

void checkLabel(const fs::path& path, const ChunkLabel& label) {
  if (label.backend != "cpu" && label.backend != "gpu")
    refuse(path, "it names a refinement backend '" + label.backend + "' that voxflame does not know");
  if (label.chunks < 1) refuse(path, "it says the render has " + std::to_string(label.chunks) + " chunks");
  if (label.chunk < 0 || label.chunk >= label.chunks)
    refuse(path, "its chunk index " + std::to_string(label.chunk) + " is not one of its " +
                     std::to_string(label.chunks) + " chunks (0 to " + std::to_string(label.chunks - 1) + ")");
  if (label.width <= 0 || label.height <= 0)
    refuse(path,
           "its image size " + std::to_string(label.width) + "×" + std::to_string(label.height) + " is not positive");
}

void checkLabelToWrite(const fs::path& path, const ChunkLabel& label) {
  if (label.chunks < 1 || label.chunk < 0 || label.chunk >= label.chunks)
    refuseToWrite(path, "chunk " + std::to_string(label.chunk) + " of " + std::to_string(label.chunks) +
                            " is not a chunk of the render");
  if (label.width <= 0 || label.height <= 0) refuseToWrite(path, "the render's size is not positive");
}

// ---- Volume method: OpenVDB --------------------------------------------------------------------

constexpr const char* kHitsGrid = "hits";
constexpr std::array<const char*, 4> kColourGrids = {"red", "green", "blue", "colour_points"};

// A metadata value of type T, refusing a missing key or another type.
template <class T>
T metaValue(const fs::path& path, const openvdb::MetaMap& meta, const std::string& name) {
  const openvdb::Metadata::ConstPtr any = meta[name];
  if (!any) refuse(path, "its metadata has no '" + name + "'");
  const auto typed = meta.getMetadata<openvdb::TypedMetadata<T>>(name);
  if (!typed)
    refuse(path, "its metadata '" + name + "' is a " + any->typeName() + ", not a " +
                     openvdb::TypedMetadata<T>::staticTypeName());
  return typed->value();
}

std::uint64_t counterValue(const fs::path& path, const openvdb::MetaMap& meta, const std::string& name) {
  const std::int64_t v = metaValue<std::int64_t>(path, meta, name);
  if (v < 0) refuse(path, "its metadata '" + name + "' is negative (" + std::to_string(v) + ")");
  return static_cast<std::uint64_t>(v);
}

ChunkLabel labelFromVdb(const fs::path& path, const openvdb::MetaMap& meta) {
  const std::int32_t format = metaValue<std::int32_t>(path, meta, "voxflame_chunk_format");
  if (format != kChunkFormat) refuse(path, "it is in chunk format " + std::to_string(format));
  ChunkLabel label;
  label.presetJson = metaValue<std::string>(path, meta, "voxflame_preset");
  label.chunk = metaValue<std::int32_t>(path, meta, "voxflame_chunk");
  label.chunks = metaValue<std::int32_t>(path, meta, "voxflame_chunks");
  label.width = metaValue<std::int32_t>(path, meta, "voxflame_width");
  label.height = metaValue<std::int32_t>(path, meta, "voxflame_height");
  if (meta["voxflame_backend"]) label.backend = metaValue<std::string>(path, meta, "voxflame_backend");
  checkLabel(path, label);
  return label;
}

std::string vecText(const glm::ivec3& v) {
  return std::to_string(v.x) + "×" + std::to_string(v.y) + "×" + std::to_string(v.z);
}

glm::ivec3 colourSizeOf(const glm::ivec3& voxels, int shift) {
  const int span = 1 << shift;
  return (voxels + (span - 1)) / span;
}

double valueCount(const glm::ivec3& size) {
  return static_cast<double>(size.x) * static_cast<double>(size.y) * static_cast<double>(size.z);
}

// What a grid and colour layout must satisfy before anything of their size is allocated.
std::string geometryProblem(const GridGeometry& g, const ColourLayout& colour) {
  if (g.size.x <= 0 || g.size.y <= 0 || g.size.z <= 0) return "its grid of " + vecText(g.size) + " voxels is empty";
  if (valueCount(g.size) > kMaxValues) return "its grid of " + vecText(g.size) + " voxels is absurdly large";
  if (!std::isfinite(g.origin.x) || !std::isfinite(g.origin.y) || !std::isfinite(g.origin.z))
    return "its grid's origin is not finite";
  if (!std::isfinite(g.voxelSize) || !(g.voxelSize > 0.0)) return "its voxel size is not a positive number";
  if (colour.shift < 0 || colour.shift > kMaxColourShift)
    return "its colour shift " + std::to_string(colour.shift) + " is not between 0 and " +
           std::to_string(kMaxColourShift);
  if (colour.size != colourSizeOf(g.size, colour.shift))
    return "its colour cells (" + vecText(colour.size) + ") do not cover its grid of " + vecText(g.size) +
           " voxels at shift " + std::to_string(colour.shift);
  return {};
}

// ... and the sums: every array the size its grid says.
std::string shapeProblem(const GridSums& sums) {
  if (std::string problem = geometryProblem(sums.geometry, sums.colour); !problem.empty()) return problem;
  if (sums.hits.size() != sums.geometry.voxelCount())
    return "it has " + std::to_string(sums.hits.size()) + " hit counts for " +
           std::to_string(sums.geometry.voxelCount()) + " voxels";
  const std::size_t cells = sums.colour.cellCount();
  for (const auto* v : {&sums.red, &sums.green, &sums.blue, &sums.colourPoints})
    if (v->size() != cells)
      return "it has " + std::to_string(v->size()) + " colour sums for " + std::to_string(cells) + " colour cells";
  return {};
}

// Sets the non-zero values of `values` (x fastest over `size`) active in `grid`, one 8³ block at a
// time: each leaf node is found once and then written directly, instead of a tree descent per voxel.
// False when a value does not fit the grid's (signed) type.
template <class GridT, class T>
bool fillGrid(GridT& grid, const glm::ivec3& size, const std::vector<T>& values) {
  using Leaf = typename GridT::TreeType::LeafNodeType;
  using Value = typename GridT::ValueType;
  constexpr int kDim = static_cast<int>(Leaf::DIM);
  constexpr T kLimit = static_cast<T>(std::numeric_limits<Value>::max());
  auto accessor = grid.getAccessor();
  const std::size_t rowStride = static_cast<std::size_t>(size.x);
  const std::size_t sliceStride = rowStride * static_cast<std::size_t>(size.y);
  for (int bz = 0; bz < size.z; bz += kDim)
    for (int by = 0; by < size.y; by += kDim)
      for (int bx = 0; bx < size.x; bx += kDim) {
        Leaf* leaf = nullptr;
        const int ez = std::min(bz + kDim, size.z), ey = std::min(by + kDim, size.y), ex = std::min(bx + kDim, size.x);
        for (int k = bz; k < ez; ++k)
          for (int j = by; j < ey; ++j) {
            const T* row =
                values.data() + static_cast<std::size_t>(k) * sliceStride + static_cast<std::size_t>(j) * rowStride;
            for (int i = bx; i < ex; ++i) {
              const T v = row[i];
              if (v == 0) continue;
              if (v > kLimit) return false;
              if (!leaf) leaf = accessor.touchLeaf(openvdb::Coord(bx, by, bz));
              leaf->setValueOn(Leaf::coordToOffset(openvdb::Coord(i, j, k)), static_cast<Value>(v));
            }
          }
      }
  return true;
}

// The active values of `grid` into `values` (x fastest over `size`; inactive ones stay 0). A
// voxel outside the grid or a negative value is refused. Tiles (which voxflame never writes) are
// filled too, clipped to the grid first, so a reader's work is bounded by the grid's size.
template <class GridT, class T>
void readGrid(const fs::path& path, const GridT& grid, const glm::ivec3& size, std::vector<T>& values) {
  using Value = typename GridT::ValueType;
  const std::string name = grid.getName();
  if (grid.background() != Value(0)) refuse(path, "grid '" + name + "' has a background other than 0");
  const openvdb::CoordBBox bounds(openvdb::Coord(0, 0, 0), openvdb::Coord(size.x - 1, size.y - 1, size.z - 1));
  const auto index = [&](const openvdb::Coord& c) {
    return static_cast<std::size_t>(c.x()) +
           static_cast<std::size_t>(size.x) *
               (static_cast<std::size_t>(c.y()) + static_cast<std::size_t>(size.y) * static_cast<std::size_t>(c.z()));
  };
  const auto store = [&](const openvdb::Coord& c, Value v) {
    if (v < 0) refuse(path, "grid '" + name + "' has a negative value (" + std::to_string(v) + ")");
    values[index(c)] = static_cast<T>(v);
  };
  const auto& tree = grid.tree();
  for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) {
    const bool inside = bounds.isInside(leaf->getNodeBoundingBox());
    for (auto it = leaf->cbeginValueOn(); it; ++it) {
      const openvdb::Coord c = it.getCoord();
      if (!inside && !bounds.isInside(c))
        refuse(path, "grid '" + name + "' has a voxel at (" + std::to_string(c.x()) + ", " + std::to_string(c.y()) +
                         ", " + std::to_string(c.z()) + "), outside its " + vecText(size) + " cells");
      store(c, *it);
    }
  }
  auto tile = tree.cbeginValueOn();
  tile.setMaxDepth(std::remove_cvref_t<decltype(tree)>::ValueOnCIter::LEAF_DEPTH - 1);
  for (; tile; ++tile) {
    openvdb::CoordBBox box;
    tile.getBoundingBox(box);
    if (!bounds.isInside(box)) refuse(path, "grid '" + name + "' has a tile outside its " + vecText(size) + " cells");
    for (int k = box.min().z(); k <= box.max().z(); ++k)
      for (int j = box.min().y(); j <= box.max().y(); ++j)
        for (int i = box.min().x(); i <= box.max().x(); ++i) store(openvdb::Coord(i, j, k), *tile);
  }
}

openvdb::MetaMap vdbFileMetadata(const GridSums& sums, const ChunkLabel& label) {
  const GridGeometry& g = sums.geometry;
  openvdb::MetaMap meta;
  meta.insertMeta("creator", openvdb::StringMetadata("voxflame"));
  meta.insertMeta("voxflame_chunk_format", openvdb::Int32Metadata(kChunkFormat));
  meta.insertMeta("voxflame_preset", openvdb::StringMetadata(label.presetJson));
  meta.insertMeta("voxflame_chunk", openvdb::Int32Metadata(label.chunk));
  meta.insertMeta("voxflame_chunks", openvdb::Int32Metadata(label.chunks));
  meta.insertMeta("voxflame_width", openvdb::Int32Metadata(label.width));
  meta.insertMeta("voxflame_height", openvdb::Int32Metadata(label.height));
  meta.insertMeta("voxflame_backend", openvdb::StringMetadata(label.backend));
  meta.insertMeta("voxflame_points", openvdb::Int64Metadata(static_cast<std::int64_t>(sums.points)));
  meta.insertMeta("voxflame_iterations", openvdb::Int64Metadata(static_cast<std::int64_t>(sums.iterations)));
  meta.insertMeta("voxflame_inside_voxels", openvdb::Int64Metadata(static_cast<std::int64_t>(sums.insideVoxels)));
  meta.insertMeta("voxflame_grid_size", openvdb::Vec3IMetadata(openvdb::Vec3i(g.size.x, g.size.y, g.size.z)));
  meta.insertMeta("voxflame_grid_origin", openvdb::Vec3DMetadata(openvdb::Vec3d(g.origin.x, g.origin.y, g.origin.z)));
  meta.insertMeta("voxflame_voxel_size", openvdb::DoubleMetadata(g.voxelSize));
  meta.insertMeta("voxflame_colour_shift", openvdb::Int32Metadata(sums.colour.shift));
  const glm::ivec3& c = sums.colour.size;
  meta.insertMeta("voxflame_colour_size", openvdb::Vec3IMetadata(openvdb::Vec3i(c.x, c.y, c.z)));
  return meta;
}

// Where the file metadata ends in an archive with `meta`: the header and the metadata come first
// whether an archive is written to a file or a stream, so this is the length of an empty stream
// archive less its grid count.
std::uint64_t vdbLabelEnd(const openvdb::MetaMap& meta) {
  std::ostringstream os(std::ios::binary);
  openvdb::io::Stream(os).write(openvdb::GridCPtrVec{}, meta);
  return static_cast<std::uint64_t>(os.str().size()) - sizeof(std::int32_t);
}

// Index (i, j, k) of a grid whose cells span `span` voxels sits at the centre of its cell, as in
// vdb_export.cpp, so the grids line up with an exported volume in a 3D program. (Readers take the
// geometry from the file metadata, which holds it exactly.)
openvdb::math::Transform::Ptr cellTransform(const GridGeometry& g, int span) {
  const double edge = g.voxelSize * span;
  auto transform = openvdb::math::Transform::createLinearTransform(edge);
  const glm::dvec3 firstCentre = g.origin + 0.5 * edge;
  transform->postTranslate(openvdb::Vec3d(firstCentre.x, firstCentre.y, firstCentre.z));
  return transform;
}

openvdb::GridPtrVecPtr parseVdb(const fs::path& path, std::string bytes, openvdb::MetaMap::Ptr& meta) {
  openvdb::initialize();
  try {
    std::istringstream is(std::move(bytes), std::ios::binary);
    openvdb::io::Stream stream(is, /*delayLoad=*/false);
    meta = stream.getMetadata();
    if (!meta) refuse(path, "it has no file metadata");
    return stream.getGrids();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    refuse(path, std::string("OpenVDB cannot read it: ") + e.what());
  }
}

template <class GridT>
typename GridT::Ptr findGrid(const fs::path& path, const openvdb::GridPtrVec& grids, const std::string& name) {
  for (const openvdb::GridBase::Ptr& grid : grids) {
    if (!grid || grid->getName() != name) continue;
    auto typed = openvdb::gridPtrCast<GridT>(grid);
    if (!typed)
      refuse(path, "its grid '" + name + "' is a " + grid->type() + " grid, not a " + GridT::gridType() + " grid");
    return typed;
  }
  refuse(path, "it has no grid '" + name + "'");
}

// ---- Points method: OpenEXR --------------------------------------------------------------------

constexpr std::array<const char*, 4> kImageChannels = {"R", "G", "B", "D"};

// Bytes in memory as an OpenEXR input stream (checked bytes, read once, not read from disk again).
class MemoryStream final : public Imf::IStream {
 public:
  explicit MemoryStream(std::string_view bytes) : Imf::IStream("chunk"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || static_cast<std::uint64_t>(n) > bytes_.size() - position_)
      throw std::runtime_error("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
    position_ += static_cast<std::uint64_t>(n);
    return position_ < bytes_.size();
  }
  std::uint64_t tellg() override { return position_; }
  void seekg(std::uint64_t position) override { position_ = std::min<std::uint64_t>(position, bytes_.size()); }

 private:
  std::string_view bytes_;
  std::uint64_t position_ = 0;
};

template <class Attribute>
const auto& exrValue(const fs::path& path, const Imf::Header& header, const char* name) {
  const auto found = header.find(name);
  if (found == header.end()) refuse(path, std::string("its header has no '") + name + "'");
  const Imf::Attribute& any = found.attribute();
  const auto* typed = dynamic_cast<const Attribute*>(&any);
  if (!typed)
    refuse(path, std::string("its header's '") + name + "' is a " + any.typeName() + ", not a " +
                     Attribute::staticTypeName());
  return typed->value();
}

std::uint64_t exrCounter(const fs::path& path, const Imf::Header& header, const char* name) {
  const std::string& text = exrValue<Imf::StringAttribute>(path, header, name);
  std::uint64_t v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    refuse(path, std::string("its header's '") + name + "' is not a whole number (\"" + text.substr(0, 40) + "\")");
  return v;
}

ChunkLabel labelFromExr(const fs::path& path, const Imf::Header& header) {
  const int format = exrValue<Imf::IntAttribute>(path, header, "voxflame_chunk_format");
  if (format != kChunkFormat) refuse(path, "it is in chunk format " + std::to_string(format));
  ChunkLabel label;
  label.presetJson = exrValue<Imf::StringAttribute>(path, header, "voxflame_preset");
  label.chunk = exrValue<Imf::IntAttribute>(path, header, "voxflame_chunk");
  label.chunks = exrValue<Imf::IntAttribute>(path, header, "voxflame_chunks");
  label.width = exrValue<Imf::IntAttribute>(path, header, "voxflame_width");
  label.height = exrValue<Imf::IntAttribute>(path, header, "voxflame_height");
  if (header.find("voxflame_backend") != header.end())
    label.backend = exrValue<Imf::StringAttribute>(path, header, "voxflame_backend");
  checkLabel(path, label);
  return label;
}

// Where the header ends in an EXR file's bytes (magic number, version, attributes).
std::uint64_t exrHeaderEnd(const std::string& bytes, Imf::Header& header) {
  MemoryStream is(bytes);
  char magicAndVersion[8];
  is.read(magicAndVersion, 8);
  if (!Imf::isImfMagic(magicAndVersion)) throw std::runtime_error("not an OpenEXR file");
  int version = static_cast<int>(load32(magicAndVersion + 4));
  if (Imf::isMultiPart(version) || Imf::isNonImage(version))
    throw std::runtime_error("a multi-part or deep OpenEXR file");
  header.readFrom(is, version);
  return is.tellg();
}

}  // namespace

// ---- Public functions ----------------------------------------------------------------------------

void writeGridChunk(const fs::path& path, const GridSums& sums, const ChunkLabel& label) {
  if (const std::string problem = shapeProblem(sums); !problem.empty()) refuseToWrite(path, problem);
  checkLabelToWrite(path, label);
  // Stored values are never negative (what a 3D program shows is the count itself), so a value
  // must fit the signed type: always true in practice (hits carry the outside flag at 2^31).
  constexpr std::uint64_t kInt64Limit = std::uint64_t{1} << 63;
  if (sums.points >= kInt64Limit || sums.iterations >= kInt64Limit || sums.insideVoxels >= kInt64Limit)
    refuseToWrite(path, "a counter is 2^63 or more");
  openvdb::initialize();

  const GridGeometry& g = sums.geometry;
  const auto hits = openvdb::Int32Grid::create(0);
  hits->setName(kHitsGrid);
  hits->setTransform(cellTransform(g, 1));
  if (!fillGrid(*hits, g.size, sums.hits)) refuseToWrite(path, "a hit count is 2^31 or more");
  openvdb::GridCPtrVec grids{hits};
  const std::array<const std::vector<std::uint64_t>*, 4> colourSums = {&sums.red, &sums.green, &sums.blue,
                                                                       &sums.colourPoints};
  for (std::size_t c = 0; c < colourSums.size(); ++c) {
    const auto grid = openvdb::Int64Grid::create(0);
    grid->setName(kColourGrids[c]);
    grid->setTransform(cellTransform(g, 1 << sums.colour.shift));
    if (!fillGrid(*grid, sums.colour.size, *colourSums[c])) refuseToWrite(path, "a colour sum is 2^63 or more");
    grids.push_back(grid);
  }
  const openvdb::MetaMap meta = vdbFileMetadata(sums, label);
  const std::uint64_t labelEnd = vdbLabelEnd(meta);

  AtomicWriteOptions options;
  options.what = "cannot write chunk file";
  writeFileAtomicallyWith(
      path,
      [&](const fs::path& temporary) {
        // OpenVDB's default compression: Blosc where the library has it (as Debian's, Houdini's and
        // Blender's do), else ZIP. ZIP would make files a fifth smaller but takes five times as
        // long, as OpenVDB sets up zlib afresh for every 8³ leaf node.
        openvdb::io::File file(temporary.string());
        file.write(grids, meta);
        file.close();
        appendTrailer(path, temporary, ChunkKind::Grid, [&](const std::string&) { return labelEnd; });
      },
      options);
}

GridSums readGridChunk(const fs::path& path, ChunkLabel& label) {
  openvdb::MetaMap::Ptr meta;
  const openvdb::GridPtrVecPtr grids = parseVdb(path, readCheckedBody(path, ChunkKind::Grid), meta);
  label = labelFromVdb(path, *meta);

  GridSums sums;
  sums.points = counterValue(path, *meta, "voxflame_points");
  sums.iterations = counterValue(path, *meta, "voxflame_iterations");
  sums.insideVoxels = counterValue(path, *meta, "voxflame_inside_voxels");
  const openvdb::Vec3i size = metaValue<openvdb::Vec3i>(path, *meta, "voxflame_grid_size");
  const openvdb::Vec3d origin = metaValue<openvdb::Vec3d>(path, *meta, "voxflame_grid_origin");
  sums.geometry.size = glm::ivec3(size.x(), size.y(), size.z());
  sums.geometry.origin = glm::dvec3(origin.x(), origin.y(), origin.z());
  sums.geometry.voxelSize = metaValue<double>(path, *meta, "voxflame_voxel_size");
  sums.colour.shift = metaValue<std::int32_t>(path, *meta, "voxflame_colour_shift");
  const openvdb::Vec3i colourSize = metaValue<openvdb::Vec3i>(path, *meta, "voxflame_colour_size");
  sums.colour.size = glm::ivec3(colourSize.x(), colourSize.y(), colourSize.z());
  // The shape is checked before the arrays are allocated: a damaged size must not allocate terabytes.
  if (const std::string problem = geometryProblem(sums.geometry, sums.colour); !problem.empty()) refuse(path, problem);
  const auto hits = findGrid<openvdb::Int32Grid>(path, *grids, kHitsGrid);
  std::array<openvdb::Int64Grid::Ptr, 4> colourGrids;
  for (std::size_t c = 0; c < colourGrids.size(); ++c)
    colourGrids[c] = findGrid<openvdb::Int64Grid>(path, *grids, kColourGrids[c]);

  // Each grid's tree is dropped once copied: at 10% of 256³ voxels the trees are as large as the
  // arrays (600 MB), and the reader never needs both in full.
  sums.hits.assign(sums.geometry.voxelCount(), 0);
  readGrid(path, *hits, sums.geometry.size, sums.hits);
  hits->clear();
  const std::array<std::vector<std::uint64_t>*, 4> colourSums = {&sums.red, &sums.green, &sums.blue,
                                                                 &sums.colourPoints};
  for (std::size_t c = 0; c < colourSums.size(); ++c) {
    colourSums[c]->assign(sums.colour.cellCount(), 0);
    readGrid(path, *colourGrids[c], sums.colour.size, *colourSums[c]);
    colourGrids[c]->clear();
  }
  return sums;
}

void writeImageChunk(const fs::path& path, const ImageSums& sums, const ChunkLabel& label) {
  if (sums.width <= 0 || sums.height <= 0)
    refuseToWrite(path, "the image " + std::to_string(sums.width) + "×" + std::to_string(sums.height) + " is empty");
  const std::size_t pixels = static_cast<std::size_t>(sums.width) * static_cast<std::size_t>(sums.height);
  if (sums.counts.size() != 4 * pixels)
    refuseToWrite(path, "it has " + std::to_string(sums.counts.size()) + " counts for " + std::to_string(pixels) +
                            " pixels (4 each)");
  if (!std::isfinite(sums.unit) || !(sums.unit > 0.0)) refuseToWrite(path, "its unit is not a positive number");
  checkLabelToWrite(path, label);

  Imf::Header header(sums.width, sums.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* channel : kImageChannels) header.channels().insert(channel, Imf::Channel(Imf::UINT));
  header.insert("voxflame_chunk_format", Imf::IntAttribute(kChunkFormat));
  header.insert("voxflame_preset", Imf::StringAttribute(label.presetJson));
  header.insert("voxflame_chunk", Imf::IntAttribute(label.chunk));
  header.insert("voxflame_chunks", Imf::IntAttribute(label.chunks));
  header.insert("voxflame_width", Imf::IntAttribute(label.width));
  header.insert("voxflame_height", Imf::IntAttribute(label.height));
  header.insert("voxflame_backend", Imf::StringAttribute(label.backend));
  header.insert("voxflame_unit", Imf::DoubleAttribute(sums.unit));
  header.insert("voxflame_points", Imf::StringAttribute(std::to_string(sums.points)));
  header.insert("voxflame_iterations", Imf::StringAttribute(std::to_string(sums.iterations)));

  AtomicWriteOptions options;
  options.what = "cannot write chunk file";
  writeFileAtomicallyWith(
      path,
      [&](const fs::path& temporary) {
        {
          Imf::FrameBuffer frame;
          const std::size_t pixelStride = 4 * sizeof(std::uint32_t);
          const std::size_t rowStride = pixelStride * static_cast<std::size_t>(sums.width);
          char* base = reinterpret_cast<char*>(const_cast<std::uint32_t*>(sums.counts.data()));
          for (std::size_t c = 0; c < kImageChannels.size(); ++c)
            frame.insert(kImageChannels[c],
                         Imf::Slice(Imf::UINT, base + c * sizeof(std::uint32_t), pixelStride, rowStride));
          Imf::OutputFile file(temporary.c_str(), header);
          file.setFrameBuffer(frame);
          file.writePixels(sums.height);
        }
        appendTrailer(path, temporary, ChunkKind::Image, [](const std::string& bytes) {
          Imf::Header written;
          return exrHeaderEnd(bytes, written);
        });
      },
      options);
}

ImageSums readImageChunk(const fs::path& path, ChunkLabel& label) {
  const std::string bytes = readCheckedBody(path, ChunkKind::Image);
  try {
    MemoryStream stream(bytes);
    Imf::InputFile file(stream);
    const Imf::Header& header = file.header();
    label = labelFromExr(path, header);
    ImageSums sums;
    sums.unit = exrValue<Imf::DoubleAttribute>(path, header, "voxflame_unit");
    if (!std::isfinite(sums.unit) || !(sums.unit > 0.0)) refuse(path, "its unit is not a positive number");
    sums.points = exrCounter(path, header, "voxflame_points");
    sums.iterations = exrCounter(path, header, "voxflame_iterations");
    const Imath::Box2i window = header.dataWindow();
    if (window.min.x != 0 || window.min.y != 0) refuse(path, "its data window does not start at (0, 0)");
    const double width = double(window.max.x) + 1.0, height = double(window.max.y) + 1.0;
    if (width < 1.0 || height < 1.0 || 4.0 * width * height > kMaxValues)
      refuse(path, "its image size is empty or absurd");
    sums.width = window.max.x + 1;
    sums.height = window.max.y + 1;
    for (const char* name : kImageChannels) {
      const Imf::Channel* channel = header.channels().findChannel(name);
      if (!channel) refuse(path, std::string("it has no channel '") + name + "'");
      if (channel->type != Imf::UINT) refuse(path, std::string("its channel '") + name + "' is not UINT");
      if (channel->xSampling != 1 || channel->ySampling != 1)
        refuse(path, std::string("its channel '") + name + "' is subsampled");
    }
    sums.counts.assign(4 * static_cast<std::size_t>(sums.width) * static_cast<std::size_t>(sums.height), 0);
    Imf::FrameBuffer frame;
    const std::size_t pixelStride = 4 * sizeof(std::uint32_t);
    const std::size_t rowStride = pixelStride * static_cast<std::size_t>(sums.width);
    char* base = reinterpret_cast<char*>(sums.counts.data());
    for (std::size_t c = 0; c < kImageChannels.size(); ++c)
      frame.insert(kImageChannels[c], Imf::Slice(Imf::UINT, base + c * sizeof(std::uint32_t), pixelStride, rowStride));
    file.setFrameBuffer(frame);
    file.readPixels(0, sums.height - 1);
    return sums;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    refuse(path, std::string("OpenEXR cannot read it: ") + e.what());
  }
}

ChunkLabel readChunkLabel(const fs::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".vdb") {
    // The checked header and metadata, then an empty list of grids: OpenVDB reads no further.
    std::string bytes = readCheckedLabelPart(path, ChunkKind::Grid);
    bytes.append(sizeof(std::int32_t), '\0');
    openvdb::MetaMap::Ptr meta;
    parseVdb(path, std::move(bytes), meta);
    return labelFromVdb(path, *meta);
  }
  if (extension == ".exr") {
    const std::string bytes = readCheckedLabelPart(path, ChunkKind::Image);
    Imf::Header header;
    try {
      exrHeaderEnd(bytes, header);
    } catch (const std::exception& e) {
      refuse(path, std::string("OpenEXR cannot read its header: ") + e.what());
    }
    return labelFromExr(path, header);
  }
  refuse(path, "a chunk file ends in .vdb (volume method) or .exr (points method)");
}

void detail::sealChunkFile(const fs::path& file) {
  const ChunkKind kind = file.extension() == ".vdb" ? ChunkKind::Grid : ChunkKind::Image;
  appendTrailer(file, file, kind, [](const std::string& bytes) { return bytes.size(); });
}

}  // namespace voxflame::core
