// The reference path tracer: furnace tests (in a uniform environment with no floor and
// no key light, what only refracts, reflects or scatters without loss is invisible),
// determinism, and that what absorbs or is lit shows.
#include "core/reference/path_tracer.hpp"

#include "core/environment/studio.hpp"
#include "core/foam/head_volume.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace draught {
namespace {

constexpr glm::vec3 kEnv{0.5f, 0.4f, 0.3f};

// The default pint, lit only by a uniform environment, with nothing that absorbs.
Params furnace_params() {
  Params p = test::params_with_glass("pint");
  p.env.mode = int(EnvMode::Constant);
  p.env.color = kEnv;
  p.env.floor = false;
  p.light.intensity = 0;
  p.glass.absorption = glm::vec3(0);
  p.liquid.srm = 0;
  p.liquid.absorption = glm::vec3(0);
  p.liquid.haze = 0;
  p.foam.height = 0;
  return p;
}

RadianceImage render(const Params& p, int size, int spp) {
  ReferenceSettings s;
  s.samples = spp;
  s.threads = 2;
  s.max_surfaces = 1024;  // a path may be piped along a wall by total internal reflection for hundreds of bounces (one of 1600 here takes 300); the furnace counts every one
  return render_reference(make_frame(p), size, size, s);
}

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

TEST(ReferencePathTracer, TheKeyLightGivesTheFloorItsIrradiance) {
  // An empty scene but the floor, the key light straight above: the floor's radiance is
  // albedo / pi x (the light's irradiance + the sky's), here with a black sky.
  Params p = test::params_with_glass("pint");
  p.env.mode = int(EnvMode::Constant);
  p.env.color = glm::vec3(0);
  p.env.floor_a = p.env.floor_b = glm::vec3(0.5f);
  p.env.ground = glm::vec3(0);
  p.light.direction = {0, 1, 0};
  p.light.intensity = 2;
  p.light.color = glm::vec3(1);
  p.camera.auto_frame = false;
  p.camera.eye = {0.5f, 0.3f, 0.5f};
  p.camera.target = {0.5f, 0.0f, 0.45f};  // looking down at the floor beside the glass
  p.camera.vfov = 5;
  const FrameState f = make_frame(p);
  ReferenceSettings s;
  s.samples = 1000;
  s.threads = 2;
  const RadianceImage img = render_reference(f, 4, 4, s);
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& c : img.pixels) mean += c / double(img.pixels.size());
  // The floor fades with distance from the eye (as the picture's): ~0.3 m away.
  const double expected = 0.5 / 3.141592653589793 * 2 * Studio::floor_visibility(std::sqrt(0.09 + 0.0025));
  EXPECT_NEAR(mean.g, expected, 0.02 * expected);
}

}  // namespace
}  // namespace draught
