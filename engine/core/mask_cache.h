// The mask cache: building a mask takes up to about a second on a large mesh, so finished masks
// are kept on disk, one file per (mesh content, grid, method), in the user's cache folder
// ($XDG_CACHE_HOME/voxflame, else ~/.cache/voxflame). Reopening a preset then reads the mask
// instead of computing it. Entries are bit-packed and carry their key and a checksum; an entry
// that does not read back whole and consistent is ignored and rebuilt. The cache is a
// convenience: when it cannot be written, the mask is simply not cached.
#pragma once

#include <cstdint>
#include <filesystem>

#include "inside_mask.h"

namespace voxflame::core {

// $XDG_CACHE_HOME/voxflame, else $HOME/.cache/voxflame; empty when neither variable is set.
std::filesystem::path defaultMaskCacheFolder();

// A 64-bit hash of the mesh's vertices and triangles (not its name): equal content, equal hash.
std::uint64_t meshContentHash(const TriangleMesh& mesh);

// The mask from `folder` when a valid entry is there, else built and stored there. An empty
// folder disables the cache. *fromCache, when given, says which happened.
InsideMask cachedInsideMask(const TriangleMesh& mesh, const GridGeometry& grid, MaskMethod method,
                            const std::filesystem::path& folder, bool* fromCache = nullptr);

// Keeps the `keep` most recently written or used entries in `folder` and removes the others, so the
// cache cannot grow without bound (an entry of a 512³ mask is 16 MB).
void pruneMaskCache(const std::filesystem::path& folder, std::size_t keep);
inline constexpr std::size_t kMaskCacheEntries = 24;

// Where the entry for this (mesh, grid, method) lives in `folder`.
std::filesystem::path maskCacheEntry(const std::filesystem::path& folder, const TriangleMesh& mesh,
                                     const GridGeometry& grid, MaskMethod method);

}  // namespace voxflame::core
