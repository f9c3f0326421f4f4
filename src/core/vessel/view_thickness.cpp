#include "core/vessel/view_thickness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace draught {

namespace {
constexpr double kFar = std::numeric_limits<double>::infinity();

// The roots of |p.xz + t d.xz| = r along the line (false: it misses the cylinder).
bool cylinder_roots(const glm::dvec3& p, const glm::dvec3& d, double r, double& t0, double& t1) {
  const double a = d.x * d.x + d.z * d.z, b = p.x * d.x + p.z * d.z, c = p.x * p.x + p.z * p.z - r * r;
  const double disc = b * b - a * c;
  if (a < 1e-12 || disc < 0) return false;
  const double s = std::sqrt(disc);
  t0 = (-b - s) / a;
  t1 = (-b + s) / a;
  return true;
}
}  // namespace

double view_thickness(const Vessel& v, const glm::dvec3& p, const glm::dvec3& d, contract::Material m) {
  using M = contract::Material;
  const double y = std::clamp(p.y, 0.0, v.height);
  const double ro = v.outer_radius(y), ri = v.inner_radius(y);
  double t0, t1;
  if (m == M::Rim) {  // the bead's sphere about its circle's point nearest p
    const double r = std::hypot(p.x, p.z);
    const glm::dvec3 c = r > 0 ? glm::dvec3(p.x / r * v.rim_major, v.height, p.z / r * v.rim_major)
                               : glm::dvec3(0, v.height, 0);
    return std::max(2.0 * glm::dot(c - p, d), 0.0);
  }
  if (m == M::GlassBottom || m == M::CavityFloor || p.y < v.base) {  // solid glass
    double t = cylinder_roots(p, d, ro, t0, t1) ? std::max(t1, 0.0) : kFar;
    if (d.y > 1e-12) t = std::min(t, (v.base - p.y) / d.y);
    if (d.y < -1e-12) t = std::min(t, -p.y / d.y);
    return std::isfinite(t) ? std::max(t, 0.0) : 0.0;
  }
  if (m == M::GlassInner) return cylinder_roots(p, d, ro, t0, t1) ? std::max(t1, 0.0) : 0.0;
  if (m == M::GlassOuter || m == M::ClipGlass) {
    if (ri > 0 && cylinder_roots(p, d, ri, t0, t1) && t0 > 0) return t0;  // into the cavity
    return cylinder_roots(p, d, ro, t0, t1) ? std::max(t1, 0.0) : 0.0;    // along the wall
  }
  return 0.0;
}

}  // namespace draught
