// The CIE 1931 colour matching functions by Wyman, Sloan and Shirley's multi-lobe fit
// ("Simple Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2),
// 2013): the drink's spectral absorption and the hot glass's Planck glow both weigh
// wavelengths with them.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace draught {

namespace cie1931_detail {
// A Gaussian with a different width either side of its mean (the fit's lobe).
inline double lobe(double x, double mean, double sigma_below, double sigma_above) {
  const double t = (x - mean) / (x < mean ? sigma_below : sigma_above);
  return std::exp(-0.5 * t * t);
}
}  // namespace cie1931_detail

// xbar, ybar, zbar at a wavelength in nm (dimensionless, ybar peaks near 1 at 555 nm).
inline glm::dvec3 cie1931_cmf(double nm) {
  using cie1931_detail::lobe;
  const double x = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                   0.065 * lobe(nm, 501.1, 20.4, 26.2);
  const double y = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
  const double z = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
  return {x, y, z};
}

}  // namespace draught
