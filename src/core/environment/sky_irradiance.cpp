#include "core/environment/sky_irradiance.hpp"

#include <cmath>
#include <numbers>

namespace draught {

std::array<double, 9> SkyIrradiance::basis(const glm::dvec3& d) {
  return {0.282095,
          0.488603 * d.y,
          0.488603 * d.z,
          0.488603 * d.x,
          1.092548 * d.x * d.y,
          1.092548 * d.y * d.z,
          0.315392 * (3 * d.z * d.z - 1),
          1.092548 * d.x * d.z,
          0.546274 * (d.x * d.x - d.y * d.y)};
}

glm::dvec3 SkyIrradiance::at(const glm::dvec3& n) const {
  const std::array<double, 9> y = basis(n);
  glm::dvec3 e(0.0);
  for (int i = 0; i < 9; ++i) e += coef[size_t(i)] * y[size_t(i)];
  return glm::max(e, glm::dvec3(0.0));
}

SkyIrradiance sky_irradiance(const Studio& studio) {
  constexpr double kPi = std::numbers::pi;
  // 64 x 128 cells: the painted strips (a few degrees wide) are resolved well enough for
  // irradiance, which only keeps their low frequencies.
  constexpr int kTheta = 64, kPhi = 128;
  const double band[9] = {kPi, 2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4, kPi / 4, kPi / 4, kPi / 4, kPi / 4};
  SkyIrradiance s;
  const double dt = kPi / kTheta, dp = 2 * kPi / kPhi;
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * dt, st = std::sin(theta), ct = std::cos(theta);
    // The integral of sin(theta) over the cell, exact, so a constant sky projects exactly.
    const double weight = (std::cos(i * dt) - std::cos((i + 1) * dt)) * dp;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * dp;
      const glm::dvec3 d(st * std::cos(phi), ct, st * std::sin(phi));
      const glm::dvec3 l = studio.sky(d) * weight;
      const std::array<double, 9> y = SkyIrradiance::basis(d);
      for (int k = 0; k < 9; ++k) s.coef[size_t(k)] += l * y[size_t(k)];
    }
  }
  for (int k = 0; k < 9; ++k) s.coef[size_t(k)] *= band[k];
  return s;
}

}  // namespace draught
