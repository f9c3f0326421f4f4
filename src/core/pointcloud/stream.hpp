// The visible pour: liquid leaving an origin (a spout, a bottle's neck, a tipping
// glass's rim) with an initial velocity, falling under gravity until it reaches a
// catching plane (the liquid's surface in a glass, or the floor), where its volume is
// absorbed: counted as arrived, for the caller to add to the glass. Parcels are emitted
// at a rate chosen from the stream's fastest speed and thinnest radius, each carrying
// the volume that flowed in its interval (the flow history integrated exactly) along
// its own ballistic path (exact, no integration error). The stream's radius follows
// continuity, r = sqrt(Q / (pi v)): it thins as it speeds up; its parcels' blobs are drawn
// at the radius that makes their line that wide. A small wobble of
// the parcels' launch velocity, two sines, keeps it from looking like a glass rod.
// Volume is conserved: emitted = arrived + in flight (compensated sums). World frame,
// metres, y up; fixed steps, deterministic.
//
// Over a lip (a tipped glass's rim, set_lip) the liquid leaves as a sheet, not from a
// point: the rim's height above its lowest point grows as k s^2 along it (k = sin(tilt) /
// 2R), the liquid over it is h - k s^2 deep, and each strip of the lip passes critical
// flow, sqrt(g) d^(3/2) per metre at sqrt(g d). Their sum, Q = sqrt(g) (3 pi / 8) h^2 /
// sqrt(k), gives the depth h and the sheet's width 2 sqrt(h / k) from the flow. Parcels
// leave side by side across it, each with its strip's share of the flow, and surface
// tension pulls the sheet's sides in at the Taylor-Culick speed sqrt(2 sigma / (rho d)),
// faster as the falling sheet thins: the sheet closes into a rope as it falls. A parcel
// is a slice of the sheet, drawn as a blob per strip (of equal width) while it is open,
// at least 0.8 of the strips' spacing wide, so that it holds together where it is
// thinner than that, and as one blob once it has closed (docs/POINT_CLOUDS.md).
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <memory>
#include <optional>
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
  double capillary = 5e-5;   // m^3/s^2, surface tension over density (water 7.3e-5, wine
                             // about 5e-5), which pulls a spilled sheet into a rope, [0, 1e-3]
};

// A circular lip the liquid spills over, its lowest point where it leaves.
struct StreamLip {
  glm::dvec3 centre{0.0};          // m, the rim circle's centre
  glm::dvec3 up{0.0, 1.0, 0.0};    // unit, the rim plane's normal (the glass's axis)
  glm::dvec3 outward{1.0, 0.0, 0.0};  // unit, in the rim's plane, towards its lowest point
  double radius = 0.04;            // m, to the rim's outer edge
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
  // Where and how fast new parcels leave (those in flight keep their paths): a spout.
  void set_origin(glm::dvec3 position, glm::dvec3 velocity);
  // New parcels leave over this lip as a sheet (until set_origin makes it a spout again).
  // Throws std::invalid_argument for a lip that is not finite or not a circle.
  void set_lip(const StreamLip&);
  // The sheet over the lip at flow q (m^3/s): its depth at the lowest point and half its
  // width along the rim, m (both 0 without a lip or flow).
  struct Sheet {
    double depth = 0, half_width = 0;
  };
  Sheet sheet(double q) const;
  // The catching plane's height (a rising level absorbs parcels sooner).
  void set_target_height(double y);
  double target_height() const { return target_; }

  // Steps of kStep up to time() + seconds (a remainder is carried to the next call).
  void advance(double seconds);
  double time() const { return steps_ * kStep; }

  // The parcels in flight: world positions, blob radii, velocities.
  PointCloud cloud() const;
  std::size_t parcels() const { return parcels_.size(); }
  // The radius of a round stream of the whole flow at the median parcel's speed
  // (continuity), m: how thick the stream is seen, once a sheet has become a rope. 0 when
  // nothing is in flight.
  double rope_radius() const;
  // Where the stream meets its catching plane now: the oldest parcel in flight (the
  // lowest) on the plane, and the stream's continuity radius and flow there. nullopt when
  // nothing carrying flow is in flight.
  struct Landing {
    glm::dvec3 position{0.0};  // m, world
    double radius = 0;         // m
    double flow = 0;           // m^3/s
  };
  std::optional<Landing> landing() const;
  // m^3 so far: emitted, absorbed at the target, and in the air now.
  double emitted_volume() const { return emitted_.value(); }
  double arrived_volume() const { return arrived_.value(); }
  double in_flight_volume() const;

  static constexpr double kStep = 1.0 / 240.0;
  // The most parcels emitted in one step (a very thin, fast stream is drawn sparser:
  // it would break into drops anyway).
  static constexpr int kMaxPerStep = 64;
  // Over a lip: the parcels side by side across the sheet (its strips). Twenty-four: with
  // twelve the sheet's strips showed as ribs across a room (docs/POINT_CLOUDS.md).
  static constexpr int kAcross = 24;

 private:
  // A Neumaier-compensated sum.
  struct Sum {
    double s = 0, c = 0;
    void add(double x);
    double value() const { return s + c; }
  };
  // How a slice of a sheet leaves a lip: its strips' offsets from the middle (closing
  // linearly to 0 at `close` s after launch), their shares of the flow and spacing.
  struct SheetShape {
    std::vector<glm::dvec3> spread;  // m
    std::vector<double> share;       // summing to 1
    double gap = 0;                  // m
    double close = 0;                // s
  };
  struct Parcel {
    double born;         // s
    glm::dvec3 origin;   // m (a sheet's middle)
    glm::dvec3 launch;   // m/s
    double volume;       // m^3
    double flow;         // m^3/s it was emitted with
    double interval;     // s to the next parcel emitted
    std::shared_ptr<const SheetShape> sheet;  // null: from a spout
  };
  glm::dvec3 at(const Parcel&, double t) const;
  glm::dvec3 velocity_of(const Parcel&, double t) const;
  double flow_integral(double a, double b) const;
  void step();
  void emit_from_spout(double t0, double t1, double q_max);
  void emit_over_lip(double t0, double t1, double q_max);
  void emit_slices(double t0, double t1, int n, glm::dvec3 origin, glm::dvec3 launch, glm::dvec3 e1, glm::dvec3 e2,
                   const std::shared_ptr<const SheetShape>& sheet);
  double fastest_speed(double launch_speed, double from_height) const;

  StreamParams p_;
  glm::dvec3 origin_, velocity_;
  std::optional<StreamLip> lip_;
  double target_;
  std::vector<std::pair<double, double>> schedule_;  // (from t, q), sorted by t
  std::vector<Parcel> parcels_;
  Sum emitted_, arrived_;
  long steps_ = 0;
  double pending_ = 0;
};

}  // namespace draught
