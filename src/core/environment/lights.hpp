// The studio's area lights in C++: where each light of the rig (light, strips, backlight)
// stands, what radiance it has, how much light it gives a surface (exact, unoccluded) and
// how a path samples it. The reference path tracer and the floor's shadows and caustics
// use these; the picture's twin is shaders/lib/environment/lights.glsl.
//
// Units are physical: a light's power is its radiant flux in watts; a uniform Lambertian
// emitter of area A then has radiance L = power / (pi A) from one side (a rect), or
// power / (4 pi^2 r^2) over a sphere of radius r. A bigger softbox of the same power is
// dimmer and softer, and gives as much light.
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace draught {

// One area light: a uniform Lambertian emitter in the world. A rect emits from its front
// (the side `normal` points to) and is not seen from behind; a sphere emits all round.
// Lights are emitters only: they cast no shadow themselves.
struct AreaLight {
  LightShape shape = LightShape::Rect;
  glm::dvec3 center{0.0};
  glm::dvec3 normal{0, 0, 1};           // rect: the side it emits to (unit)
  glm::dvec3 half_u{0.0}, half_v{0.0};  // rect: half its width and half its height, in its plane
  double radius = 0;                    // sphere
  glm::dvec3 radiance{0.0};             // W / (sr m^2), per colour channel
  bool camera_visible = true;           // seen by the camera's own rays (LightParams::camera_visible)

  double area() const;
  bool emits() const;  // some radiance over some area
  // Every number of the light (shape, place, size, radiance), for the keys of what is
  // computed from the lights (backdrop_light_inputs, floor_light_inputs).
  std::array<double, 17> numbers() const;
  // The nearest t > tmin where the ray o + t d (d unit) meets the light's emitting side.
  bool intersect(const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t) const;
  // The irradiance the whole light gives point x of a surface of unit normal n, per unit
  // radiance, with nothing in between (pi times the form factor). Exact for a rect (its
  // polygon clipped to the surface's hemisphere, Lambert's formula) and for a sphere
  // (Snyder's formula, the horizon included). Zero behind a rect.
  double irradiance_factor(const glm::dvec3& x, const glm::dvec3& n) const;
  // A direction from x towards the light: a rect uniform in its area, a sphere uniform in
  // the cone it subtends. pdf is per solid angle at x. False when x cannot see it.
  struct Sample {
    glm::dvec3 dir{0.0};
    double dist = 0, pdf = 0;
  };
  bool sample_from(const glm::dvec3& x, double u1, double u2, Sample& s) const;
  // The density (solid angle at x) with which sample_from chooses direction d (unit).
  double pdf_from(const glm::dvec3& x, const glm::dvec3& d) const;
  // A point on the emitting surface, uniform in area, and the normal it emits along.
  void sample_point(double u1, double u2, glm::dvec3& p, glm::dvec3& n) const;
};

// The irradiance a sphere of unit radiance gives point x of a surface of unit normal n
// (Snyder's formula, the horizon included; pi inside the sphere): AreaLight's for a
// sphere, and a hot cloud's glow (core/pointcloud/glow_light). Twin of
// sphere_irradiance_factor in shaders/lib/environment/lights.glsl.
double sphere_irradiance_factor(const glm::dvec3& center, double radius, const glm::dvec3& x, const glm::dvec3& n);

// The light of one row group (light, strips, backlight) placed around the scene's centre
// `aim`: `distance` along `direction`, facing `aim`, its width level (a rect's height runs
// up the world's y as far as its tilt allows). `mirror_x` mirrors it across x = aim.x.
AreaLight place_light(const LightParams&, const glm::dvec3& aim, bool mirror_x = false);

inline constexpr size_t kMaxRigLights = 4;  // key, two strips, backlight

struct LightRig {
  glm::dvec3 aim{0.0};
  std::vector<AreaLight> lights;  // only those that emit: key, left and right strip, backlight

  // The irradiance (W/m^2, RGB) the whole rig gives point x of a surface of unit normal n
  // with nothing in between: radiance x irradiance_factor summed over the lights. Twin of
  // rig_irradiance in shaders/lib/environment/lights.glsl.
  glm::dvec3 irradiance(const glm::dvec3& x, const glm::dvec3& n) const;
};

LightRig light_rig(const SceneParams&, const glm::dvec3& aim);
// The same with the backlight placed around `backlight_aim` (the middle of the drinks,
// which it shines through) instead of `aim`.
LightRig light_rig(const SceneParams&, const glm::dvec3& aim, const glm::dvec3& backlight_aim);

}  // namespace draught
