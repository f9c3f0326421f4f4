// Which medium lies across a surface, and the media's indices of refraction.
#ifndef LIB_VESSEL_MEDIA_GLSL
#define LIB_VESSEL_MEDIA_GLSL
#include "generated/constants.glsl"
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"

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

// How far light reflected inside a medium travels in it before it leaves: the path
// follows only the refracted part of an interface, and the reflected part is a look-up
// of the surroundings, which must first be absorbed along the way it would go (else
// internal reflections add the studio untinted: too bright, pinkish). p: the surface
// point, r: the reflected direction, n: the surface's normal (all local); m: the
// surface. In the drink: to the nearest of the cavity's wall (the cylinder of its radius
// at p), its floor and the surface plane. In the glass: across the wall, the base or the
// rim bead's tube. Not a twin: the reference follows these paths.
float reflected_reach(Vessel v, int m, int medium, vec3 p, vec3 r, vec3 n) {
  if (medium == MEDIUM_LIQUID) {
    float R = inner_radius(v, p.y);
    float A = dot(r.xz, r.xz), B = dot(p.xz, r.xz), C = dot(p.xz, p.xz) - R * R;
    float t = A > 1e-12 ? (-B + sqrt(max(B * B - A * C, 0.0))) / A : INF;
    float dn = dot(v.liquid.plane_normal, r);
    if (dn > 1e-6) t = min(t, max(v.liquid.plane_offset - dot(v.liquid.plane_normal, p), 0.0) / dn);
    if (r.y < -1e-6) t = min(t, max(p.y - v.shape.base, 0.0) / -r.y);
    return max(t, 0.0);
  }
  if (medium != MEDIUM_GLASS) return 0.0;
  float across = abs(dot(r, n));
  if (m == M_RIM) return 2.0 * v.shape.rim_minor * across;  // a chord of the bead's tube
  float thick = m == M_GLASS_BOTTOM || m == M_CAVITY_FLOOR ? v.shape.base
                                                           : (outer_radius(v, p.y) - inner_radius(v, p.y)) * length(n.xz);
  return min(thick / max(across, 1e-3), v.body.height);
}

#endif  // LIB_VESSEL_MEDIA_GLSL
