#version 300 es
// Pass 2: rising bubbles as instanced sphere impostors. Each instance is a bubble
// already placed where the glass and the liquid show it (core/bubbles/bubble_view):
// centre and radius in pixels, the tint of the path to it, and its drink's index.
#include "generated/frame.glsl"

layout(location = 0) in vec2 a_centre;       // pixels from the top-left
layout(location = 1) in float a_radius;      // pixels
layout(location = 2) in vec3 a_tint;         // transmittance from the camera to the bubble
layout(location = 3) in float a_liquid_ior;  // the drink around the bubble

out vec2 v_q;             // position on the impostor, unit circle = the bubble's outline
flat out vec3 v_tint;
flat out float v_radius;
flat out float v_liquid_ior;

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
  // At least a pixel and a half across, so small bubbles still cover samples.
  float r = max(a_radius, 0.75);
  vec2 px = a_centre + corner * (r + 1.0);
  v_q = corner * (r + 1.0) / r;
  v_tint = a_tint;
  v_radius = a_radius;
  v_liquid_ior = a_liquid_ior;
  gl_Position = vec4(px.x / frame.viewport_size.x * 2.0 - 1.0, 1.0 - px.y / frame.viewport_size.y * 2.0, 0.0, 1.0);
}
