// Fresnel and GGX. Twin of core/reference/optics.cpp (fresnel_dielectric, ggx terms).
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

// GGX specular lobe for a directional light: D * V * NoL (Fresnel applied by the caller).
float ggx_specular(vec3 n, vec3 v, vec3 l, float roughness) {
  float NoL = dot(n, l), NoV = dot(n, v);
  if (NoL <= 0.0 || NoV <= 0.0) return 0.0;
  vec3 h = normalize(v + l);
  float NoH = max(dot(n, h), 0.0);
  float a = roughness * roughness, a2 = a * a;
  float d = NoH * NoH * (a2 - 1.0) + 1.0;
  float D = a2 / (PI * d * d);
  float gv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
  float gl = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
  return D * 0.5 / max(gv + gl, 1e-6) * NoL;
}

#endif  // LIB_OPTICS_FRESNEL_GLSL
