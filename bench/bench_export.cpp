#include <chrono>

#include "bench.h"
#include "core/scene_io.h"
#include "pipeline.h"

namespace voxflame::bench {

namespace {

void report(const BenchOptions& options, const char* method, int grid, int samples, double seconds,
            const app::StillResult& result) {
  voxflame::bench::report(options, {{"bench", "export"},
                                    {"method", method},
                                    {"width", 3840},
                                    {"height", 2160},
                                    {"grid", grid},
                                    {"samples", samples},
                                    {"seconds", seconds},
                                    {"points", result.stats.points},
                                    {"points_projected", result.pointsProjected},
                                    {"accumulate_seconds", result.accumulateSeconds},
                                    {"render_seconds", result.renderSeconds},
                                    {"coverage", result.coverage},
                                    {"renderer", result.renderer}});
}

}  // namespace

// The exports a user makes of the default preset for a 4K still: the volume method at 512³ with 4
// samples, and the points method with 100 points per pixel (flam3's "quality" 100).
void benchExport(const BenchOptions& options) {
  if (options.method.empty() || options.method == "volume") {
    core::Scene scene = core::defaultScene();
    scene.render.method = core::RenderMethod::Volume;
    scene.gridResolution = 512;
    scene.render.samples = 4;
    app::StillOptions still;
    still.width = 3840;
    still.height = 2160;
    const auto start = std::chrono::steady_clock::now();
    const app::StillResult result = app::renderStill(scene, still);
    report(options, "volume", 512, 4, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
           result);
  }
  if (options.method.empty() || options.method == "points") {
    core::Scene scene = core::defaultScene();
    scene.render.method = core::RenderMethod::Points;
    app::StillOptions still;
    still.width = 3840;
    still.height = 2160;
    still.points = 100ULL * 3840ULL * 2160ULL;
    const auto start = std::chrono::steady_clock::now();
    const app::StillResult result = app::renderStill(scene, still);
    report(options, "points", scene.gridResolution, 100,
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), result);
  }
}

}  // namespace voxflame::bench
