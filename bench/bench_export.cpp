#include <chrono>

#include "bench.h"
#include "core/scene_io.h"
#include "pipeline.h"

namespace voxflame::bench {

// The export a user makes of the default preset for a 4K still: 3840×2160, 512³, 4 samples.
void benchExport(const BenchOptions& options) {
  core::Scene scene = core::defaultScene();
  scene.gridResolution = 512;
  scene.render.samples = 4;
  app::StillOptions still;
  still.width = 3840;
  still.height = 2160;
  const auto start = std::chrono::steady_clock::now();
  const app::StillResult result = app::renderStill(scene, still);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report(options, {{"bench", "export"},
                   {"width", 3840},
                   {"height", 2160},
                   {"grid", 512},
                   {"samples", 4},
                   {"seconds", seconds},
                   {"points", result.stats.points},
                   {"accumulate_seconds", result.accumulateSeconds},
                   {"render_seconds", result.renderSeconds},
                   {"renderer", result.renderer}});
}

}  // namespace voxflame::bench
