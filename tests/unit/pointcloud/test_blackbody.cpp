// The blackbody's colour and brightness: the Planckian locus against published
// chromaticities, the integral against Stefan-Boltzmann, the candela's old definition,
// monotonic in temperature, and the GPU table against the direct function.
#include "core/pointcloud/blackbody.hpp"
#include "core/pointcloud/glass_heat.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace draught {
namespace {

TEST(Blackbody, ChromaticityOnThePlanckianLocus) {
  // Published CIE 1931 (x, y) of the Planckian locus. The tolerance comes from the
  // multi-lobe fit: its xbar falls off too fast beyond ~650 nm (about half the tabled
  // value at 700 nm), which is where a body below ~1500 K sends most of its visible
  // light; at 6500 K the fit agrees to the table's last digit.
  struct Point {
    double kelvin, x, y, tolerance;
  };
  for (const Point& p : {Point{1000, 0.6528, 0.3444, 0.012}, Point{1500, 0.5857, 0.3931, 0.005},
                         Point{2000, 0.5267, 0.4133, 0.003}, Point{6500, 0.3135, 0.3236, 0.0005}}) {
    const glm::dvec2 c = blackbody_chromaticity(p.kelvin);
    EXPECT_NEAR(c.x, p.x, p.tolerance) << p.kelvin << " K";
    EXPECT_NEAR(c.y, p.y, p.tolerance) << p.kelvin << " K";
  }
}

TEST(Blackbody, IntegralMatchesStefanBoltzmann) {
  // Planck over 50 nm .. 1 mm (the tails beyond hold < 1e-6 of it) by the same Simpson
  // rule as the colour, in 1 nm steps: sigma T^4 / pi to 1e-6.
  for (double t : {1000.0, 1373.15, 3000.0, 6500.0}) {
    const double exact = kStefanBoltzmann * std::pow(t, 4) / M_PI;
    EXPECT_NEAR(blackbody_band_radiance(t, 50, 1e6, 1.0) / exact, 1.0, 1e-6) << t << " K";
  }
  EXPECT_EQ(planck_radiance(500e-9, 0), 0.0);
  EXPECT_EQ(planck_radiance(500e-9, 1), 0.0);  // underflows rather than overflowing
}

TEST(Blackbody, PlatinumFreezingPointIsSixtyCandelaPerSquareCentimetre) {
  // Before 1979 the candela was 1/60 of the luminance of a square centimetre of a
  // blackbody at the freezing point of platinum (2042 K on IPTS-68): 600,000 cd/m^2.
  EXPECT_NEAR(blackbody_xyz(2042).y / 6e5, 1.0, 0.02);
}

TEST(Blackbody, HotterIsBrighterAndBluer) {
  // From 700 K: below ~650 K the fit's xbar, narrower than ybar in the far red, turns
  // the chromaticity back (light there is ~1e-4 cd/m^2 and below, invisible beside the
  // rest of a scene).
  double last_y = 0, last_x = 1, last_blue = -1;
  for (double t = 700; t <= 12000; t *= 1.05) {
    const glm::dvec3 xyz = blackbody_xyz(t);
    const glm::dvec3 rgb = blackbody_linear_rgb(t);
    EXPECT_GT(xyz.y, last_y) << t;
    EXPECT_LT(blackbody_chromaticity(t).x, last_x) << t;
    const double blue = rgb.z / (rgb.x + rgb.y + rgb.z);
    EXPECT_GE(blue, last_blue) << t;
    EXPECT_GE(rgb.x, 0.0);
    EXPECT_GE(rgb.y, 0.0);
    EXPECT_GE(rgb.z, 0.0);
    last_y = xyz.y;
    last_x = blackbody_chromaticity(t).x;
    last_blue = blue;
  }
  EXPECT_EQ(blackbody_xyz(0), glm::dvec3(0.0));
  EXPECT_EQ(blackbody_linear_rgb(-5), glm::dvec3(0.0));
}

TEST(Blackbody, RgbCarriesTheLuminanceAndD65IsWhite) {
  // Where nothing is clamped, Rec. 709 luminance of the RGB is Y.
  const glm::dvec3 rgb = blackbody_linear_rgb(6500);
  EXPECT_NEAR(0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z, blackbody_xyz(6500).y,
              1e-3 * blackbody_xyz(6500).y);
  // D65's white maps to (1, 1, 1).
  const glm::dvec3 w = xyz_to_linear_srgb() * glm::dvec3(0.3127 / 0.3290, 1.0, (1 - 0.3127 - 0.3290) / 0.3290);
  EXPECT_NEAR(w.x, 1.0, 1e-12);
  EXPECT_NEAR(w.y, 1.0, 1e-12);
  EXPECT_NEAR(w.z, 1.0, 1e-12);
  // A 6500 K body is nearly white (D65 lies a little off the locus).
  EXPECT_NEAR(rgb.x / rgb.y, 1.0, 0.1);
  EXPECT_NEAR(rgb.z / rgb.y, 1.0, 0.1);
}

TEST(Blackbody, TableLookupWithinOnePercentOfTheDirectFunction) {
  const double lo = 650, hi = 4000;
  const auto table = blackbody_table(kBlackbodyMaxEntries, lo, hi);
  ASSERT_EQ(table.size(), static_cast<std::size_t>(kBlackbodyMaxEntries));
  double worst = 0;
  for (double t = lo; t <= hi; t += 7.3) {
    const glm::dvec3 direct = blackbody_linear_rgb(t);
    const glm::dvec3 looked = blackbody_table_lookup(table, lo, hi, t);
    const double y = blackbody_xyz(t).y;
    // Each channel within 1% of the luminance (channels near zero have no relative
    // scale of their own).
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(looked[c] - direct[c]) / y);
  }
  EXPECT_LT(worst, 0.01);
  // Below the table the Wien tail goes on (within 5% 50 K below), above it holds.
  const double below = blackbody_table_lookup(table, lo, hi, lo - 50).x;
  EXPECT_NEAR(below / blackbody_linear_rgb(lo - 50).x, 1.0, 0.05);
  EXPECT_EQ(blackbody_table_lookup(table, lo, hi, hi * 2), blackbody_table_lookup(table, lo, hi, hi));
  EXPECT_EQ(blackbody_table_lookup(table, lo, hi, 0), glm::dvec3(0.0));
}

TEST(Blackbody, TableRefusesBadArguments) {
  EXPECT_THROW(blackbody_table(1, 700, 1500), std::invalid_argument);
  EXPECT_THROW(blackbody_table(kBlackbodyMaxEntries + 1, 700, 1500), std::invalid_argument);
  EXPECT_THROW(blackbody_table(16, 1500, 700), std::invalid_argument);
  EXPECT_THROW(blackbody_table(16, 0, 700), std::invalid_argument);
  EXPECT_THROW(blackbody_table(16, 1, 700), std::invalid_argument);  // no visible light at 1 K
}

}  // namespace
}  // namespace draught
