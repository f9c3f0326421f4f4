// The drink's state over time: where the glass is, how much is in it, how the surface
// sloshes. Fixed time steps, no randomness: the same inputs give the same frames in the
// CLI, the desktop viewer and the web page.
#pragma once

#include "core/bubbles/bubbles.hpp"
#include "core/condensation/condensation.hpp"
#include "core/vessel/fill_table.hpp"
#include "core/foam/foam.hpp"
#include "core/scene/frame.hpp"
#include "core/input/driver.hpp"
#include "core/liquid/slosh.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/pointcloud/stream.hpp"

#include <memory>
#include <optional>

namespace draught {

// A pour's or a spill's stream of a glass: parcels in the air, their volume counted out
// of the glass (spill) or into it (pour) so that stream and glass conserve it. (Outside
// Simulation: a nested struct's member initialisers are not usable in its own class's
// members under clang.)
struct GlassStream {
  PourStream stream;
  double counted = 0;   // arrived volume already added to the glass (pour)
  double end = 0;       // time the flow stops
  std::uint64_t version = 0;
};

class Simulation {
 public:
  static constexpr double kStep = 1.0 / 240.0;  // seconds
  static constexpr double kMaxCatchUp = 0.25;   // a longer gap (a stalled app) is skipped, not simulated

  explicit Simulation(const VesselParams&);

  // New parameters (a preset switch, a slider). The vessel and its fill table are
  // rebuilt only when the glass changed; a changed liquid.fill refills the glass.
  void set_params(const VesselParams&);
  void set_fraction(double fraction);  // drink or refill; clamped to what the glass holds
  void pour();                         // fill to liquid.fill with a fresh head building
  // A pour seen: a stream falls from above the glass into it for `seconds`, carrying
  // what liquid.fill lacks (from an empty glass); the level rises as its volume arrives
  // and the head builds from the first splash. 0 seconds: pour().
  void pour_over(double seconds);
  bool pouring() const { return pour_.has_value(); }
  // The streams in the air now: the pour's, and what spills over the rim (world, drink
  // material); empty when none is.
  std::vector<CloudFrame> streams() const;
  // Lets the bubbles rise for a while with the glass at rest, so a still picture (or
  // the first frame of an animation) shows a drink that has been standing.
  void settle_bubbles(double seconds);
  // Steps to time t (seconds), sampling the driver at every step. drink_rate: fraction
  // of the cavity drunk per second meanwhile (a sip).
  void advance(InputDriver&, double t, double drink_rate = 0);
  // Puts the glass at rest at `pose` without stepping time (a placement in a scene).
  void place(const Pose& pose);
  // Jumps the clock forward to t without simulating the gap (a stalled app).
  void skip_to(double t);
  // One step with this motion (tests, or callers that sample themselves).
  void step(const MotionSample&, double drink_rate = 0);

  // This vessel's part of a frame (its pose includes where the motion put it).
  VesselFrame frame() const;
  const VesselParams& params() const { return params_; }
  double time() const { return time_; }
  double fraction() const { return fraction_; }
  // Fraction of the cavity lost over the rim since the glass was last filled (pour,
  // set_fraction): a refill starts the count again, so it never exceeds what was poured.
  double spilled() const { return spilled_; }
  const SloshState& slosh() const { return slosh_; }
  const FoamState& foam() const { return foam_; }
  const BubbleField& bubbles() const { return *bubbles_; }
  double energy() const;
  const Vessel& vessel() const { return vessel_; }
  const FillTable& fill_table() const { return *table_; }
  const MotionSample& motion() const { return motion_; }
  // The liquid surface in the glass's frame as it is now.
  const LiquidPlane& surface() const { return surface_; }

 private:
  void rebuild_glass();
  void rebuild_bubbles();
  void update_surface();
  // Where the surface plane crosses the glass's axis (the rim height for a surface
  // nearly along the axis), and how far it is below the lowest rim point.
  double axis_level() const;
  double headroom() const;
  SloshEnvironment environment(const glm::dvec3& centre_accel, double dt) const;

  VesselParams params_;
  Vessel vessel_;
  std::shared_ptr<const FillTable> table_;
  double time_ = 0, fraction_ = 0, spilled_ = 0;
  MotionSample motion_;
  glm::dvec2 level_{0.0};   // the resting slope under the last acceleration
  SloshEnvironment env_;
  SloshState slosh_;
  FoamState foam_;
  DrinkAbsorption colour_;  // fitted to the drink's spectrum when its colour changes
  std::optional<BubbleField> bubbles_;  // rebuilt with the glass or the bubble settings
  LiquidPlane surface_;
  double tilt_ = 0, azimuth_ = 0;
  bool first_step_ = true;
  std::optional<GlassStream> pour_, spill_;
  void step_streams(double dt, double spilled_before);
  // Where the pour's stream plunges in (glass frame): a dimple in the head (FoamFrame's
  // crater) and in the drink's surface (SurfaceWaves::dimple_*), opening while it lands
  // and closing after it.
  glm::dvec2 crater_xz_{0.0};
  double crater_radius_ = 0, crater_depth_ = 0, stream_radius_ = 0;
  void step_crater(double dt);
  void place_dimple();  // the surface's dimple from the crater's state
  glm::dvec3 world(const glm::dvec3& local) const;
  // Beads and fog on the outer wall (condensation.enabled): seeded when the glass, its
  // fill or the condensation's settings change, stepped with the scene's time.
  std::optional<Condensation> condensation_;
  mutable std::shared_ptr<const CondensationState> condensation_frame_;  // the last frame's copy
  void rebuild_condensation();
};

}  // namespace draught
