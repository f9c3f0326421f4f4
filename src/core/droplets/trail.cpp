#include "core/droplets/trail.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {
glm::dvec3 plane_x(float yaw) {
  const double a = glm::radians(double(yaw));
  return {std::cos(a), 0.0, -std::sin(a)};
}
glm::dvec3 plane_normal(float yaw) {
  const double a = glm::radians(double(yaw));
  return {std::sin(a), 0.0, std::cos(a)};
}
}  // namespace

glm::dvec3 droplet_plane_point(glm::vec3 position, float yaw, glm::dvec2 q) {
  return glm::dvec3(position) + q.x * plane_x(yaw) + q.y * glm::dvec3(0, 1, 0);
}

glm::dvec2 droplet_plane_coords(glm::vec3 position, float yaw, glm::dvec3 p) {
  const glm::dvec3 r = p - glm::dvec3(position);
  return {glm::dot(r, plane_x(yaw)), r.y};
}

bool droplet_plane_hit(glm::vec3 position, float yaw, glm::dvec3 o, glm::dvec3 d, glm::dvec2& q) {
  const glm::dvec3 n = plane_normal(yaw);
  const double dn = glm::dot(d, n);
  if (std::abs(dn) < 1e-9) return false;
  const double t = glm::dot(glm::dvec3(position) - o, n) / dn;
  if (!(t > 0)) return false;
  q = droplet_plane_coords(position, yaw, o + t * d);
  return true;
}

DropletTrail::DropletTrail(const DropletParams& p, glm::dvec2 pointer) : pointer_(pointer) { set_params(p); }

void DropletTrail::set_params(const DropletParams& p) {
  const bool again = p.count != params_.count || x_.empty();
  params_ = p;
  params_.count = std::clamp(p.count, 1, kMaxDroplets);
  if (again) {
    x_.assign(size_t(params_.count), pointer_);
    v_.assign(size_t(params_.count), glm::dvec2(0.0));
  }
}

void DropletTrail::step(glm::dvec2 pointer) {
  if (std::isfinite(pointer.x) && std::isfinite(pointer.y)) {
    const double len = glm::length(pointer);
    pointer_ = len > 10.0 ? pointer * (10.0 / len) : pointer;
  }
  const double k = std::clamp(double(params_.stiffness), 10.0, 5000.0);
  const double c = std::clamp(double(params_.damping), 0.0, 200.0);
  // The followers' damping is at least sqrt(2 k) (damping ratio 1 / sqrt 2): a stage
  // then passes no frequency amplified, so a wiggle does not grow down a chain of 32
  // (underdamped stages would multiply their resonance, 1 / (2 zeta), stage by stage).
  // The head keeps the damping given: it overshoots the pointer, the elastic snap.
  const double c_follow = std::max(c, std::sqrt(2.0 * k));
  // Semi-implicit Euler, leader first: each sphere follows where the one before it is
  // now. Stable for k dt^2 < 1 (5000 / 240^2 = 0.09).
  for (size_t i = 0; i < x_.size(); ++i) {
    const glm::dvec2 leader = i == 0 ? pointer_ : x_[i - 1];
    const glm::dvec2 a = k * (leader - x_[i]) - (i == 0 ? c : c_follow) * v_[i];
    v_[i] += kStep * a;
    x_[i] += kStep * v_[i];
  }
  time_ += kStep;
}

double DropletTrail::radius(int i) const {
  const int n = int(x_.size());
  const double s = n > 1 ? double(i) / double(n - 1) : 0.0;
  return double(params_.radius) * (1.0 - double(params_.taper) * s);
}

std::vector<DropletSphere> DropletTrail::spheres(glm::vec3 position, float yaw) const {
  std::vector<DropletSphere> out;
  for (size_t i = 0; i < x_.size(); ++i) out.push_back({droplet_plane_point(position, yaw, x_[i]), radius(int(i))});
  return out;
}

}  // namespace draught
