// How much glass the view crosses straight on from the first surface it meets: the MatCap
// tier's thickness mask (docs/MATCAP.md). No refraction; the profile is taken as the
// cylinders through the hit's height. Twin of view_thickness (core/vessel/view_thickness.cpp);
// tests/gpu/test_matcap.cpp compares them pixel by pixel.
#ifndef LIB_VESSEL_THICKNESS_GLSL
#define LIB_VESSEL_THICKNESS_GLSL
#include "generated/constants.glsl"
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"

// The roots of |p.xz + t d.xz| = r along the line (false: it misses the cylinder).
bool cylinder_roots(vec3 p, vec3 d, float r, out float t0, out float t1) {
  float a = dot(d.xz, d.xz), b = dot(p.xz, d.xz), c = dot(p.xz, p.xz) - r * r;
  float disc = b * b - a * c;
  t0 = t1 = 0.0;
  if (a < 1e-12 || disc < 0.0) return false;
  float s = sqrt(disc);
  t0 = (-b - s) / a;
  t1 = (-b + s) / a;
  return true;
}

// p, d: the surface point and the view's direction in the vessel's frame; m: the surface.
float view_thickness(Vessel v, vec3 p, vec3 d, int m) {
  float y = clamp(p.y, 0.0, v.body.height);
  float ro = outer_radius(v, y), ri = inner_radius(v, y);
  float t0, t1;
  if (m == M_RIM) {  // the bead's sphere about its circle's point nearest p
    float r = length(p.xz);
    vec3 c = r > 0.0 ? vec3(p.x / r * v.shape.rim_major, v.body.height, p.z / r * v.shape.rim_major)
                     : vec3(0.0, v.body.height, 0.0);
    return max(2.0 * dot(c - p, d), 0.0);
  }
  if (m == M_GLASS_BOTTOM || m == M_CAVITY_FLOOR || p.y < v.shape.base) {  // solid glass
    float t = cylinder_roots(p, d, ro, t0, t1) ? max(t1, 0.0) : INF;
    if (d.y > 1e-12) t = min(t, (v.shape.base - p.y) / d.y);
    if (d.y < -1e-12) t = min(t, -p.y / d.y);
    return t < INF ? max(t, 0.0) : 0.0;
  }
  if (m == M_GLASS_INNER) return cylinder_roots(p, d, ro, t0, t1) ? max(t1, 0.0) : 0.0;
  if (m == M_GLASS_OUTER || m == M_CLIP_GLASS) {
    if (ri > 0.0 && cylinder_roots(p, d, ri, t0, t1) && t0 > 0.0) return t0;  // into the cavity
    return cylinder_roots(p, d, ro, t0, t1) ? max(t1, 0.0) : 0.0;             // along the wall
  }
  return 0.0;
}

#endif  // LIB_VESSEL_THICKNESS_GLSL
