// Sampling through the media of a drink and a head, shared by every Monte Carlo tracer of
// the project (the reference path tracer, the floor's photons), so they follow one rule.
#pragma once

#include "core/foam/head_volume.hpp"
#include "core/liquid/beverage.hpp"
#include "core/math/channels.hpp"
#include "core/math/random.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace draught {

// A drink as a Monte Carlo path crosses it: its colour's two bands per channel (core
// DrinkAbsorption), and its haze: what scatters (per metre, colour x amount) and what the
// haze absorbs beside it (its share 1 - haze colour).
struct DrinkMedium {
  DrinkAbsorption colour;
  glm::dvec3 haze{0.0}, haze_absorption{0.0};
};

// Through a drink for t_end, `left` the shares of the path's light in the drink's colour
// bands (DrinkAbsorption::onward; updated): absorbed (thr updated, true), or scattered by
// the haze at t_scatter (false). The haze's extinction is sampled (spectral free-flight
// sampling: a channel picks the distance, the three channels' mean density weights it);
// the drink's colour weighs the path deterministically, so one path's stretches multiply
// to the bands' transmittance of their sum (exact for the bands, however the haze turns it).
inline bool liquid_free_flight(const DrinkMedium& m, glm::dvec3& left, double t_end, glm::dvec3& thr,
                               double& t_scatter, Rng& rng) {
  const glm::dvec3 sigma_t = m.haze_absorption + m.haze;
  if (std::max(m.haze.x, std::max(m.haze.y, m.haze.z)) <= 0) {
    thr *= glm::exp(-sigma_t * t_end) * m.colour.onward(left, t_end);
    return true;
  }
  const int c = std::min(2, int(rng.uniform() * 3));
  const double t = sigma_t[c] > 0 ? -std::log(1 - rng.uniform()) / sigma_t[c] : std::numeric_limits<double>::infinity();
  if (t < t_end) {
    const glm::dvec3 tr = glm::exp(-sigma_t * t);
    thr *= tr * m.haze / channel_mean(sigma_t * tr) * m.colour.onward(left, t);
    t_scatter = t;
    return false;
  }
  const glm::dvec3 tr = glm::exp(-sigma_t * t_end);
  thr *= tr / channel_mean(tr) * m.colour.onward(left, t_end);
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
