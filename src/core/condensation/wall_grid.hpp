// How the renderer finds a glass's condensation where a path meets its outer wall: not by
// marching over every bead, but through the wall's (angle, height) grid. The cold band is
// cut into CONDENSATION_ANGLES x CONDENSATION_ROWS cells; each lists the beads whose base
// touches it (at most CONDENSATION_SLOTS: beads never overlap, so few touch one cell), so
// a wall point costs CONDENSATION_SLOTS texel fetches. The fog is a map over the same
// band, read with linear filtering. A bead is a water lens on the glass: a spherical cap
// on its circular base, drawn by its normal (the lens bends and mirrors like a cap; its
// millimetre of height is not traced).
//
// C++ twin of shaders/lib/vessel/condensation.glsl (condensation_bead, condensation_fog):
// tests/gpu/test_condensation.cpp compares them pixel by pixel.
#pragma once

#include "core/condensation/condensation.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace draught {

// One glass's bead grid: CONDENSATION_ROWS rows of CONDENSATION_ANGLES x
// CONDENSATION_SLOTS texels; texel (angle, height, base radius, w) of a bead, radius 0 in
// an empty slot. A cell holding more beads than slots keeps those whose base touches it
// (w = 1; the others are listed for the fog they cleared round them, w = 0), then the
// largest.
std::vector<glm::vec4> bead_grid(const CondensationState&, const Vessel&);

// The fog map as the GPU holds it (R8): CONDENSATION_FOG_ROWS rows of
// CONDENSATION_FOG_ANGLES bytes, 255 fully fogged.
std::vector<std::uint8_t> fog_texels(const CondensationState&);

// What a wall point shows of the condensation.
struct BeadSample {
  bool found = false;    // the point lies on a bead's base
  glm::vec3 normal{0};   // the bead's cap there (outward, local frame); the wall's elsewhere
  float clear = 1;       // what is left of the fog: 0 under a bead, rising to 1 half a radius beyond its edge (the bead drank the mist around it)
};

// The bead at local point p of the outer wall (outward normal n, local), from one glass's
// grid. Twin of condensation_bead.
BeadSample bead_at(const std::vector<glm::vec4>& grid, const CondensationBand&, float contact_angle, glm::vec3 p,
                   glm::vec3 n);

// The fog's cover at local point p of the outer wall, bilinear between texel centres
// (wrapping round the axis, clamped at the band's ends) as the GPU's filtering reads the
// R8 map, 0 outside the band. Twin of condensation_fog.
float fog_at(const std::vector<std::uint8_t>& fog, const CondensationBand&, glm::vec3 p);

}  // namespace draught
