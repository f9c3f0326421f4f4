#include "core/liquid/haze.hpp"

#include "core/foam/head_volume.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

// I0(x) e^-x and I1(x) e^-x (x >= 0): the standard library's below 500, where e^x still
// fits a double with room; their asymptotic series beyond.
double i0_scaled(double x) {
  if (x < 500.0) return std::cyl_bessel_i(0.0, x) * std::exp(-x);
  return (1.0 + 1.0 / (8.0 * x) + 9.0 / (128.0 * x * x)) / std::sqrt(2.0 * std::numbers::pi * x);
}
double i1_scaled(double x) {
  if (x < 500.0) return std::cyl_bessel_i(1.0, x) * std::exp(-x);
  return (1.0 - 3.0 / (8.0 * x) - 15.0 / (128.0 * x * x)) / std::sqrt(2.0 * std::numbers::pi * x);
}

}  // namespace

HazeDiffusion haze_diffusion(double haze, const glm::dvec3& albedo, const glm::dvec3& absorption, double glass_ior) {
  HazeDiffusion d;
  if (!(haze > 0.0)) return d;
  const double wall = wall_diffuse_transmittance(glass_ior);
  for (int c = 0; c < 3; ++c) {
    const double a = std::clamp(albedo[c], 0.0, 1.0), colour = std::max(absorption[c], 0.0);
    const double sigma_s = haze * a, sigma_a = colour + haze - sigma_s, sigma_t = sigma_a + sigma_s;
    d.kappa[c] = std::max(colour, std::sqrt(3.0 * sigma_a * sigma_t));
    d.reach[c] = 2.0 / (3.0 * sigma_t) * (2.0 - wall) / wall;
  }
  return d;
}

glm::dvec3 haze_field(const HazeDiffusion& d, double r, double R) {
  glm::dvec3 share;
  for (int c = 0; c < 3; ++c) {
    const double inner = d.kappa[c] * std::clamp(r, 0.0, R), outer = d.kappa[c] * (R + d.reach[c]);
    share[c] = i0_scaled(inner) / i0_scaled(outer) * std::exp(inner - outer);
  }
  return share;
}

glm::dvec3 haze_field_mean(const HazeDiffusion& d, double R) {
  glm::dvec3 mean;
  for (int c = 0; c < 3; ++c) {
    // The mean of I0(k r) over the disc r < R is 2 I1(k R) / (k R) (1 where k R is 0).
    const double x = d.kappa[c] * R, outer = d.kappa[c] * (R + d.reach[c]);
    const double disc = x < 1e-6 ? i0_scaled(x) : 2.0 * i1_scaled(x) / x;
    mean[c] = disc / i0_scaled(outer) * std::exp(x - outer);
  }
  return mean;
}

}  // namespace draught
