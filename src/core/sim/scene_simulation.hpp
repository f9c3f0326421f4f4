// The simulation of a whole scene: one Simulation per vessel object, each at its
// placement. Input drives the selected object; the others stand at rest (or follow a
// timeline's actions addressed to them). Deterministic like Simulation.
#pragma once

#include "core/scene/frame.hpp"
#include "core/scene/scene.hpp"
#include "core/droplets/trail.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/sim/simulation.hpp"

#include <optional>
#include <vector>

namespace draught {

// A motion sample of the object's own stage moved to its placement: the foot's centre
// at placement.position, the glass turned by placement.yaw about its axis. The placement
// at the origin returns the sample unchanged (bit for bit: a single glass moves exactly
// as a Simulation of its own).
MotionSample placed(const MotionSample&, const Placement&);

class SceneSimulation {
 public:
  explicit SceneSimulation(const Scene&);

  // A new scene (a preset switch, a slider). Objects whose glass is unchanged keep their
  // simulation state; a different object list rebuilds everything.
  void set_scene(const Scene&);
  const Scene& scene() const { return scene_; }

  int selected() const { return scene_.selected; }
  void select(int object);  // clamped to the objects there are

  void settle_bubbles(double seconds);
  // The scene begins at time t of the caller's clock (an app that loads a scene while its
  // own clock has run): every object jumps there, and the point clouds' sources count their
  // time (a gob's turning, a file's cooling, a sequence's frame) from t, not from 0. The
  // CLI starts at 0 and never calls this.
  void begin_at(double t);
  // Steps every object to time t: the selected one samples `driver`, the others stand still.
  void advance(InputDriver& driver, double t, double drink_rate = 0);
  // One step: the selected object moves with `m` (in its own stage), the others rest.
  void step(const MotionSample& m, double drink_rate = 0);
  // One step with a motion (in its own stage) and a drink rate for each object, by index
  // (timelines); an object beyond the vectors rests.
  void step_each(const std::vector<MotionSample>& motions, const std::vector<double>& drink_rates);

  // The simulation of object i (nullptr when it is not a vessel).
  Simulation* vessel(int object);
  const Simulation* vessel(int object) const;
  // The selected object's simulation, or the first vessel's.
  Simulation& selected_vessel();

  FrameState frame() const;
  double time() const;

  // The trail of a droplets object (nullptr for another kind).
  const DropletTrail* trail(int object) const;
  // The pointer every droplets trail follows from now on (the viewer's or the page's mouse,
  // in the trail's plane: core/droplets/trail.hpp droplet_plane_hit); a motion sample that
  // carries its own pointer (a timeline's) wins for its step.
  void set_pointer(glm::dvec2 p) { pointer_ = p; }
  // The source of a point-cloud object (nullptr for another kind).
  const CloudSource* cloud(int object) const;

 private:
  Scene scene_;
  std::vector<std::optional<Simulation>> sims_;  // one per object; empty for other kinds
  std::vector<std::optional<DropletTrail>> trails_;  // one per object; set for droplets objects
  std::vector<std::optional<CloudSource>> clouds_;   // one per object; set for point-cloud objects
  glm::dvec2 pointer_{0.0};
  double trail_time_ = 0;  // the clock of a scene without vessels
  double clock_origin_ = 0;  // begin_at's t: where the clouds' sources count from
  void step_trails(const std::vector<MotionSample>* each, const MotionSample* all);
  void step_clouds();  // each cloud's source to the scene's time
  // A glass that input lets go of (the selection moved on) is set back upright over
  // kSettleSeconds, smoothly, so its drink sloshes as when a hand puts a glass down
  // instead of snapping to rest.
  struct Release {
    double start = -1;  // < 0: standing at rest
    Pose from;          // where input left it, in its own stage
  };
  static constexpr double kSettleSeconds = 0.6;
  MotionSample released(size_t object, double t);
  std::vector<Release> releases_;
  MotionSample last_input_;  // the selected glass's last motion, in its own stage
  // The surroundings' light of the frames made so far (frame() is const: a cache, not state).
  mutable EnvironmentCache environment_cache_;
};

}  // namespace draught
