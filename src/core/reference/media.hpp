// Which medium lies across a surface: the one rule, in C++. Its GLSL twin is
// medium_across() in shaders/lib/vessel/media.glsl; tests/gpu probes compare the two.
#pragma once

#include "core/reference/intersect.hpp"
#include "core/reference/optics.hpp"

namespace draught {

// The media a path can be in (src/interface/constants.def: the shader's MEDIUM_AIR,
// MEDIUM_GLASS, MEDIUM_LIQUID).
using MediumKind = contract::MediumKind;

// The medium on the far side of surface `m` for a path now in `from`. `below_liquid`:
// whether the point lies under the liquid's surface (it decides what is behind the
// inner wall and the cavity floor).
constexpr MediumKind medium_across(Material m, MediumKind from, bool below_liquid) {
  switch (m) {
    case Material::LiquidSurface: return from == MediumKind::Liquid ? MediumKind::Air : MediumKind::Liquid;
    case Material::ClipGlass: return from == MediumKind::Air ? MediumKind::Glass : MediumKind::Air;
    case Material::ClipLiquid: return from == MediumKind::Air ? MediumKind::Liquid : MediumKind::Air;
    default: break;
  }
  if (from != MediumKind::Glass) return MediumKind::Glass;
  if (m == Material::GlassInner || m == Material::CavityFloor) return below_liquid ? MediumKind::Liquid : MediumKind::Air;
  return MediumKind::Air;
}

// Fresnel's choice at a smooth interface for a path (or a photon) at its point (n: the
// normal facing it; indices n1 -> n2; F the reflectance; u uniform): the mirror direction,
// or the refraction into `next` (the object `next_obj` of it; -1 in the air). True when it
// reflected off a surface seen from the air.
inline bool fresnel_turn(Ray& ray, const glm::dvec3& n, double n1, double n2, double F, double u, MediumKind next,
                         int next_obj, MediumKind& medium, int& obj) {
  if (u < F) {
    ray.d = reflect_dir(ray.d, n);
    return medium == MediumKind::Air;
  }
  ray.d = glm::normalize(*refract_dir(ray.d, n, n1 / n2));  // F < 1: it refracts
  medium = next;
  obj = next == MediumKind::Air ? -1 : next_obj;
  return false;
}

}  // namespace draught
