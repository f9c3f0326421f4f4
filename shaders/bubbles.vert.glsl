#version 300 es
// Pass 2: rising bubbles as instanced sphere impostors. Each instance is a bubble
// already placed where the glass and the liquid show it (core/bubble_view): centre and
// radius in pixels, and the tint of the path to it.
precision highp float;

layout(location = 0) in vec4 a_sprite;  // centre x, y (pixels from the top-left), radius (pixels), 0
layout(location = 1) in vec4 a_tint;    // rgb transmittance to the bubble, 0

uniform vec2 u_viewport;  // width, height in pixels

out vec2 v_q;             // position on the impostor, unit circle = the bubble's outline
flat out vec3 v_tint;
flat out float v_radius;

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
  // At least a pixel and a half across, so small bubbles still cover samples.
  float r = max(a_sprite.z, 0.75);
  vec2 px = a_sprite.xy + corner * (r + 1.0);
  v_q = corner * (r + 1.0) / r;
  v_tint = a_tint.rgb;
  v_radius = a_sprite.z;
  gl_Position = vec4(px.x / u_viewport.x * 2.0 - 1.0, 1.0 - px.y / u_viewport.y * 2.0, 0.0, 1.0);
}
