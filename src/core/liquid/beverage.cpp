#include "core/liquid/beverage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

constexpr double kFirstNm = 380.0, kStepNm = 10.0;
// CIE illuminant D65, relative spectral power, 380-730 nm in 10 nm steps (CIE 15:2004).
constexpr std::array<double, 36> kD65 = {
    49.9755, 54.6482, 82.7549, 91.486,  93.4318, 86.6823, 104.865, 117.008, 117.812,
    114.861, 115.923, 108.811, 109.354, 107.802, 104.790, 107.689, 104.405, 104.046,
    100.000, 96.3342, 95.788,  88.6856, 90.0062, 89.5991, 87.6987, 83.2886, 83.6992,
    80.0268, 80.2146, 82.2778, 78.2842, 69.7213, 71.6091, 74.349,  61.604,  69.8856};

// Wyman, Sloan and Shirley (JCGT 2013): piecewise Gaussian lobes.
double lobe(double nm, double mu, double below, double above) {
  const double t = (nm - mu) / (nm < mu ? below : above);
  return std::exp(-0.5 * t * t);
}
glm::dvec3 cie1931_xyz(double nm) {
  return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
              0.065 * lobe(nm, 501.1, 20.4, 26.2),
          0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
          1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}
// XYZ -> linear sRGB (IEC 61966-2-1).
glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& c) {
  return {3.2406 * c.x - 1.5372 * c.y - 0.4986 * c.z, -0.9689 * c.x + 1.8758 * c.y + 0.0415 * c.z,
          0.0557 * c.x - 0.2040 * c.y + 1.0570 * c.z};
}

// The weight of each wavelength in each channel: D65 times the positive part of the sRGB
// colour matching functions (the negative lobes would let a filter drive a channel
// below zero; without them a channel's transmittance is a weighted mean of T(l)).
glm::dvec3 channel_weight(std::size_t i) {
  const double nm = kFirstNm + kStepNm * double(i);
  return kD65[i] * glm::max(xyz_to_linear_srgb(cie1931_xyz(nm)), glm::dvec3(0.0));
}

}  // namespace

glm::dvec3 channel_transmittance(const std::function<double(double)>& absorbance_per_cm, double metres) {
  glm::dvec3 through{0.0}, white{0.0};
  for (std::size_t i = 0; i < kD65.size(); ++i) {
    const double nm = kFirstNm + kStepNm * double(i);
    const glm::dvec3 w = channel_weight(i);
    through += w * std::pow(10.0, -absorbance_per_cm(nm) * metres * 100.0);
    white += w;
  }
  return glm::clamp(through / white, glm::dvec3(kMinChannelTransmittance), glm::dvec3(1.0));
}

double absorbance_per_cm_to_absorption(double a) { return a * std::numbers::ln10 * 100.0; }

glm::vec3 spectrum_to_absorption(const std::function<double(double)>& absorbance_per_cm, double metres) {
  return glm::vec3(-glm::log(channel_transmittance(absorbance_per_cm, metres)) / metres);
}

double ebc_to_srm(double ebc) { return ebc / kEbcPerSrm; }

double beer_absorbance(double srm, double nm) {
  const double x = nm - 430.0;
  return srm / kSrmPerA430 * (0.02465 * std::exp(-x / 17.591) + 0.97535 * std::exp(-x / 82.122));
}

glm::vec3 srm_to_absorption(float srm, double metres) {
  if (srm <= 0.0f) return glm::vec3(0.0f);
  return spectrum_to_absorption([srm](double nm) { return beer_absorbance(srm, nm); }, metres);
}

double wine_absorbance(const glm::vec3& a, double nm) {
  if (nm <= 420.0) return a[0];
  if (nm <= 520.0) return a[0] + (a[1] - a[0]) * (nm - 420.0) / 100.0;
  if (nm <= 620.0) return a[1] + (a[2] - a[1]) * (nm - 520.0) / 100.0;
  if (a[2] <= 0.0f || a[1] <= a[2]) return a[2];
  // The anthocyanin band's Gaussian fall from 520 nm, its width set by A620 / A520:
  // A(l) = A520 exp(-(l - 520)^2 / (2 s^2)), which meets A620 at 620 nm.
  const double two_s2 = 100.0 * 100.0 / std::log(double(a[1]) / a[2]), x = nm - 520.0;
  return a[1] * std::exp(-x * x / two_s2);
}

glm::vec3 wine_to_absorption(const glm::vec3& a420_520_620, double metres) {
  if (a420_520_620 == glm::vec3(0.0f)) return glm::vec3(0.0f);
  return spectrum_to_absorption([a420_520_620](double nm) { return wine_absorbance(a420_520_620, nm); }, metres);
}

glm::vec3 liquid_absorption(const LiquidParams& l, double metres) {
  if (l.ebc > 0) return srm_to_absorption(float(ebc_to_srm(l.ebc)), metres);
  if (l.srm > 0) return srm_to_absorption(l.srm, metres);
  if (l.wine.x > 0 || l.wine.y > 0 || l.wine.z > 0) return wine_to_absorption(l.wine, metres);
  return l.absorption;
}

}  // namespace draught
