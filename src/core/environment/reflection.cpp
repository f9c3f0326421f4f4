#include "core/environment/reflection.hpp"

#include <numbers>

namespace draught {

EnvironmentFrame environment_frame(const SceneParams& p, const LightRig& rig, const BackdropSurface& backdrop) {
  constexpr double kPi = std::numbers::pi;
  EnvironmentFrame f;
  const Studio studio(p);
  f.sky = sky_irradiance(studio);
  // The sky's mean radiance over the sphere is its band-0 coefficient's share.
  glm::dvec3 mean = f.sky.coef[0] * SkyIrradiance::basis({0, 1, 0})[0] / kPi;
  // Each light over the solid angle it covers at the centre (for a small light the
  // irradiance factor facing it is that solid angle), a 4 pi-th of the sphere.
  double best = 0;
  glm::dvec3 floor_light(0.0);  // irradiance on the backdrop under the centre
  const glm::dvec3 under(rig.aim.x, 0.0, rig.aim.z);
  for (const AreaLight& l : rig.lights) {
    const glm::dvec3 to = glm::normalize(l.center - rig.aim);
    const double facing = l.irradiance_factor(rig.aim, to);
    mean += l.radiance * facing / (4 * kPi);
    const glm::dvec3 e = l.radiance * facing;
    if (e.x + e.y + e.z > best) {
      best = e.x + e.y + e.z;
      f.glint_dir = glm::vec3(to);
      f.glint = glm::vec3(e);
    }
    floor_light += l.radiance * l.irradiance_factor(under, {0, 1, 0});
  }
  // The backdrop fills about the lower half of what a bubble sees: lit paper.
  if (backdrop.present && p.env.mode == int(EnvMode::Studio))
    mean += 0.5 * backdrop.albedo(under) / kPi * (floor_light + f.sky.at({0, 1, 0}));
  f.reflected = glm::vec3(mean);
  return f;
}

}  // namespace draught
