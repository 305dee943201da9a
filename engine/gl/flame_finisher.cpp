#include "flame_finisher.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "core/color.h"
#include "core/error.h"
#include "read_back.h"
#include "renderer_kind.h"

namespace voxflame::gl {

namespace {

// Must match the shaders' array sizes.
constexpr int kMaxKernels = 192;
constexpr int kMaxTaps = 128;
constexpr std::size_t kPackChunk = 64;    // finish_pack.comp.glsl's kChunk
constexpr double kGaussianSupport = 1.5;  // flam3's Gaussian support (core/flame/image.cpp)
constexpr double kKernelStep = 1.04;      // the estimator's width quantisation (core/flame/image.cpp)

double gaussian(double x) {
  return std::exp(-2.0 * x * x);
}

// The estimator's kernel table as core::estimateDensity's KernelTable builds it: per kernel
// (the Gaussian's exponent per squared pixel of distance, 1 / sum of weights, radius, largest
// dx² + dy² inside the disc). The exponent −2 (1.5 d / width)² is −4.5 / width² times d², so the
// shaders take no square root per pixel.
struct KernelTable {
  double maxWidth = 1.0, minWidth = 1.0, curve = 1.0;
  std::vector<float> kernels;  // 4 per kernel
  int count() const { return static_cast<int>(kernels.size() / 4); }
  int maxRadius() const { return kernels.empty() ? 0 : static_cast<int>(kernels[2]); }
};

KernelTable makeKernelTable(const core::ToneMapSettings& tone, int oversample) {
  KernelTable table;
  if (tone.estimatorRadius <= 0.0) return table;
  table.maxWidth = tone.estimatorRadius * oversample + 1.0;
  table.minWidth = std::min(tone.estimatorMinimum * oversample + 1.0, table.maxWidth);
  table.curve = std::max(tone.estimatorCurve, 1e-3);
  const int count =
      std::min(kMaxKernels,
               static_cast<int>(std::lround(std::log(table.maxWidth / table.minWidth) / std::log(kKernelStep))) + 1);
  for (int i = 0; i < count; ++i) {
    const double width = table.maxWidth / std::pow(kKernelStep, i);
    const int radius = static_cast<int>(std::floor(width));
    double sum = 0.0;
    int largest = 0;
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const double d = std::sqrt(static_cast<double>(dx * dx + dy * dy)) / width;
        if (d > 1.0) continue;
        sum += gaussian(kGaussianSupport * d);
        largest = std::max(largest, dx * dx + dy * dy);
      }
    const double exponentPerSquaredPixel = -2.0 * kGaussianSupport * kGaussianSupport / (width * width);
    table.kernels.insert(table.kernels.end(),
                         {static_cast<float>(exponentPerSquaredPixel), static_cast<float>(1.0 / sum),
                          static_cast<float>(radius), static_cast<float>(largest)});
  }
  return table;
}

// The table of the last settings: a live frame finishes with the same ones as the frame before,
// and a wide table (radius 20 at oversample 4) costs milliseconds to build.
const KernelTable& kernelTable(const core::ToneMapSettings& tone, int oversample) {
  thread_local KernelTable table;
  thread_local std::array<double, 4> key{-1.0, -1.0, -1.0, -1.0};
  const std::array<double, 4> wanted{tone.estimatorRadius, tone.estimatorMinimum, tone.estimatorCurve,
                                     static_cast<double>(oversample)};
  if (wanted != key) {
    table = makeKernelTable(tone, oversample);
    key = wanted;
  }
  return table;
}

// flam3's spatial filter as core::spatialFilter builds it, as 1D weights whose products are its
// normalised 2D ones (the 2D Gaussian is separable and so is its sum).
struct FilterTaps {
  int taps = 1;
  int offset = 0;
  std::vector<float> weights;
};

FilterTaps filterTaps(int oversample, double radius) {
  FilterTaps f;
  const double fw = 2.0 * kGaussianSupport * oversample * std::max(0.0, radius);
  f.taps = static_cast<int>(fw) + 1;
  if ((f.taps ^ oversample) & 1) ++f.taps;
  if (f.taps > kMaxTaps) throw core::Error("the spatial filter is too wide: lower filter_radius or the oversample");
  const double adjust = fw > 0.0 ? kGaussianSupport * f.taps / fw : 1.0;
  double sum = 0.0;
  std::vector<double> w(static_cast<std::size_t>(f.taps));
  for (int i = 0; i < f.taps; ++i) {
    const double x = ((2.0 * i + 1.0) / f.taps - 1.0) * adjust;
    w[static_cast<std::size_t>(i)] = fw > 0.0 ? gaussian(x) : 1.0;
    sum += w[static_cast<std::size_t>(i)];
  }
  for (double v : w) f.weights.push_back(static_cast<float>(v / sum));
  f.offset = (f.taps - oversample) / 2;
  return f;
}

GLuint makeTexture() {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  // texelFetch only, but the texture must be complete: no mipmaps.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

void bindTexture(const ShaderProgram& program, const char* name, int unit, GLuint texture) {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  glUniform1i(program.uniform(name), unit);
}

// The finishing shaders share finish_common.glsl, put after the version line.
ShaderSource withDefine(const ShaderSource& shader, const char* define) {
  return {shader.file, std::string("#version 430 core\n#define ") + define + "\n#line 1\n" + shader.text};
}

ShaderSource withCommon(const ShaderSource& shader) {
  const ShaderSource common = embeddedShader("finish_common.glsl");
  return {shader.file, "#version 430 core\n" + common.text + "\n#line 1\n" + shader.text};
}

// The fold or the tone (`pass`, whose function `pixelFunction` gives one pixel) as a compute or a
// fragment stage: finish_stage.glsl after it. `defines` are put first.
ShaderSource withStage(const char* pass, const char* pixelFunction, bool compute, const std::string& defines = "") {
  const ShaderSource body = withCommon(embeddedShader(pass));
  return {body.file, std::string("#version 430 core\n") + defines + (compute ? "#define COMPUTE_STAGE\n" : "") +
                         "#define FINISH_PIXEL " + pixelFunction + "\n" + body.text.substr(body.text.find('\n') + 1) +
                         "\n" + embeddedShader("finish_stage.glsl").text};
}

// Runs `program`, a compute stage of the fold or the tone, over `size` pixels of `output`
// (RGBA32F), and makes its writes visible to what reads the output next (a pass, a read-back, a
// draw that samples it).
void dispatchOver(const ShaderProgram& program, GLuint output, glm::ivec2 size) {
  glBindImageTexture(0, output, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glUniform1i(program.uniform("uOutput"), 0);
  glUniform2i(program.uniform("uOutputSize"), size.x, size.y);
  glDispatchCompute(static_cast<GLuint>((size.x + 7) / 8), static_cast<GLuint>((size.y + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
}

// What finish_tone.glsl makes of a pixel with no density and no overlay: the background as
// chosen (sRGB), with the output encoding applied; alpha 0.
glm::vec4 emptyPixel(const core::ToneMapSettings& tone, bool linearOutput) {
  glm::vec3 color = core::linearToSrgb(tone.background);
  color = linearOutput ? glm::pow(glm::max(color, glm::vec3(0.0f)), glm::vec3(static_cast<float>(tone.gamma)))
                       : glm::clamp(color, 0.0f, 1.0f);
  return glm::vec4(color, 0.0f);
}

// `rect` (x, y, width, height) grown by `margin` on every side and clipped to [0, size).
glm::ivec4 grownWithin(glm::ivec4 rect, int margin, glm::ivec2 size) {
  const glm::ivec2 low = glm::max(glm::ivec2(rect.x, rect.y) - margin, glm::ivec2(0));
  const glm::ivec2 high = glm::min(glm::ivec2(rect.x + rect.z, rect.y + rect.w) + margin, size);
  return glm::ivec4(low, glm::max(high - low, glm::ivec2(0)));
}

int glImageLimit() {
  GLint maxTexture = 0, maxRenderbuffer = 0, maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  return std::min({maxTexture, maxRenderbuffer, maxViewport[0], maxViewport[1]});
}

}  // namespace

FlameFinisher::FlameFinisher()
    : scatterProgram_(withCommon(embeddedShader("finish_scatter.vert.glsl")),
                      embeddedShader("finish_scatter.frag.glsl")),
      foldProgram_(embeddedShader("fullscreen.vert.glsl"), withStage("finish_fold.glsl", "foldPixel", false)),
      foldComputeProgram_(withStage("finish_fold.glsl", "foldPixel", true)),
      compactProgram_(withCommon(embeddedShader("finish_compact.comp.glsl"))),
      gatherProgram_(withCommon(embeddedShader("finish_gather.comp.glsl"))) {
  // Sprites are the faster on a software rasteriser, gathering on a GPU (H200: 0.7 against 27 ms
  // at 1920×1080), where rasterising and blending run on a few multiprocessors; so are the fold
  // and the tone as compute passes there.
  const bool software = softwareRasteriser();
  estimation_ = software ? Estimation::Scatter : Estimation::Gather;
  computePasses_ = !software;
  glGenBuffers(1, &command_);
  glGenBuffers(1, &sprites_);
  glGenTextures(1, &spritesTexture_);
  glGenBuffers(1, &packedSprites_);
  glGenTextures(1, &packedSpritesTexture_);
  glGenBuffers(1, &chunks_);
  glGenVertexArrays(1, &vertexArray_);
  GLfloat range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, range);
  maxPointSize_ = range[1];
  emptyOverlay_ = makeTexture();
  const float nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, nothing);
}

FlameFinisher::~FlameFinisher() {
  if (timestamps_[0]) glDeleteQueries(4, timestamps_);
  glDeleteBuffers(1, &command_);
  glDeleteBuffers(1, &sprites_);
  glDeleteTextures(1, &spritesTexture_);
  glDeleteBuffers(1, &packedSprites_);
  glDeleteTextures(1, &packedSpritesTexture_);
  glDeleteBuffers(1, &chunks_);
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteFramebuffers(1, &scatterFramebuffer_);
  glDeleteFramebuffers(1, &logFramebuffer_);
  glDeleteTextures(1, &scatter_);
  glDeleteTextures(1, &log_);
  glDeleteTextures(1, &emptyOverlay_);
}

// The pack's passes and the fill serve only the software rasteriser's way (scattered, drawn), so
// they are built when first used rather than with the finisher.
const ShaderProgram& FlameFinisher::packProgram(int pass) {
  static constexpr const char* kPasses[3] = {"COUNT", "OFFSETS", "WRITE"};
  ShaderProgram& program = packPrograms_[pass];
  if (!program.id()) program = ShaderProgram(withDefine(embeddedShader("finish_pack.comp.glsl"), kPasses[pass]));
  return program;
}

const ShaderProgram& FlameFinisher::fillProgram() {
  if (!fillProgram_.id())
    fillProgram_ = ShaderProgram(embeddedShader("fullscreen.vert.glsl"), embeddedShader("fill.frag.glsl"));
  return fillProgram_;
}

const ShaderProgram& FlameFinisher::toneProgram(bool compute, core::MeshDisplay overlay, bool linearOutput) {
  const int mode = overlay == core::MeshDisplay::Ghost ? 1 : overlay == core::MeshDisplay::Silhouette ? 2 : 0;
  ShaderProgram& program = tonePrograms_[4 * mode + (linearOutput ? 2 : 0) + (compute ? 1 : 0)];
  if (program.id()) return program;
  std::string defines = mode == 1 ? "#define OVERLAY_GHOST\n" : mode == 2 ? "#define OVERLAY_SILHOUETTE\n" : "";
  if (linearOutput) defines += "#define LINEAR_OUTPUT\n";
  const ShaderSource source = withStage("finish_tone.glsl", "tonePixel", compute, defines);
  program = compute ? ShaderProgram(source) : ShaderProgram(embeddedShader("fullscreen.vert.glsl"), source);
  return program;
}

int FlameFinisher::apron(const core::FinishSettings& settings) {
  const int oversample = std::max(1, settings.oversample);
  return kernelTable(settings.tone, oversample).maxRadius() + filterTaps(oversample, settings.filterRadius).taps;
}

void FlameFinisher::ensureTarget(GLuint& texture, GLuint& framebuffer, glm::ivec2& allocated, glm::ivec2 size) {
  if (texture && allocated == size) return;
  if (!texture) {
    texture = makeTexture();
    glGenFramebuffers(1, &framebuffer);
  }
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  allocated = size;
  if (!complete)
    throw core::Error("could not make a float image of " + std::to_string(size.x) + "×" + std::to_string(size.y) +
                      " pixels to finish the picture in");
}

void FlameFinisher::setTimed(bool timed) {
  if (timed && !timestamps_[0]) glGenQueries(4, timestamps_);
  if (!timed && timestamps_[0]) {
    glDeleteQueries(4, timestamps_);
    for (GLuint& query : timestamps_) query = 0;
  }
}

void FlameFinisher::finish(const FinishSource& source, const core::FinishSettings& settings,
                           const OverlayStyle& overlay, glm::ivec2 outputOrigin, glm::ivec2 outputSize,
                           GLuint framebuffer, GLuint outputTexture) {
  const int oversample = std::max(1, settings.oversample);
  const core::ToneMapSettings& tone = settings.tone;
  const KernelTable& kernels = kernelTable(tone, oversample);
  const bool estimate = kernels.count() > 0;
  const int pad = kernels.maxRadius();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vertexArray_);

  const bool timed = timestamps_[0] != 0;
  if (timed) glQueryCounter(timestamps_[0], GL_TIMESTAMP);

  // 1. Scatter.
  auto setKernelUniforms = [&](const ShaderProgram& p) {
    glUniform1f(p.uniform("uMaxWidth"), static_cast<float>(kernels.maxWidth));
    glUniform1f(p.uniform("uMinWidth"), static_cast<float>(kernels.minWidth));
    glUniform1f(p.uniform("uCurve"), static_cast<float>(kernels.curve));
    glUniform1i(p.uniform("uKernelCount"), std::max(kernels.count(), 1));
    if (estimate) glUniform4fv(p.uniform("uKernels"), kernels.count(), kernels.kernels.data());
    glUniform1f(p.uniform("uHitsPerUnit"), static_cast<float>(source.hitsPerUnitDensity));
    glUniform1f(p.uniform("uBrightness"), static_cast<float>(tone.brightness));
    glUniform1i(p.uniform("uPad"), pad);
  };
  if (estimate) {
    const glm::ivec2 padded = source.size + 2 * pad;
    ensureTarget(scatter_, scatterFramebuffer_, scatterSize_, padded);
    if (estimation_ == Estimation::Scatter) {  // the gather writes every pixel
      glBindFramebuffer(GL_FRAMEBUFFER, scatterFramebuffer_);
      glViewport(0, 0, padded.x, padded.y);
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    const bool quads = forceQuads_ || static_cast<float>(2 * pad + 1) > maxPointSize_;
    // The sprite list: room for every pixel, grown only.
    const std::size_t pixels = static_cast<std::size_t>(source.size.x) * static_cast<std::size_t>(source.size.y);
    if (pixels > spriteCapacity_) {
      spriteCapacity_ = pixels;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, sprites_);
      glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(8 * pixels), nullptr, GL_DYNAMIC_COPY);
      glBindTexture(GL_TEXTURE_BUFFER, spritesTexture_);
      glTexBuffer(GL_TEXTURE_BUFFER, GL_RG32UI, sprites_);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, packedSprites_);
      glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(8 * pixels), nullptr, GL_DYNAMIC_COPY);
      glBindTexture(GL_TEXTURE_BUFFER, packedSpritesTexture_);
      glTexBuffer(GL_TEXTURE_BUFFER, GL_RG32UI, packedSprites_);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, chunks_);
      glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(4 * (pixels / kPackChunk + 1)), nullptr,
                   GL_DYNAMIC_COPY);
    }
    // Every pixel has a slot, in pixel order (so the sums add up alike every time): the gather
    // reads them by pixel, and the scatter draws those that scatter something (its count is set
    // on the GPU by finish_pack.comp.glsl).
    const GLuint command[4] = {static_cast<GLuint>(pixels) * (quads ? 6u : 1u), 1, 0, 0};
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, command_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(command), command, GL_DYNAMIC_COPY);
    const ShaderProgram& compact = compactProgram_;
    glUseProgram(compact.id());
    glUniform1f(compact.uniform("uMaxWidth"), static_cast<float>(kernels.maxWidth));
    glUniform1f(compact.uniform("uMinWidth"), static_cast<float>(kernels.minWidth));
    glUniform1f(compact.uniform("uCurve"), static_cast<float>(kernels.curve));
    glUniform1i(compact.uniform("uKernelCount"), kernels.count());
    glUniform4fv(compact.uniform("uKernels"), kernels.count(), kernels.kernels.data());
    glUniform1f(compact.uniform("uHitsPerUnit"), static_cast<float>(source.hitsPerUnitDensity));
    glUniform2i(compact.uniform("uSize"), source.size.x, source.size.y);
    bindTexture(compact, "uDensity", 0, source.density);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, command_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, sprites_);
    glDispatchCompute(static_cast<GLuint>((source.size.x + 7) / 8), static_cast<GLuint>((source.size.y + 7) / 8), 1);
    // The draw reads the count as its command and the list through a buffer texture.
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);

    if (estimation_ == Estimation::Gather) {
      const ShaderProgram& p = gatherProgram_;
      glUseProgram(p.id());
      setKernelUniforms(p);
      glUniform2i(p.uniform("uSize"), source.size.x, source.size.y);
      bindTexture(p, "uDensity", 0, source.density);
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_BUFFER, spritesTexture_);
      glUniform1i(p.uniform("uSprites"), 1);
      glBindImageTexture(0, scatter_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      glUniform1i(p.uniform("uTarget"), 0);
      glDispatchCompute(static_cast<GLuint>((padded.x + 7) / 8), static_cast<GLuint>((padded.y + 7) / 8), 1);
      glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
      glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      glBindTexture(GL_TEXTURE_BUFFER, 0);
    } else {
      // Only the drawn sprites go to the vertex stage, packed to the front in pixel order.
      const GLuint chunks = static_cast<GLuint>((pixels + kPackChunk - 1) / kPackChunk);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, chunks_);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, packedSprites_);
      for (int pass = 0; pass < 3; ++pass) {
        const ShaderProgram& pack = packProgram(pass);
        glUseProgram(pack.id());
        glUniform1ui(pack.uniform("uSlots"), static_cast<GLuint>(pixels));
        glUniform1ui(pack.uniform("uChunks"), chunks);
        glUniform1ui(pack.uniform("uVerticesPerSprite"), quads ? 6u : 1u);
        glDispatchCompute(pass == 1 ? 1u : (chunks + 63) / 64, 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
      }
      const ShaderProgram& p = scatterProgram_;
      glUseProgram(p.id());
      setKernelUniforms(p);
      glUniform2i(p.uniform("uSize"), source.size.x, source.size.y);
      glUniform1i(p.uniform("uQuads"), quads ? 1 : 0);
      bindTexture(p, "uDensity", 0, source.density);
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_BUFFER, packedSpritesTexture_);
      glUniform1i(p.uniform("uSprites"), 1);
      glEnable(GL_BLEND);
      glBlendEquation(GL_FUNC_ADD);
      glBlendFunc(GL_ONE, GL_ONE);
      glEnable(GL_PROGRAM_POINT_SIZE);
      glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_);
      glDrawArraysIndirect(quads ? GL_TRIANGLES : GL_POINTS, nullptr);
      glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
      glBindTexture(GL_TEXTURE_BUFFER, 0);
      glDisable(GL_PROGRAM_POINT_SIZE);
      glDisable(GL_BLEND);
    }
  }

  // Where only part of the region can hold density, the fragment passes shade only around it:
  // the fold as far as the tone's filter reads, the tone as far as density estimation spreads
  // the density and the filter spreads it again. Beyond that a pixel is the empty pixel.
  const FilterTaps filter = filterTaps(oversample, settings.filterRadius);
  const bool withOverlay = source.overlay != 0 && overlay.mode != core::MeshDisplay::Off;
  const bool bounded = !computePasses_ && source.content.z >= 0 && oversample == 1 && outputSize == source.size &&
                       outputOrigin == source.origin;
  const glm::ivec4 foldRect = grownWithin(source.content, pad + 2 * filter.taps, source.size);
  const glm::ivec4 toneRect = grownWithin(source.content, pad + filter.taps, source.size);

  // 2. Fold: the log image of the whole source region.
  if (timed) glQueryCounter(timestamps_[1], GL_TIMESTAMP);
  {
    ensureTarget(log_, logFramebuffer_, logSize_, source.size);
    const ShaderProgram& p = computePasses_ ? foldComputeProgram_ : foldProgram_;
    glUseProgram(p.id());
    setKernelUniforms(p);
    glUniform1i(p.uniform("uEstimate"), estimate ? 1 : 0);
    glUniform2i(p.uniform("uOrigin"), source.origin.x, source.origin.y);
    glUniform2i(p.uniform("uFullSize"), source.fullSize.x, source.fullSize.y);
    bindTexture(p, "uDensity", 0, source.density);
    bindTexture(p, "uScatter", 1, estimate ? scatter_ : emptyOverlay_);
    if (computePasses_) {
      dispatchOver(p, log_, source.size);
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, logFramebuffer_);
      glViewport(0, 0, source.size.x, source.size.y);
      if (bounded) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(foldRect.x, foldRect.y, foldRect.z, foldRect.w);
      }
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glDisable(GL_SCISSOR_TEST);
    }
  }

  // 3. Filter and tone into the caller's framebuffer.
  if (timed) glQueryCounter(timestamps_[2], GL_TIMESTAMP);
  {
    const bool compute = computePasses_ && outputTexture != 0;
    if (!compute) {
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
      glViewport(0, 0, outputSize.x, outputSize.y);
    }
    const core::MeshDisplay overlayMode = withOverlay ? overlay.mode : core::MeshDisplay::Off;
    const ShaderProgram& p = toneProgram(compute, overlayMode, settings.linearOutput);
    glUseProgram(p.id());
    bindTexture(p, "uLog", 1, log_);
    glUniform2i(p.uniform("uLogOrigin"), source.origin.x, source.origin.y);
    glUniform2i(p.uniform("uFullSize"), source.fullSize.x, source.fullSize.y);
    glUniform2i(p.uniform("uOutOrigin"), outputOrigin.x, outputOrigin.y);
    glUniform2i(p.uniform("uOutFullSize"), source.fullSize.x / oversample, source.fullSize.y / oversample);
    glUniform1i(p.uniform("uOversample"), oversample);
    glUniform1i(p.uniform("uTaps"), filter.taps);
    glUniform1i(p.uniform("uTapOffset"), filter.offset);
    glUniform1fv(p.uniform("uFilter"), filter.taps, filter.weights.data());
    glUniform1f(p.uniform("uGamma"), static_cast<float>(tone.gamma));
    glUniform1f(p.uniform("uGammaThreshold"), static_cast<float>(tone.gammaThreshold));
    glUniform1f(p.uniform("uVibrancy"), static_cast<float>(tone.vibrancy));
    glUniform1f(p.uniform("uHighlightPower"), static_cast<float>(tone.highlightPower));
    glUniform1f(p.uniform("uExposure"), static_cast<float>(std::exp2(tone.exposure)));
    glUniform1f(p.uniform("uContrast"), static_cast<float>(tone.contrast));
    const glm::vec3 background = core::linearToSrgb(tone.background);
    glUniform3f(p.uniform("uBackground"), background.r, background.g, background.b);
    bindTexture(p, "uOverlay", 2, withOverlay ? source.overlay : emptyOverlay_);
    glUniform2i(p.uniform("uOverlayOrigin"), source.overlayOrigin.x, source.overlayOrigin.y);
    glUniform1f(p.uniform("uOverlayStrength"), static_cast<float>(overlay.strength));
    const glm::vec3 line = core::linearToSrgb(overlay.color);
    glUniform3f(p.uniform("uLineColor"), line.r, line.g, line.b);
    if (compute) {
      dispatchOver(p, outputTexture, outputSize);
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);  // as the fragment stage leaves it
    } else if (bounded) {
      const glm::vec4 empty = emptyPixel(tone, settings.linearOutput);
      glEnable(GL_SCISSOR_TEST);
      glScissor(toneRect.x, toneRect.y, toneRect.z, toneRect.w);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      // The rest of the viewport: the empty pixel, in up to four strips around the tone's rectangle.
      const ShaderProgram& fill = fillProgram();
      glUseProgram(fill.id());
      glUniform4f(fill.uniform("uColour"), empty.r, empty.g, empty.b, empty.a);
      const int right = toneRect.x + toneRect.z, top = toneRect.y + toneRect.w;
      for (const glm::ivec4 strip :
           {glm::ivec4(0, 0, outputSize.x, toneRect.y), glm::ivec4(0, top, outputSize.x, outputSize.y - top),
            glm::ivec4(0, toneRect.y, toneRect.x, toneRect.w),
            glm::ivec4(right, toneRect.y, outputSize.x - right, toneRect.w)}) {
        if (strip.z <= 0 || strip.w <= 0) continue;
        glScissor(strip.x, strip.y, strip.z, strip.w);
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
      glDisable(GL_SCISSOR_TEST);
    } else {
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  if (timed) {
    glQueryCounter(timestamps_[3], GL_TIMESTAMP);
    GLuint64 at[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) glGetQueryObjectui64v(timestamps_[i], GL_QUERY_RESULT, &at[i]);
    passTimes_ = {1e-6 * static_cast<double>(at[1] - at[0]), 1e-6 * static_cast<double>(at[2] - at[1]),
                  1e-6 * static_cast<double>(at[3] - at[2])};
  }
}

core::FinishedImage finishImageOnGpu(FlameFinisher& finisher, const core::DensityImage& density,
                                     const core::FinishSettings& settings, const core::MeshOverlay* overlay,
                                     int maxTile, bool alphaInImage) {
  const int oversample = std::max(1, settings.oversample);
  if (density.width % oversample || density.height % oversample)
    throw core::Error("the density image is not a whole number of supersampled pixels");
  const int width = density.width / oversample, height = density.height / oversample;
  core::FinishedImage result;
  result.image.width = width;
  result.image.height = height;
  result.image.pixels.assign(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 1.0f);
  if (!alphaInImage) result.alpha.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
  if (width == 0 || height == 0) return result;
  const bool useOverlay = overlay && overlay->mode != core::MeshDisplay::Off && overlay->width == width &&
                          overlay->height == height && !overlay->rgba.empty();
  OverlayStyle style;
  if (useOverlay) style = {overlay->mode, overlay->color, overlay->strength};

  // Output tiles whose sources (the tile, its apron and the scatter's padding) fit the GL's limits.
  const int apron = FlameFinisher::apron(settings);
  const int limit = glImageLimit();
  const int pad = apron;  // the scatter pads by the widest kernel, less than the apron
  int tile = std::max(16, (std::min(maxTile, limit) - 2 * apron) / oversample);
  tile = std::max(1, std::min(tile, (limit - 2 * apron - 2 * pad) / oversample));

  GLuint densityTexture = 0, overlayTexture = 0, outputTexture = 0, outputFramebuffer = 0;
  std::vector<float> rows;
  std::vector<std::uint8_t> byteRows;
  // A region [lo, hi) of an image in memory (rows top to bottom) into `texture`: float sums as
  // RGBA32F, the mesh layer's bytes as RGBA8 (the shader reads byte / 255, as core::finishImage
  // does). GL's rows run bottom to top: GL row y is the image's row imageHeight - 1 - y.
  auto upload = [&](GLuint& texture, const auto* pixels, int imageWidth, int imageHeight, glm::ivec2 lo,
                    glm::ivec2 hi) {
    constexpr bool kFloats = std::is_same_v<std::remove_cv_t<std::remove_pointer_t<decltype(pixels)>>, float>;
    auto& into = [&]() -> auto& {
      if constexpr (kFloats)
        return rows;
      else
        return byteRows;
    }
    ();
    const int w = hi.x - lo.x, h = hi.y - lo.y;
    into.resize(4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y)
      std::copy_n(pixels + 4 * (static_cast<std::size_t>(imageHeight - 1 - (lo.y + y)) * imageWidth + lo.x),
                  4 * static_cast<std::size_t>(w), &into[4 * static_cast<std::size_t>(y) * w]);
    if (!texture) texture = makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, kFloats ? GL_RGBA32F : GL_RGBA8, w, h, 0, GL_RGBA,
                 kFloats ? GL_FLOAT : GL_UNSIGNED_BYTE, into.data());
  };
  try {
    for (int oy = 0; oy < height; oy += tile)
      for (int ox = 0; ox < width; ox += tile) {
        const glm::ivec2 outLo(ox, oy), outHi(std::min(width, ox + tile), std::min(height, oy + tile));
        const glm::ivec2 outSize = outHi - outLo;
        FinishSource source;
        const glm::ivec2 lo = glm::max(outLo * oversample - apron, glm::ivec2(0));
        const glm::ivec2 hi = glm::min(outHi * oversample + apron, glm::ivec2(density.width, density.height));
        upload(densityTexture, density.values.data(), density.width, density.height, lo, hi);
        source.density = densityTexture;
        source.origin = lo;
        source.size = hi - lo;
        source.fullSize = glm::ivec2(density.width, density.height);
        source.hitsPerUnitDensity = density.hitsPerUnitDensity;
        if (useOverlay) {
          // The silhouette's edge looks one pixel around.
          const glm::ivec2 overlayLo = glm::max(outLo - 1, glm::ivec2(0));
          const glm::ivec2 overlayHi = glm::min(outHi + 1, glm::ivec2(width, height));
          upload(overlayTexture, overlay->rgba.data(), width, height, overlayLo, overlayHi);
          source.overlay = overlayTexture;
          source.overlayOrigin = overlayLo;
        }
        if (!outputTexture) {
          outputTexture = makeTexture();
          glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, std::min(tile, width), std::min(tile, height), 0, GL_RGBA,
                       GL_FLOAT, nullptr);
          glGenFramebuffers(1, &outputFramebuffer);
          glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer);
          glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, outputTexture, 0);
          if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw core::Error("could not make a float image to finish the picture in");
        }
        finisher.finish(source, settings, style, outLo, outSize, outputFramebuffer, outputTexture);
        const std::vector<float> pixels = readRgbaFloat(outputFramebuffer, {0, 0, outSize.x, outSize.y});
        // Tile row t (top first) is GL row outHi.y - 1 - t: the image's row height - outHi.y + t.
        for (int t = 0; t < outSize.y; ++t) {
          const int y = height - outHi.y + t;
          for (int x = 0; x < outSize.x; ++x) {
            const float* p = &pixels[4 * (static_cast<std::size_t>(t) * outSize.x + x)];
            float* o = result.image.at(ox + x, y);
            std::copy_n(p, 3, o);
            if (alphaInImage) {
              o[3] = p[3];
            } else {
              o[3] = 1.0f;
              result.alpha[static_cast<std::size_t>(y) * width + ox + x] = p[3];
            }
          }
        }
      }
  } catch (...) {
    glDeleteTextures(1, &densityTexture);
    glDeleteTextures(1, &overlayTexture);
    glDeleteTextures(1, &outputTexture);
    glDeleteFramebuffers(1, &outputFramebuffer);
    throw;
  }
  glDeleteTextures(1, &densityTexture);
  glDeleteTextures(1, &overlayTexture);
  glDeleteTextures(1, &outputTexture);
  glDeleteFramebuffers(1, &outputFramebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return result;
}

}  // namespace voxflame::gl
