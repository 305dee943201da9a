#include "camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace voxflame::core {

CameraFrame orbitCamera(const CameraSettings& settings, const Box& box, double aspect) {
  CameraFrame frame;
  const double radius = 0.5 * glm::length(box.extent());
  const double azimuth = glm::radians(settings.azimuthDeg);
  const double elevation = glm::radians(settings.elevationDeg);
  const double roll = glm::radians(settings.rollDeg);
  // Y is up in the conventional mesh frame; the orbit is about the Y axis. The up vector is the
  // derivative of the eye direction along elevation, so it is never parallel to the view.
  const glm::dvec3 toEye(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::cos(azimuth));
  const glm::dvec3 upFromAngles(-std::sin(elevation) * std::sin(azimuth), std::cos(elevation),
                                -std::sin(elevation) * std::cos(azimuth));
  const glm::dvec3 target = box.center() + settings.target * radius;
  const double distance = settings.distance * radius;
  frame.eye = target + distance * toEye;
  frame.forward = -toEye;
  const glm::dvec3 right0 = glm::normalize(glm::cross(frame.forward, glm::normalize(upFromAngles)));
  const glm::dvec3 up0 = glm::cross(right0, frame.forward);
  frame.right = std::cos(roll) * right0 + std::sin(roll) * up0;
  frame.up = std::cos(roll) * up0 - std::sin(roll) * right0;
  frame.view = glm::lookAt(frame.eye, frame.eye + frame.forward, frame.up);

  // Automatic clip planes enclose the grid's bounding sphere; explicit ones are honoured as given.
  const double toCenter = glm::length(box.center() - frame.eye);
  frame.nearPlane =
      settings.nearClip > 0.0 ? settings.nearClip * radius : std::max(1e-4 * radius, toCenter - 1.01 * radius);
  frame.farPlane = settings.farClip > 0.0 ? settings.farClip * radius : toCenter + 1.01 * radius;
  frame.farPlane = std::max(frame.farPlane, frame.nearPlane * 1.0001);
  frame.orthographic = settings.projection == Projection::Orthographic;
  if (frame.orthographic) {
    const double halfHeight = 0.5 * settings.orthoHeight * radius;
    frame.projection =
        glm::ortho(-halfHeight * aspect, halfHeight * aspect, -halfHeight, halfHeight, frame.nearPlane, frame.farPlane);
  } else {
    frame.projection = glm::perspective(glm::radians(settings.fovDeg), aspect, frame.nearPlane, frame.farPlane);
  }
  return frame;
}

CameraSettings viewCameraFor(const CameraSettings& settings, double viewAspect, double aspect) {
  CameraSettings view = settings;
  if (!(viewAspect > 0.0) || !(aspect > viewAspect)) return view;
  const double grow = aspect / viewAspect;  // the view's height over the picture's
  view.fovDeg = std::min(179.0, glm::degrees(2.0 * std::atan(std::tan(0.5 * glm::radians(settings.fovDeg)) * grow)));
  view.orthoHeight = settings.orthoHeight * grow;
  return view;
}

glm::dvec4 exportFrame(glm::dvec2 viewSize, double aspect) {
  if (!(aspect > 0.0) || viewSize.x <= 0.0 || viewSize.y <= 0.0) return {0.0, 0.0, viewSize.x, viewSize.y};
  const double width = std::min(viewSize.x, viewSize.y * aspect);
  const double height = width / aspect;
  return {0.5 * (viewSize.x - width), 0.5 * (viewSize.y - height), width, height};
}

}  // namespace voxflame::core
