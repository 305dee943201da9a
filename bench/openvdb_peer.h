// OpenVDB as a peer in the mask benchmark (see openvdb_peer.cpp); present only when built with it.
#pragma once

#include "core/grid.h"
#include "core/mesh.h"

namespace voxflame::bench {

// Seconds OpenVDB takes to make a signed level set of `mesh` at `grid`'s voxel size and extract
// its interior mask (loading excluded).
double openvdbMaskSeconds(const core::TriangleMesh& mesh, const core::GridGeometry& grid);

}  // namespace voxflame::bench
