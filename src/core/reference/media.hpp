// Which medium lies across a surface: the one rule, in C++. Its GLSL twin is
// medium_across() in shaders/lib/vessel/media.glsl; tests/gpu probes compare the two.
#pragma once

#include "core/reference/free_flight.hpp"
#include "core/reference/intersect.hpp"
#include "core/reference/optics.hpp"
#include "core/scene/frame.hpp"

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

// A glass and its drink as paths and photons cross them (the reference path tracer's and
// the floor's photons'): the glass's frame, the indices, the glass's absorption and the
// drink's, as the picture's medium_transmittance and haze_inscatter take them (its
// colour and the haze; of the haze, the haze colour scatters and the rest absorbs).
struct VesselOptics {
  glm::dquat to_local, to_world;
  glm::dvec3 position{0.0};
  double glass_ior = 1.5, liquid_ior = 1.33;
  glm::dvec3 glass_absorption{0.0};
  DrinkMedium drink;
  glm::dvec3 local_point(const glm::dvec3& p) const { return to_local * (p - position); }
  glm::dvec3 local_dir(const glm::dvec3& d) const { return to_local * d; }
  double ior(MediumKind m) const {
    return m == MediumKind::Glass ? glass_ior : (m == MediumKind::Liquid ? liquid_ior : 1.0);
  }
};

inline VesselOptics vessel_optics(const VesselFrame& vf) {
  VesselOptics m;
  m.to_world = vf.pose.orientation;
  m.to_local = glm::inverse(vf.pose.orientation);
  m.position = vf.pose.position;
  m.glass_ior = vf.params.glass.ior;
  m.liquid_ior = vf.params.liquid.ior;
  m.glass_absorption = glm::dvec3(vf.params.glass.absorption);
  m.drink.colour = vf.liquid_absorption;
  const double haze = vf.params.liquid.haze;
  m.drink.haze = haze * glm::dvec3(vf.params.liquid.haze_color);
  m.drink.haze_absorption = glm::dvec3(haze) - m.drink.haze;
  return m;
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
