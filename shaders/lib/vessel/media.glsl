// Which medium lies across a surface, and the media's indices of refraction.
#ifndef LIB_VESSEL_MEDIA_GLSL
#define LIB_VESSEL_MEDIA_GLSL
#include "generated/constants.glsl"
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"
#include "lib/liquid/body.glsl"
#include "lib/optics/fresnel.glsl"

// The medium on the far side of surface m for a path now in `from`; `below`: whether
// the point lies under the liquid's surface (it decides what is behind the inner wall
// and the cavity floor). GLSL twin of medium_across() in core/reference/media.hpp: the
// MediumRule debug view evaluates it for every input and tests/gpu compares the two.
int medium_across(int m, int from, bool below) {
  if (m == M_LIQUID_SURFACE) return from == MEDIUM_LIQUID ? MEDIUM_AIR : MEDIUM_LIQUID;
  if (m == M_CLIP_GLASS) return from == MEDIUM_AIR ? MEDIUM_GLASS : MEDIUM_AIR;
  if (m == M_CLIP_LIQUID) return from == MEDIUM_AIR ? MEDIUM_LIQUID : MEDIUM_AIR;
  if (from != MEDIUM_GLASS) return MEDIUM_GLASS;
  if (m == M_GLASS_INNER || m == M_CAVITY_FLOOR) return below ? MEDIUM_LIQUID : MEDIUM_AIR;
  return MEDIUM_AIR;
}

// Index of refraction of a medium of vessel v with glass g (air 1).
float medium_ior(Vessel v, ObjectGlass g, int medium) {
  return medium == MEDIUM_GLASS ? g.glass_ior : (medium == MEDIUM_LIQUID ? v.liquid.ior : 1.0);
}

// What even light keeps of vessel v's drink across its mean chord (4 V / S, core
// drink_mean_chord): light that reaches a point through the drink from all around it
// (under a head, up a wall to a rim, onto a decal facing the drink, turned down into it).
vec3 mean_chord_transmittance(Vessel v) { return drink_transmittance(v.body, fetch_object_foam(v.row).under_chord); }

// What a glass wall (two faces, air on both sides) lets through of light falling at
// cosine cos_i (the inner face reflects as much as the outer: Fresnel is reciprocal).
float wall_transmittance(float cos_i, float ior) {
  float t = 1.0 - fresnel_dielectric(cos_i, 1.0, ior);
  return t * t;
}

// Light reflected off the drink's surface from the air in the cavity (p, r local: the
// point and the reflected direction) leaves through the opening, or through the wall
// where it meets it first: what reaches the eye of it per unit of what it sees beyond,
// through both faces and the glass between (the way on taken straight: parallel faces).
// `back`: the part the wall sends back into the cavity (through the drink's mean chord
// where it heads down into it), which the caller gives the surroundings' mean: it leaves
// in the end, somewhere (in even light, as the light itself). A wine glass's bowl
// curves in over its drink, and what the surface mirrors at a grazing view is its far
// wall from inside, not the open studio: the surface's band came out 15-20 levels lighter
// than the reference's, which follows the reflection through the wall. Not a twin (the
// reference follows the reflection; docs/REFERENCE.md, "Wines and champagne").
vec3 surface_reflection_out(Vessel v, ObjectGlass g, vec3 p, vec3 r, out vec3 back) {
  back = vec3(0.0);
  // The cavity above p as one cone from p's height to the rim (a wall walked segment by
  // segment cost the frame up to a sixth more on llvmpipe; a bowl's curve between the
  // two matters little to where and how steeply the reflection meets it).
  float H = v.body.height, r0 = inner_radius(v, p.y), s = (inner_radius(v, H) - r0) / max(H - p.y, 1e-6);
  float A = dot(r.xz, r.xz) - s * s * r.y * r.y, B = dot(p.xz, r.xz) - s * r0 * r.y, C = dot(p.xz, p.xz) - r0 * r0;
  float disc = B * B - A * C;
  if (r.y <= 0.0 || C >= 0.0 || disc < 0.0 || abs(A) < 1e-12) return vec3(1.0);
  float sq = sqrt(disc), t = (-B + sq) / A;
  if (t <= 0.0) t = (-B - sq) / A;
  vec3 q = p + t * r;
  if (t <= 0.0 || q.y >= H) return vec3(1.0);  // out through the opening
  float rq = length(q.xz);
  vec3 n = rq > 0.0 ? normalize(vec3(q.x / rq, -s, q.z / rq)) : vec3(0.0, -1.0, 0.0);  // outward
  float c = abs(dot(n, r)), pass = wall_transmittance(c, g.glass_ior);
  float ct = sqrt(max(1.0 - (1.0 - c * c) / (g.glass_ior * g.glass_ior), 0.0));  // inside the glass
  float thick = (outer_radius(v, q.y) - inner_radius(v, q.y)) * length(n.xz) / max(ct, 0.05);
  back = (1.0 - pass) * (reflect(r, n).y < 0.0 ? mean_chord_transmittance(v) : vec3(1.0));
  return pass * exp(-g.glass_absorption * thick);
}

// Where the ray o + t r (local) crosses the cavity: within its cylinder (the radius at
// o's height), above its floor and, with `drink`, below the surface plane. span: the
// part inside, n_out: the outward normal where it leaves (the wall's, tilted by its
// slope there; the plane's; the floor's). False when it misses.
bool cavity_span(Vessel v, vec3 o, vec3 r, bool drink, out vec2 span, out vec3 n_out) {
  // One knot fetch: the wall's radius and slope at o's height (the slope stands for the
  // slope where the ray leaves; it matters for the tilt, which changes slowly).
  float s = clamp(clamp(o.y, v.shape.base, v.body.height) * v.shape.inv_dy, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  vec4 kn = segment_knots(v, k);
  float R = mix(kn.y, kn.w, s - float(k)), slope = (kn.w - kn.y) * v.shape.inv_dy;
  span = vec2(0.0, INF);
  float A = dot(r.xz, r.xz), B = dot(o.xz, r.xz), C = dot(o.xz, o.xz) - R * R;
  if (A > 1e-12) {
    float disc = B * B - A * C;
    if (disc < 0.0) return false;
    float sq = sqrt(disc);
    span = vec2(max((-B - sq) / A, 0.0), (-B + sq) / A);
  } else if (C > 0.0) {
    return false;
  }
  vec3 q = o + span.y * r;
  n_out = normalize(vec3(q.x, -slope * length(q.xz), q.z));
  if (drink) {
    float dn = dot(v.liquid.plane_normal, r), under = v.liquid.plane_offset - dot(v.liquid.plane_normal, o);
    if (dn > 1e-6 && under / dn < span.y) {
      span.y = under / dn;
      n_out = v.liquid.plane_normal;
    } else if (dn < -1e-6) {
      span.x = max(span.x, under / dn);
    } else if (abs(dn) <= 1e-6 && under < 0.0) {
      return false;
    }
  }
  if (r.y < -1e-6 && (o.y - v.shape.base) / -r.y < span.y) {
    span.y = (o.y - v.shape.base) / -r.y;
    n_out = vec3(0.0, -1.0, 0.0);
  } else if (r.y > 1e-6) {
    span.x = max(span.x, (v.shape.base - o.y) / r.y);
  } else if (abs(r.y) <= 1e-6 && o.y < v.shape.base) {
    return false;
  }
  return span.x < span.y;
}

// The direction light going along r in a medium of index eta (over the air's) leaves in
// through a surface of outward normal n_out, as if through parallel faces: light
// crosses a glass wall into the air as from the drink straight into the air. Under
// total internal reflection, the reflection.
vec3 leave_through(vec3 r, vec3 n_out, float eta) {
  vec3 n = dot(r, n_out) > 0.0 ? -n_out : n_out;
  vec3 t = refract(r, n, eta);
  return dot(t, t) > 0.0 ? t : reflect(r, n);
}

// Light reflected inside a medium at surface m (point p, reflected direction r, the
// normal n facing the reflected side; all local): what reaches the eye of it per unit of
// what it sees once out, and the direction `out` it leaves in. The path follows only the
// refracted part of an interface, and the reflected part is a look-up of the
// surroundings, which must first be absorbed along the way it would go and looked up
// where it would leave (else internal reflections add the studio untinted, in
// directions the tapered walls bend away: too bright, pinkish). In the drink: across it
// to the cavity's wall, floor or surface. In the glass: across the wall, the base or the
// rim bead's tube, and where it turns inwards (off the outer wall or the foot's
// underside) across the cavity and its drink to the far side. `turned`: the part the
// way out reflects back in (Fresnel there, as from the medium straight into the air),
// which the caller gives the surroundings' mean: it leaves in the end, somewhere (in even
// light, as the light itself). Not a twin: the reference follows these paths
// (docs/REFERENCE.md measures the difference).
vec3 reflected_light(Vessel v, ObjectGlass g, int m, int medium, bool below, vec3 left, vec3 p, vec3 r, vec3 n,
                     out vec3 out_dir, out float turned) {
  out_dir = r;
  turned = 0.0;
  bool liquid = medium == MEDIUM_LIQUID;
  if (!liquid && medium != MEDIUM_GLASS) return vec3(1.0);
  // Every case in one pass, each step once (llvmpipe runs every copy of inlined code).
  // In the glass: across the wall (from its knot at p), the base, or the rim bead's tube.
  float across = abs(dot(r, n));
  vec4 kn = segment_knots(v, clamp(int(p.y * v.shape.inv_dy), 0, SEGMENTS - 1));
  float thick = m != M_GLASS_BOTTOM && m != M_CAVITY_FLOOR ? (kn.x - kn.y) * length(n.xz) : v.shape.base;
  float in_glass = liquid ? 0.0
                   : m == M_RIM ? 2.0 * v.shape.rim_minor * across  // a chord of the tube
                                : min(thick / max(across, 1e-3), v.body.height);
  // Across the cavity: in the drink to its wall, floor or surface; in the glass where the
  // reflection turns inwards (off the outer wall or the foot's underside), across the
  // cavity and its drink to the far side.
  bool drink = liquid || below, inwards = liquid || m == M_GLASS_OUTER || m == M_GLASS_BOTTOM;
  vec2 span;
  vec3 n_out;
  bool spans = cavity_span(v, p, r, drink, span, n_out) && inwards;
  if (liquid && !spans) return vec3(1.0);
  if (!spans) n_out = -n;  // out through the face opposite the one it reflected off
  float in_drink = spans && drink ? span.y - span.x : 0.0;
  if (liquid || m != M_RIM) {
    float eta = liquid ? v.liquid.ior : g.glass_ior;
    out_dir = leave_through(r, n_out, eta);
    turned = fresnel_dielectric(abs(dot(r, n_out)), eta, 1.0);  // (1 under total internal reflection)
  }
  // left: the shares of this drink's colour bands on the path (drink_onward); a path in
  // the glass that turns inwards meets the drink again. A haze takes out only what it
  // absorbs: what it scatters out of the way it scatters in from the light around (as
  // much in even light: a white haze leaves a colourless drink invisible).
#if HAZE
  vec3 haze = v.liquid.haze > 0.0 ? v.liquid.haze * (1.0 - fetch_object_haze(v.row).haze_albedo) : vec3(0.0);
#else
  vec3 haze = vec3(0.0);  // (no drink of the frame is hazy: lib/liquid/body.glsl)
#endif
  return exp(-g.glass_absorption * in_glass - haze * in_drink) * drink_onward(v.body, left, in_drink);
}

#endif  // LIB_VESSEL_MEDIA_GLSL
