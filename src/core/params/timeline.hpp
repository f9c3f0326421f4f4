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
//       { "at": 0,   "action": "pour" },
//       { "at": 1,   "action": "play", "from": 0 },
//       { "at": 3,   "action": "seek", "to": 12.5 },
//       { "at": 5,   "action": "stop" } ] }
//
// tilt: lean the glass `angle` degrees towards `toward` (degrees from screen right, +X,
// towards the viewer, +Z), tipping on its foot; from wherever it leans at `at`.
// rotate: spin about its own axis. shake: move it to and fro horizontally (amplitude in
// metres, frequency in Hz, along `toward`). sip: drink `amount` of the glass's volume.
// orbit: move the camera around the glass. set: any parameter of the table; numbers
// and vectors blend over `duration`, others switch at `at`. pour: a stream falls from
// above into the emptied glass for `duration` seconds (default kPourSeconds; 0 fills it
// at once), the level rising to liquid.fill as its volume arrives, and a fresh head
// builds (foam.rise_time) from the first splash, then settles. Easing is smooth
// (zero speed at both ends) unless "ease": "linear".
// play, seek, stop drive the screen's source (core/environment/screen.hpp): play starts it
// (from `from` seconds into the source when given, else where it stands), seek jumps to
// `to` (playing on if it played), stop holds the frame it shows. Without them the source
// plays from screen.start as the scene's time runs (unless screen.playing is false). The
// position at time t is resolved by scene_at, so the frame shown is a function of t.
//
// In a scene of several objects, an action may carry "object": N (an index) or "object":
// "name" (an object's name in the scene preset): tilt, rotate, shake, sip and pour then
// drive that object only; without it they drive every vessel alike, each at its own
// place. A set action addresses one object with "object" or with a path such as
// "objects[2].liquid.srm"; without either, a vessel parameter is set on every object.
// orbit moves the camera and takes no object. pointer: { "at": 1, "action": "pointer",
// "to": [0.1, 0.05], "duration": 0.5 } moves a droplets object's pointer (core/droplets,
// docs/DROPLETS.md) in its plane, metres right and up from its placement; the trail of
// droplets follows it. Names and indexes are checked against the
// scene by bind_timeline (the CLI binds to the scene it renders, `draught validate` to
// the timeline's own preset).
#pragma once

#include "core/input/driver.hpp"
#include "core/params/params.hpp"
#include "core/scene/scene.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace draught {

// How long a pour action lasts when it does not say (seconds): a pint poured at a tap.
inline constexpr double kPourSeconds = 3.0;

inline constexpr int kTimelineFormat = 1;

// The object of an action that names one ("object": "stout") until bind_timeline finds
// it in a scene; such an action drives nothing before.
inline constexpr int kUnboundObject = -2;

struct TimelineAction {
  enum class Kind { Tilt, Rotate, Shake, Sip, Orbit, Set, Pour, Play, Seek, Stop, Pointer } kind;
  double at = 0, duration = 0;
  bool linear = false;
  double angle = 0, toward = 0;               // tilt (radians)
  double degrees = 0;                         // rotate, orbit (radians despite the name in JSON)
  double amplitude = 0, frequency = 0;        // shake (m, Hz); direction in `toward`
  double amount = 0;                          // sip
  glm::dvec2 to{0.0};                         // pointer: where it goes in the droplets' plane (m)
  double position = -1;                       // play (from; < 0: where it stands), seek (to): seconds into the source
  const ParamDesc* param = nullptr;           // set
  ParamValue value;
  int index = 0;            // its place in the file's "actions" (for messages: actions[3])
  int object = -1;          // the object it drives: -1 every vessel; kUnboundObject: a name not yet bound
  std::string object_name;  // "object": "name" as written; empty for an index or none
  std::string object_field; // where the object was given ("actions[3].object", "actions[3].param"); empty: none
};

struct Timeline {
  std::string file, name, description;
  std::string preset, glass;  // optional scene for the CLI (empty: none given)
  double duration = 0;        // seconds
  double fps = 0;             // 0: not given
  std::vector<TimelineAction> actions;  // sorted by `at` (stable)

  // Whether action `a` drives object `object` (-1 or that index).
  static bool drives(const TimelineAction& a, int object) { return a.object == -1 || a.object == object; }

  // For object `object` (a single glass is object 0): the glass's lean (radians, as a
  // vector: its length is the tilt, its direction the side it leans to), spin and shake
  // offset at time t, from the actions that drive it.
  glm::dvec2 lean_at(double t, int object = 0) const;
  double spin_at(double t, int object = 0) const;
  glm::dvec3 shake_at(double t, int object = 0) const;
  double drink_rate_at(double t, int object = 0) const;  // fraction of the cavity per second
  // Where the pointer of a droplets object is at time t (its plane's coordinates, m: each
  // pointer action blends from where the pointer was when it started to its `to`); none
  // when no pointer action drives the object.
  std::optional<glm::dvec2> pointer_at(double t, int object = 0) const;
  // The duration of a pour action at a time in [t0, t1) (0: an instant fill), or none.
  std::optional<double> pours_in(double t0, double t1, int object = 0) const;
  // The parameters at time t: `base` with the set and orbit actions applied (a single
  // glass: the actions for every object and for object 0).
  Params params_at(double t, const Params& base) const;
  // The same for a scene: set actions reach every object, or the one they address; the
  // screen's position at t resolved from the play, seek and stop actions.
  Scene scene_at(double t, const Scene& base) const;
  // Seconds into the screen's source at time t, from screen.start and screen.playing at 0
  // and the play, seek and stop actions up to t.
  double screen_position_at(double t, double start, bool playing) const;

  // Where each tilt starts, per object that actions address (and -1 for the others), and
  // the tilts that drive it in the order they start: computed by parse_timeline and
  // bind_timeline, in linear time.
  std::map<int, std::vector<glm::dvec2>> tilt_from;
  std::map<int, std::vector<size_t>> tilt_order;
  void prepare_tilts();
};

Timeline parse_timeline(const std::string& text, const std::string& file);  // throws InputError
Timeline load_timeline(const std::string& name_or_path);  // a path, or a name under presets/timelines/
// Resolves the actions' objects in this scene: names to indexes, and every index must be
// one of the scene's objects; throws InputError "FILE: field 'actions[3].object':
// expected ...". A timeline may be bound again to another scene.
void bind_timeline(Timeline&, const Scene&);

// The scripted input driver: the glass tipped on its foot (radius foot_radius) as the
// timeline says for object `object`, with velocities and accelerations from its smooth path.
class TimelineDriver : public InputDriver {
 public:
  TimelineDriver(const Timeline& t, double foot_radius, int object = 0)
      : timeline_(&t), foot_radius_(foot_radius), object_(object) {}
  const char* name() const override { return "timeline"; }
  MotionSample sample(double t) override;
  Pose pose_at(double t) const;

 private:
  const Timeline* timeline_;
  double foot_radius_;
  int object_;
};

class Simulation;
class SceneSimulation;
struct FrameState;
// Plays the timeline up to time t: the parameters as they are at t, then fixed
// simulation steps with the scripted motion and sips (a single glass: object 0's actions).
void play_timeline(Simulation&, TimelineDriver&, const Timeline&, const Params& base, double t);
// The frame at time t of the timeline played from the start (tests, benchmarks, stills).
FrameState timeline_frame(const Timeline&, const Params& base, double t);

// The same on a scene: one driver per object (each tips on its own glass's foot), made
// for the simulation's objects. The timeline must be bound to the scene (bind_timeline).
std::vector<TimelineDriver> timeline_drivers(const Timeline&, const SceneSimulation&);
void play_timeline(SceneSimulation&, std::vector<TimelineDriver>&, const Timeline&, const Scene& base, double t);
// Binds a copy of the timeline to `base`, plays it and returns the frame at time t; a
// scene of one glass gives exactly the frame of timeline_frame(tl, params, t).
FrameState timeline_frame(const Timeline&, const Scene& base, double t);

}  // namespace draught
