// The backdrop in the picture (the sweep or the checker floor, lib/environment/backdrop.glsl):
// where a path meets it, and the light it receives: each light of the rig by its exact
// irradiance (lights.glsl irradiance_factor) times the glasses' shadows towards that
// light's centre, and the sky's irradiance darkened around each foot (contact). Every
// glass casts a soft shadow tinted by its drink, with a caustic in the middle (analytic:
// each glass is taken as a cylinder of its mean radius); the bounds of each glass are
// tested first. A cross-section (clip.*) takes away the shadow and the contact of what
// it cuts away.
#ifndef LIB_ENVIRONMENT_FLOOR_GLSL
#define LIB_ENVIRONMENT_FLOOR_GLSL
#include "generated/frame.glsl"
#include "lib/scene/objects.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/lights.glsl"
#include "lib/environment/backdrop.glsl"

// Object `row` seen from floor point p (world), with only its bounds and body: the
// point in the glass's frame as its height on the axis (y) and the vector across the
// axis (xz), and the same for the direction l towards a light. A glass is round, so this is all the floor
// needs (no rotation matrix: for an upright glass these are exactly the local x, y, z).
struct FloorView {
  vec3 across;        // p's offset across the axis
  float along;        // p's height on the axis (local y)
  vec3 l_across;      // the light direction across the axis
  float l_along;      // and along it
};

FloorView floor_view(ObjectBounds b, vec3 p, vec3 l) {
  FloorView v;
  vec3 rel = p - b.bound_base;
  v.along = dot(rel, b.bound_axis);
  v.across = rel - v.along * b.bound_axis;
  v.l_along = dot(l, b.bound_axis);
  v.l_across = l - v.l_along * b.bound_axis;
  return v;
}

// Where a path in the air meets the backdrop. Where a glass stands on the floor, its
// foot is the surface (as core/reference/intersect.cpp first_hit).
Hit hit_floor(vec3 o, vec3 d, float tmin) {
  float t;
  vec3 n;
  if (!intersect(backdrop_surface(), o, d, tmin, t, n)) return no_hit();
  vec3 p = o + t * d;
  if (n.y > 0.999) {
    for (int i = 0; i < OBJECT_COUNT; ++i) {
      ObjectBounds b = bounds_of(i);
      vec3 rel = p - b.bound_base;
      if (dot(rel, rel) > b.bound_radius * b.bound_radius) continue;
      FloorView v = floor_view(b, p, n);
      if (abs(v.along) < 1e-5 && length(v.across) <= body_of(i).foot_radius) return no_hit();
    }
  }
  return Hit(t, n, M_FLOOR, -1);
}

// Where the shadow ray from floor point v passes the glass's axis most closely: its
// parameter t along the light, its distance from the axis and its height on the axis.
struct ShadowRay {
  bool across;  // false: the light runs along the axis (no shadow from a cylinder)
  float t, dist, y;
  float speed;  // how fast the ray moves across the axis per unit t
};

ShadowRay shadow_ray(FloorView v) {
  ShadowRay r;
  float a = dot(v.l_across, v.l_across);
  r.across = a >= 1e-8;
  r.speed = sqrt(a);
  r.t = -dot(v.across, v.l_across) / a;
  r.dist = length(v.across + r.t * v.l_across);
  r.y = v.along + r.t * v.l_along;
  return r;
}

// The part of the shadow ray's chord through the cylinder (around the point nearest the
// axis, from floor point p) that the cross-section leaves: 1 uncut (or no cut), 0 cut
// away, so a glass cut away entirely casts no shadow and a half-cut one a fainter one.
float kept_by_cut(ObjectBody body, vec3 p, vec3 l, ShadowRay r, float half_chord) {
  float dt = half_chord / max(r.speed, 1e-6);
  float s0 = dot(body.clip_world_normal, p + (r.t - dt) * l) - body.clip_world_offset;
  float s1 = dot(body.clip_world_normal, p + (r.t + dt) * l) - body.clip_world_offset;
  float lo = min(s0, s1), hi = max(s0, s1);
  if (hi <= 0.0) return 1.0;
  if (lo >= 0.0) return 0.0;
  return -lo / (hi - lo);
}

// One glass's shadow at floor point p: a cylinder of the glass's mean radius, tinted by
// the drink where the light crosses it below the surface, with a caustic in the middle,
// as much of it as the cross-section leaves.
vec3 glass_shadow(ObjectBody body, vec3 p, vec3 l, ShadowRay r) {
  float rad = body.mean_outer_radius;
  if (!r.across || r.t <= 0.0 || r.y > body.height + 0.004) return vec3(1.0);
  float edge = smoothstep(rad * 1.05, rad * 0.9, r.dist);
  if (edge <= 0.0) return vec3(1.0);
  float chord = 2.0 * sqrt(max(rad * rad - r.dist * r.dist, 0.0));
  edge *= kept_by_cut(body, p, l, r, 0.5 * chord);
  if (edge <= 0.0) return vec3(1.0);
  bool wet = body.has_liquid != 0 && r.y < body.wet_height;
  vec3 through = wet ? exp(-body.absorption * chord) : vec3(0.85);
  float x = r.dist / rad;
  float caustic = wet ? 0.45 + 1.6 * pow(max(1.0 - x * x, 0.0), 6.0) : 0.75;
  return mix(vec3(1.0), through * caustic, edge);
}

// Ambient occlusion (contact) at backdrop point p (world) from every glass: darker near
// each foot (which lifts off the floor when the glass tips), where the cross-section
// leaves the foot: its point nearest p decides, blended over 2 mm. Beyond three bound
// radii (at least two foot radii from the foot) it darkens by less than 2e-4 of the
// sky's light, nothing an 8-bit pixel shows.
float floor_contact(vec3 p) {
  float contact = 1.0;
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    ObjectBounds b = bounds_of(i);
    vec3 rel = p - b.bound_base;
    if (dot(rel, rel) < 9.0 * b.bound_radius * b.bound_radius) {  // (a block, not a continue: llvmpipe runs it faster)
      ObjectBody body = body_of(i);
      FloorView v = floor_view(b, p, vec3(0.0, 1.0, 0.0));
      float across = length(v.across);
      float foot_dist = length(vec2(max(across - body.foot_radius, 0.0), v.along));
      vec3 foot = b.bound_base + v.across * (min(across, body.foot_radius) / max(across, 1e-9));
      float foot_kept = 1.0 - smoothstep(-0.002, 0.002, dot(body.clip_world_normal, foot) - body.clip_world_offset);
      contact *= 1.0 - 0.55 * foot_kept * exp(-foot_dist / (0.25 * body.foot_radius));
    }
  }
  return contact;
}

// Every glass's shadow at backdrop point p towards direction l (unit, to a light's
// centre). Each glass's bounds decide first whether it can shade p at all; only then are
// its body's texels fetched.
vec3 floor_shadow(vec3 p, vec3 l) {
  vec3 direct = vec3(1.0);
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    ObjectBounds b = bounds_of(i);
    ShadowRay r = shadow_ray(floor_view(b, p, l));
    if (r.across && r.t > 0.0 && r.y <= b.bound_length + 0.004 && r.dist < 1.05 * b.bound_radius)
      direct *= glass_shadow(body_of(i), p, l, r);
  }
  return direct;
}

// The backdrop at p (world, normal n), seen from `dist` away: albedo / pi times the
// light it receives, each light's exact irradiance through the glasses' shadows and the
// sky's around the feet. `occluded` false: the backdrop mirrored in a glass (a few per
// cent of a pixel), where each light is taken as a point and shadows and contact are
// left out: too small to see there, and the most costly.
vec3 shade_floor(vec3 p, vec3 n, float dist, bool occluded) {
  BackdropSurface bd = backdrop_surface();
  vec3 e = sky_irradiance(n) * (occluded ? floor_contact(p) : 1.0);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= frame.light_count) break;
    AreaLight l = area_light(i);
    float f = occluded ? irradiance_factor(l, p, n) : irradiance_factor_far(l, p, n);
    if (f > 0.0) e += l.radiance * f * (occluded ? floor_shadow(p, normalize(l.center - p)) : vec3(1.0));
  }
  vec3 c = albedo(bd, p) / PI * e;
  // The checker to the horizon fades into the sky's ground, so it never aliases there.
  return bd.checker ? mix(frame.ground, c, exp(-dist / 2.0)) : c;
}

// What a ray from o in the air sees past the glasses: the nearest of a light's front
// and the backdrop (shaded), else the sky. roughness: of the surface that sent it.
vec3 background(vec3 o, vec3 d, float roughness) {
  float tb, tl;
  vec3 nb;
  bool on_backdrop = intersect(backdrop_surface(), o, d, 0.0, tb, nb);
  vec4 light = lights_seen(o, d, roughness, tb, tl);
  vec3 beyond = on_backdrop ? shade_floor(o + tb * d, nb, tb, true) : studio_backdrop(d);
  return light.rgb * light.a + beyond * (1.0 - light.a);
}

#endif  // LIB_ENVIRONMENT_FLOOR_GLSL
