#version 300 es
// One triangle that covers the viewport (no vertex buffers needed); or, drawn instanced
// with a_rect from a buffer, pixel rectangles of the target (x, y, width, height in
// pixels, GL's rows from the bottom): the same pass over a few pixels only, adaptive
// supersampling's (core/output/refine). The same program either way, so that the
// rectangles cost no second compile of the pass.
precision highp float;

layout(location = 0) in vec4 a_rect;  // without a buffer: (0, 0, 0, 1), the whole viewport
uniform vec2 u_target_inv;            // with rectangles: 1 / the target's width and height

void main() {
  if (a_rect.z > 0.0) {
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    gl_Position = vec4((a_rect.xy + corner * a_rect.zw) * u_target_inv * 2.0 - 1.0, 0.0, 1.0);
  } else {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
  }
}
