// How the glass moves: its pose in the world and the motion sample every input driver
// produces (mouse, touch, device gyro, gamepad, scripted timeline). The simulation
// reads only MotionSamples, so any driver can move the drink.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

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
MotionSample sanitize(const MotionSample&, double max_rate = 60.0, double max_accel = 200.0);

}  // namespace draught
