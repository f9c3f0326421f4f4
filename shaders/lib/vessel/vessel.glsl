// The nearest surface of the loaded vessel (glass, liquid surface, cut faces) for a
// path in one of its media, in its local frame. Twin of core/reference/intersect.cpp
// hit_vessel (which tests every surface; here only those that bound the medium).
#ifndef LIB_VESSEL_VESSEL_GLSL
#define LIB_VESSEL_VESSEL_GLSL
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"
#include "lib/liquid/surface.glsl"

// The cut face of the cross-section, where the plane passes through glass or liquid.
// Its normal points out of what is kept, like every glass surface's.
Hit hit_clip_cap(vec3 o, vec3 d, float tmin) {
  vec3 cn = g_shape.clip_normal;
  float dn = dot(cn, d);
  if (abs(dn) < 1e-12) return no_hit();
  float t = (g_shape.clip_offset - dot(cn, o)) / dn;
  if (t <= tmin) return no_hit();
  vec3 p = o + t * d;
  float r = length(p.xz);
  if (inside_body(r, p.y) || inside_torus(r, p.y)) return Hit(t, cn, M_CLIP_GLASS, g_row);
  bool in_cavity = p.y > g_shape.base && p.y < g_shape.height && r < inner_radius(p.y);
  if (in_cavity && g_shape.has_liquid != 0 && dot(g_liquid.plane_normal, p) < g_liquid.plane_offset)
    return Hit(t, cn, M_CLIP_LIQUID, g_row);
  return no_hit();
}

// The nearest surface of the loaded vessel from inside the given medium (local ray;
// only surfaces that bound the medium are tested).
Hit vessel_hit(vec3 o, vec3 d, int medium, float tmin) {
  Hit best = no_hit();
  if (medium != MEDIUM_LIQUID) {
    keep_nearest(best, hit_wall(o, d, false, tmin));
    keep_nearest(best, hit_rim(o, d, tmin));
    keep_nearest(best, hit_disk(o, d, 0.0, g_shape.foot_radius, tmin, vec3(0.0, -1.0, 0.0), M_GLASS_BOTTOM));
  }
  keep_nearest(best, hit_wall(o, d, true, tmin));
  keep_nearest(best, hit_disk(o, d, g_shape.base, g_shape.cavity_floor_radius, tmin, vec3(0.0, 1.0, 0.0), M_CAVITY_FLOOR));
  if (medium != MEDIUM_GLASS) keep_nearest(best, hit_liquid_surface(o, d, tmin));
  if (dot(g_shape.clip_normal, g_shape.clip_normal) > 0.5) keep_nearest(best, hit_clip_cap(o, d, tmin));  // a cross-section
  return best;
}

#endif  // LIB_VESSEL_VESSEL_GLSL
