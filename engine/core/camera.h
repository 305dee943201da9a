// Orbit camera around the grid: azimuth and elevation on a sphere about the grid's centre.
// The up vector is derived from the orbit angles (the derivative along elevation), so looking
// straight down or up is as well defined as any other view: there is no singular "world up".
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

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

// The camera that shows, at `aspect`, the largest rectangle of that aspect centred in a view of
// `viewAspect` (exportFrame): a wider picture than the view narrows the vertical field (or the
// orthographic height) so its width is the view's; a narrower one keeps the view's height.
CameraSettings cameraForFrame(const CameraSettings& settings, double viewAspect, double aspect);

// That rectangle within a view of `viewSize`: x, y (from the bottom), width, height.
glm::dvec4 exportFrame(glm::dvec2 viewSize, double aspect);

}  // namespace voxflame::core
