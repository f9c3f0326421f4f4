#version 300 es
// Pass 1: one path per pixel through every object of the scene. The path runs in the
// world through air, glass and liquid; its medium is (medium, object). At each interface
// Fresnel splits the light: the reflected part looks up the surroundings, the refracted
// part is followed (total internal reflection follows the reflection), so light leaves
// one glass and enters the next: a glass seen through another is right by construction.
// Stages: trace_path (find surfaces, march foam heads), shade_interface (one interface),
// surroundings (what a ray sees past everything), the debug outputs, and the output.
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/scene/camera.glsl"
#include "lib/scene/objects.glsl"
#include "lib/scene/trace.glsl"
#include "lib/vessel/media.glsl"
#include "lib/optics/fresnel.glsl"
#include "lib/liquid/surface.glsl"
#include "lib/liquid/body.glsl"
#include "lib/foam/head.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/lights.glsl"
#include "lib/environment/backdrop.glsl"
#include "lib/environment/floor.glsl"
#include "lib/output/tonemap.glsl"
#ifndef DECALS
#define DECALS 0
#endif
#if DECALS
#include "lib/vessel/decal.glsl"
#endif

out vec4 frag_color;

// The one path of this pixel.
struct Path {
  vec3 o, d;      // where it is and where it goes (world)
  int medium;     // MEDIUM_AIR, MEDIUM_GLASS or MEDIUM_LIQUID
  int obj;        // the object whose glass or drink it is in; -1 in the air
  vec3 radiance;  // gathered so far
  vec3 thr;       // throughput: what still reaches the eye of what lies ahead
};

float max3(vec3 v) { return max(v.r, max(v.g, v.b)); }

// ---- stage: the surroundings ----

// What a ray sees past every object, from its own point: the nearest of a light's front
// and the backdrop, else the sky, from the air; from inside a glass or a drink (a path
// that ran out of events) the lights and the sky.
vec3 surroundings(vec3 o, vec3 d, int medium) {
  return medium == MEDIUM_AIR ? background(o, d, 0.0) : lights_and_sky(o, d, 0.0);
}

// ---- the geometry of an interface (shared by the picture and the path-event view) ----

// Crossing the surface h at p: the normal facing the path, the media's indices, the
// Fresnel reflectance (1 under total internal reflection) and the medium beyond.
struct Crossing {
  vec3 n;
  float n1, n2, F;
  int next;
};

// v, g: the records of h's object.
Crossing crossing_at(Path path, Hit h, Vessel v, ObjectGlass g, bool below) {
  Crossing c;
  c.next = medium_across(h.m, path.medium, below);
  c.n = dot(h.n, path.d) < 0.0 ? h.n : -h.n;
  c.n1 = medium_ior(v, g, path.medium);
  c.n2 = medium_ior(v, g, c.next);
  c.F = fresnel_dielectric(-dot(c.n, path.d), c.n1, c.n2);
  return c;
}

// The path goes on from p: refracted into the next medium, or reflected under total
// internal reflection.
void go_on(inout Path path, Hit h, Crossing c, vec3 p) {
  if (c.F >= 1.0) {
    path.d = reflect(path.d, c.n);
  } else {
    path.d = refract(path.d, c.n, c.n1 / c.n2);
    path.medium = c.next;
    path.obj = c.next == MEDIUM_AIR ? -1 : h.obj;
  }
  path.o = p;
}

// ---- stage: shade an interface ----

// The light gathered at the surface h (the path's segment up to it, the reflected
// surroundings, absorbed on their way out when the path is inside) and the path onwards. v: the records of h's
// object (inside a glass or drink that is also the path's). False: the path ended (it
// reached the floor).
bool shade_interface(inout Path path, Hit h, Vessel v) {
  vec3 p = path.o + h.t * path.d;
  ObjectGlass g = glass_of(v.row);
  // The segment up to the surface, inside the path's medium.
  if (path.medium == MEDIUM_LIQUID) path.radiance += path.thr * haze_inscatter(v, h.t);
  path.thr *= medium_transmittance(v, g, path.medium, h.t);
  // The floor is shaded at most once per interface, from one place (its shading loops
  // over every glass): where the path ends on it, or where the reflection meets it.
  vec3 floor_at = p, floor_n = h.n, floor_d = path.d, floor_weight = vec3(0.0);
  float floor_dist = length(p - frame.cam_eye);
  bool on_floor = h.m == M_FLOOR;
  Crossing c;
  if (on_floor) {
    // A light's front between the path's point and the backdrop (the backlight behind
    // the glasses) is seen in front of it.
    float tl;
    vec4 light = lights_seen(path.o, path.d, 0.0, h.t, tl);
    path.radiance += path.thr * light.a * light.rgb;
    floor_weight = path.thr * (1.0 - light.a);
    path.thr = vec3(0.0);
  } else {
    vec3 pl = to_local_point(v, p);
    bool below = below_liquid(v, pl);
#if DECALS
    // A decal on the wall (lib/vessel/decal.glsl): from inside the glass or the drink its
    // ink, frost or metal meets the path first (no total internal reflection off it); from
    // the air it lies under the surface's gloss (after the reflection, below).
    DecalEffect decal = decal_effect(v, h, path.medium, p, pl, path.d, below);
    vec3 decal_look = vec3(0.0);  // what the decal's own look-up of the surroundings weighs
    if (path.medium != MEDIUM_AIR) {
      path.radiance += path.thr * decal.light;
      decal_look = path.thr * (decal.behind + decal.mirror);
      path.thr *= decal.pass;
    }
#endif
#if FOAM_HEAD
    if (h.m == M_GLASS_INNER && !below) {  // lacing on the wall
      ObjectFoam f = fetch_object_foam(v.row);
      float cover = lacing_cover(v, f, pl);
      path.radiance += path.thr * cover * lacing_light(v, f, to_local_dir(v, path.d));
      // and the bubbles the head presses on it, seen at the pixel's width there
      float footprint = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y * length(p - frame.cam_eye);
      path.thr *= (1.0 - cover) * head_wall_cells(v, f, pl, footprint);
    }
#endif
    c = crossing_at(path, h, v, g, below);
#if DECALS
    if (path.medium == MEDIUM_AIR) decal_look = path.thr * (1.0 - c.F) * (decal.behind + decal.mirror);
    if (decal.metal) decal.look = reflect(path.d, c.n);  // from inside: where it leaves the glass (below)
    if (decal.metal && c.F >= 1.0) {  // total internal reflection: the path goes where the metal sends it
      path.thr += decal_look;
      decal_look = vec3(0.0);
    }
#endif
    // The lights are seen in the reflection (blurred by the surface's roughness) or
    // through the refraction, along the ray from its point: no highlight on top.
    float rough = h.m == M_LIQUID_SURFACE || h.m == M_CLIP_LIQUID ? v.liquid.roughness : g.glass_roughness;
    if (c.F < 1.0) {
      vec3 mirrored = path.thr * c.F;  // what the reflection carries
      // The reflection sees the surroundings: a light, the backdrop or the sky from the
      // air; the lights and the sky from inside a glass.
      if (frame.transparent == 0 || path.medium != MEDIUM_AIR) {
        vec3 r = reflect(path.d, c.n);
        if (path.medium == MEDIUM_AIR) {
          float tb, tl;
          vec3 nb;
          bool on_backdrop = intersect(backdrop_surface(), p, r, 0.0, tb, nb);
          vec4 light = lights_seen(p, r, rough, tb, tl);
          path.radiance += mirrored * light.a * light.rgb;
          if (on_backdrop) {  // shaded once, below
            floor_at = p + tb * r;
            floor_n = nb;
            floor_d = r;
            floor_dist = tb;
            floor_weight = mirrored * (1.0 - light.a);
          } else {
            path.radiance += mirrored * (1.0 - light.a) * sky_seen(r, rough);
          }
        } else {
          // Inside a glass or drink the reflection is absorbed on its way out.
          vec3 out_dir;
          vec3 tr = reflected_light(v, g, h.m, path.medium, below, pl, to_local_dir(v, r), to_local_dir(v, c.n), out_dir);
          path.radiance += mirrored * tr * lights_and_sky(p, to_world_dir(v, out_dir), rough);
#if DECALS
          if (decal.metal) {  // the metal's reflection takes the same way out
            decal_look *= tr;
            decal.look = to_world_dir(v, out_dir);
          }
#endif
        }
      }
      path.thr *= 1.0 - c.F;
#if DECALS
      if (path.medium == MEDIUM_AIR) {
        path.radiance += path.thr * decal.light;
        path.thr *= decal.pass;
      }
#endif
    }
#if DECALS
    path.radiance += decal_look * decal_surroundings(p, decal.look, decal.spread, decal.rough, max3(decal_look) > 0.0 ? decal.taps : 0);
#endif
  }
  if (max3(floor_weight) > 0.0) path.radiance += floor_weight * shade_floor(floor_at, floor_n, floor_d, floor_dist, on_floor);
  if (on_floor) return false;
  go_on(path, h, c, p);
  return true;
}

#if DROPLETS
// ---- a droplet's surface (lib/droplets): water against the air ----

// The crossing of a droplet's surface: the normal facing the path, the indices, Fresnel.
Crossing droplet_crossing(Path path, Hit h) {
  Crossing c;
  bool inside = path.medium == MEDIUM_DROPLET;
  c.next = inside ? MEDIUM_AIR : MEDIUM_DROPLET;
  c.n = dot(h.n, path.d) < 0.0 ? h.n : -h.n;
  c.n1 = inside ? frame.droplet_ior : 1.0;
  c.n2 = inside ? 1.0 : frame.droplet_ior;
  c.F = fresnel_dielectric(-dot(c.n, path.d), c.n1, c.n2);
  return c;
}

// As shade_interface for a droplet: the water inside absorbs (Beer-Lambert); the reflected
// part sees the surroundings over the surface's roughness (from inside: the lights and
// the sky, absorbed along one more chord of the same length: the internal reflection is
// not followed); the refracted part goes on, into the next object or the air.
void shade_droplet(inout Path path, Hit h) {
  vec3 p = path.o + h.t * path.d;
  bool inside = path.medium == MEDIUM_DROPLET;
  vec3 chord = exp(-frame.droplet_absorption * h.t);
  if (inside) path.thr *= chord;
  Crossing c = droplet_crossing(path, h);
  float rough = frame.droplet_roughness;
  if (c.F < 1.0) {
    vec3 mirrored = path.thr * c.F;
    vec3 r = reflect(path.d, c.n);
    if (inside) {
      path.radiance += mirrored * chord * lights_and_sky(p, r, rough);
    } else if (frame.transparent == 0) {
      float tb, tl;
      vec3 nb;
      bool on_backdrop = intersect(backdrop_surface(), p, r, 0.0, tb, nb);
      vec4 light = lights_seen(p, r, rough, tb, tl);
      path.radiance += mirrored * light.a * light.rgb;
      if (on_backdrop) path.radiance += mirrored * (1.0 - light.a) * shade_floor(p + tb * r, nb, r, tb, false);
      else path.radiance += mirrored * (1.0 - light.a) * sky_seen(r, rough);
    }
    path.thr *= 1.0 - c.F;
  }
  go_on(path, h, c, p);
  path.obj = -1;
}
#endif

// ---- stage: trace the path ----

// Follows the path from the camera through at most frame.max_events interfaces; whatever
// throughput is left then sees the surroundings. see_through: achromatic transmission
// to the background (the alpha of transparent pictures). One loop: each iteration tests
// one object (lib/scene/trace.glsl search_step) and, once a segment's nearest surface is
// known, marches the heads along it and shades the interface.
vec3 trace_path(vec3 eye, vec3 dir, out float see_through) {
  Path path = Path(eye, dir, MEDIUM_AIR, -1, vec3(0.0), vec3(1.0));
  see_through = 0.0;
  bool escaped = false;
  int events = 0;
  Search s = start_search(0.0);
  int steps = frame.max_events * (OBJECT_COUNT + 1);
  for (int it = 0; it < steps; ++it) {
    Vessel v;
    if (!search_step(s, path.o, path.d, path.medium, path.obj, v)) continue;
    Hit h = s.best;
#if FOAM_HEAD
    if (path.medium == MEDIUM_AIR) {  // heads and their big bubbles sit in the air above the drinks
      foam_along(path.o, path.d, h.m == M_NONE ? 100.0 : h.t, path.radiance, path.thr);
      if (max3(path.thr) < 1e-3) break;
    }
#endif
    if (h.m == M_NONE) {
      escaped = true;
      break;
    }
#if DROPLETS
    if (h.m == M_DROPLET) {
      shade_droplet(path, h);
      if (max3(path.thr) < 1e-3) break;
    } else
#endif
    if (!shade_interface(path, h, v) || max3(path.thr) < 1e-3) break;
    if (++events == frame.max_events) break;
    s = start_search(2e-6);
  }
  if (escaped || max3(path.thr) >= 1e-3) {
    if (frame.transparent != 0) {
      float m = min(path.thr.r, min(path.thr.g, path.thr.b));
      see_through = m;
      path.radiance += (path.thr - vec3(m)) * sky_light();
    } else {
      path.radiance += path.thr * surroundings(path.o, path.d, path.medium);
    }
  }
  return path.radiance;
}

// ---- stage: debug outputs ----
// Compiled only into the debug variant (DEBUG_VIEWS 1): llvmpipe pays for code behind a
// uniform branch it does not take (this costs the picture a third of its time).
#ifndef DEBUG_VIEWS
#define DEBUG_VIEWS 0
#endif
#if DEBUG_VIEWS

// The nearest surface along a world ray from a path in `medium` (of object `obj`), its
// object's records in v: the search run to its end.
Hit nearest_surface(vec3 o, vec3 d, int medium, int obj, float tmin, out Vessel v) {
  Search s = start_search(tmin);
  for (int it = 0; it <= OBJECT_COUNT; ++it)
    if (search_step(s, o, d, medium, obj, v)) break;
  return s.best;
}

// Depth / material: (t, material, object, 1) of the first surface; normal: (world
// normal, material). Compared with core/reference first_hit by tests/gpu/test_probes.
vec4 debug_first_surface(vec3 eye, vec3 dir, int view) {
  Vessel v;
  Hit h = nearest_surface(eye, dir, MEDIUM_AIR, -1, 0.0, v);
  if (view == VIEW_NORMAL) return vec4(h.n, float(h.m));
  return vec4(h.m != M_NONE ? h.t : 0.0, float(h.m), float(h.obj), 1.0);
}

// Event n (0-based) of the refracted path, as the picture follows it: (distance from
// the previous event, material, object, medium before it); material M_NONE past the
// path's end. Compared with a double-precision CPU trace (tests/gpu).
vec4 debug_path_event(vec3 eye, vec3 dir, int n) {
  Path path = Path(eye, dir, MEDIUM_AIR, -1, vec3(0.0), vec3(1.0));
  for (int e = 0; e < frame.max_events; ++e) {
    Vessel v;
    Hit h = nearest_surface(path.o, path.d, path.medium, path.obj, e == 0 ? 0.0 : 2e-6, v);
    if (e == n) return vec4(h.m != M_NONE ? h.t : 0.0, float(h.m), float(h.obj), float(path.medium));
    if (h.m == M_NONE || h.m == M_FLOOR) break;
    vec3 p = path.o + h.t * path.d;
#if DROPLETS
    if (h.m == M_DROPLET) {
      go_on(path, h, droplet_crossing(path, h), p);
      path.obj = -1;
      continue;
    }
#endif
    go_on(path, h, crossing_at(path, h, v, glass_of(v.row), below_liquid(v, to_local_point(v, p))), p);
  }
  return vec4(0.0, float(M_NONE), -1.0, float(path.medium));
}

#if DECALS
// The first surface's decal: (u, v, layer, material); layer -1 where it shows none.
// Compared with core/reference decal_hit by tests/gpu/test_decals.
vec4 debug_decal(vec3 eye, vec3 dir) {
  Vessel v;
  Hit h = nearest_surface(eye, dir, MEDIUM_AIR, -1, 0.0, v);
  int layer = h.m == M_GLASS_INNER ? 1 : 0;
  vec2 uv;
  if ((h.m == M_GLASS_OUTER || h.m == M_GLASS_INNER) && decal_uv(v, layer, to_local_point(v, eye + h.t * dir), uv))
    return vec4(uv, float(layer), float(h.m));
  return vec4(0.0, 0.0, -1.0, float(h.m));
}
#endif

// Pixel (x, y) evaluates the medium rule for material x, medium y mod 3 and below
// (y >= 3): (medium beyond, 0, 0, 1). Compared with core's medium_across by tests/gpu.
vec4 debug_medium_rule() {
  int m = int(gl_FragCoord.x), y = int(gl_FragCoord.y);
  return vec4(float(medium_across(m, y % 3, y >= 3)), 0.0, 0.0, 1.0);
}
// The studio alone along the camera ray, for the twins' tests (tests/gpu/test_lights.cpp
// against core's AreaLight and BackdropSurface). LightHit: (t of the nearest light
// front, 0 for none; its index, -1; t of the backdrop, 0 for none; its albedo's green).
// Backdrop: (t, normal). LightIrradiance: irradiance_factor of lights 0..3 at the
// backdrop point for its normal. BackdropLight: (x, s, the rig's light green, 1).
vec4 debug_studio(vec3 eye, vec3 dir, int view) {
  BackdropSurface b = backdrop_surface();
  float tb;
  vec3 nb;
  bool on_backdrop = intersect(b, eye, dir, 0.0, tb, nb);
  if (view == VIEW_BACKDROP) return on_backdrop ? vec4(tb, nb) : vec4(0.0);
  if (view == VIEW_BACKDROP_LIGHT) {
    vec3 p = eye + tb * dir;
    return on_backdrop ? vec4(backdrop_coords(b, p), backdrop_light(p, nb).g, 1.0) : vec4(0.0);
  }
  if (view == VIEW_LIGHT_IRRADIANCE) {
    vec4 f = vec4(0.0);
    for (int i = 0; i < MAX_LIGHTS; ++i)
      if (on_backdrop && i < frame.light_count) f[i] = irradiance_factor(area_light(i), eye + tb * dir, nb);
    return f;
  }
  float tl = INF;
  int nearest = -1;
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    float t;
    if (i < frame.light_count && intersect(area_light(i), eye, dir, 0.0, t) && t < tl) {
      tl = t;
      nearest = i;
    }
  }
  return vec4(nearest >= 0 ? tl : 0.0, float(nearest), on_backdrop ? tb : 0.0,
              on_backdrop ? albedo(b, eye + tb * dir).g : 0.0);
}
#endif  // DEBUG_VIEWS

// ---- output ----

void main() {
  init_objects();
  vec3 dir = camera_dir(gl_FragCoord.xy);
#if DEBUG_VIEWS
  int view = frame.debug_view;
  if (view == VIEW_MEDIUM_RULE) {
    frag_color = debug_medium_rule();
    return;
  }
  if (view == VIEW_DEPTH || view == VIEW_NORMAL || view == VIEW_MATERIAL) {
    frag_color = debug_first_surface(frame.cam_eye, dir, view);
    return;
  }
  if (view == VIEW_LIGHT_HIT || view == VIEW_BACKDROP || view == VIEW_LIGHT_IRRADIANCE || view == VIEW_BACKDROP_LIGHT) {
    frag_color = debug_studio(frame.cam_eye, dir, view);
    return;
  }
  if (view == VIEW_PATH_EVENT) {
    frag_color = debug_path_event(frame.cam_eye, dir, frame.debug_event);
    return;
  }
#if DECALS
  if (view == VIEW_DECAL) {
    frag_color = debug_decal(frame.cam_eye, dir);
    return;
  }
#endif
#endif
  float see_through;
  vec3 radiance = trace_path(frame.cam_eye, dir, see_through);
#if DEBUG_VIEWS
  if (view == VIEW_COST) {  // the work this pixel's path needed
    frag_color = vec4(float(g_cost), float(g_foam_steps), float(g_bounds_entered), 1.0);
    return;
  }
#endif
  vec3 c = radiance * frame.exposure;
  c = frame.tonemap == 1 ? aces_filmic(c) : c;
  float alpha = frame.transparent != 0 ? clamp(1.0 - see_through, 0.0, 1.0) : 1.0;
  frag_color = vec4(linear_to_srgb(c), alpha);
}
