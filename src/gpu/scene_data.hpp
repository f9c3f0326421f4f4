// What the GPU reads of a FrameState, packed with the layouts generated from
// src/interface/*.def: the Frame uniform block (generated/frame.hpp) and the scene's
// data textures (generated/objects.hpp): one ObjectRecord row per object in u_objects,
// one row of profile knots per vessel in u_knots. Textures are updated row by row, only
// where something changed (knots when a glass changes). No physics here: every number
// comes from the FrameState (core computes the liquid plane, big-bubble places and the
// environment estimate).
#pragma once

#include "core/environment/backdrop_light.hpp"
#include "core/environment/floor_light.hpp"
#include "core/pointcloud/cloud_scene.hpp"
#include "core/scene/frame.hpp"
#include "generated/constants.hpp"
#include "generated/frame.hpp"
#include "generated/objects.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace draught::gpu {

using contract::DebugView;

// The uniform block for a width x height target. debug_event: the event the PathEvent
// view reports.
contract::FrameBlock pack_frame_block(const FrameState&, int width, int height, DebugView, int debug_event = 0);
// The droplets' members of the block (droplet_*): the first droplets object's field, or
// zeros for none.
void pack_droplets(const std::vector<DropletsFrame>&, contract::FrameBlock&);
// The point clouds' members of the block (cloud_*, blackbody): each cloud's place in the
// texel arrays of `clouds` (brought up to the frame's clouds) and its material.
void pack_clouds(const FrameState&, const CloudScene& clouds, contract::FrameBlock&);
// Object `row` of the frame (a vessel; its knots in u_knots row `row`).
contract::ObjectRecord pack_object(const FrameState&, int row);
// A vessel's knot row: texel k = (r_outer[k], r_inner[k], r_outer[k + 1], r_inner[k + 1]).
std::vector<glm::vec4> pack_knots(const Vessel&);
// The floor's light map as the texture holds it, twice its height: its rig's factor
// (FloorLightMap::factor: the light over the unoccluded light per channel) in the first
// `height` rows, the surroundings' (surround_factor) in the rest, a = 1; the shader
// multiplies the unoccluded light it computes itself.
std::vector<glm::vec4> pack_floor_light(const FloorLightMap&);
// The backdrop's light map as the texture holds it: rgb the irradiance, a whether the
// filtering may be trusted (BackdropLightMap::trusted).
std::vector<glm::vec4> pack_backdrop_light(const BackdropLightMap&);

// The two data textures (RGBA32F, fetched texel by texel: ES 3.0 does not filter float
// textures) and the floor's light map (RGBA16F, filtered). Needs a current GLES 3.0 context.
class SceneTextures {
 public:
  SceneTextures();
  ~SceneTextures();
  SceneTextures(const SceneTextures&) = delete;
  SceneTextures& operator=(const SceneTextures&) = delete;

  // Brings both textures up to the frame: rows that differ from what they hold are
  // uploaded, nothing else. Throws for more than contract::kMaxSceneObjects objects.
  // width x height: the picture's size, which sets the backdrop light map's texel.
  // light_maps: whether the frame's pass reads the floor's and the backdrop's light maps
  // (the MatCap tier's backdrop has no traced shadows and takes the rig's light per
  // pixel): without, neither is computed or uploaded (the backdrop's took 0.2 s on two
  // cores for a still after each change), the block says none, and the maps kept wait for
  // a frame that reads them.
  void update(const FrameState&, int width, int height, bool light_maps = true);
  // Binds the textures to their units (generated: kObjectSampler, kKnotsSampler,
  // kFloorLightSampler).
  void bind() const;
  // The floor's light map: computed with these settings when what it depends on changes
  // (floor_light_inputs), never else; off: none (the floor takes the unoccluded light).
  // draft_photons > 0 (interactive apps): a frame whose inputs just changed gets a draft of
  // that many photons on texels twice as wide; once they hold still the map is traced
  // again on full texels in batches over frames (set_floor_refinement) until the full
  // budget is reached: no frame stalls on the whole budget. While the inputs keep
  // changing, a draft every other frame.
  void set_floor_light(const FloorLightSettings&, bool on = true, int draft_photons = 0);
  // How a still's map is refined (with draft_photons > 0): in batches of batch_photons
  // (0: the draft's), the first frame two drafts' worth, then at least one batch a frame
  // and more while the frame's batches so far took under ms_per_frame (0: one a frame).
  // Small batches in a few milliseconds keep an app's frames at its drawing speed while
  // the map refines: the web page's one thread took 25 ms a frame for batches of 5,000
  // photons, and its adaptive quality counted them as the picture's cost.
  void set_floor_refinement(int batch_photons, double ms_per_frame);
  // Where the map lies (frame block members floor_light_*) for the frame of the last update.
  void describe_floor_light(contract::FrameBlock&) const;
  const FloorLightMap& floor_light() const;
  // The backdrop's light map (computed when backdrop_light_inputs change, never else) and
  // where it lies (frame block members backdrop_light_*).
  void describe_backdrop_light(contract::FrameBlock&) const;
  const BackdropLightMap& backdrop_light() const;
  // Whether the last update computed and uploaded the backdrop's light map.
  bool backdrop_light_computed() const { return backdrop_computed_; }
  // Drafts of the backdrop's light map (interactive apps): a frame whose backdrop inputs
  // differ from the last frame's (a light's slider dragged, a glass moved, the first frame)
  // gets a map on texels four times as wide, up to 4 cm (a sixteenth of the work; its trust marks keep
  // it as exact, handing more pixels to the exact sum), and the picture's own map comes the
  // first frame they hold still. Off (the CLI, tests): every map the picture's own.
  void set_backdrop_drafts(bool on) { backdrop_drafts_ = on; }

  // Whether the last update uploaded an environment image (env.mode image): only when the
  // frame's map is another than the one the texture holds.
  bool environment_uploaded() const { return environment_uploaded_; }

  // Rows uploaded by the last update (tests check that a still frame uploads none).
  int object_rows_uploaded() const { return object_uploads_; }
  int knot_rows_uploaded() const { return knot_uploads_; }
  // Whether the last update computed and uploaded the floor's light map.
  bool floor_light_computed() const { return floor_computed_; }
  // Whether it also put the map's texels in the texture (a refining map's every few batches).
  bool floor_light_uploaded() const { return floor_uploaded_; }
  int capacity() const { return capacity_; }
  // The frame's object records as the last update packed them (one per glass).
  std::vector<contract::ObjectRecord> records() const;

 private:
  void allocate(int rows);

  unsigned objects_tex_ = 0, knots_tex_ = 0;
  int capacity_ = 0;  // rows allocated in both textures
  std::vector<std::optional<contract::ObjectRecord>> objects_;  // what u_objects holds, row by row
  std::vector<std::vector<glm::vec4>> knots_;     // what u_knots holds
  int object_uploads_ = 0, knot_uploads_ = 0;

  void update_floor_light(const FrameState&);
  void clear_floor_light();
  // The last few maps with their textures, the current one first: frames that alternate
  // between a few states (a benchmark's interleaved scenes, a still drawn at two sizes)
  // trace each once.
  struct FloorEntry {
    std::vector<double> inputs;  // what the map was computed from
    FloorLightMap map;
    unsigned tex = 0;
    bool draft = false;
    std::unique_ptr<FloorLightTrace> refining;  // a still's map still taking batches (the current entry only)
    int batches_left = 0;
    int uploaded_batches = 0;  // the trace's batches the texture holds
    // The map, in the trace while it refines (not copied out each batch).
    const FloorLightMap& current() const { return refining ? refining->map() : map; }
    // Its rect, with no merge of a refining trace's lanes (what each frame needs).
    const FloorLightMap& rect() const { return refining ? refining->last_merged() : map; }
    // No more batches: it keeps what it has.
    void settle() {
      if (refining) map = refining->release();
      refining.reset();
    }
  };
  void refine_floor_light(FloorEntry&, int min_batches);
  const FloorLightMap& floor_rect() const;  // the current map's rect, merging nothing
  static constexpr size_t kFloorCache = 6;
  std::vector<FloorEntry> floor_cache_;
  unsigned neutral_tex_ = 0;  // one texel of factor 1, bound when there is no map
  FloorLightSettings floor_settings_;

  void update_environment(const FrameState&);
  std::shared_ptr<const EnvironmentMap> environment_;  // what u_env_image holds
  unsigned environment_tex_ = 0;
  bool environment_uploaded_ = false;

  void update_backdrop_light(const FrameState&, double texel);
  // The last few backdrop maps, the current one first (as the floor's: interleaved scenes
  // compute each once).
  struct BackdropEntry {
    std::vector<double> inputs;
    BackdropLightMap map;
    unsigned tex = 0;
  };
  std::vector<BackdropEntry> backdrop_cache_;
  bool use_cached_backdrop_light(const std::vector<double>& inputs);
  bool backdrop_computed_ = false;
  bool backdrop_drafts_ = false;
  std::vector<double> backdrop_last_inputs_;  // the picture's own map's inputs at the last update
  bool floor_on_ = true, floor_computed_ = false, floor_uploaded_ = false;
  bool maps_read_ = true;  // the last update's frame reads the light maps (update's light_maps)
  int draft_photons_ = 0;
  int refine_batch_photons_ = 0;   // 0: the draft's
  double refine_ms_per_frame_ = 0;  // 0: one batch a frame
  bool drafted_last_ = false;  // the last update traced a draft (the next one in motion skips)
};

}  // namespace draught::gpu
