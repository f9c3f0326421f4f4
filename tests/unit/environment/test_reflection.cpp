// The environment estimate handed to the renderer: what a rising bubble mirrors is the
// mean of its surroundings (the sky, each light over its solid angle, the lit backdrop);
// the glint is the brightest light's; the sky's irradiance is its spherical-harmonic
// projection.
#include "core/environment/reflection.hpp"
#include "core/params/params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace draught {
namespace {

SceneParams dark_studio() {
  SceneParams p = default_params();
  p.env.mode = int(EnvMode::Constant);
  p.env.color = {0.5f, 0.5f, 0.5f};
  p.env.floor = false;
  p.light.power = p.strips.power = p.backlight.power = 0;
  return p;
}

TEST(Environment, BubblesMirrorAConstantSkyAsIs) {
  const SceneParams p = dark_studio();
  const LightRig rig = light_rig(p, {0, 0.08, 0});
  const EnvironmentFrame f = environment_frame(p, rig, backdrop_surface(p.env, rig.aim));
  EXPECT_NEAR(f.reflected.g, 0.5f, 2e-3f);
  EXPECT_FLOAT_EQ(f.glint.g, 0.0f);
}

TEST(Environment, BubblesMirrorTheLightsOverTheirSolidAngle) {
  SceneParams p = dark_studio();
  p.env.color = glm::vec3(0.0f);
  p.light.power = 3.0f;
  p.light.shape = int(LightShape::Sphere);
  const LightRig rig = light_rig(p, {0, 0.08, 0});
  ASSERT_EQ(rig.lights.size(), 1u);
  const AreaLight& l = rig.lights[0];
  const EnvironmentFrame f = environment_frame(p, rig, backdrop_surface(p.env, rig.aim));
  // A sphere of radius r at distance D covers 2 pi (1 - cos) of the 4 pi around the centre.
  const double d = glm::distance(l.center, rig.aim), omega = 2 * std::numbers::pi * (1 - std::sqrt(1 - l.radius * l.radius / (d * d)));
  // (The estimate takes the cosine-weighted solid angle, pi sin^2 sigma, a factor
  // (1 + cos sigma) / 2 of the true one: 2 % for this big, near sphere.)
  const double cos_s = std::sqrt(1 - l.radius * l.radius / (d * d));
  EXPECT_NEAR(f.reflected.g, l.radiance.g * omega / (4 * std::numbers::pi) * (1 + cos_s) / 2, 1e-3 * f.reflected.g);
  EXPECT_NEAR(glm::dot(glm::dvec3(f.glint_dir), glm::normalize(l.center - rig.aim)), 1.0, 1e-6);
  EXPECT_NEAR(f.glint.g, l.radiance.g * l.irradiance_factor(rig.aim, glm::normalize(l.center - rig.aim)), 1e-4 * f.glint.g);
}

// The nine coefficients give a constant sky's irradiance pi L everywhere, and a studio
// gradient's within 3 % of brute-force cosine-weighted integration.
TEST(Environment, SkyIrradianceMatchesDirectIntegration) {
  SceneParams p = default_params();
  p.env.mode = int(EnvMode::Constant);
  p.env.color = {0.3f, 0.5f, 0.7f};
  const SkyIrradiance c = sky_irradiance(Studio(p));
  for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(1, 0.3, -0.5))})
    EXPECT_NEAR(c.at(n).b, std::numbers::pi * 0.7, 2e-3);
  p.env.mode = int(EnvMode::Studio);
  p.env.sky_top = {0.9f, 0.9f, 0.9f};
  p.env.sky_horizon = {0.3f, 0.3f, 0.3f};
  p.env.ground = {0.05f, 0.05f, 0.05f};
  p.env.strip_intensity = 0;
  p.env.backdrop_glow = 0;
  const Studio studio(p);
  const SkyIrradiance s = sky_irradiance(studio);
  for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(0.3, 0.5, 0.8))}) {
    // Brute force over the hemisphere around n.
    glm::dvec3 t = glm::normalize(glm::cross(n, std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    glm::dvec3 b = glm::cross(n, t);
    double e = 0;
    const int k = 400;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const double u = (i + 0.5) / k, ph = 2 * std::numbers::pi * (j + 0.5) / k;
        const double r = std::sqrt(u);  // cosine-weighted: pdf cos / pi
        const glm::dvec3 d = r * std::cos(ph) * t + r * std::sin(ph) * b + std::sqrt(1 - u) * n;
        e += studio.sky(d).g;
      }
    e *= std::numbers::pi / (k * k);
    EXPECT_NEAR(s.at(n).g, e, 0.03 * e) << n.x << "," << n.y << "," << n.z;
  }
}

// What heads and haze are lit by besides the lights: with no backdrop, the sky itself;
// under a constant sky over white paper lit by that sky alone, the paper is as bright as
// the sky (albedo 1), so the surround is the same even light (the furnace); and a lit
// sweep throws light back: the surround then gives a surface facing down (the paper
// below) more than the sky alone does.
TEST(Environment, TheSurroundIsTheSkyAndTheLitBackdrop) {
  SceneParams p = dark_studio();
  const LightRig none = light_rig(p, {0, 0.08, 0});
  const EnvironmentFrame bare = environment_frame(p, none, backdrop_surface(p.env, none.aim));
  for (int k = 0; k < 9; ++k) EXPECT_EQ(bare.surround.coef[size_t(k)], bare.sky.coef[size_t(k)]);

  p.env.floor = true;
  p.env.sweep_color = {1.0f, 1.0f, 1.0f};
  const EnvironmentFrame white = environment_frame(p, none, backdrop_surface(p.env, none.aim));
  for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1)})
    EXPECT_NEAR(white.surround.at(n).g, std::numbers::pi * 0.5, 0.02 * std::numbers::pi * 0.5) << n.x << n.y << n.z;
  EXPECT_NEAR(mean_radiance(white.surround).g, 0.5, 0.01);

  SceneParams lit = default_params();
  const LightRig rig = light_rig(lit, {0, 0.08, 0});
  const EnvironmentFrame f = environment_frame(lit, rig, backdrop_surface(lit.env, rig.aim));
  EXPECT_GT(f.surround.at({0, -1, 0}).g, 1.5 * f.sky.at({0, -1, 0}).g);
  EXPECT_GT(mean_radiance(f.surround).g, mean_radiance(f.sky).g);
}

}  // namespace
}  // namespace draught
