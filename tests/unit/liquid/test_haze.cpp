// A hazy drink's diffusion field (core/liquid/haze.hpp) against closed forms: the Bessel
// functions against their tables, the decay and extrapolation from the drink's
// coefficients, the cylinder's field I0(kappa r) / I0(kappa (R + reach)), its mean over the
// cross-section against quadrature, and the furnace's flat field.
#include "core/liquid/haze.hpp"

#include "core/foam/head_volume.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught {
namespace {

// I0 and I1 at published points (Abramowitz and Stegun, table 9.8; the last two on the
// asymptotic branch).
struct BesselValue {
  double x, i0, i1;
};
const BesselValue kBessel[] = {{1.0, 1.266065877752008, 0.5651591039924850},
                               {2.0, 2.279585302336067, 1.590636854637329},
                               {5.0, 27.23987182360445, 24.33564214245053},
                               {10.0, 2815.716628466254, 2670.988303701255},
                               {20.0, 4.355828255955353e7, 4.245497338512777e7},
                               {50.0, 2.932553783849336e20, 2.903078590103557e20}};

TEST(Haze, BesselFunctionsMatchTheirTables) {
  EXPECT_DOUBLE_EQ(bessel_i0_scaled(0.0), 1.0);
  EXPECT_DOUBLE_EQ(bessel_i1_scaled(0.0), 0.0);
  for (const BesselValue& b : kBessel) {
    const double scale = std::exp(-b.x);
    EXPECT_NEAR(bessel_i0_scaled(b.x), b.i0 * scale, 1e-12 * b.i0 * scale) << "I0(" << b.x << ")";
    EXPECT_NEAR(bessel_i1_scaled(b.x), b.i1 * scale, 1e-12 * b.i1 * scale) << "I1(" << b.x << ")";
  }
  // Where the series hands over to the asymptotic expansion, no seam: a step e below 40
  // changes the values by e times minus their slopes, (I0 - I1) e^-x and (I1 + I1 / x -
  // I0) e^-x (I0' = I1, I1' = I0 - I1 / x), to within rounding.
  const double e = 1e-6, i0 = bessel_i0_scaled(40.0), i1 = bessel_i1_scaled(40.0);
  EXPECT_NEAR(bessel_i0_scaled(40.0 - e) - i0, e * (i0 - i1), 1e-15);
  EXPECT_NEAR(bessel_i1_scaled(40.0 - e) - i1, e * (i1 - (i0 - i1 / 40.0)), 1e-15);
}

// I0 itself, for the field's closed form below (well inside double's range there).
double i0(double x) { return bessel_i0_scaled(x) * std::exp(x); }

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
      const double want = i0(d.kappa[c] * std::min(r, kRadius)) / i0(d.kappa[c] * (kRadius + d.reach[c]));
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
