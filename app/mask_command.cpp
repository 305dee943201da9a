// `voxflame mask MESH --grid N -o OUT.nrrd [--stats]`: the inside mask of a mesh as an NRRD
// volume in the mesh file's own coordinates, for checking it in ParaView or 3D Slicer.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/nrrd.h"
#include "usage_error.h"

namespace voxflame::app {

int maskCommand(const MaskArguments& arguments) {
  if (!arguments.mesh) throw UsageError("mask needs a mesh file: voxflame mask MESH -o OUT.nrrd");
  if (!arguments.output) throw UsageError("mask needs an output file: -o OUT.nrrd");
  const std::string& output = *arguments.output;
  if (std::filesystem::path(output).extension() != ".nrrd")
    throw UsageError("output '" + output + "' must end in .nrrd");

  const core::TriangleMesh mesh = core::loadMesh(*arguments.mesh);
  const core::GridGeometry grid = core::gridOverBox(mesh.bounds(), arguments.grid);
  // The mask itself is one byte a voxel; building it needs about as much again at most.
  core::checkGridFitsInMemory(grid, 2.0);
  const auto start = std::chrono::steady_clock::now();
  const core::InsideMask mask = core::buildInsideMask(mesh, grid, arguments.method);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  core::writeNrrdMask(output, mask);
  if (arguments.stats) {
    std::printf("triangles: %zu\n", mesh.triangles.size());
    std::printf("grid: %d %d %d (voxel %.9g)\n", grid.size.x, grid.size.y, grid.size.z, grid.voxelSize);
    std::printf("inside fraction: %.6f\n", mask.insideFraction());
    std::printf("method: %s (%zu voxels by winding number)\n", core::maskMethodName(arguments.method),
                mask.windingNumberVoxels);
    std::printf("seconds: %.4f\n", seconds);
  }
  return 0;
}

}  // namespace voxflame::app
