// What the surroundings give the renderer beyond its own per-pixel look-ups: estimates
// that are physics of the environment, computed once per frame on the CPU.
#pragma once

#include "core/environment/backdrop.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/params/params.hpp"

#include <glm/glm.hpp>

#include <memory>

namespace draught {

struct EnvironmentFrame {
  // The radiance a small mirror-like sphere (a rising bubble) reflects on average: the
  // mean of everything around the scene's centre (the sky, each light over the solid
  // angle it covers there, the lit backdrop below and behind). The bubble pass scales it
  // by each bubble's Fresnel reflectance.
  glm::vec3 reflected{0.0f};
  // The light whose glint a bubble shows: the one giving the scene's centre the most
  // light; the direction towards it and that irradiance (0 without lights).
  glm::vec3 glint_dir{0, 1, 0};
  glm::vec3 glint{0.0f};
  // The sky's irradiance (spherical harmonics) for the backdrop, the heads and the haze.
  SkyIrradiance sky;
  // env.mode image: the environment and how it is seen (Studio's image, rotation, blur).
  std::shared_ptr<const EnvironmentMap> image;
  float rotation_cos = 1, rotation_sin = 0, blur_lod = 0, intensity = 1;
};

EnvironmentFrame environment_frame(const SceneParams&, const LightRig&, const BackdropSurface&);

}  // namespace draught
