// The reference path tracer: furnace tests (in a uniform environment with no floor and
// no key light, what only refracts, reflects or scatters without loss is invisible),
// determinism, and that what absorbs or is lit shows.
#include "core/reference/path_tracer.hpp"

#include "core/environment/studio.hpp"
#include "core/foam/head_volume.hpp"
#include "core/pointcloud/blackbody.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <memory>

namespace draught {
namespace {

constexpr glm::vec3 kEnv{0.5f, 0.4f, 0.3f};

// The default pint, lit only by a uniform environment, with nothing that absorbs.
Params furnace_params() {
  Params p = test::params_with_glass("pint");
  p.env.mode = int(EnvMode::Constant);
  p.env.color = kEnv;
  p.env.floor = false;
  p.light.power = p.strips.power = p.backlight.power = 0;  // no lights
  p.glass.absorption = glm::vec3(0);
  p.liquid.srm = 0;
  p.liquid.absorption = glm::vec3(0);
  p.liquid.haze = 0;
  p.foam.height = 0;
  return p;
}

RadianceImage render(const FrameState& f, int size, int spp) {
  ReferenceSettings s;
  s.samples = spp;
  s.threads = 2;
  s.max_surfaces = 1024;  // a path may be piped along a wall by total internal reflection for hundreds of bounces (one of 1600 here takes 300); the furnace counts every one
  return render_reference(f, size, size, s);
}
RadianceImage render(const Params& p, int size, int spp) { return render(make_frame(p), size, spp); }

// The largest relative difference of any pixel channel from the environment.
double worst_error(const RadianceImage& img) {
  double worst = 0;
  for (const glm::dvec3& c : img.pixels)
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::fabs(c[i] / kEnv[i] - 1.0));
  return worst;
}

TEST(ReferenceFurnace, ANonAbsorbingGlassIsInvisible) {
  Params p = furnace_params();
  p.liquid.fill = 0;
  EXPECT_LT(worst_error(render(p, 20, 4)), 0.02);
}

TEST(ReferenceFurnace, ANonAbsorbingDrinkIsInvisible) {
  Params p = furnace_params();
  p.liquid.fill = 0.8f;
  EXPECT_LT(worst_error(render(p, 20, 4)), 0.02);
}

TEST(ReferenceFurnace, AHazeThatOnlyScattersIsInvisible) {
  Params p = furnace_params();
  p.liquid.fill = 0.8f;
  p.liquid.haze = 40;
  p.liquid.haze_color = glm::vec3(1);
  EXPECT_LT(worst_error(render(p, 16, 4)), 0.02);
}

TEST(ReferenceFurnace, AScatteringOnlyHeadComesOutAtTheEnvironmentsBrightness) {
  Params p = furnace_params();
  p.liquid.fill = 0.8f;
  p.foam.height = 0.015f;
  p.foam.density = 400;  // ~6 mean free paths deep: many scatterings per path, a quick test
  p.foam.color = glm::vec3(1);
  p.foam.anisotropy = 0.3f;
  const FrameState f = make_frame(p);
  ASSERT_FALSE(HeadVolume(f.vessels[0], scene_geometry(f).vessels[0]).empty());
  EXPECT_LT(worst_error(render(p, 16, 4)), 0.03);
}

// A band of the shipped gold-band decal (white, its middle opaque) round the pint at
// 7 cm, and a camera that sees only that opaque middle, straight on.
Params decal_furnace(DecalKind kind, glm::vec3 colour) {
  Params p = furnace_params();
  p.liquid.fill = 0;
  p.decal_outer.file = "gold-band";
  p.decal_outer.kind = int(kind);
  p.decal_outer.width = 0;
  p.decal_outer.height = 0.07f;
  p.decal_outer.color = colour;
  p.camera.auto_frame = false;
  p.camera.eye = {0.0f, 0.07f, 0.08f};  // 4 mm of the band's middle in view
  p.camera.target = {0.0f, 0.07f, 0.0f};
  p.camera.vfov = 5;
  return p;
}

TEST(ReferenceFurnace, AWhiteDecalOfAnyKindIsInvisible) {
  // White paint, white frost and a white mirror lose nothing: in a uniform environment they
  // show it, like the clear glass around them (the decals' energy is conserved).
  for (DecalKind kind : {DecalKind::Enamel, DecalKind::Etched, DecalKind::Metallic}) {
    Params p = decal_furnace(kind, glm::vec3(1));
    p.camera.vfov = 28;  // the whole band and the glass around it
    EXPECT_LT(worst_error(render(p, 16, 4)), 0.02) << int(kind);
  }
}

TEST(ReferenceFurnace, AColouredDecalShowsItsColourUnderTheGlassGloss) {
  // From the air a decal lies under the surface's gloss: F of the environment, and of the
  // rest the paint's albedo (enamel) or the metal's reflectance (metallic).
  const double F = std::pow((1.52 - 1.0) / (1.52 + 1.0), 2);  // straight on
  const glm::vec3 colour{0.8f, 0.5f, 0.2f};
  for (DecalKind kind : {DecalKind::Enamel, DecalKind::Metallic}) {
    // The mean of 4 x 4 pixels of 64 paths: a path is either reflected (F) or coloured.
    const RadianceImage img = render(decal_furnace(kind, colour), 4, 64);
    glm::dvec3 mean(0.0);
    for (const glm::dvec3& c : img.pixels) mean += c / double(img.pixels.size());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean[i] / kEnv[i], F + (1 - F) * colour[i], 0.02) << int(kind) << " channel " << i;
  }
}

TEST(ReferenceFurnace, ACondensedGlassWithoutMistIsInvisible) {
  // Beads are water lenses on the wall (their caps and the water-glass face reflect or
  // pass by Fresnel): nothing is lost, so a cold glass without mist vanishes too.
  Params p = furnace_params();
  p.liquid.fill = 0.8f;  // (a clear drink: the cold band is the drink's height)
  p.condensation.enabled = true;
  p.condensation.coverage = 0;
  const FrameState f = make_frame(p);
  ASSERT_TRUE(f.vessels[0].condensation);
  EXPECT_GT(f.vessels[0].condensation->beads.size(), 500u);
  EXPECT_LT(worst_error(render(f, 20, 4)), 0.02);
}

TEST(ReferenceFurnace, TheMistLosesOnlyWhatItsAlbedoLeaves) {
  // A fully fogged wall scatters FOG_SCATTER of what crosses it and absorbs 1 - FOG_ALBEDO
  // of that: a glass seen through two walls loses a few per cent, no more, and some.
  Params p = furnace_params();
  p.liquid.fill = 0.8f;  // (a clear drink: the cold band is the drink's height)
  p.condensation.enabled = true;
  p.condensation.coverage = 1;
  const double loss = worst_error(render(p, 20, 16));
  std::printf("a fogged glass in the furnace: worst %.3f\n", loss);
  EXPECT_GT(loss, 0.01);
  EXPECT_LT(loss, 0.2);
}

TEST(ReferenceFurnace, AnAbsorbingDrinkIsNotInvisible) {  // the tests above can fail
  Params p = furnace_params();
  p.liquid.fill = 0.8f;
  p.liquid.srm = 8;
  EXPECT_GT(worst_error(render(p, 16, 2)), 0.3);
}

TEST(ReferenceFurnace, AHeadThatAbsorbsIsDarker) {
  Params p = furnace_params();
  p.liquid.fill = 0.8f;
  p.foam.height = 0.015f;
  p.foam.density = 400;
  p.foam.color = glm::vec3(0.3f);  // a deep head of this colour reflects 30 % of even light
  EXPECT_GT(worst_error(render(p, 16, 2)), 0.1);
}

TEST(ReferencePathTracer, IsTheSameForAnyNumberOfThreads) {
  const FrameState f = make_frame(test::params_with_glass("pint"));
  ReferenceSettings s;
  s.samples = 2;
  s.threads = 1;
  const RadianceImage one = render_reference(f, 12, 10, s);
  s.threads = 3;
  const RadianceImage three = render_reference(f, 12, 10, s);
  ASSERT_EQ(one.pixels.size(), three.pixels.size());
  for (size_t i = 0; i < one.pixels.size(); ++i) EXPECT_EQ(one.pixels[i], three.pixels[i]) << i;
  s.seed = 2;
  const RadianceImage other = render_reference(f, 12, 10, s);
  EXPECT_NE(one.pixels, other.pixels);
}

TEST(ReferencePathTracer, ReportsProgressForEveryRow) {
  ReferenceSettings s;
  s.samples = 1;
  int calls = 0, last = 0;
  s.progress = [&](int done, int rows) {
    ++calls;
    EXPECT_EQ(rows, 7);
    EXPECT_EQ(done, last + 1);
    last = done;
  };
  render_reference(make_frame(test::params_with_glass("pint")), 5, 7, s);
  EXPECT_EQ(calls, 7);
}

// An empty scene but the floor, lit by one light of the rig and a black studio: the
// floor's radiance is albedo / pi x the light's irradiance (AreaLight::irradiance_factor,
// checked against Monte Carlo in tests/unit/environment/test_lights.cpp).
void expect_floor_irradiance(int shape, glm::vec3 direction, float distance) {
  Params p = test::params_with_glass("pint");
  p.env.mode = int(EnvMode::Constant);
  p.env.color = glm::vec3(0);
  p.env.backdrop = int(Backdrop::Checker);
  p.env.floor_a = p.env.floor_b = glm::vec3(0.5f);
  p.env.ground = glm::vec3(0);
  p.strips.power = p.backlight.power = 0;
  p.light.shape = shape;
  p.light.direction = direction;
  p.light.distance = distance;
  p.light.width = 0.3f;
  p.light.height = 0.2f;
  p.light.power = 2;
  p.light.color = glm::vec3(1);
  p.camera.auto_frame = false;
  p.camera.eye = {0.5f, 0.3f, 0.5f};
  p.camera.target = {0.5f, 0.0f, 0.45f};  // looking down at the floor beside the glass
  p.camera.vfov = 1;
  const FrameState f = make_frame(p);
  ASSERT_EQ(f.lights.lights.size(), 1u);
  const AreaLight& light = f.lights.lights[0];
  ReferenceSettings s;
  s.samples = 2000;
  s.threads = 2;
  const RadianceImage img = render_reference(f, 2, 2, s);
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& c : img.pixels) mean += c / double(img.pixels.size());
  // The checker floor fades with distance from the eye (as the picture's): ~0.3 m away.
  const glm::dvec3 at(0.5, 0.0, 0.45);
  const double expected = 0.5 / 3.141592653589793 * light.radiance.g * light.irradiance_factor(at, {0, 1, 0}) *
                          Studio::floor_visibility(std::sqrt(0.09 + 0.0025));
  EXPECT_NEAR(mean.g, expected, 0.02 * expected);
}

TEST(ReferencePathTracer, ARectLightGivesTheFloorItsIrradiance) {
  expect_floor_irradiance(int(LightShape::Rect), {0.3f, 1.0f, 0.2f}, 0.5f);
}

TEST(ReferencePathTracer, ASphereLightGivesTheFloorItsIrradiance) {
  expect_floor_irradiance(int(LightShape::Sphere), {0.6f, 0.5f, 0.2f}, 0.4f);
}

// The floor seen straight down through an empty pint's thick base, in even light: a path
// leaves the base's underside onto the floor it stands on (within a hair of it, where a
// search from that point finds nothing), so it sees the floor (albedo 0.5, lit by the sky
// through the non-absorbing glass: half the sky's radiance), not the sky below it (the
// whole radiance: 2x).
TEST(ReferencePathTracer, TheFloorIsSeenThroughAFootStandingOnIt) {
  Params p = furnace_params();
  p.liquid.fill = 0;
  p.env.floor = true;
  p.env.backdrop = int(Backdrop::Checker);
  p.env.floor_a = p.env.floor_b = glm::vec3(0.5f);
  p.env.ground = kEnv;
  p.camera.auto_frame = false;
  p.camera.eye = {0.0f, 0.4f, 0.001f};
  p.camera.target = {0.0f, 0.0f, 0.0f};  // down the empty glass, through its base
  p.camera.vfov = 5;
  ReferenceSettings s;
  s.samples = 400;
  s.threads = 2;
  s.max_surfaces = 1024;
  const RadianceImage img = render_reference(make_frame(p), 2, 2, s);
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& c : img.pixels) mean += c / double(img.pixels.size());
  // (The checker's fade into the ground with distance, a guard against aliasing at the
  // horizon, is not applied under a foot.)
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean[i], 0.5 * kEnv[i], 0.05 * kEnv[i]) << "channel " << i;
}

// A light seen directly shows its radiance; from behind, a softbox is not seen.
TEST(ReferencePathTracer, ALightSeenDirectlyHasItsRadiance) {
  Params p = furnace_params();
  p.env.color = glm::vec3(0.1f);
  p.backlight.power = 3;
  p.backlight.facing = int(LightFacing::Scene);
  p.backlight.width = 2;
  p.backlight.height = 2;
  p.camera.auto_frame = false;
  p.camera.eye = {0.0f, 0.5f, 0.3f};
  p.camera.target = {0.0f, 0.5f, -1.0f};  // above the glass, at the panel behind it
  p.camera.vfov = 5;
  p.backlight.camera_visible = true;
  const FrameState f = make_frame(p);
  ASSERT_EQ(f.lights.lights.size(), 1u);
  const RadianceImage img = render(p, 4, 4);
  for (const glm::dvec3& c : img.pixels) EXPECT_NEAR(c.g, f.lights.lights[0].radiance.g, 1e-9);
  // Kept out of the shot (the default), the camera's rays pass it: the studio behind.
  p.backlight.camera_visible = false;
  for (const glm::dvec3& c : render(p, 4, 4).pixels) EXPECT_NEAR(c.g, 0.1, 1e-6);
  p.backlight.camera_visible = true;
  p.camera.eye = {0.0f, 0.5f, -2.0f};
  p.camera.target = {0.0f, 0.5f, 1.0f};
  p.backlight.direction = {0, 0, -1};
  for (const glm::dvec3& c : render(p, 4, 4).pixels) EXPECT_NEAR(c.g, 0.1, 1e-6);  // its back: the studio
}

TEST(ReferencePathTracer, StripsKeptOutOfTheShotChangeOnlyThePixelsThatSawThemStraight) {
  // The default pint at 16:9, where the strip softboxes stand inside the frame's sides:
  // kept out of the shot, the pixels that saw them straight see the sweep behind; every
  // other pixel, the glass mirroring and bending them, the floor they light, is the same
  // to the bit (the same paths: the camera's rays are the only ones that pass them).
  Params p = test::params_with_glass("pint");
  p.foam.height = 0;  // (quicker; the head is not what this is about)
  p.strips.camera_visible = true;
  ReferenceSettings s;
  s.samples = 2;
  s.threads = 2;
  const int w = 48, h = 27;
  const RadianceImage seen = render_reference(make_frame(p), w, h, s);
  p.strips.camera_visible = false;
  const RadianceImage hidden = render_reference(make_frame(p), w, h, s);
  int changed = 0, changed_inside = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (seen.at(x, y) == hidden.at(x, y)) continue;
      ++changed;
      if (x >= w / 8 && x < w - w / 8) ++changed_inside;
      EXPECT_GT(seen.at(x, y).g, hidden.at(x, y).g) << x << ", " << y;  // a strip is brighter than the paper
    }
  EXPECT_GT(changed, 2 * h / 3);  // both strips, most of the frame's height
  EXPECT_EQ(changed_inside, 0);   // only at the sides
}

// ---- droplets and point clouds (core/droplets, core/pointcloud) among the vessels ----

// The furnace's empty pint seen from 0.3 m, with what a test puts 7 cm in front of it
// (centred on (0, 0.1, 0.07)): paths go from the body into the glass and back.
FrameState furnace_before_the_glass() {
  Params p = furnace_params();
  p.liquid.fill = 0;
  p.camera.auto_frame = false;
  p.camera.eye = {0.0f, 0.1f, 0.3f};
  p.camera.target = {0.0f, 0.1f, 0.0f};
  p.camera.vfov = 12;
  return make_frame(p);
}

// Three droplets of water blended into one, their surface noisy.
DropletsFrame water(glm::vec3 absorption) {
  DropletsFrame d;
  d.params.ior = 1.33f;
  d.params.absorption = absorption;
  d.field.spheres = {{{-0.012, 0.1, 0.07}, 0.008}, {{0.0, 0.103, 0.07}, 0.01}, {{0.013, 0.097, 0.072}, 0.007}};
  d.field.blend = 0.01;
  d.field.noise_amplitude = 0.0008;
  d.field.noise_frequency = 90;
  return d;
}

// A cloud of these points (blob radius `radius`), cold, clear and colourless.
CloudFrame clear_cloud(std::vector<glm::vec3> at, float radius) {
  auto points = std::make_shared<PointCloud>();
  points->position = std::move(at);
  points->default_radius = radius;
  CloudFrame c;
  c.points = points;
  c.version = 1;
  c.ior = 1.5f;
  return c;
}

TEST(ReferenceFurnace, ANonAbsorbingDropletFieldIsInvisible) {
  FrameState f = furnace_before_the_glass();
  f.droplets.push_back(water(glm::vec3(0)));
  EXPECT_LT(worst_error(render(f, 16, 4)), 0.02);
  f.droplets[0].params.absorption = glm::vec3(50);  // the test can fail: the droplets are in view
  EXPECT_GT(worst_error(render(f, 16, 2)), 0.3);
}

TEST(ReferenceFurnace, AClearColdPointCloudIsInvisible) {
  std::vector<glm::vec3> ball;  // points 4 mm apart in a ball of 1.4 cm, blended into one blob
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k)
        if (i * i + j * j + k * k <= 12) ball.push_back(glm::vec3(0.0f, 0.1f, 0.07f) + 0.004f * glm::vec3(i, j, k));
  FrameState f = furnace_before_the_glass();
  f.clouds.push_back(clear_cloud(ball, 0.003f));
  EXPECT_LT(worst_error(render(f, 16, 4)), 0.02);
  f.clouds[0].absorption = glm::vec3(50);  // the test can fail: the blob is in view
  EXPECT_GT(worst_error(render(f, 16, 2)), 0.3);
}

// A sphere of radius 1 cm at (0, 0.1, 0), nothing else, seen head-on from 0.5 m over
// 0.05 degrees (off the axis by at most 0.22 mm: the chord is 2 cm within 0.03 %).
FrameState head_on(glm::vec3 env) {
  Params p = furnace_params();
  p.env.color = env;
  p.camera.auto_frame = false;
  p.camera.eye = {0.0f, 0.1f, 0.5f};
  p.camera.target = {0.0f, 0.1f, 0.0f};
  p.camera.vfov = 0.05f;
  FrameState f = make_frame(p);
  f.vessels.clear();
  return f;
}
constexpr double kChord = 0.02;

// The mean pixel over the environment, and what a sphere of index n whose body transmits
// T = exp(-absorption x chord) along its diameter shows head-on in a uniform environment:
// T, adjusted by the F (2 % for water, 4 % for glass) reflected at each face: F of the
// environment, and what leaves after 0, 1, 2 ... internal reflections (by either face: the
// environment is the same all round), (1 - F)^2 T / (1 - F T).
glm::dvec3 seen_head_on(const FrameState& f) {
  glm::dvec3 mean(0.0);
  const RadianceImage img = render(f, 2, 256);
  for (const glm::dvec3& c : img.pixels) mean += c / (double(img.pixels.size()) * glm::dvec3(kEnv));
  return mean;
}
double through_sphere(double n, double T) {
  const double F = std::pow((n - 1) / (n + 1), 2);
  return F + (1 - F) * (1 - F) * T / (1 - F * T);
}

TEST(ReferencePathTracer, AnAbsorbingDropletDimsWhatIsBehindItByBeerLambert) {
  FrameState f = head_on(kEnv);
  const glm::vec3 absorption{20, 40, 80};  // 1/m: 0.4, 0.8 and 1.6 optical depths across
  DropletsFrame d;
  d.params.ior = 1.33f;
  d.params.absorption = absorption;
  d.field.spheres = {{{0.0, 0.1, 0.0}, 0.01}};
  d.field.noise_amplitude = 0;
  f.droplets.push_back(d);
  const glm::dvec3 seen = seen_head_on(f);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(seen[c], through_sphere(1.33, std::exp(-absorption[c] * kChord)), 0.01) << "channel " << c;
}

TEST(ReferencePathTracer, AnAbsorbingBlobDimsWhatIsBehindItByBeerLambert) {
  FrameState f = head_on(kEnv);
  CloudFrame c = clear_cloud({{0.0f, 0.1f, 0.0f}}, 0.01f);  // a lone point: a sphere of its blob radius
  c.absorption = {20, 40, 80};
  f.clouds.push_back(c);
  const glm::dvec3 seen = seen_head_on(f);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(seen[i], through_sphere(1.5, std::exp(-c.absorption[i] * kChord)), 0.01) << "channel " << i;
}

TEST(ReferencePathTracer, AThickHotBlobGlowsAsABlackbodySeenThroughItsSurface) {
  // In the dark, glass at 1100 C opaque to the visible (its extinction 1000 / m: 20 optical
  // depths across) shows the blackbody's radiance times the surface's transmittance head-on,
  // 1 - F (Kirchhoff: an opaque dielectric's emissivity), at the points' temperature.
  FrameState f = head_on(glm::vec3(0));
  const float kelvin = 1373;  // (exact in the half floats of the points' attributes)
  auto hot = std::make_shared<PointCloud>(*clear_cloud({{0.0f, 0.1f, 0.0f}}, 0.01f).points);
  hot->temperature = {kelvin};
  CloudFrame c = clear_cloud({}, 0);
  c.points = hot;
  c.temperature = 800;  // the cloud's, for points without their own: not this one
  c.glow = 1;
  c.glow_depth = 0.001f;
  f.clouds.push_back(c);
  const RadianceImage img = render(f, 2, 256);  // a path is reflected (into the dark) or sees the glow
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& px : img.pixels) mean += px / double(img.pixels.size());
  const double F = std::pow(0.5 / 2.5, 2);
  const glm::dvec3 expected = (1 - F) * kGlowPerNit * blackbody_linear_rgb(kelvin);
  ASSERT_GT(expected.g, 0.3);  // a bright orange
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean[i], expected[i], 0.02 * expected.r) << "channel " << i;
}

}  // namespace
}  // namespace draught
