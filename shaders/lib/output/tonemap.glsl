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

#endif  // LIB_OUTPUT_TONEMAP_GLSL
