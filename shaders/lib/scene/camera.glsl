// Camera rays. Twin of core/scene/camera.cpp (camera_ray): pixel centres counted from
// the top-left; the lens may be shifted (cam_shift).
#ifndef LIB_SCENE_CAMERA_GLSL
#define LIB_SCENE_CAMERA_GLSL
#include "generated/frame.glsl"

// The PANORAMA variant (env.reflections) draws a glass's surroundings from cam_eye, its
// middle, into an equirectangular panorama: every pixel a direction of the sphere.
#ifndef PANORAMA
#define PANORAMA 0
#endif
#if PANORAMA
#include "lib/environment/reflections.glsl"
vec3 camera_dir(vec2 frag) { return panorama_dir(frag * frame.viewport_inv); }
#else
vec3 camera_dir(vec2 frag) {
  vec2 px = vec2(frag.x, frame.viewport_size.y - frag.y);
  float x = (2.0 * px.x * frame.viewport_inv.x - 1.0 - frame.cam_shift.x) * frame.cam_aspect * frame.cam_tan_half_vfov;
  float y = (1.0 - 2.0 * px.y * frame.viewport_inv.y - frame.cam_shift.y) * frame.cam_tan_half_vfov;
  return normalize(frame.cam_forward + x * frame.cam_right + y * frame.cam_up);
}
#endif

#endif  // LIB_SCENE_CAMERA_GLSL
