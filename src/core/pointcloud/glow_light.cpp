#include "core/pointcloud/glow_light.hpp"

#include "core/pointcloud/blackbody.hpp"
#include "generated/constants.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace draught {

const std::vector<glm::vec4>& picture_blackbody_table() {
  static const std::vector<glm::vec4> table =
      blackbody_table(contract::kBlackbodyEntries, contract::kBlackbodyMinK, contract::kBlackbodyMaxK);
  return table;
}

glm::dvec3 glow_table(double kelvin) {
  return blackbody_table_lookup(picture_blackbody_table(), contract::kBlackbodyMinK, contract::kBlackbodyMaxK, kelvin);
}

double hot_glass_extinction(double kelvin, double glow_depth) {
  return glow_depth > 0 ? std::clamp((kelvin - 700.0) / 400.0, 0.0, 1.0) / glow_depth : 0.0;
}

GlowSphere cloud_glow_sphere(const CloudFrame& c) {
  GlowSphere s;
  const PointCloud* pc = c.points.get();
  if (!pc || pc->size() == 0 || !(c.glow > 0) || !(c.glow_depth > 0)) return s;
  const std::size_t n = pc->size(), stride = std::max<std::size_t>(1, (n + kGlowSamples - 1) / kGlowSamples);
  const auto kelvin = [&](std::size_t i) {
    return pc->temperature.empty() ? double(c.temperature) : double(pc->temperature[i]);
  };
  glm::dvec3 centre(0.0);
  double blob = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; i += stride, ++count) {
    centre += glm::dvec3(pc->position[i]);
    blob += pc->radius_of(i);
  }
  centre /= double(count);
  blob /= double(count);
  double spread = 0;
  for (std::size_t i = 0; i < n; i += stride) {
    const glm::dvec3 r = glm::dvec3(pc->position[i]) - centre;
    spread += glm::dot(r, r);
  }
  const double radius = std::sqrt(5.0 / 3.0 * spread / double(count)) + blob;
  const double chord = 4.0 / 3.0 * radius;
  glm::dvec3 radiance(0.0);
  for (std::size_t i = 0; i < n; i += stride) {
    const double k = kelvin(i), emissivity = 1.0 - std::exp(-hot_glass_extinction(k, c.glow_depth) * chord);
    if (emissivity > 0) radiance += emissivity * glow_table(k);
  }
  const double f0 = std::pow((double(c.ior) - 1.0) / (double(c.ior) + 1.0), 2.0);
  s.radiance = radiance / double(count) * double(c.glow) * kGlowPerNit * (1.0 - f0);
  if (s.radiance.x + s.radiance.y + s.radiance.z > 0) {
    s.centre = centre;
    s.radius = radius;
  } else {
    s.radiance = glm::dvec3(0.0);
  }
  return s;
}

}  // namespace draught
