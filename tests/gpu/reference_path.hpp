// The refracted path of a camera ray traced on the CPU in double precision: the same
// rules as the path pass (shaders/passes/path.frag.glsl: trace_path / debug_path_event),
// with core's intersector (first_hit in the air, hit_vessel inside an object), core's
// medium rule (medium_across) and core's optics. Tests compare it with the GPU's
// PathEvent debug view event by event.
#pragma once

#include "core/reference/intersect.hpp"
#include "core/reference/media.hpp"
#include "core/reference/optics.hpp"
#include "core/scene/camera.hpp"
#include "core/scene/frame.hpp"

#include <cmath>
#include <vector>

namespace draught::test {

struct PathEvent {
  double t = 0;  // distance from the previous event
  Material m = Material::None;
  int object = -1;
  MediumKind medium = MediumKind::Air;  // the medium before the surface
  Ray ray;                              // the stretch of the path that ends here
};

// The next surface along r: any object's from the air, else the walls of the object the
// path is inside.
inline Hit next_surface(const SceneGeometry& geo, const Ray& r, MediumKind medium, int object, double tmin) {
  if (medium == MediumKind::Air) return first_hit(geo, r, tmin);
  Hit h = hit_vessel(geo.vessels[size_t(object)], r, tmin);
  h.object = h.valid() ? object : -1;
  return h;
}

// Where the path goes on from surface h at the end of r, travelling in `medium` inside
// `object`: refracted into the medium across it, or reflected where no light crosses
// (total internal reflection). fresnel: the reflected fraction at that surface.
struct PathTurn {
  Ray ray;
  MediumKind medium = MediumKind::Air;
  int object = -1;
  double fresnel = 1;
  bool crossed = false;
};
inline PathTurn turn_at(const FrameState& f, const Hit& h, const Ray& r, MediumKind medium, int object) {
  const glm::dvec3 p = r.at(h.t);
  const VesselFrame& v = f.vessels[size_t(h.object)];
  const glm::dvec3 local = glm::inverse(v.pose.orientation) * (p - v.pose.position);
  const bool below = v.has_liquid && v.liquid.below(local);
  const MediumKind next = medium_across(h.m, medium, below);
  auto ior = [&](MediumKind k) {
    return k == MediumKind::Glass ? double(v.params.glass.ior) : k == MediumKind::Liquid ? double(v.params.liquid.ior) : 1.0;
  };
  const glm::dvec3 n = glm::dot(h.n, r.d) < 0 ? h.n : -h.n;
  const double n1 = ior(medium), n2 = ior(next);
  const double F = fresnel_dielectric(-glm::dot(n, r.d), n1, n2);
  const auto refracted = refract_dir(r.d, n, n1 / n2);
  if (F >= 1.0 || !refracted) return {Ray{p, reflect_dir(r.d, n)}, medium, object, 1.0, false};
  return {Ray{p, glm::normalize(*refracted)}, next, next == MediumKind::Air ? -1 : h.object, F, true};
}

inline std::vector<PathEvent> reference_path(const FrameState& f, const SceneGeometry& geo, Ray r, int max_events) {
  std::vector<PathEvent> events;
  MediumKind medium = MediumKind::Air;
  int object = -1;
  for (int e = 0; e < max_events; ++e) {
    const Hit h = next_surface(geo, r, medium, object, e == 0 ? 0.0 : 2e-6);
    events.push_back({h.valid() ? h.t : 0.0, h.m, h.object, medium, r});
    if (!h.valid() || h.m == Material::Floor) break;
    const PathTurn turn = turn_at(f, h, r, medium, object);
    r = turn.ray;
    medium = turn.medium;
    object = turn.object;
  }
  return events;
}

// Whether the GPU's PathEvent debug pixel (t, material, object, medium) is event c's
// surface, object and medium.
inline bool same_event(const float* px, const PathEvent& c) {
  return int(std::lround(px[1])) == int(c.m) && int(std::lround(px[2])) == c.object &&
         int(std::lround(px[3])) == int(c.medium);
}

// reference_path of every pixel's centre ray of a w x h picture, rows top-down.
inline std::vector<std::vector<PathEvent>> reference_paths(const FrameState& f, const SceneGeometry& geo, int w, int h) {
  const CameraBasis cam = camera_basis(f, w, h);
  std::vector<std::vector<PathEvent>> paths(size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      paths[size_t(y * w + x)] = reference_path(f, geo, camera_ray(cam, x + 0.5, y + 0.5, w, h), f.params.render.max_events);
  return paths;
}

}  // namespace draught::test
