// Drink colour. Brewers give beer colour as SRM (12.7 x absorbance of 1 cm at 430 nm);
// absorption is proportional to the colourant concentration, so each RGB channel's
// absorption per metre is SRM times a constant.
#pragma once

#include "core/params/params.hpp"

namespace draught {

// Absorption per metre per SRM for R, G, B. Fitted so that 5 cm of beer over white
// gives the familiar SRM colour chart (SRM 4 gold, 13 copper, 40 near black with a
// ruby edge) when rendered in linear sRGB.
inline constexpr float kAbsorptionPerSrm[3] = {1.6f, 3.8f, 11.0f};

glm::vec3 srm_to_absorption(float srm);

// The absorption the renderer uses: from SRM when liquid.srm > 0, else liquid.absorption.
glm::vec3 liquid_absorption(const LiquidParams&);

}  // namespace draught
