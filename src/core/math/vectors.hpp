// Small vector helpers that the simulation, the input drivers and the Monte Carlo samplers
// share.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace draught {

// v shortened to at most max_len, its direction kept.
template <glm::length_t N, glm::qualifier Q>
glm::vec<N, double, Q> clamp_length(const glm::vec<N, double, Q>& v, double max_len) {
  const double len = glm::length(v);
  return len > max_len ? v * (max_len / len) : v;
}

inline bool all_finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline double max_component(const glm::dvec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

}  // namespace draught
