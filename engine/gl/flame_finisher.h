// flam3's finish (core/flame/image.h) on the GPU, so neither the explorer nor an export reads the
// marched sums back to finish them on the CPU. Three passes, each giving what core::finishImage
// gives to within float rounding:
//   1. scatter: a compute pass lists the non-empty pixels whose kernel is wider than a pixel and
//      counts them into an indirect draw (so only those reach the vertex stage, and nothing is
//      read back); density estimation draws them as additive point sprites into a float target
//      padded by the widest kernel's radius (quads of six vertices where a kernel is wider than
//      the driver's largest point);
//   2. fold: the log image, the padding folded onto the image's edge pixels (core piles weight
//      that falls outside the image on the edge pixel), one-pixel kernels added in place;
//   3. tone: the spatial filter from the supersampled log image, gamma, vibrancy, highlight power,
//      background, mesh overlay, contrast, exposure, display encoding or linear light.
// Each pass works on a region of a larger image, so an image larger than GL allows is finished in
// tiles whose aprons (the widest kernel plus the filter's taps) make them seamless.
// core::finishImage stays as the reference the tests hold this to. Main (GL) thread only.
#pragma once

#include <epoxy/gl.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/flame/image.h"
#include "shader_program.h"

namespace voxflame::gl {

// The pixels a finish reads, in GL's orientation (rows bottom to top).
struct FinishSource {
  GLuint density = 0;      // RGBA32F sums (red·D, green·D, blue·D, D) of a region of the full image
  glm::ivec2 origin{0};    // the region's lower-left pixel in the full supersampled image
  glm::ivec2 size{0};      // the region's size (the texture's)
  glm::ivec2 fullSize{0};  // the full supersampled image's size: a multiple of the oversample
  double hitsPerUnitDensity = 1.0;
  GLuint overlay = 0;  // RGBA mesh layer of a region of the full output image (0: none)
  glm::ivec2 overlayOrigin{0};
  // The region's pixels that may hold density or the overlay (x, y, width, height), when known:
  // the grid box's and the mesh's outlines on the screen. A finish drawn as fragments folds and
  // tones only around them and fills the rest with the empty pixel's colour, since a software
  // rasteriser shades every pixel it draws in full. A negative width: unknown, all of them.
  glm::ivec4 content{0, 0, -1, -1};
};

// How the mesh layer is drawn over the pattern (core::MeshOverlay without its pixels).
struct OverlayStyle {
  core::MeshDisplay mode = core::MeshDisplay::Off;
  glm::vec3 color{1.0f};
  double strength = 0.35;
};

class FlameFinisher {
 public:
  FlameFinisher();  // needs a current GL 4.3 core context
  ~FlameFinisher();
  FlameFinisher(const FlameFinisher&) = delete;
  FlameFinisher& operator=(const FlameFinisher&) = delete;

  // Finishes the output pixels [outputOrigin, outputOrigin + outputSize) of the full output image
  // (fullSize / oversample) into `framebuffer`'s viewport (0, 0, outputSize): RGB as
  // core::finishImage makes it, alpha the pattern's opacity (core::FinishedImage::alpha). The
  // source must hold every pixel those outputs depend on (apron(): kernels and filter taps),
  // clipped to the image. Leaves blending and the program state changed; binds `framebuffer`.
  // `outputTexture`, when given, is the RGBA32F texture attached to `framebuffer`: the compute
  // passes write it directly (a window's framebuffer has none, and is drawn into).
  void finish(const FinishSource& source, const core::FinishSettings& settings, const OverlayStyle& overlay,
              glm::ivec2 outputOrigin, glm::ivec2 outputSize, GLuint framebuffer, GLuint outputTexture = 0);

  // Supersampled pixels a region must reach beyond the pixels its outputs cover: the widest
  // density-estimation kernel's radius plus the spatial filter's reach.
  static int apron(const core::FinishSettings& settings);

  // Draws the scatter as quads even where points would do (so tests reach the fallback).
  void forceQuads(bool force) { forceQuads_ = force; }

  // How density estimation adds the wide kernels up: sprites drawn with additive blending, or a
  // compute pass in which each pixel gathers the kernels that reach it. Both give the same floats.
  // Gathering is many times faster on a compute GPU and slower on a software rasteriser, so the
  // default follows the renderer (defaultEstimation).
  enum class Estimation { Scatter, Gather };
  void setEstimation(Estimation estimation) { estimation_ = estimation; }
  Estimation estimation() const { return estimation_; }
  // The fold and the tone as compute passes (the default on a GPU) or drawn as fragments (on a
  // software rasteriser); the same floats either way.
  void setComputePasses(bool compute) { computePasses_ = compute; }
  bool computePasses() const { return computePasses_; }

  // GPU time of each pass of the last finish, measured with timestamp queries when timing is on
  // (bench raymarch). Timing waits for the GPU at the end of every finish, so it stays off in the
  // explorer.
  struct PassTimes {
    double scatterMs = 0.0;  // the sprite list and density estimation (scattered or gathered)
    double foldMs = 0.0;
    double toneMs = 0.0;
  };
  void setTimed(bool timed);
  const PassTimes& lastPassTimes() const { return passTimes_; }

 private:
  void ensureTarget(GLuint& texture, GLuint& framebuffer, glm::ivec2& allocated, glm::ivec2 size);

  ShaderProgram scatterProgram_;
  ShaderProgram foldProgram_;
  ShaderProgram foldComputeProgram_;
  // The tone per stage, overlay mode and output (display or linear), built when first used: a
  // software rasteriser runs the code of a branch on a uniform for every pixel, so what a finish
  // does not do is left out.
  const ShaderProgram& toneProgram(bool compute, core::MeshDisplay overlay, bool linearOutput);
  ShaderProgram tonePrograms_[12];
  ShaderProgram compactProgram_;  // compute: the sprite list and the indirect draw's count
  // compute: the scatter's drawn sprites moved to the front (count, offsets, write); built when used
  const ShaderProgram& packProgram(int pass);
  ShaderProgram packPrograms_[3];
  ShaderProgram gatherProgram_;  // compute: density estimation gathered
  // one colour: the empty pixels around a bounded finish; built when used
  const ShaderProgram& fillProgram();
  ShaderProgram fillProgram_;
  Estimation estimation_ = Estimation::Scatter;
  bool computePasses_ = false;
  GLuint command_ = 0;  // DrawArraysIndirectCommand
  GLuint sprites_ = 0, spritesTexture_ = 0;
  std::size_t spriteCapacity_ = 0;                                    // pixels the sprite list holds
  GLuint packedSprites_ = 0, packedSpritesTexture_ = 0, chunks_ = 0;  // the scatter's packed list
  GLuint vertexArray_ = 0;
  GLuint scatter_ = 0, scatterFramebuffer_ = 0;
  glm::ivec2 scatterSize_{0};
  GLuint log_ = 0, logFramebuffer_ = 0;
  glm::ivec2 logSize_{0};
  GLuint emptyOverlay_ = 0;
  float maxPointSize_ = 1.0f;
  bool forceQuads_ = false;
  GLuint timestamps_[4] = {0, 0, 0, 0};  // queries: before the scatter, the fold, the tone, after it
  PassTimes passTimes_;
};

// core::finishImage on the GPU for an image in memory (rows top to bottom), in tiles no larger
// than `maxTile` (and the GL's limits) with aprons: for the still methods, whose sums come from
// tiled marches or from the points histogram.
// With `alphaInImage` the opacity goes into the image's fourth channel and `alpha` stays empty
// (core::takeSilhouetteCoverage reads it there): a 16K print then holds no separate plane of it.
core::FinishedImage finishImageOnGpu(FlameFinisher& finisher, const core::DensityImage& density,
                                     const core::FinishSettings& settings, const core::MeshOverlay* overlay,
                                     int maxTile = 2048, bool alphaInImage = false);

}  // namespace voxflame::gl
