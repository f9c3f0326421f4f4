// Fresnel. Twin of core/reference/optics.cpp (fresnel_dielectric).
#ifndef LIB_OPTICS_FRESNEL_GLSL
#define LIB_OPTICS_FRESNEL_GLSL
#include "lib/common/math.glsl"

// Unpolarised dielectric Fresnel; 1 under total internal reflection.
float fresnel_dielectric(float cos_i, float n1, float n2) {
  cos_i = clamp(cos_i, 0.0, 1.0);
  float eta = n1 / n2;
  float sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return 1.0;
  float cos_t = sqrt(1.0 - sin2_t);
  float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  float rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
  return 0.5 * (rs * rs + rp * rp);
}

#endif  // LIB_OPTICS_FRESNEL_GLSL
