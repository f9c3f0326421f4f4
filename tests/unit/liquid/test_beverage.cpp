// Drink colour against its published definitions: SRM and EBC (ASBC / EBC methods),
// deLange's average beer spectrum, wine absorbances (Glories' intensity and hue), and the
// spectrum integrated per sRGB channel (D65, CIE 1931) at the reference path.
#include "core/liquid/beverage.hpp"

#include "core/params/preset.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

namespace draught {
namespace {

LiquidParams drink(const char* name) {
  Params p = default_params();
  apply_preset(load_preset(test::preset_source_dir() / "drinks" / (std::string(name) + ".json")), p);
  return p.liquid;
}

// Transmittance through `metres` of a liquid with this absorption.
glm::vec3 through(const glm::vec3& absorption, float metres) { return glm::exp(-absorption * metres); }

TEST(Beverage, SrmIsTwelvePointSevenTimesA430) {
  // The definition: a beer of SRM s absorbs s / 12.7 (decadic) in 1 cm at 430 nm.
  for (double srm : {1.0, 4.0, 12.7, 40.0}) EXPECT_NEAR(beer_absorbance(srm, 430.0), srm / 12.7, 1e-12) << srm;
  // Wikipedia's worked example: a hundredth of the light through 1 cm (A = 2) is SRM 25.4.
  EXPECT_NEAR(beer_absorbance(25.4, 430.0), 2.0, 1e-12);
  // Decadic absorbance of 1 cm -> natural absorption per metre: 10^-A = exp(-sigma 0.01 m).
  EXPECT_NEAR(std::exp(-absorbance_per_cm_to_absorption(2.0) * 0.01), 0.01, 1e-12);
}

TEST(Beverage, EbcIsOnePointNineSevenTimesSrm) {
  EXPECT_NEAR(kEbcPerSrm, 1.97, 0.005);
  EXPECT_NEAR(ebc_to_srm(78.74), 40.0, 0.01);
  LiquidParams by_ebc = default_params().liquid, by_srm = by_ebc;
  by_ebc.srm = 0.0f;
  by_ebc.ebc = 25.0f;  // A430 = 1: SRM 12.7
  by_srm.srm = 12.7f;
  const glm::vec3 a = liquid_absorption(by_ebc), b = liquid_absorption(by_srm);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-4f * b[c]);
}

TEST(Beverage, TheAverageBeerSpectrumFallsWithWavelength) {
  // deLange's model: one at 430 nm, falling smoothly through the visible.
  for (double nm = 400; nm < 700; nm += 5) EXPECT_GT(beer_absorbance(13, nm), beer_absorbance(13, nm + 5)) << nm;
  const glm::vec3 a = srm_to_absorption(10.0f);
  EXPECT_GT(a.g, a.r);
  EXPECT_GT(a.b, a.g);
}

TEST(Beverage, AbsorptionMatchesTheSpectrumAtTheReferencePath) {
  // Each channel's Beer-Lambert coefficient gives exactly the spectrally integrated
  // transmittance at kColourPathMetres; darker beers absorb more in every channel.
  for (float srm : {2.0f, 4.0f, 13.0f, 40.0f}) {
    const glm::vec3 t = through(srm_to_absorption(srm), float(kColourPathMetres));
    const glm::dvec3 exact = channel_transmittance([srm](double nm) { return beer_absorbance(srm, nm); }, kColourPathMetres);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], exact[c], 1e-4 + 1e-4 * exact[c]) << srm << " " << c;
  }
  const glm::vec3 light = srm_to_absorption(4.0f), dark = srm_to_absorption(9.0f);
  for (int c = 0; c < 3; ++c) EXPECT_LT(light[c], dark[c]);
  EXPECT_EQ(srm_to_absorption(0.0f), glm::vec3(0.0f));
  EXPECT_EQ(wine_to_absorption(glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(Beverage, AChannelSeesMoreThanOneWavelength) {
  // A clear liquid passes everything; a liquid black only beyond 600 nm leaves green and
  // blue nearly whole but takes most of red; one black only below 500 nm takes blue.
  const glm::dvec3 clear = channel_transmittance([](double) { return 0.0; }, 0.05);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(clear[c], 1.0, 1e-12);
  const glm::dvec3 no_red = channel_transmittance([](double nm) { return nm > 600 ? 50.0 : 0.0; }, 0.05);
  EXPECT_LT(no_red.r, 0.6);
  EXPECT_GT(no_red.r, 0.05);  // sRGB red also sees 560-600 nm
  EXPECT_GT(no_red.g, 0.9);
  EXPECT_NEAR(no_red.b, 1.0, 1e-6);
  const glm::dvec3 no_blue = channel_transmittance([](double nm) { return nm < 500 ? 50.0 : 0.0; }, 0.05);
  EXPECT_LT(no_blue.b, 0.2);
  EXPECT_GT(no_blue.g, 0.7);
  // A window only 650-700 nm wide (the far red a dark wine passes) is seen by red alone.
  const glm::dvec3 far_red = channel_transmittance([](double nm) { return nm >= 650 && nm <= 700 ? 0.0 : 50.0; }, 0.05);
  EXPECT_GT(far_red.r, 0.03);
  EXPECT_GT(far_red.r, 30.0 * far_red.g);
  EXPECT_LT(far_red.b, 1e-6);
}

TEST(Beverage, StoutIsNearOpaqueInThePintWithRubyEdges) {
  const glm::vec3 a = liquid_absorption(drink("stout"));
  // The body: 7 cm across a pint passes under 1 % of the light in every channel.
  const glm::vec3 body = through(a, 0.07f);
  EXPECT_LT(std::max({body.r, body.g, body.b}), 0.01f);
  // A thin edge (2 cm): red passes, green much less, blue hardly: ruby / red-brown.
  const glm::vec3 edge = through(a, 0.02f);
  EXPECT_GT(edge.r, 0.15f);
  EXPECT_GT(edge.r, 4.0f * edge.g);
  EXPECT_LT(edge.b, 0.01f);
}

TEST(Beverage, WineAbsorbanceMeetsItsThreePublishedPoints) {
  const glm::vec3 w{3.5f, 5.2f, 1.3f};
  EXPECT_FLOAT_EQ(float(wine_absorbance(w, 420)), 3.5f);
  EXPECT_FLOAT_EQ(float(wine_absorbance(w, 520)), 5.2f);
  EXPECT_FLOAT_EQ(float(wine_absorbance(w, 620)), 1.3f);
  EXPECT_FLOAT_EQ(float(wine_absorbance(w, 470)), 4.35f);  // halfway, linearly
  // Past 620 nm the band keeps falling, continuously and steeply: the far red gets through.
  EXPECT_NEAR(wine_absorbance(w, 620.001), 1.3, 1e-3);
  for (double nm = 620; nm < 730; nm += 10) EXPECT_LT(wine_absorbance(w, nm + 10), wine_absorbance(w, nm)) << nm;
  EXPECT_LT(wine_absorbance(w, 700), 0.2 * 1.3);
  EXPECT_GT(wine_absorbance(w, 700), 0.0);
  // A wine that absorbs no less at 620 than at 520 is held flat.
  EXPECT_FLOAT_EQ(float(wine_absorbance({1.0f, 0.5f, 0.5f}, 700)), 0.5f);
}

TEST(Beverage, ABordeauxIsRedThroughOneCentimetre) {
  // A young Bordeaux-like red, absorbances of 1 cm (a 1 mm cell's reading x 10, as labs
  // publish them): A420 3.3, A520 5.2, A620 1.5, colour intensity 10, hue 0.63. Through
  // 1 cm, the spectrum integrated per channel: red passes several percent, green and blue
  // hardly anything. (One wavelength per channel, read at 611 nm, passed 1.5 % red.)
  const glm::vec3 bordeaux{3.3f, 5.2f, 1.5f};
  const glm::dvec3 t = channel_transmittance([&](double nm) { return wine_absorbance(bordeaux, nm); }, 0.01);
  EXPECT_GT(t.r, 0.03);
  EXPECT_GT(t.r, 10.0 * t.g);
  EXPECT_GT(t.r, 10.0 * t.b);
  // The renderer's coefficients keep that order at 1 cm, and the glass's middle (5 cm) is
  // near-black: deep garnet, not pure black where the wine is thin.
  const glm::vec3 a = wine_to_absorption(bordeaux);
  const glm::vec3 edge = through(a, 0.01f), middle = through(a, 0.05f);
  EXPECT_GT(edge.r, 0.1f);
  EXPECT_GT(edge.r, 1.3f * edge.g);
  EXPECT_GT(edge.g, 10.0f * edge.b);
  EXPECT_LT(std::max({middle.r, middle.g, middle.b}), 0.01f);
}

TEST(Beverage, TheLightRedIsRubyThroughItsGlass) {
  // The red-wine preset (a light young red) across a wine bowl: red clearly passes through
  // 5 cm where green and blue do not, and a thin edge (1 cm) is bright red.
  const glm::vec3 a = liquid_absorption(drink("red-wine"));
  const glm::vec3 bowl = through(a, 0.05f), edge = through(a, 0.01f);
  EXPECT_GT(bowl.r, 0.03f);
  EXPECT_GT(bowl.r, 20.0f * bowl.g);
  EXPECT_GT(bowl.r, 20.0f * bowl.b);
  EXPECT_GT(edge.r, 0.4f);
  EXPECT_GT(edge.r, 2.0f * edge.g);
  EXPECT_GT(edge.g, edge.b);
}

TEST(Beverage, ShippedWinesHavePublishedIntensityAndHue) {
  // Glories: colour intensity CI = A420 + A520 + A620 and hue = A420 / A520, in 1 cm.
  // Young reds: hue 0.5-0.7, CI from about 2.5 (light reds) to 15; roses: CI about 0.3 (pale Provence) to 2, hue 0.7-1.1;
  // whites (and champagne): A420 about 0.05-0.2, little at 520 (yellow, hue > 2).
  const LiquidParams red = drink("red-wine"), rose = drink("rose-wine"), white = drink("white-wine"),
                     champagne = drink("champagne");
  auto ci = [](const LiquidParams& l) { return l.wine.x + l.wine.y + l.wine.z; };
  auto hue = [](const LiquidParams& l) { return l.wine.x / l.wine.y; };
  EXPECT_GE(hue(red), 0.5f);
  EXPECT_LE(hue(red), 0.7f);
  EXPECT_GE(ci(red), 2.5f);
  EXPECT_GE(hue(rose), 0.7f);
  EXPECT_LE(hue(rose), 1.1f);
  EXPECT_GE(ci(rose), 0.3f);
  EXPECT_LE(ci(rose), 2.0f);
  for (const LiquidParams& l : {white, champagne}) {
    EXPECT_GE(l.wine.x, 0.05f);
    EXPECT_LE(l.wine.x, 0.2f);
    EXPECT_GT(hue(l), 2.0f);
  }
  // They are used: no beer colour shadows them.
  for (const LiquidParams& l : {red, rose, white, champagne}) {
    EXPECT_EQ(l.srm, 0.0f);
    EXPECT_EQ(l.ebc, 0.0f);
    EXPECT_EQ(liquid_absorption(l), wine_to_absorption(l.wine));
  }
}

TEST(Beverage, ChampagneIsPaleStraw) {
  // Through the 5 cm of a flute: nearly clear in red and green, blue somewhat held back.
  const glm::vec3 t = through(liquid_absorption(drink("champagne")), 0.05f);
  EXPECT_GT(t.r, 0.9f);
  EXPECT_GT(t.g, 0.85f);
  EXPECT_LT(t.b, t.g - 0.1f);
  EXPECT_GT(t.b, 0.4f);
}

TEST(Beverage, TheFirstColourGivenWins) {
  LiquidParams l = default_params().liquid;
  l.absorption = {9.0f, 170.0f, 95.0f};
  l.srm = 0.0f;
  EXPECT_EQ(liquid_absorption(l), l.absorption);
  l.wine = {0.1f, 0.02f, 0.01f};
  EXPECT_EQ(liquid_absorption(l), wine_to_absorption(l.wine));
  l.srm = 4.0f;
  EXPECT_EQ(liquid_absorption(l), srm_to_absorption(4.0f));
  l.ebc = 30.0f;
  EXPECT_EQ(liquid_absorption(l), srm_to_absorption(float(ebc_to_srm(30.0))));
}

// sRGB-encoded 8-bit level of a linear transmittance (the error as a picture shows it).
double level(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return 255.0 * (linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055);
}


TEST(Beverage, TwoBandsFollowTheSpectrumFromAnEdgeToADeepBowl) {
  // Every shipped drink, from 1 mm to 16 cm: the bands' colour within a few 8-bit levels
  // of the spectrum's (the red wine's thin edge crimson, its deep middle still red).
  // One coefficient per channel, fitted at 4 cm, is off by up to 37 levels for the red.
  for (const char* name : {"red-wine", "rose-wine", "white-wine", "champagne", "lager", "hefeweizen", "amber-ale", "stout"}) {
    const LiquidParams l = drink(name);
    const DrinkAbsorption bands = drink_absorption(l);
    const glm::vec3 one = liquid_absorption(l);
    double worst = 0, worst_one = 0;
    for (double L = 0.001; L <= 0.16 + 1e-9; L *= std::sqrt(2.0)) {
      const glm::dvec3 truth = channel_transmittance(drink_spectrum(l), L), fit = bands.transmittance(L);
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(level(fit[c]) - level(truth[c])));
        worst_one = std::max(worst_one, std::abs(level(std::exp(-double(one[c]) * L)) - level(truth[c])));
      }
    }
    std::printf("%-10s worst %5.1f levels (one coefficient per channel: %5.1f)\n", name, worst, worst_one);
    EXPECT_LE(worst, 6.0) << name;
    EXPECT_LE(worst, worst_one) << name;
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(bands.fast[c], bands.slow[c]) << name;
      EXPECT_GE(bands.share[c], 0.0f) << name;
      EXPECT_LT(bands.share[c], 1.0f) << name;
    }
  }
  // The red wine's edge at 1 cm is crimson (the spectrum's 158, 71, 72), not the
  // orange-brown one coefficient gave (188, 110, 76): green and blue alike.
  const glm::dvec3 edge = drink_absorption(drink("red-wine")).transmittance(0.01);
  EXPECT_NEAR(level(edge.g), level(edge.b), 4.0);
  EXPECT_NEAR(level(edge.r), 158.0, 4.0);
}

TEST(Beverage, APathsStretchesMultiplyToTheBandsOfTheirSum) {
  const DrinkAbsorption bands = drink_absorption(drink("stout"));
  for (double a : {0.0, 0.003, 0.02, 0.1})
    for (double b : {0.001, 0.01, 0.05}) {
      glm::dvec3 left(bands.share);
      const glm::dvec3 first = bands.onward(left, a), second = bands.onward(left, b);
      const glm::dvec3 split = first * second, whole = bands.transmittance(a + b);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(split[c], whole[c], 1e-12 + 1e-9 * whole[c]) << a << " " << b;
    }
  // Deep in the drink (10 m: everything absorbed long before) onward stays finite.
  glm::dvec3 left(bands.share);
  bands.onward(left, 10.0);
  const glm::dvec3 deep = bands.onward(left, 0.01);
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(std::isfinite(deep[c]));
    EXPECT_TRUE(std::isfinite(left[c]));
    EXPECT_GE(deep[c], 0.0);
    EXPECT_LE(deep[c], 1.0);
  }
  // The effective coefficient gives the bands' transmittance at its length.
  const glm::vec3 e = bands.effective(0.04);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(std::exp(-double(e[c]) * 0.04), bands.transmittance(0.04)[c], 1e-6);
  // A drink given as liquid.absorption is one band: Beer-Lambert as given.
  LiquidParams l = default_params().liquid;
  l.srm = l.ebc = 0.0f;
  l.wine = glm::vec3(0.0f);
  l.absorption = {9.0f, 170.0f, 95.0f};
  glm::dvec3 shares(drink_absorption(l).share);
  drink_absorption(l).onward(shares, 0.05);
  const glm::dvec3 t = drink_absorption(l).onward(shares, 0.02);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], std::exp(-double(l.absorption[c]) * 0.02), 1e-7);
}

TEST(Beverage, ShippedBeersDarkenWithTheirColour) {
  // Lager (3.5 SRM) < hefeweizen (14 EBC) < amber ale (13 SRM) < stout (40 SRM).
  const glm::vec3 lager = liquid_absorption(drink("lager")), weizen = liquid_absorption(drink("hefeweizen")),
                  ale = liquid_absorption(drink("amber-ale")), stout = liquid_absorption(drink("stout"));
  EXPECT_GT(drink("hefeweizen").ebc, 0.0f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(lager[c], weizen[c]);
    EXPECT_LT(weizen[c], ale[c]);
    EXPECT_LT(ale[c], stout[c]);
  }
}

// Panels say beside each colour row what is in effect when it is not: the first colour
// given wins (EBC, SRM, wine, absorption), and an unset EBC shows the SRM's as EBC.
TEST(DrinkColourNote, SaysWhichColourIsInEffect) {
  LiquidParams l;  // the default: SRM 4, no EBC, no wine
  EXPECT_EQ(drink_colour_note(l, "srm"), "");
  EXPECT_EQ(drink_colour_note(l, "ebc"), "in effect: 7.87 (from SRM)");
  EXPECT_EQ(drink_colour_note(l, "wine"), "unused: SRM in effect");
  EXPECT_EQ(drink_colour_note(l, "absorption"), "unused: SRM in effect");
  EXPECT_EQ(drink_colour_note(l, "haze"), "");
  l.ebc = 20;
  EXPECT_EQ(drink_colour_note(l, "ebc"), "");
  EXPECT_EQ(drink_colour_note(l, "srm"), "in effect: 10.2 (from EBC)");
  EXPECT_EQ(drink_colour_note(l, "wine"), "unused: EBC in effect");
  l.ebc = 0;
  l.srm = 0;
  l.wine = {1.2f, 1.5f, 0.4f};
  EXPECT_EQ(drink_colour_note(l, "wine"), "");
  EXPECT_EQ(drink_colour_note(l, "srm"), "unused: the wine colour in effect");
  EXPECT_EQ(drink_colour_note(l, "absorption"), "unused: the wine colour in effect");
  l.wine = glm::vec3(0.0f);
  EXPECT_EQ(drink_colour_note(l, "absorption"), "");
  EXPECT_EQ(drink_colour_note(l, "ebc"), "unused: the absorption in effect");
}

}  // namespace
}  // namespace draught
