#include "camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace voxflame::core {

CameraFrame orbitCamera(const CameraSettings& settings, const Box& box, double aspect) {
  CameraFrame frame;
  const double radius = 0.5 * glm::length(box.extent());
  const double azimuth = glm::radians(settings.azimuthDeg);
  const double elevation = glm::radians(settings.elevationDeg);
  // Y is up in the conventional mesh frame; the orbit is about the Y axis.
  const glm::dvec3 toEye(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::cos(azimuth));
  const glm::dvec3 upFromAngles(-std::sin(elevation) * std::sin(azimuth), std::cos(elevation),
                                -std::sin(elevation) * std::cos(azimuth));
  const double distance = settings.distance * radius;
  frame.eye = box.center() + distance * toEye;
  frame.forward = -toEye;
  frame.up = glm::normalize(upFromAngles);
  frame.right = glm::normalize(glm::cross(frame.forward, frame.up));
  frame.view = glm::lookAt(frame.eye, box.center(), frame.up);
  frame.nearPlane = std::max(1e-4 * radius, distance - 2.0 * radius);
  frame.farPlane = distance + 2.0 * radius;
  frame.projection = glm::perspective(glm::radians(settings.fovDeg), aspect, frame.nearPlane, frame.farPlane);
  return frame;
}

}  // namespace voxflame::core
