// What the scene stands on (env.backdrop): the packshot studio's seamless paper sweep, or
// the checker floor to the horizon (a test environment). Where a ray meets it, its normal
// and its albedo, in the world. The picture's twin is shaders/lib/environment/backdrop.glsl.
//
// The sweep, around the scene's centre `aim` (core/scene/frame.hpp scene_aim): the floor
// y = 0 in front of z_curve = aim.z - env.sweep_distance; behind it a quarter cylinder of
// radius R = env.sweep_radius along x, (y - R)^2 + (z - z_curve)^2 = R^2 with y <= R and
// z <= z_curve; above y = R the wall z = z_curve - R. It is endless across x and upwards,
// seen from the scene's side (its normal points there).
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

namespace draught {

struct BackdropSurface {
  bool present = false;  // env.floor
  Backdrop kind = Backdrop::Sweep;
  double z_curve = 0, radius = 0.3;  // the sweep
  glm::dvec3 sweep_albedo{0.8};
  double checker_size = 0.04;
  // The floor alone, the whole plane y = 0 to the horizon: the checker, and the sweep's paper
  // under an environment image (env.mode image), whose horizon its curve and wall would hide.
  bool plane = false;
  glm::dvec3 floor_a{0.58}, floor_b{0.44};

  // The nearest t > tmin where the ray o + t d meets the backdrop from the scene's side,
  // and the normal there (unit, towards the scene). False when it does not.
  bool intersect(const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t, glm::dvec3& n) const;
  // Its diffuse albedo at point p on it.
  glm::dvec3 albedo(const glm::dvec3& p) const;
};

BackdropSurface backdrop_surface(const EnvParams&, const glm::dvec3& aim);

}  // namespace draught
