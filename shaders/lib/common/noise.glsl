// Cheap per-pixel randomness: a hash, value noise (the foam's micro bubbles, lacing), a
// cell hash (the bubbles on the glass) and the march jitter.
#ifndef LIB_COMMON_NOISE_GLSL
#define LIB_COMMON_NOISE_GLSL
precision highp float;

float hash13(vec3 p) {
  p = fract(p * 0.1031);
  p += dot(p, p.zyx + 31.32);
  return fract((p.x + p.y) * p.z);
}

float value_noise(vec3 x) {
  vec3 i = floor(x), f = fract(x);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(hash13(i), hash13(i + vec3(1, 0, 0)), f.x), mix(hash13(i + vec3(0, 1, 0)), hash13(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(hash13(i + vec3(0, 0, 1)), hash13(i + vec3(1, 0, 1)), f.x), mix(hash13(i + vec3(0, 1, 1)), hash13(i + vec3(1, 1, 1)), f.x), f.y),
             f.z);
}

// Two uniform numbers for an integer cell (Hoskins' integer hash): decorrelated between
// neighbours, as a Voronoi pattern's feature points need (hash13 of nearby integers is
// not: its cells line up in streaks). The picture's own (no C++ twin).
vec2 hash22_cell(ivec2 c) {
  uvec2 q = uvec2(c) * uvec2(1597334673u, 3812015801u);
  q = (q.x ^ q.y) * uvec2(1597334673u, 3812015801u);
  return vec2(q) * (1.0 / 4294967295.0);
}

// Per-pixel jitter of a march's start (interleaved gradient noise): no layered banding.
float march_jitter() { return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715)))); }

#endif  // LIB_COMMON_NOISE_GLSL
