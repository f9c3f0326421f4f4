#version 300 es
// Pass 1 of the MatCap tier (render.tier matcap, docs/MATCAP.md): the low-cost glass for
// weak devices, after seed 002. No refracted path: per pixel the nearest surface over every
// object (the same search and records as the path pass), then, straight on:
//   the reflection: the MatCap (u_matcap) at the surface's view-space normal, by Fresnel;
//   the refraction mask: the glass's thickness along the view (lib/vessel/thickness.glsl:
//     thick base, stem and rim, the wall seen edge-on) and the Fresnel edge; where it
//     holds, the MatCap looked up again, offset by the thickness (thick glass hides what is
//     behind it), tinted; frost reads blurrier levels;
//   the drink: absorption and haze over the straight line's length through the cavity
//     below the liquid's plane, the head as a layer of its colour above it;
//   decals: their image at the wall, lit cheaply;
//   condensation (CONDENSATION): the fog's veil on the outer wall, a bead a water lens;
//   droplets and point clouds (DROPLETS, CLOUDS): water and hot glass as lenses, the
//     MatCap by Fresnel and along the line bent through the blob, absorbed (and glowing)
//     over the blob's chord;
//   behind everything: the backdrop, the lights and the sky seen straight (drawn once per
//     view into u_matcap_background, MATCAP_CACHED, when float targets allow).
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/scene/camera.glsl"
#include "lib/scene/objects.glsl"
#include "lib/scene/trace.glsl"
#include "lib/vessel/thickness.glsl"
#include "lib/optics/fresnel.glsl"
#include "lib/liquid/surface.glsl"
#include "lib/liquid/body.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/lights.glsl"
#include "lib/environment/backdrop.glsl"
#include "lib/environment/floor.glsl"
#include "lib/shading/matcap.glsl"
#include "lib/output/tonemap.glsl"
#ifndef DECALS
#define DECALS 0
#endif
#if DECALS
#include "lib/vessel/decal.glsl"
#endif
#ifndef DEBUG_VIEWS
#define DEBUG_VIEWS 0
#endif
#ifndef CONDENSATION
#define CONDENSATION 0
#endif
#if CONDENSATION
#include "lib/vessel/condensation.glsl"
#endif

out vec4 frag_color;

// What the view sees past the glasses, straight: the nearest of a light's front and the
// backdrop (lit by the rig and the sky, darkened round the feet; no traced shadows), else
// the sky.
vec3 seen_straight(vec3 o, vec3 d) {
#if defined(SCREEN) && SCREEN == 2
  return sky_seen(d, 0.0);  // the AR view: the picture is what lies behind
#endif
  float tb, tl;
  vec3 nb;
  bool on_backdrop = intersect(backdrop_surface(), o, d, 0.0, tb, nb);
  vec4 light = lights_seen(o, d, 0.0, tb, true, tl);  // (the camera's view: the shot's lights kept out)
  vec3 beyond = sky_seen(d, 0.0);
  if (on_backdrop) {
    vec3 p = o + tb * d;
    beyond = shade_backdrop_mirrored(p, nb, d, tb, false) * mix(1.0, floor_contact(p), 0.8);
  }
  return light.rgb * light.a + beyond * (1.0 - light.a);
}

// The part [t0, t1] of span s where the level h0 + t dh lies in [lo, hi) (empty: t1 <= t0).
vec2 level_span(vec2 s, float h0, float dh, float lo, float hi) {
  if (abs(dh) < 1e-9) return h0 >= lo && h0 < hi ? s : vec2(0.0);
  float ta = (lo - h0) / dh, tb = (hi - h0) / dh;
  return vec2(max(s.x, min(ta, tb)), min(s.y, max(ta, tb)));
}

// The straight line p + t d (local, t >= 0) inside the cavity: the cylinder of the inner
// radius at p's height, between the cavity floor and `top` (the rim, or a head's dome
// above it).
vec2 cavity_span(Vessel v, vec3 p, vec3 d, float top) {
  float ri = inner_radius(v, clamp(p.y, v.shape.base, v.body.height));
  float t0, t1;
  if (ri <= 0.0 || !cylinder_roots(p, d, ri, t0, t1)) return vec2(0.0);
  vec2 s = vec2(max(t0, 0.0), t1);
  return level_span(s, p.y, d.y, v.shape.base, top);
}

// The drink along the straight line from p (local) in the order the view meets it: the
// head's layer (its colour, opacity by its density) and the liquid (Beer-Lambert over the
// length below the plane, haze lit as the path pass lights it). Adds to radiance, takes
// from the throughput. g: the glass's record, which the caller holds (the head's side is
// lit through its wall).
void drink_along(Vessel v, ObjectGlass g, vec3 p, vec3 d, vec3 pw, inout vec3 radiance, inout vec3 thr) {
  if (v.body.has_liquid == 0) return;
  ObjectFoam f = fetch_object_foam(v.row);
  float head_top = v.shape.has_head != 0 ? f.thickness * (1.0 + max(f.dome, 0.0)) : 0.0;  // the dome's top
  vec2 cav = cavity_span(v, p, d, max(v.body.height, v.liquid.plane_offset + head_top));
  if (cav.y <= cav.x) return;
  vec3 n = v.liquid.plane_normal;
  float h0 = dot(n, p) - v.liquid.plane_offset, dh = dot(n, d);
  vec2 liquid = level_span(cav, h0, dh, -1e3, 0.0);
  float len = max(liquid.y - liquid.x, 0.0);
  // The haze along the line: its even light (the record's, core: the surround's mean and
  // the lights, fallen off inwards) scattered towards the eye under the segment's whole
  // extinction, the drink's colour and the haze's own (as the path pass's haze_inscatter
  // with one part), and what lies behind dimmed by both.
  vec3 colour = drink_transmittance(v.body, len);
  vec3 tau = -log(max(colour, vec3(1e-30))) + v.liquid.haze * len;
  vec3 through = exp(-tau);
  vec3 haze = v.liquid.haze_light * (v.liquid.haze * len / max(tau, vec3(1e-12))) * (1.0 - through);
  vec2 head = vec2(0.0);
  float opacity = 0.0;
  vec3 head_color = vec3(0.0);
  if (v.shape.has_head != 0) {
    head = level_span(cav, h0, dh, 0.0, head_top);
    opacity = 1.0 - exp(-f.density * max(head.y - head.x, 0.0));
    // The head lit as the floor's paper is, by the rig and the surround, with the
    // reflectance of a deep head from its single-scattering albedo (the two-stream form
    // with the similarity relation: back to about foam.color, which core derived it from).
    // Its face is the one the view enters by: the top, facing up, or the side against the
    // glass, facing out from the axis there, lit through the wall's two faces (so a head
    // is round, lit on the key's side, not one flat tone).
    bool side = head.x <= cav.x + 1e-6;
    vec3 q = p + head.x * d;
    vec3 radial = vec3(q.x, 0.0, q.z);
    vec3 face = side && dot(radial, radial) > 1e-12 ? normalize(radial) : n;
    vec3 fw = to_world_dir(v, face);
    vec3 s = sqrt(max(vec3(1.0) - f.foam_color, vec3(0.0)) / max(vec3(1.0) - f.foam_color * f.anisotropy, vec3(1e-6)));
    vec3 reflectance = (vec3(1.0) - s) / (vec3(1.0) + s);
    float wall = side ? 1.0 - 2.0 * fresnel_dielectric(1.0, 1.0, g.glass_ior) : 1.0;
    head_color = reflectance * wall * (rig_irradiance_far(pw, fw, frame.light_count) + surround_irradiance(fw)) / PI;
  }
  if (opacity > 0.0 && head.x < liquid.x) {  // the head in front (seen from above or through its side)
    radiance += thr * opacity * head_color;
    thr *= 1.0 - opacity;
    radiance += thr * haze;
    thr *= through;
  } else {
    radiance += thr * haze;
    thr *= through;
    radiance += thr * opacity * head_color;
    thr *= 1.0 - opacity;
  }
}

#if DECALS
// A decal's colour at wall point pl (local) of surface m, lit cheaply: enamel by the rig
// and the sky, frost by the surroundings' blur, metal mirroring the MatCap. a: its cover.
vec3 decal_seen(Vessel v, int m, vec3 pl, vec3 pw, vec3 n, vec2 uv, float footprint, out float a) {
  DecalSample s = decal_at(v, m, pl, footprint);
  a = s.cover;
  if (a <= 0.0) return vec3(0.0);
  vec3 lit = (sky_irradiance(n) + rig_irradiance_far(pw, n, frame.light_count)) / PI;
  if (s.kind == DECAL_METALLIC) return s.tint * matcap_at(uv, 1.0 + 6.0 * s.rough);
  if (s.kind == DECAL_ETCHED) return s.tint * (0.5 * lit + 0.5 * matcap_at(uv, frame.matcap_max_lod - 2.0));
  return s.tint * lit;
}
#endif

#if DROPLETS || CLOUDS || CONDENSATION
// The surroundings along world direction w from the MatCap: the texel whose normal mirrors
// the view (-z in view space) into w, n = normalize(w - view); straight on is its rim.
vec3 matcap_along(vec3 w, float lod) {
  vec3 n = view_space(w) + vec3(0.0, 0.0, 1.0);
  float l = length(n);
  return matcap_at(matcap_uv(l > 1e-4 ? n / l : vec3(1.0, 0.0, 0.0)), lod);
}
#endif

#if DROPLETS || CLOUDS

// A droplet's or a cloud's blob (h.m M_DROPLET or M_CLOUD) as a lens: the MatCap's
// reflection by Fresnel; the line refracted in, across the blob to where it leaves (one
// march inside: the chord and the far side's normal) and out again, seeing the MatCap
// along where it goes, absorbed over the chord; hot glass glows over it (Kirchhoff, as
// the path pass: emissivity 1 - exp(-kappa chord)). Nothing behind shows through
// otherwise: thr is spent.
vec3 shade_blob(Hit h, vec3 eye, vec3 dir, inout vec3 thr) {
  vec3 p = eye + h.t * dir;
  vec3 n = dot(h.n, dir) < 0.0 ? h.n : -h.n;
  float nv = clamp(-dot(n, dir), 0.0, 1.0);
  bool cloud = h.m == M_CLOUD;
  float ior = frame.droplet_ior, lod = 0.0;
  vec3 absorption = frame.droplet_absorption, tint = vec3(1.0), glow_light = vec3(0.0);
  float kappa = 0.0;
#if CLOUDS
  int k = -2 - h.obj;
  vec4 attrs = g_cloud_attrs;
  if (cloud) {
    ior = frame.cloud_lo[k].w;
    absorption = frame.cloud_absorption[k].rgb;
    float kelvin = attrs.x > 0.0 ? attrs.x : frame.cloud_absorption[k].w;
    vec4 glow = frame.cloud_glow[k];
    kappa = glow.y * clamp((kelvin - 700.0) / 400.0, 0.0, 1.0);
    if (glow.x > 0.0) glow_light = glow.x * blackbody_luminance(kelvin);
    if (max(attrs.y, max(attrs.z, attrs.w)) > 0.0) tint = attrs.yzw;
    lod = 6.0 * frame.cloud_hi[k].w;
  }
#endif
#if DROPLETS
  if (!cloud) lod = 6.0 * frame.droplet_roughness;
#endif
  float F = fresnel_dielectric(nv, 1.0, ior);
  vec3 radiance = F * matcap_along(reflect(dir, n), lod);
  // In, across, out.
  vec3 d1 = refract(dir, n, 1.0 / ior);
  float chord = 0.0;
  vec3 n2 = n;  // (no far side found: out as through a slab)
  float t2;
  vec3 m;
  bool left = false;
#if CLOUDS
  if (cloud) left = march_cloud(cloud_ref_of(k), p, d1, 1e-5, 1.0, true, t2, m, attrs);
#endif
#if DROPLETS
  if (!cloud) {  // as through a ball of the head's radius: no second march (the tier's cost)
    m = reflect(n, d1);
    t2 = 2.0 * frame.droplet_spheres[0].w * max(-dot(n, d1), 0.0);
    left = true;
  }
#endif
  if (left) {
    chord = t2;
    n2 = dot(m, d1) > 0.0 ? -m : m;  // facing the line inside
  }
  vec3 d2 = refract(d1, n2, ior);
  if (dot(d2, d2) == 0.0) d2 = reflect(d1, n2);  // turned back inside: its mirror, not followed further
  float hot = exp(-kappa * chord);
  vec3 through = matcap_along(d2, lod + 1.0) * exp(-absorption * chord) * hot;
  radiance += thr * (1.0 - F) * tint * ((1.0 - hot) * glow_light + through);
  thr = vec3(0.0);
  return radiance;
}
#endif

// The picture of the pixel: radiance, and the throughput left to the background.
vec3 shade(vec3 eye, vec3 dir, out vec3 thr) {
  thr = vec3(1.0);
  Search s = start_search(0.0);
  Vessel v;
  for (int it = 0; it <= OBJECT_COUNT; ++it)
    if (search_step(s, eye, dir, MEDIUM_AIR, -1, true, v)) break;
  Hit h = s.best;
  vec3 radiance = vec3(0.0);
#if DROPLETS || CLOUDS
  if (h.m == M_DROPLET || h.m == M_CLOUD) return shade_blob(h, eye, dir, thr);
#endif
  if (h.obj < 0) return radiance;  // the floor and the surroundings: seen straight
  vec3 p = eye + h.t * dir;
  vec3 pl = to_local_point(v, p), dl = to_local_dir(v, dir);
  vec3 n = dot(h.n, dir) < 0.0 ? h.n : -h.n;  // facing the eye
  float nv = clamp(-dot(n, dir), 0.0, 1.0);
  vec3 nview = view_space(n);
  vec2 uv = matcap_uv(nview);
  float lod = frame.matcap_frost_lod;
  bool liquid = h.m == M_LIQUID_SURFACE || h.m == M_CLIP_LIQUID;
  ObjectGlass g = glass_of(v.row);
#if CONDENSATION
  // Beads and fog on the outer wall (lib/vessel/condensation.glsl): the fog veils the wall;
  // a bead is a water lens on it: it reflects by its cap; through its middle the drink
  // shows (the line goes on into the glass), and towards its rim, where the cap is steep,
  // the line is bent away to the surroundings' darker sides (a quarter of the MatCap along it:
  // the dark outline of a bead seen in photographs).
  if (h.m == M_GLASS_OUTER) {
    vec3 nl = to_local_dir(v, n);
    nl = dot(nl.xz, pl.xz) < 0.0 ? -nl : nl;
    BeadSample bead = condensation_bead(v, pl, nl);
    float fog = condensation_fog(v, pl) * bead.clear;
    if (fog > 0.0) {
      vec4 veil = fog_veil(v, to_world_dir(v, nl), fog);
      radiance += thr * veil.rgb;
      thr *= veil.a;
    }
    if (bead.found) {
      vec3 nb = to_world_dir(v, bead.n);
      float Fb = fresnel_dielectric(clamp(-dot(nb, dir), 0.0, 1.0), 1.0, WATER_IOR);
      radiance += thr * Fb * matcap_at(matcap_uv(view_space(nb)), 0.0);
      float bend = smoothstep(0.03, 0.35, 1.0 - dot(nb, n));
      radiance += thr * (1.0 - Fb) * bend * 0.25 * matcap_along(refract(dir, nb, 1.0 / WATER_IOR), 1.0);
      thr *= (1.0 - Fb) * (1.0 - bend);
    }
  }
#endif
  // The reflection, under Fresnel (the drink's surface with its index).
  float F = fresnel_dielectric(nv, 1.0, liquid ? v.liquid.ior : g.glass_ior);
  radiance += thr * F * matcap_at(uv, liquid ? 0.0 : lod);
  thr *= 1.0 - F;
  if (!liquid) {
    float thick = view_thickness(v, pl, dl, h.m);
#if DECALS
    float footprint = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y * h.t;
    float a;
    vec3 dc = decal_seen(v, h.m, pl, p, n, uv, footprint, a);
    radiance += thr * a * dc;
    thr *= 1.0 - a;
#endif
    // The refraction: thick glass and the edge hide what lies behind them; they show the
    // MatCap pulled towards its middle (the surroundings on the camera's side, as a line
    // bent through thick glass sees them), the further the thicker.
    float mask = max(thickness_mask(thick), fresnel_edge(nv));
    // Half of it is the surroundings' mean: thick glass still lets light through, scrambled.
    vec3 refracted = 0.5 * (matcap_at(clamp(uv - nview.xy * frame.matcap_refraction * mask, 0.0, 1.0), lod + 1.0) +
                            matcap_mean());
    radiance += thr * mask * refracted * frame.matcap_tint;
    thr *= (1.0 - mask) * frame.matcap_tint * exp(-g.glass_absorption * thick);
#if DECALS
    if (h.m == M_GLASS_OUTER) {  // the inner wall's layer, where the line reaches the cavity
      vec3 q = pl + thick * dl;
      dc = decal_seen(v, M_GLASS_INNER, q, to_world_point(v, q), n, uv, footprint, a);
      radiance += thr * a * dc;
      thr *= 1.0 - a;
    }
#endif
  }
  drink_along(v, g, pl, dl, p, radiance, thr);
  return radiance;
}

#if DEBUG_VIEWS
// (glass along the view from the first surface, m; material; object; 1). Compared with
// core's view_thickness at the reference intersector's first hit by tests/gpu/test_matcap.
vec4 debug_thickness(vec3 eye, vec3 dir) {
  Search s = start_search(0.0);
  Vessel v;
  for (int it = 0; it <= OBJECT_COUNT; ++it)
    if (search_step(s, eye, dir, MEDIUM_AIR, -1, true, v)) break;
  Hit h = s.best;
  float thick = h.obj >= 0 ? view_thickness(v, to_local_point(v, eye + h.t * dir), to_local_dir(v, dir), h.m) : 0.0;
  return vec4(thick, float(h.m), float(h.obj), 1.0);
}
#endif

void main() {
  init_objects();
  init_lights();
  init_studio();
  init_backdrop();
  vec3 dir = camera_dir(gl_FragCoord.xy);
#ifdef MATCAP_BACKDROP
  // The background alone, in linear light, for the pictures after it (u_matcap_background).
  frag_color = vec4(seen_straight(frame.cam_eye, dir), 1.0);
  return;
#endif
#if DEBUG_VIEWS
  frag_color = debug_thickness(frame.cam_eye, dir);
  return;
#endif
  vec3 thr;
#ifdef BACKGROUND_ONLY
  // Outside the objects' part of the screen (gpu/renderer objects_on_screen): what a line
  // that meets no object's bounds sees.
  thr = vec3(1.0);
  vec3 radiance = vec3(0.0);
#else
  vec3 radiance = shade(frame.cam_eye, dir, thr);
#endif
  float alpha = 1.0;
  if (frame.transparent != 0) {
    float m = min(thr.r, min(thr.g, thr.b));
    alpha = clamp(1.0 - m, 0.0, 1.0);
    radiance += (thr - vec3(m)) * cutout_light();
  } else {
#if defined(MATCAP_CACHED) && defined(MATCAP_CACHED_SMALL)
    // Drawn smaller while things move (MatCapBackground::kMovingScale), read between its texels.
    radiance += thr * texture(u_matcap_background, gl_FragCoord.xy * frame.viewport_inv).rgb;
#elif defined(MATCAP_CACHED)
    radiance += thr * texelFetch(u_matcap_background, ivec2(gl_FragCoord.xy), 0).rgb;  // drawn once for this view
#else
    radiance += thr * seen_straight(frame.cam_eye, dir);
#endif
  }
  frag_color = vec4(output_transform(radiance * frame.exposure, frame.tonemap, frame.output_linear != 0), alpha);
}
