// Which medium lies across a surface: the one rule, in C++. Its GLSL twin is
// medium_across() in shaders/lib/vessel/media.glsl; tests/gpu probes compare the two.
#pragma once

#include "core/reference/intersect.hpp"

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

}  // namespace draught
