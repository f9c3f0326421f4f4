// The screen (core/environment/screen.hpp): the moving picture in u_screen, seen on a card
// in the scene (the SCREEN 1 variant: lights_seen puts it in front of what lies behind it)
// or as the whole background (SCREEN 2: sky_seen looks it up, the AR view; the rig's
// lights then light the drinks and show in reflections off the glass and the liquid from
// outside, but are not seen behind or through the glass: look_out (passes/path.frag.glsl) and
// lights_and_sky() see the picture alone). Frames without a screen compile none of this. Twins: ScreenFrame::intersect, card_radiance,
// background_uv and background_radiance in core/environment/screen.cpp.
#ifndef LIB_ENVIRONMENT_SCREEN_GLSL
#define LIB_ENVIRONMENT_SCREEN_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/output/tonemap.glsl"

#ifdef SCREEN

// How much of [-1, 1] at coordinate s is seen with its edge spread over +-w (lights.glsl's
// soft_box: the card's edges blur as a softbox's do).
float screen_soft_box(float s, float w) { return 1.0 - smoothstep(1.0 - w, 1.0 + w, abs(s)); }

// The picture at uv through a footprint `texels` wide (its mip level), in linear light
// (the sRGB texture decodes, then filters).
vec3 screen_picture(vec2 uv, float texels) {
  float lod = clamp(log2(max(texels, 1e-6)), 0.0, frame.screen_max_lod);
  return textureLod(u_screen, uv, lod).rgb;
}

#if SCREEN == 1
// The card's front along o + t d (d unit) before t_max: rgb its radiance, a the part of the
// pixel's ray it covers, its edges spread by the GGX roughness of the surface that sent
// the ray (as lights_seen spreads a softbox's); t where (INF: not seen). Seen from the
// front only. The picture is read at the level as wide as the ray's footprint: a pixel's
// cone from the eye, or the rough surface's lobe. Twin of ScreenFrame::intersect and
// card_radiance.
vec4 screen_card_seen(vec3 o, vec3 d, float roughness, float t_max, out float t) {
  t = INF;
  float denom = dot(d, frame.screen_normal);
  if (denom >= 0.0) return vec4(0.0);  // parallel, or its back
  float ti = dot(frame.screen_center - o, frame.screen_normal) / denom;
  if (ti <= 0.0 || ti >= t_max) return vec4(0.0);
  vec3 hu = frame.screen_half_u.xyz, hv = frame.screen_half_v.xyz;
  vec3 q = o + ti * d - frame.screen_center;
  float su = dot(q, hu) / dot(hu, hu), sv = dot(q, hv) / dot(hv, hv);
  float a = roughness * roughness;
  float spread = max(0.0015, 2.0 * a);
  float cover = screen_soft_box(su, spread * ti / length(hu)) * screen_soft_box(sv, spread * ti / length(hv));
  if (cover <= 0.0) return vec4(0.0);
  t = ti;
  float pixel = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y;  // radians a pixel spans
  float footprint = max(pixel, 2.0 * a) * (length(o - frame.cam_eye) + ti);
  vec3 c = screen_picture(vec2(0.5 + 0.5 * su, 0.5 - 0.5 * sv), footprint * frame.screen_half_u.w);
  return vec4(frame.screen_brightness * c, cover);
}

// `seen` (a light's front at t, as lights_seen returns it) with the card in front of it or
// behind it, as one layer: rgb its radiance where it covers, a how much it covers; t the
// nearer of the two.
vec4 screen_with_light(vec4 seen, vec3 o, vec3 d, float roughness, float t_max, inout float t) {
  float ts;
  vec4 card = screen_card_seen(o, d, roughness, t_max, ts);
  if (card.a <= 0.0) return seen;
  vec4 front = ts < t ? card : seen, back = ts < t ? seen : card;
  float a = 1.0 - (1.0 - front.a) * (1.0 - back.a);
  vec3 light = front.rgb * front.a + (1.0 - front.a) * back.a * back.rgb;
  t = min(t, ts);
  return vec4(a > 0.0 ? light / a : vec3(0.0), a);
}
#endif  // SCREEN == 1

#if SCREEN == 2
// One mirror back into [-1, 1] beyond an edge, then clamped (core: fold).
vec2 screen_fold(vec2 s) {
  s = mix(s, sign(s) * (2.0 - abs(s)), step(1.0, abs(s)));
  return clamp(s, -1.0, 1.0);
}

// Where direction d (unit, world) looks in the picture: across the camera's picture plane
// (a direction behind it mirrored to the front), the picture covering the view. Twin of
// ScreenFrame::background_uv.
vec2 screen_background_uv(vec3 d) {
  float z = max(abs(dot(d, frame.cam_forward)), 0.05);
  vec2 s = vec2(dot(d, frame.cam_right) / (z * frame.cam_aspect * frame.cam_tan_half_vfov),
                dot(d, frame.cam_up) / (z * frame.cam_tan_half_vfov)) + frame.cam_shift;
  s = screen_fold(s) * frame.screen_cover;
  return vec2(0.5 + 0.5 * s.x, 0.5 - 0.5 * s.y);
}

// The background seen along d through a surface of GGX roughness `roughness`: the picture
// with the output transform undone (seen directly it comes out as it went in), blurred
// over the pixel's or the rough lobe's width. Twin of ScreenFrame::background_radiance.
vec3 screen_background(vec3 d, float roughness) {
  float pixel = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y;
  vec3 c = screen_picture(screen_background_uv(d), max(pixel, 2.0 * roughness * roughness) * frame.screen_half_v.w);
  if (frame.tonemap == 1) c = aces_filmic_inverse(c);
  return frame.screen_brightness * c / frame.exposure;
}
#endif  // SCREEN == 2

#endif  // SCREEN
#endif  // LIB_ENVIRONMENT_SCREEN_GLSL
