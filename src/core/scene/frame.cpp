#include "core/scene/frame.hpp"

#include "core/scene/camera.hpp"
#include "core/sim/scene_simulation.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {
// Where everything to be framed lies: a box around the glasses as they stand.
struct Bounds {
  glm::dvec3 lo{1e30}, hi{-1e30};
  void add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
};

CameraParams frame_bounds(const CameraParams& c, const Bounds& b, double aspect = 1.0) {
  if (!c.auto_frame || b.empty()) return c;
  glm::dvec3 back = glm::dvec3(c.eye - c.target);
  back = glm::length(back) > 1e-9 ? glm::normalize(back) : glm::dvec3(0, 0, 1);
  const double half_tan = std::tan(glm::radians(double(c.vfov)) * 0.5);
  const glm::dvec3 size = b.hi - b.lo;
  const double radius = 0.5 * std::max(size.x, size.z);
  const double height = b.hi.y;
  // Half the height with a margin for the floor and the rim, or the width.
  // The width fits the picture's width: a wide picture of a flight frames it tightly.
  const double half = std::max(0.5 * height + 0.012, radius * 1.1 / std::max(aspect, 1e-3)) * 1.12;
  const double dist = half / half_tan + radius;
  CameraParams out = c;
  const glm::dvec3 centre(0.5 * (b.lo.x + b.hi.x), 0.47 * height, 0.5 * (b.lo.z + b.hi.z));
  out.target = glm::vec3(centre);
  out.eye = glm::vec3(centre + back * dist);
  return out;
}
}  // namespace

CameraParams frame_camera(const CameraParams& c, const Vessel& v) {
  Bounds b;
  b.add({-v.bound_radius, 0, -v.bound_radius});
  b.add({v.bound_radius, v.height, v.bound_radius});
  return frame_bounds(c, b);
}

namespace {
Bounds standing_bounds(const std::vector<VesselFrame>& vessels) {
  Bounds b;
  // Each glass as it stands at its place (its upright bounds, so motion does not make the
  // camera swim).
  for (const VesselFrame& f : vessels) {
    const glm::dvec3 at(f.placement.position.x, 0, f.placement.position.z);
    const double r = f.vessel.bound_radius;
    b.add(at + glm::dvec3(-r, 0, -r));
    b.add(at + glm::dvec3(r, f.vessel.height, r));
  }
  return b;
}
}  // namespace

CameraParams frame_camera(const CameraParams& c, const std::vector<VesselFrame>& vessels, double aspect) {
  return frame_bounds(c, standing_bounds(vessels), aspect);
}

CameraParams FrameState::camera_for(int width, int height) const {
  if (width <= 0 || height <= 0 || width == height) return camera;
  return frame_camera(params.camera, vessels, double(width) / double(height));
}

CameraBasis camera_basis(const FrameState& f, int width, int height) {
  if (f.view.whole()) return camera_basis(f.camera_for(width, height), width, height);
  const int w = std::max(1, int(std::lround(width * f.view.width)));
  const int h = std::max(1, int(std::lround(height * f.view.height)));
  return camera_basis(f.camera_for(w, h), width, height, f.view);
}

FrameState assemble_frame(const SceneParams& p, std::vector<VesselFrame> vessels, int selected) {
  FrameState f;
  f.params = p;
  f.vessels = std::move(vessels);
  f.selected = std::clamp(selected, 0, std::max(0, int(f.vessels.size()) - 1));
  f.camera = frame_camera(p.camera, f.vessels);
  f.environment = environment_frame(p.env);
  return f;
}

FrameState make_frame(const Scene& s) {
  SceneSimulation sim(s);
  sim.settle_bubbles(4.0);
  return sim.frame();
}

FrameState make_frame(const Params& p) { return make_frame(single_glass_scene(p)); }

SceneGeometry scene_geometry(const FrameState& f) {
  SceneGeometry g;
  g.floor = f.params.env.floor && !f.params.render.transparent;
  for (const VesselFrame& v : f.vessels) {
    VesselGeometry vg{&v.vessel, v.liquid, v.pose};
    const ClipParams& c = v.params.clip;
    const double len = glm::length(glm::dvec3(c.normal));
    if (c.enabled && len > 1e-4) vg.clip = glm::dvec4(glm::dvec3(c.normal) / len, c.offset);
    g.vessels.push_back(vg);
  }
  return g;
}

int pick_object(const FrameState& f, double px, double py, int width, int height) {
  const CameraBasis cam = camera_basis(f, width, height);
  return first_hit(scene_geometry(f), camera_ray(cam, px, py, width, height)).object;
}

DepthRange depth_range(const FrameState& f, int width, int height) {
  const glm::dvec3 eye(camera_basis(f, width, height).eye);
  DepthRange r{1e30, 0};
  for (const VesselFrame& v : f.vessels) {
    // The glass's bounding box in its own frame: the eye moved there, the nearest point of
    // the box is a clamp and the farthest one of its corners.
    const double b = v.vessel.bound_radius, top = v.vessel.height + v.vessel.rim_minor;
    const glm::dvec3 lo(-b, 0, -b), hi(b, top, b);
    const glm::dvec3 e = glm::inverse(v.pose.orientation) * (eye - v.pose.position);
    r.near = std::min(r.near, glm::length(glm::clamp(e, lo, hi) - e));
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 corner(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
      r.far = std::max(r.far, glm::length(corner - e));
    }
  }
  if (f.vessels.empty()) r = {};
  return r;
}

}  // namespace draught
