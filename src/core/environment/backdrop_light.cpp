#include "core/environment/backdrop_light.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
constexpr double kHalfPi = std::numbers::pi / 2;
}

glm::dvec2 backdrop_coords(const BackdropSurface& b, const glm::dvec3& p) {
  if (b.plane || p.z >= b.z_curve) return {p.x, b.z_curve - p.z};  // the floor
  if (p.y >= b.radius) return {p.x, b.radius * kHalfPi + (p.y - b.radius)};          // the wall
  return {p.x, b.radius * std::atan2(b.z_curve - p.z, b.radius - p.y)};              // the curve
}

glm::dvec3 backdrop_point(const BackdropSurface& b, const glm::dvec2& xs, glm::dvec3& n) {
  const double x = xs.x, s = xs.y, r = b.radius;
  if (b.plane || s <= 0) {
    n = {0, 1, 0};
    return {x, 0, b.z_curve - s};
  }
  if (s >= r * kHalfPi) {
    n = {0, 0, 1};
    return {x, r + (s - r * kHalfPi), b.z_curve - r};
  }
  const double phi = s / r;
  n = {0, std::cos(phi), std::sin(phi)};
  return {x, r - r * std::cos(phi), b.z_curve - r * std::sin(phi)};
}

bool BackdropLightMap::covers(const glm::dvec2& xs) const {
  if (empty()) return false;
  const glm::dvec2 uv = (xs - origin) / size * glm::dvec2(width, height);
  return uv.x >= 0.5 && uv.y >= 0.5 && uv.x <= width - 0.5 && uv.y <= height - 0.5;
}

double BackdropLightMap::untrusted_fraction() const {
  if (trusted.empty()) return 0;
  return double(std::count(trusted.begin(), trusted.end(), 0.0f)) / double(trusted.size());
}

glm::dvec4 BackdropLightMap::sample(const glm::dvec2& xs) const {
  return bilinear(xs, [this](int a, int b) {
    const size_t k = size_t(b) * size_t(width) + size_t(a);
    return glm::dvec4(glm::dvec3(irradiance[k]), trusted[k]);
  });
}

BackdropLightMap compute_backdrop_light(const LightRig& rig, const BackdropSurface& b, const glm::dvec3& aim,
                                        const BackdropLightSettings& s) {
  BackdropLightMap map;
  if (!b.present || rig.lights.empty()) return map;
  // s from `front` in front of the aim to `up` up the wall (the checker: as far behind).
  const double s_lo = b.z_curve - (aim.z + s.front);
  const double s_hi = b.plane ? b.z_curve - (aim.z - s.front) : b.radius * kHalfPi + (s.up - b.radius);
  const glm::dvec2 lo(aim.x - s.across, s_lo), hi(aim.x + s.across, std::max(s_hi, s_lo + s.texel));
  const glm::dvec2 extent = hi - lo;
  const double coarsest = std::max(extent.x, extent.y) / std::max(s.max_resolution - 2, 1);
  glm::dvec2 texel(std::max(s.texel, coarsest));
  double s0 = lo.y;
  if (!b.plane) {
    // Rows of texel centres at both ends of the curve, where the light's slope along s has
    // a kink (the normal starts and stops turning): no cell filters across one.
    const double curve = b.radius * kHalfPi;
    texel.y = curve / std::ceil(curve / texel.y);
    s0 = -(std::ceil(-lo.y / texel.y - 0.5) + 0.5) * texel.y;
  }
  map.width = std::clamp(int(std::ceil(extent.x / texel.x)), 2, s.max_resolution);
  map.height = std::clamp(int(std::ceil((hi.y - s0) / texel.y)), 2, s.max_resolution);
  map.size = {map.width * texel.x, map.height * texel.y};
  map.origin = {lo.x, s0};
  map.irradiance.resize(size_t(map.width) * size_t(map.height));
  const int threads = sweep_grid_lanes();
  auto rows = [&](int t) {
    for (int j = t; j < map.height; j += threads)
      for (int i = 0; i < map.width; ++i) {
        glm::dvec3 n;
        const glm::dvec3 p = backdrop_point(b, map.texel_centre(i, j), n);
        map.irradiance[size_t(j) * size_t(map.width) + size_t(i)] = glm::vec3(rig.irradiance(p, n));
      }
  };
  in_lanes(threads, rows);

  // Cells (i, j)-(i + 1, j + 1) where filtering errs: checked at the middle and at the
  // middles of the bottom and left edges (the others are a neighbour's).
  const int cw = map.width - 1, ch = map.height - 1;
  std::vector<char> bad(size_t(cw) * size_t(ch), 0);
  auto off = [&](const glm::dvec2& xs, const glm::dvec3& filtered) {
    glm::dvec3 n;
    const glm::dvec3 e = rig.irradiance(backdrop_point(b, xs, n), n);
    const glm::dvec3 err = glm::abs(filtered - e);
    const glm::dvec3 allowed = s.tolerance * e + 1e-6;
    return err.x > allowed.x || err.y > allowed.y || err.z > allowed.z;
  };
  auto cells = [&](int t) {
    for (int j = t; j < ch; j += threads)
      for (int i = 0; i < cw; ++i) {
        auto e = [&](int a, int c) { return glm::dvec3(map.irradiance[size_t(c) * size_t(map.width) + size_t(a)]); };
        const glm::dvec2 c00 = map.texel_centre(i, j), c11 = map.texel_centre(i + 1, j + 1);
        const glm::dvec2 mid = 0.5 * (c00 + c11);
        bad[size_t(j) * size_t(cw) + size_t(i)] =
            off(mid, 0.25 * (e(i, j) + e(i + 1, j) + e(i, j + 1) + e(i + 1, j + 1))) ||
            off({mid.x, c00.y}, 0.5 * (e(i, j) + e(i + 1, j))) || off({c00.x, mid.y}, 0.5 * (e(i, j) + e(i, j + 1)));
      }
  };
  in_lanes(threads, cells);
  // A bad cell and the cells around it (a light's edge the checks just missed) distrust
  // all their corners.
  map.trusted.assign(map.irradiance.size(), 1.0f);
  for (int j = 0; j < ch; ++j)
    for (int i = 0; i < cw; ++i) {
      if (!bad[size_t(j) * size_t(cw) + size_t(i)]) continue;
      for (int tj = std::max(j - s.guard, 0); tj <= std::min(j + 1 + s.guard, map.height - 1); ++tj)
        for (int ti = std::max(i - s.guard, 0); ti <= std::min(i + 1 + s.guard, map.width - 1); ++ti)
          map.trusted[size_t(tj) * size_t(map.width) + size_t(ti)] = 0.0f;
    }
  return map;
}

BackdropLightMap compute_backdrop_light(const FrameState& f, const BackdropLightSettings& s) {
  return compute_backdrop_light(f.lights, f.backdrop, scene_aim(f.vessels), s);
}

double backdrop_light_texel(const FrameState& f, int width, int height, double finest) {
  const CameraBasis cam = camera_basis(f, std::max(width, 1), std::max(height, 1));
  const double distance = std::max(glm::dot(scene_aim(f.vessels) - glm::dvec3(cam.eye), glm::dvec3(cam.forward)), 1e-3);
  const double pixel = 2.0 * distance * double(cam.tan_half_vfov) / double(std::max(height, 1));
  double texel = finest;
  while (2.0 * texel <= std::min(4.0 * pixel, kBackdropLightCoarsestTexel)) texel *= 2.0;
  return texel;
}

std::vector<double> backdrop_light_inputs(const FrameState& f, double texel) {
  std::vector<double> k;
  k.push_back(texel);
  auto put = [&k](auto... xs) { (k.push_back(double(xs)), ...); };
  auto put3 = [&put](const glm::dvec3& v) { put(v.x, v.y, v.z); };
  const BackdropSurface& b = f.backdrop;
  put(b.present ? 1 : 0, int(b.kind), b.z_curve, b.radius);
  put3(scene_aim(f.vessels));
  put(f.lights.lights.size());
  for (const AreaLight& l : f.lights.lights) {
    for (double x : l.numbers()) put(x);
  }
  return k;
}

}  // namespace draught
