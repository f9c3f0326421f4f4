// A hot cloud's glow as a sphere (core/pointcloud/glow_light): where it is, how wide, how
// bright by the law the reference's chord uses; none for a cloud that cannot glow; the
// sphere's irradiance by Snyder's formula against its closed forms.
#include "core/environment/lights.hpp"
#include "core/pointcloud/glow_light.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

namespace draught {
namespace {

// `n` points evenly at random in a ball of radius R about `centre`, each a blob of `blob`.
CloudFrame ball(std::size_t n, glm::dvec3 centre, double R, double blob, float kelvin) {
  auto pc = std::make_shared<PointCloud>();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  while (pc->size() < n) {
    const glm::dvec3 p(u(rng), u(rng), u(rng));
    if (glm::dot(p, p) <= 1.0) pc->position.push_back(glm::vec3(centre + R * p));
  }
  pc->default_radius = float(blob);
  CloudFrame c;
  c.points = pc;
  c.glow = 1.0f;
  c.glow_depth = 0.02f;
  c.ior = 1.5f;
  c.temperature = kelvin;
  return c;
}

TEST(GlowLight, AHotBallIsASphereOfItsSizeAndEmission) {
  const glm::dvec3 centre(0.1, 0.2, -0.05);
  const double R = 0.03, blob = 0.002;
  const CloudFrame c = ball(20000, centre, R, blob, 1373.15f);
  const GlowSphere s = cloud_glow_sphere(c);
  ASSERT_FALSE(s.empty());
  EXPECT_LT(glm::length(s.centre - centre), 0.05 * R);  // (4096 of the points sampled)
  EXPECT_NEAR(s.radius, R + blob, 0.03 * R);  // sqrt(5/3) x the RMS distance of a uniform ball is its radius
  // Every point at 1100 C: the mean chord 4 R / 3 of the sphere it found, at the full
  // extinction 1 / glow_depth, out through the surface at normal incidence.
  const double emissivity = 1.0 - std::exp(-(4.0 / 3.0 * s.radius) / double(0.02f)), f0 = 0.04;
  const glm::dvec3 expect = emissivity * (1.0 - f0) * kGlowPerNit * glow_table(double(1373.15f));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.radiance[k], expect[k], 1e-9 * expect[k] + 1e-12);
  EXPECT_GT(s.radiance.r, s.radiance.g);  // orange
  EXPECT_GT(s.radiance.g, s.radiance.b);
}

TEST(GlowLight, AMillionPointsAreSampledNotWalked) {
  // The same ball at 1M points, strided down to kGlowSamples: the same sphere within a
  // few per cent.
  const CloudFrame small = ball(kGlowSamples, glm::dvec3(0.0), 0.05, 0.001, 1300.0f);
  const CloudFrame big = ball(1000000, glm::dvec3(0.0), 0.05, 0.001, 1300.0f);
  const GlowSphere a = cloud_glow_sphere(small), b = cloud_glow_sphere(big);
  EXPECT_NEAR(a.radius, b.radius, 0.02 * a.radius);
  EXPECT_NEAR(b.radiance.r, a.radiance.r, 0.02 * a.radiance.r);
  EXPECT_LT(glm::length(b.centre), 0.05 * 0.05);
}

TEST(GlowLight, CoolNoGlowOrNoPointsCastsNothing) {
  EXPECT_TRUE(cloud_glow_sphere(ball(1000, glm::dvec3(0.0), 0.03, 0.002, 690.0f)).empty());  // below 700 K
  CloudFrame no_glow = ball(1000, glm::dvec3(0.0), 0.03, 0.002, 1373.15f);
  no_glow.glow = 0;
  EXPECT_TRUE(cloud_glow_sphere(no_glow).empty());
  CloudFrame drink = ball(1000, glm::dvec3(0.0), 0.03, 0.002, 1373.15f);
  drink.glow_depth = 0;  // a drink's stream: no visible extinction, no emission
  EXPECT_TRUE(cloud_glow_sphere(drink).empty());
  CloudFrame none;
  none.points = std::make_shared<PointCloud>();
  none.glow = 1;
  none.glow_depth = 0.02f;
  EXPECT_TRUE(cloud_glow_sphere(none).empty());
  EXPECT_TRUE(cloud_glow_sphere(CloudFrame{}).empty());
  // Points with their own temperatures: a cool half glows less than all hot.
  CloudFrame mixed = ball(2000, glm::dvec3(0.0), 0.03, 0.002, 1373.15f);
  auto pc = std::make_shared<PointCloud>(*mixed.points);
  pc->temperature.assign(pc->size(), 1373.15f);
  for (std::size_t i = 0; i < pc->size(); i += 2) pc->temperature[i] = 300.0f;
  const double hot = cloud_glow_sphere(mixed).radiance.r;
  mixed.points = pc;
  EXPECT_NEAR(cloud_glow_sphere(mixed).radiance.r, 0.5 * hot, 0.01 * hot);
}

TEST(GlowLight, ASphereGivesSnydersIrradiance) {
  const glm::dvec3 c(0.0, 1.0, 0.0), up(0.0, 1.0, 0.0);
  // Straight below, wholly above the horizon: pi sin^2 = pi r^2 / d^2.
  EXPECT_NEAR(sphere_irradiance_factor(c, 0.1, glm::dvec3(0.0), up), kPi * 0.01, 1e-12);
  // Off to the side, still above the horizon: times the cosine.
  const glm::dvec3 x(0.5, 0.0, 0.0), w = c - x;
  const double d2 = glm::dot(w, w);
  EXPECT_NEAR(sphere_irradiance_factor(c, 0.1, x, up), kPi * 0.01 / d2 * w.y / std::sqrt(d2), 1e-12);
  // Inside the sphere: pi; wholly below the horizon: 0; half across it, about half.
  EXPECT_NEAR(sphere_irradiance_factor(c, 2.0, glm::dvec3(0.0), up), kPi, 1e-12);
  EXPECT_EQ(sphere_irradiance_factor(c, 0.1, glm::dvec3(0.0), -up), 0.0);
  const double grazing = sphere_irradiance_factor(glm::dvec3(1.0, 0.0, 0.0), 0.1, glm::dvec3(0.0), up);
  EXPECT_GT(grazing, 0.0);
  EXPECT_LT(grazing, kPi * 0.01);
}

}  // namespace
}  // namespace draught
