// A hazy drink's diffusion field (core/liquid/haze.hpp) against closed forms: its decay
// and extrapolation from the drink's coefficients, the cylinder's field I0(kappa r) /
// I0(kappa (R + reach)) against I0's power series, its mean over the cross-section against
// quadrature, and the furnace's flat field.
#include "core/liquid/haze.hpp"

#include "core/foam/head_volume.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught {
namespace {

// I0 by its power series, sum (x / 2)^(2k) / (k!)^2 (enough terms for x < 30).
double i0_series(double x) {
  double term = 1.0, sum = 1.0;
  for (int k = 1; k < 200; ++k) {
    term *= (x / 2.0) * (x / 2.0) / (double(k) * double(k));
    sum += term;
  }
  return sum;
}

const glm::dvec3 kAlbedo{0.98, 0.93, 0.82}, kColour{15.8, 32.6, 88.2};  // a hefeweizen's
constexpr double kHaze = 30.0, kGlassIor = 1.5, kRadius = 0.03;

TEST(Haze, DecayAndReachAreDiffusionsThroughTheWall) {
  const HazeDiffusion d = haze_diffusion(kHaze, kAlbedo, kColour, kGlassIor);
  const double wall = wall_diffuse_transmittance(kGlassIor);
  for (int c = 0; c < 3; ++c) {
    const double sigma_s = kHaze * kAlbedo[c], sigma_a = kColour[c] + kHaze - sigma_s, sigma_t = sigma_a + sigma_s;
    EXPECT_NEAR(d.kappa[c], std::sqrt(3.0 * sigma_a * sigma_t), 1e-9 * d.kappa[c]);
    EXPECT_NEAR(d.reach[c], 2.0 / (3.0 * sigma_t) * (2.0 - wall) / wall, 1e-12);
  }
  // (the wall's even-light transmittance: about 0.84 for glass)
  EXPECT_GT(d.reach.x, 2.0 / (3.0 * (kColour.x + kHaze)));
}

TEST(Haze, NoHazeNoField) {
  const HazeDiffusion d = haze_diffusion(0.0, kAlbedo, kColour, kGlassIor);
  EXPECT_EQ(d.kappa, glm::dvec3(0.0));
  EXPECT_EQ(d.reach, glm::dvec3(0.0));
}

// A white haze in a colourless drink only scatters: its field is the surroundings' light
// everywhere (the furnace; tests/gpu/test_furnace.cpp sees the picture do it).
TEST(Haze, AWhiteHazeInAColourlessDrinkHoldsEvenLightEverywhere) {
  const HazeDiffusion d = haze_diffusion(60.0, glm::dvec3(1.0), glm::dvec3(0.0), kGlassIor);
  EXPECT_EQ(d.kappa, glm::dvec3(0.0));
  for (double r : {0.0, 0.01, 0.02, kRadius}) {
    const glm::dvec3 f = haze_field(d, r, kRadius);
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(f[c], 1.0);
  }
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(haze_field_mean(d, kRadius)[c], 1.0);
}

TEST(Haze, FieldIsTheCylindersBesselSolution) {
  const HazeDiffusion d = haze_diffusion(kHaze, kAlbedo, kColour, kGlassIor);
  for (double r : {0.0, 0.005, 0.015, 0.025, kRadius, 2 * kRadius}) {
    const glm::dvec3 f = haze_field(d, r, kRadius);
    for (int c = 0; c < 3; ++c) {
      const double want = i0_series(d.kappa[c] * std::min(r, kRadius)) / i0_series(d.kappa[c] * (kRadius + d.reach[c]));
      EXPECT_NEAR(f[c], want, 1e-10 + 1e-9 * want) << "r " << r << " channel " << c;
    }
  }
  // Brightest at the wall, darkest in the middle; the colour deepens inwards.
  const glm::dvec3 middle = haze_field(d, 0.0, kRadius), wall = haze_field(d, kRadius, kRadius);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(middle[c], wall[c]);
    EXPECT_LT(wall[c], 1.0);
  }
  EXPECT_GT(middle.x / middle.z, wall.x / wall.z);
}

TEST(Haze, MeanIsTheFieldOverTheCrossSection) {
  const HazeDiffusion d = haze_diffusion(kHaze, kAlbedo, kColour, kGlassIor);
  glm::dvec3 sum(0.0);
  constexpr int kRings = 4000;
  for (int k = 0; k < kRings; ++k) {
    const double r = (k + 0.5) / kRings * kRadius;
    sum += haze_field(d, r, kRadius) * (2.0 * r * (kRadius / kRings) / (kRadius * kRadius));
  }
  const glm::dvec3 mean = haze_field_mean(d, kRadius);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], sum[c], 1e-6 * sum[c]);
}

// A deep colour (a stout's, hazy) far past where e^x fits a double: finite, tiny, ordered.
TEST(Haze, DeepDrinksStayFinite) {
  const HazeDiffusion d = haze_diffusion(50.0, glm::dvec3(0.9), glm::dvec3(4000.0, 9000.0, 20000.0), kGlassIor);
  for (double r : {0.0, 0.02, 0.0299, kRadius}) {
    const glm::dvec3 f = haze_field(d, r, kRadius);
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(std::isfinite(f[c]));
      EXPECT_GE(f[c], 0.0);
      EXPECT_LE(f[c], 1.0);
    }
  }
  EXPECT_GT(haze_field(d, kRadius, kRadius).x, haze_field(d, 0.02, kRadius).x);
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(haze_field_mean(d, kRadius)[c]));
}

}  // namespace
}  // namespace draught
