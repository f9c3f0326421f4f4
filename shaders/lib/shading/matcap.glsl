// The MatCap tier's glass (docs/MATCAP.md, after the low-cost glass of seed 002): a lit
// sphere (u_matcap, core/environment/matcap) looked up by the view-space normal for the
// reflection, again with an offset for the refraction, a refraction mask from the glass's
// thickness along the view and a Fresnel edge, frost as a blurrier level, a tint.
#ifndef LIB_SHADING_MATCAP_GLSL
#define LIB_SHADING_MATCAP_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"

// Where view-space normal n looks in the MatCap (t up: GL's rows run bottom-up). Twin of
// matcap_uv (core/environment/matcap.cpp), which has v down.
vec2 matcap_uv(vec3 n) { return 0.5 + 0.5 * n.xy; }

// A world direction in the picture's camera (x right, y up, z towards the eye): the
// MatCap's light turns with the view, as a MatCap's does.
vec3 view_space(vec3 n) { return vec3(dot(n, frame.cam_right), dot(n, frame.cam_up), -dot(n, frame.cam_forward)); }

vec3 matcap_at(vec2 uv, float lod) { return textureLod(u_matcap, uv, min(lod, frame.matcap_max_lod)).rgb; }

// The mean of the MatCap: the surroundings' mean radiance seen from the scene (its last
// level), the even light of the drink's haze.
vec3 matcap_mean() { return textureLod(u_matcap, vec2(0.5), frame.matcap_max_lod).rgb; }

// The seed's two masks of where the glass hides what lies behind it: the solid glass
// (thickness along the view, m: lib/vessel/thickness.glsl) and the Fresnel edge.
float thickness_mask(float thickness) {
  float x = thickness / frame.matcap_thickness;
  return 1.0 - exp(-x * x);
}
float fresnel_edge(float nv) {
  return 1.0 - clamp((nv - frame.matcap_edge_range) * frame.matcap_edge_intensity, 0.0, 1.0);
}

#endif  // LIB_SHADING_MATCAP_GLSL
