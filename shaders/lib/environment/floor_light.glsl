// The floor's light through the light map core traces (core/environment/floor_light:
// shadows of stem, foot and bowl, tinted by the drink, and the caustics) inside its rect,
// blended over its last texels into the unoccluded light outside it. The texture holds,
// per channel, the map over the unoccluded irradiance: the rig's lights in the first half
// of its rows, the surroundings' (the sky and the lit paper, for the paper's bounce: the
// glasses' soft shadow round the feet, FloorLightMap::surround_factor) in the second. The
// light here is the unoccluded light times that factor.
#ifndef LIB_ENVIRONMENT_FLOOR_LIGHT_GLSL
#define LIB_ENVIRONMENT_FLOOR_LIGHT_GLSL
#include "generated/frame.glsl"
#include "lib/environment/backdrop_light.glsl"

// The map's two factors at p, the rig's and the surroundings': 1 outside the rect, the
// texture inside (each half filtered within itself), blended over the outer 4 texels (the
// map's kernel reaches 3 texels in; beyond the rect nothing is traced).
void floor_light_factors(vec3 p, out vec3 lights, out vec3 around) {
  lights = around = vec3(1.0);
  if (frame.floor_light_on == 0) return;
  vec2 uv = (p.xz - frame.floor_light_origin) / frame.floor_light_size;
  ivec2 texels = textureSize(u_floor_light, 0);  // (rows: twice the map's)
  vec2 from_edge = min(uv, 1.0 - uv) * vec2(texels.x, texels.y / 2);
  float inside = smoothstep(0.5, 4.0, min(from_edge.x, from_edge.y));
  if (inside <= 0.0) return;
  float row = 1.0 / float(texels.y);
  float v = clamp(0.5 * uv.y, 0.5 * row, 0.5 - 0.5 * row);
  // (one level: no derivatives needed)
  lights = mix(vec3(1.0), textureLod(u_floor_light, vec2(uv.x, v), 0.0).rgb, inside);
  around = mix(vec3(1.0), textureLod(u_floor_light, vec2(uv.x, v + 0.5), 0.0).rgb, inside);
}

// Under an image, the factor of its whole light at p: the map's two factors are each a
// share of that light (the photons' of its brightest patches, the gathered of the rest:
// FloorLightMap::surround_factor), their shadows of different light, so they add.
vec3 floor_image_factor(vec3 p) {
  vec3 lights, around;
  floor_light_factors(p, lights, around);
  return max(lights + around - 1.0, 0.0);
}

// The light the backdrop receives at p (normal n) from the rig (backdrop_light.glsl) and
// from its surroundings (`around`: the paper's own bounce), on the floor (where the map
// lies) each through its factor: the glasses' shadows and caustics of the lights, and
// their soft shadow of the surroundings round the feet.
vec3 floor_light(vec3 p, vec3 n, vec3 direct, vec3 around) {
  if (n.y > 0.999) {
    vec3 lights_factor, around_factor;
    floor_light_factors(p, lights_factor, around_factor);
    direct *= lights_factor;
    around *= around_factor;
  }
  return direct + around;
}

#endif  // LIB_ENVIRONMENT_FLOOR_LIGHT_GLSL
