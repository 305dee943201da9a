// The inside mask says, per voxel of a GridGeometry, whether the voxel centre lies inside the
// mesh. Patterns are only ever accumulated where the mask is set, so the mask *is* the shape the
// user sees. Computed once per (mesh, grid) and shared read-only by every worker thread.
//
// "Inside" is defined by the generalized winding number (Jacobson et al. 2013): the signed solid
// angle the mesh subtends at a point, over 4π; a point is inside where it is ≥ 0.5. On a closed
// mesh that is the usual inside; on a mesh with holes or overlapping parts (scans, the teapot,
// game assets) it is still the answer a person expects. A mesh whose triangles all face inwards
// (negative enclosed volume) is read as if they faced outwards.
//
// The default method gets that answer fast: signed ray crossings counted along grid columns of
// all three axes give an integer winding number per voxel; where every usable axis agrees that is
// the answer (a column whose crossings do not sum to zero passed through a hole and is not
// usable). The few voxels left undecided get the fast winding number (Barill et al. 2018): a
// bounding-volume hierarchy whose far clusters are replaced by their dipole.
#pragma once

#include <cstdint>
#include <vector>

#include "grid.h"
#include "mesh.h"

namespace voxflame::core {

enum class MaskMethod {
  WindingNumber,       // ray crossings voted over x, y and z, fast winding number where they disagree
  ExactWindingNumber,  // the reference: every voxel summed over every triangle; O(voxels × triangles)
  Parity,              // crossings along z only; right on closed meshes, wrong where they have holes
};
const char* maskMethodName(MaskMethod method);

struct InsideMask {
  GridGeometry geometry;
  std::vector<std::uint8_t> inside;     // 1 inside, 0 outside; geometry.index order
  std::size_t windingNumberVoxels = 0;  // voxels the ray votes left to the winding number (statistics)
  // Where the time went (statistics): crossings, the voting sweep, the winding-number tree and its queries.
  double crossingSeconds = 0.0, sweepSeconds = 0.0, treeSeconds = 0.0, windingNumberSeconds = 0.0;

  bool at(int i, int j, int k) const { return inside[geometry.index(i, j, k)] != 0; }
  double insideFraction() const;
};

// threads: 0 means every hardware thread.
InsideMask buildInsideMask(const TriangleMesh& mesh, const GridGeometry& grid,
                           MaskMethod method = MaskMethod::WindingNumber, int threads = 0);

// The generalized winding number at `point`, summed exactly over every triangle.
double windingNumber(const TriangleMesh& mesh, const glm::dvec3& point);

// +1 when the mesh encloses a positive volume (triangles wound counter-clockwise seen from
// outside), -1 when it is inside-out.
int meshOrientation(const TriangleMesh& mesh);

// The fast winding number: a bounding-volume hierarchy over the triangles; a cluster farther than
// `accuracy` times its radius from the query point is replaced by its dipole (the area-weighted
// normal sum at its area-weighted centre). Built once, queried from any number of threads; the
// mesh must outlive the tree.
class WindingNumberTree {
 public:
  explicit WindingNumberTree(const TriangleMesh& mesh, int threads = 0);  // threads: 0 means all
  ~WindingNumberTree();
  WindingNumberTree(const WindingNumberTree&) = delete;
  WindingNumberTree& operator=(const WindingNumberTree&) = delete;

  double operator()(const glm::dvec3& point, double accuracy = 2.5) const;

 private:
  struct Node;
  static Node combine(const Node& left, const Node& right, std::uint32_t rightIndex);
  std::vector<Node> nodes_;
  const TriangleMesh* mesh_;
  std::vector<std::uint32_t> order_;  // triangle indices in leaf order
};

}  // namespace voxflame::core
