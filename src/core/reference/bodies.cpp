#include "core/reference/bodies.hpp"

#include "core/droplets/field.hpp"
#include "core/math/random.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/pointcloud/glow_light.hpp"
#include "core/reference/optics.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

MarchedBodies::MarchedBodies(const FrameState& f, bool smooth) : frame_(f) {
  if (!f.droplets.empty() && !droplet_bounds(f.droplets.front().field).empty) {
    droplets_ = f.droplets.front();
    if (smooth) droplets_->field.noise_amplitude = 0;
  }
  clouds_.update(f.clouds);
  for (size_t c = 0; c < std::min(f.clouds.size(), clouds_.ranges().size()); ++c)
    cloud_refs_.push_back(cloud_ref(clouds_.ranges()[c], f.clouds[c].threshold));
}

Hit MarchedBodies::nearest(const SceneGeometry& geo, const Ray& ray, double eps, MediumKind medium, int obj,
                           glm::dvec4& attrs) const {
  if (medium == MediumKind::Glass || medium == MediumKind::Liquid) return first_hit(geo, ray, eps);
  Hit h;
  if (medium == MediumKind::Air) h = first_hit(geo, ray, eps);
  march(ray, medium, obj, h, attrs);
  return h;
}

void MarchedBodies::march(const Ray& ray, MediumKind medium, int obj, Hit& h, glm::dvec4& attrs) const {
  if (droplets_ && (medium == MediumKind::Air || medium == MediumKind::Droplet)) {
    if (const auto d = march_droplets(droplets_->field, ray.o, ray.d, kBodyMarchEps, h.t, medium == MediumKind::Droplet))
      h = {d->t, d->n, Material::Droplet, -1};
  }
  for (size_t c = 0; c < cloud_refs_.size(); ++c) {
    const bool own = medium == MediumKind::Cloud && int(c) == obj;
    if (medium != MediumKind::Air && !own) continue;
    const auto k = march_cloud(clouds_.texels(), cloud_refs_[c], glm::vec3(ray.o), glm::vec3(ray.d),
                               float(kBodyMarchEps), float(h.t), own);
    if (k && k->t < h.t) {
      h = {double(k->t), glm::dvec3(k->n), Material::Cloud, int(c)};
      attrs = glm::dvec4(k->attrs);
    }
  }
}

bool MarchedBodies::cross(const Hit& h, const glm::dvec4& attrs, Ray& ray, MediumKind& medium, int& obj,
                          glm::dvec3& thr, Rng& rng) const {
  const bool droplet = h.m == Material::Droplet;
  const double ior = droplet ? double(droplets_->params.ior) : double(frame_.clouds[size_t(h.object)].ior);
  const bool inside = medium != MediumKind::Air;
  const glm::dvec3 hn = glm::length(h.n) > 0 ? h.n : -ray.d;  // (a march out of steps inside gives none)
  const glm::dvec3 n = glm::dot(hn, ray.d) < 0 ? hn : -hn;
  const double n1 = inside ? ior : 1.0, n2 = inside ? 1.0 : ior;
  const double F = fresnel_dielectric(-glm::dot(n, ray.d), n1, n2);
  ray.o = ray.at(h.t);
  const MediumKind before = medium;
  const MediumKind next = inside ? MediumKind::Air : (droplet ? MediumKind::Droplet : MediumKind::Cloud);
  const bool reflected = fresnel_turn(ray, n, n1, n2, F, rng.uniform(), next, h.object, medium, obj);
  const glm::dvec3 tint(attrs.y, attrs.z, attrs.w);  // 0: the points give no colour
  if (medium != before && max_component(tint) > 0) thr *= tint;
  return reflected;
}

void MarchedBodies::chord(MediumKind medium, int obj, double t, double kelvin, glm::dvec3& thr, glm::dvec3& L) const {
  if (medium == MediumKind::Droplet) {
    thr *= glm::exp(-glm::dvec3(droplets_->params.absorption) * t);
    return;
  }
  const CloudFrame& cf = frame_.clouds[size_t(obj)];
  if (!(kelvin > 0)) kelvin = cf.temperature;
  const double kappa = hot_glass_extinction(kelvin, double(cf.glow_depth));
  const double hot = std::exp(-kappa * t);
  if (cf.glow > 0 && hot < 1) L += thr * (1 - hot) * double(cf.glow) * kGlowPerNit * glow_table(kelvin);
  thr *= glm::exp(-glm::dvec3(cf.absorption) * t) * hot;
}

std::vector<MarchedBodies::Bound> MarchedBodies::bounds() const {
  std::vector<Bound> out;
  auto put = [&out](const glm::dvec3& lo, const glm::dvec3& hi, bool cloud = false) {
    out.push_back({0.5 * (lo + hi), 0.5 * glm::length(hi - lo), cloud});
  };
  if (droplets_) {
    const DropletBounds b = droplet_bounds(droplets_->field);
    put(b.lo, b.hi);
  }
  for (size_t c = 0; c < cloud_refs_.size(); ++c) {
    const std::vector<BvhNode>& nodes = clouds_.tree(c).nodes;
    if (nodes.empty()) continue;
    // The largest box split into its children until there are enough (or only leaves).
    auto size = [&nodes](int i) { return glm::length(glm::dvec3(nodes[size_t(i)].hi - nodes[size_t(i)].lo)); };
    std::vector<int> cut{0};
    while (int(cut.size()) < kBoundsPerCloud) {
      int widest = -1;
      for (size_t k = 0; k < cut.size(); ++k)
        if (!nodes[size_t(cut[k])].leaf() && (widest < 0 || size(cut[k]) > size(cut[size_t(widest)]))) widest = int(k);
      if (widest < 0) break;
      const int node = cut[size_t(widest)];
      cut[size_t(widest)] = node + 1;  // the left child
      cut.push_back(nodes[size_t(node)].index);
    }
    for (int i : cut) put(glm::dvec3(nodes[size_t(i)].lo), glm::dvec3(nodes[size_t(i)].hi), true);
  }
  return out;
}

}  // namespace draught
