#version 300 es
// Pass 1: the glass of drink. One path per pixel through air, glass and liquid;
// Fresnel splits each interface: the reflected part samples the surroundings, the
// refracted part is followed (total internal reflection follows the reflection).
#include "common.glsl"
#include "optics.glsl"
#include "vessel.glsl"
#include "environment.glsl"
#include "liquid.glsl"
#include "foam.glsl"
#include "tonemap.glsl"

out vec4 frag_color;

float medium_ior(int medium) {
  return medium == GLASS ? u_glass.x : (medium == LIQUID ? u_liquid.x : 1.0);
}

bool below_liquid(vec3 p) {
  return u_liquid.w > 0.5 && liquid_level(p) < 0.0;
}

// The medium on the far side of a surface, seen from `medium`.
int other_side(Hit h, int medium, vec3 p) {
  if (h.m == M_LIQUID_SURFACE) return medium == LIQUID ? AIR : LIQUID;
  if (h.m == M_CLIP_GLASS) return medium == AIR ? GLASS : AIR;
  if (h.m == M_CLIP_LIQUID) return medium == AIR ? LIQUID : AIR;
  if (medium != GLASS) return GLASS;
  if (h.m == M_GLASS_INNER || h.m == M_CAVITY_FLOOR) return below_liquid(p) ? LIQUID : AIR;
  return AIR;
}

float surface_roughness(Hit h) { return h.m == M_LIQUID_SURFACE || h.m == M_CLIP_LIQUID ? u_liquid.y : u_glass.y; }

void main() {
  // The path is followed in the glass's frame; the surroundings are looked up in the world.
  vec3 o = to_local_point(u_cam_eye.xyz);
  vec3 d = to_local_dir(camera_dir(gl_FragCoord.xy));
  init_liquid();
  int debug_view = int(u_output.w + 0.5);
  if (debug_view == 1 || debug_view == 2) {
    Hit h = scene_hit(o, d, AIR, 0.0);
    bool hit = h.m != M_NONE;
    frag_color = debug_view == 2 ? vec4(to_world_dir(h.n), float(h.m)) : vec4(hit ? h.t : 0.0, float(h.m), 0.0, 1.0);
    return;
  }

  bool transparent = u_output.z > 0.5;
  vec3 radiance = vec3(0.0);
  vec3 thr = vec3(1.0);
  float see_through = 0.0;  // achromatic transmission to the background (alpha)
  vec3 l = to_local_dir(normalize(u_light_dir.xyz));
  int medium = AIR;
  bool escaped = false;
  for (int e = 0; e < u_limits.x; ++e) {
    Hit h = scene_hit(o, d, medium, e == 0 ? 0.0 : 2e-6);
#if FOAM_HEAD
    if (medium == AIR) {  // the head and its big bubbles sit in the air above the liquid
      float t0 = 0.0, t1 = h.m == M_NONE ? 100.0 : h.t;
      if (foam_interval(o, d, t0, t1)) {
        bubble_caps(o, d, t0, t1, l, radiance, thr);
        march_foam(o, d, t0, t1, l, radiance, thr);
        if (max(thr.r, max(thr.g, thr.b)) < 1e-3) break;
      }
    }
#endif
    if (h.m == M_NONE) {
      escaped = true;
      break;
    }
    vec3 p = o + h.t * d;
    if (medium == LIQUID) radiance += thr * haze_inscatter(h.t);
    thr *= medium_transmittance(medium, h.t);
    if (h.m == M_FLOOR) {
      radiance += thr * shade_floor(p, length(to_world_point(p) - u_cam_eye.xyz));
      thr = vec3(0.0);
      break;
    }
#if FOAM_HEAD
    if (h.m == M_GLASS_INNER && !below_liquid(p)) {  // lacing on the wall
      float cover = lacing_cover(p);
      radiance += thr * cover * foam_light(d, l, 0.001, 0.0);
      thr *= 1.0 - cover;
    }
#endif
    int next = other_side(h, medium, p);
    vec3 n = dot(h.n, d) < 0.0 ? h.n : -h.n;  // facing the incoming ray
    float n1 = medium_ior(medium), n2 = medium_ior(next);
    float cos_i = -dot(n, d);
    float F = fresnel_dielectric(cos_i, n1, n2);
    vec3 refl = reflect(d, n);
    // Key light highlight (GGX), on the side the ray arrives from.
    radiance += thr * u_light_color.rgb * u_light_dir.w * F * ggx_specular(n, -d, l, surface_roughness(h));
    if (F >= 1.0) {  // total internal reflection: stay in the medium
      d = refl;
    } else {
      if (!transparent || medium != AIR)
        radiance += thr * F * (medium == AIR ? background(p, refl) : studio_sky(to_world_dir(refl)));
      thr *= 1.0 - F;
      d = refract(d, n, n1 / n2);
      medium = next;
    }
    o = p;
    if (max(thr.r, max(thr.g, thr.b)) < 1e-3) break;
  }
  if (escaped || max(thr.r, max(thr.g, thr.b)) >= 1e-3) {
    if (transparent) {
      float m = min(thr.r, min(thr.g, thr.b));
      see_through = m;
      radiance += (thr - vec3(m)) * ambient_light();
    } else {
      radiance += thr * (medium == AIR ? background(o, d) : studio_sky(to_world_dir(d)));
    }
  }

  if (debug_view == 4) {  // cost: intersection tests this pixel needed, events followed
    frag_color = vec4(float(g_cost), float(g_foam_steps), 0.0, 1.0);
    return;
  }
  vec3 c = radiance * u_output.y;
  c = u_output.x > 0.5 ? aces_filmic(c) : c;
  float alpha = transparent ? clamp(1.0 - see_through, 0.0, 1.0) : 1.0;
  frag_color = vec4(linear_to_srgb(c), alpha);
}
