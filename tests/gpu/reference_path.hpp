// The refracted path of a camera ray traced on the CPU in double precision: the same
// rules as the path pass (shaders/passes/path.frag.glsl: trace_path / debug_path_event),
// with core's intersector (first_hit in the air, hit_vessel inside an object), core's
// medium rule (medium_across) and core's optics. Tests compare it with the GPU's
// PathEvent debug view event by event.
#pragma once

#include "core/reference/intersect.hpp"
#include "core/reference/media.hpp"
#include "core/reference/optics.hpp"
#include "core/scene/frame.hpp"

#include <vector>

namespace draught::test {

struct PathEvent {
  double t = 0;  // distance from the previous event
  Material m = Material::None;
  int object = -1;
  MediumKind medium = MediumKind::Air;  // the medium before the surface
  Ray ray;                              // the stretch of the path that ends here
};

inline std::vector<PathEvent> reference_path(const FrameState& f, const SceneGeometry& geo, Ray r, int max_events) {
  std::vector<PathEvent> events;
  MediumKind medium = MediumKind::Air;
  int object = -1;
  for (int e = 0; e < max_events; ++e) {
    const double tmin = e == 0 ? 0.0 : 2e-6;
    Hit h;
    if (medium == MediumKind::Air) {
      h = first_hit(geo, r, tmin);
    } else {
      h = hit_vessel(geo.vessels[size_t(object)], r, tmin);
      h.object = h.valid() ? object : -1;
    }
    events.push_back({h.valid() ? h.t : 0.0, h.m, h.object, medium, r});
    if (!h.valid() || h.m == Material::Floor) break;
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
    const auto refracted = refract_dir(r.d, n, n1 / n2);
    if (fresnel_dielectric(-glm::dot(n, r.d), n1, n2) >= 1.0 || !refracted) {
      r = Ray{p, reflect_dir(r.d, n)};  // total internal reflection
    } else {
      r = Ray{p, glm::normalize(*refracted)};
      medium = next;
      object = next == MediumKind::Air ? -1 : h.object;
    }
  }
  return events;
}

}  // namespace draught::test
