// Orbit camera around the grid: azimuth and elevation on a sphere about the grid's centre.
// The up vector is derived from the orbit angles (the derivative along elevation), so looking
// straight down or up is as well defined as any other view: there is no singular "world up".
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "grid.h"
#include "scene.h"

namespace voxflame::core {

struct CameraFrame {
  glm::dvec3 eye{0.0};
  glm::dvec3 forward{0.0, 0.0, -1.0};
  glm::dvec3 right{1.0, 0.0, 0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  double nearPlane = 0.01;
  double farPlane = 100.0;
  bool orthographic = false;
};

// The frame for a camera orbiting `box` (in world units), for an image of the given aspect.
CameraFrame orbitCamera(const CameraSettings& settings, const Box& box, double aspect);

}  // namespace voxflame::core
