// The glow of hot glass: the colour and brightness of a blackbody. Planck's law is
// integrated against the CIE 1931 2-degree colour matching functions (as the analytic
// multi-lobe fit of Wyman, Sloan and Shirley, JCGT 2(2), 2013) to absolute XYZ, then
// to linear sRGB (Rec. 709 primaries, D65 white). A small table carries it to the GPU;
// blackbody_table_lookup is exactly what the shader does with it. docs/POINT_CLOUDS.md.
#pragma once

#include "core/math/cie1931.hpp"  // cie1931_cmf

#include <glm/glm.hpp>

#include <vector>

namespace draught {

// The visible band the colour is integrated over, and the step (Simpson's rule).
inline constexpr double kBlackbodyMinNm = 360.0;
inline constexpr double kBlackbodyMaxNm = 830.0;
inline constexpr double kBlackbodyStepNm = 1.0;
// The luminous efficacy of 555 nm (540 THz) light, lm/W: the SI candela.
inline constexpr double kLuminousEfficacy = 683.0;
// The most entries a table may have (the integrator keeps it in a uniform array).
inline constexpr int kBlackbodyMaxEntries = 64;

// Planck's spectral radiance, W / (m^2 sr m), at a wavelength in metres; 0 for a
// temperature or wavelength that is not positive.
double planck_radiance(double wavelength_m, double kelvin);
// Planck's radiance integrated over [min_nm, max_nm] by Simpson's rule with about
// step_nm per interval, W / (m^2 sr): the same rule as the colour below.
double blackbody_band_radiance(double kelvin, double min_nm, double max_nm, double step_nm);

// Absolute XYZ of a blackbody: Y is its luminance in cd/m^2 (683 lm/W times the
// photopically weighted radiance); X and Z on the same scale. Zero for kelvin <= 0.
glm::dvec3 blackbody_xyz(double kelvin);
// Its CIE 1931 (x, y) chromaticity (kelvin > 0).
glm::dvec2 blackbody_chromaticity(double kelvin);
// Linear sRGB on the same absolute scale (0.2126 R + 0.7152 G + 0.0722 B = Y where no
// component was clamped). Negative components are clamped to 0: below about 1900 K the
// Planckian locus runs outside the sRGB gamut (too saturated a red-orange for the
// primaries; blue goes negative), and light cannot be negative.
glm::dvec3 blackbody_linear_rgb(double kelvin);
// The matrix from XYZ to linear sRGB, derived from the primaries' and D65's
// chromaticities (IEC 61966-2-1).
glm::dmat3 xyz_to_linear_srgb();

// A table for the GPU: `entries` (2 .. kBlackbodyMaxEntries) samples spaced evenly in
// 1/T from kelvin_min to kelvin_max (0 < min < max). Entry i holds (rgb / Y, ln Y): the
// colour of unit luminance and the log of the luminance (cd/m^2). Spacing in 1/T and
// interpolating ln Y make Wien's law, ln L = a - c2 / (lambda T), nearly linear in the
// table's coordinate, so radiance that spans many decades between 700 K and 1500 K
// interpolates within a fraction of a percent. Bad arguments throw std::invalid_argument.
std::vector<glm::vec4> blackbody_table(int entries, double kelvin_min, double kelvin_max);
// What the shader does: u = (1/min - 1/T) / (1/min - 1/max) (n - 1); i = clamp(floor(u),
// 0, n - 2); colour = mix(c_i, c_i+1, clamp(u - i, 0, 1)); ln Y = mix(w_i, w_i+1,
// min(u - i, 1)) (below the table ln Y goes on along the first interval: the Wien tail
// fades smoothly; above it, it holds the last entry); result = colour * exp(ln Y).
// Zero for kelvin <= 0.
glm::dvec3 blackbody_table_lookup(const std::vector<glm::vec4>& table, double kelvin_min,
                                  double kelvin_max, double kelvin);

}  // namespace draught
