// Auto-framing of posed glasses: a glass tilted as far as a timeline may tilt it (135
// degrees, any side) stays inside the picture at any aspect; small tilts do not move the
// camera (no swimming), and the camera backs away continuously as the tilt grows.
#include "core/scene/frame.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace draught {
namespace {

// The frame of one shipped glass, filled, posed as a timeline tilt would pose it:
// tilted `tilt` towards `toward`, tipped on its foot.
FrameState tilted(const std::string& glass, double tilt, double toward, const std::vector<std::string>& camera = {}) {
  static std::map<std::string, FrameState> upright;  // making a frame settles bubbles: once per glass
  std::string key = glass;
  for (auto& c : camera) key += " " + c;
  if (!upright.count(key)) {
    upright[key] = make_frame(camera.empty() ? test::params_with_glass(glass) : resolve_scene({"lager", glass, {}, camera}));
    upright[key].params.camera.auto_frame = true;  // --camera fixes the camera; here it gives the direction only
  }
  FrameState f = upright[key];
  VesselFrame& v = f.vessels.at(0);
  v.pose = tipped_on_floor(tilt_orientation(tilt, toward), v.vessel.r_outer.front());
  // make_frame framed the upright glass; frame again from the pose, as assemble_frame does.
  f.camera = frame_camera(f.params.camera, f.vessels);
  return f;
}

// The glass's rim and foot circles and its widest circle, moved by its pose, as pixels
// of a width x height picture (x right, y down): the points above the floor (a glass
// tipped past lying goes through it, and the floor hides that part).
std::vector<glm::dvec2> glass_pixels(const FrameState& f, int width, int height) {
  const VesselFrame& v = f.vessels.at(0);
  const Vessel& g = v.vessel;
  size_t widest = 0;
  for (size_t k = 0; k < g.r_outer.size(); ++k)
    if (g.r_outer[k] > g.r_outer[widest]) widest = k;
  const struct { double y, r; } circles[] = {
      {0, g.r_outer.front()},
      {g.dy * double(widest), g.r_outer[widest]},
      {g.height, g.rim_major + g.rim_minor},
      {g.height + g.rim_minor, g.rim_major},
  };
  const CameraBasis cam = camera_basis(f, width, height);
  std::vector<glm::dvec2> out;
  for (auto [y, r] : circles)
    for (int j = 0; j < 72; ++j) {
      const double a = 2 * std::numbers::pi * j / 72;
      const glm::dvec3 p = v.pose.orientation * glm::dvec3(r * std::cos(a), y, r * std::sin(a)) + v.pose.position;
      if (p.y < 0) continue;
      const glm::dvec3 d = p - glm::dvec3(cam.eye);
      const double z = glm::dot(d, glm::dvec3(cam.forward));
      if (z <= 0) {
        out.push_back(glm::dvec2(-1e9));  // behind the camera: surely out of the picture
        continue;
      }
      const double x = glm::dot(d, glm::dvec3(cam.right)) / (z * cam.tan_half_vfov * cam.aspect);
      const double yy = glm::dot(d, glm::dvec3(cam.up)) / (z * cam.tan_half_vfov);
      out.push_back({(x + 1) * 0.5 * width, (1 - yy) * 0.5 * height});
    }
  return out;
}

double camera_distance(const CameraParams& c) { return glm::length(glm::dvec3(c.eye - c.target)); }

TEST(Framing, AGlassTiltedToTheMaximumStaysInThePicture) {
  for (const char* glass : {"pint", "nonic", "tulip", "wine", "weizen", "flute", "pilsner"})
    for (double toward : {0.0, 45.0, 90.0, 180.0, 270.0})
      for (auto [w, h] : {std::pair{160, 160}, {320, 180}, {120, 200}}) {
        const FrameState f = tilted(glass, 135 * kDegree, toward * kDegree);
        for (const glm::dvec2& px : glass_pixels(f, w, h)) {
          ASSERT_TRUE(px.x >= 0 && px.x <= w && px.y >= 0 && px.y <= h)
              << glass << " tilted towards " << toward << " deg, " << w << "x" << h << ": a point at pixel (" << px.x
              << ", " << px.y << ") is outside the picture";
        }
      }
}

TEST(Framing, ATiltedGlassSeenFromAboveStaysInThePicture) {
  // Auto-framed from above and in front (the direction of pint_lager_above's camera).
  for (const char* glass : {"pint", "wine"})
    for (double toward : {0.0, 90.0, 180.0, 270.0}) {
      const FrameState f = tilted(glass, 135 * kDegree, toward * kDegree, {"eye=0.08,0.32,0.2", "target=0,0.07,0"});
      for (const glm::dvec2& px : glass_pixels(f, 160, 160))
        ASSERT_TRUE(px.x >= 0 && px.x <= 160 && px.y >= 0 && px.y <= 160)
            << glass << " towards " << toward << ": a point at pixel (" << px.x << ", " << px.y << ")";
    }
}

TEST(Framing, UprightAndSlightlyTiltedGlassesKeepTheStandingCamera) {
  // The camera frames the glass as it stands; a tilt that keeps it well inside the
  // picture does not move the camera (an animation would swim otherwise).
  for (const char* glass : {"pint", "wine"}) {
    const FrameState upright = make_frame(test::params_with_glass(glass));
    const FrameState slight = tilted(glass, 5 * kDegree, 0);
    EXPECT_EQ(upright.camera.eye, slight.camera.eye) << glass;
    EXPECT_EQ(upright.camera.target, slight.camera.target) << glass;
    // The upright frame is framed from its pose too (assemble_frame), with the same result.
    EXPECT_EQ(upright.camera.eye, frame_camera(upright.params.camera, upright.vessels).eye) << glass;
  }
}

TEST(Framing, TheCameraBacksAwayContinuouslyAsTheTiltGrows) {
  const CameraParams upright = make_frame(test::params_with_glass("pint")).camera;
  double last = camera_distance(upright), lying = 0;
  for (int deg = 0; deg <= 135; ++deg) {
    const CameraParams c = tilted("pint", deg * kDegree, 0).camera;
    const double d = camera_distance(c);
    // Past lying on its side the glass comes down again, and so may the camera.
    EXPECT_GE(d, camera_distance(upright) - 1e-9) << deg << " deg: closer than for the upright glass";
    EXPECT_LT(std::abs(d - last), 0.05 * last) << deg << " deg: the camera jumped";
    // It only backs away: the same target and line of sight.
    EXPECT_EQ(c.target, upright.target) << deg;
    EXPECT_NEAR(glm::length(glm::normalize(glm::dvec3(c.eye - c.target)) -
                            glm::normalize(glm::dvec3(upright.eye - upright.target))),
                0, 1e-6)
        << deg;
    last = d;
    if (deg == 90) lying = d;
  }
  EXPECT_GT(lying, 1.2 * camera_distance(upright)) << "a pint lying on its side needs a wider picture";
}

}  // namespace
}  // namespace draught

namespace draught {
namespace {

TEST(Framing, TheStudioIsPlacedAroundTheMiddleOfTheGlassesAsTheyStand) {
  Scene s = single_glass_scene(default_params());
  s.objects.push_back(s.objects[0]);
  s.objects[0].placement.position = {-0.1f, 0, 0.02f};
  s.objects[1].placement.position = {0.3f, 0, -0.04f};
  const FrameState f = make_frame(s);
  const glm::dvec3 aim = scene_aim(f.vessels);
  EXPECT_NEAR(aim.x, 0.1, 1e-6);
  EXPECT_NEAR(aim.z, -0.01, 1e-6);
  EXPECT_NEAR(aim.y, 0.5 * f.vessels[0].vessel.height, 1e-9);
  ASSERT_EQ(f.lights.lights.size(), 4u);
  EXPECT_EQ(f.lights.aim, aim);
  EXPECT_NEAR(glm::distance(f.lights.lights[0].center, aim), f.params.light.distance, 1e-5);
  EXPECT_EQ(surroundings_centre(f), aim);  // the MatCap's bake looks from there too
}

TEST(Framing, ASceneWithoutGlassesIsSeenFromTheMiddleOfItsDropletsAndClouds) {
  FrameState f;
  EXPECT_EQ(surroundings_centre(f), glm::dvec3(0.0));
  DropletsFrame d;
  d.position = {-0.02f, 0.1f, 0.1f};
  f.droplets.push_back(d);
  EXPECT_EQ(surroundings_centre(f), glm::dvec3(d.position));
  CloudFrame c;
  c.placement = {0.1f, 0.2f, 0.0f};
  f.clouds.push_back(c);
  const glm::dvec3 mid = surroundings_centre(f);
  EXPECT_NEAR(mid.x, 0.04, 1e-7);
  EXPECT_NEAR(mid.y, 0.15, 1e-7);
  EXPECT_NEAR(mid.z, 0.05, 1e-7);
}

}  // namespace
}  // namespace draught
