#include "volume_renderer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "core/error.h"
#include "gpu_volume.h"
#include "read_back.h"
#include "renderer_kind.h"

namespace voxflame::gl {

namespace {

// A mesh layer of the settings' look with nothing drawn yet.
core::MeshOverlay emptyOverlay(const RenderSettings& settings, int width, int height) {
  core::MeshOverlay mesh;
  mesh.mode = settings.render.meshDisplay;
  mesh.color = settings.render.meshColor;
  mesh.strength = settings.render.meshStrength;
  mesh.width = width;
  mesh.height = height;
  mesh.rgba.assign(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  return mesh;
}

// The pixels of a width × height target that the box can cover under viewProjection (x, y,
// width, height), with two pixels to spare for the sub-pixel jitter and rounding; all of them
// when a corner lies behind the eye.
glm::ivec4 screenOutline(const core::Box& box, const glm::dmat4& viewProjection, int width, int height) {
  glm::dvec2 low(std::numeric_limits<double>::max()), high(std::numeric_limits<double>::lowest());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                       (corner & 4) ? box.max.z : box.min.z);
    const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
    if (clip.w <= 1e-9) return glm::ivec4(0, 0, width, height);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    low = glm::min(low, ndc);
    high = glm::max(high, ndc);
  }
  const glm::dvec2 size(width, height);
  const glm::ivec2 first = glm::ivec2(glm::clamp(glm::floor((low * 0.5 + 0.5) * size) - 2.0, glm::dvec2(0.0), size));
  const glm::ivec2 last = glm::ivec2(glm::clamp(glm::ceil((high * 0.5 + 0.5) * size) + 2.0, glm::dvec2(0.0), size));
  return glm::ivec4(first, glm::max(last - first, glm::ivec2(0)));
}

glm::ivec4 unite(glm::ivec4 a, glm::ivec4 b) {
  if (a.z <= 0 || a.w <= 0) return b;
  if (b.z <= 0 || b.w <= 0) return a;
  const glm::ivec2 low = glm::min(glm::ivec2(a.x, a.y), glm::ivec2(b.x, b.y));
  const glm::ivec2 high = glm::max(glm::ivec2(a.x + a.z, a.y + a.w), glm::ivec2(b.x + b.z, b.y + b.w));
  return glm::ivec4(low, high - low);
}

GLuint makeTexture(GLenum target, GLint filter) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(target, texture);
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (target == GL_TEXTURE_3D) glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return texture;
}

// Sub-pixel offsets of the R2 low-discrepancy sequence, so S samples cover a pixel evenly.
glm::dvec2 samplePixelOffset(int sampleIndex) {
  if (sampleIndex == 0) return {0.0, 0.0};
  constexpr double kG = 1.32471795724474602596;
  const double a1 = 1.0 / kG, a2 = 1.0 / (kG * kG);
  const double n = static_cast<double>(sampleIndex);
  return {std::fmod(0.5 + a1 * n, 1.0) - 0.5, std::fmod(0.5 + a2 * n, 1.0) - 0.5};
}

void setUniform(const ShaderProgram& program, const char* name, glm::vec3 v) {
  glUniform3f(program.uniform(name), v.x, v.y, v.z);
}
// Binds `texture` to texture unit `unit` and points the sampler uniform `name` at it.
void bindSampler(const ShaderProgram& program, const char* name, int unit, GLenum target, GLuint texture) {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(target, texture);
  glUniform1i(program.uniform(name), unit);
}

void setUniform(const ShaderProgram& program, const char* name, double v) {
  glUniform1f(program.uniform(name), static_cast<float>(v));
}

}  // namespace

FrameTarget::~FrameTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteFramebuffers(1, &meshFramebuffer_);
  glDeleteTextures(1, &radiance_);
  glDeleteTextures(1, &meshLayer_);
  glDeleteRenderbuffers(1, &meshDepth_);
  glDeleteTextures(1, &finished_);
  glDeleteFramebuffers(1, &finishedFramebuffer_);
  glDeleteTextures(1, &pending_);
  glDeleteFramebuffers(1, &pendingFramebuffer_);
  glDeleteTextures(1, &stripDensity_);
  glDeleteTextures(1, &stripOverlay_);
  glDeleteTextures(1, &stripOutput_);
  glDeleteFramebuffers(1, &stripFramebuffer_);
}

core::DensityImage FrameTarget::readDensity() const {
  core::DensityImage image;
  image.width = width_;
  image.height = height_;
  image.hitsPerUnitDensity = hitsPerUnitDensity_;
  image.values = readRgbaFloat(framebuffer_, {0, 0, width_, height_});
  return image;
}

void FrameTarget::setSums(const core::DensityImage& image, int oversample) {
  oversample = std::max(1, oversample);
  if (image.width % oversample != 0 || image.height % oversample != 0 ||
      image.values.size() != 4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw core::Error("the sums are not a whole supersampled image");
  resize(image.width / oversample, image.height / oversample);
  const glm::ivec2 size(image.width, image.height);
  glBindTexture(GL_TEXTURE_2D, radiance_);
  if (radianceSize_ != size) glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  // The image's rows run top to bottom, GL's bottom to top.
  for (int y = 0; y < size.y; ++y)
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, size.y - 1 - y, size.x, 1, GL_RGBA, GL_FLOAT,
                    &image.values[4 * static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x)]);
  glBindTexture(GL_TEXTURE_2D, 0);
  radianceSize_ = size;
  oversample_ = oversample;
  hitsPerUnitDensity_ = image.hitsPerUnitDensity;
  content_ = glm::ivec4(0, 0, size.x, size.y);
  ++revision_;
}

core::MeshOverlay FrameTarget::readMeshOverlay(const RenderSettings& settings) const {
  core::MeshOverlay overlay = emptyOverlay(settings, 0, 0);
  overlay.width = width_;
  overlay.height = height_;
  overlay.rgba = readRgba8(meshFramebuffer_, {0, 0, width_, height_});
  return overlay;
}

void FrameTarget::copyFrom(const FrameTarget& other) {
  resize(other.width_, other.height_);
  glCopyImageSubData(other.radiance_, GL_TEXTURE_2D, 0, 0, 0, 0, radiance_, GL_TEXTURE_2D, 0, 0, 0, 0, width_, height_,
                     1);
  glCopyImageSubData(other.meshLayer_, GL_TEXTURE_2D, 0, 0, 0, 0, meshLayer_, GL_TEXTURE_2D, 0, 0, 0, 0, width_,
                     height_, 1);
  samples = other.samples;
  hitsPerUnitDensity_ = other.hitsPerUnitDensity_;
  content_ = other.content_;
  ++revision_;
}

void FrameTarget::resize(int width, int height) {
  if (width == width_ && height == height_ && framebuffer_) return;
  ++revision_;
  width_ = std::max(1, width);
  height_ = std::max(1, height);
  radianceSize_ = glm::ivec2(width_, height_);
  oversample_ = 1;
  samples = 0;
  content_ = glm::ivec4(0);  // cleared below
  if (!framebuffer_) {
    glGenFramebuffers(1, &framebuffer_);
    glGenFramebuffers(1, &meshFramebuffer_);
    radiance_ = makeTexture(GL_TEXTURE_2D, GL_LINEAR);
    meshLayer_ = makeTexture(GL_TEXTURE_2D, GL_LINEAR);
    glGenRenderbuffers(1, &meshDepth_);
  }
  glBindTexture(GL_TEXTURE_2D, radiance_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width_, height_, 0, GL_RGBA, GL_FLOAT, nullptr);
  glBindTexture(GL_TEXTURE_2D, meshLayer_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindRenderbuffer(GL_RENDERBUFFER, meshDepth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, radiance_, 0);
  const bool radianceOk = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, meshFramebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, meshLayer_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, meshDepth_);
  const bool meshOk = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!radianceOk || !meshOk)
    throw core::Error("could not make an offscreen image of " + std::to_string(width) + "×" + std::to_string(height) +
                      " pixels");
}

namespace {

// A march stage's source behind the version line, the variant's defines and the body both
// stages share.
ShaderSource withMarchBody(const ShaderSource& stage, const std::string& defines) {
  return {stage.file,
          "#version 430 core\n" + defines + embeddedShader("march_common.glsl").text + "\n#line 1\n" + stage.text};
}

}  // namespace

VolumeRenderer::VolumeRenderer()
    : blitProgram_(embeddedShader("fullscreen.vert.glsl"), embeddedShader("blit.frag.glsl")),
      meshProgram_(embeddedShader("mesh.vert.glsl"), embeddedShader("mesh.frag.glsl")),
      finisher_() {
  // The fragment stage is the faster one on a software rasteriser (llvmpipe: 0.5 against 0.66 s a
  // 1280×720 sample at 256³); compute, many times faster on a compute GPU (H200: 0.9 against
  // 24 ms at 1920×1080 and 512³).
  softwareRasteriser_ = softwareRasteriser();
  marchStage_ = softwareRasteriser_ ? MarchStage::Fragment : MarchStage::Compute;
  glGenVertexArrays(1, &vertexArray_);
  for (Slot& slot : slots_) {
    slot.volume = makeTexture(GL_TEXTURE_3D, GL_LINEAR);
    slot.density = makeTexture(GL_TEXTURE_3D, GL_LINEAR);
    slot.emptyDistance = makeTexture(GL_TEXTURE_3D, GL_NEAREST);
  }
  shadowTexture_ = makeTexture(GL_TEXTURE_3D, GL_LINEAR);
}

VolumeRenderer::~VolumeRenderer() {
  for (Slot& slot : slots_) {
    glDeleteTextures(1, &slot.volume);
    glDeleteTextures(1, &slot.density);
    glDeleteTextures(1, &slot.emptyDistance);
  }
  glDeleteTextures(1, &shadowTexture_);
  for (GLuint* buffer : {&shadowSigma_, &shadowDepth_})
    if (*buffer) glDeleteBuffers(1, buffer);
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteVertexArrays(1, &meshArray_);
  glDeleteBuffers(1, &meshVertices_);
  glDeleteBuffers(1, &meshIndices_);
}

const ShaderProgram& VolumeRenderer::marchProgram(unsigned variant) {
  ShaderProgram& program = marchPrograms_[variant];
  if (program.id()) return program;
  std::string defines;
  if (variant & kLighting) defines += "#define LIGHTING\n";
  if (variant & kDensityInColour) defines += "#define DENSITY_IN_COLOUR\n";
  if (variant & kComputeStage)
    program = ShaderProgram(withMarchBody(embeddedShader("march.comp.glsl"), defines));
  else
    program = ShaderProgram(embeddedShader("fullscreen.vert.glsl"),
                            withMarchBody(embeddedShader("march.frag.glsl"), defines));
  return program;
}

void VolumeRenderer::upload(const core::PackedVolume& volume) {
  beginUpload(volume);
  continueUpload(~std::size_t{0});
}

bool VolumeRenderer::densityInColour(const core::ColourLayout& colour) const {
  // Where colour cells are voxels their alpha is the density: a software rasteriser then fetches
  // one texel a step instead of two (it gains nothing from testing the density first, since it
  // fetches the colour for all lanes whenever one needs it); a GPU skips the colour where a
  // step sees no density, which most do.
  return colour.shift == 0 && (densityFetch_ == DensityFetch::FromColour ||
                               (densityFetch_ == DensityFetch::Automatic && softwareRasteriser_));
}

void VolumeRenderer::allocate(Slot& slot, glm::ivec3 size, const core::ColourLayout& colour) {
  const bool withDensity = !densityInColour(colour);
  if (size == slot.allocated && colour.size == slot.colour.size && withDensity == slot.hasDensity) return;
  glBindTexture(GL_TEXTURE_3D, slot.volume);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA16F, colour.size.x, colour.size.y, colour.size.z, 0, GL_RGBA, GL_HALF_FLOAT,
               nullptr);
  // Without its density the texture shrinks to a texel, so it holds no memory either.
  const glm::ivec3 densitySize = withDensity ? size : glm::ivec3(1);
  glBindTexture(GL_TEXTURE_3D, slot.density);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R16F, densitySize.x, densitySize.y, densitySize.z, 0, GL_RED, GL_HALF_FLOAT,
               nullptr);
  slot.allocated = size;
  slot.colour = colour;
  slot.hasDensity = withDensity;
  slot.version = 0;  // the old content is gone until an upload completes
}

void VolumeRenderer::beginUpload(const core::PackedVolume& volume) {
  pending_ = &volume;
  pendingZ_ = 0;
  allocate(slots_[kMain], volume.geometry.size, volume.colour);
  // A GPU copies a whole volume in well under a millisecond; a software rasteriser copies on the
  // CPU's cores, so there it goes in slabs under the upload's budget, like an upload.
  if (volume.onDevice() && !softwareRasteriser_) continueUpload(~std::size_t{0});
}

void VolumeRenderer::uploadProxy(const core::PackedVolume& volume) {
  Slot& slot = slots_[kProxy];
  allocate(slot, volume.geometry.size, volume.colour);
  if (volume.onDevice()) {
    copyFromDevice(slot, volume, 0, volume.geometry.size.z);
    return;
  }
  uploadSlab(slot, volume, 0, volume.geometry.size.z);
  finishUpload(slot, volume);
}

void VolumeRenderer::uploadSlab(Slot& slot, const core::PackedVolume& volume, int firstZ, int endZ) {
  const glm::ivec3 size = volume.geometry.size;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (slot.hasDensity) {
    glBindTexture(GL_TEXTURE_3D, slot.density);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, firstZ, size.x, size.y, endZ - firstZ, GL_RED, GL_HALF_FLOAT,
                    volume.density.data() + volume.geometry.index(0, 0, firstZ));
    uploadedBytes_ += sizeof(std::uint16_t) * static_cast<std::uint64_t>(size.x) * size.y * (endZ - firstZ);
  }
  // The colour cells over these slices (a cell over two slabs goes up with both).
  const glm::ivec3 cells = volume.colour.size;
  const int firstCellZ = firstZ >> volume.colour.shift;
  const int endCellZ = std::min(cells.z, ((endZ - 1) >> volume.colour.shift) + 1);
  glBindTexture(GL_TEXTURE_3D, slot.volume);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, firstCellZ, cells.x, cells.y, endCellZ - firstCellZ, GL_RGBA, GL_HALF_FLOAT,
                  volume.colours.data() + 4 * static_cast<std::size_t>(cells.x) * cells.y * firstCellZ);
  uploadedBytes_ += 4 * sizeof(std::uint16_t) * static_cast<std::uint64_t>(cells.x) * cells.y * (endCellZ - firstCellZ);
}

bool VolumeRenderer::continueUpload(std::size_t budgetBytes) {
  if (!pending_) return true;
  const core::PackedVolume& volume = *pending_;
  const std::size_t voxels = volume.geometry.voxelCount();
  const std::size_t densityValues = slots_[kMain].hasDensity ? voxels : 0;
  const std::size_t slabBytes =
      (densityValues + 4 * volume.colour.cellCount()) * sizeof(std::uint16_t) / std::max(volume.geometry.size.z, 1);
  const int slabs = static_cast<int>(std::clamp<std::size_t>(budgetBytes / std::max<std::size_t>(slabBytes, 1), 1,
                                                             static_cast<std::size_t>(volume.geometry.size.z)));
  const int endZ = std::min(volume.geometry.size.z, pendingZ_ + slabs);
  if (volume.onDevice()) {
    copyFromDevice(slots_[kMain], volume, pendingZ_, endZ);
  } else {
    uploadSlab(slots_[kMain], volume, pendingZ_, endZ);
    if (endZ == volume.geometry.size.z) finishUpload(slots_[kMain], volume);
  }
  pendingZ_ = endZ;
  if (pendingZ_ < volume.geometry.size.z) return false;
  pending_ = nullptr;
  return true;
}

void VolumeRenderer::copyFromDevice(Slot& slot, const core::PackedVolume& volume, int firstZ, int endZ) {
  auto* source = dynamic_cast<GpuVolume*>(volume.device.get());
  if (!source) throw core::Error("a volume on the GPU that this renderer cannot read");
  const glm::ivec3 size = volume.geometry.size, cells = volume.colour.size, bricks = volume.brickCount;
  // The colour cells over these slices (a cell over two slabs is copied with both).
  const int firstCellZ = firstZ >> volume.colour.shift;
  const int endCellZ = std::min(cells.z, ((endZ - 1) >> volume.colour.shift) + 1);
  const bool last = endZ == size.z;
  {
    // Held until the copy's sync is made, so the backend cannot delete the textures meanwhile. The
    // volume is not packed into again while it is shown (its buffer is with the live view), so
    // the slabs of one copy all come from one pack.
    std::lock_guard lock(source->mutex);
    if (!source->alive || !source->packed || source->size != size || source->colourSize != cells) {
      slot.version = 0;  // the backend is gone: nothing to show from it
      return;
    }
    glWaitSync(source->packed, 0, GL_TIMEOUT_IGNORED);  // the pack's commands come first on the device
    glCopyImageSubData(source->colour, GL_TEXTURE_3D, 0, 0, 0, firstCellZ, slot.volume, GL_TEXTURE_3D, 0, 0, 0,
                       firstCellZ, cells.x, cells.y, endCellZ - firstCellZ);
    if (slot.hasDensity)
      glCopyImageSubData(source->density, GL_TEXTURE_3D, 0, 0, 0, firstZ, slot.density, GL_TEXTURE_3D, 0, 0, 0, firstZ,
                         size.x, size.y, endZ - firstZ);
    if (last) {
      // The empty distances are small (a byte per 4³ voxels): copied whole with the last slab, so
      // they match the volume.
      glBindTexture(GL_TEXTURE_3D, slot.emptyDistance);
      glTexImage3D(GL_TEXTURE_3D, 0, GL_R8UI, bricks.x, bricks.y, bricks.z, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                   nullptr);
      glCopyImageSubData(source->emptyDistance, GL_TEXTURE_3D, 0, 0, 0, 0, slot.emptyDistance, GL_TEXTURE_3D, 0, 0, 0,
                         0, bricks.x, bricks.y, bricks.z);
    }
    if (source->copied) glDeleteSync(source->copied);
    source->copied = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  }
  glFlush();  // the backend's next pack into these textures waits on the sync
  copiedBytes_ += 4 * sizeof(std::uint16_t) * static_cast<std::uint64_t>(cells.x) * cells.y * (endCellZ - firstCellZ) +
                  (slot.hasDensity ? sizeof(std::uint16_t) * static_cast<std::uint64_t>(size.x) * size.y *
                                         static_cast<std::uint64_t>(endZ - firstZ)
                                   : 0);
  if (last) setSlotVolume(slot, volume);
}

void VolumeRenderer::finishUpload(Slot& slot, const core::PackedVolume& volume) {
  // The empty distances are small (a byte per 4³ voxels); they go up whole, with the last slab, so
  // they match the volume.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, slot.emptyDistance);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8UI, volume.brickCount.x, volume.brickCount.y, volume.brickCount.z, 0,
               GL_RED_INTEGER, GL_UNSIGNED_BYTE, volume.emptyDistance.data());
  uploadedBytes_ += volume.emptyDistance.size();
  setSlotVolume(slot, volume);
}

void VolumeRenderer::setSlotVolume(Slot& slot, const core::PackedVolume& volume) {
  slot.geometry = volume.geometry;
  slot.brickCount = volume.brickCount;
  slot.texelDensity = volume.texelDensity;
  slot.referenceDensity = volume.referenceDensity;
  slot.insideVoxels = volume.insideVoxels;
  slot.points = static_cast<double>(volume.points);
  slot.version = std::max<std::uint64_t>(volume.version, 1);
}

void VolumeRenderer::uploadShadow(const core::ShadowVolume& shadow, int downsample, glm::ivec3 sourceSize) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, shadowTexture_);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, shadow.size.x, shadow.size.y, shadow.size.z, 0, GL_RED, GL_UNSIGNED_BYTE,
               shadow.transmittance.data());
  shadowSize_ = shadow.size;
  shadowDownsample_ = std::max(1, downsample);
  shadowSource_ = sourceSize == glm::ivec3(0) ? slots_[kMain].geometry.size : sourceSize;
}

void VolumeRenderer::computeShadow(Source source, glm::dvec3 towardLight, double extinctionScale, int downsample) {
  const Slot& slot = slots_[source == Source::Main ? kMain : kProxy];
  if (slot.version == 0) return;
  const glm::ivec3 voxels = slot.geometry.size;
  downsample = std::max(1, downsample);
  const glm::ivec3 cells = (voxels + (downsample - 1)) / downsample;
  const std::size_t cellCount = static_cast<std::size_t>(cells.x) * cells.y * cells.z;
  auto program = [&](int pass) -> const ShaderProgram& {
    static constexpr const char* kDefines[] = {"#define SIGMA\n", "#define SWEEP\n", "#define TRANSMITTANCE\n"};
    ShaderProgram& built = shadowPrograms_[pass];
    if (!built.id()) {
      const ShaderSource body = embeddedShader("shadow.comp.glsl");
      built = ShaderProgram(
          ShaderSource{body.file, std::string("#version 430 core\n") + kDefines[pass] + "#line 1\n" + body.text});
    }
    glUseProgram(built.id());
    glUniform3i(built.uniform("uVoxels"), voxels.x, voxels.y, voxels.z);
    glUniform3i(built.uniform("uCells"), cells.x, cells.y, cells.z);
    return built;
  };
  for (GLuint* buffer : {&shadowSigma_, &shadowDepth_}) {
    if (!*buffer) glGenBuffers(1, buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(cellCount, 4) * sizeof(float)),
                 nullptr, GL_DYNAMIC_COPY);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, shadowSigma_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, shadowDepth_);
  auto groups = [](std::size_t invocations) { return static_cast<GLuint>((invocations + 255) / 256); };

  // As core::computeShadowVolume: extinction per cell edge from densities relative to the mesh's mean.
  const ShaderProgram& sigma = program(0);
  const bool inAlpha = !slot.hasDensity;
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_3D, inAlpha ? slot.volume : slot.density);
  glUniform1i(sigma.uniform("uDensity"), 0);
  glUniform1i(sigma.uniform("uDensityInAlpha"), inAlpha ? 1 : 0);
  glUniform1i(sigma.uniform("uDownsample"), downsample);
  const double toRelative = slot.texelDensity / std::max(slot.referenceDensity, 1e-30);
  const double perVoxel = extinctionScale / std::max({voxels.x, voxels.y, voxels.z, 1});
  glUniform1f(sigma.uniform("uPerVoxelWeight"),
              static_cast<float>(toRelative * perVoxel / (static_cast<double>(downsample) * downsample)));
  glDispatchCompute(groups(cellCount), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  // The CPU's sweep (core::shadowSweep), one dispatch a slice.
  const core::ShadowSweep plan = core::shadowSweep(towardLight);
  const ShaderProgram& sweep = program(1);
  glUniform1i(sweep.uniform("uAxis"), plan.axis);
  glUniform1i(sweep.uniform("uU"), plan.u);
  glUniform1i(sweep.uniform("uV"), plan.v);
  glUniform2f(sweep.uniform("uShift"), static_cast<float>(plan.shift.x), static_cast<float>(plan.shift.y));
  glUniform1f(sweep.uniform("uPathPerSlice"), static_cast<float>(plan.pathPerSlice));
  const int slices = cells[plan.axis];
  const GLint sliceLocation = sweep.uniform("uSlice"), previousLocation = sweep.uniform("uPrevious");
  for (int step = 0; step < slices; ++step) {
    const int a = plan.towardLightStep > 0 ? slices - 1 - step : step;
    const int previous = a + plan.towardLightStep;
    glUniform1i(sliceLocation, a);
    glUniform1i(previousLocation, previous >= 0 && previous < slices ? previous : -1);
    glDispatchCompute(groups(static_cast<std::size_t>(cells[plan.u]) * cells[plan.v]), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  glBindTexture(GL_TEXTURE_3D, shadowTexture_);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, cells.x, cells.y, cells.z, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
  program(2);
  glBindImageTexture(3, shadowTexture_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R8);
  glDispatchCompute(groups(cellCount), 1, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  shadowSize_ = cells;
  shadowDownsample_ = downsample;
  shadowSource_ = voxels;
}

void VolumeRenderer::setMesh(const core::TriangleMesh& mesh) {
  if (!meshArray_) {
    glGenVertexArrays(1, &meshArray_);
    glGenBuffers(1, &meshVertices_);
    glGenBuffers(1, &meshIndices_);
  }
  glBindVertexArray(meshArray_);
  glBindBuffer(GL_ARRAY_BUFFER, meshVertices_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(glm::vec3)), mesh.vertices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshIndices_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.triangles.size() * sizeof(mesh.triangles[0])),
               mesh.triangles.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  meshIndexCount_ = static_cast<GLsizei>(3 * mesh.triangles.size());
  meshBox_ = mesh.bounds();
}

glm::dmat4 VolumeRenderer::tileProjection(const RenderSettings& settings, glm::ivec4 tile, int width, int height,
                                          glm::dvec2 pixelJitter) const {
  // Maps the full image's NDC onto this tile's, shifted by the sub-pixel jitter.
  const double fullWidth = tile.z > 0 ? tile.z : width;
  const double fullHeight = tile.w > 0 ? tile.w : height;
  const double scaleX = fullWidth / width, scaleY = fullHeight / height;
  const double centreX = (tile.x + 0.5 * width) / fullWidth * 2.0 - 1.0;
  const double centreY = (tile.y + 0.5 * height) / fullHeight * 2.0 - 1.0;
  glm::dmat4 remap(1.0);
  remap[0][0] = scaleX;
  remap[1][1] = scaleY;
  remap[3][0] = -centreX * scaleX + 2.0 * pixelJitter.x / width;
  remap[3][1] = -centreY * scaleY + 2.0 * pixelJitter.y / height;
  return remap * settings.camera.projection;
}

void VolumeRenderer::march(FrameTarget& target, const RenderSettings& settings, int sampleIndex, glm::ivec4 tile) {
  marchPixels(target, settings, sampleIndex, tile, glm::ivec4(0), target.samples);
  target.samples = hasVolume() ? target.samples + 1 : 1;
}

void VolumeRenderer::marchRows(FrameTarget& target, const RenderSettings& settings, int sampleIndex, int firstRow,
                               int rowCount, int samplesBefore) {
  firstRow = std::clamp(firstRow, 0, target.height());
  rowCount = std::clamp(rowCount, 0, target.height() - firstRow);
  if (rowCount == 0) return;
  marchPixels(target, settings, sampleIndex, glm::ivec4(0), glm::ivec4(0, firstRow, target.width(), rowCount),
              samplesBefore);
}

void VolumeRenderer::marchPixels(FrameTarget& target, const RenderSettings& settings, int sampleIndex, glm::ivec4 tile,
                                 glm::ivec4 scissor, int samplesBefore) {
  const int width = target.width(), height = target.height();
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  // The projection and the jitter stay those of the whole target; only the pixels written are
  // limited, so a pixel's value does not depend on the scissor.
  if (scissor.z > 0) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(scissor.x, scissor.y, scissor.z, scissor.w);
  }
  if (!hasVolume()) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    if (scissor.z == 0) target.content_ = glm::ivec4(0);
    ++target.revision_;
    return;
  }
  const bool compute = marchStage_ == MarchStage::Compute;
  if (!compute) {
    // A running average: sample n replaces 1/(n+1) of what is there.
    glEnable(GL_BLEND);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / static_cast<float>(samplesBefore + 1));
  }

  const Slot& slot = slots_[marched_];
  const bool lighting = settings.render.lighting && hasShadow();
  // A volume uploaded without its density texture (the fetch order changed since) is marched
  // from its colour texels all the same: their alpha is its density.
  const bool fromColour = densityInColour(slot.colour) || !slot.hasDensity;
  const ShaderProgram& p =
      marchProgram((compute ? kComputeStage : 0u) | (lighting ? kLighting : 0u) | (fromColour ? kDensityInColour : 0u));
  glUseProgram(p.id());
  const glm::dmat4 projection = tileProjection(settings, tile, width, height, samplePixelOffset(sampleIndex));
  const glm::mat4 inverseViewProjection(glm::inverse(projection * settings.camera.view));
  glUniformMatrix4fv(p.uniform("uInverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inverseViewProjection));
  glUniform2f(p.uniform("uTargetSize"), static_cast<float>(width), static_cast<float>(height));
  const core::GridGeometry& geometry = slot.geometry;
  const core::Box box = geometry.box();
  setUniform(p, "uGridOrigin", glm::vec3(box.min));
  setUniform(p, "uGridExtent", glm::vec3(box.extent()));
  glUniform3i(p.uniform("uGridSize"), geometry.size.x, geometry.size.y, geometry.size.z);
  // Voxel coordinates to the colour texture's: its cells span 2^shift voxels (the last ones may
  // reach past the grid's end).
  setUniform(p, "uColourScale", 1.0f / (glm::vec3(slot.colour.size) * static_cast<float>(1 << slot.colour.shift)));
  setUniform(p, "uVoxelSize", geometry.voxelSize);
  setUniform(p, "uStepVoxels", std::clamp(settings.render.stepVoxels, 0.05, 4.0));
  glUniform3i(p.uniform("uBrickCount"), slot.brickCount.x, slot.brickCount.y, slot.brickCount.z);
  glUniform1i(p.uniform("uBrickShift"), core::kBrickShift);
  // Density relative to the mesh's mean and lengths in grid sides make a pixel's sum independent
  // of the point count and the grid resolution (flame/image.h).
  glUniform1f(p.uniform("uToRelative"), static_cast<float>(slot.texelDensity / std::max(slot.referenceDensity, 1e-30)));
  setUniform(p, "uStepUnits",
             std::clamp(settings.render.stepVoxels, 0.05, 4.0) /
                 std::max({geometry.size.x, geometry.size.y, geometry.size.z, 1}));
  setUniform(p, "uAbsorption", std::max(0.0, settings.tone.opacity) * core::kAbsorptionPerDensity);
  glUniform1ui(p.uniform("uSample"), static_cast<GLuint>(sampleIndex));
  glUniform2i(p.uniform("uPixelOffset"), tile.x, tile.y);
  // The shadow's cells cover its source grid; the marched grid spans the same box, perhaps at
  // another resolution (the proxy), so voxel coordinates are rescaled to the source's.
  if (lighting)
    setUniform(p, "uShadowScale",
               glm::vec3(shadowSource_) / glm::vec3(shadowSize_ * shadowDownsample_) / glm::vec3(geometry.size));
  setUniform(p, "uLightStrength", settings.render.lightStrength);
  bindSampler(p, "uVolume", 0, GL_TEXTURE_3D, slot.volume);
  bindSampler(p, "uEmptyDistance", 1, GL_TEXTURE_3D, slot.emptyDistance);
  bindSampler(p, "uShadow", 2, GL_TEXTURE_3D, shadowTexture_);
  bindSampler(p, "uDensity", 3, GL_TEXTURE_3D, slot.density);
  if (compute) {
    const glm::ivec4 region = scissor.z > 0 ? scissor : glm::ivec4(0, 0, width, height);
    glBindImageTexture(0, target.radiance_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glUniform1i(p.uniform("uTarget"), 0);
    glUniform4i(p.uniform("uRegion"), region.x, region.y, region.z, region.w);
    glUniform1f(p.uniform("uWeight"), 1.0f / static_cast<float>(samplesBefore + 1));
    glDispatchCompute(static_cast<GLuint>((region.z + 7) / 8), static_cast<GLuint>((region.w + 7) / 8), 1);
    // What reads the target next (the finish, a read-back, the next sample) sees these writes.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  } else {
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  }
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ++target.revision_;
  // A sample that replaced every pixel (the first, unscissored) leaves only its own outline.
  const glm::ivec4 outline = screenOutline(geometry.box(), projection * settings.camera.view, width, height);
  if (samplesBefore == 0 && scissor.z == 0)
    target.content_ = outline;
  else
    target.content_ = unite(target.content_, outline);
  const int fullHeight = tile.w > 0 ? tile.w : height;
  target.hitsPerUnitDensity_ =
      core::hitsPerUnitDensity(settings.camera, geometry, slot.points, slot.insideVoxels, fullHeight);
}

void VolumeRenderer::drawMesh(FrameTarget& target, const RenderSettings& settings, glm::ivec4 tile, bool always) {
  ++target.revision_;
  glBindFramebuffer(GL_FRAMEBUFFER, target.meshFramebuffer_);
  glViewport(0, 0, target.width(), target.height());
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if ((always || settings.render.meshDisplay != core::MeshDisplay::Off) && meshIndexCount_ > 0) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    const ShaderProgram& p = meshProgram_;
    glUseProgram(p.id());
    const glm::mat4 viewProjection(tileProjection(settings, tile, target.width(), target.height(), {0.0, 0.0}) *
                                   settings.camera.view);
    glUniformMatrix4fv(p.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    setUniform(p, "uEye", glm::vec3(settings.camera.eye));
    setUniform(p, "uViewDirection", glm::vec3(settings.camera.forward));
    glUniform1i(p.uniform("uOrthographic"), settings.camera.orthographic ? 1 : 0);
    setUniform(p, "uMeshColor", settings.render.meshColor);
    glBindVertexArray(meshArray_);
    glDrawElements(GL_TRIANGLES, meshIndexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_DEPTH_TEST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {

// What a finished image depends on besides the target's content.
std::string finishKey(const RenderSettings& settings, bool linearOutput, bool withMesh) {
  const core::ToneMapSettings& t = settings.tone;
  std::string key;
  for (double v :
       {t.brightness, t.gamma, t.gammaThreshold, t.vibrancy, t.highlightPower, t.exposure, t.contrast,
        static_cast<double>(t.background.r), static_cast<double>(t.background.g), static_cast<double>(t.background.b),
        t.estimatorRadius, t.estimatorMinimum, t.estimatorCurve, settings.render.filterRadius,
        settings.render.meshStrength, static_cast<double>(settings.render.meshColor.r),
        static_cast<double>(settings.render.meshColor.g), static_cast<double>(settings.render.meshColor.b)})
    key += std::to_string(v) + ",";
  key += std::to_string(static_cast<int>(settings.render.meshDisplay)) + (linearOutput ? "L" : "D") +
         (withMesh ? "M" : "-");
  return key;
}

core::FinishSettings finishSettings(const RenderSettings& settings, bool linearOutput, int oversample) {
  core::FinishSettings finish;
  finish.tone = settings.tone;
  finish.oversample = oversample;
  finish.filterRadius = settings.render.filterRadius;
  finish.linearOutput = linearOutput;
  return finish;
}

}  // namespace

void VolumeRenderer::resolve(const FrameTarget& target, const RenderSettings& settings, glm::ivec4 viewport,
                             bool linearOutput) {
  // The picture goes to the framebuffer bound on entry (the window's, or an offscreen one); the
  // finish below binds others.
  GLint output = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &output);
  const bool withMesh = meshIndexCount_ > 0 && settings.render.meshDisplay != core::MeshDisplay::Off;
  const std::string key = finishKey(settings, linearOutput, withMesh);
  const glm::ivec2 size(target.width_, target.height_);
  // A picture for the screen is display-encoded and clamped, so bytes hold all of it: where the
  // tone is drawn as fragments (a software rasteriser) it writes and the blit reads a quarter of
  // the float image's bytes. Linear light (EXR) stays float, and so does the compute tone's image.
  const bool computeTone = finisher_.computePasses();
  const GLenum format = linearOutput || computeTone ? GL_RGBA32F : GL_RGBA8;
  if (!target.finished_ || target.finishedSize_ != size || target.finishedFormat_ != format) {
    if (!target.finished_) {
      target.finished_ = makeTexture(GL_TEXTURE_2D, GL_LINEAR);
      glGenFramebuffers(1, &target.finishedFramebuffer_);
    }
    glBindTexture(GL_TEXTURE_2D, target.finished_);
    if (format == GL_RGBA8)
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    else
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, target.finishedFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.finished_, 0);
    target.finishedSize_ = size;
    target.finishedFormat_ = format;
    target.finishedRevision_ = ~std::uint64_t{0};
  }
  if (target.finishedRevision_ != target.revision_ || target.finishedKey_ != key) {
    // Straight from the target's textures: the whole image, no apron needed.
    FinishSource source;
    source.density = target.radiance_;
    source.size = target.radianceSize_;
    source.fullSize = target.radianceSize_;
    source.hitsPerUnitDensity = target.hitsPerUnitDensity_;
    source.content = target.content_;
    OverlayStyle style;
    if (withMesh) {
      // The mesh layer (drawMesh, at the camera's own projection) shows within the mesh's outline.
      source.content = unite(
          source.content, screenOutline(meshBox_, settings.camera.projection * settings.camera.view, size.x, size.y));
      source.overlay = target.meshLayer_;
      style = {settings.render.meshDisplay, settings.render.meshColor, settings.render.meshStrength};
    }
    finisher_.finish(source, finishSettings(settings, linearOutput, target.oversample_), style, glm::ivec2(0), size,
                     target.finishedFramebuffer_, target.finished_);
    target.finishedRevision_ = target.revision_;
    target.finishedKey_ = key;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(output));
  blit(target.finished_, viewport);
}

void VolumeRenderer::blit(GLuint texture, glm::ivec4 viewport) {
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  const ShaderProgram& p = blitProgram_;
  glUseProgram(p.id());
  glUniform4f(p.uniform("uViewport"), static_cast<float>(viewport.x), static_cast<float>(viewport.y),
              static_cast<float>(viewport.z), static_cast<float>(viewport.w));
  bindSampler(p, "uImage", 0, GL_TEXTURE_2D, texture);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

namespace {

// (Re)allocates `texture` as a 2D texture of `size` and `format` when either differs from `had`.
void ensureTexture(GLuint& texture, glm::ivec2& had, glm::ivec2 size, GLenum format) {
  if (texture && had == size) return;
  if (!texture) texture = makeTexture(GL_TEXTURE_2D, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, texture);
  if (format == GL_RGBA8)
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  else
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  had = size;
}

}  // namespace

bool VolumeRenderer::finishStrip(const FrameTarget& target, const RenderSettings& settings, int rows) {
  const bool withMesh = meshIndexCount_ > 0 && settings.render.meshDisplay != core::MeshDisplay::Off;
  const std::string key = finishKey(settings, false, withMesh);
  const glm::ivec2 size(target.width_, target.height_);
  const GLenum format = finisher_.computePasses() ? GL_RGBA32F : GL_RGBA8;
  if (target.finished_ && target.finishedRevision_ == target.revision_ && target.finishedKey_ == key &&
      target.finishedSize_ == size && target.finishedFormat_ == format)
    return true;
  if (!target.pending_ || target.pendingRevision_ != target.revision_ || target.pendingKey_ != key) {
    if (!target.pendingFramebuffer_) glGenFramebuffers(1, &target.pendingFramebuffer_);
    glm::ivec2 had(-1);  // made anew at the target's size and format (it may be the last picture's)
    ensureTexture(target.pending_, had, size, format);
    glBindFramebuffer(GL_FRAMEBUFFER, target.pendingFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.pending_, 0);
    target.pendingRow_ = 0;
    target.pendingRevision_ = target.revision_;
    target.pendingKey_ = key;
  }
  const core::FinishSettings finish = finishSettings(settings, false, target.oversample_);
  const int oversample = target.oversample_;
  const int apron = FlameFinisher::apron(finish);
  const int firstRow = target.pendingRow_, stripRows = std::min(std::max(1, rows), size.y - firstRow);
  // The strip's sums with the apron its kernels and filter reach (GL rows, bottom up).
  const glm::ivec2 lo(0, std::max(0, firstRow * oversample - apron));
  const glm::ivec2 hi(target.radianceSize_.x,
                      std::min(target.radianceSize_.y, (firstRow + stripRows) * oversample + apron));
  ensureTexture(target.stripDensity_, target.stripDensitySize_, hi - lo, GL_RGBA32F);
  glCopyImageSubData(target.radiance_, GL_TEXTURE_2D, 0, lo.x, lo.y, 0, target.stripDensity_, GL_TEXTURE_2D, 0, 0, 0, 0,
                     hi.x - lo.x, hi.y - lo.y, 1);
  FinishSource source;
  source.density = target.stripDensity_;
  source.origin = lo;
  source.size = hi - lo;
  source.fullSize = target.radianceSize_;
  source.hitsPerUnitDensity = target.hitsPerUnitDensity_;
  OverlayStyle style;
  if (withMesh) {
    // The silhouette's edge looks one pixel around.
    const int overlayLo = std::max(0, firstRow - 1), overlayHi = std::min(size.y, firstRow + stripRows + 1);
    ensureTexture(target.stripOverlay_, target.stripOverlaySize_, glm::ivec2(size.x, overlayHi - overlayLo), GL_RGBA8);
    glCopyImageSubData(target.meshLayer_, GL_TEXTURE_2D, 0, 0, overlayLo, 0, target.stripOverlay_, GL_TEXTURE_2D, 0, 0,
                       0, 0, size.x, overlayHi - overlayLo, 1);
    source.overlay = target.stripOverlay_;
    source.overlayOrigin = glm::ivec2(0, overlayLo);
    style = {settings.render.meshDisplay, settings.render.meshColor, settings.render.meshStrength};
  }
  if (target.stripOutputSize_ != glm::ivec2(size.x, stripRows) || !target.stripFramebuffer_) {
    if (!target.stripFramebuffer_) glGenFramebuffers(1, &target.stripFramebuffer_);
    glm::ivec2 had(-1);
    ensureTexture(target.stripOutput_, had, glm::ivec2(size.x, stripRows), format);
    target.stripOutputSize_ = glm::ivec2(size.x, stripRows);
    glBindFramebuffer(GL_FRAMEBUFFER, target.stripFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.stripOutput_, 0);
  }
  finisher_.finish(source, finish, style, glm::ivec2(0, firstRow), glm::ivec2(size.x, stripRows),
                   target.stripFramebuffer_, format == GL_RGBA32F ? target.stripOutput_ : 0);
  glCopyImageSubData(target.stripOutput_, GL_TEXTURE_2D, 0, 0, 0, 0, target.pending_, GL_TEXTURE_2D, 0, 0, firstRow, 0,
                     size.x, stripRows, 1);
  target.pendingRow_ += stripRows;
  if (target.pendingRow_ < size.y) return false;
  // Whole: it becomes the picture drawn.
  std::swap(target.finished_, target.pending_);
  std::swap(target.finishedFramebuffer_, target.pendingFramebuffer_);
  target.finishedSize_ = size;
  target.finishedFormat_ = format;
  target.finishedRevision_ = target.pendingRevision_;
  target.finishedKey_ = key;
  target.pendingRevision_ = ~std::uint64_t{0};
  return true;
}

bool VolumeRenderer::drawFinished(const FrameTarget& target, glm::ivec4 viewport) {
  if (!target.finished_ || target.finishedRevision_ == ~std::uint64_t{0}) return false;
  blit(target.finished_, viewport);
  return true;
}

namespace {

int tileSizeFor(int maxTile) {
  GLint maxRenderbuffer = 0, maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  return std::max(16, std::min({maxTile, static_cast<int>(maxRenderbuffer), maxViewport[0], maxViewport[1]}));
}

// Averages a supersampled overlay down to the output size, rounded to bytes. Taken by value: at
// oversample 1 it is moved through, not copied (a second full-size layer at 16K).
core::MeshOverlay downsampleOverlay(core::MeshOverlay full, int oversample) {
  if (oversample <= 1) return full;
  core::MeshOverlay out;
  out.mode = full.mode;
  out.color = full.color;
  out.strength = full.strength;
  out.width = full.width / oversample;
  out.height = full.height / oversample;
  out.rgba.assign(4 * static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height), 0);
  const int samples = oversample * oversample;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int j = 0; j < oversample; ++j)
          for (int i = 0; i < oversample; ++i)
            sum += full.rgba[4 * (static_cast<std::size_t>(y * oversample + j) * full.width + x * oversample + i) + c];
        out.rgba[4 * (static_cast<std::size_t>(y) * out.width + x) + c] =
            static_cast<std::uint8_t>((sum + samples / 2) / samples);
      }
  return out;
}

void checkImageSize(int width, int height, int oversample) {
  if (width <= 0 || height <= 0) throw core::Error("image size must be positive");
  // Sums, log image and overlay: about 48 bytes per supersampled pixel.
  const double bytes = 48.0 * width * height * oversample * oversample;
  const double available = 0.75 * core::physicalMemoryBytes();
  if (available > 0.0 && bytes > available)
    throw core::Error("an image of " + std::to_string(width) + "×" + std::to_string(height) + " at oversample " +
                      std::to_string(oversample) + " needs about " +
                      std::to_string(static_cast<long long>(bytes / 1e9)) + " GB; lower the size or the oversample");
}

}  // namespace

MarchedImage marchImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height, int maxTile,
                        const std::function<void(double)>& progress) {
  const int oversample = std::clamp(settings.render.oversample, 1, 4);
  checkImageSize(width, height, oversample);
  const int tileSize = tileSizeFor(maxTile);
  const int fullWidth = width * oversample, fullHeight = height * oversample;
  MarchedImage result;
  result.density.resize(fullWidth, fullHeight);
  core::MeshOverlay mesh = emptyOverlay(settings, fullWidth, fullHeight);
  const int samples = std::max(1, settings.render.samples);

  FrameTarget target;
  const auto tilesAcross = static_cast<long long>((fullWidth + tileSize - 1) / tileSize);
  const auto tilesDown = static_cast<long long>((fullHeight + tileSize - 1) / tileSize);
  const double totalSteps = static_cast<double>(tilesAcross * tilesDown * samples);
  long long stepsDone = 0;
  for (int tileY = 0; tileY < fullHeight; tileY += tileSize) {
    for (int tileX = 0; tileX < fullWidth; tileX += tileSize) {
      const int tileWidth = std::min(tileSize, fullWidth - tileX);
      const int tileHeight = std::min(tileSize, fullHeight - tileY);
      // GL's rows run bottom to top: this tile's GL origin is measured from the image's bottom.
      const int glY = fullHeight - tileY - tileHeight;
      const glm::ivec4 tile(tileX, glY, fullWidth, fullHeight);
      target.resize(tileWidth, tileHeight);
      target.samples = 0;
      for (int s = 0; s < samples; ++s) {
        renderer.march(target, settings, s, tile);
        if (progress) {
          // Waiting for the GPU here makes the fraction mean work done, not work queued.
          glFinish();
          progress(static_cast<double>(++stepsDone) / totalSteps);
        }
      }
      const core::DensityImage tileDensity = target.readDensity();
      result.density.hitsPerUnitDensity = tileDensity.hitsPerUnitDensity;
      for (int y = 0; y < tileHeight; ++y)
        std::copy_n(tileDensity.at(0, y), 4 * static_cast<std::size_t>(tileWidth), result.density.at(tileX, tileY + y));
      if (renderer.hasMesh()) {
        renderer.drawMesh(target, settings, tile, true);
        const core::MeshOverlay tileMesh = target.readMeshOverlay(settings);
        for (int y = 0; y < tileHeight; ++y)
          std::copy_n(&tileMesh.rgba[4 * static_cast<std::size_t>(y) * tileWidth],
                      4 * static_cast<std::size_t>(tileWidth),
                      &mesh.rgba[4 * (static_cast<std::size_t>(tileY + y) * fullWidth + tileX)]);
      }
    }
  }
  result.mesh = downsampleOverlay(std::move(mesh), oversample);
  return result;
}

core::MeshOverlay renderMeshOverlay(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                                    int maxTile) {
  const int oversample = std::clamp(settings.render.oversample, 1, 4);
  checkImageSize(width, height, oversample);
  const int tileSize = tileSizeFor(maxTile);
  const int fullWidth = width * oversample, fullHeight = height * oversample;
  core::MeshOverlay mesh = emptyOverlay(settings, fullWidth, fullHeight);
  FrameTarget target;
  if (renderer.hasMesh())
    for (int tileY = 0; tileY < fullHeight; tileY += tileSize)
      for (int tileX = 0; tileX < fullWidth; tileX += tileSize) {
        const int tileWidth = std::min(tileSize, fullWidth - tileX);
        const int tileHeight = std::min(tileSize, fullHeight - tileY);
        const glm::ivec4 tile(tileX, fullHeight - tileY - tileHeight, fullWidth, fullHeight);
        target.resize(tileWidth, tileHeight);
        renderer.drawMesh(target, settings, tile, true);
        const core::MeshOverlay tileMesh = target.readMeshOverlay(settings);
        for (int y = 0; y < tileHeight; ++y)
          std::copy_n(&tileMesh.rgba[4 * static_cast<std::size_t>(y) * tileWidth],
                      4 * static_cast<std::size_t>(tileWidth),
                      &mesh.rgba[4 * (static_cast<std::size_t>(tileY + y) * fullWidth + tileX)]);
      }
  return downsampleOverlay(std::move(mesh), oversample);
}

core::ImageRGBA renderToImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                              bool linearOutput, int maxTile, const std::function<void(double)>& progress) {
  const MarchedImage marched = marchImage(renderer, settings, width, height, maxTile, progress);
  core::FinishSettings finish = finishSettings(settings, linearOutput, std::clamp(settings.render.oversample, 1, 4));
  return finishImageOnGpu(renderer.finisher(), marched.density, finish, &marched.mesh, maxTile).image;
}

}  // namespace voxflame::gl
