#include "core/environment/paper_bounce.hpp"

#include "core/environment/backdrop_light.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

constexpr double kReach = 3.0;   // m round the aim, across, in front and up the wall
constexpr int kGatherRings = 6, kGatherSpokes = 12;  // the directions gathered round a point's normal
constexpr int kRounds = 3;

// One of the map's layers at (x, s), bilinear (SweepGrid).
glm::dvec3 layer_at(const PaperBounceMap& m, const std::vector<glm::dvec3>& v, const glm::dvec2& xs) {
  return m.bilinear(xs, [&](int a, int c) { return v[size_t(c) * size_t(m.width) + size_t(a)]; });
}

// The rig's light at x (normal n) with each light taken as a point: for paper beyond the
// map's reach, metres from lights a fraction of a metre wide (a few per cent off there).
glm::dvec3 far_light(const LightRig& rig, const glm::dvec3& x, const glm::dvec3& n) {
  glm::dvec3 e(0.0);
  for (const AreaLight& l : rig.lights) {
    const glm::dvec3 to = l.center - x;
    const double d2 = glm::dot(to, to), d = std::sqrt(d2);
    const glm::dvec3 dir = to / d;
    const double facing = l.shape == LightShape::Rect ? std::max(0.0, -glm::dot(l.normal, dir)) : 1.0;
    e += l.radiance * (l.area() * (l.shape == LightShape::Rect ? 1.0 : 0.25) * facing * std::max(0.0, glm::dot(n, dir)) / d2);
  }
  return e;
}

bool inside(const PaperBounceMap& m, const glm::dvec2& xs) {
  return xs.x >= m.origin.x && xs.y >= m.origin.y && xs.x <= m.origin.x + m.size.x && xs.y <= m.origin.y + m.size.y;
}

}  // namespace

glm::dvec3 PaperBounceMap::at(const BackdropSurface& b, const glm::dvec3& p) const {
  return empty() ? glm::dvec3(0.0) : layer_at(*this, bounce, backdrop_coords(b, p));
}

PaperBounceMap paper_bounce_map(const LightRig& rig, const BackdropSurface& b, const SkyIrradiance& sky,
                                const glm::dvec3& aim) {
  PaperBounceMap map;
  if (!b.present) return map;
  const double half_pi = 0.5 * std::numbers::pi;
  const double s_lo = b.z_curve - (aim.z + kReach);
  const double s_hi = b.plane ? b.z_curve - (aim.z - kReach) : b.radius * half_pi + (kReach - b.radius);
  map.width = map.height = kPaperBounceTexels;
  map.size = {2 * kReach, s_hi - s_lo};
  map.origin = {aim.x - kReach, s_lo};
  const size_t count = size_t(map.width) * size_t(map.height);
  std::vector<glm::dvec3> points(count), normals(count);
  map.rig.resize(count);
  map.bounce.resize(count);
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      const size_t k = size_t(j) * size_t(map.width) + size_t(i);
      points[k] = backdrop_point(b, map.texel_centre(i, j), normals[k]);
      map.rig[k] = rig.irradiance(points[k], normals[k]);
      map.bounce[k] = sky.at(normals[k]);
    }

  // One round: each texel gathers the sky and the paper lit by the last round's bounce
  // (the first, by the sky alone).
  std::vector<glm::dvec3> next(count);
  auto gather = [&](size_t k) {
    const glm::dvec3 n = normals[k], from = points[k] + 1e-6 * n;
    // A cosine-weighted grid of the hemisphere round n: each direction carries pi / count.
    const glm::dvec3 u = std::abs(n.y) < 0.9 ? glm::normalize(glm::cross(n, glm::dvec3(0, 1, 0)))
                                             : glm::normalize(glm::cross(n, glm::dvec3(1, 0, 0)));
    const glm::dvec3 v = glm::cross(n, u);
    const double weight = std::numbers::pi / (kGatherRings * kGatherSpokes);
    glm::dvec3 e = sky.at(n);
    for (int i = 0; i < kGatherRings; ++i)
      for (int j = 0; j < kGatherSpokes; ++j) {
        const double r2 = (i + 0.5) / kGatherRings, r = std::sqrt(r2), phi = 2 * std::numbers::pi * (j + 0.5) / kGatherSpokes;
        const glm::dvec3 d = r * std::cos(phi) * u + r * std::sin(phi) * v + std::sqrt(1 - r2) * n;
        double t;
        glm::dvec3 m;
        if (!b.intersect(from, d, 0.0, t, m)) continue;
        const glm::dvec3 q = from + t * d;
        const glm::dvec2 xs = backdrop_coords(b, q);
        const glm::dvec3 lit = (inside(map, xs) ? layer_at(map, map.rig, xs) : far_light(rig, q, m)) + layer_at(map, map.bounce, xs);
        e += (b.albedo(q) / std::numbers::pi * lit - sky.radiance(d)) * weight;
      }
    next[k] = glm::max(e, glm::dvec3(0.0));
  };
  const int lanes = sweep_grid_lanes();
  for (int round = 0; round < kRounds; ++round) {
    in_lanes(lanes, [&](int t) {
      for (size_t k = size_t(t); k < count; k += size_t(lanes)) gather(k);
    });
    map.bounce.swap(next);
  }
  return map;
}

}  // namespace draught
