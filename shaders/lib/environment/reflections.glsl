// Scene reflections (env.reflections): each glass's surroundings rendered from its middle
// without it (the PANORAMA variant of the path pass, gpu/reflection_panoramas) into a
// layer of u_reflections, equirectangular. A reflection off a glass's outside looks there
// instead of at the backdrop, the lights and the sky alone, so glasses mirror each other
// (and a screen card, droplets and clouds); what it sees is taken as far away (no
// parallax: a neighbour 10 cm off is mirrored as seen from the glass's middle).
// Twin of panorama_st / panorama_dir in gpu/reflection_panoramas.cpp (the tests' look-ups).
#ifndef LIB_ENVIRONMENT_REFLECTIONS_GLSL
#define LIB_ENVIRONMENT_REFLECTIONS_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"

// Where world direction d (unit) lies in a panorama: s across (1/2 + atan(x, -z) / 2 pi,
// an environment image's mapping, unturned), t up the rows as drawn (0 straight down).
vec2 panorama_st(vec3 d) {
  float across = abs(d.x) + abs(d.z) > 0.0 ? atan(d.x, -d.z) : 0.0;  // (atan(0, 0) is undefined)
  return vec2(0.5 + across * (0.5 / PI), 1.0 - acos(clamp(d.y, -1.0, 1.0)) / PI);
}

// Its inverse: the direction a panorama's point (s, t) looks along.
vec3 panorama_dir(vec2 st) {
  float phi = (st.x - 0.5) * 2.0 * PI, theta = (1.0 - st.y) * PI;  // theta from straight up
  float r = sin(theta);
  return vec3(r * sin(phi), cos(theta), -r * cos(phi));
}

#if defined(REFLECTIONS) && REFLECTIONS
// What glass `obj`'s panorama shows along d through a surface of GGX roughness
// `roughness`: the level as wide as the reflected lobe, 2 alpha (as env_image).
vec3 reflections_seen(int obj, vec3 d, float roughness) {
  float a = roughness * roughness;
  float lod = a > 0.0 ? log2(2.0 * a * frame.reflections_texels_per_radian) : 0.0;
  return textureLod(u_reflections, vec3(panorama_st(d), float(obj)), clamp(lod, 0.0, frame.reflections_max_lod)).rgb;
}
#endif

#endif  // LIB_ENVIRONMENT_REFLECTIONS_GLSL
