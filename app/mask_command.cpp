// `voxflame mask MESH --grid N -o OUT.nrrd [--stats]`: the inside mask of a mesh as an NRRD
// volume in the mesh file's own coordinates, for checking it in ParaView or 3D Slicer.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "arguments.h"
#include "commands.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/nrrd.h"

namespace voxflame::app {

namespace {

core::MaskMethod methodNamed(const std::string& name) {
  for (core::MaskMethod method :
       {core::MaskMethod::WindingNumber, core::MaskMethod::ExactWindingNumber, core::MaskMethod::Parity})
    if (name == core::maskMethodName(method)) return method;
  throw UsageError("--method must be winding-number, exact-winding-number or parity, not '" + name + "'");
}

}  // namespace

int maskCommand(const CommandArgs& args) {
  Arguments arguments(args, 2, {"--stats"});
  const auto output = arguments.take("-o", "--output");
  const int resolution =
      static_cast<int>(arguments.integer("--grid", 256, core::kMinGridResolution, core::kMaxGridResolution));
  const bool stats = arguments.flag("--stats");
  const core::MaskMethod method = methodNamed(arguments.take("--method").value_or("winding-number"));
  arguments.finish(1);
  if (arguments.positional().empty()) throw UsageError("mask needs a mesh file: voxflame mask MESH -o OUT.nrrd");
  if (!output) throw UsageError("mask needs an output file: -o OUT.nrrd");
  if (std::filesystem::path(*output).extension() != ".nrrd")
    throw UsageError("output '" + *output + "' must end in .nrrd");

  const core::TriangleMesh mesh = core::loadMesh(arguments.positional().front());
  const core::GridGeometry grid = core::gridOverBox(mesh.bounds(), resolution);
  // The mask itself is one byte a voxel; building it needs about as much again at most.
  core::checkGridFitsInMemory(grid, 2.0);
  const auto start = std::chrono::steady_clock::now();
  const core::InsideMask mask = core::buildInsideMask(mesh, grid, method);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  core::writeNrrdMask(*output, mask);
  if (stats) {
    std::printf("triangles: %zu\n", mesh.triangles.size());
    std::printf("grid: %d %d %d (voxel %.9g)\n", grid.size.x, grid.size.y, grid.size.z, grid.voxelSize);
    std::printf("inside fraction: %.6f\n", mask.insideFraction());
    std::printf("method: %s (%zu voxels by winding number)\n", core::maskMethodName(method), mask.windingNumberVoxels);
    std::printf("seconds: %.4f\n", seconds);
  }
  return 0;
}

}  // namespace voxflame::app
