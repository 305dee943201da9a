#include <chrono>

#include "bench.h"
#include "core/accumulator.h"
#include "core/camera.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/packed_volume.h"
#include "core/scene_io.h"
#include "gl/headless_context.h"
#include "gl/volume_renderer.h"

namespace voxflame::bench {

// A 1280×720 frame of the default pattern in the bunny at 256³ and 512³, headless.
void benchRaymarch(const BenchOptions& options) {
  const core::TriangleMesh mesh = core::loadMesh(options.meshFolder + "/bunny.obj");
  const core::Scene scene = core::defaultScene();
  gl::HeadlessContext context;
  for (int resolution : {256, 512}) {
    const auto mask = std::make_shared<const core::InsideMask>(
        core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), resolution)));
    core::PackedVolume volume;
    {
      core::Accumulator accumulator(mask);
      accumulator.setTargetPoints(20'000'000);
      accumulator.setPattern(scene.layers, scene.seed);
      accumulator.waitUntilDone(120.0);
      core::VolumeSnapshot snapshot;
      accumulator.snapshot(snapshot);
      core::packVolume(snapshot, volume);
    }
    gl::VolumeRenderer renderer;
    renderer.upload(volume);
    gl::RenderSettings settings;
    settings.camera = core::orbitCamera(scene.camera, mask->geometry.box(), 1280.0 / 720.0);
    settings.tone = scene.tone;
    settings.render = scene.render;
    // One frame as the explorer draws it: one march sample into a 1280×720 target, then resolve.
    gl::FrameTarget target;
    target.resize(1280, 720);
    auto frame = [&](int index) {
      target.samples = 0;
      renderer.march(target, settings, index);
      renderer.resolve(target, settings, glm::ivec4(0, 0, 1280, 720), false);
      glFinish();
    };
    frame(0);  // warm-up: shader compile, texture residency
    constexpr int kFrames = 5;
    const auto start = std::chrono::steady_clock::now();
    for (int index = 1; index <= kFrames; ++index) frame(index);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / kFrames;
    report(options, {{"bench", "raymarch"},
                     {"grid", resolution},
                     {"width", 1280},
                     {"height", 720},
                     {"ms_per_frame", ms},
                     {"renderer", context.renderer()}});
  }
}

}  // namespace voxflame::bench
