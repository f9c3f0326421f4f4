#include "core/pointcloud/blackbody.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

// CODATA 2018 exact SI constants.
constexpr double kPlanck = 6.62607015e-34;     // J s
constexpr double kLight = 299792458.0;         // m / s
constexpr double kBoltzmann = 1.380649e-23;    // J / K

// Composite Simpson over [a, b] with an even count of intervals near `step` wide.
template <class F>
double simpson(F f, double a, double b, double step) {
  int n = std::max(2, static_cast<int>(std::ceil((b - a) / step)));
  n += n & 1;
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i & 1 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

}  // namespace

double planck_radiance(double wavelength_m, double kelvin) {
  if (!(kelvin > 0) || !(wavelength_m > 0)) return 0.0;
  const double x = kPlanck * kLight / (wavelength_m * kBoltzmann * kelvin);
  if (x > 700) return 0.0;  // exp would overflow; the radiance is below 1e-290 anyway
  const double l5 = std::pow(wavelength_m, 5);
  return 2.0 * kPlanck * kLight * kLight / (l5 * std::expm1(x));
}

double blackbody_band_radiance(double kelvin, double min_nm, double max_nm, double step_nm) {
  // Integrated in nm, the radiance per nm is per metre times 1e-9.
  return simpson([&](double nm) { return planck_radiance(nm * 1e-9, kelvin) * 1e-9; }, min_nm,
                 max_nm, step_nm);
}

glm::dvec3 blackbody_xyz(double kelvin) {
  if (!(kelvin > 0)) return glm::dvec3(0.0);
  glm::dvec3 sum(0.0);
  // Simpson by hand over the three functions at once (one Planck evaluation per node).
  const int n = static_cast<int>((kBlackbodyMaxNm - kBlackbodyMinNm) / kBlackbodyStepNm);
  static_assert(static_cast<int>((kBlackbodyMaxNm - kBlackbodyMinNm) / kBlackbodyStepNm) % 2 == 0);
  for (int i = 0; i <= n; ++i) {
    const double nm = kBlackbodyMinNm + i * kBlackbodyStepNm;
    const double w = (i == 0 || i == n) ? 1.0 : (i & 1 ? 4.0 : 2.0);
    sum += w * planck_radiance(nm * 1e-9, kelvin) * cie1931_cmf(nm);
  }
  // Radiance per metre times nm steps: 1e-9 m per nm.
  return sum * (kBlackbodyStepNm * 1e-9 / 3.0) * kLuminousEfficacy;
}

glm::dvec2 blackbody_chromaticity(double kelvin) {
  const glm::dvec3 c = blackbody_xyz(kelvin);
  const double s = c.x + c.y + c.z;
  return s > 0 ? glm::dvec2(c.x / s, c.y / s) : glm::dvec2(0.0);
}

glm::dmat3 xyz_to_linear_srgb() {
  // Columns of RGB -> XYZ are the primaries' XYZ (Y = 1) scaled so that (1, 1, 1) is
  // D65's white with Y = 1.
  auto xyz = [](double x, double y) { return glm::dvec3(x / y, 1.0, (1.0 - x - y) / y); };
  const glm::dmat3 p(xyz(0.64, 0.33), xyz(0.30, 0.60), xyz(0.15, 0.06));
  const glm::dvec3 s = glm::inverse(p) * xyz(0.3127, 0.3290);
  const glm::dmat3 to_xyz(p[0] * s.x, p[1] * s.y, p[2] * s.z);
  return glm::inverse(to_xyz);
}

glm::dvec3 blackbody_linear_rgb(double kelvin) {
  static const glm::dmat3 m = xyz_to_linear_srgb();
  // Outside the gamut (low temperatures) blue comes out negative: clamp, light is not.
  return glm::max(m * blackbody_xyz(kelvin), glm::dvec3(0.0));
}

std::vector<glm::vec4> blackbody_table(int entries, double kelvin_min, double kelvin_max) {
  if (entries < 2 || entries > kBlackbodyMaxEntries)
    throw std::invalid_argument("blackbody_table: entries is " + std::to_string(entries) +
                                ", expected 2 to " + std::to_string(kBlackbodyMaxEntries));
  if (!(kelvin_min > 0) || !(kelvin_max > kelvin_min) || !std::isfinite(kelvin_max))
    throw std::invalid_argument("blackbody_table: kelvin range [" + std::to_string(kelvin_min) +
                                ", " + std::to_string(kelvin_max) +
                                "], expected 0 < min < max, finite");
  std::vector<glm::vec4> table;
  table.reserve(entries);
  for (int i = 0; i < entries; ++i) {
    const double inv = 1.0 / kelvin_min + (1.0 / kelvin_max - 1.0 / kelvin_min) * i / (entries - 1);
    const double t = 1.0 / inv;
    const double y = blackbody_xyz(t).y;
    if (!(y > 0))
      throw std::invalid_argument("blackbody_table: kelvin_min " + std::to_string(kelvin_min) +
                                  " is too cold, no visible light to take the log of");
    table.emplace_back(glm::vec3(blackbody_linear_rgb(t) / y), static_cast<float>(std::log(y)));
  }
  return table;
}

glm::dvec3 blackbody_table_lookup(const std::vector<glm::vec4>& table, double kelvin_min,
                                  double kelvin_max, double kelvin) {
  if (!(kelvin > 0) || table.size() < 2) return glm::dvec3(0.0);
  const int n = static_cast<int>(table.size());
  const double u = (1.0 / kelvin_min - 1.0 / kelvin) / (1.0 / kelvin_min - 1.0 / kelvin_max) * (n - 1);
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, n - 2);
  const double f = u - i;
  const glm::dvec4 a(table[i]), b(table[i + 1]);
  const glm::dvec3 colour = glm::mix(glm::dvec3(a), glm::dvec3(b), std::clamp(f, 0.0, 1.0));
  const double log_y = a.w + (b.w - a.w) * std::min(f, 1.0);
  return colour * std::exp(log_y);
}

}  // namespace draught
