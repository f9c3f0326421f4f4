// A hot cloud's glow on the floor (core/pointcloud/glow_light, lib/environment/floor.glsl):
// the gob held low over the marver (presets/scenes/gob-marver.json) lights the floor under
// it as the reference path tracer finds it, where paths from the floor meet the glowing
// body; a gob without glow leaves the floor as the rig alone lights it.
#include "color_difference.hpp"
#include "gpu_fixture.hpp"

#include "stored_reference.hpp"

#include "core/pointcloud/glow_light.hpp"
#include "core/reference/path_tracer.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace draught::test {
namespace {

double pixel_linear(const Image& img, int x, int y) {
  const std::uint8_t* p = img.px(x, y);
  return (srgb8_to_linear(p[0]) + srgb8_to_linear(p[1]) + srgb8_to_linear(p[2])) / 3.0;
}

TEST(CloudGlow, TheFloorUnderAHotGobIsLitAsTheReferenceFindsIt) {
  constexpr int kW = 64, kH = 48;
  const FrameState hot = make_frame(resolve_scene_objects({"gob-marver"}));
  ASSERT_FALSE(hot.clouds.empty());
  const GlowSphere glow = cloud_glow_sphere(hot.clouds[0]);
  ASSERT_FALSE(glow.empty());
  EXPECT_NEAR(glow.centre.y, 0.06, 0.02);  // the gob's middle, where the preset holds it
  FrameState dark = hot;
  for (CloudFrame& c : dark.clouds) c.glow = 0;
  EXPECT_TRUE(cloud_glow_sphere(dark.clouds[0]).empty());

  gpu::Renderer& r = *gpu_instance().renderer;
  const Image lit = r.render(hot, kW, kH), unlit = r.render(dark, kW, kH);
  ReferenceSettings settings;
  settings.samples = 256;
  // Stored with the reference comparisons' (stored_reference.hpp: only its first paths are
  // traced and checked here; scripts/bless-references.sh gob_marver_glow traces it afresh).
  StoredReference stored = stored_reference(std::filesystem::path(DRAUGHT_GOLDEN_DIR) / "reference", "gob_marver_glow",
                                            hot, kW, kH, settings, g_bless);
  ASSERT_TRUE(stored.error.empty()) << stored.error;
  std::printf("gob_marver_glow: reference %dx%d at %d paths, %s\n", kW, kH, settings.samples, stored.how.c_str());
  const Image reference = display_image(stored.radiance, hot.params.render);

  // The pool: where the glow changes the picture (the gob itself is the same either way).
  double picture = 0, traced = 0, without = 0;
  int pixels = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double a = pixel_linear(lit, x, y), b = pixel_linear(unlit, x, y);
      if (a - b < 0.02) continue;
      picture += a;
      traced += pixel_linear(reference, x, y);
      without += b;
      ++pixels;
    }
  std::printf("glow pool: %d px, picture %.4f, reference %.4f (ratio %.3f), without the glow %.4f\n", pixels,
              picture / pixels, traced / pixels, picture / traced, without / pixels);
  ASSERT_GE(pixels, 200);  // a pool, not a few pixels
  EXPECT_GT(picture, 4.0 * without);
  // Today 1.04 (64 x 48, 256 paths): the sphere's light unshadowed (the blowpipe's shadow
  // on the floor is left out), against the reference's noise over several hundred pixels.
  EXPECT_NEAR(picture / traced, 1.0, 0.2);
}

}  // namespace
}  // namespace draught::test
