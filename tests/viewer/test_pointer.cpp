// The mouse as the droplets' pointer: the mouse at the picture of a point of the trail's
// plane gives that point back (the lens shifted beside the panel, the plane turned), and
// the trail then gathers there; the panel, a glass being dragged, a timeline or a
// screenshot, a position that is no number and a scene without droplets leave the pointer
// alone.
#include "pointer.hpp"

#include "editor.hpp"

#include "core/droplets/trail.hpp"
#include "core/sim/scene_simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught::viewer {
namespace {

constexpr int kWindowW = 1280, kWindowH = 800;

// The pixel (x, y from the top-left, pixel centres at +0.5) where the camera of `b` sees the
// world point p: camera_ray (core/scene/camera.cpp) solved backwards.
glm::dvec2 project(const CameraBasis& b, glm::dvec3 p, int width, int height) {
  const glm::dvec3 d = p - glm::dvec3(b.eye);
  const double z = glm::dot(d, glm::dvec3(b.forward));
  const double x = glm::dot(d, glm::dvec3(b.right)) / z, y = glm::dot(d, glm::dvec3(b.up)) / z;
  return {(x / (b.aspect * b.tan_half_vfov) + 1.0 + b.shift.x) * width / 2.0,
          (1.0 - b.shift.y - y / b.tan_half_vfov) * height / 2.0};
}

// The droplets preset's scene with its droplets object turned by `yaw` degrees.
Scene droplets_scene(float yaw) {
  Scene s = Editor("droplets", "").scene();
  for (SceneObject& o : s.objects)
    if (as_droplets(o)) o.placement.yaw = yaw;
  return s;
}

// The frame as the viewer draws it: framed in the part of the window beside the panel.
FrameState framed(const SceneSimulation& sim) {
  FrameState f = sim.frame();
  f.view = PictureRect{0.33, 0.0, 0.67, 1.0};
  return f;
}

// The window point (SDL's, pixel centres at +0.5 of it) where the frame shows plane point q.
MouseMotion mouse_at(const FrameState& f, glm::dvec2 q) {
  const DropletsFrame& d = f.droplets.at(0);
  const glm::dvec2 px = project(camera_basis(f, kWindowW, kWindowH), droplet_plane_point(d.position, d.yaw, q),
                                kWindowW, kWindowH);
  MouseMotion m;
  m.x = px.x - 0.5;
  m.y = px.y - 0.5;
  m.window_width = kWindowW;
  m.window_height = kWindowH;
  return m;
}

TEST(MousePointer, TheMouseOverAPlanePointGivesThatPoint) {
  for (const float yaw : {0.0f, 35.0f, -60.0f}) {
    SCOPED_TRACE(yaw);
    const SceneSimulation sim(droplets_scene(yaw));
    const FrameState f = framed(sim);
    ASSERT_EQ(f.droplets.size(), 1u);
    for (const glm::dvec2 q : {glm::dvec2(0.0, 0.0), glm::dvec2(0.05, 0.03), glm::dvec2(-0.08, -0.04)}) {
      const MouseMotion m = mouse_at(f, q);
      // Inside the window, in the framed part (the right of the panel's third) for the centre.
      ASSERT_GT(m.x, 0);
      ASSERT_LT(m.x, kWindowW);
      const std::optional<glm::dvec2> p = mouse_pointer(f, m);
      ASSERT_TRUE(p.has_value());
      EXPECT_NEAR(p->x, q.x, 1e-6);
      EXPECT_NEAR(p->y, q.y, 1e-6);
    }
  }
}

TEST(MousePointer, MovingTheMouseMovesThePointerTheSameWay) {
  const SceneSimulation sim(droplets_scene(0));
  const FrameState f = framed(sim);
  MouseMotion m = mouse_at(f, {0.0, 0.0});
  const glm::dvec2 centre = *mouse_pointer(f, m);
  m.x += 100;  // right and down on the screen: right and down in a plane facing the camera
  m.y += 60;
  const glm::dvec2 moved = *mouse_pointer(f, m);
  EXPECT_GT(moved.x - centre.x, 0.01);
  EXPECT_LT(moved.y - centre.y, -0.005);
}

TEST(MousePointer, TheTrailGathersWhereTheMouseIs) {
  SceneSimulation sim(droplets_scene(20));
  const glm::dvec2 q{-0.06, 0.02};
  const std::optional<glm::dvec2> p = mouse_pointer(framed(sim), mouse_at(framed(sim), q));
  ASSERT_TRUE(p.has_value());
  sim.set_pointer(*p);
  for (int i = 0; i < 3 * 240; ++i) {
    MotionSample rest;
    rest.time = sim.time() + Simulation::kStep;
    sim.step(rest);
  }
  const DropletTrail* trail = nullptr;
  for (int i = 0; i < int(sim.scene().objects.size()) && !trail; ++i) trail = sim.trail(i);
  ASSERT_NE(trail, nullptr);
  EXPECT_LT(glm::length(trail->positions().front() - q), 1e-3);
  EXPECT_LT(glm::length(trail->positions().back() - q), 1e-3);
}

TEST(MousePointer, OnlyPlainMotionOverThePictureOfDropletsDrivesIt) {
  const SceneSimulation sim(droplets_scene(0));
  const FrameState f = framed(sim);
  const MouseMotion m = mouse_at(f, {0.02, 0.01});
  ASSERT_TRUE(mouse_pointer(f, m).has_value());
  MouseMotion ui = m;
  ui.over_ui = true;
  EXPECT_FALSE(mouse_pointer(f, ui).has_value());
  MouseMotion drag = m;
  drag.dragging_glass = true;
  EXPECT_FALSE(mouse_pointer(f, drag).has_value());
  MouseMotion scripted = m;
  scripted.scripted = true;
  EXPECT_FALSE(mouse_pointer(f, scripted).has_value());
  MouseMotion no_window = m;
  no_window.window_width = 0;
  EXPECT_FALSE(mouse_pointer(f, no_window).has_value());
  MouseMotion nowhere = m;
  nowhere.x = std::nan("");
  EXPECT_FALSE(mouse_pointer(f, nowhere).has_value());
  // A lager alone has no trail to drive.
  const SceneSimulation lager(Editor("lager", "").scene());
  EXPECT_FALSE(mouse_pointer(framed(lager), m).has_value());
}

TEST(MousePointer, ARayThatMissesThePlaneGivesNoPointer) {
  // The plane turned edge-on to the camera (yaw 90: it faces +x, the camera looks along -z
  // from beside it): rays turned away from it meet it only behind the eye.
  const SceneSimulation sim(droplets_scene(90));
  const FrameState f = framed(sim);
  MouseMotion m;
  m.window_width = kWindowW;
  m.window_height = kWindowH;
  const DropletsFrame& d = f.droplets.at(0);
  const CameraBasis b = camera_basis(f, kWindowW, kWindowH);
  // Which side of the plane the eye is on decides which side of the window sees it ahead.
  const glm::dvec3 normal(std::sin(glm::radians(double(d.yaw))), 0.0, std::cos(glm::radians(double(d.yaw))));
  const double side = glm::dot(glm::dvec3(b.eye) - glm::dvec3(d.position), normal);
  ASSERT_NE(side, 0.0);
  const glm::dvec2 at_plane = project(b, glm::dvec3(d.position), kWindowW, kWindowH);
  // Rays turned further towards the eye's side than the plane's own picture never meet it.
  const double away = glm::dot(glm::dvec3(b.right), normal) * side > 0 ? 1.0 : -1.0;
  m.y = at_plane.y;
  m.x = at_plane.x + away * 200;
  EXPECT_FALSE(mouse_pointer(f, m).has_value());
  m.x = at_plane.x - away * 200;
  EXPECT_TRUE(mouse_pointer(f, m).has_value());
}

}  // namespace
}  // namespace draught::viewer
