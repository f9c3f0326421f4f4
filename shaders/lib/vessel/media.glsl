// Which medium lies across a surface, and the media's indices of refraction.
#ifndef LIB_VESSEL_MEDIA_GLSL
#define LIB_VESSEL_MEDIA_GLSL
#include "generated/constants.glsl"
#include "lib/scene/objects.glsl"

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

#endif  // LIB_VESSEL_MEDIA_GLSL
