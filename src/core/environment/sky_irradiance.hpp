// The sky's light on a diffuse surface: Studio::sky projected onto the nine real
// spherical harmonics of bands 0-2 and convolved with the clamped cosine (Ramamoorthi
// and Hanrahan, "An efficient representation for irradiance environment maps", 2001).
// Irradiance is that smooth: nine numbers per colour give it within a few per cent for
// any sky, so the backdrop, the head and the haze read it, not a guessed ambient term.
// The picture's twin is sky_irradiance in shaders/lib/environment/studio.glsl.
#pragma once

#include "core/environment/studio.hpp"

#include <array>
#include <glm/glm.hpp>

namespace draught {

struct SkyIrradiance {
  // Coefficient i of basis function Y_i (the order of basis()), already multiplied by
  // the cosine's band factor (pi, 2 pi / 3, pi / 4): E(n) = sum_i coef[i] Y_i(n).
  std::array<glm::dvec3, 9> coef{};
  // The irradiance a surface of unit normal n receives from the whole sky (W / m^2 per
  // unit of the sky's radiance units), nothing in between.
  glm::dvec3 at(const glm::dvec3& n) const;
  // The radiance from direction d of the light these nine bands hold (each coefficient
  // over its cosine factor), at least 0: the smooth part of the sky, for what a surface
  // hides of it.
  glm::dvec3 radiance(const glm::dvec3& d) const;
  // The nine basis functions at unit direction d: 1; y, z, x; xy, yz, 3z^2 - 1, xz, x^2 - y^2
  // with their normalisations.
  static std::array<double, 9> basis(const glm::dvec3& d);
};

// Projects the studio's sky (Studio::sky: an environment image texel by texel; else the
// gradient, painted strips and glow, or the
// constant colour) by midpoint quadrature over the sphere.
SkyIrradiance sky_irradiance(const Studio&);

}  // namespace draught
