// The light a head and a drink's haze receive (shaders/lib/foam/head.glsl, the haze's
// light in gpu/scene_data): up to MAX_LIGHTS lights, each taken as a distant light from a
// glass's middle (objects.def lit_by: a head shades and shadows itself towards each), and
// the rest of the surroundings as nine harmonics of irradiance.
//
// In the studio these are the rig's lights and the surround (the sky and the lit
// backdrop). Under an environment image the image's brightest patches become the lights:
// a texel each of the level nearest 32 wide (about 11 degrees), the brightest first, none
// beside one already taken, and only patches far brighter than the image on average (a
// lamp, not the sky). Their light leaves the harmonics: the same light, moved from a
// smooth glow to where it comes from, so a bar's lamps light a head from above and its
// side away from them is darker, as the reference path tracer shows.
#pragma once

#include "core/environment/lights.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/environment/studio.hpp"

#include <vector>

namespace draught {

struct MediaLight {
  std::vector<AreaLight> lights;  // at most contract::kMaxLights
  SkyIrradiance surround;         // everything else, as irradiance harmonics
};

// How much brighter than the image's mean radiance a patch must be to be a light.
inline constexpr double kMediaPatchContrast = 4.0;

// `surround`: what lies around the scene's centre besides the rig's lights
// (EnvironmentFrame::surround); `rig`: the studio's lights (none under an image).
MediaLight media_light(const Studio&, const LightRig& rig, const SkyIrradiance& surround);

}  // namespace draught
