#include "volume_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "core/error.h"

namespace voxflame::gl {

namespace {

// One triangle covering the viewport; the fragment shader does all the work.
const char* kVertexShader = R"(#version 430 core
out vec2 vNdc;
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  vNdc = corner * 2.0 - 1.0;
  gl_Position = vec4(vNdc, 0.0, 1.0);
}
)";

const char* kFragmentShader = R"(#version 430 core
in vec2 vNdc;
out vec4 fragColor;

uniform mat4 uInverseViewProjection;
uniform vec3 uGridOrigin;
uniform vec3 uGridExtent;
uniform float uVoxelSize;
uniform float uStepVoxels;
uniform sampler3D uDensity;
uniform sampler3D uColor;
uniform float uDensityScale;   // maps raw hits into the log curve
uniform float uLogNormalizer;  // 1 / log(1 + maxDensity * uDensityScale)
uniform float uBrightness;
uniform float uExposure;
uniform float uGamma;
uniform float uOpacity;
uniform vec3 uBackground;
uniform uint uFrame;

// PCG-style hash: a per-pixel, per-frame jitter of the first sample hides step banding.
float hash(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  return float(v.x & 0x00ffffffu) / 16777216.0;
}

void main() {
  vec4 nearPoint = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
  vec4 farPoint = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
  nearPoint /= nearPoint.w;
  farPoint /= farPoint.w;
  vec3 direction = farPoint.xyz - nearPoint.xyz;
  float rayLength = length(direction);
  direction /= rayLength;

  // The ray runs from the near plane to the far plane, so both clip every sample.
  vec3 inverseDirection = 1.0 / direction;
  vec3 t0 = (uGridOrigin - nearPoint.xyz) * inverseDirection;
  vec3 t1 = (uGridOrigin + uGridExtent - nearPoint.xyz) * inverseDirection;
  vec3 tLow = min(t0, t1);
  vec3 tHigh = max(t0, t1);
  float tEnter = max(max(tLow.x, tLow.y), max(tLow.z, 0.0));
  float tExit = min(min(tHigh.x, tHigh.y), min(tHigh.z, rayLength));

  vec3 radiance = vec3(0.0);
  float transmittance = 1.0;
  if (tExit > tEnter) {
    float stepLength = uStepVoxels * uVoxelSize;
    float t = tEnter + stepLength * hash(uvec3(gl_FragCoord.xy, uFrame));
    vec3 toTexture = 1.0 / uGridExtent;
    for (; t < tExit; t += stepLength) {
      vec3 uvw = (nearPoint.xyz + t * direction - uGridOrigin) * toTexture;
      float density = texture(uDensity, uvw).r;
      if (density <= 0.0) continue;
      float level = log(1.0 + density * uDensityScale) * uLogNormalizer;
      float alpha = 1.0 - exp(-level * uOpacity * uStepVoxels);
      radiance += transmittance * alpha * texture(uColor, uvw).rgb;
      transmittance *= 1.0 - alpha;
      if (transmittance < 0.003) break;  // nothing behind can show
    }
  }
  vec3 color = radiance * uBrightness * exp2(uExposure) + transmittance * uBackground;
  fragColor = vec4(pow(max(color, vec3(0.0)), vec3(1.0 / uGamma)), 1.0);
}
)";

GLuint makeVolumeTexture() {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_3D, texture);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
  return texture;
}

}  // namespace

VolumeRenderer::VolumeRenderer() : program_(kVertexShader, kFragmentShader) {
  glGenVertexArrays(1, &vertexArray_);
  densityTexture_ = makeVolumeTexture();
  colorTexture_ = makeVolumeTexture();
}

VolumeRenderer::~VolumeRenderer() {
  glDeleteTextures(1, &densityTexture_);
  glDeleteTextures(1, &colorTexture_);
  glDeleteVertexArrays(1, &vertexArray_);
}

void VolumeRenderer::upload(const core::VolumeSnapshot& snapshot) {
  const glm::ivec3 size = snapshot.geometry.size;
  const bool resized = size != geometry_.size;
  geometry_ = snapshot.geometry;
  maxDensity_ = snapshot.maxDensity;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_3D, densityTexture_);
  if (resized)
    glTexImage3D(GL_TEXTURE_3D, 0, GL_R32F, size.x, size.y, size.z, 0, GL_RED, GL_FLOAT, snapshot.density.data());
  else
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, size.x, size.y, size.z, GL_RED, GL_FLOAT, snapshot.density.data());
  glBindTexture(GL_TEXTURE_3D, colorTexture_);
  if (resized)
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, size.x, size.y, size.z, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 snapshot.rgba.data());
  else
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, size.x, size.y, size.z, GL_RGBA, GL_UNSIGNED_BYTE, snapshot.rgba.data());
  uploadedVersion_ = snapshot.version;
}

void VolumeRenderer::draw(const RenderSettings& settings, int width, int height) {
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glUseProgram(program_.id());
  const glm::mat4 inverseViewProjection(glm::inverse(settings.camera.projection * settings.camera.view));
  const core::Box box = geometry_.box();
  glUniformMatrix4fv(program_.uniform("uInverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inverseViewProjection));
  glUniform3f(program_.uniform("uGridOrigin"), static_cast<float>(box.min.x), static_cast<float>(box.min.y),
              static_cast<float>(box.min.z));
  const glm::dvec3 extent = box.extent();
  glUniform3f(program_.uniform("uGridExtent"), static_cast<float>(extent.x), static_cast<float>(extent.y),
              static_cast<float>(extent.z));
  glUniform1f(program_.uniform("uVoxelSize"), static_cast<float>(geometry_.voxelSize));
  glUniform1f(program_.uniform("uStepVoxels"), static_cast<float>(std::clamp(settings.stepVoxels, 0.05, 4.0)));
  // The log curve spans about four decades between one hit and the densest voxel.
  const float densityScale = maxDensity_ > 0.0f ? 1e4f / maxDensity_ : 1.0f;
  glUniform1f(program_.uniform("uDensityScale"), densityScale);
  glUniform1f(program_.uniform("uLogNormalizer"), 1.0f / std::log1p(std::max(maxDensity_, 1.0f) * densityScale));
  glUniform1f(program_.uniform("uBrightness"), static_cast<float>(settings.tone.brightness));
  glUniform1f(program_.uniform("uExposure"), static_cast<float>(settings.tone.exposure));
  glUniform1f(program_.uniform("uGamma"), static_cast<float>(settings.tone.gamma));
  glUniform1f(program_.uniform("uOpacity"), static_cast<float>(settings.tone.opacity));
  glUniform3f(program_.uniform("uBackground"), settings.tone.background.r, settings.tone.background.g,
              settings.tone.background.b);
  glUniform1ui(program_.uniform("uFrame"), settings.frameIndex);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_3D, densityTexture_);
  glUniform1i(program_.uniform("uDensity"), 0);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_3D, colorTexture_);
  glUniform1i(program_.uniform("uColor"), 1);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
}

core::ImageRGBA renderToImage(VolumeRenderer& renderer, const RenderSettings& settings, int width, int height) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
    throw core::Error("image size " + std::to_string(width) + "×" + std::to_string(height) +
                      " is outside what this GL can render (1 to " + std::to_string(maxSize) + " per side)");
  GLuint framebuffer = 0, colorBuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glGenRenderbuffers(1, &colorBuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, colorBuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorBuffer);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  core::ImageRGBA image;
  if (complete) {
    renderer.draw(settings, width, height);
    image.width = width;
    image.height = height;
    std::vector<float> flipped(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, flipped.data());
    image.pixels.resize(flipped.size());
    const std::size_t row = 4 * static_cast<std::size_t>(width);
    for (int y = 0; y < height; ++y)  // GL's rows run bottom to top
      std::copy_n(&flipped[static_cast<std::size_t>(height - 1 - y) * row], row,
                  &image.pixels[static_cast<std::size_t>(y) * row]);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteRenderbuffers(1, &colorBuffer);
  glDeleteFramebuffers(1, &framebuffer);
  if (!complete) throw core::Error("could not make an offscreen framebuffer of that size");
  return image;
}

}  // namespace voxflame::gl
