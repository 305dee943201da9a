#include "inside_mask.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace voxflame::core {

double InsideMask::insideFraction() const {
  if (inside.empty()) return 0.0;
  const auto count = std::accumulate(inside.begin(), inside.end(), std::size_t{0});
  return static_cast<double>(count) / static_cast<double>(inside.size());
}

namespace {

// Every triangle is rasterised onto the xy columns its projection covers; each column collects
// the z of its crossings, then the column is filled between alternate crossings. Column rays are
// nudged off the voxel centres by a fraction no mesh is aligned to, so a ray never passes
// exactly through a shared edge or vertex and counts it twice.
constexpr double kNudgeX = 1.3e-4;
constexpr double kNudgeY = 2.9e-4;

InsideMask parityAlongZ(const TriangleMesh& mesh, const GridGeometry& grid) {
  InsideMask mask;
  mask.geometry = grid;
  mask.inside.assign(grid.voxelCount(), 0);
  const int nx = grid.size.x;
  const int ny = grid.size.y;
  std::vector<std::vector<float>> crossings(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));

  for (const auto& tri : mesh.triangles) {
    // Work in voxel units so that column (i, j) sits at (i + 0.5, j + 0.5).
    glm::dvec3 p[3];
    for (int c = 0; c < 3; ++c) p[c] = (glm::dvec3(mesh.vertices[tri[c]]) - grid.origin) / grid.voxelSize;
    const double minX = std::min({p[0].x, p[1].x, p[2].x});
    const double maxX = std::max({p[0].x, p[1].x, p[2].x});
    const double minY = std::min({p[0].y, p[1].y, p[2].y});
    const double maxY = std::max({p[0].y, p[1].y, p[2].y});
    const int i0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5 - kNudgeX)));
    const int i1 = std::min(nx - 1, static_cast<int>(std::floor(maxX - 0.5 - kNudgeX)));
    const int j0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5 - kNudgeY)));
    const int j1 = std::min(ny - 1, static_cast<int>(std::floor(maxY - 0.5 - kNudgeY)));
    if (i0 > i1 || j0 > j1) continue;
    const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (area == 0.0) continue;  // edge-on to the columns: no crossing
    for (int j = j0; j <= j1; ++j) {
      const double y = j + 0.5 + kNudgeY;
      for (int i = i0; i <= i1; ++i) {
        const double x = i + 0.5 + kNudgeX;
        // Barycentric coordinates of (x, y) in the projected triangle.
        const double w0 = ((p[1].x - x) * (p[2].y - y) - (p[2].x - x) * (p[1].y - y)) / area;
        const double w1 = ((p[2].x - x) * (p[0].y - y) - (p[0].x - x) * (p[2].y - y)) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
        const double z = w0 * p[0].z + w1 * p[1].z + w2 * p[2].z;
        crossings[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j].push_back(static_cast<float>(z));
      }
    }
  }

  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      auto& zs = crossings[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j];
      if (zs.size() < 2) continue;
      std::sort(zs.begin(), zs.end());
      for (std::size_t c = 0; c + 1 < zs.size(); c += 2) {
        const int k0 = std::max(0, static_cast<int>(std::ceil(zs[c] - 0.5)));
        const int k1 = std::min(grid.size.z - 1, static_cast<int>(std::floor(zs[c + 1] - 0.5)));
        for (int k = k0; k <= k1; ++k) mask.inside[grid.index(i, j, k)] = 1;
      }
    }
  }
  return mask;
}

}  // namespace

InsideMask buildInsideMask(const TriangleMesh& mesh, const GridGeometry& grid, MaskMethod method) {
  switch (method) {
    case MaskMethod::Parity:
      break;
  }
  return parityAlongZ(mesh, grid);
}

}  // namespace voxflame::core
