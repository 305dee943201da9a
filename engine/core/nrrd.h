// NRRD is the plain volume format ParaView, 3D Slicer and teem read: a short text header (type,
// sizes, where the voxels sit in space) followed by the raw samples. voxflame writes the inside
// mask as one byte per voxel, x fastest, placed in the mesh file's own coordinates, so the mask
// can be laid over the mesh in those tools.
#pragma once

#include <filesystem>
#include <string>

#include "inside_mask.h"

namespace voxflame::core {

// The header, up to and including the blank line that ends it: type uchar, dimension 3, sizes
// nx ny nz, space 3D-right-handed, space origin = centre of voxel (0, 0, 0), space directions =
// the three voxel edge vectors, encoding raw.
std::string nrrdMaskHeader(const InsideMask& mask);

// Writes header and voxels (0 or 1) to `path` through a temporary file renamed into place, so
// a reader never sees half a file. Throws core::Error naming the file when it cannot be written.
void writeNrrdMask(const std::filesystem::path& path, const InsideMask& mask);

}  // namespace voxflame::core
