#include "core/reference/decal_optics.hpp"

#include "core/math/basis.hpp"
#include "core/reference/optics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

bool meets_decal(double& u, double F, double cover, bool from_air) {
  if (!(cover > 0)) return false;
  const double before = from_air ? F : 0.0, share = from_air ? (1 - F) * cover : cover;
  if (u >= before && u < before + share) return true;
  if (!from_air) u = (u - share) / std::max(1 - share, 1e-12);
  return false;
}

std::optional<glm::dvec3> decal_turn(const DecalSample& decal, const glm::dvec3& n, MediumKind next, int object,
                                     Ray& ray, MediumKind& medium, int& obj, glm::dvec3& thr, Rng& rng) {
  thr *= decal.tint;
  if (decal.kind == DecalKind::Metallic) {
    const double a = decal.roughness * decal.roughness, u = rng.uniform();
    const double cos_h = std::sqrt((1 - u) / (1 + (a * a - 1) * u));
    const glm::dvec3 d = reflect_dir(ray.d, around(n, cos_h, 2 * std::numbers::pi * rng.uniform()));
    ray.d = glm::dot(d, n) > 0 ? d : reflect_dir(ray.d, n);
    return std::nullopt;
  }
  glm::dvec3 side = n;
  if (decal.kind == DecalKind::Etched && rng.uniform() >= kFrostBackscatter) {
    side = -n;
    medium = next;
    obj = next == MediumKind::Air ? -1 : object;
  }
  return side;
}

glm::dvec3 decal_diffuse_direction(const glm::dvec3& side, Rng& rng, double& cos_t) {
  cos_t = std::sqrt(rng.uniform());
  return around(side, cos_t, 2 * std::numbers::pi * rng.uniform());
}

}  // namespace draught
