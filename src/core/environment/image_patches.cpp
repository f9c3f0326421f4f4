#include "core/environment/image_patches.hpp"
#include "core/math/constants.hpp"

#include <cmath>
#include <numbers>

namespace draught {

const HdrImage& image_level(const EnvironmentMap& map, int max_width) {
  size_t level = 0;
  while (level + 1 < map.levels.size() && map.levels[level].width > max_width) ++level;
  return map.levels[level];
}

ImagePatch image_patch(const Studio& studio, const HdrImage& img, int i, int j) {
  const double t0 = kPi * j / img.height, t1 = kPi * (j + 1) / img.height;
  ImagePatch p;
  p.dir = studio.world_direction(equirect_direction({(i + 0.5) / img.width, (j + 0.5) / img.height}));
  p.radiance = glm::dvec3(img.at(i, j)) * double(studio.env.intensity);
  p.solid_angle = (std::cos(t0) - std::cos(t1)) * 2 * kPi / img.width;
  p.i = i;
  p.j = j;
  return p;
}

ImagePatches image_patches(const Studio& studio, int max_width, bool upper_half) {
  ImagePatches out;
  if (!studio.image) return out;
  const HdrImage& img = image_level(*studio.image, max_width);
  out.width = img.width;
  out.height = img.height;
  const int rows = upper_half ? img.height / 2 : img.height;
  out.patches.reserve(size_t(rows) * size_t(img.width));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < img.width; ++i) out.patches.push_back(image_patch(studio, img, i, j));
  return out;
}

AreaLight far_patch_light(const ImagePatch& patch, const glm::dvec3& centre) {
  AreaLight l;
  l.shape = LightShape::Sphere;
  l.radius = kImageEmitterDistance * std::sqrt(patch.solid_angle / std::numbers::pi);  // its solid angle
  l.center = centre + kImageEmitterDistance * patch.dir;
  l.radiance = patch.radiance;
  return l;
}

}  // namespace draught
