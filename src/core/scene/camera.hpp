// Pinhole camera. Pixel (x, y) counts from the top-left; pixel centres are at +0.5.
// Its GLSL twin, camera_dir() in shaders/lib/scene/camera.glsl, builds the same rays.
#pragma once

#include "core/reference/intersect.hpp"
#include "core/params/params.hpp"

namespace draught {

struct CameraBasis {
  glm::vec3 eye, right, up, forward;
  float tan_half_vfov = 0, aspect = 1;
};

CameraBasis camera_basis(const CameraParams&, int width, int height);
Ray camera_ray(const CameraBasis&, double px, double py, int width, int height);

}  // namespace draught
