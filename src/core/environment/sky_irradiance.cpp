#include "core/environment/sky_irradiance.hpp"

#include "core/environment/image_patches.hpp"
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

glm::dvec3 SkyIrradiance::radiance(const glm::dvec3& d) const {
  const std::array<double, 9> y = basis(d);
  glm::dvec3 l(0.0);
  for (int i = 0; i < 9; ++i) l += coef[size_t(i)] / kCosineBand[size_t(i)] * y[size_t(i)];
  return glm::max(l, glm::dvec3(0.0));
}

namespace {

// An environment image projected texel by texel (of the first level at most 256 wide: each
// texel the mean of those above it), each weighted by its exact solid angle, so a small
// bright lamp in the image gives its whole light, not what a grid of directions meets.
SkyIrradiance image_irradiance(const Studio& studio) {
  const HdrImage& img = image_level(*studio.image, kImageProjectionWidth);
  SkyIrradiance s;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const ImagePatch p = image_patch(studio, img, i, j);
      const glm::dvec3 l = p.irradiance();
      const std::array<double, 9> y = SkyIrradiance::basis(p.dir);
      for (int k = 0; k < 9; ++k) s.coef[size_t(k)] += l * y[size_t(k)];
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
