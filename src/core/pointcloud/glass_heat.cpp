#include "core/pointcloud/glass_heat.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

std::optional<double> glass_heat(std::string_view name) {
  for (const GlassHeat& h : kGlassHeats)
    if (name == h.name) return h.kelvin;
  return std::nullopt;
}

double cooled_temperature(double start, double ambient, double seconds, double time_constant) {
  if (!(seconds > 0) || !(time_constant > 0)) return start;
  return ambient + (start - ambient) * std::exp(-seconds / time_constant);
}

double glass_cooling_rate(const GlassCooling& g, double t, double ta) {
  const double heat = g.density * g.heat_capacity * g.thickness;  // J / (m^2 K)
  const double flux = g.emissivity * kStefanBoltzmann * (t * t * t * t - ta * ta * ta * ta) +
                      g.convection * (t - ta);
  return -flux / heat;
}

double cooled_glass_temperature(const GlassCooling& g, double start, double ambient,
                                double seconds) {
  if (!(seconds > 0)) return start;
  // The linearised rate at the hotter end bounds how fast anything changes: steps of a
  // fiftieth of that time scale keep RK4 within about 1e-6 K per hundred steps.
  const double hot = std::max(start, ambient);
  const double k = (4 * g.emissivity * kStefanBoltzmann * hot * hot * hot + g.convection) /
                   (g.density * g.heat_capacity * g.thickness);
  const double scale = k > 0 ? 0.02 / k : seconds;
  const int n = static_cast<int>(std::clamp(std::ceil(seconds / scale), 1.0, 1e6));
  const double h = seconds / n;
  double t = start;
  for (int i = 0; i < n; ++i) {
    const double k1 = glass_cooling_rate(g, t, ambient);
    const double k2 = glass_cooling_rate(g, t + 0.5 * h * k1, ambient);
    const double k3 = glass_cooling_rate(g, t + 0.5 * h * k2, ambient);
    const double k4 = glass_cooling_rate(g, t + h * k3, ambient);
    t += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return t;
}

}  // namespace draught
