#include "volume_renderer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "core/error.h"

namespace voxflame::gl {

namespace {

// One triangle covering the viewport; the fragment shaders do the work.
const char* kFullscreenVertexShader = R"(#version 430 core
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* kMarchShader = R"(#version 430 core
out vec4 fragColor;

uniform mat4 uInverseViewProjection;
uniform vec2 uTargetSize;
uniform vec3 uGridOrigin;
uniform vec3 uGridExtent;
uniform ivec3 uGridSize;
uniform float uVoxelSize;
uniform float uStepVoxels;
uniform sampler3D uVolume;      // rgb: colour × normalised density, a: normalised density
uniform sampler3D uDensity;     // normalised density alone, tested before the colour is fetched
uniform usampler3D uOccupancy;  // 1 per brick that holds density
uniform ivec3 uBrickCount;
uniform int uBrickSize;
uniform usampler3D uCoarseOccupancy;  // 1 per group of kCoarseBricks³ bricks with any density
uniform ivec3 uCoarseCount;
uniform int uCoarseSize;              // voxels along a coarse brick
uniform float uMaxDensity;
uniform float uDensityScale;    // maps raw hits into the log curve
uniform float uLogNormalizer;   // 1 / log(1 + maxDensity * uDensityScale)
uniform float uBrightness;
uniform float uOpacity;
uniform uint uSample;
uniform ivec2 uPixelOffset;     // this tile's place in the whole image, so jitter ignores tiling
uniform sampler3D uShadow;      // light transmittance, when lighting is on
uniform bool uLighting;
uniform vec3 uShadowScale;      // voxel coordinates to shadow texture coordinates
uniform float uLightStrength;

// A per-pixel, per-sample jitter of the first step hides the wood-grain banding of fixed steps.
float hash(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  return float(v.x & 0x00ffffffu) / 16777216.0;
}

void main() {
  vec2 ndc = gl_FragCoord.xy / uTargetSize * 2.0 - 1.0;
  vec4 nearPoint = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
  nearPoint /= nearPoint.w;
  farPoint /= farPoint.w;
  vec3 origin = nearPoint.xyz;
  vec3 direction = farPoint.xyz - origin;
  float rayLength = length(direction);
  direction /= rayLength;
  // Rays run from the near plane to the far plane, so both clip every sample.
  vec3 inverseDirection = 1.0 / direction;
  vec3 t0 = (uGridOrigin - origin) * inverseDirection;
  vec3 t1 = (uGridOrigin + uGridExtent - origin) * inverseDirection;
  vec3 tLow = min(t0, t1);
  vec3 tHigh = max(t0, t1);
  float tEnter = max(max(tLow.x, tLow.y), max(tLow.z, 0.0));
  float tExit = min(min(tHigh.x, tHigh.y), min(tHigh.z, rayLength));

  vec3 radiance = vec3(0.0);
  float coverage = 1.0;       // product of (1 - alpha): what the pixel's opacity is measured by
  float transmittance = 1.0;  // what is left to see behind, given uOpacity
  if (tExit > tEnter) {
    float stepLength = uStepVoxels * uVoxelSize;
    float t = tEnter + stepLength * hash(uvec3(uvec2(ivec2(gl_FragCoord.xy) + uPixelOffset), uSample));
    vec3 toVoxel = vec3(1.0 / uVoxelSize);
    vec3 toTexture = 1.0 / vec3(uGridSize);
    vec3 exitSide = step(vec3(0.0), direction);
    while (t < tExit) {
      vec3 position = origin + t * direction;
      vec3 voxel = (position - uGridOrigin) * toVoxel;
      ivec3 voxelIndex = ivec3(floor(voxel));
      // Two levels of empty space: a coarse brick, then a brick; either leaps to the first step
      // past its far side, staying on the jittered step lattice.
      ivec3 coarse = clamp(voxelIndex / uCoarseSize, ivec3(0), uCoarseCount - 1);
      int leapVoxels = 0;
      ivec3 leapCell;
      if (texelFetch(uCoarseOccupancy, coarse, 0).r == 0u) {
        leapVoxels = uCoarseSize;
        leapCell = coarse;
      } else {
        ivec3 brick = clamp(voxelIndex / uBrickSize, ivec3(0), uBrickCount - 1);
        if (texelFetch(uOccupancy, brick, 0).r == 0u) {
          leapVoxels = uBrickSize;
          leapCell = brick;
        }
      }
      if (leapVoxels > 0) {
        float cellLength = float(leapVoxels) * uVoxelSize;
        vec3 cellMin = uGridOrigin + vec3(leapCell) * cellLength;
        vec3 tCell = (cellMin + exitSide * cellLength - origin) * inverseDirection;
        float tLeave = min(tCell.x, min(tCell.y, tCell.z));
        t += max(ceil((tLeave - t) / stepLength), 1.0) * stepLength;
        continue;
      }
      // Explicit LOD: there are no mipmaps, and implicit derivatives are undefined in this loop.
      float density = textureLod(uDensity, voxel * toTexture, 0.0).r;
      if (density > 0.0) {
        vec4 texel = textureLod(uVolume, voxel * toTexture, 0.0);
        float level = log(1.0 + density * uMaxDensity * uDensityScale) * uLogNormalizer;
        float alpha = 1.0 - exp(-level * uBrightness * uStepVoxels);
        float lit = uLighting ? mix(1.0, textureLod(uShadow, voxel * uShadowScale, 0.0).r, uLightStrength) : 1.0;
        radiance += transmittance * alpha * lit * (texel.rgb / texel.a);
        coverage *= 1.0 - alpha;
        transmittance *= 1.0 - alpha * uOpacity;
        if (transmittance < 0.002 || coverage < 0.0005 && uOpacity >= 1.0) break;
      }
      t += stepLength;
    }
  }
  fragColor = vec4(radiance, 1.0 - coverage);
}
)";

// flam3's final stage (rect.c), on the marched radiance and opacity of each pixel.
const char* kResolveShader = R"(#version 430 core
out vec4 fragColor;

uniform sampler2D uRadiance;
uniform sampler2D uMeshLayer;
uniform vec4 uViewport;
uniform int uMeshMode;         // 0 off, 1 ghost, 2 silhouette
uniform vec3 uMeshColor;       // display-encoded
uniform float uMeshStrength;
uniform float uGamma;
uniform float uGammaThreshold;
uniform float uVibrancy;
uniform float uHighlightPower;
uniform float uExposure;
uniform float uContrast;
uniform vec3 uBackground;      // display-encoded
uniform bool uLinearOutput;

// Gamma on opacity, linear below the threshold so faint noise is not amplified.
float gammaAlpha(float density, float g, float threshold) {
  if (density <= 0.0) return 0.0;
  if (density < threshold) {
    float fraction = density / threshold;
    return (1.0 - fraction) * density * pow(threshold, g) / threshold + fraction * pow(density, g);
  }
  return pow(density, g);
}

vec3 rgbToHsv(vec3 c) {
  vec4 k = vec4(0.0, -1.0 / 3.0, 2.0 / 3.0, -1.0);
  vec4 p = mix(vec4(c.bg, k.wz), vec4(c.gb, k.xy), step(c.b, c.g));
  vec4 q = mix(vec4(p.xyw, c.r), vec4(c.r, p.yzx), step(p.x, c.r));
  float d = q.x - min(q.w, q.y);
  return vec3(abs(q.z + (q.w - q.y) / (6.0 * d + 1e-10)), d / (q.x + 1e-10), q.x);
}

vec3 hsvToRgb(vec3 c) {
  vec3 p = abs(fract(c.xxx + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
  return c.z * mix(vec3(1.0), clamp(p - 1.0, 0.0, 1.0), c.y);
}

// Scales colour by ls; with highlight power ≥ 0, overexposed colours keep their brightest channel
// at 1 and lose saturation instead of clipping to a different hue.
vec3 scaledColor(vec3 c, float ls, float highlightPower) {
  float maxChannel = max(c.r, max(c.g, c.b));
  if (ls <= 0.0 || maxChannel <= 0.0) return vec3(0.0);
  float maxScaled = ls * maxChannel;
  if (maxScaled > 1.0 && highlightPower >= 0.0) {
    float newScale = 1.0 / maxChannel;
    float saturationKept = pow(newScale / ls, highlightPower);
    vec3 hsv = rgbToHsv(newScale * c);
    hsv.y *= saturationKept;
    return hsvToRgb(hsv);
  }
  float blend = maxScaled <= 1.0 ? 1.0 : min(1.0, -highlightPower);
  return ((1.0 - blend) + blend * ls) * c;
}

void main() {
  vec2 uv = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw;
  vec4 accumulated = texture(uRadiance, uv);
  vec3 c = max(accumulated.rgb, vec3(0.0)) * exp2(uExposure);
  float density = clamp(accumulated.a, 0.0, 1.0);
  float g = 1.0 / uGamma;
  float alpha = gammaAlpha(density, g, uGammaThreshold);
  float ls = density > 0.0 ? uVibrancy * alpha / density : 0.0;
  vec3 color = scaledColor(c, ls, uHighlightPower) + (1.0 - uVibrancy) * pow(c, vec3(g));
  color += (1.0 - min(alpha, 1.0)) * uBackground;

  if (uMeshMode == 1) {
    color += uMeshStrength * texture(uMeshLayer, uv).rgb;
  } else if (uMeshMode == 2) {
    vec2 texel = 1.0 / vec2(textureSize(uMeshLayer, 0));
    float centre = texture(uMeshLayer, uv).a;
    float edge = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        edge = max(edge, abs(texture(uMeshLayer, uv + vec2(dx, dy) * texel).a - centre));
    color = mix(color, uMeshColor, clamp(edge * uMeshStrength * 2.5, 0.0, 1.0));
  }
  color = (color - 0.5) * uContrast + 0.5;
  if (uLinearOutput) {
    // Undo the display gamma so an EXR holds linear light, highlights above 1 included.
    fragColor = vec4(pow(max(color, vec3(0.0)), vec3(uGamma)), 1.0);
  } else {
    fragColor = vec4(clamp(color, 0.0, 1.0), 1.0);
  }
}
)";

const char* kMeshVertexShader = R"(#version 430 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
out vec3 vPosition;
void main() {
  vPosition = aPosition;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

// A fresnel rim: surfaces seen edge-on glow, surfaces facing the camera stay clear, so the shape
// reads without hiding the volume inside.
const char* kMeshFragmentShader = R"(#version 430 core
in vec3 vPosition;
out vec4 fragColor;
uniform vec3 uEye;
uniform vec3 uMeshColor;
uniform bool uOrthographic;
uniform vec3 uViewDirection;
void main() {
  vec3 facet = cross(dFdx(vPosition), dFdy(vPosition));
  float facetLength = length(facet);
  vec3 toEye = uOrthographic ? -uViewDirection : normalize(uEye - vPosition);
  // Sub-pixel triangles have no usable derivative: treat them as seen edge-on.
  float facing = facetLength > 0.0 ? abs(dot(facet / facetLength, toEye)) : 0.0;
  float rim = 0.12 + 0.88 * pow(clamp(1.0 - facing, 0.0, 1.0), 3.0);
  fragColor = vec4(uMeshColor * rim, 1.0);
}
)";

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

glm::vec3 displayEncode(glm::vec3 linear, double gamma) {
  return glm::pow(glm::max(linear, glm::vec3(0.0f)), glm::vec3(static_cast<float>(1.0 / gamma)));
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
}

void FrameTarget::resize(int width, int height) {
  if (width == width_ && height == height_ && framebuffer_) return;
  width_ = std::max(1, width);
  height_ = std::max(1, height);
  samples = 0;
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

VolumeRenderer::VolumeRenderer()
    : marchProgram_(kFullscreenVertexShader, kMarchShader),
      resolveProgram_(kFullscreenVertexShader, kResolveShader),
      meshProgram_(kMeshVertexShader, kMeshFragmentShader) {
  glGenVertexArrays(1, &vertexArray_);
  volumeTexture_ = makeTexture(GL_TEXTURE_3D, GL_LINEAR);
  densityTexture_ = makeTexture(GL_TEXTURE_3D, GL_LINEAR);
  occupancyTexture_ = makeTexture(GL_TEXTURE_3D, GL_NEAREST);
  coarseTexture_ = makeTexture(GL_TEXTURE_3D, GL_NEAREST);
  shadowTexture_ = makeTexture(GL_TEXTURE_3D, GL_LINEAR);
}

VolumeRenderer::~VolumeRenderer() {
  glDeleteTextures(1, &volumeTexture_);
  glDeleteTextures(1, &densityTexture_);
  glDeleteTextures(1, &occupancyTexture_);
  glDeleteTextures(1, &coarseTexture_);
  glDeleteTextures(1, &shadowTexture_);
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteVertexArrays(1, &meshArray_);
  glDeleteBuffers(1, &meshVertices_);
  glDeleteBuffers(1, &meshIndices_);
}

void VolumeRenderer::upload(const core::PackedVolume& volume) {
  beginUpload(volume);
  continueUpload(~std::size_t{0});
}

void VolumeRenderer::beginUpload(const core::PackedVolume& volume) {
  pending_ = &volume;
  pendingZ_ = 0;
  if (volume.geometry.size != geometry_.size) {
    glBindTexture(GL_TEXTURE_3D, volumeTexture_);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA16F, volume.geometry.size.x, volume.geometry.size.y, volume.geometry.size.z,
                 0, GL_RGBA, GL_HALF_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_3D, densityTexture_);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_R16F, volume.geometry.size.x, volume.geometry.size.y, volume.geometry.size.z, 0,
                 GL_RED, GL_HALF_FLOAT, nullptr);
    uploadedVersion_ = 0;  // the old content is gone until this upload completes
  }
}

void VolumeRenderer::uploadSlab(int firstZ, int endZ) {
  const glm::ivec3 size = pending_->geometry.size;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, volumeTexture_);
  const std::size_t offset = 4 * pending_->geometry.index(0, 0, firstZ);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, firstZ, size.x, size.y, endZ - firstZ, GL_RGBA, GL_HALF_FLOAT,
                  pending_->texels.data() + offset);
  glBindTexture(GL_TEXTURE_3D, densityTexture_);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, firstZ, size.x, size.y, endZ - firstZ, GL_RED, GL_HALF_FLOAT,
                  pending_->density.data() + offset / 4);
}

bool VolumeRenderer::continueUpload(std::size_t budgetBytes) {
  if (!pending_) return true;
  const core::PackedVolume& volume = *pending_;
  const std::size_t slabBytes = 10 * static_cast<std::size_t>(volume.geometry.size.x) * volume.geometry.size.y;
  const int slabs = static_cast<int>(std::clamp<std::size_t>(budgetBytes / std::max<std::size_t>(slabBytes, 1), 1,
                                                             static_cast<std::size_t>(volume.geometry.size.z)));
  const int endZ = std::min(volume.geometry.size.z, pendingZ_ + slabs);
  uploadSlab(pendingZ_, endZ);
  pendingZ_ = endZ;
  if (pendingZ_ < volume.geometry.size.z) return false;

  // The occupancy grid is small; it goes up whole, with the last slab, so it matches the volume.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, occupancyTexture_);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8UI, volume.brickCount.x, volume.brickCount.y, volume.brickCount.z, 0,
               GL_RED_INTEGER, GL_UNSIGNED_BYTE, volume.occupancy.data());
  geometry_ = volume.geometry;
  brickCount_ = volume.brickCount;
  glBindTexture(GL_TEXTURE_3D, coarseTexture_);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8UI, volume.coarseCount.x, volume.coarseCount.y, volume.coarseCount.z, 0,
               GL_RED_INTEGER, GL_UNSIGNED_BYTE, volume.coarseOccupancy.data());
  coarseCount_ = volume.coarseCount;
  maxDensity_ = volume.maxDensity;
  meanDensity_ = volume.meanDensity;
  uploadedVersion_ = std::max<std::uint64_t>(volume.version, 1);
  pending_ = nullptr;
  return true;
}

void VolumeRenderer::uploadShadow(const core::ShadowVolume& shadow, int downsample) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, shadowTexture_);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, shadow.size.x, shadow.size.y, shadow.size.z, 0, GL_RED, GL_UNSIGNED_BYTE,
               shadow.transmittance.data());
  shadowSize_ = shadow.size;
  shadowDownsample_ = std::max(1, downsample);
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
  const int width = target.width(), height = target.height();
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  if (!hasVolume()) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    target.samples = 1;
    return;
  }
  // A running average: sample n replaces 1/(n+1) of what is there.
  glEnable(GL_BLEND);
  glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / static_cast<float>(target.samples + 1));

  const ShaderProgram& p = marchProgram_;
  glUseProgram(p.id());
  const glm::dmat4 projection = tileProjection(settings, tile, width, height, samplePixelOffset(sampleIndex));
  const glm::mat4 inverseViewProjection(glm::inverse(projection * settings.camera.view));
  glUniformMatrix4fv(p.uniform("uInverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inverseViewProjection));
  glUniform2f(p.uniform("uTargetSize"), static_cast<float>(width), static_cast<float>(height));
  const core::Box box = geometry_.box();
  setUniform(p, "uGridOrigin", glm::vec3(box.min));
  setUniform(p, "uGridExtent", glm::vec3(box.extent()));
  glUniform3i(p.uniform("uGridSize"), geometry_.size.x, geometry_.size.y, geometry_.size.z);
  setUniform(p, "uVoxelSize", geometry_.voxelSize);
  setUniform(p, "uStepVoxels", std::clamp(settings.render.stepVoxels, 0.05, 4.0));
  glUniform3i(p.uniform("uBrickCount"), brickCount_.x, brickCount_.y, brickCount_.z);
  glUniform1i(p.uniform("uBrickSize"), core::kBrickSize);
  glUniform3i(p.uniform("uCoarseCount"), coarseCount_.x, coarseCount_.y, coarseCount_.z);
  glUniform1i(p.uniform("uCoarseSize"), core::kBrickSize * core::kCoarseBricks);
  // Like flam3's k2: density is measured against a typical (mean) occupied voxel, so the image
  // does not change character as points accumulate, and the log keeps sparse and dense visible.
  const float densityScale = meanDensity_ > 0.0f ? 1.0f / meanDensity_ : 1.0f;
  glUniform1f(p.uniform("uMaxDensity"), maxDensity_);
  glUniform1f(p.uniform("uDensityScale"), densityScale);
  glUniform1f(p.uniform("uLogNormalizer"), 1.0f / std::log1p(std::max(maxDensity_, 1.0f) * densityScale));
  setUniform(p, "uBrightness", settings.tone.brightness);
  setUniform(p, "uOpacity", std::clamp(settings.tone.opacity, 0.0, 1.0));
  glUniform1ui(p.uniform("uSample"), static_cast<GLuint>(sampleIndex));
  glUniform2i(p.uniform("uPixelOffset"), tile.x, tile.y);
  const bool lighting = settings.render.lighting && hasShadow();
  glUniform1i(p.uniform("uLighting"), lighting ? 1 : 0);
  if (lighting) setUniform(p, "uShadowScale", 1.0f / glm::vec3(shadowSize_ * shadowDownsample_));
  setUniform(p, "uLightStrength", settings.render.lightStrength);
  bindSampler(p, "uVolume", 0, GL_TEXTURE_3D, volumeTexture_);
  bindSampler(p, "uOccupancy", 1, GL_TEXTURE_3D, occupancyTexture_);
  bindSampler(p, "uShadow", 2, GL_TEXTURE_3D, shadowTexture_);
  bindSampler(p, "uDensity", 3, GL_TEXTURE_3D, densityTexture_);
  bindSampler(p, "uCoarseOccupancy", 4, GL_TEXTURE_3D, coarseTexture_);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ++target.samples;
}

void VolumeRenderer::drawMesh(FrameTarget& target, const RenderSettings& settings, glm::ivec4 tile) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.meshFramebuffer_);
  glViewport(0, 0, target.width(), target.height());
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (settings.render.meshDisplay != core::MeshDisplay::Off && meshIndexCount_ > 0) {
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

void VolumeRenderer::resolve(const FrameTarget& target, const RenderSettings& settings, glm::ivec4 viewport,
                             bool linearOutput) {
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  const ShaderProgram& p = resolveProgram_;
  glUseProgram(p.id());
  const core::ToneMapSettings& tone = settings.tone;
  glUniform4f(p.uniform("uViewport"), static_cast<float>(viewport.x), static_cast<float>(viewport.y),
              static_cast<float>(viewport.z), static_cast<float>(viewport.w));
  const int meshMode = meshIndexCount_ > 0 ? static_cast<int>(settings.render.meshDisplay) : 0;
  glUniform1i(p.uniform("uMeshMode"), meshMode);
  setUniform(p, "uMeshColor", displayEncode(settings.render.meshColor, tone.gamma));
  setUniform(p, "uMeshStrength", settings.render.meshStrength);
  setUniform(p, "uGamma", tone.gamma);
  setUniform(p, "uGammaThreshold", tone.gammaThreshold);
  setUniform(p, "uVibrancy", tone.vibrancy);
  setUniform(p, "uHighlightPower", tone.highlightPower);
  setUniform(p, "uExposure", tone.exposure);
  setUniform(p, "uContrast", tone.contrast);
  setUniform(p, "uBackground", displayEncode(tone.background, tone.gamma));
  glUniform1i(p.uniform("uLinearOutput"), linearOutput ? 1 : 0);
  bindSampler(p, "uRadiance", 0, GL_TEXTURE_2D, target.radiance_);
  bindSampler(p, "uMeshLayer", 1, GL_TEXTURE_2D, target.meshLayer_);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
}

core::ImageRGBA renderToImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height,
                              bool linearOutput, int maxTile, const std::function<void(double)>& progress) {
  GLint maxRenderbuffer = 0, maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  const int tileSize =
      std::max(16, std::min({maxTile, static_cast<int>(maxRenderbuffer), maxViewport[0], maxViewport[1]}));
  if (width <= 0 || height <= 0) throw core::Error("image size must be positive");

  core::ImageRGBA image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  const int samples = std::max(1, settings.render.samples);

  FrameTarget target;
  // Freed on every way out, a progress callback that throws (a cancelled export) included.
  struct OutputTarget {
    GLuint framebuffer = 0, renderbuffer = 0;
    OutputTarget() {
      glGenFramebuffers(1, &framebuffer);
      glGenRenderbuffers(1, &renderbuffer);
    }
    ~OutputTarget() {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glDeleteFramebuffers(1, &framebuffer);
      glDeleteRenderbuffers(1, &renderbuffer);
    }
    OutputTarget(const OutputTarget&) = delete;
    OutputTarget& operator=(const OutputTarget&) = delete;
  } outputTarget;
  const GLuint output = outputTarget.framebuffer, outputBuffer = outputTarget.renderbuffer;
  const auto tilesAcross = static_cast<long long>((width + tileSize - 1) / tileSize);
  const auto tilesDown = static_cast<long long>((height + tileSize - 1) / tileSize);
  const double totalSteps = static_cast<double>(tilesAcross * tilesDown * samples);
  long long stepsDone = 0;
  std::vector<float> tilePixels;
  for (int tileY = 0; tileY < height; tileY += tileSize) {
    for (int tileX = 0; tileX < width; tileX += tileSize) {
      const int tileWidth = std::min(tileSize, width - tileX);
      const int tileHeight = std::min(tileSize, height - tileY);
      // GL's rows run bottom to top: this tile's GL origin is measured from the image's bottom.
      const int glY = height - tileY - tileHeight;
      const glm::ivec4 tile(tileX, glY, width, height);
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
      renderer.drawMesh(target, settings, tile);

      glBindRenderbuffer(GL_RENDERBUFFER, outputBuffer);
      glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, tileWidth, tileHeight);
      glBindFramebuffer(GL_FRAMEBUFFER, output);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, outputBuffer);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw core::Error("could not make an offscreen framebuffer for a " + std::to_string(tileWidth) + "×" +
                          std::to_string(tileHeight) + " tile");
      renderer.resolve(target, settings, glm::ivec4(0, 0, tileWidth, tileHeight), linearOutput);
      tilePixels.resize(4 * static_cast<std::size_t>(tileWidth) * static_cast<std::size_t>(tileHeight));
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, tileWidth, tileHeight, GL_RGBA, GL_FLOAT, tilePixels.data());
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      const std::size_t row = 4 * static_cast<std::size_t>(tileWidth);
      for (int y = 0; y < tileHeight; ++y)
        std::copy_n(&tilePixels[static_cast<std::size_t>(tileHeight - 1 - y) * row], row, image.at(tileX, tileY + y));
    }
  }
  return image;
}

}  // namespace voxflame::gl
