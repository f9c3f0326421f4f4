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
#ifndef REFLECTIONS
#define REFLECTIONS 0
#endif
#include "lib/environment/reflections.glsl"
#ifndef DECALS
#define DECALS 0
#endif
#if DECALS
#include "lib/vessel/decal.glsl"
#endif
#ifndef CONDENSATION
#define CONDENSATION 0
#endif
#if CONDENSATION
#include "lib/vessel/condensation.glsl"
#endif

out vec4 frag_color;

// The one path of this pixel.
struct Path {
  vec3 o, d;      // where it is and where it goes (world)
  int medium;     // MEDIUM_AIR, MEDIUM_GLASS, MEDIUM_LIQUID, MEDIUM_DROPLET or MEDIUM_CLOUD
  int obj;        // the object whose glass or drink it is in; -1 in the air; -2 - c in cloud c
  vec3 radiance;  // gathered so far
  vec3 thr;       // throughput: what still reaches the eye of what lies ahead
  int drink;      // the object whose drink it was last in (-1: none yet)
  vec3 left;      // how its light is shared between that drink's colour bands (drink_onward)
};

float max3(vec3 v) { return max(v.r, max(v.g, v.b)); }

// A path through a condensation bead is bent every way by the lens: it is followed for
// BEAD_EVENTS more interfaces, then looks out from where it is (what it would see is a
// blur of the drink; following it to the end made a cold pint cost twice the dry one on
// llvmpipe, where a SIMD group runs as long as its longest path).
const int BEAD_EVENTS = 4;
int g_bead_events = 1 << 20;

// ---- stage: the surroundings ----

// A ray that looks out at the surroundings past every object, and what reaches the eye
// of what it sees. Each iteration of the path loop makes at most one (the reflection at
// an interface, or the path itself where it leaves) and looks it up in one place:
// llvmpipe runs every copy of inlined code for every pixel of a SIMD group, taken or not.
struct Look {
  vec3 o, d;       // from where, which way (world)
  vec3 w;          // what reaches the eye of what it sees
  float rough;     // the GGX roughness of the surface that sent it (0: none)
  bool backdrop;   // the backdrop can be seen (not by a path that finds no way out of a
                   // glass or drink while it still has events: the lights and the sky)
  bool mirrored;   // a reflection off a glass: its backdrop as a glass mirrors it
  int obj;         // the glass it reflects off, for its panorama (env.reflections); -1: none
  bool camera;     // the camera's own ray, before any surface: it passes the lights kept
                   // out of the shot (lights_seen)
};

Look no_look() { return Look(vec3(0.0), vec3(0.0, 1.0, 0.0), vec3(0.0), 0.0, false, false, -1, false); }

// Where the path's own ray meets the backdrop, shaded once after the path loop (its light
// map, the glasses' shadows, the contact: heavier than a reflection's backdrop, and one
// per path): the point, its normal, the ray's direction and what reaches the eye of it.
struct LitBackdrop {
  vec3 p, n, d, w;
};

// What the look sees, from its own point: the nearest of a light's front and the
// backdrop, else the sky (an environment image at the level of the surface's lobe): added
// to the path's radiance. A mirrored backdrop is shaded here (each light taken as a
// point); the path's own goes to `lit`. With the screen as the background (the AR view)
// the picture is all that lies behind and through the glass; the rig's lights show only
// in reflections off the glass and the liquid from outside (lib/environment/screen.glsl).
void look_out(Look l, inout vec3 radiance, inout LitBackdrop lit) {
#if REFLECTIONS
  // A glass with a panorama of its surroundings (env.reflections) mirrors that: the other
  // objects too (lib/environment/reflections.glsl).
  if (l.mirrored && l.obj >= 0 && l.obj < frame.reflections_count) {
    radiance += l.w * reflections_seen(l.obj, l.d, l.rough);
    return;
  }
#endif
  BackdropSurface b = backdrop_surface();
  b.present = b.present && l.backdrop;
  float tb, tl;
  vec3 nb;
  bool on_backdrop = intersect(b, l.o, l.d, 0.0, tb, nb);
  // A path out through a foot's or a base's underside starts on the floor, a rounding
  // above or below it: it meets the floor there (as the reference's floor_under_foot).
  if (b.present && !on_backdrop && l.d.y < 0.0 && abs(l.o.y) < 1e-5 && (b.plane || l.o.z >= b.z_curve)) {
    on_backdrop = true;
    tb = 0.0;
    nb = vec3(0.0, 1.0, 0.0);
  }
  vec4 light = lights_seen(l.o, l.d, l.rough, tb, l.camera, tl);
#if defined(SCREEN) && SCREEN == 2
  on_backdrop = false;  // (no floor in front of the picture)
  if (!l.mirrored) light = vec4(0.0);
#endif
  vec3 p = l.o + tb * l.d;
  vec3 beyond = on_backdrop ? shade_backdrop_mirrored(p, nb, l.d, tb, true) : sky_seen(l.d, l.rough);
  if (on_backdrop && !l.mirrored) {
    lit = LitBackdrop(p, nb, l.d, l.w * (1.0 - light.a));
    beyond = vec3(0.0);
  }
  radiance += l.w * (light.rgb * light.a + beyond * (1.0 - light.a));
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

// The light gathered at the surface h (the path's segment up to it) and the path onwards
// (the lacing on the wall is done before: lace_wall); the reflection's look at the
// surroundings (absorbed on its way out when the path is inside) goes to `look`. v: the
// records of h's object (inside a glass or drink that is also the path's).
void shade_interface(inout Path path, Hit h, Vessel v, out Look look) {
  look = no_look();
  vec3 p = path.o + h.t * path.d;
  ObjectGlass g = glass_of(v.row);
  // The segment up to the surface, inside the path's medium.
  if (path.medium == MEDIUM_LIQUID) {
    if (path.drink != path.obj) {  // a drink it has not crossed yet: its colour from the start
      path.drink = path.obj;
      path.left = v.body.absorption_share;
    }
    vec3 colour = drink_onward(v.body, path.left, h.t);
    path.radiance += path.thr * haze_inscatter(v, colour, h.t, path.o, path.d);
    path.thr *= colour * exp(-v.liquid.haze * h.t);
  } else {
    path.thr *= medium_transmittance(v, g, path.medium, vec3(0.5), h.t);
  }
  vec3 pl = to_local_point(v, p);
  bool below = below_liquid(v, pl);
#if CONDENSATION
  // Condensation on the outer wall (lib/vessel/condensation.glsl): a bead is a water lens
  // the path crosses instead of the bare wall (below); the fog between the beads veils
  // it. (In a loop that a SIMD group leaves at once when none of its pixels meets an
  // outer wall at this event: llvmpipe runs straight-line code for every pixel.)
  BeadSample bead = BeadSample(false, vec3(0.0), 1.0);
  vec3 bead_wall = vec3(0.0);  // the wall's outward normal under a bead (world)
  for (int k = 0; k < 1; ++k) {
    if (h.m != M_GLASS_OUTER) break;
    vec3 nl = to_local_dir(v, h.n);
    nl = dot(nl.xz, pl.xz) < 0.0 ? -nl : nl;
    bead_wall = to_world_dir(v, nl);
    bead = condensation_bead(v, pl, nl);
    float fog = condensation_fog(v, pl) * bead.clear;
    if (fog <= 0.0) break;
    vec4 veil = fog_veil(v, to_world_dir(v, nl), fog);
    path.radiance += path.thr * veil.rgb;
    path.thr *= veil.a;
  }
#endif
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
  Crossing c = crossing_at(path, h, v, g, below);
#if CONDENSATION
  BeadCrossing bx;
  for (int k = 0; k < 1; ++k) {
    if (!bead.found) break;
    bool from_air = path.medium == MEDIUM_AIR;
    bx = bead_crossing(path.d, to_world_dir(v, bead.n), c.n, from_air ? c.n2 : c.n1, from_air);
    c.n = bx.n;
    c.F = bx.F;
  }
#endif
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
    // The reflection sees the surroundings: a light, the backdrop or the sky, from the
    // air or from inside a glass, where it is absorbed on its way out and leaves bent
    // (looked up from where it reflects: the backdrop is far beside the way out's few
    // centimetres; with the sky alone a thick base's inner reflections, which lead down
    // to the floor, came out dark: docs/REFERENCE.md).
    vec3 r = reflect(path.d, c.n);
    // Towards a bead's rim its cap is steep, and what it reflects goes down into the wall
    // beside it, into the glass and the drink the path itself goes on to see: that share
    // stays with the path. (Looked up as the surroundings it showed the studio's white at
    // every rim: a speckle of white pixels over a beaded glass that the reference, which
    // follows the reflection into the wall, does not have; docs/CONDENSATION.md.)
    bool into_wall = false;
#if CONDENSATION
    into_wall = bead.found && path.medium == MEDIUM_AIR && dot(r, bead_wall) < 0.0;
#endif
    if (path.medium == MEDIUM_AIR) {
      vec3 out_w = vec3(1.0);
      if (h.m == M_LIQUID_SURFACE) {
        vec3 back;
        out_w = surface_reflection_out(v, g, pl, to_local_dir(v, r), back);
        path.radiance += path.thr * c.F * back * surround_mean();
      }
      if (!into_wall) look = Look(p, r, path.thr * c.F * out_w, rough, true, true, h.obj, false);
    } else {
      vec3 out_dir;
      float turned;  // what the way out turns back in sees the sky's mean
      vec3 tr = reflected_light(v, g, h.m, path.medium, below, path.drink == h.obj ? path.left : v.body.absorption_share, pl,
                                to_local_dir(v, r), to_local_dir(v, c.n), out_dir, turned);
      look = Look(p, to_world_dir(v, out_dir), path.thr * c.F * tr * (1.0 - turned), rough, true, true, -1, false);
      path.radiance += path.thr * c.F * tr * turned * sky_mean();
#if DECALS
      if (decal.metal) {  // the metal's reflection takes the same way out
        decal_look *= tr;
        decal.look = to_world_dir(v, out_dir);
      }
#endif
    }
    if (!into_wall) path.thr *= 1.0 - c.F;
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
  go_on(path, h, c, p);
#if CONDENSATION
  for (int k = 0; k < 1; ++k) {  // through the bead: its two faces bend the path (bead_crossing)
    if (!bead.found || c.F >= 1.0) break;
    g_bead_events = min(g_bead_events, BEAD_EVENTS);
    path.d = bx.onward;
    path.medium = bx.leaves ? MEDIUM_AIR : MEDIUM_GLASS;
    path.obj = bx.leaves ? -1 : h.obj;
  }
#endif
}

#if FOAM_HEAD
// The lacing on the inner wall where the path meets it at h.t (above the drink, within
// or above a head), and the bubbles the head presses on it, seen at the pixel's width
// there: light added, and the path dimmed (before the interface is shaded; as its
// segment's absorption, which it commutes with).
void lace_wall(inout Path path, float t, int obj) {
  Vessel v = load_vessel(obj);
  ObjectFoam f = fetch_object_foam(v.row);
  vec3 p = path.o + t * path.d, pl = to_local_point(v, p);
  float cover = lacing_cover(v, f, pl);
  vec3 reach = path.thr * medium_transmittance(v, glass_of(v.row), path.medium,
                                                path.drink == obj ? path.left : v.body.absorption_share, t);
  path.radiance += reach * cover * lacing_light(v, f, to_local_dir(v, path.d));
  float footprint = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y * length(p - frame.cam_eye);
  path.thr *= (1.0 - cover) * head_wall_cells(v, f, pl, footprint);
}
#endif

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
// part's look at the surroundings goes to `look` (from inside absorbed along one more
// chord of the same length: the internal reflection is not followed); the refracted part
// goes on, into the next object or the air.
void shade_droplet(inout Path path, Hit h, out Look look) {
  look = no_look();
  vec3 p = path.o + h.t * path.d;
  bool inside = path.medium == MEDIUM_DROPLET;
  vec3 chord = exp(-frame.droplet_absorption * h.t);
  if (inside) path.thr *= chord;
  Crossing c = droplet_crossing(path, h);
  float rough = frame.droplet_roughness;
  if (c.F < 1.0) {
    vec3 r = reflect(path.d, c.n);
    look = Look(p, r, path.thr * c.F * (inside ? chord : vec3(1.0)), rough, true, true, -1, false);
    path.thr *= 1.0 - c.F;
  }
  go_on(path, h, c, p);
  path.obj = -1;
}
#endif

#if CLOUDS
// ---- a point cloud's surface (lib/pointcloud): hot glass or a drink against the air ----

// The crossing of cloud h's surface (h.obj = -2 - the cloud).
Crossing cloud_crossing(Path path, Hit h) {
  int k = -2 - h.obj;
  float ior = frame.cloud_lo[k].w;
  Crossing c;
  bool inside = path.medium == MEDIUM_CLOUD;
  c.next = inside ? MEDIUM_AIR : MEDIUM_CLOUD;
  c.n = dot(h.n, path.d) < 0.0 ? h.n : -h.n;
  c.n1 = inside ? ior : 1.0;
  c.n2 = inside ? 1.0 : ior;
  c.F = fresnel_dielectric(-dot(c.n, path.d), c.n1, c.n2);
  return c;
}

// As shade_droplet for a blob of a point cloud: the body absorbs (Beer-Lambert) and, hot,
// glows. Along a chord inside, hot glass emits the blackbody's light of its temperature
// and absorbs as much (Kirchhoff: emissivity 1 - exp(-kappa chord)), its visible
// extinction kappa growing from 0 at 700 K to 1 / glow_depth at 1100 K and above: a thick
// gob glows deep and bright, its thin edges less, and little is seen through it; cooled,
// it is clear glass. A point's colour tints the light that crosses the surface there
// (coloured glass, a tinted drink).
void shade_cloud(inout Path path, Hit h, out Look look) {
  look = no_look();
  int k = -2 - h.obj;
  vec3 p = path.o + h.t * path.d;
  bool inside = path.medium == MEDIUM_CLOUD;
  vec3 chord = exp(-frame.cloud_absorption[k].rgb * h.t);
  float kelvin = g_cloud_attrs.x > 0.0 ? g_cloud_attrs.x : frame.cloud_absorption[k].w;
  vec4 glow = frame.cloud_glow[k];
  if (inside) {
    float hot = exp(-glow.y * clamp((kelvin - 700.0) / 400.0, 0.0, 1.0) * h.t);
    if (glow.x > 0.0) path.radiance += path.thr * (1.0 - hot) * glow.x * blackbody_luminance(kelvin);
    path.thr *= chord * hot;
  }
  Crossing c = cloud_crossing(path, h);
  float rough = frame.cloud_hi[k].w;
  if (c.F < 1.0) {
    vec3 r = reflect(path.d, c.n);
    look = Look(p, r, path.thr * c.F * (inside ? chord : vec3(1.0)), rough, true, true, -1, false);
    path.thr *= 1.0 - c.F;
    if (max3(g_cloud_attrs.yzw) > 0.0) path.thr *= g_cloud_attrs.yzw;
  }
  go_on(path, h, c, p);
}
#endif

// ---- stage: trace the path ----

// Follows the path from the camera through at most frame.max_events interfaces; whatever
// throughput is left then sees the surroundings. see_through: achromatic transmission
// to the background (the alpha of transparent pictures). The path loop: each iteration
// tests one object (lib/scene/trace.glsl search_step) and, once a segment's nearest
// surface is known, shades the interface and looks up its reflection; the iteration
// where the path leaves (past every object, or out of events) looks up what its ray
// sees. The backdrop is not a surface the search stops at: everything stands in front of
// it (the space in front of the sweep is convex), so a path that meets no object sees it.
//
// The heads' work (a stretch of air through a head, the lacing where the path meets the
// inner wall above a drink) is rare along a path but heavy, and llvmpipe would pay for
// it in every iteration of the path loop, taken or not. So the path loop stops where a
// path needs it, and the stage loop around it does it and resumes the path (searching
// its segment again): its code runs once per stage, a few times per pixel at most.
vec3 trace_path(vec3 eye, vec3 dir, out float see_through) {
  Path path = Path(eye, dir, MEDIUM_AIR, -1, vec3(0.0), vec3(1.0), -1, vec3(0.5));
  see_through = 0.0;
  LitBackdrop lit = LitBackdrop(vec3(0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, -1.0), vec3(0.0));
  // (Read before the loops: inside them each read of the Frame block costs llvmpipe a load.)
  int max_events = frame.max_events;
  bool transparent = frame.transparent != 0;
  int events = 0, steps = 0, max_steps = max_events * (OBJECT_COUNT + 1) + 1;  // iterations of the path loop
  float tmin = 0.0;
  bool foam_done = false, lace_done = false;  // this segment's heads marched, this hit's wall laced
  // A path held in a glass or a drink past its last event (below): what it still carries,
  // and whether it runs down a vessel's wall (the vessel's index; -1: not so).
  vec3 trapped = vec3(0.0), trapped_at = vec3(0.0), trapped_dir = vec3(0.0);
  int trapped_wall = -1;
  // A path stops at most once per segment for the heads and once per event for the
  // lacing (a path held in a glass wall by total internal reflection above the drink
  // meets the inner wall again and again); the last stage stops for nothing.
  int max_stages = 2 * max_events + 3;
  for (int stage = 0; stage < max_stages; ++stage) {
    bool stops = stage < max_stages - 1;
    bool stop_foam = false, stop_lace = false;
    float stop_t = 0.0;
    int stop_obj = 0;
    Search s = start_search(tmin);
    while (steps < max_steps) {
      ++steps;
      Vessel v;
      Hit h = no_hit();
      // Out of events (or of iterations) the path looks out from where it is. Compiled
      // for the background alone (gpu/renderer: where no object can show), it has none:
      // what its ray sees, none of the objects' code.
#ifdef BACKGROUND_ONLY
      bool in_events = false;
#else
      bool in_events = events < max_events && steps < max_steps && g_bead_events > 0;
#endif
      if (in_events && !search_step(s, path.o, path.d, path.medium, path.obj, false, v)) continue;
      if (in_events) h = s.best;
#if FOAM_HEAD
      // Heads and their big bubbles sit in the air above the drinks; lacing on the wall.
      stop_foam = stops && in_events && !foam_done && path.medium == MEDIUM_AIR &&
                  meets_head(path.o, path.d, h.m == M_NONE ? 100.0 : h.t);
      stop_lace = stops && !lace_done && h.m == M_GLASS_INNER && !below_liquid(v, to_local_point(v, path.o + h.t * path.d));
      if (stop_foam || stop_lace) {
        stop_t = h.m == M_NONE ? 100.0 : h.t;
        stop_obj = h.obj;
        --steps;  // (the segment's search runs again after the stop)
        break;
      }
#endif
      Look look;
      bool leaves = h.m == M_NONE;
      if (leaves) {
        // (A panorama's rays are not the camera's: the lights show in what glasses mirror.)
        look = Look(path.o, path.d, path.thr, 0.0, path.medium == MEDIUM_AIR, false, -1, events == 0 && PANORAMA == 0);
        if (transparent) {
          // The page behind a cutout (core/output/cutout): alpha lets its achromatic part
          // through, the studio behind the objects lights the coloured rest. (Reflections
          // off the objects mirror the studio as in the opaque picture.)
          float m = min(path.thr.r, min(path.thr.g, path.thr.b));
          see_through = m;
          path.radiance += (path.thr - vec3(m)) * cutout_light();
          look.w = vec3(0.0);
        } else if (!in_events && path.medium != MEDIUM_AIR) {
          // Out of events, a path in glass or a drink (held in a rim or a wall by total
          // internal reflection, a light guide that leaves it far from here) takes the
          // mean radiance of the surroundings (the sky and the lit backdrop), through the
          // drink where it runs down a wall round the drink (the light a wall guides up to
          // a rim comes from the base and the drink above it; not a stem's or a foot's,
          // below the cavity); after the loop, once. Along its ray
          // the sky alone gave black rims (the studio's sky behind the sweep is dark), the
          // backdrop there rims brighter than the reference's (docs/REFERENCE.md). (Not a
          // condensation bead's path: its events ran out in the bead.)
          trapped = path.thr;
          trapped_at = path.o;
          trapped_dir = path.d;
          trapped_wall = path.medium == MEDIUM_GLASS && g_bead_events > 0 ? path.obj : -1;
          look.w = vec3(0.0);
        }
      } else {
#if DROPLETS
        if (h.m == M_DROPLET) shade_droplet(path, h, look);
        else
#endif
#if CLOUDS
        if (h.m == M_CLOUD) shade_cloud(path, h, look);
        else
#endif
        shade_interface(path, h, v, look);
      }
      look_out(look, path.radiance, lit);
      foam_done = lace_done = false;
      if (leaves || max3(path.thr) < 1e-3) break;
      ++events;
      --g_bead_events;
      s = start_search(2e-6);
      tmin = 2e-6;
    }
#if FOAM_HEAD
    if (!stop_foam && !stop_lace) break;
    if (stop_foam) {
      foam_along(path.o, path.d, stop_t, path.radiance, path.thr);
      foam_done = true;
    }
    if (stop_lace && max3(path.thr) >= 1e-3) {
      lace_wall(path, stop_t, stop_obj);
      lace_done = true;
    }
    if (max3(path.thr) < 1e-3) break;
#else
    break;
#endif
  }
  for (int k = 0; k < 1; ++k) {  // (a SIMD group with no such path leaves at once)
    if (max3(trapped) <= 0.0) break;
    vec3 drink = vec3(1.0);
    if (trapped_wall >= 0) {
      Vessel tv = load_vessel(trapped_wall);
      bool down_a_wall = to_local_dir(tv, trapped_dir).y < 0.0 && to_local_point(tv, trapped_at).y > tv.shape.base;
      if (down_a_wall) drink = mean_chord_transmittance(tv);
    }
    path.radiance += trapped * surround_mean() * drink;
  }
  // The backdrop the path's ray met, lit.
  if (max3(lit.w) > 0.0) path.radiance += lit.w * shade_backdrop(lit.p, lit.n, lit.d, length(lit.p - frame.cam_eye));
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
    if (search_step(s, o, d, medium, obj, true, v)) break;
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
  Path path = Path(eye, dir, MEDIUM_AIR, -1, vec3(0.0), vec3(1.0), -1, vec3(0.5));
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
#if CLOUDS
    if (h.m == M_CLOUD) {
      go_on(path, h, cloud_crossing(path, h), p);
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

#if CONDENSATION
// The first surface's condensation: (the bead's cap normal, local; 0 off a bead; the fog's
// cover times what the beads leave of it) on a condensed glass's outer wall, else
// (0, 0, 0, -1). Compared with core's bead_at and fog_at by tests/gpu/test_condensation.
vec4 debug_condensation(vec3 eye, vec3 dir) {
  Vessel v;
  Hit h = nearest_surface(eye, dir, MEDIUM_AIR, -1, 0.0, v);
  if (h.m != M_GLASS_OUTER || fetch_object_condensation(v.row).condensation_band < 0) return vec4(0.0, 0.0, 0.0, -1.0);
  vec3 pl = to_local_point(v, eye + h.t * dir), nl = to_local_dir(v, h.n);
  BeadSample b = condensation_bead(v, pl, dot(nl.xz, pl.xz) < 0.0 ? -nl : nl);
  return vec4(b.found ? b.n : vec3(0.0), condensation_fog(v, pl) * b.clear);
}
#endif

// Pixel (x, y) evaluates the medium rule for material x, medium y mod 3 and below
// (y >= 3): (medium beyond, 0, 0, 1). Compared with core's medium_across by tests/gpu.
vec4 debug_medium_rule() {
  int m = int(gl_FragCoord.x), y = int(gl_FragCoord.y);
  return vec4(float(medium_across(m, y % 3, y >= 3)), 0.0, 0.0, 1.0);
}
// The haze's diffusion field of object 0 over a grid of radii (core haze_field's twin;
// tests/gpu/test_furnace.cpp compares them).
vec4 debug_haze_field() {
  float R = 0.01 * (floor(gl_FragCoord.y) + 1.0);
  float r = floor(gl_FragCoord.x) / max(frame.viewport_size.x - 1.0, 1.0) * R;
  return vec4(haze_field(fetch_object_haze(0), r, R), R);
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
  // (Uniforms read in the path loop are held from here: on llvmpipe each read of a uniform
  // block's member is a load and a broadcast to every lane.)
  init_objects();
  init_lights();
  init_studio();
  init_backdrop();
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
  if (view == VIEW_HAZE_FIELD) {
    frag_color = debug_haze_field();
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
#if CONDENSATION
  if (view == VIEW_CONDENSATION) {
    frag_color = debug_condensation(frame.cam_eye, dir);
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
#if PANORAMA
  frag_color = vec4(max(radiance, vec3(0.0)), 1.0);  // linear radiance, into u_reflections
  return;
#endif
  vec3 c = radiance * frame.exposure;
  float alpha = frame.transparent != 0 ? clamp(1.0 - see_through, 0.0, 1.0) : 1.0;
  frag_color = vec4(output_transform(c, frame.tonemap, frame.output_linear != 0), alpha);
}
