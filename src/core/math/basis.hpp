// Directions around a unit vector, for the Monte Carlo samplers (the reference tracer, the
// floor's photons, the lights' sampling).
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace draught {

// An orthonormal basis (t, b) around unit n (Duff et al. 2017): no branch, no singularity
// but at n.z = -1 exactly, which the sign choice avoids.
inline void basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double s = std::copysign(1.0, n.z), a = -1.0 / (s + n.z), c = n.x * n.y * a;
  t = {1 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

// The unit direction at cosine cos_t from n and azimuth phi about it.
inline glm::dvec3 around(const glm::dvec3& n, double cos_t, double phi) {
  glm::dvec3 t, b;
  basis(n, t, b);
  const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
  return glm::normalize(sin_t * std::cos(phi) * t + sin_t * std::sin(phi) * b + cos_t * n);
}

}  // namespace draught
