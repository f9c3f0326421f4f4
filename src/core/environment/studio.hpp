// The surroundings as light, in C++: the procedural studio's radiance by direction (the
// twin of studio_backdrop in shaders/lib/environment/studio.glsl), the reference's old
// key light as an emitter of its own, and the checker floor's albedo (shade_floor in
// shaders/lib/environment/floor.glsl). The reference path tracer lights its scenes with
// these.
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

namespace draught {

// The key softbox: a disc of uniform radiance seen from everywhere in the same
// direction (it is far away). `intensity` is the irradiance it gives a surface facing
// it, so radiance = colour x intensity / (pi sin^2 radius): a bigger softbox is dimmer and
// softer, the light it gives the same.
struct KeyLight {
  glm::dvec3 dir{0, 1, 0};  // towards the light, unit
  double cos_radius = 1;    // cosine of its angular radius
  double solid_angle = 0;   // steradians
  glm::dvec3 radiance{0.0};
  bool contains(const glm::dvec3& d) const { return solid_angle > 0 && glm::dot(d, dir) >= cos_radius; }
};

struct Studio {
  EnvParams env;
  KeyLight key;
  explicit Studio(const SceneParams&);
  // Radiance from direction d (unit, world) of everything but the key light.
  glm::dvec3 sky(const glm::dvec3& d) const;
  // The floor's diffuse albedo at world point p (the checker).
  glm::dvec3 floor_albedo(const glm::dvec3& p) const;
  // How much of the floor's own light a ray sees at distance `dist` (the rest is the
  // backdrop's ground colour): the floor fades out over 2 m, as the picture's does.
  static double floor_visibility(double dist);
};

}  // namespace draught
