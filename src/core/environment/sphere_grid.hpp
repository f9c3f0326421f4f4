// The sphere of directions cut into a theta x phi grid for projecting radiance onto
// spherical harmonics by midpoint quadrature (sky_irradiance, surround_irradiance), and
// the clamped cosine's band factors that turn a projection into irradiance (Ramamoorthi
// and Hanrahan 2001).
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace draught {

// Coefficient k of a radiance projection times kCosineBand[k] is coefficient k of the
// irradiance (pi, 2 pi / 3 for band 1, pi / 4 for band 2).
inline constexpr std::array<double, 9> kCosineBand = {
    std::numbers::pi,         2 * std::numbers::pi / 3, 2 * std::numbers::pi / 3,
    2 * std::numbers::pi / 3, std::numbers::pi / 4,     std::numbers::pi / 4,
    std::numbers::pi / 4,     std::numbers::pi / 4,     std::numbers::pi / 4};

// Calls f(d, solid angle) for the middle direction d (unit, y up) of each cell of an
// n_theta x n_phi grid; the solid angle is the cell's exact one (the integral of
// sin(theta) over it), so a constant projects exactly.
template <class F>
void for_each_sphere_cell(int n_theta, int n_phi, F&& f) {
  const double dt = std::numbers::pi / n_theta, dp = 2 * std::numbers::pi / n_phi;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = (i + 0.5) * dt, st = std::sin(theta), ct = std::cos(theta);
    const double weight = (std::cos(i * dt) - std::cos((i + 1) * dt)) * dp;
    for (int j = 0; j < n_phi; ++j) {
      const double phi = (j + 0.5) * dp;
      f(glm::dvec3(st * std::cos(phi), ct, st * std::sin(phi)), weight);
    }
  }
}

}  // namespace draught
