// The depth range a depth picture spreads its greys over: every surface of the scene's
// glasses that the camera sees lies inside it, and it is no wider than the glasses.
#include "core/params/preset.hpp"
#include "core/scene/frame.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace draught {
namespace {

// The nearest and farthest first hits on any glass (not the floor) over the picture.
DepthRange seen(const FrameState& f, int w, int h) {
  const SceneGeometry geo = scene_geometry(f);
  const CameraBasis cam = camera_basis(f, w, h);
  DepthRange r{1e30, 0};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Hit hit = first_hit(geo, camera_ray(cam, x + 0.5, y + 0.5, w, h));
      if (hit.object < 0) continue;
      r.near = std::min(r.near, hit.t);
      r.far = std::max(r.far, hit.t);
    }
  return r;
}

void expect_holds(const FrameState& f, int w, int h, const char* what) {
  const DepthRange range = depth_range(f, w, h), hits = seen(f, w, h);
  ASSERT_GT(hits.far, 0) << what << ": no glass in the picture";
  EXPECT_LE(range.near, hits.near + 1e-9) << what;
  EXPECT_GE(range.far, hits.far - 1e-9) << what;
  // Tight: the range is the glasses' depth, not the floor's (which runs to the horizon).
  EXPECT_GT(range.near, 0.5 * hits.near) << what;
  EXPECT_LT(range.far - range.near, 3 * (hits.far - hits.near)) << what;
}

TEST(DepthRange, HoldsWhatTheCameraSeesOfTheGlass) {
  expect_holds(make_frame(resolve_scene({"lager", "pint", {}, {}})), 64, 64, "pint");
  expect_holds(make_frame(resolve_scene({"red-wine", "wine", {}, {"eye=0.05,0.4,0.25", "target=0,0.14,0"}})), 64, 64,
               "wine glass from above");
}

TEST(DepthRange, FollowsATippedGlass) {
  FrameState f = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  // Tipped 40 degrees towards the camera, about its foot's edge.
  f.vessels[0].pose.orientation = glm::angleAxis(glm::radians(40.0), glm::dvec3(1, 0, 0));
  expect_holds(f, 64, 64, "tipped pint");
}

TEST(DepthRange, NoGlassNoRange) {
  FrameState f = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  f.vessels.clear();
  const DepthRange r = depth_range(f, 64, 64);
  EXPECT_EQ(r.near, 0);
  EXPECT_EQ(r.far, 0);
}

}  // namespace
}  // namespace draught
