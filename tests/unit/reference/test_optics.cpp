// Optics: Snell refraction and Fresnel reflectance.
#include "core/reference/optics.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace draught {
namespace {

using glm::dvec3;

double sin_between(const dvec3& a, const dvec3& n) { return glm::length(glm::cross(a, n)); }

// ------------------------------------------------------------------- Snell --

TEST(Refraction, ObeysSnellsLaw) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  for (const auto& [n1, n2] : {std::pair{1.0, 1.52}, std::pair{1.0, 1.34}, std::pair{1.34, 1.52},
                               std::pair{1.52, 1.34}, std::pair{1.52, 1.0}, std::pair{1.33, 1.0}}) {
    const double eta = n1 / n2;
    int refracted = 0;
    for (int k = 0; k < 2000; ++k) {
      // A random normal and an incident direction against it.
      const double a = 2 * kPi * u(rng), b = std::acos(2 * u(rng) - 1);
      const dvec3 n(std::sin(b) * std::cos(a), std::cos(b), std::sin(b) * std::sin(a));
      const double theta = 0.5 * kPi * u(rng), phi = 2 * kPi * u(rng);
      const dvec3 t1 = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
      const dvec3 t2 = glm::cross(n, t1);
      const dvec3 i = -std::cos(theta) * n + std::sin(theta) * (std::cos(phi) * t1 + std::sin(phi) * t2);
      const double sin_i = std::sin(theta);
      const auto t = refract_dir(i, n, eta);
      if (n1 * sin_i > n2 * (1 + 1e-12)) {
        EXPECT_FALSE(t.has_value()) << "total internal reflection expected, n1=" << n1 << " n2=" << n2;
        continue;
      }
      if (n1 * sin_i > n2 * (1 - 1e-9)) continue;  // right at the critical angle
      ASSERT_TRUE(t.has_value()) << "n1=" << n1 << " n2=" << n2 << " theta=" << theta;
      ++refracted;
      EXPECT_NEAR(glm::length(*t), 1.0, 1e-12);
      EXPECT_NEAR(n1 * sin_i, n2 * sin_between(*t, n), 1e-12);
      EXPECT_LT(glm::dot(*t, n), 0.0) << "transmitted ray must continue through the surface";
      EXPECT_NEAR(glm::dot(*t, glm::cross(i, n)), 0.0, 1e-12) << "must stay in the plane of incidence";
      // Bends towards the normal going into the denser medium, away from it otherwise.
      if (sin_i > 1e-6) {
        if (n2 > n1) { EXPECT_LT(sin_between(*t, n), sin_i); }
        else { EXPECT_GT(sin_between(*t, n), sin_i); }
      }
    }
    EXPECT_GT(refracted, 500);
  }
}

TEST(Refraction, NormalIncidenceGoesStraightThrough) {
  const auto t = refract_dir({0, -1, 0}, {0, 1, 0}, 1.0 / 1.5);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(glm::length(*t - dvec3(0, -1, 0)), 0.0, 1e-15);
}

TEST(Refraction, TotalInternalReflectionPastTheCriticalAngle) {
  const double n1 = 1.52, n2 = 1.0, crit = std::asin(n2 / n1);
  const dvec3 n(0, 1, 0);
  auto incident = [&](double th) { return dvec3(std::sin(th), -std::cos(th), 0); };
  EXPECT_TRUE(refract_dir(incident(crit - 1e-6), n, n1 / n2).has_value());
  EXPECT_FALSE(refract_dir(incident(crit + 1e-6), n, n1 / n2).has_value());
  EXPECT_FALSE(refract_dir(incident(0.5 * kPi - 1e-3), n, n1 / n2).has_value());
  // Just below the critical angle the refracted ray skims the surface.
  const auto t = refract_dir(incident(crit - 1e-9), n, n1 / n2);
  ASSERT_TRUE(t.has_value());
  EXPECT_LT(std::fabs(t->y), 1e-3);
}

TEST(Reflection, MirrorsAboutTheNormal) {
  std::mt19937 rng(32);
  std::normal_distribution<double> g;
  for (int k = 0; k < 200; ++k) {
    const dvec3 n = glm::normalize(dvec3(g(rng), g(rng), g(rng)));
    dvec3 i = glm::normalize(dvec3(g(rng), g(rng), g(rng)));
    if (glm::dot(i, n) > 0) i = -i;
    const dvec3 r = reflect_dir(i, n);
    EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(r, n), -glm::dot(i, n), 1e-12);               // equal angles
    EXPECT_NEAR(glm::length(glm::cross(i, n) - glm::cross(r, n)), 0.0, 1e-12);  // same tangential part
  }
}

// ----------------------------------------------------------------- Fresnel --

TEST(Fresnel, NormalIncidence) {
  for (const auto& [n1, n2] : {std::pair{1.0, 1.52}, std::pair{1.0, 1.34}, std::pair{1.34, 1.52}, std::pair{1.52, 1.0}}) {
    const double r = (n1 - n2) / (n1 + n2);
    EXPECT_NEAR(fresnel_dielectric(1.0, n1, n2), r * r, 1e-15);
  }
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.5), 0.04, 1e-15);
  EXPECT_NEAR(fresnel_dielectric(0.3, 1.4, 1.4), 0.0, 1e-20);  // index matched: no reflection
}

TEST(Fresnel, GoesToOneAtGrazingIncidence) {
  for (double n2 : {1.2, 1.34, 1.52, 2.4}) {
    EXPECT_NEAR(fresnel_dielectric(0.0, 1.0, n2), 1.0, 1e-12);
    EXPECT_GT(fresnel_dielectric(1e-4, 1.0, n2), 0.99);
    // Increases monotonically towards grazing (external reflection).
    double prev = fresnel_dielectric(1.0, 1.0, n2);
    for (int k = 1; k <= 1000; ++k) {
      const double f = fresnel_dielectric(1.0 - k / 1000.0, 1.0, n2);
      EXPECT_GE(f, prev - 1e-15);
      prev = f;
    }
  }
}

TEST(Fresnel, OneBeyondTheCriticalAngle) {
  const double n1 = 1.52, n2 = 1.0, crit = std::asin(n2 / n1);
  for (double th = crit + 1e-6; th < 0.5 * kPi; th += 0.01) EXPECT_EQ(fresnel_dielectric(std::cos(th), n1, n2), 1.0);
  EXPECT_LT(fresnel_dielectric(std::cos(crit - 1e-3), n1, n2), 1.0);
}

TEST(Fresnel, BrewsterAngleLeavesOnlyTheSPolarisation) {
  // At Brewster's angle tan(theta) = n2 / n1 the p-reflectance vanishes and
  // theta_i + theta_t = 90 degrees, so r_s = cos(2 theta_B) and F = r_s^2 / 2.
  for (const auto& [n1, n2] : {std::pair{1.0, 1.52}, std::pair{1.0, 1.34}, std::pair{1.52, 1.0}, std::pair{1.34, 1.52}}) {
    const double th = std::atan(n2 / n1);
    const double rs = std::cos(2 * th);
    EXPECT_NEAR(fresnel_dielectric(std::cos(th), n1, n2), 0.5 * rs * rs, 1e-14) << n1 << " -> " << n2;
    // Away from Brewster's angle the p-component no longer vanishes: F > r_s^2 / 2,
    // with r_s from the textbook formula.
    for (double dth : {-0.05, 0.05}) {
      const double ti = th + dth, tt = std::asin(n1 / n2 * std::sin(ti));
      const double s = std::sin(ti - tt) / std::sin(ti + tt);
      EXPECT_GT(fresnel_dielectric(std::cos(ti), n1, n2), 0.5 * s * s);
    }
  }
}

TEST(Fresnel, TextbookFormulaAtRandomAngles) {
  // r_s = -sin(ti - tt) / sin(ti + tt), r_p = tan(ti - tt) / tan(ti + tt).
  std::mt19937 rng(33);
  std::uniform_real_distribution<double> u(0.01, 0.5 * kPi - 0.01);
  for (int k = 0; k < 500; ++k) {
    const double n1 = k % 2 ? 1.0 : 1.34, n2 = k % 3 ? 1.52 : 1.34 + 0.1 * (k % 5);
    const double ti = u(rng), st = n1 / n2 * std::sin(ti);
    if (st >= 1) continue;
    const double tt = std::asin(st);
    if (std::fabs(ti - tt) < 1e-9) continue;
    const double rs = std::sin(ti - tt) / std::sin(ti + tt), rp = std::tan(ti - tt) / std::tan(ti + tt);
    EXPECT_NEAR(fresnel_dielectric(std::cos(ti), n1, n2), 0.5 * (rs * rs + rp * rp), 1e-12);
  }
}

TEST(Fresnel, ReflectedAndTransmittedPowerSumToOne) {
  // Energy per interface: R = F and the transmitted power from the Fresnel transmission
  // amplitudes, T = (n2 cos tt) / (n1 cos ti) t^2 per polarisation (the beam's change of
  // cross-section and speed), add up to 1 at every angle and for every pair of the
  // renderer's media (air 1, drinks 1.33-1.36, glass 1.5-1.52), both ways.
  for (const auto& [a, b] : {std::pair{1.0, 1.52}, std::pair{1.0, 1.333}, std::pair{1.333, 1.52}, std::pair{1.36, 1.5}})
    for (const auto& [n1, n2] : {std::pair{a, b}, std::pair{b, a}})
      for (double ti = 0.0; ti < 0.5 * kPi; ti += 0.01) {
        const double st = n1 / n2 * std::sin(ti);
        const double ci = std::cos(ti);
        const double F = fresnel_dielectric(ci, n1, n2);
        if (st >= 1) {
          EXPECT_EQ(F, 1.0);  // total internal reflection: nothing is transmitted
          continue;
        }
        const double ct = std::sqrt(1 - st * st);
        const double ts = 2 * n1 * ci / (n1 * ci + n2 * ct), tp = 2 * n1 * ci / (n1 * ct + n2 * ci);
        const double T = n2 * ct / (n1 * ci) * 0.5 * (ts * ts + tp * tp);
        EXPECT_NEAR(F + T, 1.0, 1e-12) << n1 << " -> " << n2 << " at " << ti;
      }
}

TEST(Fresnel, Reciprocity) {
  // Light going back along the refracted path sees the same reflectance.
  for (double ti = 0.0; ti < 1.5; ti += 0.05) {
    const double n1 = 1.0, n2 = 1.52, tt = std::asin(n1 / n2 * std::sin(ti));
    EXPECT_NEAR(fresnel_dielectric(std::cos(ti), n1, n2), fresnel_dielectric(std::cos(tt), n2, n1), 1e-12);
  }
}

}  // namespace
}  // namespace draught
