// FrameState: the plain-data snapshot the renderer draws. Built from the parameters
// (and, later, the simulation state); the GPU side never computes geometry itself.
#pragma once

#include "core/intersect.hpp"
#include "core/params.hpp"
#include "core/vessel.hpp"

namespace draught {

struct FrameState {
  Params params;
  CameraParams camera;     // the camera in effect (auto-framed or as given)
  Vessel vessel;
  LiquidPlane liquid;      // offset < base when the glass is empty
  bool has_liquid = false;
  glm::vec3 liquid_absorption{0};
  double mean_outer_radius = 0;
};

FrameState make_frame(const Params&);
// The camera that frames the vessel, looking along target - eye of `c`.
CameraParams frame_camera(const CameraParams& c, const Vessel&);
SceneGeometry scene_geometry(const FrameState&);  // for the reference intersector

}  // namespace draught
