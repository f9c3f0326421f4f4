// No slider makes a frame black or NaN: every numeric parameter at its minimum and at
// its maximum still renders a picture with content (the rest at the defaults).
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace draught::test {
namespace {

struct Stats {
  double mean = 0;      // mean of RGB over the image, 0..255
  double black = 0;     // fraction of pixels that are exactly black
};

Stats stats(const Image& img) {
  Stats s;
  long blacks = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    s.mean += (img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2]) / 3.0;
    blacks += img.rgba[i] == 0 && img.rgba[i + 1] == 0 && img.rgba[i + 2] == 0;
  }
  const double n = double(img.rgba.size() / 4);
  s.mean /= n;
  s.black = double(blacks) / n;
  return s;
}

TEST(Extremes, EveryNumericParameterAtItsLimitsStillRenders) {
  Gpu& g = gpu_instance();
  int cases = 0;
  for (const ParamDesc& d : param_table()) {
    if (d.type != ParamType::Float && d.type != ParamType::Int) continue;
    for (float v : {d.min, d.max}) {
      // The floor's light from 20,000 photons (a still's 500,000 were half the test's time:
      // every change to the glass or the drink traces it again), but for its own limits.
      Params p = resolve_scene({"lager", "pint", {"render.supersample=1", "render.floor_photons=20000"}, {}});
      set_param(p, d, d.type == ParamType::Int ? ParamValue(int(v)) : ParamValue(v));
      Image img = g.renderer->render(make_frame(p), 32, 32);
      Stats s = stats(img);
      EXPECT_GT(s.mean, 3.0) << d.path << " = " << v << " renders a black frame";
      EXPECT_LT(s.black, 0.02) << d.path << " = " << v << " leaves black (NaN) pixels";
      ++cases;
    }
  }
  std::printf("%d extreme settings rendered\n", cases);
  EXPECT_GT(cases, 30);
}

// Total internal reflection must not leave black holes: a very dense glass, seen at
// grazing angles, with few path events allowed.
TEST(Extremes, DenseGlassHasNoBlackHoles) {
  Gpu& g = gpu_instance();
  Params p = resolve_scene({"lager", "pint", {"glass.ior=2.5", "render.max_events=2", "render.supersample=1"}, {}});
  Stats s = stats(g.renderer->render(make_frame(p), 48, 48));
  EXPECT_LT(s.black, 0.001);
}

}  // namespace
}  // namespace draught::test
