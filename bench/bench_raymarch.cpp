#include <epoxy/gl.h>

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
    // One frame as the explorer draws it: one march sample into a 1280×720 target, then resolve
    // (the finish on the GPU and the draw). Each half waits for the GPU, so it is timed alone.
    gl::FrameTarget target;
    target.resize(1280, 720);
    GLuint canvas = 0, canvasFramebuffer = 0;
    glGenTextures(1, &canvas);
    glBindTexture(GL_TEXTURE_2D, canvas);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 1280, 720);
    glGenFramebuffers(1, &canvasFramebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, canvasFramebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, canvas, 0);
    double marchMs = 0.0, finishMs = 0.0;
    auto frame = [&](int index) {
      const auto start = std::chrono::steady_clock::now();
      target.samples = 0;
      renderer.march(target, settings, index);
      glFinish();
      const auto marched = std::chrono::steady_clock::now();
      glBindFramebuffer(GL_FRAMEBUFFER, canvasFramebuffer);
      renderer.resolve(target, settings, glm::ivec4(0, 0, 1280, 720), false);
      glFinish();
      const auto finished = std::chrono::steady_clock::now();
      marchMs += std::chrono::duration<double, std::milli>(marched - start).count();
      finishMs += std::chrono::duration<double, std::milli>(finished - marched).count();
    };
    frame(0);  // warm-up: shader compile, texture residency
    marchMs = finishMs = 0.0;
    constexpr int kFrames = 5;
    for (int index = 1; index <= kFrames; ++index) frame(index);
    marchMs /= kFrames;
    finishMs /= kFrames;
    glDeleteFramebuffers(1, &canvasFramebuffer);
    glDeleteTextures(1, &canvas);
    report(options, {{"bench", "raymarch"},
                     {"grid", resolution},
                     {"width", 1280},
                     {"height", 720},
                     {"march_ms", marchMs},
                     {"finish_ms", finishMs},
                     {"total_ms", marchMs + finishMs},
                     {"ms_per_frame", marchMs + finishMs},  // the total, under its earlier name
                     {"renderer", context.renderer()}});
  }
}

}  // namespace voxflame::bench
