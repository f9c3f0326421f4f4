#version 300 es
// A gas bubble in the drink: light reflects off its surface (liquid to gas), totally
// near the outline, so it shows a bright rim around a clear middle, plus the key light's
// glint. Premultiplied alpha over the picture of pass 1.
#include "generated/frame.glsl"
#include "lib/output/tonemap.glsl"

in vec2 v_q;
flat in vec3 v_tint;
flat in float v_radius;
flat in float v_liquid_ior;

out vec4 frag_color;

void main() {
  float q2 = dot(v_q, v_q);
  // Coverage with a one-pixel soft edge (the impostor is drawn slightly larger).
  float edge = clamp((1.0 - sqrt(q2)) * max(v_radius, 0.75) + 0.5, 0.0, 1.0);
  if (edge <= 0.0) discard;
  float cos_i = sqrt(max(1.0 - min(q2, 1.0), 0.0));
  // Liquid to gas: total reflection beyond sin = 1 / n_liquid.
  float sin_i = sqrt(min(q2, 1.0)), sin_c = 1.0 / v_liquid_ior;
  float F = sin_i >= sin_c ? 1.0 : mix(0.02, 1.0, pow(sin_i / sin_c, 6.0));
  // What the bubble mirrors (core/environment: the lights, the backdrop, the sky), and
  // the glint of the light giving the most light where its direction falls on the impostor.
  vec3 reflected = frame.bubble_env * F;
  vec2 glint_at = 0.45 * vec2(dot(frame.glint_dir, frame.cam_right), -dot(frame.glint_dir, frame.cam_up));
  float glint = exp(-dot(v_q - glint_at, v_q - glint_at) * 40.0);
  vec3 c = v_tint * (reflected + frame.glint * 0.8 * glint) * frame.exposure;
  // A bubble under the impostor's least radius (0.75 px, bubbles.vert.glsl: so that it
  // still covers a sample) covers only its own area of that disc: drawn whole, a bubble a
  // fifth of a pixel across was a pixel-sized dot of what it mirrors, which reads as a
  // dark speck over a lit drink (the flight's weizen). So tiny bubbles fade out.
  float area = min(v_radius * v_radius / (0.75 * 0.75), 1.0);
  float alpha = area * edge * clamp(max(F, glint) * 0.85 + 0.08 * cos_i, 0.0, 1.0);
  frag_color = vec4(output_transform(c, frame.tonemap, frame.output_linear != 0) * alpha, alpha);
}
