// A hazy drink's diffusion field on the GPU against core: haze_field in
// shaders/lib/liquid/body.glsl (I0 from Abramowitz and Stegun's polynomials, in float)
// against core/liquid/haze.cpp's (the standard library's I0, in double), through the
// HazeField debug view, over radii 1 to 8 cm and the whole cross-section. The field's
// use is measured against the reference in tests/gpu/test_reference_comparison.cpp
// (the hefeweizen and the amber tulip) and in even light in tests/gpu/test_furnace.cpp.
#include "core/liquid/haze.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace draught::test {
namespace {

void expect_field_twins_agree(const FrameState& f) {
  const VesselFrame& v = f.vessels[0];
  const HazeDiffusion d = haze_diffusion(v.params.liquid.haze, glm::dvec3(v.params.liquid.haze_color),
                                         glm::dvec3(v.liquid_absorption.effective()), v.params.glass.ior);
  constexpr int kW = 33, kH = 8;
  const gpu::DebugImage img = gpu_instance().renderer->render_debug(f, kW, kH, gpu::DebugView::HazeField);
  double worst = 0;
  for (int row = 0; row < kH; ++row)
    for (int x = 0; x < kW; ++x) {
      const float* px = img.px(x, kH - 1 - row);  // (gl_FragCoord.y counts from the bottom)
      const double R = 0.01 * (row + 1);
      ASSERT_NEAR(px[3], R, 1e-7);
      const glm::dvec3 want = haze_field(d, double(x) / (kW - 1) * R, R);
      for (int c = 0; c < 3; ++c) {
        const double err = std::fabs(px[c] - want[c]) / std::max(want[c], 1e-6);
        worst = std::max(worst, err);
        EXPECT_LT(err, 2e-4) << "x " << x << " R " << R << " channel " << c << ": " << px[c] << " against " << want[c];
      }
    }
  std::printf("haze_field twins: worst relative difference %.2e\n", worst);
}

TEST(HazeTwins, FieldAgreesWithCore) {
  const FrameState f = scene_frame({"hefeweizen", "weizen", {"bubbles.carbonation=0"}});
  ASSERT_GT(f.vessels[0].params.liquid.haze, 0.0f);
  expect_field_twins_agree(f);
}

// A thin haze in a deep colour (the amber), where the field falls off steeply: the
// polynomials' other branch (kappa r past 3.75) does the work.
TEST(HazeTwins, FieldAgreesWithCoreInADeepColour) {
  expect_field_twins_agree(scene_frame({"amber-ale", "tulip", {"bubbles.carbonation=0"}}));
}

// The haze's field is taken where the scattering happens in the glass's own frame: a
// hazy drink in even light (no lights, no floor) looks the same wherever its glass stands,
// the camera moved with it. (A field taken at world positions made the flight's
// hefeweizen, off the origin, as bright as its wall all through.)
TEST(HazePicture, TheSameWhereverTheGlassStands) {
  const std::vector<std::string> sets = {"env.mode=constant", "env.color=0.6,0.6,0.6", "env.floor=false",
                                         "light.power=0",     "strips.power=0",        "backlight.power=0",
                                         "bubbles.carbonation=0", "camera.auto_frame=false"};
  const FrameState here = scene_frame({"hefeweizen", "weizen", sets, {"eye=0,0.12,0.45", "target=0,0.1,0", "vfov=32"}});
  FrameState there = scene_frame({"hefeweizen", "weizen", sets, {"eye=0.25,0.12,0.3", "target=0.25,0.1,-0.15", "vfov=32"}});
  there.vessels[0].pose.position += glm::dvec3(0.25, 0.0, -0.15);
  Gpu& g = gpu_instance();
  const Image a = g.renderer->render(here, 48, 64), b = g.renderer->render(there, 48, 64);
  int worst = 0, body = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.px(x, y)[c]) - int(b.px(x, y)[c])));
      body += a.px(x, y)[2] + 40 < a.px(x, y)[0];  // (the drink: red well over blue)
    }
  std::printf("a hazy glass moved: worst difference %d levels (%d drink pixels)\n", worst, body);
  EXPECT_GT(body, 300);
  EXPECT_LE(worst, 3);
}

}  // namespace
}  // namespace draught::test
