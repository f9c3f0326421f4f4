// How hot glass is and how it cools: named temperatures for presets, Newton's law, and
// Newton plus radiation (glass above ~800 K loses most of its heat by radiating).
// docs/POINT_CLOUDS.md.
#pragma once

#include <optional>
#include <string_view>

namespace draught {

inline constexpr double kStefanBoltzmann = 5.670374419e-8;  // W / (m^2 K^4)
inline constexpr double kZeroCelsius = 273.15;              // K

// A named temperature of glass, for presets.
struct GlassHeat {
  const char* name;
  double kelvin;
};
// gob: 1100 C, fresh from the furnace, bright orange; working: 950 C, being shaped;
// cooling: 700 C, a dull red; cooled: 20 C, room temperature (no visible glow).
inline constexpr GlassHeat kGlassHeats[] = {
    {"gob", 1100 + kZeroCelsius},
    {"working", 950 + kZeroCelsius},
    {"cooling", 700 + kZeroCelsius},
    {"cooled", 20 + kZeroCelsius},
};
// The temperature of a named heat, or nothing for an unknown name.
std::optional<double> glass_heat(std::string_view name);

// Newton's cooling: ambient + (start - ambient) exp(-seconds / time_constant).
// A time constant that is not positive means no cooling; seconds <= 0 give start.
double cooled_temperature(double start_kelvin, double ambient_kelvin, double seconds,
                          double time_constant);

// A piece of glass cooling by radiation to surroundings at ambient and by convection:
//   rho c L dT/dt = -eps sigma (T^4 - Ta^4) - h (T - Ta),
// L = volume / surface area (r / 3 for a ball of radius r).
struct GlassCooling {
  double thickness = 0.04 / 3;   // m, volume / area, [1e-4, 1]; a 4 cm gob's by default
  double density = 2500;         // kg/m^3, [2000, 3000]; soda-lime glass
  double heat_capacity = 1250;   // J/(kg K), [700, 1600]; soda-lime glass when hot
  double emissivity = 0.9;       // [0, 1]; glass is nearly black in the infrared
  double convection = 10;        // W/(m^2 K), [0, 100]; still air
};
// dT/dt in K/s (negative when hotter than ambient).
double glass_cooling_rate(const GlassCooling&, double kelvin, double ambient_kelvin);
// The temperature after `seconds`, integrated by RK4 in steps short against the
// cooling's time scale (deterministic; seconds <= 0 give start).
double cooled_glass_temperature(const GlassCooling&, double start_kelvin, double ambient_kelvin,
                                double seconds);

}  // namespace draught
