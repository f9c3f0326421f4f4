// Vessel geometry: cavity volumes and fill heights against closed forms and
// brute-force integrals.
#include "core/vessel/vessel.hpp"

#include "core/vessel/profile.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include <numbers>

namespace draught {
namespace {

double frustum(double r0, double r1, double h) { return kPi * h / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1); }

// The test glasses. Control points are floats in Params, so closed forms use the
// float values widened to double.
struct ConeCase {
  float r0, r1, height, wall, base;
  GlassParams glass() const { return test::simple_glass({{r0, 0.0f}, {r1, height}}, wall, base, wall); }
  double H() const { return double(height); }
  double b() const { return double(base); }
  double w() const { return double(wall); }
  double slope() const { return (double(r1) - double(r0)) / H(); }
  double inner(double y) const { return double(r0) + slope() * y - w(); }
};

const ConeCase kCylinder{0.04f, 0.04f, 0.15f, 0.003f, 0.01f};
const ConeCase kCone{0.03f, 0.045f, 0.15f, 0.0035f, 0.013f};
const ConeCase kNarrowingCone{0.05f, 0.028f, 0.12f, 0.002f, 0.02f};  // wider at the foot

TEST(VesselVolume, FrustumClosedFormSanity) {
  // The closed form itself: a cylinder and a cone (apex) are its special cases.
  EXPECT_NEAR(frustum(2.0, 2.0, 3.0), kPi * 4.0 * 3.0, 1e-12);
  EXPECT_NEAR(frustum(0.0, 2.0, 3.0), kPi * 4.0 * 3.0 / 3.0, 1e-12);
}

TEST(VesselVolume, CylinderCavityMatchesClosedForm) {
  const Vessel v = build_vessel(kCylinder.glass());
  const double ri = double(kCylinder.r0) - kCylinder.w();
  EXPECT_DOUBLE_EQ(v.height, kCylinder.H());
  EXPECT_DOUBLE_EQ(v.base, kCylinder.b());
  const double expected = kPi * ri * ri * (kCylinder.H() - kCylinder.b());
  EXPECT_NEAR(v.cavity_volume(), expected, 1e-12 * expected);
  for (double h : {0.011, 0.02, 0.05, 0.0731, 0.1, 0.149}) {
    const double e = kPi * ri * ri * (h - kCylinder.b());
    EXPECT_NEAR(v.cavity_volume_below(h), e, 1e-12 * expected) << "h = " << h;
  }
}

TEST(VesselVolume, ConeCavityMatchesClosedForm) {
  for (const ConeCase& c : {kCone, kNarrowingCone}) {
    const Vessel v = build_vessel(c.glass());
    const double expected = frustum(c.inner(c.b()), c.inner(c.H()), c.H() - c.b());
    EXPECT_NEAR(v.cavity_volume(), expected, 1e-12 * expected);
    for (double f : {0.01, 0.1, 0.25, 0.5, 0.777, 0.99}) {
      const double h = c.b() + f * (c.H() - c.b());
      const double e = frustum(c.inner(c.b()), c.inner(h), h - c.b());
      EXPECT_NEAR(v.cavity_volume_below(h), e, 1e-12 * expected) << "h = " << h;
    }
  }
}

TEST(VesselVolume, VolumeBelowIsClampedToTheCavity) {
  const Vessel v = build_vessel(kCone.glass());
  EXPECT_EQ(v.cavity_volume_below(0.0), 0.0);
  EXPECT_EQ(v.cavity_volume_below(kCone.b() * 0.5), 0.0);
  EXPECT_EQ(v.cavity_volume_below(-1.0), 0.0);
  EXPECT_NEAR(v.cavity_volume_below(10.0), v.cavity_volume(), 1e-18);
}

TEST(VesselFill, CylinderFillHeightIsLinear) {
  const Vessel v = build_vessel(kCylinder.glass());
  for (int i = 0; i <= 20; ++i) {
    const double f = i / 20.0;
    EXPECT_NEAR(v.fill_height(f), kCylinder.b() + f * (kCylinder.H() - kCylinder.b()), 1e-9) << "f = " << f;
  }
}

TEST(VesselFill, ConeFillHeightSolvesTheCubic) {
  // V(h) = pi / (3 s) (r(h)^3 - r(b)^3) with r linear of slope s, so
  // r(h) = cbrt(r(b)^3 + f (r(H)^3 - r(b)^3)) and h = b + (r(h) - r(b)) / s.
  for (const ConeCase& c : {kCone, kNarrowingCone}) {
    const Vessel v = build_vessel(c.glass());
    const double rb = c.inner(c.b()), rH = c.inner(c.H()), s = c.slope();
    for (int i = 0; i <= 20; ++i) {
      const double f = i / 20.0;
      const double rh = std::cbrt(rb * rb * rb + f * (rH * rH * rH - rb * rb * rb));
      const double h = c.b() + (rh - rb) / s;
      EXPECT_NEAR(v.fill_height(f), h, 1e-9) << "f = " << f;
    }
  }
}

TEST(VesselFill, FractionIsClampedToZeroOne) {
  const Vessel v = build_vessel(kCone.glass());
  EXPECT_NEAR(v.fill_height(-0.5), kCone.b(), 1e-12);
  EXPECT_NEAR(v.fill_height(1.5), kCone.H(), 1e-12);
}

// Brute-force midpoint integral of pi r_inner(y)^2 from the cavity floor to the rim.
double brute_cavity_volume(const Vessel& v, double top) {
  const int n = 400000;
  const double h = (top - v.base) / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = v.inner_radius(v.base + (i + 0.5) * h);
    sum += r * r;
  }
  return kPi * sum * h;
}

class PresetGlassVolume : public ::testing::TestWithParam<const char*> {};

TEST_P(PresetGlassVolume, CavityVolumeMatchesNumericalIntegral) {
  const Vessel v = test::preset_vessel(GetParam());
  const double brute = brute_cavity_volume(v, v.height);
  EXPECT_GT(brute, 0);
  EXPECT_NEAR(v.cavity_volume(), brute, 1e-7 * brute);
  const double mid = 0.5 * (v.base + v.height);
  EXPECT_NEAR(v.cavity_volume_below(mid), brute_cavity_volume(v, mid), 1e-7 * brute);
}

TEST_P(PresetGlassVolume, FillHeightRoundTrips) {
  const Vessel v = test::preset_vessel(GetParam());
  const double total = v.cavity_volume();
  double prev = v.base;
  for (double f : {0.01, 0.05, 0.2, 0.35, 0.5, 0.75, 0.85, 0.98}) {
    const double h = v.fill_height(f);
    EXPECT_GT(h, prev) << "fill height must increase with the fraction";
    EXPECT_LT(h, v.height);
    EXPECT_NEAR(v.cavity_volume_below(h) / total, f, 1e-9) << "f = " << f;
    prev = h;
  }
}

TEST_P(PresetGlassVolume, InnerWallIsOuterMinusThicknessClampedAtZero) {
  const Params p = test::params_with_glass(GetParam());
  const Vessel v = build_vessel(p.glass);
  ASSERT_EQ(v.r_outer.size(), size_t(Vessel::kSegments + 1));
  ASSERT_EQ(v.r_inner.size(), size_t(Vessel::kSegments + 1));
  for (size_t k = 0; k < v.r_outer.size(); ++k)
    EXPECT_DOUBLE_EQ(v.r_inner[k], std::max(v.r_outer[k] - double(p.glass.wall_thickness), 0.0));
  // The segmented profile passes through the designer's control points (knots are
  // uniform, so only the foot and the rim are guaranteed to be knots).
  EXPECT_NEAR(v.r_outer.front(), double(p.glass.profile.front().x), 1e-12);
  EXPECT_NEAR(v.r_outer.back(), double(p.glass.profile.back().x), 1e-12);
  EXPECT_DOUBLE_EQ(v.height, double(p.glass.profile.back().y));
}

INSTANTIATE_TEST_SUITE_P(Presets, PresetGlassVolume,
                         ::testing::Values("pint", "nonic", "wine", "flute", "tulip", "weizen"));

// The angle in degrees between the profile normals (1, -a) and (1, -b) of two slopes.
double normal_angle(double a, double b) {
  return std::acos(std::clamp((1 + a * b) / std::sqrt((1 + a * a) * (1 + b * b)), -1.0, 1.0)) * 180 / kPi;
}

class CurvedBowlNormals : public ::testing::TestWithParam<const char*> {};

// The shading slope is one value at every knot, seen from either segment: the normal has
// no step where the frustum segments meet (the contour bands of one normal per segment).
TEST_P(CurvedBowlNormals, SlopeIsContinuousAcrossEveryKnot) {
  const Vessel v = test::preset_vessel(GetParam());
  double worst_step = 0, worst_segment_step = 0;
  for (bool inner : {false, true})
    for (int k = 1; k < Vessel::kSegments; ++k) {
      const double below = v.wall_slope(inner, k - 1, 1.0), above = v.wall_slope(inner, k, 0.0);
      const auto& r = inner ? v.r_inner : v.r_outer;
      const double s0 = (r[size_t(k)] - r[size_t(k) - 1]) / v.dy, s1 = (r[size_t(k) + 1] - r[size_t(k)]) / v.dy;
      if (normal_angle(s0, s1) > std::acos(double(contract::kCreaseCos)) * 180 / kPi) continue;  // a crease
      worst_step = std::max(worst_step, std::fabs(below - above));
      worst_segment_step = std::max(worst_segment_step, normal_angle(s0, s1));
    }
  EXPECT_LT(worst_step, 1e-12) << "the normal jumps at a knot (slope step)";
  // The bowl is curved: one normal per segment would jump by this much.
  EXPECT_GT(worst_segment_step, 0.3);
}

// Away from creases the smooth normal follows the designer's curve (the profile's own
// slope, by a fine central difference) more closely than one normal per segment does.
// (Where the curve's curvature jumps, at its control points, neither is exact.)
TEST_P(CurvedBowlNormals, SlopeFollowsTheProfileCurve) {
  const Params p = test::params_with_glass(GetParam());
  const Vessel v = build_vessel(p.glass);
  const ProfileCurve curve(p.glass.profile);
  std::vector<double> err, err_segment;
  for (int k = 2; k + 2 < Vessel::kSegments; ++k)
    for (double f : {0.0, 0.25, 0.5, 0.75}) {
      const double y = (k + f) * v.dy, h = 1e-6;
      const double truth = (curve.radius(y + h) - curve.radius(y - h)) / (2 * h);
      const double a = (v.r_outer[size_t(k)] - v.r_outer[size_t(k) - 1]) / v.dy;
      const double b = (v.r_outer[size_t(k) + 1] - v.r_outer[size_t(k)]) / v.dy;
      const double c = (v.r_outer[size_t(k) + 2] - v.r_outer[size_t(k) + 1]) / v.dy;
      if (std::max(normal_angle(a, b), normal_angle(b, c)) > 5) continue;  // near a crease or a sharp turn
      err.push_back(normal_angle(v.wall_slope(false, k, f), truth));
      err_segment.push_back(normal_angle(b, truth));
    }
  ASSERT_GT(err.size(), 250u);
  auto mean = [](const std::vector<double>& e) {
    double s = 0;
    for (double x : e) s += x;
    return s / double(e.size());
  };
  auto p90 = [](std::vector<double> e) {
    std::nth_element(e.begin(), e.begin() + ptrdiff_t(e.size() * 9 / 10), e.end());
    return e[e.size() * 9 / 10];
  };
  std::printf("%s: degrees from the curve's normal: smooth mean %.3f p90 %.3f, per segment mean %.3f p90 %.3f\n",
              GetParam(), mean(err), p90(err), mean(err_segment), p90(err_segment));
  EXPECT_LT(mean(err), 0.5 * mean(err_segment));
  EXPECT_LT(p90(err), 0.5 * p90(err_segment));
  EXPECT_LT(p90(err), 0.25);
}

// A crease (the wine glass's foot meeting its stem) stays sharp: each side keeps its own
// segment's slope there.
TEST(CurvedBowlNormals, CreasesKeepEachSegmentsOwnSlope) {
  const Vessel v = test::preset_vessel("wine");
  int creases = 0;
  for (int k = 1; k < Vessel::kSegments; ++k) {
    const double s0 = (v.r_outer[size_t(k)] - v.r_outer[size_t(k) - 1]) / v.dy;
    const double s1 = (v.r_outer[size_t(k) + 1] - v.r_outer[size_t(k)]) / v.dy;
    if (normal_angle(s0, s1) <= std::acos(double(contract::kCreaseCos)) * 180 / kPi + 1) continue;
    ++creases;
    EXPECT_DOUBLE_EQ(v.wall_slope(false, k - 1, 1.0), s0) << "knot " << k;
    EXPECT_DOUBLE_EQ(v.wall_slope(false, k, 0.0), s1) << "knot " << k;
  }
  EXPECT_GT(creases, 0) << "the wine glass's foot meets its stem at a crease";
}

INSTANTIATE_TEST_SUITE_P(Bowls, CurvedBowlNormals, ::testing::Values("wine", "tulip", "flute"));

TEST(VesselBuild, RimRadiusIsClampedBetweenHalfAndTwiceTheWall) {
  const float wall = 0.003f;
  auto rim_of = [&](float rim) {
    return build_vessel(test::simple_glass({{0.03f, 0.0f}, {0.04f, 0.1f}}, wall, 0.01f, rim));
  };
  EXPECT_NEAR(rim_of(0.0002f).rim_minor, 0.5 * double(wall), 1e-15);
  EXPECT_NEAR(rim_of(0.02f).rim_minor, 2.0 * double(wall), 1e-15);
  EXPECT_NEAR(rim_of(0.004f).rim_minor, double(0.004f), 1e-15);
  const Vessel v = rim_of(0.004f);
  EXPECT_NEAR(v.rim_major, double(0.04f) - 0.5 * double(wall), 1e-12);
  EXPECT_NEAR(v.bound_radius, v.rim_major + v.rim_minor, 1e-15);
}

TEST(VesselBuild, BoundRadiusEnclosesWallsAndRim) {
  for (const char* name : {"pint", "nonic", "wine", "flute", "tulip", "weizen"}) {
    const Vessel v = test::preset_vessel(name);
    for (double r : v.r_outer) EXPECT_LE(r, v.bound_radius) << name;
    EXPECT_LE(v.rim_major + v.rim_minor, v.bound_radius) << name;
  }
}

TEST(VesselBuild, BaseIsClampedBelowTheRim) {
  const Vessel v = build_vessel(test::simple_glass({{0.03f, 0.0f}, {0.04f, 0.1f}}, 0.003f, 0.3f, 0.002f));
  EXPECT_NEAR(v.base, double(0.1f) - 0.01, 1e-12);
  EXPECT_GT(v.cavity_volume(), 0.0);
}

}  // namespace
}  // namespace draught
