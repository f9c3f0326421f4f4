// How the glass moves: its pose in the world and the motion sample every input driver
// produces (mouse, touch, device gyro, gamepad, scripted timeline). The simulation
// reads only MotionSamples, so any driver can move the drink.
#pragma once

#include "core/vessel/vessel.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace draught {

// The vessel's rigid pose: p_world = orientation * p_local + position. The local frame is
// the glass's own (axis = +Y, foot at y = 0); world +Y is up (against gravity).
struct Pose {
  glm::dquat orientation{1, 0, 0, 0};
  glm::dvec3 position{0.0};
};

struct MotionSample {
  double time = 0;                      // seconds
  Pose pose;                            // where the glass is at `time`
  glm::dvec3 angular_velocity{0.0};     // world frame, rad/s
  glm::dvec3 linear_acceleration{0.0};  // of pose.position, world frame, m/s^2, gravity excluded
  // A droplets object's pointer in its plane (core/droplets/trail.hpp), when the input
  // gives one; none: the trail follows the last pointer it had.
  std::optional<glm::dvec2> pointer;
};

// Angle between the glass axis and world up, radians in [0, pi].
double tilt_angle(const glm::dquat& orientation);
// The orientation that tilts the upright glass by `tilt` radians towards the horizontal
// direction `azimuth` (radians from +X towards +Z), after spinning it by `spin` about its axis.
glm::dquat tilt_orientation(double tilt, double azimuth, double spin = 0);
// Where the glass stands when it is tipped on a table: rotated about the point of its foot
// rim that stays on the floor, so no part of the foot sinks below y = 0.
Pose tipped_on_floor(const glm::dquat& orientation, double foot_radius);

// Finite, bounded motion: NaN/Inf components become 0 (identity for the orientation),
// angular velocity is limited to max_rate rad/s and acceleration to max_accel m/s^2.
// How far the lowest point of the glass lies below its own origin (the middle of the
// foot) when it is turned by `orientation`: the lowest of the outer profile's rings (the
// wall is straight between them) and of the rim bead.
double reach_below_origin(const glm::dquat& orientation, const Vessel&);
// The pose lifted just enough that no part of the glass is below the floor (y = 0): a
// glass turned about the middle of its foot (the mouse, the gyro) comes to rest on the
// edge of its foot; one held above the floor stays there.
Pose resting_on_floor(Pose, const Vessel&);

MotionSample sanitize(const MotionSample&, double max_rate = 60.0, double max_accel = 200.0);

// The motion sample at time t of a smooth scripted path of poses (a timeline, a glass set
// back down): angular velocity and acceleration by central differences over +-1 ms.
template <class PoseAt>
MotionSample sample_path(double t, const PoseAt& pose_at);

template <class PoseAt>
MotionSample sample_path(double t, const PoseAt& pose_at) {
  constexpr double h = 1e-3;
  MotionSample m;
  m.time = t;
  m.pose = pose_at(t);
  const Pose before = pose_at(t - h), after = pose_at(t + h);
  const glm::dquat dq = after.orientation * glm::inverse(before.orientation);
  const double angle = 2.0 * std::acos(std::clamp(std::abs(dq.w), 0.0, 1.0));
  const glm::dvec3 axis(dq.x, dq.y, dq.z);
  if (glm::length(axis) > 1e-15) m.angular_velocity = glm::normalize(axis) * (dq.w < 0 ? -angle : angle) / (2 * h);
  m.linear_acceleration = (after.position - 2.0 * m.pose.position + before.position) / (h * h);
  return sanitize(m);
}

}  // namespace draught
