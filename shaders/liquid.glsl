// The drink's body: Beer-Lambert absorption along the path and single-scattering haze,
// both closed-form over a straight segment (no marching).

// Transmittance of a straight path of length dist in the medium.
vec3 medium_transmittance(int medium, float dist) {
  if (medium == GLASS) return exp(-u_glass_absorb.rgb * dist);
  if (medium == LIQUID) return exp(-(u_liquid_absorb.rgb + vec3(u_liquid.z)) * dist);
  return vec3(1.0);
}

// Light scattered towards the eye by haze along the segment (single scattering of the
// ambient light, which reaches the inside already tinted by the drink).
vec3 haze_inscatter(float dist) {
  float s = u_liquid.z;
  if (s <= 0.0) return vec3(0.0);
  vec3 sigma_t = u_liquid_absorb.rgb + vec3(s);
  vec3 lit = ambient_light() + u_light_color.rgb * u_light_dir.w * 0.25;
  vec3 inside = lit * exp(-u_liquid_absorb.rgb * u_glass.w * 0.7);
  return u_haze_color.rgb * inside * (s / sigma_t) * (1.0 - exp(-sigma_t * dist));
}
