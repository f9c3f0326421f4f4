// Drink colour from the figures drinks are published with. Every colour ends as the
// per-channel Beer-Lambert absorption (1/m, natural log) the renderer uses, read at one
// wavelength per channel: the dominant wavelengths of the sRGB primaries.
//  - Beer: SRM = 12.7 x A430 (decadic absorbance of 1 cm at 430 nm); EBC = 25 x A430 =
//    1.97 x SRM. The rest of the spectrum follows deLange's average beer spectrum (the
//    BJCP colour guide's model of 99 measured beers): A(l) / A430 =
//    0.02465 exp(-(l - 430) / 17.591) + 0.97535 exp(-(l - 430) / 82.122).
//  - Wine: the absorbances of 1 cm at 420, 520 and 620 nm that oenologists measure
//    (Glories: colour intensity = their sum, hue = A420 / A520), joined linearly in
//    wavelength between those points and held flat beyond them.
#pragma once

#include "core/params/params.hpp"

namespace draught {

// Nanometres: sRGB red, green and blue primaries' dominant wavelengths.
inline constexpr double kChannelWavelength[3] = {611.0, 549.0, 464.0};
inline constexpr double kSrmPerA430 = 12.7;  // ASBC: SRM = 12.7 x A430 in 1 cm
inline constexpr double kEbcPerA430 = 25.0;  // EBC: EBC = 25 x A430 in 1 cm
inline constexpr double kEbcPerSrm = kEbcPerA430 / kSrmPerA430;  // 1.97

// Decadic absorbance of 1 cm -> natural absorption per metre (ln 10 x 100 cm/m).
double absorbance_per_cm_to_absorption(double a);

double ebc_to_srm(double ebc);
// deLange's average beer: absorbance of 1 cm at `nm` for a beer of this SRM.
double beer_absorbance(double srm, double nm);
glm::vec3 srm_to_absorption(float srm);

// A wine's absorbance of 1 cm at `nm` from its A420, A520, A620.
double wine_absorbance(const glm::vec3& a420_520_620, double nm);
glm::vec3 wine_to_absorption(const glm::vec3& a420_520_620);

// The absorption the renderer uses. The first colour given wins: liquid.ebc > 0, then
// liquid.srm > 0, then liquid.wine (any absorbance > 0), else liquid.absorption.
glm::vec3 liquid_absorption(const LiquidParams&);

}  // namespace draught
