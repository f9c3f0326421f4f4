#include "core/environment/media_light.hpp"

#include "core/environment/image_patches.hpp"
#include "core/environment/sphere_grid.hpp"
#include "core/math/channels.hpp"
#include "generated/constants.hpp"

#include <algorithm>
#include <cstdlib>

namespace draught {

MediaLight media_light(const Studio& studio, const LightRig& rig, const SkyIrradiance& surround) {
  MediaLight m;
  m.surround = surround;
  if (!studio.image) {
    m.lights = rig.lights;
    if (m.lights.size() > size_t(contract::kMaxLights)) m.lights.resize(size_t(contract::kMaxLights));
    return m;
  }
  ImagePatches level = image_patches(studio, 32);
  std::vector<ImagePatch>& patches = level.patches;
  double power = 0, solid = 0;
  for (const ImagePatch& p : patches) {
    power += channel_mean(p.irradiance());
    solid += p.solid_angle;
  }
  const double mean_radiance = solid > 0 ? power / solid : 0.0;
  std::sort(patches.begin(), patches.end(), [](const ImagePatch& a, const ImagePatch& b) {
    return channel_mean(a.irradiance()) > channel_mean(b.irradiance());
  });
  std::vector<const ImagePatch*> taken;
  const auto beside = [&](const ImagePatch& p) {
    for (const ImagePatch* t : taken) {
      const int di = std::abs(p.i - t->i), dj = std::abs(p.j - t->j);
      if (dj <= 1 && std::min(di, level.width - di) <= 1) return true;
    }
    return false;
  };
  // A chosen patch's light is summed from the texels of the level the harmonics were
  // projected from (kImageProjectionWidth) that it covers, and those texels' share taken
  // out of them: exactly the light moved, the image less those texels left.
  const HdrImage& fine = image_level(*studio.image, kImageProjectionWidth);
  const int rx = std::max(1, fine.width / level.width), ry = std::max(1, fine.height / level.height);
  for (const ImagePatch& p : patches) {
    if (taken.size() == size_t(contract::kMaxLights)) break;
    if (!(channel_mean(p.radiance) > kMediaPatchContrast * mean_radiance)) break;  // the rest are dimmer still
    if (beside(p)) continue;  // (a lamp across two texels is one light and a little glow)
    taken.push_back(&p);
    ImagePatch light = p;
    glm::dvec3 e(0.0), towards(0.0);
    double solid_angle = 0;
    for (int j = p.j * ry; j < (p.j + 1) * ry; ++j)
      for (int i = p.i * rx; i < (p.i + 1) * rx; ++i) {
        const ImagePatch t = image_patch(studio, fine, i, j);
        e += t.irradiance();
        towards += channel_mean(t.irradiance()) * t.dir;
        solid_angle += t.solid_angle;
        const std::array<double, 9> y = SkyIrradiance::basis(t.dir);
        for (size_t k = 0; k < 9; ++k) m.surround.coef[k] -= t.irradiance() * (y[k] * kCosineBand[k]);
      }
    if (glm::length(towards) > 0) light.dir = glm::normalize(towards);
    light.solid_angle = solid_angle;
    light.radiance = e / solid_angle;
    m.lights.push_back(far_patch_light(light, rig.aim));
  }
  return m;
}

}  // namespace draught
