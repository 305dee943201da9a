// Helpers shared by the suites that drive the GPU backend: the default preset's mask, whether a
// headless GL context can be made here at all, a storage buffer's upload, and what the GPU lacks.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <memory>

#include "core/error.h"
#include "core/flame/flame.h"
#include "core/inside_mask.h"
#include "core/mesh.h"
#include "core/scene_io.h"
#include "gl/headless_context.h"

namespace voxflame::test {

// The inside mask of the default preset's mesh (the bunny) at this resolution.
inline std::shared_ptr<const core::InsideMask> bunnyMask(int resolution) {
  const core::TriangleMesh mesh = core::loadSceneMesh(core::defaultScene());
  return std::make_shared<const core::InsideMask>(
      core::buildInsideMask(mesh, core::gridOverBox(mesh.bounds(), resolution)));
}

inline bool glAvailable() {
  try {
    const gl::HeadlessContext context;
    return true;
  } catch (const core::Error&) {
    return false;
  }
}

// `bytes` of `values` into `buffer`, bound to storage-buffer binding `binding`.
inline void uploadStorage(GLuint buffer, GLuint binding, std::size_t bytes, const void* values) {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), values, GL_DYNAMIC_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
}

// What the GPU's chaos game does not have, added to a transform: a weighting field that moves
// crackle's cell size per point (the GPU's crackle reads numbers derived from its parameters).
inline void addWhatTheGpuLacks(core::FlameXform& xform) {
  xform.variations.push_back({"crackle", 0.1, {1.0}});
  xform.fieldKind = core::WeightFieldKind::Noise;
  xform.fieldParam1Variation = "crackle";
  xform.fieldParam1Name = "cellsize";
  xform.fieldParam1Intensity = 0.5;
}

}  // namespace voxflame::test
