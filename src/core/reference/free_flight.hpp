// Sampling through the media of a drink and a head, shared by every Monte Carlo tracer of
// the project (the reference path tracer, the floor's photons), so they follow one rule.
#pragma once

#include "core/foam/head_volume.hpp"
#include "core/math/channels.hpp"
#include "core/math/random.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace draught {

// Through a drink of this absorption and haze (scattering per metre) for t_end: absorbed
// (thr updated, true), or scattered by the haze at t_scatter (false). Spectral free-flight
// sampling: a channel picks the distance, the three channels' mean density weights it.
inline bool liquid_free_flight(const glm::dvec3& absorption, const glm::dvec3& haze, double t_end, glm::dvec3& thr,
                               double& t_scatter, Rng& rng) {
  const glm::dvec3 sigma_t = absorption + haze;
  if (std::max(haze.x, std::max(haze.y, haze.z)) <= 0) {
    thr *= glm::exp(-sigma_t * t_end);
    return true;
  }
  const int c = std::min(2, int(rng.uniform() * 3));
  const double t = sigma_t[c] > 0 ? -std::log(1 - rng.uniform()) / sigma_t[c] : std::numeric_limits<double>::infinity();
  if (t < t_end) {
    const glm::dvec3 tr = glm::exp(-sigma_t * t);
    thr *= tr * haze / channel_mean(sigma_t * tr);
    t_scatter = t;
    return false;
  }
  const glm::dvec3 tr = glm::exp(-sigma_t * t_end);
  thr *= tr / channel_mean(tr);
  return true;
}

// The head's transmittance along o + t d (its local frame) over [t0, t1], by ratio
// tracking (unbiased); below 1e-4 it counts as none.
inline double head_transmittance(const HeadVolume& head, const glm::dvec3& o, const glm::dvec3& d, double t0, double t1,
                                 Rng& rng) {
  const double M = head.majorant();
  double T = 1;
  for (double t = t0;;) {
    t -= std::log(1 - rng.uniform()) / M;
    if (t >= t1) return T;
    T *= 1 - std::min(head.density(o + t * d), M) / M;
    if (T < 1e-4) return 0;
  }
}

}  // namespace draught
