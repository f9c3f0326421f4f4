// Transparent pictures (core/output/cutout): what alpha cannot carry of the light through
// a drink (its colour) is lit by the studio behind the objects, so a cutout composited
// over the studio's own background looks as the opaque picture does, in both tiers. (Before,
// the sky's light facing up lit it: the studio's dark ceiling, and a lager came out brown.)
#include "core/output/cutout.hpp"
#include "core/output/tonemap.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace draught::test {
namespace {

constexpr int kW = 64, kH = 96;

struct Drink {
  const char* preset;
  const char* glass;
};

double lin(std::uint8_t code) { return srgb_to_linear(code / 255.0); }

TEST(Cutout, OverTheStudioTheDrinkLooksAsInTheOpaquePicture) {
  Gpu& g = gpu_instance();
  const Drink drinks[] = {{"lager", "pint"}, {"hefeweizen", "weizen"}, {"amber-ale", "tulip"}, {"rose-wine", "wine"}};
  for (const char* tier : {"full", "matcap"}) {
    for (const Drink& d : drinks) {
      std::vector<std::string> sets = {"bubbles.max_bubbles=0", "render.supersample=1", "render.tonemap=none",
                                       std::string("render.tier=") + tier};
      const FrameState opaque = scene_frame({d.preset, d.glass, sets, {}});
      sets.push_back("render.transparent=true");
      const FrameState cut = scene_frame({d.preset, d.glass, sets, {}});
      const Image o = g.renderer->render(opaque, kW, kH), t = g.renderer->render(cut, kW, kH);
      const glm::dvec3 behind = cutout_light(cut) * double(cut.params.render.exposure);
      // The drink: the middle third across, where the cutout is nearly covered (the liquid
      // lets little through unchanged; the clear glass and the air around it much), less
      // the head (white in both, near the cutout's full coverage).
      glm::dvec3 want(0.0), got(0.0);
      int n = 0;
      for (int y = 0; y < kH; ++y)
        for (int x = kW / 3; x < 2 * kW / 3; ++x) {
          const std::uint8_t* pt = t.px(x, y);
          const double a = pt[3] / 255.0;
          const std::uint8_t* po = o.px(x, y);
          if (a < 0.8 || std::min({po[0], po[1], po[2]}) > 180) continue;
          for (int k = 0; k < 3; ++k) {
            got[k] += lin(pt[k]) + (1.0 - a) * std::min(behind[k], 1.0);
            want[k] += lin(po[k]);
          }
          ++n;
        }
      ASSERT_GT(n, 150) << d.preset << " " << tier;
      got /= double(n);
      want /= double(n);
      std::printf("%-6s %-10s %4d px: opaque %5.1f %5.1f %5.1f  cutout over the studio %5.1f %5.1f %5.1f (sRGB codes)\n",
                  tier, d.preset, n, 255 * linear_to_srgb(want.r), 255 * linear_to_srgb(want.g),
                  255 * linear_to_srgb(want.b), 255 * linear_to_srgb(got.r), 255 * linear_to_srgb(got.g),
                  255 * linear_to_srgb(got.b));
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(255 * linear_to_srgb(got[k]), 255 * linear_to_srgb(want[k]), 24.0) << d.preset << " " << tier << " channel " << k;
    }
  }
}

}  // namespace
}  // namespace draught::test
