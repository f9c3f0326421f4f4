// A scene framed in part of the picture (the desktop viewer's free area beside its panel):
// inside that part the picture is exactly the camera's own picture of that size, the rest
// extends it, and everything that projects (picking, bubble sprites) follows the same lens.
#include "core/bubbles/bubble_view.hpp"
#include "core/params/preset.hpp"
#include "core/scene/camera.hpp"
#include "core/scene/frame.hpp"
#include "core/sim/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace draught {
namespace {

void expect_same_ray(const Ray& a, const Ray& b, const std::string& where) {
  EXPECT_NEAR(glm::length(a.o - b.o), 0.0, 1e-6) << where;
  EXPECT_NEAR(glm::length(a.d - b.d), 0.0, 1e-6) << where;
}

TEST(CameraView, TheWholePictureIsTheUsualCamera) {
  CameraParams c;
  c.eye = {0.1f, 0.2f, 0.4f};
  c.target = {0, 0.07f, 0};
  const CameraBasis plain = camera_basis(c, 160, 90), whole = camera_basis(c, 160, 90, PictureRect{});
  EXPECT_EQ(whole.shift, glm::vec2(0));
  EXPECT_EQ(whole.tan_half_vfov, plain.tan_half_vfov);
  for (double px : {0.5, 80.0, 159.5}) {
    const Ray a = camera_ray(plain, px, 30.5, 160, 90), b = camera_ray(whole, px, 30.5, 160, 90);
    EXPECT_EQ(a.d, b.d) << px;  // bit for bit: the CLI and the web page do not move
  }
}

TEST(CameraView, InsideTheViewThePictureIsTheCamerasOwn) {
  CameraParams c;
  c.eye = {0.1f, 0.2f, 0.4f};
  c.target = {0, 0.07f, 0};
  c.vfov = 30;
  // A 400 x 200 picture; the view is its right 60 % below the top 30 %: 240 x 140 pixels.
  const int w = 400, h = 200;
  const PictureRect view{0.4, 0.3, 0.6, 0.7};
  const int vw = 240, vh = 140;
  const CameraBasis full = camera_basis(c, w, h, view), own = camera_basis(c, vw, vh);
  for (double u : {0.0, 0.25, 0.5, 1.0})
    for (double v : {0.0, 0.5, 1.0}) {
      const Ray a = camera_ray(full, 160 + u * vw, 60 + v * vh, w, h);
      const Ray b = camera_ray(own, u * vw, v * vh, vw, vh);
      expect_same_ray(a, b, "view point " + std::to_string(u) + ", " + std::to_string(v));
    }
  // The view's middle looks straight at the target; the picture's middle does not.
  const Ray mid = camera_ray(full, 160 + 0.5 * vw, 60 + 0.5 * vh, w, h);
  EXPECT_NEAR(glm::length(mid.d - glm::dvec3(glm::normalize(c.target - c.eye))), 0.0, 1e-6);
  EXPECT_GT(glm::length(camera_ray(full, 200, 100, w, h).d - mid.d), 0.1);
}

// The lager framed in the right half of a wide picture (a panel over the left half): every
// pixel where the reference intersector sees the glass lies in that half, the glass fills
// it about as it fills a picture of that size, and picking finds it there.
TEST(CameraView, AFramedGlassLiesInItsView) {
  FrameState f = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  const int w = 320, h = 160;
  f.view = PictureRect{0.5, 0, 0.5, 1};
  const SceneGeometry geo = scene_geometry(f);
  const CameraBasis cam = camera_basis(f, w, h);
  int x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (int y = 0; y < h; y += 2)
    for (int x = 0; x < w; x += 2)
      if (first_hit(geo, camera_ray(cam, x + 0.5, y + 0.5, w, h)).object == 0) {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
  ASSERT_GE(x1, 0) << "the glass is not in the picture";
  EXPECT_GE(x0, w / 2) << "the glass reaches into the covered half";
  EXPECT_GT(y1 - y0, h / 2) << "the glass is framed to its view's height";
  EXPECT_EQ(pick_object(f, 0.75 * w, 0.6 * h, w, h), 0);
  EXPECT_EQ(pick_object(f, 0.25 * w, 0.6 * h, w, h), -1);
  // Framed for the view, not for the whole picture: the same camera as a 160 x 160 picture.
  const CameraParams own = f.camera_for(160, 160);
  EXPECT_EQ(cam.eye, own.eye);
}

// Bubble sprites project through the same shifted lens: the sprites of a picture whose
// right half is the view are those of a picture of that half's size, moved right.
TEST(CameraView, BubbleSpritesFollowTheView) {
  const Params p = resolve_scene({"lager", "pint", {"foam.height=0"}, {}});
  Simulation sim(p);
  sim.settle_bubbles(3.0);
  FrameState f = assemble_frame(p, {sim.frame()});
  const std::vector<BubbleSprite> own = bubble_sprites(f, 100, 100);
  f.view = PictureRect{0.5, 0, 0.5, 1};
  const std::vector<BubbleSprite> shifted = bubble_sprites(f, 200, 100);
  ASSERT_GT(own.size(), 20u);
  ASSERT_EQ(own.size(), shifted.size());
  for (size_t i = 0; i < own.size(); ++i) {
    EXPECT_NEAR(shifted[i].centre.x, own[i].centre.x + 100, 0.02) << i;
    EXPECT_NEAR(shifted[i].centre.y, own[i].centre.y, 0.02) << i;
    EXPECT_NEAR(shifted[i].radius, own[i].radius, 0.01) << i;
  }
}

}  // namespace
}  // namespace draught
