#version 300 es
// A gas bubble in the drink: light reflects off its surface (liquid to gas), totally
// near the outline, so it shows a bright rim around a clear middle, plus the key light's
// glint. Premultiplied alpha over the picture of pass 1.
precision highp float;

in vec2 v_q;
flat in vec3 v_tint;
flat in float v_radius;

uniform vec3 u_env_light;    // brightness of the surroundings reflected by the bubble
uniform vec3 u_glint;        // key light colour x intensity
uniform vec2 u_glint_dir;    // where the glint sits on the impostor (unit disk)
uniform float u_exposure;
uniform int u_tonemap;

out vec4 frag_color;

#include "tonemap.glsl"

void main() {
  float q2 = dot(v_q, v_q);
  // Coverage with a one-pixel soft edge (the impostor is drawn slightly larger).
  float edge = clamp((1.0 - sqrt(q2)) * max(v_radius, 0.75) + 0.5, 0.0, 1.0);
  if (edge <= 0.0) discard;
  float cos_i = sqrt(max(1.0 - min(q2, 1.0), 0.0));
  // Liquid (1.34) to gas (1.0): total reflection beyond sin = 1 / 1.34.
  float sin_i = sqrt(min(q2, 1.0));
  float F = sin_i >= 0.746 ? 1.0 : mix(0.02, 1.0, pow(sin_i / 0.746, 6.0));
  vec3 reflected = u_env_light * F;
  float glint = exp(-dot(v_q - u_glint_dir, v_q - u_glint_dir) * 40.0);
  vec3 c = v_tint * (reflected + u_glint * glint) * u_exposure;
  c = u_tonemap == 1 ? aces_filmic(c) : c;
  float alpha = edge * clamp(max(F, glint) * 0.85 + 0.08 * cos_i, 0.0, 1.0);
  frag_color = vec4(linear_to_srgb(c) * alpha, alpha);
}
