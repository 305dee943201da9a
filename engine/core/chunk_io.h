// Checkpoint files of a still split into chunks (chunk_sums.h): one file per finished chunk, holding
// its raw integer sums exactly, so that adding the files of all chunks gives the same image bit for
// bit whichever machine rendered which chunk.
//
// The volume method's sums go to an OpenVDB file (.vdb), the points method's to an OpenEXR file
// (.exr): standard formats, so a chunk can be looked at in Houdini, Blender or exrheader. Layout:
//
//   .vdb  OpenVDB's default compression (Blosc, else ZIP); grids (index space, inactive voxels are 0,
//         stored values are never negative):
//           "hits"           Int32Grid  per voxel: GridSums::hits, active where not 0
//           "red", "green", "blue", "colour_points"
//                            Int64Grid  per colour cell (voxel i covers cell i >> shift): the sums
//         file metadata:
//           voxflame_preset (string), voxflame_chunk, voxflame_chunks, voxflame_width,
//           voxflame_height (int32): the ChunkLabel;
//           voxflame_points, voxflame_iterations, voxflame_inside_voxels (int64): the counters;
//           voxflame_grid_size (vec3i), voxflame_grid_origin (vec3d), voxflame_voxel_size (double):
//           the GridGeometry; voxflame_colour_shift (int32), voxflame_colour_size (vec3i): the
//           ColourLayout; voxflame_chunk_format (int32, 1) and creator ("voxflame").
//   .exr  one part, scanlines, ZIP, data window (0, 0)-(width - 1, height - 1) of ImageSums:
//           UINT channels "R", "G", "B" (the colour sums) and "D" (the density), i.e. counts[4p + c]
//         header attributes:
//           voxflame_preset (string), voxflame_chunk, voxflame_chunks, voxflame_width,
//           voxflame_height (int): the ChunkLabel; voxflame_unit (double); voxflame_points,
//           voxflame_iterations (string, decimal: EXR has no 64-bit integer attribute);
//           voxflame_chunk_format (int, 1).
//
// Doubles are stored as doubles, integers as integers: a round trip is exact.
//
// Both end in a 40-byte voxflame trailer after the library's own data (OpenVDB and OpenEXR readers
// never look past their last grid or chunk, so the files stay readable by other tools):
//   uint64 labelEnd   bytes [0, labelEnd) are the file's header with the label and counters
//   uint64 labelHash  XXH64 (seed 0) of bytes [0, labelEnd)
//   uint64 bodyHash   XXH64 (seed 0) of every byte before the trailer
//   uint32 format (1), uint32 kind (1: volume grid, 2: points image), char[8] "VXFCHUNK"
// (little-endian). A reader checks the checksums before it hands a single byte to OpenVDB or
// OpenEXR: neither library is hardened against damaged input (OpenVDB loops over counts it reads,
// unchecked), and a flipped bit in a hit count would otherwise pass unnoticed into the image. So a
// truncated or damaged file is refused with a message, never crashes or hangs a reader, and never
// adds wrong sums.
#pragma once

#include <filesystem>

#include "chunk_sums.h"

namespace voxflame::core {

// Volume method: writes `sums` and `label` to `path` (.vdb) atomically (file_output.h). Throws
// core::Error when the sums do not match their grid, a value does not fit (a hit count of 2^31 or
// more, a sum or counter of 2^63 or more) or the file cannot be written.
void writeGridChunk(const std::filesystem::path& path, const GridSums& sums, const ChunkLabel& label);
// Reads what writeGridChunk wrote; throws core::Error naming the file and what is wrong (missing,
// damaged, incomplete, not a volume chunk, metadata missing or of the wrong type, sizes that do not
// agree, values out of range).
GridSums readGridChunk(const std::filesystem::path& path, ChunkLabel& label);

// Points method: the same for an ImageSums (.exr).
void writeImageChunk(const std::filesystem::path& path, const ImageSums& sums, const ChunkLabel& label);
ImageSums readImageChunk(const std::filesystem::path& path, ChunkLabel& label);

// Only the label, for checking a folder of chunks quickly: reads the trailer and the file's header,
// nothing of the sums. The kind follows the extension (.vdb or .exr). Throws core::Error as above.
ChunkLabel readChunkLabel(const std::filesystem::path& path);

namespace detail {
// For tests only: appends a valid trailer (its header part: the whole file) to a file that OpenVDB
// or OpenEXR wrote, as if voxflame had, so that a test can check how the readers refuse files that
// are intact but wrong. The kind follows the extension.
void sealChunkFile(const std::filesystem::path& file);
}  // namespace detail

}  // namespace voxflame::core
