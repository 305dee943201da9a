// Ray-marches the accumulated voxel grid in a fragment shader, then finishes each pixel the way
// flam3 does, in two passes, both on the GPU:
//   1. march: emission–absorption on raw density between the ray's entry into and exit from the
//      grid box: each pixel sums the density it sees (D) and the colour it carries, dimmed by the
//      density in front of it. A jittered start per pixel, early termination and leaps over empty
//      bricks. Sub-samples (jittered rays) are averaged into a float FrameTarget, so the explorer
//      refines its image over frames and exports average S samples.
//   2. resolve: the target's sums are finished by FlameFinisher (flame_finisher.h: log density,
//      density estimation, spatial filter, gamma, vibrancy, highlight power, background, mesh
//      overlay) straight from the target's textures, and the result is drawn into whatever
//      framebuffer is bound. Nothing is read back, so a live frame never waits for the GPU.
//      Changing tone never re-marches.
// The same code draws the explorer window and offline exports. Main (GL) thread only.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <functional>
#include <string>

#include "core/camera.h"
#include "core/flame/image.h"
#include "core/image_io.h"
#include "core/mesh.h"
#include "core/packed_volume.h"
#include "core/scene.h"
#include "core/shadow_volume.h"
#include "flame_finisher.h"
#include "shader_program.h"

namespace voxflame::gl {

struct RenderSettings {
  core::CameraFrame camera;
  core::ToneMapSettings tone;
  core::RenderSettingsDoc render;
};

// The float image one view accumulates into (colour-weighted density + density, flame/image.h's
// DensityImage on the GL side), plus the mesh overlay layer and the finished image last drawn
// from them. Sized in pixels; reallocated on resize.
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

  // Takes `other`'s sums, mesh layer and sample count (resized to its size), so that this copy
  // can be shown while `other` refines on in bands (a part-refined image would show their seams).
  void copyFrom(const FrameTarget& other);

  // Takes sums made elsewhere (the points method's screen histogram, supersampled `oversample`
  // times along each axis) in place of marched ones: the target becomes image / oversample pixels,
  // and resolve() finishes the sums with that oversample, as an export of the points method does.
  // The mesh layer stays at the target's (output) size; drawMesh fills it.
  void setSums(const core::DensityImage& image, int oversample);

  // The sums read back (rows top to bottom), for tests and exports (gl/read_back.h counts it).
  core::DensityImage readDensity() const;
  // The mesh layer read back as an overlay at this target's size.
  core::MeshOverlay readMeshOverlay(const RenderSettings& settings) const;

 private:
  friend class VolumeRenderer;
  int width_ = 0, height_ = 0;
  // The sums' size and oversample: width_ × height_ and 1 for marched sums, larger for setSums's.
  glm::ivec2 radianceSize_{0};
  int oversample_ = 1;
  GLuint framebuffer_ = 0, radiance_ = 0;
  GLuint meshFramebuffer_ = 0, meshLayer_ = 0, meshDepth_ = 0;
  std::uint64_t revision_ = 0;       // bumped by every march, mesh draw and resize
  double hitsPerUnitDensity_ = 1.0;  // of the last march
  // The finished image last resolved, and what it was made from, so an unchanged frame is only drawn.
  mutable GLuint finished_ = 0, finishedFramebuffer_ = 0;
  mutable glm::ivec2 finishedSize_{0};
  // The pixels that may hold density (x, y, width, height): the union of the grid box's outlines
  // marched into the target since a sample replaced all of it (FinishSource::content).
  glm::ivec4 content_{0, 0, 0, 0};
  mutable GLenum finishedFormat_ = 0;  // RGBA8 for a display drawn by fragments, else RGBA32F
  mutable std::uint64_t finishedRevision_ = ~std::uint64_t{0};
  mutable std::string finishedKey_;
  // A finish made strip by strip (VolumeRenderer::finishStrips): the picture being finished, the
  // GL row it has reached and what it is of, and the strips' own source, overlay and output.
  mutable GLuint pending_ = 0, pendingFramebuffer_ = 0;
  mutable int pendingRow_ = 0;
  mutable std::uint64_t pendingRevision_ = ~std::uint64_t{0};
  mutable std::string pendingKey_;
  mutable GLuint stripDensity_ = 0, stripOverlay_ = 0, stripOutput_ = 0, stripFramebuffer_ = 0;
  mutable glm::ivec2 stripDensitySize_{0}, stripOverlaySize_{0}, stripOutputSize_{0};
};

class VolumeRenderer {
 public:
  VolumeRenderer();  // needs a current GL 4.3 core context
  ~VolumeRenderer();
  VolumeRenderer(const VolumeRenderer&) = delete;
  VolumeRenderer& operator=(const VolumeRenderer&) = delete;

  // Uploads a packed volume, reallocating the textures when the grid's size changed. A volume packed
  // on the GPU (PackedVolume::device, by a backend sharing this renderer's context) is copied there
  // instead, with no upload: whole by beginUpload on a GPU, in slabs under the budget on a software
  // rasteriser (whose copies run on the CPU).
  void upload(const core::PackedVolume& volume);
  // Uploads at most `budgetBytes` of the pending volume (whole z-slabs) and returns whether the
  // upload is complete, so a frame never stalls on a large grid. beginUpload keeps a pointer:
  // `volume` must outlive the upload.
  void beginUpload(const core::PackedVolume& volume);
  bool continueUpload(std::size_t budgetBytes);
  std::uint64_t uploadedVersion() const { return slots_[kMain].version; }  // of the main volume

  // A second, small volume (a coarse proxy of the same pattern, uploaded whole) that march() can
  // draw instead of the main one, e.g. while the main one is still being filled or uploaded.
  // Brightness does not depend on the grid (flame/image.h), so the two look alike.
  enum class Source { Main, Proxy };
  void uploadProxy(const core::PackedVolume& volume);
  void marchFrom(Source source) { marched_ = source == Source::Main ? kMain : kProxy; }
  Source marchedSource() const { return marched_ == kMain ? Source::Main : Source::Proxy; }
  bool hasVolume(Source source) const { return slots_[source == Source::Main ? kMain : kProxy].version > 0; }
  bool hasVolume() const { return slots_[marched_].version > 0; }    // the one march() draws
  bool onSoftwareRasteriser() const { return softwareRasteriser_; }  // its context's, as made

  void setMesh(const core::TriangleMesh& mesh);  // for the ghost and silhouette overlays
  // Light transmittance used when settings.render.lighting is on; `downsample` voxels per cell of
  // a grid of `sourceSize` voxels (default: the main volume's). It is looked up by position in
  // the grid box, so a shadow made from the main volume also lights the proxy and vice versa.
  void uploadShadow(const core::ShadowVolume& shadow, int downsample, glm::ivec3 sourceSize = glm::ivec3(0));
  bool hasShadow() const { return shadowDownsample_ > 0; }
  // The same shadow (core::computeShadowVolume's sweep), computed here on the GPU from the volume
  // `source` holds: what a volume that was packed on the GPU and never was in host memory gets
  // (PackedVolume::device). Milliseconds on a GPU; it replaces the shadow in use.
  void computeShadow(Source source, glm::dvec3 towardLight, double extinctionScale, int downsample);

  // How a sample is marched: by a compute program (the default), or a fragment program drawn over
  // the target. Both give the same sums. Compute is much faster on GPUs that run fragment work on
  // a few of their multiprocessors only (NVIDIA's H100 and H200); the fragment stage stays for
  // comparison (bench raymarch) and for drivers where it is the faster of the two.
  enum class MarchStage { Compute, Fragment };
  void setMarchStage(MarchStage stage) { marchStage_ = stage; }
  MarchStage marchStage() const { return marchStage_; }

  // Where the march reads a step's density: from the density texture, fetching the colour only
  // where there is some (what a GPU, which skips work per pixel, does best), or from the colour
  // texel's alpha where colour cells are voxels (one fetch a step: what a software rasteriser,
  // which runs both sides of every branch, does best). Automatic: by the renderer's kind. The
  // sums are the same either way.
  enum class DensityFetch { Automatic, DensityFirst, FromColour };
  void setDensityFetch(DensityFetch fetch) { densityFetch_ = fetch; }
  // Bytes of volume data sent to GL so far (density, colour and empty distances), for tests and
  // benches.
  std::uint64_t uploadedBytes() const { return uploadedBytes_; }
  // Bytes of volume data copied on the GPU from volumes packed there (PackedVolume::device): none of
  // them passed through host memory.
  std::uint64_t copiedBytes() const { return copiedBytes_; }

  // Adds one jittered sub-sample of the view to `target` (a running average). `sampleIndex`
  // picks the jitter; `tile` selects part of a larger image (x, y, full width, full height).
  void march(FrameTarget& target, const RenderSettings& settings, int sampleIndex,
             glm::ivec4 tile = glm::ivec4(0, 0, 0, 0));
  // The same sub-sample for rows [firstRow, firstRow + rowCount) of `target` alone (GL's rows,
  // bottom up), whose pixels hold `samplesBefore` samples; the rest of the target is untouched.
  // Each pixel gets exactly what march() would give it, so a target marched in bands of rows
  // converges to the picture an untiled march makes. target.samples is left to the caller, who
  // counts samples per band (app/explorer/frame_budget.h's RefineBands).
  void marchRows(FrameTarget& target, const RenderSettings& settings, int sampleIndex, int firstRow, int rowCount,
                 int samplesBefore);
  // Draws the mesh overlay layer of `target` (when settings ask for one).
  // `always` draws it even when the settings show no mesh (for the silhouette coverage).
  void drawMesh(FrameTarget& target, const RenderSettings& settings, glm::ivec4 tile = glm::ivec4(0, 0, 0, 0),
                bool always = false);
  // Finishes `target` on the GPU (flame_finisher.h, with the settings' tone and filter; no
  // supersampling) and draws it into the bound framebuffer's viewport (x, y, w, h). `linearOutput`
  // skips the display encoding and clamping (for EXR). An unchanged target and settings are only
  // drawn again. Reads nothing back.
  void resolve(const FrameTarget& target, const RenderSettings& settings, glm::ivec4 viewport, bool linearOutput);
  // resolve() in strips of `rows` output rows, one strip a call, for a picture too costly to
  // finish within a frame (the points method's full-size sums on a software GL): the picture last
  // finished whole stays the one drawn (drawFinished) until the new one is whole. Returns whether
  // the finished picture is `target`'s current one (nothing left to finish).
  bool finishStrip(const FrameTarget& target, const RenderSettings& settings, int rows);
  // Draws the picture finishStrip last made whole into the bound framebuffer's viewport; false
  // when there is none yet.
  bool drawFinished(const FrameTarget& target, glm::ivec4 viewport);
  bool hasMesh() const { return meshIndexCount_ > 0; }
  // The GPU finish this renderer resolves with, for the still methods' sums (finishImageOnGpu).
  FlameFinisher& finisher() { return finisher_; }

 private:
  // Draws a finished picture into the bound framebuffer's viewport.
  void blit(GLuint texture, glm::ivec4 viewport);
  // One sub-sample into the pixels of `scissor` (x, y, w, h; all of the target when w is 0).
  void marchPixels(FrameTarget& target, const RenderSettings& settings, int sampleIndex, glm::ivec4 tile,
                   glm::ivec4 scissor, int samplesBefore);
  glm::dmat4 tileProjection(const RenderSettings& settings, glm::ivec4 tile, int width, int height,
                            glm::dvec2 pixelJitter) const;
  // One uploaded volume: its textures and what the march needs to know about it.
  struct Slot {
    GLuint volume = 0;         // RGBA16F per colour cell: premultiplied colour, relative density
    GLuint density = 0;        // R16F: relative density alone (when hasDensity)
    GLuint emptyDistance = 0;  // R8UI per brick (core::PackedVolume::emptyDistance)
    glm::ivec3 brickCount{0};
    core::GridGeometry geometry;
    glm::ivec3 allocated{0};    // the size the volume textures were last allocated at
    core::ColourLayout colour;  // and the colour cells
    float texelDensity = 1.0f;
    double referenceDensity = 1.0;
    double insideVoxels = 0.0;
    double points = 0.0;
    std::uint64_t version = 0;  // 0: nothing complete in it
    // The density texture is allocated and uploaded: not where draws read the density from the
    // colour texels (densityInColour), which saves a fifth of the bytes an upload sends.
    bool hasDensity = false;
  };
  // Whether draws of a volume with these colour cells read a step's density from the colour
  // texel's alpha (DensityFetch).
  bool densityInColour(const core::ColourLayout& colour) const;
  static constexpr int kMain = 0, kProxy = 1;
  void allocate(Slot& slot, glm::ivec3 size, const core::ColourLayout& colour);
  void uploadSlab(Slot& slot, const core::PackedVolume& volume, int firstZ, int endZ);
  void finishUpload(Slot& slot, const core::PackedVolume& volume);
  // Slices [firstZ, endZ) of a volume packed on the GPU (PackedVolume::device), copied there in
  // place of an upload; the last slab completes the slot.
  void copyFromDevice(Slot& slot, const core::PackedVolume& volume, int firstZ, int endZ);
  void setSlotVolume(Slot& slot, const core::PackedVolume& volume);  // what a march needs to know of it

  // The march programs, built when first used, one per combination of the bits of MarchVariant:
  // features a draw does not use are compiled out, since a software rasteriser runs both sides of
  // every branch (and a branch on a uniform) for all of its lanes.
  enum MarchVariant : unsigned {
    kComputeStage = 1,     // the compute stage, else the fragment one
    kLighting = 2,         // the shadow lookup
    kDensityInColour = 4,  // colour cells are voxels: one fetch gives colour and density (software only)
  };
  const ShaderProgram& marchProgram(unsigned variant);
  ShaderProgram marchPrograms_[8];
  bool softwareRasteriser_ = false;
  DensityFetch densityFetch_ = DensityFetch::Automatic;
  std::uint64_t uploadedBytes_ = 0;
  std::uint64_t copiedBytes_ = 0;
  MarchStage marchStage_ = MarchStage::Compute;
  ShaderProgram blitProgram_;
  ShaderProgram meshProgram_;
  FlameFinisher finisher_;
  GLuint vertexArray_ = 0;
  Slot slots_[2];
  int marched_ = kMain;
  GLuint shadowTexture_ = 0;  // R8 light transmittance
  glm::ivec3 shadowSize_{0};
  glm::ivec3 shadowSource_{0};  // the grid it was made from, in voxels
  int shadowDownsample_ = 0;
  ShaderProgram shadowPrograms_[3];           // computeShadow's passes, built when first used
  GLuint shadowSigma_ = 0, shadowDepth_ = 0;  // ... and their per-cell buffers
  const core::PackedVolume* pending_ = nullptr;
  int pendingZ_ = 0;

  GLuint meshArray_ = 0, meshVertices_ = 0, meshIndices_ = 0;
  GLsizei meshIndexCount_ = 0;
  core::Box meshBox_;  // the mesh's bounds: where its overlay can show
};

inline constexpr int kDefaultMaxTile = 2048;  // pixels along a tile's side, at most

// The ray-marched sums of a whole image, supersampled by settings.render.oversample, in tiles no
// larger than the GL allows, each pixel averaging `samples` jittered sub-samples; plus the mesh
// layer at the output size (drawn even when the settings show none, for the coverage).
// `progress`, when set, is called after each tile's sub-sample with the fraction done (0–1]; it
// may throw to stop the render (GL objects are freed).
struct MarchedImage {
  core::DensityImage density;
  core::MeshOverlay mesh;
};
MarchedImage marchImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                        int maxTile = kDefaultMaxTile, const std::function<void(double)>& progress = {});

// Draws the mesh layer alone at the output size, supersampled and averaged down (for the points
// method's overlay and coverage).
core::MeshOverlay renderMeshOverlay(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                                    int maxTile = kDefaultMaxTile);

// marchImage, then flame/image.h's finish on the GPU (finishImageOnGpu) with the settings' tone,
// oversample and filter. Rows top to bottom; display-encoded in [0, 1], or linear light when
// `linearOutput`.
core::ImageRGBA renderToImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                              bool linearOutput = false, int maxTile = kDefaultMaxTile,
                              const std::function<void(double)>& progress = {});

}  // namespace voxflame::gl
