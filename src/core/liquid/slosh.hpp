// Sloshing: a small damped model of the drink's surface. The surface's tilt (its slope in
// world x and z) is a damped oscillator pulled towards the level of the effective gravity
// (gravity minus the liquid's acceleration), at the natural frequency of a real glass's
// first sloshing mode. Two wave shapes ride on it: a ring (axisymmetric) and a cross
// (the two m = 2 modes), excited by how fast that level changes (a shake, a jolt) and
// decaying on their own. Below a tiny energy everything snaps to rest: no endless jitter.
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

namespace draught {

struct SloshState {
  glm::dvec2 slope{0.0}, slope_rate{0.0};  // surface normal ~ normalize(slope.x, 1, slope.y)
  double ring = 0, ring_rate = 0;          // metres at the centre
  glm::dvec2 cross{0.0}, cross_rate{0.0};  // metres at the wall
};

struct SloshEnvironment {
  glm::dvec2 level_slope{0.0};  // where the surface would rest under the current acceleration
  glm::dvec2 level_rate{0.0};   // d(level_slope)/dt: what excites the waves
  double radius = 0.04;         // of the surface (inner wall radius at the level)
  double depth = 0.1;           // of the liquid
  double max_slope = 1.0;       // the surface may not tilt further (spill / rim)
  double max_wave = 0.01;       // nor may waves rise higher, metres
};

// Natural angular frequency of the first sloshing mode of an upright cylinder:
// omega^2 = g xi / R tanh(xi H / R), xi = 1.8412 (first root of J1').
double slosh_frequency(double radius, double depth, double root = 1.8412);

// One fixed step of the model (semi-implicit Euler; stable for the clamped parameters).
void step_slosh(SloshState&, const LiquidParams&, const SloshEnvironment&, double dt);
// Kinetic + potential energy per unit mass-ish, for tests and settling.
double slosh_energy(const SloshState&, const LiquidParams&, const SloshEnvironment&);
bool at_rest(const SloshState&);

// The waves as the renderer draws them, in the glass's local frame: height above the
// surface plane at (x, z). With u = (x, z) / radius, the ring is 1 - 3u^2 + 1.5u^4 (zero
// mean over the disk, flat at the wall) and the cross is u^2 cos 2a, u^2 sin 2a (zero
// mean too): waves move no volume. Where a pour's stream plunges in, the surface dips
// under it: -depth (1 - s^2) exp(-s^2), s the distance from dimple_xz in dimple radii, a
// hollow with a low raised ring round it that moves no volume either (its integral over
// the plane is 0).
struct SurfaceWaves {
  double ring = 0;
  glm::dvec2 cross{0.0};
  double radius = 1;
  glm::dvec2 dimple_xz{0.0};
  double dimple_radius = 0, dimple_depth = 0;  // m; depth 0: none
  bool flat() const { return ring == 0 && cross.x == 0 && cross.y == 0 && !(dimple_depth > 0); }
  double height(double x, double z) const;
  glm::dvec2 gradient(double x, double z) const;  // d(height)/dx, d(height)/dz
};

}  // namespace draught
