// Drink colour from the figures drinks are published with. Every colour ends as the
// per-channel Beer-Lambert absorption (1/m, natural log) the renderer uses.
//  - Beer: SRM = 12.7 x A430 (decadic absorbance of 1 cm at 430 nm); EBC = 25 x A430 =
//    1.97 x SRM. The rest of the spectrum follows deLange's average beer spectrum (the
//    BJCP colour guide's model of 99 measured beers): A(l) / A430 =
//    0.02465 exp(-(l - 430) / 17.591) + 0.97535 exp(-(l - 430) / 82.122).
//  - Wine: the absorbances at 420, 520 and 620 nm that oenologists measure (Glories:
//    colour intensity = their sum, hue = A420 / A520), as the absorbance of a 1 cm path.
//    Labs measure reds in a 1 mm cell and multiply by ten (OIV-MA-AS2-07B; Glories 1984),
//    so published red-wine figures (intensity 5-15 for young reds) are already per cm.
//    Joined linearly in wavelength between the three points, held flat below 420 nm, and
//    past 620 nm continued as an exponential tail with the slope the 520-620 nm fall
//    gives: A(l) = A620 (A620 / A520)^((l - 620) / 100 nm) (anthocyanin's band at 520 nm
//    falls steeply into the red; a wine with A620 >= A520 is held flat).
//
// From spectrum to RGB: a channel is not one wavelength. The light of CIE illuminant D65
// through a reference path of the drink (kColourPathMetres) is integrated over 380-730 nm
// in 10 nm steps with the CIE 1931 2-degree colour matching functions (the analytic
// multi-lobe fit of Wyman, Sloan and Shirley, "Simple Analytic Approximations to the CIE
// XYZ Color Matching Functions", JCGT 2(2), 2013), taken to linear sRGB (IEC 61966-2-1
// matrix) and divided by the same for D65 unfiltered: the transmittance of each channel.
// The effective absorption is -ln(T) / L, so the renderer's per-channel Beer-Lambert
// reproduces the drink's true colour exactly at the reference path, and the far red that
// dark wines and stouts pass (650-700 nm) is seen. Deep colours outside the sRGB gamut
// can give a channel a negative value; it is clamped to kMinChannelTransmittance.
#pragma once

#include "core/params/params.hpp"

#include <functional>
#include <string>
#include <string_view>

namespace draught {

inline constexpr double kSrmPerA430 = 12.7;  // ASBC: SRM = 12.7 x A430 in 1 cm
inline constexpr double kEbcPerA430 = 25.0;  // EBC: EBC = 25 x A430 in 1 cm
inline constexpr double kEbcPerSrm = kEbcPerA430 / kSrmPerA430;  // 1.97
// The path at which a drink's RGB absorption matches its spectrum exactly. Light crosses
// a round glass 6-8 cm across in pi/4 of its diameter on average (4.7-6.3 cm); 4 cm, a
// little under, keeps the thin edges where a dark drink shows its colour from drifting
// to orange (a shorter path's colour from a longer path's coefficients is too light in
// the channels whose spectrum is steepest), and the middle darker than the spectrum.
inline constexpr double kColourPathMetres = 0.04;
inline constexpr double kMinChannelTransmittance = 1e-12;

// Decadic absorbance of 1 cm -> natural absorption per metre (ln 10 x 100 cm/m).
double absorbance_per_cm_to_absorption(double a);

// Linear-sRGB transmittance of D65 light through `metres` of a liquid whose decadic
// absorbance of 1 cm at wavelength nm is absorbance_per_cm(nm). 1 where it is clear.
glm::dvec3 channel_transmittance(const std::function<double(double)>& absorbance_per_cm, double metres);
// The per-channel absorption (1/m) that gives channel_transmittance at `metres`.
glm::vec3 spectrum_to_absorption(const std::function<double(double)>& absorbance_per_cm,
                                 double metres = kColourPathMetres);

double ebc_to_srm(double ebc);
// deLange's average beer: absorbance of 1 cm at `nm` for a beer of this SRM.
double beer_absorbance(double srm, double nm);
glm::vec3 srm_to_absorption(float srm, double metres = kColourPathMetres);

// A wine's absorbance of 1 cm at `nm` from its A420, A520, A620 (per cm).
double wine_absorbance(const glm::vec3& a420_520_620, double nm);
glm::vec3 wine_to_absorption(const glm::vec3& a420_520_620, double metres = kColourPathMetres);

// A drink's absorption as the renderer follows it along a path: in each channel, two
// bands of the channel's spectrum, a share of its light absorbed at `fast` per metre and
// the rest at `slow`: T(L) = share e^(-fast L) + (1 - share) e^(-slow L). One coefficient
// per channel is exact at one length only: fitted at a glassful's 4 cm, a red wine's
// thin edge came out orange-brown (188, 110, 76 at 1 cm) where its spectrum gives crimson
// (158, 71, 72), and its 8 cm middle too dark. Two bands follow the spectrum from a
// millimetre to 16 cm within a few 8-bit levels. A path through the drink keeps how the
// light it still carries is shared between the two bands (`left`: the fast band's share,
// `share` as it enters), and each stretch passes left e^(-fast t) + (1 - left) e^(-slow t)
// and updates it (onward): a path's stretches multiply to T of their sum, as the
// spectrum's do (the same as T(depth + t) / T(depth), with two exponentials a stretch).
struct DrinkAbsorption {
  glm::vec3 fast{0.0f}, slow{0.0f};  // per metre; fast >= slow
  glm::vec3 share{0.5f};             // of each channel's light, the share in the fast band (< 1)

  // One coefficient per channel (a drink given as liquid.absorption, a test's medium).
  static DrinkAbsorption uniform(const glm::vec3& per_metre) { return {per_metre, per_metre, glm::vec3(0.5f)}; }
  glm::dvec3 transmittance(double metres) const;
  // What passes the next `metres` of a path whose light is shared `left` : 1 - left
  // between the fast and the slow band (updated to the shares after).
  glm::dvec3 onward(glm::dvec3& left, double metres) const;
  // The one coefficient per channel that gives transmittance(metres) (a diffusion's
  // decay, a bubble's small view of the drink).
  glm::vec3 effective(double metres = kColourPathMetres) const;
};

// The two bands of each channel fitted to the spectrum's transmittance over paths of
// 1 mm to 16 cm (in sRGB-encoded error): the spectrum's wavelengths split by absorbance
// into two groups, each group's rate the best single rate for it; the split whose sum is
// nearest, then its two rates and share refined together (2.3 ms for three channels).
DrinkAbsorption spectrum_to_bands(const std::function<double(double)>& absorbance_per_cm);
// The absorbance spectrum (decadic, of 1 cm, by wavelength in nm) of the drink's colour:
// the first colour given wins, liquid.ebc > 0, then liquid.srm > 0, then liquid.wine (any
// absorbance > 0); empty when it is given as liquid.absorption (no spectrum).
std::function<double(double)> drink_spectrum(const LiquidParams&);
// The drink's colour as bands, fitted to drink_spectrum; liquid.absorption as given is
// one band.
DrinkAbsorption drink_absorption(const LiquidParams&);

// The absorption the renderer uses. The first colour given wins: liquid.ebc > 0, then
// liquid.srm > 0, then liquid.wine (any absorbance > 0), else liquid.absorption. Exact
// at `metres` of the drink: a glassful's path by default; a thin stream of it passes
// light over a path of its own thickness, where the glassful's coefficients would make a
// red wine orange (its channels' spectra are far from flat).
glm::vec3 liquid_absorption(const LiquidParams&, double metres = kColourPathMetres);

// For panels: which of the drink's four colour rows (liquid.ebc, srm, wine, absorption:
// `field` is the part after "liquid.") is in effect, the first given winning as in
// drink_spectrum, said beside the rows that are not: "" for the row in effect; an unset
// EBC beside an SRM of 3.5 reads "in effect: 6.9 (from SRM)", not as a colourless beer.
std::string drink_colour_note(const LiquidParams&, std::string_view field);
inline constexpr std::string_view kDrinkColourFields[] = {"ebc", "srm", "wine", "absorption"};

}  // namespace draught
