// The OpenVDB side of `voxflame bench mask`: the time OpenVDB takes for the same job, a signed
// level set of the mesh (mesh-to-level-set with its sign flood fill) turned into an interior
// mask: a yardstick for voxflame's own inside mask.
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/MeshToVolume.h>

#include <chrono>

#include "openvdb_peer.h"

namespace voxflame::bench {

double openvdbMaskSeconds(const core::TriangleMesh& mesh, const core::GridGeometry& grid) {
  openvdb::initialize();
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  const auto transform = openvdb::math::Transform::createLinearTransform(grid.voxelSize);
  const auto start = std::chrono::steady_clock::now();
  const auto levelSet = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles, 3.0f);
  const auto interior = openvdb::tools::sdfInteriorMask(*levelSet);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!interior) return -1.0;
  return seconds;
}

}  // namespace voxflame::bench
