#include <chrono>
#include <filesystem>

#include "bench.h"
#include "core/flame/image.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "pipeline.h"

namespace voxflame::bench {

// How noisy a render at a preset's own budget is: the relative RMS difference of linear luminance
// between it and the same scene with ten times the points (flame/image.h), for both methods, at
// 1280×720; plus the seconds each render took. 0 would be converged; flam3-render's stock genome
// at its default quality sits near 0.34 by the same measure.
void benchQuality(const BenchOptions& options) {
  const std::filesystem::path presets = std::filesystem::path(VOXFLAME_SOURCE_DIR) / "presets";
  std::vector<std::pair<std::string, core::Scene>> scenes = {{"default", core::defaultScene()}};
  for (const char* name : {"thomas-pinwheel", "lorenz-heart"})
    scenes.emplace_back(name, core::loadScene(presets / (std::string(name) + ".json")));
  for (auto& [name, preset] : scenes) {
    for (core::RenderMethod method : {core::RenderMethod::Volume, core::RenderMethod::Points}) {
      if (!options.method.empty() && options.method != core::toString(method)) continue;
      core::Scene scene = preset;
      scene.render.method = method;
      app::StillOptions still;
      still.width = 1280;
      still.height = 720;
      auto timed = [&](std::uint64_t points, double& seconds) {
        still.points = points;
        const auto start = std::chrono::steady_clock::now();
        app::StillResult result = app::renderStill(scene, still);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
      };
      double budgetSeconds = 0.0, referenceSeconds = 0.0;
      const app::StillResult budget = timed(scene.points, budgetSeconds);
      const app::StillResult reference = timed(10 * scene.points, referenceSeconds);
      report(options, {{"bench", "quality"},
                       {"preset", name},
                       {"method", core::toString(method)},
                       {"points", scene.points},
                       {"relative_rmse", core::relativeLuminanceRmse(budget.image, reference.image, scene.tone.gamma)},
                       {"mean_luminance", core::meanLuminance(budget.image, scene.tone.gamma)},
                       {"reference_mean_luminance", core::meanLuminance(reference.image, scene.tone.gamma)},
                       {"coverage", budget.coverage},
                       {"seconds", budgetSeconds},
                       {"reference_seconds", referenceSeconds}});
    }
  }
}

}  // namespace voxflame::bench
