// Ray-marches the accumulated voxel grid in a fragment shader: emission–absorption between the
// ray's entry into and exit from the grid box, log-density tone mapping, a jittered start per
// pixel. The same code draws the explorer window and offline exports. Main (GL) thread only.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>

#include "core/accumulator.h"
#include "core/camera.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "shader_program.h"

namespace voxflame::gl {

struct RenderSettings {
  core::CameraFrame camera;
  core::ToneMapSettings tone;
  double stepVoxels = 0.5;       // ray step as a fraction of a voxel edge
  std::uint32_t frameIndex = 0;  // varies the per-pixel jitter between frames
};

class VolumeRenderer {
 public:
  VolumeRenderer();  // needs a current GL 4.3 core context
  ~VolumeRenderer();
  VolumeRenderer(const VolumeRenderer&) = delete;
  VolumeRenderer& operator=(const VolumeRenderer&) = delete;

  // Uploads a snapshot, reallocating the textures when the grid's size changed.
  void upload(const core::VolumeSnapshot& snapshot);
  std::uint64_t uploadedVersion() const { return uploadedVersion_; }

  // Draws into the currently bound framebuffer over a viewport of width × height.
  void draw(const RenderSettings& settings, int width, int height);

 private:
  ShaderProgram program_;
  GLuint vertexArray_ = 0;
  GLuint densityTexture_ = 0;
  GLuint colorTexture_ = 0;
  core::GridGeometry geometry_;
  float maxDensity_ = 0.0f;
  std::uint64_t uploadedVersion_ = 0;
};

// Renders one image offscreen (an FBO) and reads it back, rows top to bottom.
core::ImageRGBA renderToImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height);

}  // namespace voxflame::gl
