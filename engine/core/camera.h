// Orbit camera around the grid: azimuth and elevation on a sphere about the grid's centre.
// The up vector is derived from the orbit angles (the derivative along elevation), so looking
// straight down or up is as well defined as any other view: there is no singular "world up".
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "mesh.h"
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

// The camera of a view of `viewAspect` that shows all of what `settings` shows at `aspect`, as
// the rectangle exportFrame() gives: a picture wider than the view widens the view's vertical
// field (or its orthographic height) so the picture's width is the view's; a narrower one
// keeps the view's height, the same field.
CameraSettings viewCameraFor(const CameraSettings& settings, double viewAspect, double aspect);

// That rectangle within a view of `viewSize`: x, y (from the bottom), width, height.
glm::dvec4 exportFrame(glm::dvec2 viewSize, double aspect);

}  // namespace voxflame::core
