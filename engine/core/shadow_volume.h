// Light transmittance through the volume toward one directional light: per cell, how much of the
// light survives the density between it and the light. The renderer dims emission by it so the
// pattern reads as a lit shape. Computed on the CPU by sweeping slices away from the light, each
// slice reading the one before it a fraction of a cell sideways (O(cells), no ray per voxel).
#pragma once

#include <cstdint>
#include <stop_token>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "packed_volume.h"

namespace voxflame::core {

struct ShadowVolume {
  glm::ivec3 size{0};                       // cells; each covers `downsample`³ voxels
  std::vector<std::uint8_t> transmittance;  // 255 = fully lit
};

// `towardLight` need not be normalised. `extinctionScale` is the extinction per unit of
// normalised column density (flame/image.h: density relative to the mesh's mean, lengths in grid
// sides), as the renderer absorbs. A stop requested through `stop` ends the work within a slice
// (a millisecond or so at 512³) and returns false, `out` then being no shadow; true otherwise.
bool computeShadowVolume(const PackedVolume& volume, glm::dvec3 towardLight, double extinctionScale, int downsample,
                         ShadowVolume& out, std::stop_token stop = {});

// How the sweep crosses the cells toward a light: slice by slice along the axis the light is most
// aligned with, from the light's side, each slice reading the one before it `shift` cells sideways.
// The CPU's sweep and the GPU's (gl::VolumeRenderer::computeShadow) both follow it.
struct ShadowSweep {
  int axis = 1, u = 2, v = 0;  // the sweep's axis and the slice's two others
  int towardLightStep = 1;     // +1: the light lies toward higher indices along the axis
  glm::dvec2 shift{0.0};       // where a cell reads the slice before it, in cells along u and v
  double pathPerSlice = 1.0;   // cell edges a ray toward the light crosses per slice
};
ShadowSweep shadowSweep(glm::dvec3 towardLight);  // `towardLight` need not be normalised

// The unit vector toward a light at these angles, in the camera's orbit convention (Y up).
glm::dvec3 lightDirection(double azimuthDeg, double elevationDeg);

}  // namespace voxflame::core
