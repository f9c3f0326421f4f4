// Transparent pictures (core/output/cutout): what alpha cannot carry of the light through
// a drink (its colour) is lit by the studio behind the objects, and the glass mirrors the
// studio, so a cutout composited over the studio's own background looks as the opaque
// picture does, in both tiers. (Before, the sky's light facing up lit it: the studio's
// dark ceiling, and a lager came out brown; and an empty bowl mirrored nothing: grey.)
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

constexpr int kCutoutW = 64, kCutoutH = 96;

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
      const Image o = g.renderer->render(opaque, kCutoutW, kCutoutH), t = g.renderer->render(cut, kCutoutW, kCutoutH);
      const glm::dvec3 behind = cutout_light(cut) * double(cut.params.render.exposure);
      // Over the studio's light behind, the cutout's pixels of `kind` against the opaque
      // picture's: the mean of each channel, in sRGB codes.
      auto compare = [&](const char* kind, auto wanted, double tolerance, int min_pixels) -> glm::dvec3 {
        glm::dvec3 want(0.0), got(0.0), white(0.0);
        int n = 0;
        for (int y = 0; y < kCutoutH; ++y)
          for (int x = kCutoutW / 3; x < 2 * kCutoutW / 3; ++x) {
            const std::uint8_t *pt = t.px(x, y), *po = o.px(x, y);
            const double a = pt[3] / 255.0;
            if (!wanted(a, po)) continue;
            for (int k = 0; k < 3; ++k) {
              got[k] += lin(pt[k]) + (1.0 - a) * std::min(behind[k], 1.0);
              want[k] += lin(po[k]);
              white[k] += lin(pt[k]) + (1.0 - a);
            }
            ++n;
          }
        EXPECT_GE(n, min_pixels) << d.preset << " " << tier << " " << kind;
        if (n < min_pixels) return glm::dvec3(1.0);
        got /= double(n);
        want /= double(n);
        white /= double(n);
        auto code = [](double c) { return 255 * linear_to_srgb(c); };
        std::printf("%-6s %-10s %-5s %4d px: opaque %5.1f %5.1f %5.1f  cutout over the studio %5.1f %5.1f %5.1f, over white %5.1f %5.1f %5.1f\n",
                    tier, d.preset, kind, n, code(want.r), code(want.g), code(want.b), code(got.r), code(got.g),
                    code(got.b), code(white.r), code(white.g), code(white.b));
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(code(got[k]), code(want[k]), tolerance) << d.preset << " " << tier << " " << kind << " channel " << k;
        return white;
      };
      const double tolerance = std::string(tier) == "full" ? 14.0 : 24.0;
      // The drink: the middle third across, where the cutout is nearly covered (the liquid
      // lets little through unchanged; the clear glass and the air around it much), less
      // the head (white in both, near the cutout's full coverage).
      compare("drink", [](double a, const std::uint8_t* po) { return a >= 0.8 && std::min({po[0], po[1], po[2]}) <= 180; },
              tolerance, 150);
      // The clear glass (the walls, a bowl above the wine): over white nearly white, its
      // reflections of the studio making up for the light they take from what is behind.
      if (std::string(d.glass) == "wine") {
        const glm::dvec3 white = compare("glass", [](double a, const std::uint8_t*) { return a > 0.03 && a < 0.5; }, tolerance, 40);
        EXPECT_GT(std::min({white.r, white.g, white.b}), 0.86) << "the empty glass is grey over white (its reflections left out)";
      }
    }
  }
}

}  // namespace
}  // namespace draught::test
