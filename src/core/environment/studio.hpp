// The surroundings as light, in C++: the procedural studio's radiance by direction (the
// twin of studio_backdrop in shaders/lib/environment/studio.glsl). The reference path
// tracer lights its scenes with it and the rig's area lights (core/environment/lights.hpp).
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

namespace draught {

struct Studio {
  EnvParams env;
  explicit Studio(const SceneParams&);
  // Radiance from direction d (unit, world) of the studio around the scene (the lights of
  // the rig are emitters of their own: core/environment/lights.hpp).
  glm::dvec3 sky(const glm::dvec3& d) const;
  // How much of the checker floor's own light a ray sees at distance `dist` (the rest is
  // the studio's ground colour): it fades out over 2 m, as the picture's does.
  static double floor_visibility(double dist);
};

}  // namespace draught
