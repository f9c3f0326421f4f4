#include "core/environment/backdrop.hpp"

#include <cmath>

namespace draught {

bool BackdropSurface::intersect(const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t, glm::dvec3& n) const {
  if (!present) return false;
  t = INFINITY;
  // The floor: the whole plane when `plane`, in front of the curve for the sweep.
  if (d.y < 0) {
    const double tf = -o.y / d.y;
    if (tf > tmin && (plane || o.z + tf * d.z >= z_curve)) {
      t = tf;
      n = {0, 1, 0};
    }
  }
  if (plane) return std::isfinite(t);
  // The wall above the curve.
  const double z_wall = z_curve - radius;
  if (d.z < 0) {
    const double tw = (z_wall - o.z) / d.z;
    if (tw > tmin && tw < t && o.y + tw * d.y >= radius) {
      t = tw;
      n = {0, 0, 1};
    }
  }
  // The curve: the far crossing of the cylinder (the scene lies inside it there).
  const double oy = o.y - radius, oz = o.z - z_curve;
  const double a = d.y * d.y + d.z * d.z, b = oy * d.y + oz * d.z, c = oy * oy + oz * oz - radius * radius;
  const double disc = b * b - a * c;
  if (a > 1e-18 && disc >= 0) {
    const double tc = (-b + std::sqrt(disc)) / a;
    const double y = oy + tc * d.y, z = oz + tc * d.z;  // relative to the cylinder's axis
    if (tc > tmin && tc < t && y <= 0 && z <= 0) {
      t = tc;
      n = glm::normalize(glm::dvec3(0, -y, -z));
    }
  }
  return std::isfinite(t);
}

glm::dvec3 BackdropSurface::albedo(const glm::dvec3& p) const {
  if (kind == Backdrop::Sweep) return sweep_albedo;
  const double cx = std::floor(p.x / checker_size), cz = std::floor(p.z / checker_size);
  const bool light_square = std::fmod(std::fmod(cx + cz, 2.0) + 2.0, 2.0) < 0.5;
  return light_square ? floor_a : floor_b;
}

BackdropSurface backdrop_surface(const EnvParams& e, const glm::dvec3& aim) {
  BackdropSurface b;
  b.present = e.floor;
  b.kind = Backdrop(e.backdrop);
  b.z_curve = aim.z - double(e.sweep_distance);
  b.plane = b.kind == Backdrop::Checker || e.mode == int(EnvMode::Image);
  b.radius = e.sweep_radius;
  b.sweep_albedo = glm::dvec3(e.sweep_color);
  b.checker_size = e.checker_size;
  b.floor_a = glm::dvec3(e.floor_a);
  b.floor_b = glm::dvec3(e.floor_b);
  return b;
}

}  // namespace draught
