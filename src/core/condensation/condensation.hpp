// Condensation on a cold glass (docs/CONDENSATION.md): water beads on the outer wall where
// the cold drink cools it, and a fog of micro-droplets between them. The beads grow from
// the humid air, merge when they touch (volume conserved), and once too heavy to cling
// run down the wall, taking the beads in their way, wiping the fog off their trail and
// shedding a little water as they go; the fog comes back into the trails slowly and new
// beads nucleate in it. Everything happens in the wall's own coordinates (angle about the
// axis, height), so beads stay on the wall by construction. Deterministic per seed: the
// same parameters give the same beads at the same time.
#pragma once

#include "core/params/params.hpp"
#include "core/vessel/vessel.hpp"

#include <cstdint>
#include <vector>

namespace draught {

// The heights (local y) between which the outer wall is cold enough to bead: from just
// below the cavity's floor up to the drink's level plus condensation.margin.
struct CondensationBand {
  double y0 = 0, y1 = 0;
  bool empty() const { return y1 - y0 < 0.005; }
};

// One bead of water on the outer wall: a spherical cap on a circular base.
struct Bead {
  double angle = 0;   // rad about the axis, from +z towards +x (atan2(x, z)), in [-pi, pi)
  double y = 0;       // m: the base's centre, local height
  double radius = 0;  // m: the base's radius on the wall
  bool sliding = false;
};

// What the renderer draws (gpu/condensation_textures) and the probes compare.
struct CondensationState {
  CondensationBand band;
  float contact_angle = 1.0f;  // rad
  std::vector<Bead> beads;
  // The fog's cover (0..1): kFogAngles x kFogRows, row-major, row r at the band's height
  // fraction (r + 0.5) / kFogRows, column c at angle -pi + (c + 0.5) 2 pi / kFogAngles.
  std::vector<float> fog;
  std::uint64_t version = 0;  // a new value with every change of the above
};

// The volume of a bead of base radius r on glass at contact angle theta (rad): a
// spherical cap, (pi / 3) R^3 (2 + cos theta)(1 - cos theta)^2 with R = r / sin theta.
double bead_volume(double radius, double contact_angle);

class Condensation {
 public:
  static constexpr double kStep = 1.0 / 30.0;  // s: the beads move slowly; 30 steps a second
  static constexpr int kFogAngles = 256, kFogRows = 128;  // = CONDENSATION_FOG_ANGLES, _ROWS

  // Seeds the beads and the fog on the wall of `vessel` up to the drink's level `level`
  // (local y), then ages them params.age seconds: time 0 is the scene's.
  Condensation(const CondensationParams&, const Vessel&, double level);

  // Steps up to the scene's time t (an earlier t does nothing).
  void advance_to(double t);
  double time() const { return double(steps_) * kStep - aged_; }

  const CondensationState& state() const { return state_; }
  const CondensationParams& params() const { return params_; }

  // Where the water is (m^3): on the wall in beads, shed along trails, run off the band's
  // foot. Their sum changes only by growth and nucleation (tests: merging conserves it).
  double bead_water() const;
  double shed_water() const { return shed_; }
  double drained_water() const { return drained_; }
  // How much of the wall's (angle, height) a hand print clears (0..1) at angle a (rad)
  // and height y: 1 inside the palm and the fingers, a soft edge.
  double hand_print(double a, double y) const;

  void step();  // one kStep (public for tests)
  // A bead put on the wall (a splash; tests): it merges with any it touches at the next step.
  void place_bead(const Bead&);

 private:
  CondensationParams params_;
  Vessel vessel_;  // a copy: the Simulation that holds this may move
  CondensationState state_;
  std::vector<float> fog_target_;  // what the fog grows back to
  long steps_ = 0;
  double aged_ = 0;
  double shed_ = 0, drained_ = 0;

  double wall_radius(double y) const;
  double arc(const Bead& a, const Bead& b) const;  // m: around the wall, at their mean height
  void seed_fog();
  void seed_beads();
  void grow_and_nucleate();
  void slide();
  void merge(bool everything);  // touching beads into one; else only those that moved, grew or are new
  size_t merged_upto_ = 0;      // beads from here on are new since the last merge
  std::vector<std::vector<int>> grid_;  // merge's cells (kept: no allocation per step)
  void refog();
  void clear_fog(double angle, double y_low, double y_high, double half_width);
  float fog_cell(double a, double y) const;  // the fog at (a, y), nearest cell
};

}  // namespace draught
