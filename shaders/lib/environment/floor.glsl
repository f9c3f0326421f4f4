// The checker floor at world y = 0: where a path meets it, and the light it receives:
// the direct light with every glass's shadow and caustics from the traced map
// (floor_light.glsl), and the ambient light darkened around each foot (contact). A
// cross-section (clip.*) takes away the contact of what it cuts away (the map honours it).
#ifndef LIB_ENVIRONMENT_FLOOR_GLSL
#define LIB_ENVIRONMENT_FLOOR_GLSL
#include "generated/frame.glsl"
#include "lib/scene/objects.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/floor_light.glsl"

// Object `row` seen from floor point p (world), with only its bounds: the point's height
// on the glass's axis and its offset across it. A glass is round, so this is all the
// contact darkening needs.
struct FloorView {
  vec3 across;  // p's offset across the axis
  float along;  // p's height on the axis (local y)
};

FloorView floor_view(ObjectBounds b, vec3 p) {
  FloorView v;
  vec3 rel = p - b.bound_base;
  v.along = dot(rel, b.bound_axis);
  v.across = rel - v.along * b.bound_axis;
  return v;
}

// Where a path in the air meets the floor. Where a glass stands on it, its foot is the
// surface (as core/reference/intersect.cpp first_hit).
Hit hit_floor(vec3 o, vec3 d, float tmin) {
  if (frame.floor_on == 0 || d.y >= 0.0) return no_hit();
  float t = -o.y / d.y;
  if (t <= tmin) return no_hit();
  vec3 p = o + t * d;
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    ObjectBounds b = bounds_of(i);
    vec3 rel = p - b.bound_base;
    if (dot(rel, rel) > b.bound_radius * b.bound_radius) continue;
    FloorView v = floor_view(b, p);
    if (abs(v.along) < 1e-5 && length(v.across) <= body_of(i).foot_radius) return no_hit();
  }
  return Hit(t, vec3(0.0, 1.0, 0.0), M_FLOOR, -1);
}

// Ambient occlusion (contact) at floor point p (world) from every glass: darker near the
// foot, where the cross-section leaves it. (Direct light, shadows and caustics included,
// comes from the traced map: floor_light.glsl.)
float floor_contact(vec3 p) {
  float contact = 1.0;
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    ObjectBounds b = bounds_of(i);
    // Beyond three bound radii (at least two foot radii from the foot) it darkens by less
    // than 2e-4 of the ambient light, nothing an 8-bit pixel shows.
    vec3 rel = p - b.bound_base;
    if (dot(rel, rel) < 9.0 * b.bound_radius * b.bound_radius) {  // (a block, not a continue: llvmpipe runs it faster)
      ObjectBody body = body_of(i);
      FloorView v = floor_view(b, p);
      // Darker near the foot (which lifts off the floor when the glass tips), where the
      // cross-section leaves the foot: its point nearest p decides, blended over 2 mm.
      float across = length(v.across);
      float foot_dist = length(vec2(max(across - body.foot_radius, 0.0), v.along));
      vec3 foot = b.bound_base + v.across * (min(across, body.foot_radius) / max(across, 1e-9));
      float foot_kept = 1.0 - smoothstep(-0.002, 0.002, dot(body.clip_world_normal, foot) - body.clip_world_offset);
      contact *= 1.0 - 0.55 * foot_kept * exp(-foot_dist / (0.25 * body.foot_radius));
    }
  }
  return contact;
}

// The floor at p (world), seen from `dist` away.
vec3 shade_floor(vec3 p, float dist) {
  vec2 cell = floor(p.xz / frame.checker_size);
  bool light_square = mod(cell.x + cell.y, 2.0) < 0.5;
  vec3 albedo = light_square ? frame.floor_a : frame.floor_b;
  vec3 light = ambient_light() * floor_contact(p) + floor_direct_light(p);
  vec3 c = albedo * light / PI * 1.6;
  // Far floor fades into the studio backdrop, so the checker never aliases at the horizon.
  return mix(frame.ground, c, exp(-dist / 2.0));
}

// Where a world ray from o meets the floor (t along it); false when it does not.
bool floor_along(vec3 o, vec3 d, out float t) {
  t = d.y < 0.0 ? -o.y / d.y : -1.0;
  return frame.floor_on != 0 && t > 0.0;
}

// Everything that is not a glass, along a world ray: the floor where the ray meets it,
// else the sky.
vec3 background(vec3 o, vec3 d) {
  float t;
  if (floor_along(o, d, t)) return shade_floor(o + t * d, t);
  return studio_sky(d);
}

#endif  // LIB_ENVIRONMENT_FLOOR_GLSL
