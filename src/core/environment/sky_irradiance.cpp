#include "core/environment/sky_irradiance.hpp"

#include "core/environment/sphere_grid.hpp"

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

namespace {

// An environment image projected texel by texel (of the first level at most 256 wide: each
// texel the mean of those above it), each weighted by its exact solid angle, so a small
// bright lamp in the image gives its whole light, not what a grid of directions meets.
SkyIrradiance image_irradiance(const Studio& studio) {
  constexpr double kPi = std::numbers::pi;
  const EnvironmentMap& map = *studio.image;
  size_t level = 0;
  while (level + 1 < map.levels.size() && map.levels[level].width > 256) ++level;
  const HdrImage& img = map.levels[level];
  SkyIrradiance s;
  const double dp = 2 * kPi / img.width, dt = kPi / img.height;
  for (int j = 0; j < img.height; ++j) {
    const double weight = (std::cos(j * dt) - std::cos((j + 1) * dt)) * dp * double(studio.env.intensity);
    for (int i = 0; i < img.width; ++i) {
      const glm::dvec3 d = studio.world_direction(equirect_direction({(i + 0.5) / img.width, (j + 0.5) / img.height}));
      const glm::dvec3 l = glm::dvec3(img.at(i, j)) * weight;
      const std::array<double, 9> y = SkyIrradiance::basis(d);
      for (int k = 0; k < 9; ++k) s.coef[size_t(k)] += l * y[size_t(k)];
    }
  }
  return s;
}

}  // namespace

SkyIrradiance sky_irradiance(const Studio& studio) {
  if (studio.image) {
    SkyIrradiance s = image_irradiance(studio);
    for (int k = 0; k < 9; ++k) s.coef[size_t(k)] *= kCosineBand[size_t(k)];
    return s;
  }
  // 64 x 128 cells: the painted strips (a few degrees wide) are resolved well enough for
  // irradiance, which only keeps their low frequencies.
  SkyIrradiance s;
  for_each_sphere_cell(64, 128, [&](const glm::dvec3& d, double weight) {
    const glm::dvec3 l = studio.sky(d) * weight;
    const std::array<double, 9> y = SkyIrradiance::basis(d);
    for (int k = 0; k < 9; ++k) s.coef[size_t(k)] += l * y[size_t(k)];
  });
  for (int k = 0; k < 9; ++k) s.coef[size_t(k)] *= kCosineBand[size_t(k)];
  return s;
}

}  // namespace draught
