// Timelines: JSON files that script what happens to a drink over time, for headless
// animations (and replays in the viewer and the web page).
//
//   { "draught_timeline": 1, "name": "shake-and-settle", "description": "...",
//     "preset": "lager", "glass": "pint", "duration": 6, "fps": 30,
//     "actions": [
//       { "at": 0.5, "action": "tilt",   "angle": 20, "toward": 0, "duration": 1 },
//       { "at": 2,   "action": "shake",  "amplitude": 0.008, "frequency": 3, "duration": 1.5 },
//       { "at": 4,   "action": "sip",    "amount": 0.1, "duration": 1 },
//       { "at": 0,   "action": "rotate", "degrees": 90, "duration": 2 },
//       { "at": 0,   "action": "orbit",  "degrees": 45, "duration": 4 },
//       { "at": 1,   "action": "set",    "param": "liquid.srm", "value": 12, "duration": 2 },
//       { "at": 0,   "action": "pour" } ] }
//
// tilt: lean the glass `angle` degrees towards `toward` (degrees from screen right, +X,
// towards the viewer, +Z), tipping on its foot; from wherever it leans at `at`.
// rotate: spin about its own axis. shake: move it to and fro horizontally (amplitude in
// metres, frequency in Hz, along `toward`). sip: drink `amount` of the glass's volume.
// orbit: move the camera around the glass. set: any parameter of the table; numbers
// and vectors blend over `duration`, others switch at `at`. pour: the glass is filled to
// liquid.fill and a fresh head builds (foam.rise_time), then settles. Easing is smooth
// (zero speed at both ends) unless "ease": "linear".
#pragma once

#include "core/input/driver.hpp"
#include "core/params/params.hpp"

#include <string>
#include <vector>

namespace draught {

inline constexpr int kTimelineFormat = 1;

struct TimelineAction {
  enum class Kind { Tilt, Rotate, Shake, Sip, Orbit, Set, Pour } kind;
  double at = 0, duration = 0;
  bool linear = false;
  double angle = 0, toward = 0;               // tilt (radians)
  double degrees = 0;                         // rotate, orbit (radians despite the name in JSON)
  double amplitude = 0, frequency = 0;        // shake (m, Hz); direction in `toward`
  double amount = 0;                          // sip
  const ParamDesc* param = nullptr;           // set
  ParamValue value;
  glm::dvec2 tilt_from{0.0};                  // tilt: lean vector where this action starts
};

struct Timeline {
  std::string file, name, description;
  std::string preset, glass;  // optional scene for the CLI (empty: none given)
  double duration = 0;        // seconds
  double fps = 0;             // 0: not given
  std::vector<TimelineAction> actions;

  // The glass's lean (radians, as a vector: its length is the tilt, its direction the
  // side it leans to), spin and shake offset at time t.
  glm::dvec2 lean_at(double t) const;
  double spin_at(double t) const;
  glm::dvec3 shake_at(double t) const;
  double drink_rate_at(double t) const;  // fraction of the cavity per second
  bool pours_in(double t0, double t1) const;  // a pour action at a time in [t0, t1)
  // The parameters at time t: `base` with the set and orbit actions applied.
  Params params_at(double t, const Params& base) const;
};

Timeline parse_timeline(const std::string& text, const std::string& file);  // throws InputError
Timeline load_timeline(const std::string& name_or_path);  // a path, or a name under presets/timelines/

// The scripted input driver: the glass tipped on its foot (radius foot_radius) as the
// timeline says, with velocities and accelerations from its smooth path.
class TimelineDriver : public InputDriver {
 public:
  TimelineDriver(const Timeline& t, double foot_radius) : timeline_(t), foot_radius_(foot_radius) {}
  const char* name() const override { return "timeline"; }
  MotionSample sample(double t) override;
  Pose pose_at(double t) const;

 private:
  const Timeline& timeline_;
  double foot_radius_;
};

class Simulation;
struct FrameState;
// Plays the timeline up to time t: the parameters as they are at t, then fixed
// simulation steps with the scripted motion and sips.
void play_timeline(Simulation&, TimelineDriver&, const Timeline&, const Params& base, double t);
// The frame at time t of the timeline played from the start (tests, benchmarks, stills).
FrameState timeline_frame(const Timeline&, const Params& base, double t);

}  // namespace draught
