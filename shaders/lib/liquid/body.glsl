// The drink's body in a vessel: Beer-Lambert absorption along the path and
// single-scattering haze, both closed-form over a straight segment (no marching).
#ifndef LIB_LIQUID_BODY_GLSL
#define LIB_LIQUID_BODY_GLSL
#include "lib/scene/objects.glsl"
#include "lib/environment/lights.glsl"

// Transmittance of a straight path of length dist in the medium of vessel v (glass g).
vec3 medium_transmittance(Vessel v, ObjectGlass g, int medium, float dist) {
  if (medium == MEDIUM_GLASS) return exp(-g.glass_absorption * dist);
  if (medium == MEDIUM_LIQUID) return exp(-(v.body.absorption + vec3(v.liquid.haze)) * dist);
  return vec3(1.0);
}

// Light scattered towards the eye by haze along the segment (single scattering of the
// sky's light and the rig's lights, each a distant light from the glass's middle: the
// quarter of its irradiance an isotropic scatterer sends per steradian over pi, as
// before; all reach the inside already tinted by the drink).
vec3 haze_inscatter(Vessel v, float dist) {
  float s = v.liquid.haze;
  if (s <= 0.0) return vec3(0.0);
  vec3 sigma_t = v.body.absorption + vec3(s);
  vec3 lit = sky_light();
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= frame.light_count) break;
    lit += 0.25 * frame.light_radiance[i].rgb * object_lit_by(v.row, i).w;
  }
  vec3 inside = lit * exp(-v.body.absorption * v.body.mean_outer_radius * 0.7);
  return v.liquid.haze_color * inside * (s / sigma_t) * (1.0 - exp(-sigma_t * dist));
}

#endif  // LIB_LIQUID_BODY_GLSL
