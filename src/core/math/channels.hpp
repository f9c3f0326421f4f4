// RGB triples taken as one number: the Monte Carlo samplers weigh, sort and compare light
// by its channels' mean (the reference tracer, the floor's photons, the media's lights).
#pragma once

#include <glm/glm.hpp>

namespace draught {

inline double channel_mean(const glm::dvec3& v) { return (v.x + v.y + v.z) / 3.0; }

}  // namespace draught
