#include "core/scene/camera.hpp"

#include <cmath>

namespace draught {

CameraBasis camera_basis(const CameraParams& c, int width, int height) {
  CameraBasis b;
  b.eye = c.eye;
  glm::vec3 f = c.target - c.eye;
  b.forward = glm::length(f) > 1e-6f ? glm::normalize(f) : glm::vec3(0, 0, -1);
  glm::vec3 up = std::fabs(b.forward.y) > 0.999f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  b.right = glm::normalize(glm::cross(b.forward, up));
  b.up = glm::cross(b.right, b.forward);
  b.tan_half_vfov = std::tan(glm::radians(c.vfov) * 0.5f);
  b.aspect = float(width) / float(height);
  return b;
}

CameraBasis camera_basis(const CameraParams& c, int width, int height, const PictureRect& view) {
  CameraBasis b = camera_basis(c, width, height);
  if (view.whole() || !(view.width > 0 && view.height > 0)) return b;
  // The camera's field of view spans view.height of the picture, so the picture's is wider.
  b.tan_half_vfov /= float(view.height);
  b.shift = glm::vec2(2.0 * (view.x + 0.5 * view.width) - 1.0, 1.0 - 2.0 * (view.y + 0.5 * view.height));
  return b;
}

Ray camera_ray(const CameraBasis& b, double px, double py, int width, int height) {
  const double x = (2.0 * px / width - 1.0 - b.shift.x) * b.aspect * b.tan_half_vfov;
  const double y = (1.0 - 2.0 * py / height - b.shift.y) * b.tan_half_vfov;
  glm::dvec3 d = glm::dvec3(b.forward) + x * glm::dvec3(b.right) + y * glm::dvec3(b.up);
  return {glm::dvec3(b.eye), glm::normalize(d)};
}

}  // namespace draught
