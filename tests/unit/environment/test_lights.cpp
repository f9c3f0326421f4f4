// The studio's area lights: the exact irradiance of a rect and a sphere against Monte Carlo
// integration of their own samples (horizon clipping included), the far-field limit, the
// sampling densities, the emitting side, and placement from the parameter groups.
#include "core/environment/lights.hpp"
#include "core/math/atan2.hpp"
#include "core/math/random.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace draught {
namespace {

AreaLight rect(glm::dvec3 c, glm::dvec3 n, glm::dvec3 hu, glm::dvec3 hv) {
  AreaLight l;
  l.shape = LightShape::Rect;
  l.center = c;
  l.normal = glm::normalize(n);
  l.half_u = hu;
  l.half_v = hv;
  l.radiance = glm::dvec3(1.0);
  return l;
}

// The rect's edge angles come from atan2_fast: within 1e-15 rad of std::atan2 in every
// quadrant, at the range reduction's borders, for tiny and huge arguments, and the same
// signed zeros and infinities.
TEST(Atan2Fast, MatchesTheLibrarysAtan2) {
  double worst = 0, worst_small = 0;
  Rng rng(3, 0, 0);
  for (int i = 0; i < 200000; ++i) {
    const double a = 2 * kPi * rng.uniform() - kPi, m = std::exp(60 * rng.uniform() - 30);
    const double y = m * std::sin(a), x = m * std::cos(a);
    worst = std::max(worst, std::fabs(atan2_fast(y, x) - std::atan2(y, x)));
  }
  for (double r : {0.19891236737965800, 0.66817863791929888, 0.41421356237309503, 1.0, 1e-300, 1e-9, 0.5})
    for (double e : {-1e-15, 0.0, 1e-15})
      for (double sy : {1.0, -1.0})
        for (double sx : {1.0, -1.0}) {
          const double y = sy * (r + e), x = sx * 1.0;
          worst = std::max(worst, std::fabs(atan2_fast(y, x) - std::atan2(y, x)));
          worst = std::max(worst, std::fabs(atan2_fast(x, y) - std::atan2(x, y)));
        }
  for (double y : {1e-12, 3e-8, 1e-5})  // a far light's edge: the angle itself is tiny
    worst_small = std::max(worst_small, std::fabs(atan2_fast(y, 1.0) / std::atan2(y, 1.0) - 1));
  EXPECT_LT(worst, 1e-15);
  EXPECT_LT(worst_small, 1e-14);
  const double inf = std::numeric_limits<double>::infinity();
  for (double y : {0.0, -0.0, 1.0, -1.0, inf, -inf})
    for (double x : {0.0, -0.0, 1.0, -1.0, inf, -inf}) {
      EXPECT_EQ(atan2_fast(y, x), std::atan2(y, x)) << y << ", " << x;
      EXPECT_EQ(std::signbit(atan2_fast(y, x)), std::signbit(std::atan2(y, x))) << y << ", " << x;
    }
  EXPECT_TRUE(std::isnan(atan2_fast(std::nan(""), 1.0)));
}

AreaLight sphere(glm::dvec3 c, double r) {
  AreaLight l;
  l.shape = LightShape::Sphere;
  l.center = c;
  l.radius = r;
  l.radiance = glm::dvec3(1.0);
  return l;
}

// E / L at x (normal n) by sampling the light: the mean of cos / pdf over the samples that
// reach the surface's front.
double monte_carlo_factor(const AreaLight& l, glm::dvec3 x, glm::dvec3 n, int count = 400000) {
  Rng rng(7, 3, 0);
  double sum = 0;
  for (int i = 0; i < count; ++i) {
    AreaLight::Sample s;
    const double v = rng.uniform(), u = rng.uniform();  // (drawn in this order)
    if (!l.sample_from(x, u, v, s)) continue;
    sum += std::max(glm::dot(s.dir, n), 0.0) / s.pdf;
  }
  return sum / count;
}

TEST(Lights, RectIrradianceIsExactAboveAndAcrossTheHorizon) {
  const glm::dvec3 up(0, 1, 0);
  // A softbox above and in front, facing the point.
  const AreaLight key = rect({-0.3, 0.5, 0.4}, {0.3, -0.5, -0.4}, {0.2, 0, 0.15}, {0, 0.25, 0.0});
  const glm::dvec3 hv = glm::normalize(glm::cross(key.normal, glm::normalize(key.half_u))) * 0.25;
  AreaLight k = key;
  k.half_v = hv;  // in its plane
  EXPECT_NEAR(k.irradiance_factor({0, 0, 0}, up), monte_carlo_factor(k, {0, 0, 0}, up), 4e-3);
  // A strip standing on the floor, its lower half below the horizon of a floor point:
  // only its upper half lights the floor (the clipped polygon).
  const AreaLight strip = rect({0.3, 0.0, 0.0}, {-1, 0, 0}, {0, 0, 0.05}, {0, 0.4, 0});
  const double clipped = strip.irradiance_factor({0, 0, 0}, up);
  EXPECT_GT(clipped, 0);
  EXPECT_NEAR(clipped, monte_carlo_factor(strip, {0, 0, 0}, up), 2e-3);
  // A tilted surface sees the part of a softbox in front of its plane.
  const glm::dvec3 tilted = glm::normalize(glm::dvec3(1, 0.2, 0));
  EXPECT_NEAR(k.irradiance_factor({0, 0, 0}, tilted), monte_carlo_factor(k, {0, 0, 0}, tilted), 4e-3);
}

TEST(Lights, RectIrradianceFarAwayIsAreaTimesCosinesOverDistanceSquared) {
  const AreaLight l = rect({0, 20, 0}, {0, -1, 0}, {0.01, 0, 0}, {0, 0, 0.01});
  const double expected = l.area() / (20.0 * 20.0);
  EXPECT_NEAR(l.irradiance_factor({0, 0, 0}, {0, 1, 0}), expected, 1e-6 * expected);
  // Behind the softbox: nothing.
  EXPECT_EQ(l.irradiance_factor({0, 30, 0}, {0, -1, 0}), 0.0);
}

TEST(Lights, SphereIrradianceIsExactAboveAndAcrossTheHorizon) {
  const glm::dvec3 up(0, 1, 0);
  const AreaLight above = sphere({0.2, 0.5, 0}, 0.1);
  const double d2 = 0.29, sin2 = 0.01 / d2, cos_t = 0.5 / std::sqrt(d2);
  EXPECT_NEAR(above.irradiance_factor({0, 0, 0}, up), kPi * sin2 * cos_t, 1e-12);
  EXPECT_NEAR(above.irradiance_factor({0, 0, 0}, up), monte_carlo_factor(above, {0, 0, 0}, up), 2e-3);
  // Half sunk below the horizon.
  const AreaLight setting = sphere({0.5, 0.02, 0}, 0.1);
  const double partial = setting.irradiance_factor({0, 0, 0}, up);
  EXPECT_GT(partial, 0);
  EXPECT_NEAR(partial, monte_carlo_factor(setting, {0, 0, 0}, up), 1e-3);
  EXPECT_EQ(sphere({0.5, -0.2, 0}, 0.1).irradiance_factor({0, 0, 0}, up), 0.0);
}

TEST(Lights, SamplingDensitiesAgreeWithTheLookUp) {
  Rng rng(3, 1, 0);
  for (const AreaLight& l : {rect({0, 0.6, 0.5}, {0, -0.6, -0.5}, {0.2, 0, 0}, {0, 0.1, -0.12}),
                             sphere({0.1, 0.4, -0.3}, 0.07)}) {
    for (int i = 0; i < 100; ++i) {
      AreaLight::Sample s;
      const double v = rng.uniform(), u = rng.uniform();  // (drawn in this order)
      ASSERT_TRUE(l.sample_from({0, 0, 0}, u, v, s));
      EXPECT_NEAR(l.pdf_from({0, 0, 0}, s.dir), s.pdf, 1e-6 * s.pdf);
      double t;
      ASSERT_TRUE(l.intersect({0, 0, 0}, s.dir, 0, t));
      EXPECT_NEAR(t, s.dist, 1e-6);
    }
    // Away from the light: no density.
    EXPECT_EQ(l.pdf_from({0, 0, 0}, {0, -1, 0}), 0.0);
  }
}

TEST(Lights, ARectIsSeenFromItsFrontOnly) {
  const AreaLight l = rect({0, 0, -1}, {0, 0, 1}, {0.5, 0, 0}, {0, 0.5, 0});
  double t;
  EXPECT_TRUE(l.intersect({0, 0, 0}, {0, 0, -1}, 0, t));
  EXPECT_DOUBLE_EQ(t, 1.0);
  EXPECT_FALSE(l.intersect({0, 0, -2}, {0, 0, 1}, 0, t));  // its back
  EXPECT_FALSE(l.intersect({0, 0, 0}, glm::normalize(glm::dvec3(0.6, 0, -1)), 0, t));  // beside it
}

TEST(Lights, PlacedLightsFaceTheSceneAndEmitTheirPower) {
  LightParams p;
  p.direction = {0, 0, 2};
  p.distance = 0.8f;
  p.width = 0.4f;
  p.height = 0.2f;
  p.color = {1, 0.5f, 0.25f};
  p.power = 3;
  const glm::dvec3 aim(0.1, 0.07, 0);
  const AreaLight l = place_light(p, aim);
  EXPECT_NEAR(glm::distance(l.center, aim + glm::dvec3(0, 0, 0.8)), 0, 1e-6);
  EXPECT_NEAR(glm::dot(l.normal, glm::dvec3(0, 0, -1)), 1, 1e-12);
  EXPECT_NEAR(2 * glm::length(l.half_v), 0.2, 1e-6);
  EXPECT_NEAR(l.half_v.y, 0.1, 1e-6);  // its height runs up
  // A Lambertian emitter of radiance L and area A gives off pi L A.
  EXPECT_NEAR(kPi * l.radiance.r * l.area(), 3.0, 1e-5);
  EXPECT_NEAR(kPi * l.radiance.b * l.area(), 0.75, 1e-5);
  p.shape = int(LightShape::Sphere);
  const AreaLight s = place_light(p, aim);
  EXPECT_NEAR(s.radius, 0.2, 1e-6);
  EXPECT_NEAR(kPi * s.radiance.r * s.area(), 3.0, 1e-5);
  // Straight overhead: still a proper rect.
  p.shape = int(LightShape::Rect);
  p.direction = {0, 1, 0};
  EXPECT_NEAR(place_light(p, aim).area(), 0.08, 1e-6);
}

TEST(Lights, TheRigHasItsEmittingLightsWithMirroredStrips) {
  SceneParams p;
  const LightRig rig = light_rig(p, {0, 0.07, 0});
  ASSERT_EQ(rig.lights.size(), 4u);
  EXPECT_NEAR(rig.lights[1].center.x, -rig.lights[2].center.x, 1e-12);
  EXPECT_NEAR(rig.lights[1].center.z, rig.lights[2].center.z, 1e-12);
  p.strips.power = 0;
  p.light.power = 0;
  EXPECT_EQ(light_rig(p, {0, 0, 0}).lights.size(), 1u);
}

}  // namespace
}  // namespace draught
