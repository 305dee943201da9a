// Ray-marches the accumulated voxel grid in a fragment shader and tone-maps the result the way
// flam3 does, in two passes:
//   1. march: emission–absorption between the ray's entry into and exit from the grid box,
//      log-density emission, a jittered start per pixel, early termination and leaps over empty
//      bricks. Sub-samples (jittered rays) are averaged into a float FrameTarget, so the explorer
//      refines its image over frames and exports average S samples.
//   2. resolve: gamma with a linear threshold, vibrancy, highlight power, exposure, contrast and
//      background, drawn into whatever framebuffer is bound. Changing tone never re-marches.
// The same code draws the explorer window and offline exports. Main (GL) thread only.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <functional>

#include "core/camera.h"
#include "core/image_io.h"
#include "core/mesh.h"
#include "core/packed_volume.h"
#include "core/scene.h"
#include "core/shadow_volume.h"
#include "shader_program.h"

namespace voxflame::gl {

struct RenderSettings {
  core::CameraFrame camera;
  core::ToneMapSettings tone;
  core::RenderSettingsDoc render;
};

// The float image one view accumulates into (premultiplied radiance + opacity), plus the mesh
// overlay layer. Sized in pixels; reallocated on resize.
class FrameTarget {
 public:
  FrameTarget() = default;
  ~FrameTarget();
  FrameTarget(const FrameTarget&) = delete;
  FrameTarget& operator=(const FrameTarget&) = delete;

  void resize(int width, int height);  // clears when the size changes
  int width() const { return width_; }
  int height() const { return height_; }
  int samples = 0;  // sub-samples accumulated so far

 private:
  friend class VolumeRenderer;
  int width_ = 0, height_ = 0;
  GLuint framebuffer_ = 0, radiance_ = 0;
  GLuint meshFramebuffer_ = 0, meshLayer_ = 0, meshDepth_ = 0;
};

class VolumeRenderer {
 public:
  VolumeRenderer();  // needs a current GL 4.3 core context
  ~VolumeRenderer();
  VolumeRenderer(const VolumeRenderer&) = delete;
  VolumeRenderer& operator=(const VolumeRenderer&) = delete;

  // Uploads a packed volume, reallocating the textures when the grid's size changed.
  void upload(const core::PackedVolume& volume);
  // Uploads at most `budgetBytes` of the pending volume (whole z-slabs) and returns whether the
  // upload is complete, so a frame never stalls on a large grid. beginUpload keeps a pointer:
  // `volume` must outlive the upload.
  void beginUpload(const core::PackedVolume& volume);
  bool continueUpload(std::size_t budgetBytes);
  std::uint64_t uploadedVersion() const { return uploadedVersion_; }
  bool hasVolume() const { return uploadedVersion_ > 0; }

  void setMesh(const core::TriangleMesh& mesh);  // for the ghost and silhouette overlays
  // Light transmittance used when settings.render.lighting is on; `downsample` voxels per cell.
  void uploadShadow(const core::ShadowVolume& shadow, int downsample);
  bool hasShadow() const { return shadowDownsample_ > 0; }

  // Adds one jittered sub-sample of the view to `target` (a running average). `sampleIndex`
  // picks the jitter; `tile` selects part of a larger image (x, y, full width, full height).
  void march(FrameTarget& target, const RenderSettings& settings, int sampleIndex,
             glm::ivec4 tile = glm::ivec4(0, 0, 0, 0));
  // Draws the mesh overlay layer of `target` (when settings ask for one).
  void drawMesh(FrameTarget& target, const RenderSettings& settings, glm::ivec4 tile = glm::ivec4(0, 0, 0, 0));
  // Tone-maps `target` into the bound framebuffer's viewport (x, y, w, h). `linearOutput` skips
  // the display encoding and clamping (for EXR).
  void resolve(const FrameTarget& target, const RenderSettings& settings, glm::ivec4 viewport, bool linearOutput);

 private:
  glm::dmat4 tileProjection(const RenderSettings& settings, glm::ivec4 tile, int width, int height,
                            glm::dvec2 pixelJitter) const;
  void uploadSlab(int firstZ, int endZ);

  ShaderProgram marchProgram_;
  ShaderProgram resolveProgram_;
  ShaderProgram meshProgram_;
  GLuint vertexArray_ = 0;
  GLuint volumeTexture_ = 0;     // RGBA16F: premultiplied colour, normalised density
  GLuint densityTexture_ = 0;    // R16F: normalised density alone
  GLuint occupancyTexture_ = 0;  // R8UI per brick
  GLuint coarseTexture_ = 0;     // R8UI per coarse brick
  glm::ivec3 coarseCount_{0};
  GLuint shadowTexture_ = 0;  // R8 light transmittance
  glm::ivec3 shadowSize_{0};
  int shadowDownsample_ = 0;
  core::GridGeometry geometry_;
  glm::ivec3 brickCount_{0};
  float maxDensity_ = 0.0f;
  float meanDensity_ = 0.0f;
  std::uint64_t uploadedVersion_ = 0;
  const core::PackedVolume* pending_ = nullptr;
  int pendingZ_ = 0;

  GLuint meshArray_ = 0, meshVertices_ = 0, meshIndices_ = 0;
  GLsizei meshIndexCount_ = 0;
};

inline constexpr int kDefaultMaxTile = 2048;  // pixels along a tile's side, at most

// Renders one image offscreen in tiles no larger than the GL allows, averaging `samples`
// jittered sub-samples per pixel, and reads it back (rows top to bottom). Display-encoded in
// [0, 1], or linear light when `linearOutput`. `progress`, when set, is called after each tile's
// sub-sample with the fraction done (0–1]; it may throw to stop the render (GL objects are freed).
core::ImageRGBA renderToImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                              bool linearOutput = false, int maxTile = kDefaultMaxTile,
                              const std::function<void(double)>& progress = {});

}  // namespace voxflame::gl
