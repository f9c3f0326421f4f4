// Pinhole camera. Pixel (x, y) counts from the top-left; pixel centres are at +0.5.
// Its GLSL twin, camera_dir() in shaders/lib/scene/camera.glsl, builds the same rays.
// The lens may be shifted (a view camera's rise and shift): the camera's own picture then
// lies in a part of a larger one, which extends it, so the desktop viewer can frame the
// scene in the part of its window that the panel leaves free and still draw behind it.
#pragma once

#include "core/reference/intersect.hpp"
#include "core/params/params.hpp"

namespace draught {

struct CameraBasis {
  glm::vec3 eye, right, up, forward;
  float tan_half_vfov = 0, aspect = 1;
  // Where the centre of projection lies in the picture, in [-1, 1] (x right, y up); 0: in
  // the middle.
  glm::vec2 shift{0};
};

// A part of a picture, in fractions of its width and height from the top-left.
struct PictureRect {
  double x = 0, y = 0, width = 1, height = 1;
  bool whole() const { return x == 0 && y == 0 && width == 1 && height == 1; }
};

CameraBasis camera_basis(const CameraParams&, int width, int height);
// The basis of a width x height picture in whose part `view` the camera shows what it
// would show in a picture of that part's size (same eye, direction and field of view
// there); the rest of the picture extends it through the shifted lens.
CameraBasis camera_basis(const CameraParams&, int width, int height, const PictureRect& view);
Ray camera_ray(const CameraBasis&, double px, double py, int width, int height);

}  // namespace draught
