// The drink's body in a vessel: Beer-Lambert absorption along the path and
// single-scattering haze, both closed-form over a straight segment (no marching).
#ifndef LIB_LIQUID_BODY_GLSL
#define LIB_LIQUID_BODY_GLSL
#include "lib/scene/objects.glsl"

// Transmittance of a straight path of length dist in the medium of vessel v (glass g).
vec3 medium_transmittance(Vessel v, ObjectGlass g, int medium, float dist) {
  if (medium == MEDIUM_GLASS) return exp(-g.glass_absorption * dist);
  if (medium == MEDIUM_LIQUID) return exp(-(v.body.absorption + vec3(v.liquid.haze)) * dist);
  return vec3(1.0);
}

// Light scattered towards the eye by haze along the segment (single scattering of the
// sky's light and the rig's lights, each a distant light from the glass's middle: the
// quarter of its irradiance an isotropic scatterer sends per steradian over pi; all reach
// the inside already tinted by the drink): the record's haze_light, computed in
// gpu/scene_data.cpp once per frame.
vec3 haze_inscatter(Vessel v, float dist) {
  float s = v.liquid.haze;
  if (s <= 0.0) return vec3(0.0);
  vec3 sigma_t = v.body.absorption + vec3(s);
  return v.liquid.haze_light * (s / sigma_t) * (1.0 - exp(-sigma_t * dist));
}

#endif  // LIB_LIQUID_BODY_GLSL
