// The visible pour: liquid leaving an origin (a spout, a bottle's neck, a tipping
// glass's rim) with an initial velocity, falling under gravity until it reaches a
// catching plane (the liquid's surface in a glass, or the floor), where its volume is
// absorbed: counted as arrived, for the caller to add to the glass. Parcels are emitted
// at a rate chosen from the stream's fastest speed and thinnest radius, each carrying
// the volume that flowed in its interval (the flow history integrated exactly) along
// its own ballistic path (exact, no integration error). A parcel's blob radius follows
// continuity, r = sqrt(Q / (pi v)): the stream thins as it speeds up. A small wobble of
// the parcels' launch velocity, two sines, keeps it from looking like a glass rod.
// Volume is conserved: emitted = arrived + in flight (compensated sums). World frame,
// metres, y up; fixed steps, deterministic.
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace draught {

struct StreamParams {
  double gravity = 9.81;     // m/s^2, [0.1, 30] (downwards, -y; a parcel must come down)
  double wobble = 0.02;      // m/s, the launch velocity's sideways wobble, [0, 0.5]
  double wobble_hz = 6.0;    // Hz, [0, 50] (the second sine runs 1.618 times as fast)
  double overlap = 0.5;      // spacing of parcels where the stream is fastest, in blob
                             // radii there, [0.1, 1]: smaller is smoother and dearer
  double min_speed = 0.2;    // m/s, the least speed the radius is computed with (a stream
                             // at rest would be infinitely thick), [0.01, 2]
  double max_radius = 0.02;  // m, the thickest a parcel is drawn, [1e-4, 0.1]
};

class PourStream {
 public:
  // Throws std::invalid_argument naming the field and its range for a parameter out of it.
  explicit PourStream(const StreamParams& = {}, glm::dvec3 origin = glm::dvec3(0.0),
                      glm::dvec3 velocity = glm::dvec3(0.0), double target_height = -1.0);

  // From time t on, the flow is q m^3/s (>= 0), until a later entry; an entry at the
  // same t is replaced. A time already past counts from time().
  void set_flow(double t, double cubic_metres_per_second);
  double flow(double t) const;
  // Where and how fast new parcels leave (those in flight keep their paths).
  void set_origin(glm::dvec3 position, glm::dvec3 velocity);
  // The catching plane's height (a rising level absorbs parcels sooner).
  void set_target_height(double y);
  double target_height() const { return target_; }

  // Steps of kStep up to time() + seconds (a remainder is carried to the next call).
  void advance(double seconds);
  double time() const { return steps_ * kStep; }

  // The parcels in flight: world positions, blob radii, velocities.
  PointCloud cloud() const;
  std::size_t parcels() const { return parcels_.size(); }
  // m^3 so far: emitted, absorbed at the target, and in the air now.
  double emitted_volume() const { return emitted_.value(); }
  double arrived_volume() const { return arrived_.value(); }
  double in_flight_volume() const;

  static constexpr double kStep = 1.0 / 240.0;
  // The most parcels emitted in one step (a very thin, fast stream is drawn sparser:
  // it would break into drops anyway).
  static constexpr int kMaxPerStep = 64;

 private:
  // A Neumaier-compensated sum.
  struct Sum {
    double s = 0, c = 0;
    void add(double x);
    double value() const { return s + c; }
  };
  struct Parcel {
    double born;         // s
    glm::dvec3 origin;   // m
    glm::dvec3 launch;   // m/s
    double volume;       // m^3
    double flow;         // m^3/s it was emitted with
  };
  glm::dvec3 at(const Parcel&, double t) const;
  glm::dvec3 velocity_of(const Parcel&, double t) const;
  double flow_integral(double a, double b) const;
  void step();

  StreamParams p_;
  glm::dvec3 origin_, velocity_;
  double target_;
  std::vector<std::pair<double, double>> schedule_;  // (from t, q), sorted by t
  std::vector<Parcel> parcels_;
  Sum emitted_, arrived_;
  long steps_ = 0;
  double pending_ = 0;
};

}  // namespace draught
