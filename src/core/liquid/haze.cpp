#include "core/liquid/haze.hpp"

#include "core/foam/head_volume.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

// I_n(x) e^-x (n = 0, 1; x >= 0): below 40 the power series sum (x / 2)^(2k + n) /
// (k! (k + n)!), every term positive (nothing cancels), each scaled by e^-x as it goes so
// that nothing overflows; beyond, the asymptotic series 1 / sqrt(2 pi x) sum_k (-1)^k
// a_k(n) / x^k, a_k = prod_{j <= k} (4 n^2 - (2j - 1)^2) / (8 j), to its 12th term
// (relative error far below 1e-12 there). (The standard library's cyl_bessel_i is not in
// every library the project builds with: the web build's has none.)
double bessel_scaled(int n, double x) {
  x = std::max(x, 0.0);
  if (x < 40.0) {
    double term = std::exp(-x) * (n == 1 ? 0.5 * x : 1.0), sum = term;
    const double q = 0.25 * x * x;
    for (int k = 1; k < 400; ++k) {
      term *= q / (double(k) * double(k + n));
      sum += term;
      if (term < 1e-17 * sum) break;
    }
    return sum;
  }
  const double mu = 4.0 * n * n;
  double term = 1.0, sum = 1.0;
  for (int k = 1; k <= 12; ++k) {
    term *= -(mu - double(2 * k - 1) * double(2 * k - 1)) / (8.0 * k * x);
    sum += term;
  }
  return sum / std::sqrt(2.0 * std::numbers::pi * x);
}

}  // namespace

double bessel_i0_scaled(double x) { return bessel_scaled(0, x); }
double bessel_i1_scaled(double x) { return bessel_scaled(1, x); }

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
    share[c] = bessel_i0_scaled(inner) / bessel_i0_scaled(outer) * std::exp(inner - outer);
  }
  return share;
}

glm::dvec3 haze_field_mean(const HazeDiffusion& d, double R) {
  glm::dvec3 mean;
  for (int c = 0; c < 3; ++c) {
    // The mean of I0(k r) over the disc r < R is 2 I1(k R) / (k R) (1 where k R is 0).
    const double x = d.kappa[c] * R, outer = d.kappa[c] * (R + d.reach[c]);
    const double disc = x < 1e-6 ? bessel_i0_scaled(x) : 2.0 * bessel_i1_scaled(x) / x;
    mean[c] = disc / bessel_i0_scaled(outer) * std::exp(x - outer);
  }
  return mean;
}

}  // namespace draught
