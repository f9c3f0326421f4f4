// The head as a medium: its colour to single-scattering albedo (diffusion theory), the
// density field's bound, how it thins low in the head, where along a ray it can be, and
// how far light from below crosses the drink to it.
#include "core/foam/head_volume.hpp"
#include "core/scene/frame.hpp"

#include "../test_common.hpp"

#include <gtest/gtest.h>

#include <random>

namespace draught {
namespace {

TEST(FoamAlbedo, ReflectanceInvertsToTheSingleScatteringAlbedo) {
  for (double g : {0.0, 0.3, 0.7})
    for (double R : {0.0, 0.1, 0.5, 0.8, 0.9, 0.97, 0.99, 1.0}) {
      const glm::dvec3 a = foam_single_scattering_albedo(glm::dvec3(R), g);
      EXPECT_NEAR(foam_reflectance(a.x, g), R, 1e-9) << "R " << R << " g " << g;
    }
}

TEST(FoamAlbedo, AWhiteHeadScattersAlmostWithoutLoss) {
  // A head that looks 97 % white loses about 2e-4 of the light per scattering.
  EXPECT_NEAR(foam_single_scattering_albedo(glm::dvec3(0.97), 0.0).x, 0.9998, 1e-4);
  EXPECT_DOUBLE_EQ(foam_single_scattering_albedo(glm::dvec3(1.0), 0.0).x, 1.0);
  EXPECT_NEAR(foam_single_scattering_albedo(glm::dvec3(0.0), 0.0).x, 0.0, 1e-9);
  // Darker heads need a lower albedo, channel by channel.
  const glm::dvec3 tan = foam_single_scattering_albedo({0.9, 0.8, 0.6}, 0.0);
  EXPECT_GT(tan.r, tan.g);
  EXPECT_GT(tan.g, tan.b);
}

struct Head {
  FrameState frame;
  SceneGeometry geo;
  HeadVolume volume() const { return HeadVolume(frame.vessels[0], geo.vessels[0]); }
};

Head default_head() {
  Head h{make_frame(test::params_with_glass("pint")), {}};
  h.geo = scene_geometry(h.frame);
  return h;
}

void expect_density_under_bound_and_inside_interval(const Head& h) {
  const HeadVolume head = h.volume();
  ASSERT_FALSE(head.empty());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vessel& v = h.frame.vessels[0].vessel;
  int inside = 0;
  for (int i = 0; i < 4000; ++i) {
    // Rays through random points of the glass's bounding box.
    const glm::dvec3 p(u(rng) * v.bound_radius, v.height * (0.5 + 0.5 * u(rng)), u(rng) * v.bound_radius);
    glm::dvec3 d(u(rng), u(rng), u(rng));
    if (glm::length(d) < 1e-3) continue;
    d = glm::normalize(d);
    const double sigma = head.density(p);
    ASSERT_LE(sigma, head.majorant()) << i;
    if (sigma <= 0) continue;
    ++inside;
    double t0 = -1, t1 = 1;  // the ray o = p - d through p at t = 1
    ASSERT_TRUE(head.interval(p - d, d, t0, t1)) << i;
    EXPECT_LE(t0, 1.0);
    EXPECT_GE(t1, 1.0);
  }
  EXPECT_GT(inside, 40);  // the test saw the head
}

TEST(HeadVolume, DensityStaysUnderItsBoundAndInsideItsInterval) { expect_density_under_bound_and_inside_interval(default_head()); }

// Where a pour's stream plunges in, the head dips to a tenth of its thickness and heaps
// the foam in a collar around the dimple; the interval still holds the collar.
TEST(HeadVolume, APoursCraterDipsAndItsCollarStaysInsideTheInterval) {
  Head h = default_head();
  const double radius = 0.012, x_collar = 0.01 + FoamFrame::kCraterCollarAt * radius;
  const double flat = h.volume().thickness_at(0.01, 0.0), flat_collar = h.volume().thickness_at(x_collar, 0.0),
               flat_far = h.volume().thickness_at(-0.04, 0.0);
  FoamFrame& fo = h.frame.vessels[0].foam;
  fo.crater_xz = {0.01, 0.0};
  fo.crater_radius = radius;
  fo.crater_depth = FoamFrame::kMaxCraterDepth;
  const HeadVolume head = h.volume();
  EXPECT_NEAR(head.thickness_at(0.01, 0.0), flat * (1 - FoamFrame::kMaxCraterDepth), 0.01 * flat);
  EXPECT_GT(head.thickness_at(x_collar, 0.0), flat_collar * (1 + 0.5 * FoamFrame::kCraterCollar * fo.crater_depth))
      << "the foam pushed aside heaps in a collar";
  EXPECT_NEAR(head.thickness_at(-0.04, 0.0), flat_far, 1e-4 * flat) << "far from the dimple the head is as it was";
  expect_density_under_bound_and_inside_interval(h);
}

TEST(HeadVolume, NoFoamUnderTheLiquidOrOutsideTheCavity) {
  const Head h = default_head();
  const HeadVolume head = h.volume();
  const VesselFrame& vf = h.frame.vessels[0];
  const double level = vf.liquid.offset;  // upright: the surface's height
  EXPECT_EQ(head.density({0, level - 0.002, 0}), 0);
  EXPECT_GT(head.density({0, level + 0.5 * vf.foam.thickness, 0}) + head.density({0.003, level + 0.4 * vf.foam.thickness, 0.002}), 0);
  EXPECT_EQ(head.density({vf.vessel.bound_radius, level + 0.005, 0}), 0);
}

// Wet foam low in the head has bigger bubbles and so less extinction (1 / size): its
// mean density just above the liquid is about 1 / 2.5 of the mean near the top (below
// its soft edge). Averaged over many points across the head, away from big bubbles.
TEST(HeadVolume, TheWetFoamLowInTheHeadIsTheMoreTranslucent) {
  Head h = default_head();
  h.frame.vessels[0].big_bubbles.clear();
  const HeadVolume head = h.volume();
  const VesselFrame& vf = h.frame.vessels[0];
  const double level = vf.liquid.offset;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  double low = 0, high = 0;
  for (int i = 0; i < 4000; ++i) {
    const double x = u(rng), z = u(rng), top = head.thickness_at(x, z);
    low += head.density({x, level + 0.02 * top, z});
    high += head.density({x, level + 0.8 * top, z});
  }
  EXPECT_NEAR(low / high, (1 + 1.5 * 0.2) / (1 + 1.5 * 0.98), 0.08);
}

// Light from below reaches the head's underside across the drink: a chord of a few
// centimetres in a pint, none without liquid.
TEST(HeadVolume, LightFromBelowCrossesCentimetresOfTheDrink) {
  const Head h = default_head();
  const double chord = drink_mean_chord(h.frame.vessels[0]);
  EXPECT_GT(chord, 0.03);
  EXPECT_LT(chord, 0.12);
  Params p = test::params_with_glass("pint");
  p.liquid.fill = 0;
  EXPECT_EQ(drink_mean_chord(make_frame(p).vessels[0]), 0);
}

TEST(HeadVolume, NoHeadWithoutLiquid) {
  Params p = test::params_with_glass("pint");
  p.liquid.fill = 0;
  const FrameState f = make_frame(p);
  EXPECT_TRUE(HeadVolume(f.vessels[0], scene_geometry(f).vessels[0]).empty());
}

TEST(HeadVolume, TheWallPassesMostOfEvenLight) {
  // No interface: all of it. Glass of 1.5: 0.84 (two faces' Fresnel, cosine-weighted;
  // 0.92 face-on, (1 - 0.04)^2). Denser glass passes less.
  EXPECT_NEAR(wall_diffuse_transmittance(1.0), 1.0, 1e-12);
  EXPECT_NEAR(wall_diffuse_transmittance(1.5), 0.84, 0.01);
  EXPECT_LT(wall_diffuse_transmittance(1.9), wall_diffuse_transmittance(1.5));
  EXPECT_GT(wall_diffuse_transmittance(1.9), 0.7);
}

}  // namespace
}  // namespace draught
