#include "mask_cache.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "error.h"
#include "file_output.h"
#include "xdg_paths.h"

namespace voxflame::core {

namespace {

constexpr char kMagic[8] = {'V', 'X', 'M', 'A', 'S', 'K', '0', '1'};

// A fast non-cryptographic hash: eight bytes at a time, multiply and fold.
class Hasher {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, bytes + i, 8);
      mix(word);
    }
    std::uint64_t tail = 0;
    for (std::size_t shift = 0; i < size; ++i, shift += 8) tail |= static_cast<std::uint64_t>(bytes[i]) << shift;
    mix(tail ^ (static_cast<std::uint64_t>(size) << 56));
  }
  template <class T>
  void addValue(const T& value) {
    add(&value, sizeof value);
  }
  std::uint64_t value() const { return state_ ^ (state_ >> 31); }

 private:
  void mix(std::uint64_t word) {
    state_ = (state_ ^ word) * 0x9E3779B97F4A7C15ull;
    state_ ^= state_ >> 29;
  }
  std::uint64_t state_ = 0x243F6A8885A308D3ull;
};

std::uint64_t entryKey(const TriangleMesh& mesh, const GridGeometry& grid, MaskMethod method) {
  Hasher hasher;
  hasher.addValue(meshContentHash(mesh));
  hasher.addValue(grid.size.x);
  hasher.addValue(grid.size.y);
  hasher.addValue(grid.size.z);
  hasher.addValue(grid.origin.x);
  hasher.addValue(grid.origin.y);
  hasher.addValue(grid.origin.z);
  hasher.addValue(grid.voxelSize);
  hasher.addValue(static_cast<std::uint32_t>(method));
  return hasher.value();
}

struct EntryHeader {
  char magic[8];
  std::uint64_t key;
  std::int32_t size[3];
  std::uint32_t method;
  double origin[3];
  double voxelSize;
  std::uint64_t packedBytes;
  std::uint64_t checksum;  // of the packed bits
};

std::uint64_t checksumOf(const std::vector<std::uint8_t>& bytes) {
  Hasher hasher;
  hasher.add(bytes.data(), bytes.size());
  return hasher.value();
}

// The stored mask when the entry is whole and belongs to this key and grid; false otherwise.
bool readEntry(const std::filesystem::path& path, std::uint64_t key, const GridGeometry& grid, MaskMethod method,
               InsideMask& mask) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  EntryHeader header{};
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return false;
  const std::size_t voxels = grid.voxelCount();
  if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 || header.key != key || header.size[0] != grid.size.x ||
      header.size[1] != grid.size.y || header.size[2] != grid.size.z ||
      header.method != static_cast<std::uint32_t>(method) || header.voxelSize != grid.voxelSize ||
      header.origin[0] != grid.origin.x || header.origin[1] != grid.origin.y || header.origin[2] != grid.origin.z ||
      header.packedBytes != (voxels + 7) / 8)
    return false;
  std::vector<std::uint8_t> packed(header.packedBytes);
  if (!in.read(reinterpret_cast<char*>(packed.data()), static_cast<std::streamsize>(packed.size()))) return false;
  if (in.peek() != std::char_traits<char>::eof()) return false;  // trailing bytes: not ours
  if (checksumOf(packed) != header.checksum) return false;
  mask.geometry = grid;
  mask.inside.resize(voxels);
  for (std::size_t v = 0; v < voxels; ++v) mask.inside[v] = (packed[v >> 3] >> (v & 7)) & 1u;
  return true;
}

void writeEntry(const std::filesystem::path& path, std::uint64_t key, const InsideMask& mask, MaskMethod method) {
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return;
  std::vector<std::uint8_t> packed((mask.inside.size() + 7) / 8, 0);
  for (std::size_t v = 0; v < mask.inside.size(); ++v)
    if (mask.inside[v]) packed[v >> 3] |= static_cast<std::uint8_t>(1u << (v & 7));
  EntryHeader header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.key = key;
  const GridGeometry& g = mask.geometry;
  header.size[0] = g.size.x;
  header.size[1] = g.size.y;
  header.size[2] = g.size.z;
  header.method = static_cast<std::uint32_t>(method);
  header.origin[0] = g.origin.x;
  header.origin[1] = g.origin.y;
  header.origin[2] = g.origin.z;
  header.voxelSize = g.voxelSize;
  header.packedBytes = packed.size();
  header.checksum = checksumOf(packed);
  std::string bytes(reinterpret_cast<const char*>(&header), sizeof header);
  bytes.append(reinterpret_cast<const char*>(packed.data()), packed.size());
  // Two processes filling the same entry at once each write a whole file and one of them wins.
  // The cache is an optimisation: an entry that cannot be written is simply not cached.
  try {
    writeFileAtomically(path, bytes);
  } catch (const Error&) {  // nothing cached; the caller has its mask
  }
}

}  // namespace

std::filesystem::path defaultMaskCacheFolder() {
  return xdgFolder(XdgKind::Cache);
}

std::uint64_t meshContentHash(const TriangleMesh& mesh) {
  Hasher hasher;
  hasher.addValue(static_cast<std::uint64_t>(mesh.vertices.size()));
  hasher.add(mesh.vertices.data(), mesh.vertices.size() * sizeof(mesh.vertices[0]));
  hasher.addValue(static_cast<std::uint64_t>(mesh.triangles.size()));
  hasher.add(mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
  return hasher.value();
}

void pruneMaskCache(const std::filesystem::path& folder, std::size_t keep) {
  std::error_code ec;
  std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> entries;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = item.path().filename().string();
    if (name.rfind("mask-", 0) != 0 || item.path().extension() != ".bin") continue;
    entries.emplace_back(item.last_write_time(ec), item.path());
  }
  if (entries.size() <= keep) return;
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t e = keep; e < entries.size(); ++e) std::filesystem::remove(entries[e].second, ec);
}

std::filesystem::path maskCacheEntry(const std::filesystem::path& folder, const TriangleMesh& mesh,
                                     const GridGeometry& grid, MaskMethod method) {
  char name[64];
  std::snprintf(name, sizeof name, "mask-%016llx.bin", static_cast<unsigned long long>(entryKey(mesh, grid, method)));
  return folder / name;
}

InsideMask cachedInsideMask(const TriangleMesh& mesh, const GridGeometry& grid, MaskMethod method,
                            const std::filesystem::path& folder, bool* fromCache) {
  if (fromCache) *fromCache = false;
  if (folder.empty()) return buildInsideMask(mesh, grid, method);
  const std::uint64_t key = entryKey(mesh, grid, method);
  const std::filesystem::path path = maskCacheEntry(folder, mesh, grid, method);
  InsideMask mask;
  if (readEntry(path, key, grid, method, mask)) {
    if (fromCache) *fromCache = true;
    // Touched on use, so pruning drops the entries used least recently.
    std::error_code ec;
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);
    return mask;
  }
  mask = buildInsideMask(mesh, grid, method);
  writeEntry(path, key, mask, method);
  pruneMaskCache(folder, kMaskCacheEntries);
  return mask;
}

}  // namespace voxflame::core
