// FrameState: the plain-data snapshot the renderer draws, made by the Simulation (or,
// for a still picture, by make_frame at rest). The GPU side never computes geometry
// or physics itself.
#pragma once

#include "core/bubbles/bubbles.hpp"
#include "core/vessel/fill_table.hpp"
#include "core/foam/foam.hpp"
#include "core/reference/intersect.hpp"
#include "core/scene/motion.hpp"
#include "core/params/params.hpp"
#include "core/vessel/vessel.hpp"

#include <memory>

namespace draught {

struct FrameState {
  Params params;
  CameraParams camera;  // the camera in effect (auto-framed or as given)
  Vessel vessel;
  std::shared_ptr<const FillTable> fill_table;  // the same object while the glass is unchanged
  Pose pose;                                    // the glass in the world
  LiquidPlane liquid;                           // local frame; offset < base when empty
  double liquid_tilt = 0, liquid_azimuth = 0;   // the surface normal in the local frame
  double liquid_fraction = 0;                   // of the cavity volume
  bool has_liquid = false;
  FoamFrame foam;  // the head on the liquid, lacing, big bubbles
  std::vector<Bubble> bubbles;  // rising in the liquid, glass frame
  glm::vec3 liquid_absorption{0};
  double mean_outer_radius = 0;
};

// A still frame: the glass upright at rest, filled to params.liquid.fill.
FrameState make_frame(const Params&);
// The camera that frames the vessel, looking along target - eye of `c`.
CameraParams frame_camera(const CameraParams& c, const Vessel&);
SceneGeometry scene_geometry(const FrameState&);  // for the reference intersector

}  // namespace draught
