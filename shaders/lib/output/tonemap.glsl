// Output transforms: linear -> (ACES filmic | clamp) -> sRGB.
#ifndef LIB_OUTPUT_TONEMAP_GLSL
#define LIB_OUTPUT_TONEMAP_GLSL
precision highp float;

vec3 aces_filmic(vec3 x) {  // Narkowicz's fit of the ACES reference rendering transform
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Its inverse on [0, 1] (twin of core/output/tonemap.hpp aces_filmic_inverse): the linear
// value aces_filmic maps to y.
vec3 aces_filmic_inverse(vec3 y) {
  y = clamp(y, 0.0, 1.0);
  vec3 a = 2.43 * y - 2.51, b = 0.59 * y - 0.03, c = 0.14 * y;
  return max((-b - sqrt(max(b * b - 4.0 * a * c, 0.0))) / (2.0 * a), 0.0);
}

vec3 linear_to_srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// A pass's output of c (linear light times the exposure): tone mapped (tonemap 1: ACES)
// and sRGB-encoded; or, with `linear`, c itself (no tone map, no clamp but to a half
// float's range): supersamples are then averaged in scene-linear light before the output
// transform, as a camera's pixel integrates light and as the reference resolves its
// paths (core/output/resolve; twin of display_code in core/output/tonemap.hpp).
vec3 output_transform(vec3 c, int tonemap, bool linear) {
  if (linear) return clamp(c, 0.0, 65504.0);
  return linear_to_srgb(tonemap == 1 ? aces_filmic(c) : c);
}

#endif  // LIB_OUTPUT_TONEMAP_GLSL
