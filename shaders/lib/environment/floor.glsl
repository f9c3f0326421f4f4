// The checker floor at world y = 0: where a path meets it, and the light it receives:
// every glass casts a soft shadow tinted by its drink, with a caustic in the middle
// (analytic: each glass is taken as a cylinder of its mean radius), and darkens the
// floor around its foot (contact shadow). A floor point is shaded by the product of
// every glass's shadow; the bounds of each glass are tested first.
#ifndef LIB_ENVIRONMENT_FLOOR_GLSL
#define LIB_ENVIRONMENT_FLOOR_GLSL
#include "generated/frame.glsl"
#include "lib/scene/objects.glsl"
#include "lib/liquid/surface.glsl"
#include "lib/environment/studio.glsl"

// Where a path in the air meets the floor. Where a glass stands on it, its foot is the
// surface (as core/reference/intersect.cpp first_hit).
Hit hit_floor(vec3 o, vec3 d, float tmin) {
  if (frame.floor_on == 0 || d.y >= 0.0) return no_hit();
  float t = -o.y / d.y;
  if (t <= tmin) return no_hit();
  vec3 p = o + t * d;
  for (int i = 0; i < frame.object_count; ++i) {
    ObjectBounds b = fetch_object_bounds(i);
    vec3 rel = p - b.bound_base;
    if (dot(rel, rel) > b.bound_radius * b.bound_radius) continue;
    use_object(i);
    vec3 q = to_local_point(p);
    if (abs(q.y) < 1e-5 && length(q.xz) <= g_shape.foot_radius) return no_hit();
  }
  return Hit(t, vec3(0.0, 1.0, 0.0), M_FLOOR, -1);
}

// One glass's shadow at floor point p (the glass's frame) for the light l (its frame).
vec3 glass_shadow(ObjectShape s, ObjectLiquid lq, vec3 p, vec3 l) {
  float rad = s.mean_outer_radius;
  // Closest approach of the shadow ray p + t l to the axis.
  vec2 dxz = l.xz;
  float a = dot(dxz, dxz);
  if (a < 1e-8) return vec3(1.0);
  float t = -dot(p.xz, dxz) / a;
  float dist = length(p.xz + t * dxz);
  float y = p.y + t * l.y;
  if (t <= 0.0 || y > s.height + 0.004) return vec3(1.0);
  float edge = smoothstep(rad * 1.05, rad * 0.9, dist);
  if (edge <= 0.0) return vec3(1.0);
  float chord = 2.0 * sqrt(max(rad * rad - dist * dist, 0.0));
  bool wet = s.has_liquid != 0 && level_over(lq, vec3(0.0, y, 0.0)) < 0.0;
  vec3 through = wet ? exp(-lq.absorption * chord) : vec3(0.85);
  float x = dist / rad;
  float caustic = wet ? 0.45 + 1.6 * pow(max(1.0 - x * x, 0.0), 6.0) : 0.75;
  return mix(vec3(1.0), through * caustic, edge);
}

// Direct light (shadows) and ambient occlusion (contact) at floor point p (world) from
// every glass. The loaded object is not changed.
void floor_occlusion(vec3 p, out vec3 direct, out float contact) {
  direct = vec3(1.0);
  contact = 1.0;
  vec3 l = frame.light_dir;
  for (int i = 0; i < frame.object_count; ++i) {
    ObjectBounds b = fetch_object_bounds(i);
    vec3 rel = p - b.bound_base;
    // Contact: exp(-16) is invisible beyond five bound radii.
    bool near = dot(rel, rel) < 25.0 * b.bound_radius * b.bound_radius;
    // Shadow: the shadow ray's closest distance to the glass's axis.
    vec3 n = cross(b.bound_axis, l);
    float nn = dot(n, n);
    bool shade = nn > 1e-10 && abs(dot(rel, n)) < 1.1 * b.bound_radius * sqrt(nn);
    if (!near && !shade) continue;
    ObjectShape s;
    ObjectLiquid lq;
    if (i == g_row) {
      s = g_shape;
      lq = g_liquid;
    } else {
      s = fetch_object_shape(i);
      lq = fetch_object_liquid(i);
    }
    mat3 rot = mat3(s.rot_x, s.rot_y, s.rot_z);
    vec3 q = (p - s.position) * rot;
    // Darker near the foot (which lifts off the floor when the glass tips).
    float foot_dist = length(vec2(max(length(q.xz) - s.foot_radius, 0.0), q.y));
    if (near) contact *= 1.0 - 0.55 * exp(-foot_dist / (0.25 * s.foot_radius));
    if (shade) direct *= glass_shadow(s, lq, q, l * rot);
  }
}

// The floor at p (world), seen from `dist` away.
vec3 shade_floor(vec3 p, float dist) {
  vec2 cell = floor(p.xz / frame.checker_size);
  bool light_square = mod(cell.x + cell.y, 2.0) < 0.5;
  vec3 albedo = light_square ? frame.floor_a : frame.floor_b;
  vec3 direct;
  float contact;
  floor_occlusion(p, direct, contact);
  vec3 light = ambient_light() * contact + frame.light_color * frame.light_intensity * max(frame.light_dir.y, 0.0) * direct;
  vec3 c = albedo * light / PI * 1.6;
  // Far floor fades into the studio backdrop, so the checker never aliases at the horizon.
  return mix(frame.ground, c, exp(-dist / 2.0));
}

// Everything that is not a glass, along a world ray: the floor where the ray meets it,
// else the sky.
vec3 background(vec3 o, vec3 d) {
  if (frame.floor_on != 0 && d.y < 0.0) {
    float t = -o.y / d.y;
    if (t > 0.0) return shade_floor(o + t * d, t);
  }
  return studio_sky(d);
}

#endif  // LIB_ENVIRONMENT_FLOOR_GLSL
