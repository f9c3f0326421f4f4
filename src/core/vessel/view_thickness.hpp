// How much glass the view crosses straight on from the first surface it meets (the MatCap
// tier's thickness mask, docs/MATCAP.md): no refraction, the glass's profile taken as the
// cylinders through the hit's height. Twin of view_thickness in
// shaders/lib/vessel/thickness.glsl; tests/gpu/test_matcap.cpp compares them pixel by pixel.
#pragma once

#include "core/vessel/vessel.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

namespace draught {

// p: the surface point, d: the view's direction (unit), both in the vessel's frame; m: the
// surface. Through a wall: to the cavity (the inner cylinder), else out of the outer one
// (near the silhouette the line runs along the wall: the thick edge); through the solid
// base, stem or foot: out of the outer cylinder or the slab 0 <= y <= base; through the rim
// bead: the chord of its circle's sphere; 0 for surfaces that are not glass.
double view_thickness(const Vessel&, const glm::dvec3& p, const glm::dvec3& d, contract::Material m);

}  // namespace draught
