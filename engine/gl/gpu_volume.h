// A packed volume in GL textures (core::PackedVolume::device): what the GPU refinement backend
// packs from its grid on its own thread, in a context that shares its objects with the
// renderer's, so the grid reaches the ray-marcher without a read-back or an upload.
//
// The textures are the renderer's formats (volume_renderer.h's Slot): RGBA16F per colour cell
// (mean colour times density, density), R16F per voxel (density relative to the mesh's mean),
// R8UI per brick (empty distance). The renderer copies them into its own textures on the GPU
// (glCopyImageSubData: a few hundred microseconds at 512³ on a GPU) rather than sampling these:
// the backend can then pack again, and be destroyed with its context, whatever the renderer still
// shows. Two syncs order the two contexts: the renderer's copy waits for the pack, and the next
// pack into these textures waits for the copy.
#pragma once

#include <epoxy/gl.h>

#include <mutex>

#include <glm/vec3.hpp>

#include "core/packed_volume.h"

namespace voxflame::gl {

class GpuVolume final : public core::DeviceVolume {
 public:
  // Made and deleted by the backend's GPU thread only.
  GLuint colour = 0, density = 0, emptyDistance = 0;
  glm::ivec3 size{0}, colourSize{0}, brickCount{0};

  // Everything below is under `mutex`, which a copy holds from its check of `alive` until its
  // sync is made, so the backend never deletes the textures under a copy being recorded.
  std::mutex mutex;
  bool alive = true;        // false once the backend deleted the textures: nothing to copy
  GLsync packed = nullptr;  // signals when the pack's commands are done (the backend's context)
  GLsync copied = nullptr;  // signals when the renderer's copy is done (the renderer's context)
};

}  // namespace voxflame::gl
