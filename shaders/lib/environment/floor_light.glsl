// The floor's direct light: the light map core traces from the actual glasses
// (core/environment/floor_light: shadows of stem, foot and bowl, tinted by the drink, and
// the caustics) inside its rect, blended over its last texels into the unoccluded light
// outside it. The texture holds the map over the unoccluded irradiance per channel, so the
// light here is the unoccluded light times that factor.
#ifndef LIB_ENVIRONMENT_FLOOR_LIGHT_GLSL
#define LIB_ENVIRONMENT_FLOOR_LIGHT_GLSL
#include "generated/frame.glsl"
#include "lib/environment/backdrop_light.glsl"

// The map's factor at p: 1 outside the rect, the texture inside, blended over the outer
// 4 texels (the map's kernel reaches 3 texels in; beyond the rect nothing is traced).
vec3 floor_light_factor(vec3 p) {
  if (frame.floor_light_on == 0) return vec3(1.0);
  vec2 uv = (p.xz - frame.floor_light_origin) / frame.floor_light_size;
  vec2 from_edge = min(uv, 1.0 - uv) * vec2(textureSize(u_floor_light, 0));
  float inside = smoothstep(0.5, 4.0, min(from_edge.x, from_edge.y));
  if (inside <= 0.0) return vec3(1.0);
  return mix(vec3(1.0), textureLod(u_floor_light, uv, 0.0).rgb, inside);  // one level: no derivatives needed
}

// The backdrop's direct light at p (normal n): the rig's unoccluded light
// (backdrop_light.glsl), on the floor (where the map lies) with the glasses' shadows and
// caustics.
vec3 floor_direct_light(vec3 p, vec3 n) {
  vec3 e = backdrop_light(p, n);
  return n.y > 0.999 ? e * floor_light_factor(p) : e;
}

#endif  // LIB_ENVIRONMENT_FLOOR_LIGHT_GLSL
