// FrameState: the plain-data snapshot of one frame of a scene that the renderer draws,
// made by the simulation (or, for a still picture, by make_frame at rest). It holds every
// object's state; the GPU side never computes geometry or physics itself.
#pragma once

#include "core/bubbles/bubbles.hpp"
#include "core/condensation/condensation.hpp"
#include "core/droplets/droplets.hpp"
#include "core/environment/backdrop.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/reflection.hpp"
#include "core/environment/screen.hpp"
#include "core/foam/foam.hpp"
#include "core/liquid/beverage.hpp"
#include "core/params/params.hpp"
#include "core/scene/camera.hpp"
#include "core/reference/intersect.hpp"
#include "core/scene/motion.hpp"
#include "core/scene/scene.hpp"
#include "core/vessel/fill_table.hpp"
#include "core/vessel/vessel.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace draught {

// One vessel object's state in a frame.
struct VesselFrame {
  VesselParams params;
  Placement placement;  // where it stands in the scene (auto-framing uses this, not the motion)
  Vessel vessel;
  std::shared_ptr<const FillTable> fill_table;  // the same object while the glass is unchanged
  Pose pose;                                    // the glass in the world (placement and motion)
  LiquidPlane liquid;                           // local frame; offset < base when empty
  double liquid_tilt = 0, liquid_azimuth = 0;   // the surface normal in the local frame
  double liquid_fraction = 0;                   // of the cavity volume
  bool has_liquid = false;
  FoamFrame foam;               // the head on the liquid, lacing, big bubbles
  std::vector<PlacedBubble> big_bubbles;  // the head's big bubbles placed on its top (glass frame)
  std::vector<Bubble> bubbles;  // rising in the liquid, glass frame
  DrinkAbsorption liquid_absorption;  // the drink's colour, two bands per channel (core/liquid/beverage)
  double mean_outer_radius = 0;
  // Beads and fog on the outer wall (core/condensation); null when the glass is dry.
  std::shared_ptr<const CondensationState> condensation;
  // What its head is lit by besides the lights: the media's surround seen from the head's
  // middle (EnvironmentFrame::media_seen_from; assemble_frame). Without a head, unset.
  SkyIrradiance head_surround;
};

// Whether a vessel has a head: liquid and more than a tenth of a millimetre of foam (the
// renderer's FOAM_HEAD variant, the reference's head volume and the head's own view).
inline bool has_head(const VesselFrame& v) { return v.has_liquid && v.foam.thickness > 1e-4; }

// Where a vessel's head is, in the world: on the axis, half its thickness above the
// liquid's surface.
glm::dvec3 head_middle(const VesselFrame&);

// The light's straight path through each glass's drink, taken as an upright column of its
// mean outer radius from the cavity's floor to the surface on the axis, passing
// exp(-absorption x chord) (the drink's colour at its glassful's path; refraction, the
// glass and the head left out): what a head's view of the paper needs of the glasses'
// shadows (a stout's is dark, a lager's pale), not the floor's caustics.
LightPasses drink_columns(const std::vector<VesselFrame>&);
// The same in two steps: each glass's column (its surface in steps of kViewStep), and the
// light's passes through them.
struct DrinkColumn {
  glm::dquat to_local;  // world to the glass's frame
  glm::dvec3 origin;    // the glass's origin in the world
  double radius, y0, y1;
  glm::dvec3 absorption;
};
std::vector<DrinkColumn> drink_column_list(const std::vector<VesselFrame>&);
LightPasses light_passes(std::vector<DrinkColumn>);

// The step the heads' views of their surroundings are taken in (m): a head's middle and a
// drink's surface rounded to it, so a settling head is not seen again every frame.
inline constexpr double kViewStep = 5e-4;

// What assemble_frame computed of the surroundings, and from what: an app's frames
// (SceneSimulation::frame) reuse the scene's light while the studio's parameters and where
// the rig stands are unchanged, and each head's view while its middle and the drinks'
// columns are (core_bench BM_SceneFrame: a still pint's frame 2.9 ms of CPU without it).
// The frames are the same with or without one. One per app; not for two threads at once.
struct EnvironmentCache {
  std::string scene_key;   // what `scene` was computed from
  EnvironmentFrame scene;  // the surroundings without the heads' views
  std::string columns_key; // the drinks' columns the views were taken through
  std::vector<std::pair<glm::dvec3, SkyIrradiance>> views;  // each head's, by its (rounded) middle
};

struct FrameState {
  SceneParams params;
  CameraParams camera;  // the camera in effect for a square picture (auto-framed or as given)
  // The camera in effect for a width x height picture: auto-framing fits the scene's
  // width to the picture's, so a wide picture of a flight is framed tightly.
  CameraParams camera_for(int width, int height) const;
  std::vector<VesselFrame> vessels;
  int selected = 0;  // index into vessels of the object input drives
  // The part of the picture the camera frames the scene in; the rest extends it (the
  // desktop viewer: the part its panel and overlay leave free). The whole picture by default.
  PictureRect view;
  EnvironmentFrame environment;  // what the surroundings give the renderer (core/environment)
  LightRig lights;               // the studio's area lights, placed around scene_aim
  BackdropSurface backdrop;      // what the scene stands on (the sweep around scene_aim)
  double time = 0;               // the scene's time (s): what the screen shows depends on it
  ScreenFrame screen;            // the moving picture on a card or as the background (screen.*)
  std::vector<DropletsFrame> droplets;  // the droplets objects (at most one), their spheres in the world
  std::vector<CloudFrame> clouds;       // the point clouds (at most kMaxClouds), their points in the world
};

// The middle of a glass as it stands now (its pose): halfway up its axis. Where the head
// and the haze take their lights from, and where a glass's surroundings are seen from
// (env.reflections' panoramas).
glm::dvec3 vessel_middle(const VesselFrame&);

// The scene's centre the studio's lights (and the sweep) are placed around: the middle of
// the glasses' placements across the floor, at half the tallest glass's height. Placements,
// not poses: a glass tipped by the hand does not move the lights.
glm::dvec3 scene_aim(const std::vector<VesselFrame>&);
// Where the scene's surroundings are seen from (the MatCap's bake): scene_aim where there
// are glasses, else the middle of the droplets' and point clouds' placements (a scene of
// droplets alone looks from them, not from the floor under them).
glm::dvec3 surroundings_centre(const FrameState&);
// The middle of the drinks as poured (placements, the liquid at rest; the glasses' middle
// where there is none), at scene_aim's x and z: what the backlight shines through.
glm::dvec3 drink_aim(const std::vector<VesselFrame>&);

// The frame of these vessels in a scene with these parameters (the camera framed) at the
// scene's time `time` (what the screen shows). A screen in the background leaves out the
// floor: the picture is the surroundings.
FrameState assemble_frame(const SceneParams&, std::vector<VesselFrame>, int selected = 0, double time = 0,
                          EnvironmentCache* cache = nullptr);
// A still frame: every glass upright at rest at its placement, filled to its liquid.fill.
FrameState make_frame(const Scene&);
FrameState make_frame(const Params&);  // a single glass
// The camera that frames everything in the frame, looking along target - eye of `c`: the
// glasses as they stand at their places, and if a posed glass (tilted, shaken) would
// reach out of that picture, backed away along its line of sight until it is inside.
CameraParams frame_camera(const CameraParams& c, const std::vector<VesselFrame>&, double aspect = 1.0);
CameraParams frame_camera(const CameraParams& c, const Vessel&);  // one upright glass at the origin
// The reference intersector's view of the frame (every object, the floor, clip planes);
// with_decals: each vessel's decals placed too (their images read, through the cache of
// core/vessel/decal_files), for the reference path tracer and the decal probes.
SceneGeometry scene_geometry(const FrameState&, bool with_decals = false);

// The camera basis of a width x height picture of the frame (camera_for the part `view` of
// the picture, then the basis, its lens shifted to that part).
CameraBasis camera_basis(const FrameState&, int width, int height);

// How far the scene's objects lie from the camera of a width x height picture: the nearest
// and the farthest point of every object's bounds as it stands now (walls and rim, posed),
// metres from the eye. A depth picture spreads its greys over this range; the floor and the
// sky reach to the horizon and would squeeze the glasses into one grey.
struct DepthRange {
  double near = 0, far = 0;
};
DepthRange depth_range(const FrameState&, int width, int height);

// The object seen at pixel (px, py) of a width x height picture (the first surface along
// the camera ray, reference intersector), or -1 for the floor and the sky.
int pick_object(const FrameState&, double px, double py, int width, int height);

// Where the camera ray through pixel (px, py) of a width x height picture of the frame
// meets the plane of its droplets object's trail, in that plane's coordinates (metres
// right and up from the object's position; core/droplets/trail.hpp droplet_plane_hit):
// the pointer SceneSimulation::set_pointer takes. The one mapping of the viewer's mouse
// and the web page's mouse and touch. Empty when the frame has no droplets, the pixel or
// the size is not finite and positive, or the ray does not meet the plane ahead of the eye.
std::optional<glm::dvec2> droplet_pointer_at(const FrameState&, double px, double py, int width, int height);

}  // namespace draught
