#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <memory>

#include "bench.h"
#include "core/refinement/accumulator.h"
#include "core/camera.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/packed_volume.h"
#include "core/scene_io.h"
#include "gl/canvas.h"
#include "gl/headless_context.h"
#include "gl/volume_renderer.h"

namespace voxflame::bench {

namespace {

using MarchStage = gl::VolumeRenderer::MarchStage;
using Estimation = gl::FlameFinisher::Estimation;

const char* name(MarchStage stage) {
  return stage == MarchStage::Compute ? "compute" : "fragment";
}
const char* name(Estimation estimation) {
  return estimation == Estimation::Gather ? "gather" : "scatter";
}

}  // namespace

// A frame of the default pattern in the bunny as the explorer draws it, headless: 1280×720 at 256³
// and 512³ (the goals on a software rasteriser), and 1920×1080 at 512³ (the goal on a GPU). The
// first row of each is the renderer's own choice of march stage and density estimation; the next
// two change one of them, so the choice is measured against its peer in the same run.
void benchRaymarch(const BenchOptions& options) {
  const core::TriangleMesh mesh = core::loadMesh(options.meshFolder + "/bunny.obj");
  const core::Scene scene = core::defaultScene();
  gl::HeadlessContext context;
  struct Case {
    int resolution, width, height;
  };
  int builtResolution = 0;
  std::shared_ptr<const core::InsideMask> mask;
  core::PackedVolume volume;
  for (const Case& c : {Case{256, 1280, 720}, Case{512, 1280, 720}, Case{512, 1920, 1080}}) {
    if (!options.grids.empty() &&
        std::find(options.grids.begin(), options.grids.end(), c.resolution) == options.grids.end())
      continue;
    const int width = c.width, height = c.height;
    // One 512³ volume serves both sizes: filling it is the slow part of this bench on a CPU.
    if (c.resolution != builtResolution) {
      builtResolution = c.resolution;
      mask = std::make_shared<const core::InsideMask>(
          core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), c.resolution)));
      volume = core::PackedVolume{};
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
    const MarchStage ownStage = renderer.marchStage();
    const Estimation ownEstimation = renderer.finisher().estimation();
    const MarchStage otherStage = ownStage == MarchStage::Compute ? MarchStage::Fragment : MarchStage::Compute;
    const Estimation otherEstimation = ownEstimation == Estimation::Gather ? Estimation::Scatter : Estimation::Gather;
    struct Variant {
      MarchStage stage;
      Estimation estimation;
    };
    for (const Variant& variant :
         {Variant{ownStage, ownEstimation}, Variant{otherStage, ownEstimation}, Variant{ownStage, otherEstimation}}) {
      renderer.setMarchStage(variant.stage);
      renderer.finisher().setEstimation(variant.estimation);
      gl::RenderSettings settings;
      settings.camera = core::orbitCamera(scene.camera, mask->geometry.box(), double(width) / height);
      settings.tone = scene.tone;
      settings.render = scene.render;
      // One frame as the explorer draws it: one march sample into the target, then resolve (the
      // finish on the GPU and the draw). Each half waits for the GPU, so it is timed alone.
      gl::FrameTarget target;
      target.resize(width, height);
      const gl::Canvas canvas(width, height);
      double marchMs = 0.0, finishMs = 0.0;
      gl::FlameFinisher::PassTimes passes;
      bool timing = true;
      auto frame = [&](int index) {
        const auto start = std::chrono::steady_clock::now();
        target.samples = 0;
        renderer.march(target, settings, index);
        glFinish();
        const auto marched = std::chrono::steady_clock::now();
        glBindFramebuffer(GL_FRAMEBUFFER, canvas.framebuffer());
        renderer.resolve(target, settings, glm::ivec4(0, 0, width, height), false);
        glFinish();
        const auto finished = std::chrono::steady_clock::now();
        marchMs += std::chrono::duration<double, std::milli>(marched - start).count();
        finishMs += std::chrono::duration<double, std::milli>(finished - marched).count();
        if (!timing) return;
        const auto& last = renderer.finisher().lastPassTimes();
        passes.scatterMs += last.scatterMs;
        passes.foldMs += last.foldMs;
        passes.toneMs += last.toneMs;
      };
      // The passes' GPU times from three frames of their own: the timestamp queries slow llvmpipe's
      // finish down (to twice its time at 256³), so the timed frames are not the ones counted.
      renderer.finisher().setTimed(true);
      for (int index = 0; index < 3; ++index) frame(index);  // the first also warms up: shader compile, residency
      renderer.finisher().setTimed(false);
      timing = false;
      passes.scatterMs /= 3;
      passes.foldMs /= 3;
      passes.toneMs /= 3;
      marchMs = finishMs = 0.0;
      // At least 5 frames, and on a fast GPU enough of them to fill half a second.
      int frames = 0;
      while (frames < 5 || (marchMs + finishMs < 500.0 && frames < 1000)) frame(++frames);
      const double total = (marchMs + finishMs) / frames;
      report(options, {{"bench", "raymarch"},
                       {"grid", c.resolution},
                       {"width", width},
                       {"height", height},
                       {"frames", frames},
                       {"own_choice", variant.stage == ownStage && variant.estimation == ownEstimation},
                       {"march_stage", name(variant.stage)},
                       {"estimation", name(variant.estimation)},
                       {"march_ms", marchMs / frames},
                       {"finish_ms", finishMs / frames},
                       {"estimation_gpu_ms", passes.scatterMs},
                       {"fold_gpu_ms", passes.foldMs},
                       {"tone_gpu_ms", passes.toneMs},
                       {"total_ms", total},
                       {"ms_per_frame", total},  // the total, under its earlier name
                       {"renderer", context.renderer()}});
    }
  }
}

}  // namespace voxflame::bench
