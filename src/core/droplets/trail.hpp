// The pointer trail: a chain of spheres that follows a pointer, each sphere pulled by a
// damped spring towards the one before it (the head towards the pointer), so the trail
// stretches behind a moving pointer and snaps back, overshooting a little, when it
// stops; where the spheres spread apart the smooth minimum splits the droplet, where
// they gather it merges them. Fixed steps (Simulation::kStep), semi-implicit Euler:
// deterministic. The trail lies in its object's plane: through the placement, facing
// +z turned by the yaw (x right, y up, metres from the placement).
#pragma once

#include "core/droplets/droplets.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

class DropletTrail {
 public:
  explicit DropletTrail(const DropletParams& = {}, glm::dvec2 pointer = glm::dvec2(0.0));
  // New parameters; a different count starts the trail again, gathered at the head.
  void set_params(const DropletParams&);
  // One step of kStep towards the pointer (plane coordinates, m); a pointer that is not
  // finite is ignored (the trail goes on towards the last one), one farther than 10 m
  // from the placement is held at 10 m.
  void step(glm::dvec2 pointer);
  double time() const { return time_; }
  void skip_to(double t) { time_ = t; }
  glm::dvec2 pointer() const { return pointer_; }
  const std::vector<glm::dvec2>& positions() const { return x_; }
  const std::vector<glm::dvec2>& velocities() const { return v_; }
  // The spheres in the world for a placement (position, yaw in degrees).
  std::vector<DropletSphere> spheres(glm::vec3 position, float yaw) const;
  // Sphere i's radius.
  double radius(int i) const;

  static constexpr double kStep = 1.0 / 240.0;

 private:
  DropletParams params_;
  std::vector<glm::dvec2> x_, v_;
  glm::dvec2 pointer_{0.0};
  double time_ = 0;
};

// The world point of plane coordinates q, and the plane coordinates of the world point p
// (projected onto the plane), for a placement.
glm::dvec3 droplet_plane_point(glm::vec3 position, float yaw, glm::dvec2 q);
glm::dvec2 droplet_plane_coords(glm::vec3 position, float yaw, glm::dvec3 p);
// Where the ray o + t d meets the trail's plane, as plane coordinates (false: parallel or
// behind the eye).
bool droplet_plane_hit(glm::vec3 position, float yaw, glm::dvec3 o, glm::dvec3 d, glm::dvec2& q);

}  // namespace draught
