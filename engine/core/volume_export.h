// Volume export: the accumulated grid written for other tools, so Blender, Houdini, ParaView or
// 3D Slicer can render or inspect the pattern. Both formats hold, per voxel, a density and a
// colour, placed in the mesh file's own coordinates so the volume lines up with the mesh:
//
// * density is normalised the way voxflame's own renderer sees it before tone mapping:
//   log(1 + hits / mean) / log(1 + max / mean), where mean is the mean hit count of the voxels
//   that have any. It lies in [0, 1], is 1 in the densest voxel, and does not depend on how many
//   points were accumulated, so a renderer's density multiplier means the same for every export.
// * colour is the mean linear RGB of the points that landed in the voxel (0 where none did).
//
// OpenVDB (`.vdb`): a float grid "density" (a fog volume) and a Vec3s grid "color", both sparse
// (only voxels with hits are active), with a linear transform whose index-space voxel centres are
// the grid's voxel centres; the preset JSON is file and grid metadata ("voxflame_preset").
// NRRD (`.nrrd`): one float volume of 4 channels per voxel (density, red, green, blue), with
// space origin and voxel edge vectors; the preset is the key/value pair "voxflame_preset".
#pragma once

#include <filesystem>
#include <string>

#include "core/refinement/refinement_backend.h"

namespace voxflame::core {

// The normalised density of every voxel of `snapshot` (see above).
std::vector<float> normalisedDensity(const VolumeSnapshot& snapshot);

std::string nrrdVolumeHeader(const VolumeSnapshot& snapshot, const std::string& presetJson);

// Both write through a temporary file renamed into place, so a reader never sees half a file,
// and throw core::Error naming the file when it cannot be written.
void writeNrrdVolume(const std::filesystem::path& path, const VolumeSnapshot& snapshot, const std::string& presetJson);
void writeVdbVolume(const std::filesystem::path& path, const VolumeSnapshot& snapshot, const std::string& presetJson);

}  // namespace voxflame::core
