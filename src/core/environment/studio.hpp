// The surroundings as light, in C++: the procedural studio's radiance by direction, a
// constant colour, or an HDR environment image (env.mode; the twin of sky_seen in
// shaders/lib/environment/studio.glsl). The reference path tracer lights its scenes with it
// and the rig's area lights (core/environment/lights.hpp; none in image mode).
#pragma once

#include "core/environment/environment_map.hpp"
#include "core/params/params.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <string>

namespace draught {

struct Studio {
  EnvParams env;
  // env.mode image: the environment (read through core/environment/environment_files, so
  // a frame does not read the file again), turned by env.rotation, scaled by env.intensity.
  std::shared_ptr<const EnvironmentMap> image;
  double rotation_cos = 1, rotation_sin = 0;
  double blur_lod = 0;  // the level env.blur reads at least

  explicit Studio(const SceneParams&);
  // Radiance from direction d (unit, world) of the studio around the scene (the lights of
  // the rig are emitters of their own: core/environment/lights.hpp).
  glm::dvec3 sky(const glm::dvec3& d) const;
  // The same seen through a surface of GGX roughness r (glass, the liquid's surface): an
  // image is read at the level of detail as wide as the reflected lobe (about 2 r^2).
  glm::dvec3 sky(const glm::dvec3& d, double roughness) const;
  // Where world direction d looks in env.image (env.rotation undone).
  glm::dvec3 image_direction(const glm::dvec3& d) const;
  // Its inverse: the world direction at which the image's direction e is seen.
  glm::dvec3 world_direction(const glm::dvec3& e) const;
  // How much of the checker floor's own light a ray sees at distance `dist` (the rest is
  // the studio's ground colour): it fades out over 2 m, as the picture's does.
  static double floor_visibility(double dist);
};

// Every value the studio and its lights are made of (each env.*, light.*, strips.* and
// backlight.* parameter), as text: what a bake or a frame's light computed from them is
// reused for while it stays the same (the MatCap's bake, assemble_frame's EnvironmentCache).
std::string studio_params_key(const SceneParams&);

}  // namespace draught
