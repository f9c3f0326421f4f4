// Auto-framing on the GPU: a glass a timeline tips to the maximum (135 degrees) is drawn
// whole, inside the picture: no pixel on the picture's border sees it first.
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <string>

namespace draught::test {
namespace {

TEST(Framing, AGlassTippedToTheMaximumIsDrawnInsideThePicture) {
  Gpu& g = gpu_instance();
  // Lying on its side, and tipped to the maximum (its bowl then goes through the floor,
  // which hides it: what is above the floor is framed).
  for (auto [angle, toward] : {std::pair{"100", "0"}, {"135", "0"}, {"135", "90"}, {"135", "200"}}) {
    const Timeline tl = parse_timeline(std::string(R"({"draught_timeline": 1, "name": "tip", "actions": [
        {"at": 0, "action": "tilt", "angle": )") + angle + R"(, "toward": )" + toward + R"(, "duration": 1}]})",
                                       "tip.json");
    const FrameState f = draught::timeline_frame(tl, single_glass_scene(resolve_scene({"red-wine", "wine", {}, {}})), 1.5);
    for (auto [w, h] : {std::pair{96, 96}, {160, 90}}) {
      const gpu::DebugImage first = g.renderer->render_debug(f, w, h, gpu::DebugView::Depth);
      int glass = 0, on_border = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          if (first.px(x, y)[2] < 0) continue;  // floor or sky
          ++glass;
          on_border += x == 0 || y == 0 || x == w - 1 || y == h - 1;
        }
      EXPECT_GT(glass, 40) << angle << " deg towards " << toward << ", " << w << "x" << h << ": the glass is hardly seen";
      EXPECT_EQ(on_border, 0) << angle << " deg towards " << toward << ", " << w << "x" << h << ": the tipped glass touches the "
                              << "picture's edge in " << on_border << " pixels";
    }
  }
}

}  // namespace
}  // namespace draught::test
