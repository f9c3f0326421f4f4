// An equirectangular HDR environment (env.mode image) as light by direction: the image's
// chain of ever blurrier levels in u_env_image's mipmaps, turned by env.rotation. Twin of
// Studio::sky with its image (core/environment/studio.cpp) and EnvironmentMap::radiance
// (core/environment/environment_map.cpp): the same mapping, the same filtering.
#ifndef LIB_ENVIRONMENT_IMAGE_GLSL
#define LIB_ENVIRONMENT_IMAGE_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"

// Where world direction d (unit) lands in the image, u across and v down: Studio::
// image_direction, then equirect_uv (the image's centre seen looking along -z).
vec2 env_image_uv(vec3 d) {
  vec3 e = vec3(frame.env_rotation.x * d.x - frame.env_rotation.y * d.z, d.y,
                frame.env_rotation.y * d.x + frame.env_rotation.x * d.z);
  float across = abs(e.x) + abs(e.z) > 0.0 ? atan(e.x, -e.z) : 0.0;  // (atan(0, 0) is undefined)
  return vec2(0.5 + across * (0.5 / PI), acos(clamp(e.y, -1.0, 1.0)) / PI);
}

// The level whose texels span `angle` radians, at least env.blur's (environment_lod).
float env_image_lod(float angle) {
  float lod = angle > 0.0 ? log2(angle * frame.env_texels_per_radian) : 0.0;
  return clamp(max(lod, frame.env_blur_lod), 0.0, frame.env_max_lod);
}

// Radiance from direction d seen through a surface of GGX roughness `roughness` (0: as the
// eye sees the image directly): the level as wide as the reflected lobe, 2 alpha.
vec3 env_image(vec3 d, float roughness) {
  float a = roughness * roughness;
  return frame.env_intensity * textureLod(u_env_image, env_image_uv(d), env_image_lod(2.0 * a)).rgb;
}

#endif  // LIB_ENVIRONMENT_IMAGE_GLSL
