// The drink's body in the loaded vessel: Beer-Lambert absorption along the path and
// single-scattering haze, both closed-form over a straight segment (no marching).
#ifndef LIB_LIQUID_BODY_GLSL
#define LIB_LIQUID_BODY_GLSL
#include "lib/scene/objects.glsl"
#include "lib/environment/studio.glsl"

// Transmittance of a straight path of length dist in the medium (of the loaded object).
vec3 medium_transmittance(int medium, float dist) {
  if (medium == MEDIUM_GLASS) return exp(-g_glass.glass_absorption * dist);
  if (medium == MEDIUM_LIQUID) return exp(-(g_liquid.absorption + vec3(g_liquid.haze)) * dist);
  return vec3(1.0);
}

// Light scattered towards the eye by haze along the segment (single scattering of the
// ambient light, which reaches the inside already tinted by the drink).
vec3 haze_inscatter(float dist) {
  float s = g_liquid.haze;
  if (s <= 0.0) return vec3(0.0);
  vec3 sigma_t = g_liquid.absorption + vec3(s);
  vec3 lit = ambient_light() + frame.light_color * frame.light_intensity * 0.25;
  vec3 inside = lit * exp(-g_liquid.absorption * g_shape.mean_outer_radius * 0.7);
  return g_liquid.haze_color * inside * (s / sigma_t) * (1.0 - exp(-sigma_t * dist));
}

#endif  // LIB_LIQUID_BODY_GLSL
