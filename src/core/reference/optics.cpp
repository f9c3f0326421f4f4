#include "core/reference/optics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

double fresnel_dielectric(double cos_i, double n1, double n2) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const double eta = n1 / n2;
  const double sin2_t = eta * eta * (1 - cos_i * cos_i);
  if (sin2_t >= 1) return 1.0;
  const double cos_t = std::sqrt(1 - sin2_t);
  const double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  const double rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
  return 0.5 * (rs * rs + rp * rp);
}

std::optional<glm::dvec3> refract_dir(const glm::dvec3& i, const glm::dvec3& n, double eta) {
  const double c = -glm::dot(n, i);
  const double k = 1 - eta * eta * (1 - c * c);
  if (k < 0) return std::nullopt;
  return eta * i + (eta * c - std::sqrt(k)) * n;
}

glm::dvec3 reflect_dir(const glm::dvec3& i, const glm::dvec3& n) { return i - 2 * glm::dot(n, i) * n; }

}  // namespace draught
