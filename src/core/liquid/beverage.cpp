#include "core/liquid/beverage.hpp"

#include <cmath>
#include <numbers>

namespace draught {

double absorbance_per_cm_to_absorption(double a) { return a * std::numbers::ln10 * 100.0; }

double ebc_to_srm(double ebc) { return ebc / kEbcPerSrm; }

double beer_absorbance(double srm, double nm) {
  const double x = nm - 430.0;
  return srm / kSrmPerA430 * (0.02465 * std::exp(-x / 17.591) + 0.97535 * std::exp(-x / 82.122));
}

glm::vec3 srm_to_absorption(float srm) {
  glm::vec3 a;
  for (int c = 0; c < 3; ++c) a[c] = float(absorbance_per_cm_to_absorption(beer_absorbance(srm, kChannelWavelength[c])));
  return a;
}

double wine_absorbance(const glm::vec3& a, double nm) {
  if (nm <= 420.0) return a[0];
  if (nm <= 520.0) return a[0] + (a[1] - a[0]) * (nm - 420.0) / 100.0;
  if (nm <= 620.0) return a[1] + (a[2] - a[1]) * (nm - 520.0) / 100.0;
  return a[2];
}

glm::vec3 wine_to_absorption(const glm::vec3& a420_520_620) {
  glm::vec3 a;
  for (int c = 0; c < 3; ++c)
    a[c] = float(absorbance_per_cm_to_absorption(wine_absorbance(a420_520_620, kChannelWavelength[c])));
  return a;
}

glm::vec3 liquid_absorption(const LiquidParams& l) {
  if (l.ebc > 0) return srm_to_absorption(float(ebc_to_srm(l.ebc)));
  if (l.srm > 0) return srm_to_absorption(l.srm);
  if (l.wine.x > 0 || l.wine.y > 0 || l.wine.z > 0) return wine_to_absorption(l.wine);
  return l.absorption;
}

}  // namespace draught
