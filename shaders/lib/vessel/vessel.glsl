// The nearest surface of a vessel (glass, liquid surface, cut faces) for a
// path in one of its media, in its local frame. Twin of core/reference/intersect.cpp
// hit_vessel (which tests every surface; here only those that bound the medium).
#ifndef LIB_VESSEL_VESSEL_GLSL
#define LIB_VESSEL_VESSEL_GLSL
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"
#include "lib/liquid/surface.glsl"

// The cut face of the cross-section, where the plane passes through glass or liquid.
// Its normal points out of what is kept, like every glass surface's.
Hit hit_clip_cap(Vessel v, vec3 o, vec3 d, float tmin) {
  vec3 cn = v.shape.clip_normal;
  float dn = dot(cn, d);
  if (abs(dn) < 1e-12) return no_hit();
  float t = (v.shape.clip_offset - dot(cn, o)) / dn;
  if (t <= tmin) return no_hit();
  vec3 p = o + t * d;
  float r = length(p.xz);
  if (inside_body(v, r, p.y) || inside_torus(v, r, p.y)) return Hit(t, cn, M_CLIP_GLASS, v.row);
  bool in_cavity = p.y > v.shape.base && p.y < v.body.height && r < inner_radius(v, p.y);
  if (in_cavity && v.body.has_liquid != 0 && dot(v.liquid.plane_normal, p) < v.liquid.plane_offset)
    return Hit(t, cn, M_CLIP_LIQUID, v.row);
  return no_hit();
}

// The nearest surface of a vessel from inside the given medium (local ray;
// only surfaces that bound the medium are tested).
Hit vessel_hit(Vessel v, vec3 o, vec3 d, int medium, float tmin) {
  Hit best = no_hit();
  if (medium != MEDIUM_LIQUID) {
    keep_nearest(best, hit_wall(v, o, d, false, tmin));
    keep_nearest(best, hit_rim(v, o, d, tmin));
    keep_nearest(best, hit_disk(v, o, d, 0.0, v.body.foot_radius, tmin, vec3(0.0, -1.0, 0.0), M_GLASS_BOTTOM));
  }
  keep_nearest(best, hit_wall(v, o, d, true, tmin));
  keep_nearest(best, hit_disk(v, o, d, v.shape.base, v.shape.cavity_floor_radius, tmin, vec3(0.0, 1.0, 0.0), M_CAVITY_FLOOR));
  if (medium != MEDIUM_GLASS) keep_nearest(best, hit_liquid_surface(v, o, d, tmin));
  if (dot(v.shape.clip_normal, v.shape.clip_normal) > 0.5) keep_nearest(best, hit_clip_cap(v, o, d, tmin));  // a cross-section
  return best;
}

#endif  // LIB_VESSEL_VESSEL_GLSL
