// An environment image cut into patches: the texels of one level of its chain, each with
// the world direction of its middle, its radiance (env.intensity applied) and its solid
// angle. What stands in for the image where light must come from a few directions: the
// bubbles' glint (reflection), the floor's shadow casters (floor_light) and the lights
// a head takes (media_light).
#pragma once

#include "core/environment/environment_map.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/studio.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

struct ImagePatch {
  glm::dvec3 dir{0, 1, 0};    // towards its middle (world, unit)
  glm::dvec3 radiance{0.0};   // its mean radiance
  double solid_angle = 0;     // sr
  int i = 0, j = 0;           // its texel (column, row) in the level
  // The irradiance it gives a surface facing it (a small patch: radiance x solid angle).
  glm::dvec3 irradiance() const { return radiance * solid_angle; }
};

struct ImagePatches {
  int width = 0, height = 0;  // the level's size
  std::vector<ImagePatch> patches;  // row by row
};

// The level an image's light is projected from (sky_irradiance): the first at most this
// wide. Each level's texel is the plain mean of the four above it, so a coarser level's
// texel times its solid angle is not quite their light: sums of light use this level.
inline constexpr int kImageProjectionWidth = 256;

// The first level of the chain at most `max_width` texels wide (the last if none is).
const HdrImage& image_level(const EnvironmentMap&, int max_width);
// Texel (i, j) of `level` (a level of the studio's image) as a patch.
ImagePatch image_patch(const Studio&, const HdrImage& level, int i, int j);
// The patches of the studio's image (none without one) at the first level at most
// `max_width` texels wide, the rows of its upper half only when `upper_half` is set.
ImagePatches image_patches(const Studio&, int max_width, bool upper_half = false);

// How far from the scene's centre a patch is placed as a light: far enough that its
// direction barely changes over a flight of glasses.
inline constexpr double kImageEmitterDistance = 50.0;  // m
// A patch as a sphere light kImageEmitterDistance from `centre` in its direction, of its
// solid angle and radiance there (the floor's photons and the heads take it so).
AreaLight far_patch_light(const ImagePatch&, const glm::dvec3& centre);

}  // namespace draught
