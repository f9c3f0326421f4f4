// ProfileCurve: interpolates, never overshoots its control points, is C1.
#include "core/vessel/profile.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace draught {
namespace {

// Random designer curves: y strictly increasing from 0, r wandering up and down,
// including flat runs and sharp turns.
std::vector<Curve> random_curves() {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> dr(0.001f, 0.06f), dy(0.002f, 0.05f);
  std::uniform_int_distribution<int> count(2, 12), flat(0, 5);
  std::vector<Curve> out;
  for (int i = 0; i < 200; ++i) {
    Curve c;
    float y = 0;
    const int n = count(rng);
    for (int k = 0; k < n; ++k) {
      float r = (k > 0 && flat(rng) == 0) ? c.back().x : dr(rng);
      c.push_back({r, y});
      y += dy(rng);
    }
    out.push_back(c);
  }
  // The shipped glass profiles.
  for (const char* name : {"pint", "nonic", "wine", "flute", "tulip", "weizen"})
    out.push_back(test::params_with_glass(name).glass.profile);
  return out;
}

TEST(ProfileCurve, PassesThroughControlPoints) {
  for (const Curve& c : random_curves()) {
    ProfileCurve curve(c);
    EXPECT_DOUBLE_EQ(curve.height(), double(c.back().y));
    for (auto& p : c) EXPECT_NEAR(curve.radius(p.y), double(p.x), 1e-12) << "at y = " << p.y;
  }
}

TEST(ProfileCurve, ClampsOutsideTheHeight) {
  const Curve c = {{0.03f, 0.0f}, {0.05f, 0.07f}, {0.04f, 0.12f}};
  ProfileCurve curve(c);
  EXPECT_NEAR(curve.radius(-1.0), double(0.03f), 1e-12);
  EXPECT_NEAR(curve.radius(1.0), double(0.04f), 1e-12);
}

TEST(ProfileCurve, TwoPointsGiveAStraightLine) {
  const Curve c = {{0.03f, 0.0f}, {0.045f, 0.15f}};
  ProfileCurve curve(c);
  for (int i = 0; i <= 100; ++i) {
    const double y = double(0.15f) * i / 100.0;
    const double line = double(0.03f) + (double(0.045f) - double(0.03f)) * y / double(0.15f);
    EXPECT_NEAR(curve.radius(y), line, 1e-14);
  }
}

TEST(ProfileCurve, MonotoneBetweenControlPoints) {
  for (const Curve& c : random_curves()) {
    ProfileCurve curve(c);
    for (size_t i = 0; i + 1 < c.size(); ++i) {
      const double lo = std::min(c[i].x, c[i + 1].x), hi = std::max(c[i].x, c[i + 1].x);
      const double y0 = c[i].y, y1 = c[i + 1].y;
      const double sign = c[i + 1].x > c[i].x ? 1 : (c[i + 1].x < c[i].x ? -1 : 0);
      double prev = curve.radius(y0);
      for (int k = 1; k <= 400; ++k) {
        const double y = y0 + (y1 - y0) * k / 400.0;
        const double r = curve.radius(y);
        ASSERT_GE(r, lo - 1e-12) << "undershoot in piece " << i << " at y = " << y;
        ASSERT_LE(r, hi + 1e-12) << "overshoot in piece " << i << " at y = " << y;
        ASSERT_GE(sign * (r - prev), -1e-12) << "not monotone in piece " << i << " at y = " << y;
        prev = r;
      }
    }
  }
}

TEST(ProfileCurve, ContinuousFirstDerivative) {
  // One-sided finite differences agree at each interior control point (C1), and the
  // value is continuous there.
  const double eps = 1e-8;
  for (const Curve& c : random_curves()) {
    ProfileCurve curve(c);
    for (size_t i = 1; i + 1 < c.size(); ++i) {
      const double y = c[i].y;
      const double left = (curve.radius(y) - curve.radius(y - eps)) / eps;
      const double right = (curve.radius(y + eps) - curve.radius(y)) / eps;
      EXPECT_NEAR(left, right, 2e-3 + 1e-4 * std::fabs(left)) << "kink at control point " << i;
      EXPECT_NEAR(curve.radius(y - 1e-12), curve.radius(y + 1e-12), 1e-10);
    }
    // Inside a piece the derivative changes smoothly too.
    for (size_t i = 0; i + 1 < c.size(); ++i) {
      const double y = 0.5 * (c[i].y + c[i + 1].y);
      const double left = (curve.radius(y) - curve.radius(y - eps)) / eps;
      const double right = (curve.radius(y + eps) - curve.radius(y)) / eps;
      EXPECT_NEAR(left, right, 2e-3 + 1e-4 * std::fabs(left));
    }
  }
}

TEST(ProfileCurve, FlatControlPointsStayFlat) {
  // Equal neighbouring radii: the piece between them is exactly flat (no ripple).
  const Curve c = {{0.03f, 0.0f}, {0.04f, 0.03f}, {0.04f, 0.08f}, {0.02f, 0.1f}};
  ProfileCurve curve(c);
  for (int k = 0; k <= 100; ++k) {
    const double y = double(0.03f) + (double(0.08f) - double(0.03f)) * k / 100.0;
    EXPECT_NEAR(curve.radius(y), double(0.04f), 1e-15);
  }
}

}  // namespace
}  // namespace draught
