#include <algorithm>
#include <chrono>
#include <map>
#include <string>

#include "bench.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "openvdb_peer.h"

namespace voxflame::bench {

// The inside mask of the bunny at 256³ and the full dragon at 256³ and 512³ with the default
// method, on every hardware thread. Loading is not timed and the mask cache is not used; each
// figure is the best of a few runs, so a busy machine disturbs it less. Each case is followed by
// OpenVDB's time for the same mask ("peer":"openvdb").
void benchMask(const BenchOptions& options) {
  struct Case {
    const char* mesh;
    int grid;
  };
  std::map<std::string, core::TriangleMesh> meshes;
  for (const Case& c : {Case{"bunny.obj", 256}, Case{"dragon.ply", 256}, Case{"dragon.ply", 512}}) {
    if (!meshes.count(c.mesh)) meshes[c.mesh] = core::loadMesh(options.meshFolder + "/" + c.mesh);
    const core::TriangleMesh& mesh = meshes.at(c.mesh);
    const core::GridGeometry grid = core::gridOverBox(mesh.bounds(), c.grid);
    double best = 1e300;
    for (int run = 0; run < 3; ++run) {
      const auto start = std::chrono::steady_clock::now();
      const core::InsideMask mask = core::buildInsideMask(mesh, grid);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    report(options, {{"bench", "mask"},
                     {"mesh", c.mesh},
                     {"triangles", mesh.triangles.size()},
                     {"grid", c.grid},
                     {"seconds", best}});
    double peerBest = 1e300;
    for (int run = 0; run < 2; ++run) peerBest = std::min(peerBest, openvdbMaskSeconds(mesh, grid));
    report(options, {{"bench", "mask"},
                     {"mesh", c.mesh},
                     {"triangles", mesh.triangles.size()},
                     {"grid", c.grid},
                     {"seconds", peerBest},
                     {"peer", "openvdb"}});
  }
}

}  // namespace voxflame::bench
