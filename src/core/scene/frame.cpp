#include "core/scene/frame.hpp"

#include "core/sim/simulation.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

CameraParams frame_camera(const CameraParams& c, const Vessel& v) {
  if (!c.auto_frame) return c;
  glm::dvec3 back = glm::dvec3(c.eye - c.target);
  back = glm::length(back) > 1e-9 ? glm::normalize(back) : glm::dvec3(0, 0, 1);
  const double half_tan = std::tan(glm::radians(double(c.vfov)) * 0.5);
  // Half the glass height with a margin for the floor and the rim, or its width.
  const double half = std::max(0.5 * v.height + 0.012, v.bound_radius * 1.1) * 1.12;
  const double dist = half / half_tan + v.bound_radius;
  CameraParams out = c;
  out.target = glm::vec3(0.0, 0.47 * v.height, 0.0);
  out.eye = out.target + glm::vec3(back * dist);
  return out;
}

FrameState make_frame(const Params& p) {
  Simulation sim(p);
  sim.settle_bubbles(4.0);
  return sim.frame();
}

SceneGeometry scene_geometry(const FrameState& f) {
  SceneGeometry g{&f.vessel, f.liquid, f.params.env.floor && !f.params.render.transparent, f.pose};
  const ClipParams& c = f.params.clip;
  const double len = glm::length(glm::dvec3(c.normal));
  if (c.enabled && len > 1e-4) g.clip = glm::dvec4(glm::dvec3(c.normal) / len, c.offset);
  return g;
}

}  // namespace draught
