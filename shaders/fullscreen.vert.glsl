#version 300 es
// One triangle that covers the viewport; no vertex buffers needed. The liquid's plane
// offset is the same for every pixel, so it is looked up here, once per vertex.
#include "common.glsl"
#include "fill_table.glsl"

flat out float v_liquid_offset;

void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
  v_liquid_offset = liquid_offset();
}
