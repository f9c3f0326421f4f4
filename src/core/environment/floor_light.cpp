#include "core/environment/floor_light.hpp"

#include "core/environment/environment_map.hpp"
#include "core/environment/image_patches.hpp"
#include "core/environment/studio.hpp"
#include "core/math/basis.hpp"

#include "core/foam/head_volume.hpp"
#include "core/math/channels.hpp"
#include "core/math/random.hpp"
#include "core/reference/bodies.hpp"
#include "core/reference/decal_optics.hpp"
#include "core/reference/media.hpp"
#include "core/reference/free_flight.hpp"
#include "core/reference/optics.hpp"
#include "core/math/constants.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>
#include <limits>
#include <memory>
#include <string>
#include <thread>

namespace draught {

namespace {

constexpr int kLanes = 4;      // fixed accumulation buffers: the sum does not depend on the thread count
constexpr int kMaxEvents = 64;
constexpr int kGatherStep = 4;  // texels between the surroundings' gathered nodes (1 cm)
constexpr double kKernelScale = 2.0;  // texels per unit of the cubic B-spline (radius 2 units: 4 texels, 1 cm)

// The cubic B-spline (support [-2, 2], a partition of unity over integer shifts).
double bspline3(double t) {
  t = std::fabs(t);
  if (t < 1) return (4 - 6 * t * t + 3 * t * t * t) / 6;
  if (t < 2) return (2 - t) * (2 - t) * (2 - t) / 6;
  return 0;
}

// The radical inverse of k in a prime base: the Halton sequence's coordinate.
double radical_inverse(int base, std::uint64_t k) {
  const double inv = 1.0 / base;
  double f = inv, r = 0;
  for (; k > 0; k /= std::uint64_t(base), f *= inv) r += f * double(k % std::uint64_t(base));
  return r;
}

// The second coordinate of the Sobol' sequence (its first is radical_inverse(2, k)): with
// it every power-of-two prefix of the points is a (0, m, 2)-net, as even as a Hammersley
// set of that many, so a gather spread over batches is even after each of them.
double sobol_second(std::uint32_t k) {
  std::uint32_t r = 0;
  for (std::uint32_t v = 1u << 31; k != 0; k >>= 1, v ^= v >> 1)
    if (k & 1u) r ^= v;
  return double(r) * 0x1.0p-32;
}

// What the photons aim at: the sphere around a glass's bounding cylinder, or around a
// droplet trail's or a cloud's box.
struct Target {
  glm::dvec3 centre{0.0};
  double radius = 0;
};

// The cone of directions from x that holds the sphere: its axis, cos of its half-angle and
// solid angle (the whole sphere of directions when x is inside).
struct Cone {
  glm::dvec3 axis{0, 1, 0};
  double cos_max = -1, solid_angle = 4 * kPi;
  bool contains(const glm::dvec3& d) const { return glm::dot(d, axis) >= cos_max; }
};
Cone cone_towards(const Target& g, const glm::dvec3& x) {
  Cone c;
  const glm::dvec3 to = g.centre - x;
  const double d2 = glm::dot(to, to);
  if (d2 <= g.radius * g.radius) return c;
  c.axis = to / std::sqrt(d2);
  c.cos_max = std::sqrt(1 - g.radius * g.radius / d2);
  c.solid_angle = 2 * kPi * (1 - c.cos_max);
  return c;
}

// Everything the photons need of one vessel.
// One accumulation buffer of the change (W/m^2 per channel).
struct Lane {
  std::vector<glm::dvec3> change;
  FloorLightStats stats;
};

// The world the floor's light is traced in: the studio's, a transparent picture's too (the
// floor its glasses mirror and its reflection panoramas draw is the opaque world's;
// scene_geometry leaves a cutout's backdrop out for the paths that would meet it).
SceneGeometry lit_geometry(const FrameState& f, bool with_decals = false) {
  SceneGeometry g = scene_geometry(f, with_decals);
  g.backdrop.present = f.backdrop.present;
  return g;
}

class PhotonTracer {
 public:
  PhotonTracer(const FrameState& f, const FloorLightMap& map)
      : geo_(lit_geometry(f, true)), bodies_(f, true), map_(map) {  // (with the walls' decals: they cast shadows)
    // The heads without their big bubbles (ignored, as the rising bubbles).
    frames_.reserve(f.vessels.size());
    for (const VesselFrame& vf : f.vessels) {
      frames_.push_back(vf);
      frames_.back().big_bubbles.clear();
      frames_.back().bubbles.clear();
    }
    for (size_t i = 0; i < frames_.size(); ++i) {
      geo_.vessels[i].vessel = &frames_[i].vessel;
      heads_.emplace_back(frames_[i], geo_.vessels[i]);
      media_.push_back(vessel_optics(frames_[i]));
    }
  }

  const MarchedBodies& bodies() const { return bodies_; }

  // The surroundings' light (radiance `around`) arriving at a floor point along the ray
  // back from it (ray.d up): what the objects in its way let through, from where the path
  // through them leaves (the lit paper's as the harmonics hold it where it leaves
  // downwards); nothing in its way, around's radiance along ray.d.
  template <class Around>  // glm::dvec3 around(direction)
  glm::dvec3 arriving(Ray ray, const Around& around, Rng& rng) const {
    glm::dvec4 attrs(0.0);
    const Hit h = bodies_.nearest(geo_, ray, kRestartEps, MediumKind::Air, -1, attrs);
    if (!h.valid() || h.m == Material::Floor) return around(ray.d);
    glm::dvec3 power(1.0);
    const Walk w = follow(ray, power, h, attrs, rng, nullptr);
    return w.end == End::Lost ? glm::dvec3(0.0) : power * around(ray.d);
  }

  // One photon of power `power` leaving x along d (unit).
  void trace(Ray ray, glm::dvec3 power, Rng& rng, Lane& lane) const {
    glm::dvec4 attrs(0.0);  // a cloud's surface: its temperature and colour there
    Hit h = bodies_.nearest(geo_, ray, kRestartEps, MediumKind::Air, -1, attrs);
    if (!h.valid() || h.m == Material::Floor) return;  // its light is the unoccluded one
    lane.stats.hit += power;
    // Where its straight line would have met the backdrop: on the floor, the map's; on the
    // sweep's curve or wall, beyond it (the map holds the floor only).
    double t_open;
    glm::dvec3 n_open;
    if (geo_.backdrop.intersect(ray.o, ray.d, kRestartEps, t_open, n_open) && n_open.y > 0.999) {
      splat(ray.at(t_open), -power, lane);
      lane.stats.removed += power;
    } else {
      lane.stats.escaped -= power;  // what the glass sends there instead is counted as escaped too
    }
    const Walk w = follow(ray, power, h, attrs, rng, &lane.stats);
    if (w.end == End::Landed) {
      splat(w.p, power, lane);
      lane.stats.landed += power;
    } else if (w.end != End::Lost) {
      lane.stats.escaped += power;  // out of the scene, or onto the sweep's curve or wall
    }
  }

  // How a path through the objects ends: out of the scene (along ray.d), on the floor
  // (at p), on the sweep's curve or wall, or lost (absorbed or trapped).
  enum class End { Escaped, Landed, Wall, Lost };
  struct Walk {
    End end = End::Lost;
    glm::dvec3 p{0.0};
  };

  // Follows a path from the air, its first hit h (an object's), with the path tracer's
  // media rules, until it leaves the objects: `ray` is then its last straight line,
  // `power` what is left of it; what the media take is added to stats->absorbed.
  Walk follow(Ray& ray, glm::dvec3& power, Hit h, glm::dvec4& attrs, Rng& rng, FloorLightStats* stats) const {
    const auto absorb = [stats](const glm::dvec3& x) {
      if (stats) stats->absorbed += x;
    };
    MediumKind medium = MediumKind::Air;
    int obj = -1, drink_obj = -1;
    glm::dvec3 drink_left(0.5);  // as the path tracer: the shares of the drink's colour bands
    for (int events = 0;; ++events) {
      if (events > 0) h = bodies_.nearest(geo_, ray, kRestartEps, medium, obj, attrs);
      const double t_end = h.valid() ? h.t : (medium == MediumKind::Air ? kInf : 0.0);
      const glm::dvec3 before = power;
      if (medium == MediumKind::Droplet || medium == MediumKind::Cloud) {
        glm::dvec3 glow(0.0);  // a hot blob's own light is not the lights' (the map holds theirs)
        bodies_.chord(medium, obj, t_end, attrs.x, power, glow);
      } else if (medium == MediumKind::Glass) {
        power *= glm::exp(-media_[size_t(obj)].glass_absorption * t_end);
      } else if (medium == MediumKind::Liquid) {
        if (drink_obj != obj) {  // as the path tracer: a drink it has not crossed yet
          drink_obj = obj;
          drink_left = glm::dvec3(media_[size_t(obj)].drink.colour.share);
        }
        double t_scatter;
        const bool through = liquid_free_flight(media_[size_t(obj)].drink, drink_left, t_end, power, t_scatter, rng);
        absorb(before - power);  // in expectation (the free flight's weights are not per channel)
        if (!through) {
          if (events >= kMaxEvents) {  // scattered too often: what is left is lost
            absorb(power);
            return {End::Lost};
          }
          ray.o = ray.at(t_scatter);
          const double spin = rng.uniform(), cos_t = 1 - 2 * rng.uniform();  // (drawn in this order)
          ray.d = around(ray.d, cos_t, 2 * kPi * spin);  // haze: isotropic
          continue;
        }
      } else {
        power *= head_transmittance(ray, t_end, rng);
      }
      if (medium != MediumKind::Liquid) absorb(before - power);
      if (max_component(power) <= 0) return {End::Lost};
      if (!h.valid()) return {End::Escaped};
      const glm::dvec3 p = ray.at(h.t);
      // The floor, or the floor under a foot the photon leaves through; the backdrop's
      // curve and wall are not the floor: what lands there has left it.
      if (h.m == Material::Floor && h.n.y <= 0.999) return {End::Wall};
      if (h.m == Material::Floor || (p.y < 1e-6 && ray.d.y < 0)) return {End::Landed, p};
      if (events >= kMaxEvents) {  // trapped between surfaces: what is left is lost
        absorb(power);
        return {End::Lost};
      }
      if (h.m == Material::Droplet || h.m == Material::Cloud) {  // water or a blob against the air
        const glm::dvec3 untinted = power;
        bodies_.cross(h, attrs, ray, medium, obj, power, rng);
        absorb(untinted - power);  // a cloud point's colour, where it crossed
        continue;
      }
      const VesselOptics& m = media_[size_t(h.object)];
      const VesselGeometry& vg = geo_.vessels[size_t(h.object)];
      const bool below = vg.liquid.below(m.local_point(p));
      const MediumKind next = medium_across(h.m, medium, below);
      const glm::dvec3 n = glm::dot(h.n, ray.d) < 0 ? h.n : -h.n;
      const double n1 = m.ior(medium), n2 = m.ior(next);
      const double F = fresnel_dielectric(-glm::dot(n, ray.d), n1, n2);
      ray.o = p;
      // A decal on the wall, as the path tracer meets it: from the air under the surface's
      // gloss (Fresnel first), from inside before it. Its ink, frost or metal turns the
      // photon and takes its colour: a logo casts its shadow, tinted.
      double u = rng.uniform();
      const bool wall = h.m == Material::GlassOuter || h.m == Material::GlassInner;
      const DecalSample decal = vg.decals && wall ? vg.decals->sample(*vg.vessel, h.m == Material::GlassInner, m.local_point(p))
                                                  : DecalSample{};
      if (meets_decal(u, F, decal.cover, medium == MediumKind::Air)) {
        const glm::dvec3 untinted = power;
        if (const std::optional<glm::dvec3> side = decal_turn(decal, n, next, h.object, ray, medium, obj, power, rng)) {
          double cos_t;
          ray.d = decal_diffuse_direction(*side, rng, cos_t);
        }
        absorb(untinted - power);
        continue;
      }
      fresnel_turn(ray, n, n1, n2, F, u, next, h.object, medium, obj);
    }
  }

  // Adds power (W) at floor point p with the kernel, as irradiance.
  void splat(const glm::dvec3& p, const glm::dvec3& power, Lane& lane) const {
    const glm::dvec2 texel(map_.size.x / map_.width, map_.size.y / map_.height);
    const double u = (p.x - map_.origin.x) / texel.x - 0.5, v = (p.z - map_.origin.y) / texel.y - 0.5;
    const int reach = int(std::ceil(2 * kKernelScale));
    const int i0 = int(std::floor(u)) - reach + 1, j0 = int(std::floor(v)) - reach + 1;
    constexpr int kTaps = 8;
    double wx[kTaps], wy[kTaps], sx = 0, sy = 0, inx = 0, iny = 0;
    const int taps = std::min(kTaps, 2 * reach);
    for (int k = 0; k < taps; ++k) {
      wx[k] = bspline3((i0 + k - u) / kKernelScale);
      wy[k] = bspline3((j0 + k - v) / kKernelScale);
      sx += wx[k];
      sy += wy[k];
    }
    const glm::dvec3 e = power / (sx * sy * texel.x * texel.y);
    for (int b = 0; b < taps; ++b) {
      const int j = j0 + b;
      if (j < 0 || j >= map_.height || wy[b] <= 0) continue;
      iny += wy[b];
      for (int a = 0; a < taps; ++a) {
        const int i = i0 + a;
        if (i < 0 || i >= map_.width || wx[a] <= 0) continue;
        lane.change[size_t(j) * size_t(map_.width) + size_t(i)] += e * (wx[a] * wy[b]);
      }
    }
    for (int a = 0; a < taps; ++a)
      if (int i = i0 + a; i >= 0 && i < map_.width) inx += wx[a];
    lane.stats.outside += power * (1 - (inx / sx) * (iny / sy));
  }

 private:
  // The heads' transmittance along the air stretch [0, t_end] (ratio tracking: unbiased).
  double head_transmittance(const Ray& ray, double t_end, Rng& rng) const {
    double T = 1;
    for (size_t i = 0; i < heads_.size(); ++i) {
      const HeadVolume& head = heads_[i];
      if (head.empty()) continue;
      const VesselOptics& m = media_[i];
      const glm::dvec3 o = m.local_point(ray.o), d = m.to_local * ray.d;
      double t0 = 0, t1 = t_end;
      if (!head.interval(o, d, t0, t1)) continue;
      T *= draught::head_transmittance(head, o, d, t0, t1, rng);
      if (T <= 0) return 0;
    }
    return T;
  }

  std::vector<VesselFrame> frames_;
  SceneGeometry geo_;
  MarchedBodies bodies_;  // the droplets and the clouds: their shadows and caustics too
  std::vector<HeadVolume> heads_;
  std::vector<VesselOptics> media_;
  const FloorLightMap& map_;
};

// The sphere around a glass's bounding cylinder, as it stands.
Target target_of(const VesselFrame& v) {
  const double half = 0.5 * (v.vessel.height + v.vessel.rim_minor);
  return {v.pose.position + v.pose.orientation * glm::dvec3(0, half, 0), std::hypot(v.vessel.bound_radius, half)};
}

// Points that span a light: a rect's corners and centre, a sphere's extremes.
std::vector<glm::dvec3> light_points(const AreaLight& l) {
  std::vector<glm::dvec3> pts{l.center};
  if (l.shape == LightShape::Sphere) {
    for (int a = 0; a < 3; ++a)
      for (double s : {-1.0, 1.0}) {
        glm::dvec3 o(0.0);
        o[a] = s * l.radius;
        pts.push_back(l.center + o);
      }
  } else {
    for (double su : {-1.0, 1.0})
      for (double sv : {-1.0, 1.0}) pts.push_back(l.center + su * l.half_u + sv * l.half_v);
  }
  return pts;
}

// What casts light and shade on the floor, as the rect sees it: the corners of its box, the
// point of the floor under it, how far its shadow may reach from there, and how far light
// it bends lands beside its shadow.
struct Caster {
  std::array<glm::dvec3, 8> corners;
  glm::dvec2 foot{0.0};
  double reach = 0, spread = 0;
};

// A glass: its bounding cylinder as it stands; its shadow reaches three glass heights.
Caster caster_of(const VesselFrame& v) {
  Caster c;
  const double top = v.vessel.height + v.vessel.rim_minor, b = v.vessel.bound_radius;
  for (int k = 0; k < 8; ++k)
    c.corners[size_t(k)] = v.pose.position + v.pose.orientation * glm::dvec3(k & 1 ? b : -b, k & 2 ? top : 0, k & 4 ? b : -b);
  c.foot = {v.pose.position.x, v.pose.position.z};
  c.reach = 3 * top;
  c.spread = b;
  return c;
}

// A droplet trail or a cloud: the box around its sphere; its shadow reaches three times the
// sphere's top's height.
Caster caster_of(const Target& t) {
  Caster c;
  for (int k = 0; k < 8; ++k)
    c.corners[size_t(k)] = t.centre + t.radius * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
  c.foot = {t.centre.x, t.centre.z};
  c.reach = 3 * std::max(t.centre.y + t.radius, t.radius);
  c.spread = t.radius;
  return c;
}

// The rect of the floor where the casters may change the light: every light point's shadow
// of every corner of every caster, each reaching at most the caster's reach from its foot,
// widened by its spread (light bent by a glass lands beside its shadow).
void place_rect(const std::vector<Caster>& casters, const LightRig& emitters, const FloorLightSettings& s,
                FloorLightMap& map) {
  glm::dvec2 lo(kInf), hi(-kInf);
  for (const Caster& c : casters) {
    const double reach = c.reach, b = c.spread;
    const glm::dvec2 foot = c.foot;
    for (const glm::dvec3& g : c.corners) {
      const glm::dvec2 gxz(g.x, g.z);
      lo = glm::min(lo, gxz - b);
      hi = glm::max(hi, gxz + b);
      for (const AreaLight& l : emitters.lights)
        for (const glm::dvec3& q : light_points(l)) {
          glm::dvec2 away = gxz - glm::dvec2(q.x, q.z);
          const double len = glm::length(away);
          if (len < 1e-9) continue;
          double dist = reach;  // a light at or below the corner: the shadow runs far
          if (q.y > g.y + 1e-6) dist = std::min(reach, len * std::max(g.y, 0.0) / (q.y - g.y));
          const glm::dvec2 shadow = gxz + away / len * dist;
          // Kept within reach of the foot (the corners of a tall glass lean out too).
          glm::dvec2 rel = shadow - foot;
          if (glm::length(rel) > reach + b) rel *= (reach + b) / glm::length(rel);
          // And as far on the light's side: the walls reflect light back towards it.
          for (const glm::dvec2& at : {foot + rel, foot - rel}) {
            lo = glm::min(lo, at - b);
            hi = glm::max(hi, at + b);
          }
        }
    }
  }
  const glm::dvec2 size = hi - lo;
  const double texel = std::max(s.texel, std::max(size.x, size.y) / std::max(s.max_resolution, 1));
  map.width = std::clamp(int(std::ceil(size.x / texel)), 1, s.max_resolution);
  map.height = std::clamp(int(std::ceil(size.y / texel)), 1, s.max_resolution);
  map.size = {map.width * texel, map.height * texel};
  map.origin = 0.5 * (lo + hi) - 0.5 * map.size;
}

// How many photons each (light, glass) pair gets: in proportion to the power the light
// sends into the glass's cone (so photons carry about equal power), at least a few
// hundred wherever the light reaches it at all.
std::vector<int> photon_counts(const LightRig& emitters, const std::vector<Target>& targets, int budget) {
  const size_t L = emitters.lights.size(), G = targets.size();
  std::vector<double> flux(L * G, 0.0);
  double total = 0;
  for (size_t l = 0; l < L; ++l) {
    const AreaLight& light = emitters.lights[l];
    for (size_t g = 0; g < G; ++g) {
      double sum = 0;
      const std::vector<glm::dvec3> pts = light_points(light);
      for (const glm::dvec3& q : pts) {
        const Cone c = cone_towards(targets[g], q);
        const double cos_l = light.shape == LightShape::Sphere ? 1.0 : std::max(0.0, glm::dot(c.axis, light.normal));
        sum += cos_l * c.solid_angle;
      }
      const double proj_area = light.shape == LightShape::Sphere ? kPi * light.radius * light.radius : light.area();
      flux[l * G + g] = channel_mean(light.radiance) * proj_area * sum / double(pts.size());
      total += flux[l * G + g];
    }
  }
  std::vector<int> n(L * G, 0);
  if (total <= 0) return n;
  const int least = std::max(1, budget / int(8 * L * G));
  for (size_t k = 0; k < n.size(); ++k)
    if (flux[k] > 0) n[k] = std::max(least, int(std::lround(budget * flux[k] / total)));
  return n;
}

// Values over a map's texels known at every `step`-th texel (and the last of a row or
// column), bilinear between.
class TexelLattice {
 public:
  TexelLattice(const FloorLightMap& m, int step) : step_(step) {
    for (int i = 0;; i = std::min(i + step, m.width - 1)) {
      xs_.push_back(i);
      if (i == m.width - 1) break;
    }
    for (int j = 0;; j = std::min(j + step, m.height - 1)) {
      ys_.push_back(j);
      if (j == m.height - 1) break;
    }
    values_.assign(xs_.size() * ys_.size(), glm::dvec3(1.0));
  }
  size_t columns() const { return xs_.size(); }
  size_t rows() const { return ys_.size(); }
  int texel_x(size_t a) const { return xs_[a]; }
  int texel_y(size_t b) const { return ys_[b]; }
  glm::dvec3& node(size_t a, size_t b) { return values_[b * xs_.size() + a]; }
  glm::dvec3 at(int i, int j) const {
    const size_t a = std::min(size_t(i / step_), xs_.size() - 1), b = std::min(size_t(j / step_), ys_.size() - 1);
    const size_t a1 = std::min(a + 1, xs_.size() - 1), b1 = std::min(b + 1, ys_.size() - 1);
    const double u = a1 > a ? double(i - xs_[a]) / (xs_[a1] - xs_[a]) : 0.0;
    const double v = b1 > b ? double(j - ys_[b]) / (ys_[b1] - ys_[b]) : 0.0;
    auto value = [&](size_t x, size_t y) { return values_[y * xs_.size() + x]; };
    return glm::mix(glm::mix(value(a, b), value(a1, b), u), glm::mix(value(a, b1), value(a1, b1), u), v);
  }

 private:
  int step_;
  std::vector<int> xs_, ys_;  // the texels where the values are known
  std::vector<glm::dvec3> values_;
};

// The unoccluded light over a map's texels for its factor: exact at every kStep-th texel
// (and the last of a row or column), bilinear between. It is smooth at the texels' scale
// (a softbox's light changes over tens of centimetres; bilinear over 1 cm is off by about
// 1e-3 of it, and the factor by that times the change's share), and a sixteenth of the
// exact evaluations, which were most of a draft's time.
class OpenLightLattice {
 public:
  static constexpr int kStep = 4;
  explicit OpenLightLattice(const FloorLightMap& m) : map_(m), open_(m, kStep) {
    for (size_t b = 0; b < open_.rows(); ++b)
      for (size_t a = 0; a < open_.columns(); ++a) open_.node(a, b) = m.unoccluded(open_.texel_x(a), open_.texel_y(b));
  }
  glm::dvec3 at(int i, int j) const { return map_.even ? map_.even_light : open_.at(i, j); }

 private:
  const FloorLightMap& map_;
  TexelLattice open_;
};

}  // namespace

glm::dvec2 FloorLightMap::texel_centre(int i, int j) const {
  return origin + glm::dvec2((i + 0.5) * size.x / width, (j + 0.5) * size.y / height);
}

glm::dvec3 FloorLightMap::unoccluded(int i, int j) const {
  if (even) return even_light;
  const glm::dvec2 c = texel_centre(i, j);
  return unoccluded_floor_irradiance(lights, {c.x, 0, c.y});
}

glm::dvec3 FloorLightMap::at(int i, int j) const {
  return glm::max(unoccluded(i, j) + glm::dvec3(change[size_t(j) * size_t(width) + size_t(i)]), glm::dvec3(0.0));
}

namespace {
// `at` at world (x, z) over map m's texels, bilinear between texel centres as GL's linear
// filter, clamped to the edge.
template <class At>
glm::dvec3 bilinear(const FloorLightMap& m, double x, double z, const At& at) {
  if (m.empty()) return glm::dvec3(0.0);
  const double u = std::clamp((x - m.origin.x) / m.size.x * m.width - 0.5, 0.0, m.width - 1.0);
  const double v = std::clamp((z - m.origin.y) / m.size.y * m.height - 0.5, 0.0, m.height - 1.0);
  const int i = std::min(int(u), m.width - 2 < 0 ? 0 : m.width - 2), j = std::min(int(v), m.height - 2 < 0 ? 0 : m.height - 2);
  const int i1 = std::min(i + 1, m.width - 1), j1 = std::min(j + 1, m.height - 1);
  const double fu = u - i, fv = v - j;
  const glm::dvec3 a = glm::mix(at(i, j), at(i1, j), fu);
  const glm::dvec3 b = glm::mix(at(i, j1), at(i1, j1), fu);
  return glm::mix(a, b, fv);
}
}  // namespace

glm::dvec3 FloorLightMap::sample(double x, double z) const {
  return bilinear(*this, x, z, [this](int i, int j) { return at(i, j); });
}

glm::dvec3 FloorLightMap::surround_sample(double x, double z) const {
  return bilinear(*this, x, z, [this](int i, int j) { return glm::dvec3(surround_factor[size_t(j) * size_t(width) + size_t(i)]); });
}

namespace {
// Under an image: its patches of the level nearest 32 wide that give the floor the most
// light, the brightest first (none in the studio).
ImagePatches floor_emitter_patches(const FrameState& f) {
  if (!f.environment.image) return {};
  ImagePatches level = image_patches(Studio(f.params), kImageFloorEmitterWidth, true);
  std::vector<ImagePatch>& patches = level.patches;
  const auto floor_light = [](const ImagePatch& p) { return channel_mean(p.radiance) * p.solid_angle * p.dir.y; };
  const size_t keep = std::min(patches.size(), kImageFloorEmitters);
  std::partial_sort(patches.begin(), patches.begin() + long(keep), patches.end(),
                    [&](const ImagePatch& a, const ImagePatch& b) { return floor_light(a) > floor_light(b); });
  size_t n = 0;
  while (n < keep && floor_light(patches[n]) > 0) ++n;
  patches.resize(n);
  return level;
}

// What the floor gathers under an image: the image less the patches the photons trace,
// read at the level twice as fine as the patches' (a patch's four texels), so the two
// parts add up to the image's light, each once; below the horizon, where the image's
// ground is the floor itself, the lit floor as the surroundings' harmonics hold it (what
// a glass mirrors down onto the floor beside it).
class ImageRest {
 public:
  ImageRest(const FrameState& f, const ImagePatches& taken)
      : studio_(f.params), surround_(f.environment.surround),
        level_(image_level(*studio_.image, 2 * kImageFloorEmitterWidth)),
        width_(std::max(taken.width, 1)), height_(std::max(taken.height, 1)),
        taken_(size_t(width_) * size_t(height_), false) {
    for (const ImagePatch& p : taken.patches) taken_[size_t(p.j) * size_t(width_) + size_t(p.i)] = true;
  }
  glm::dvec3 operator()(const glm::dvec3& d) const {
    if (d.y < 0) return surround_.radiance(d);
    const glm::dvec2 uv = equirect_uv(studio_.image_direction(d));
    const int i = std::clamp(int(uv.x * level_.width), 0, level_.width - 1);
    const int j = std::clamp(int(uv.y * level_.height), 0, level_.height - 1);
    const size_t patch = size_t(j * height_ / level_.height) * size_t(width_) + size_t(i * width_ / level_.width);
    return taken_[patch] ? glm::dvec3(0.0) : glm::dvec3(level_.at(i, j)) * double(studio_.env.intensity);
  }

 private:
  Studio studio_;
  SkyIrradiance surround_;
  const HdrImage& level_;
  int width_, height_;
  std::vector<bool> taken_;
};

// The lights whose photons the map traces, given the image's patches (none in the studio).
LightRig emitters_of(const FrameState& f, const ImagePatches& patches) {
  if (!f.environment.image) return f.lights;
  LightRig rig;
  rig.aim = f.lights.aim;
  for (const ImagePatch& p : patches.patches) rig.lights.push_back(far_patch_light(p, rig.aim));
  return rig;
}
}  // namespace

LightRig floor_emitters(const FrameState& f) { return emitters_of(f, floor_emitter_patches(f)); }

glm::dvec3 unoccluded_floor_irradiance(const LightRig& rig, const glm::dvec3& p) {
  return rig.irradiance(p, {0, 1, 0});
}

struct FloorLightTrace::State {
  FrameState frame;  // the photons' scene, kept for the batches to come
  FloorLightSettings settings;
  LightRig emitters;
  FloorLightMap map;
  std::unique_ptr<PhotonTracer> tracer;
  std::vector<Target> targets;
  std::vector<int> counts;                          // photons of a batch per (light, target) pair
  std::vector<long long> first{0};                  // the first photon of each pair in a batch
  std::vector<std::array<double, 4>> shifts;        // each pair's random shift of its sequence
  std::vector<Lane> lanes;                          // sums over the batches so far
  std::unique_ptr<OpenLightLattice> lattice;
  int batches = 0;
  int merged = 0;  // the batches the map holds
  double seconds = 0;

  // The surroundings' shadow, gathered a share of the rays with each batch: per node, the
  // radiance that got through and what would have with nothing in the way, summed over the
  // rays so far in the rays' order (so the sums do not depend on how the rays were split).
  struct GatherNode {
    size_t a = 0, b = 0;      // in gather_lattice
    glm::dvec3 o{0.0};        // on the floor
    glm::dvec2 shift{0.0};    // the node's random shift of the directions
    std::uint64_t index = 0;  // the node's random streams
    glm::dvec3 got{0.0}, open{0.0};
  };
  std::vector<GatherNode> gather_nodes;
  std::unique_ptr<TexelLattice> gather_lattice;
  // The light gathered (radiance by direction): the surroundings' harmonics, or an
  // image less the patches the photons trace; and its share of the light the map's
  // factor is over.
  std::function<glm::dvec3(const glm::dvec3&)> gather_light;
  glm::dvec3 gather_share{1.0};
  int gathered = 0;         // rays gathered at every node so far
  int gather_merged = 0;    // those the map's surround_factor holds

  int threads() const {
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    return std::clamp(settings.threads > 0 ? settings.threads : int(hw), 1, kLanes);
  }
  template <class F>
  void in_parallel(F&& f) const {
    const int n = threads();
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(f, t);
    f(0);
    for (std::thread& t : pool) t.join();
  }

  void merge();  // the lanes into the map, if batches came since the last merge
  void plan_gather(const std::vector<Caster>&, const ImagePatches&);  // the nodes near the casters
  void gather(int rays);                          // that many more rays at every node

  // Photon i of pair (l, g) in batch b: a point on light l, a direction in g's cone. The
  // weight is the balance heuristic over every target's cone from that point, so directions
  // towards several targets are not counted twice.
  void photon(int b, long long k, Lane& lane) const {
    const size_t G = targets.size();
    const size_t pair = size_t(std::upper_bound(first.begin(), first.end(), k) - first.begin()) - 1;
    const AreaLight& light = emitters.lights[pair / G];
    const std::uint64_t index = std::uint64_t(b) * std::uint64_t(counts[pair]) + std::uint64_t(k - first[pair]);
    Rng rng(settings.seed, pair, index);
    // The point and the direction from a Halton sequence shifted by the pair's random offset
    // (randomised quasi-Monte Carlo: unbiased, and a shadow's noise falls much faster than
    // with independent samples), a batch going on where the last stopped; the rest of the
    // path from the photon's own stream.
    auto halton = [&](int dim) {
      static constexpr int kBases[4] = {2, 3, 5, 7};
      const double u = radical_inverse(kBases[dim], index) + shifts[pair][size_t(dim)];
      return u - std::floor(u);
    };
    glm::dvec3 x, nl;
    light.sample_point(halton(0), halton(1), x, nl);
    const Cone c = cone_towards(targets[pair % G], x);
    const glm::dvec3 d = around(c.axis, 1 - halton(2) * (1 - c.cos_max), 2 * kPi * halton(3));
    const double cos_l = glm::dot(d, nl);
    if (cos_l <= 0) return;
    double density = 0;  // photons per unit solid angle over every pair of this light
    for (size_t g = 0; g < G; ++g) {
      const int n = counts[(pair / G) * G + g];
      if (n == 0) continue;
      const Cone cg = g == pair % G ? c : cone_towards(targets[g], x);
      if (cg.contains(d)) density += n / cg.solid_angle;
    }
    if (density <= 0) return;
    tracer->trace({x + d * 1e-6, d}, light.radiance * (cos_l * light.area() / density), rng, lane);
  }
};

FloorLightTrace::FloorLightTrace(const FrameState& f, const FloorLightSettings& s) : state_(std::make_unique<State>()) {
  State& st = *state_;
  st.frame = f;
  st.settings = s;
  const ImagePatches patches = floor_emitter_patches(f);  // (an image's: its light for both parts)
  st.emitters = emitters_of(f, patches);
  if (!f.backdrop.present || st.emitters.lights.empty()) return;  // (the studio's: lit_geometry)
  st.tracer = std::make_unique<PhotonTracer>(st.frame, st.map);
  std::vector<Caster> casters;
  for (const VesselFrame& v : f.vessels) {
    st.targets.push_back(target_of(v));
    casters.push_back(caster_of(v));
  }
  std::vector<bool> cloud(st.targets.size(), false);
  for (const MarchedBodies::Bound& b : st.tracer->bodies().bounds()) {
    st.targets.push_back({b.centre, b.radius});
    casters.push_back(caster_of(st.targets.back()));
    cloud.push_back(b.cloud);
  }
  if (st.targets.empty()) return;
  place_rect(casters, st.emitters, s, st.map);
  // The clouds' photons from a budget of their own, kCloudPhotonShare of the glasses' and
  // droplets': each costs tens of theirs (the march through the tree), and a blob's soft
  // shadow needs fewer.
  std::vector<Target> solid, blobs;
  for (size_t g = 0; g < st.targets.size(); ++g) (cloud[g] ? blobs : solid).push_back(st.targets[g]);
  const int budget = std::max(s.photons, 0);
  const std::vector<int> solid_counts = photon_counts(st.emitters, solid, budget);
  const std::vector<int> blob_counts = photon_counts(st.emitters, blobs, int(budget * kCloudPhotonShare));
  for (size_t l = 0; l < st.emitters.lights.size(); ++l) {  // per (light, target) pair, as targets lists them
    size_t a = 0, b = 0;
    for (size_t g = 0; g < st.targets.size(); ++g)
      st.counts.push_back(cloud[g] ? blob_counts[l * blobs.size() + b++] : solid_counts[l * solid.size() + a++]);
  }
  for (int n : st.counts) st.first.push_back(st.first.back() + n);
  st.shifts.resize(st.counts.size());
  for (size_t pair = 0; pair < st.counts.size(); ++pair) {
    Rng rng(s.seed, pair, ~std::uint64_t(0));
    for (double& u : st.shifts[pair]) u = rng.uniform();
  }
  const size_t texels = size_t(st.map.width) * size_t(st.map.height);
  st.lanes.resize(kLanes);
  for (Lane& lane : st.lanes) lane.change.assign(texels, glm::dvec3(0.0));
  st.map.lights = f.lights;
  st.map.even = bool(f.environment.image);  // the image's whole light: the same everywhere
  if (st.map.even) st.map.even_light = f.environment.sky.at({0, 1, 0});
  st.lattice = std::make_unique<OpenLightLattice>(st.map);
  st.map.change.assign(texels, glm::vec3(0.0f));
  st.map.factor.assign(texels, glm::vec3(1.0f));
  st.map.surround_factor.assign(texels, glm::vec3(1.0f));
  st.plan_gather(casters, patches);
}

void FloorLightTrace::State::plan_gather(const std::vector<Caster>& casters, const ImagePatches& taken) {
  if (settings.gather_rays <= 0) return;
  if (!map.even) {
    gather_light = [sky = frame.environment.surround](const glm::dvec3& d) { return sky.radiance(d); };
  } else {
    // Under an image the photons trace its brightest patches (floor_emitters) and the
    // map's factor is over the image's whole light (even_light): the gather takes the
    // rest of the image, and its factor is turned into one over the whole light (merge)
    // with the rest's share of it, the whole less what the patches give the floor.
    gather_light = ImageRest(frame, taken);
    glm::dvec3 rest = map.even_light;
    for (const ImagePatch& p : taken.patches) rest -= p.irradiance() * std::max(p.dir.y, 0.0);
    for (int c = 0; c < 3; ++c)
      gather_share[c] = map.even_light[c] > 1e-12 ? std::clamp(rest[c] / map.even_light[c], 0.0, 1.0) : 0.0;
  }
  // The nodes: every kGatherStep-th texel (and the last of a row or column), those within
  // a caster's reach; the texels between bilinear.
  gather_lattice = std::make_unique<TexelLattice>(map, kGatherStep);
  const TexelLattice& lattice = *gather_lattice;
  for (size_t b = 0; b < lattice.rows(); ++b)
    for (size_t a = 0; a < lattice.columns(); ++a) {
      const glm::dvec2 c = map.texel_centre(lattice.texel_x(a), lattice.texel_y(b));
      bool near = false;
      for (const Caster& k : casters) near = near || glm::length(c - k.foot) < k.reach + k.spread;
      if (!near) continue;
      GatherNode node;
      node.a = a;
      node.b = b;
      node.o = {c.x, 1e-6, c.y};
      node.index = b * lattice.columns() + a;
      Rng rng(settings.seed, 0x9a7e, node.index);
      node.shift.x = rng.uniform();
      node.shift.y = rng.uniform();
      gather_nodes.push_back(node);
    }
}

void FloorLightTrace::State::gather(int rays) {
  rays = std::min(rays, settings.gather_rays - gathered);
  if (gather_nodes.empty() || rays <= 0) return;
  const auto& around = gather_light;
  const int from = gathered, n = threads();
  gathered += rays;
  in_parallel([&](int t) {
    for (size_t k = size_t(t); k < gather_nodes.size(); k += size_t(n)) {
      GatherNode& node = gather_nodes[k];
      // Cosine-weighted directions from the Sobol' sequence's first two coordinates,
      // shifted at random per node (randomised quasi-Monte Carlo); the factor a ratio of
      // sums over the same directions, so it is exactly 1 where nothing is in the way.
      for (int r = from; r < from + rays; ++r) {
        const double u = std::fmod(radical_inverse(2, std::uint64_t(r)) + node.shift.x, 1.0);
        const double v = std::fmod(sobol_second(std::uint32_t(r)) + node.shift.y, 1.0);
        const double sin_t = std::sqrt(u), cos_t = std::sqrt(1 - u), phi = 2 * kPi * v;
        const glm::dvec3 d(sin_t * std::cos(phi), cos_t, sin_t * std::sin(phi)), l = around(d);
        node.open += l;
        // (most directions miss every object's bounding sphere: nothing to follow)
        bool meets = false;
        for (const Target& g : targets) {
          const glm::dvec3 to = g.centre - node.o;
          const double along = glm::dot(to, d);
          meets = meets || (along > -g.radius && glm::dot(to, to) - along * along < g.radius * g.radius);
        }
        Rng rng(settings.seed, (std::uint64_t(0x9a7e) << 32) | std::uint64_t(r), node.index);  // the ray's own
        node.got += meets ? tracer->arriving({node.o, d}, around, rng) : l;
      }
    }
  });
}

FloorLightTrace::~FloorLightTrace() = default;

int FloorLightTrace::batches() const { return state_->batches; }
const FloorLightMap& FloorLightTrace::map() const {
  state_->merge();
  return state_->map;
}
const FloorLightMap& FloorLightTrace::last_merged() const { return state_->map; }
FloorLightMap FloorLightTrace::release() {
  state_->merge();
  FloorLightMap m = std::move(state_->map);
  state_->map = {};  // empty: add_batch does nothing more
  return m;
}

FloorLightSettings floor_light_draft(FloorLightSettings s, int photons) {
  s.photons = std::min(s.photons, photons);
  s.texel *= 2;
  s.max_resolution = std::max(1, s.max_resolution / 2);
  s.gather_rays = std::min(s.gather_rays, 8);
  return s;
}

void FloorLightTrace::add_batch() {
  State& st = *state_;
  if (st.map.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  const int b = st.batches++;
  const long long total = st.first.back();
  const int threads = st.threads();
  st.in_parallel([&](int t) {
    for (int l = t; l < kLanes; l += threads)
      for (long long k = l; k < total; k += kLanes) st.photon(b, k, st.lanes[size_t(l)]);
  });
  st.gather(st.settings.gather_rays_per_batch > 0 ? st.settings.gather_rays_per_batch : st.settings.gather_rays);
  st.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void FloorLightTrace::State::merge() {
  if (map.empty() || merged == batches) return;
  const auto start = std::chrono::steady_clock::now();
  if (gather_merged != gathered) {  // the surroundings' factor: the nodes' ratios, bilinear between
    gather_merged = gathered;
    for (const GatherNode& node : gather_nodes)
      for (int c = 0; c < 3; ++c) {
        const double kept = node.open[c] > 1e-12 ? node.got[c] / node.open[c] : 1.0;
        gather_lattice->node(node.a, node.b)[c] = 1 - gather_share[c] * (1 - kept);
      }
    for (int j = 0; j < map.height; ++j)
      for (int i = 0; i < map.width; ++i)
        map.surround_factor[size_t(j) * size_t(map.width) + size_t(i)] = glm::vec3(gather_lattice->at(i, j));
  }
  merged = batches;
  const long long total = first.back();
  // The mean change over the batches, the lanes summed in a fixed order, and the factor the
  // picture reads: where a photon changed the light, over the unoccluded light there (noise
  // may dip below zero).
  const double per = 1.0 / batches;
  const int n = threads();
  in_parallel([&](int t) {
    for (int j = t; j < map.height; j += n)
      for (int i = 0; i < map.width; ++i) {
        const size_t at = size_t(j) * size_t(map.width) + size_t(i);
        glm::dvec3 change(0.0);
        for (const Lane& lane : lanes) change += lane.change[at];
        if (change == glm::dvec3(0.0)) continue;
        change *= per;
        map.change[at] = glm::vec3(change);
        const glm::dvec3 open = lattice->at(i, j);
        for (int c = 0; c < 3; ++c)
          if (open[c] > 1e-9) map.factor[at][c] = float(std::max(open[c] + change[c], 0.0) / open[c]);
      }
  });
  map.stats = {};
  for (const Lane& lane : lanes) {
    map.stats.hit += lane.stats.hit * per;
    map.stats.landed += lane.stats.landed * per;
    map.stats.removed += lane.stats.removed * per;
    map.stats.absorbed += lane.stats.absorbed * per;
    map.stats.escaped += lane.stats.escaped * per;
    map.stats.outside += lane.stats.outside * per;
  }
  map.stats.photons = int(std::min<long long>(total * batches, std::numeric_limits<int>::max()));
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  map.stats.seconds = seconds;
}

FloorLightMap compute_floor_light(const FrameState& f, const FloorLightSettings& s) {
  FloorLightTrace trace(f, s);
  trace.add_batch();
  return trace.release();
}

std::vector<double> floor_light_inputs(const FrameState& f) {
  std::vector<double> k;
  // Rounded to a hundredth of a millimetre (or 1e-5 of a unit): a glass coming to rest, a
  // head settling, stop changing the map once nothing the map shows moves any more.
  auto put = [&k](auto... xs) { (k.push_back(std::round(double(xs) * 1e5)), ...); };
  auto put3 = [&put](const auto& v) { put(v.x, v.y, v.z); };
  const SceneGeometry geo = lit_geometry(f);
  const BackdropSurface& b = geo.backdrop;
  const LightRig emitters = floor_emitters(f);
  put(b.present ? 1 : 0, int(b.kind), b.plane ? 1 : 0, b.z_curve, b.radius, emitters.lights.size(), f.vessels.size());
  const glm::dvec3 sky = f.environment.image ? f.environment.sky.at({0, 1, 0}) : glm::dvec3(0.0);
  put3(sky);
  for (const glm::dvec3& c : f.environment.surround.coef) put3(c);  // the surroundings whose shadow it gathers
  for (const AreaLight& l : emitters.lights) {
    for (double x : l.numbers()) put(x);
  }
  for (size_t i = 0; i < f.vessels.size(); ++i) {
    const VesselFrame& v = f.vessels[i];
    put3(v.pose.position);
    put(v.pose.orientation.w, v.pose.orientation.x, v.pose.orientation.y, v.pose.orientation.z);
    const Vessel& ve = v.vessel;
    put(ve.height, ve.base, ve.dy, ve.rim_major, ve.rim_minor, ve.r_outer.size());
    for (double r : ve.r_outer) put(r);
    for (double r : ve.r_inner) put(r);
    put(v.has_liquid ? 1 : 0, v.liquid.offset, v.liquid.waves.ring, v.liquid.waves.radius);
    put(v.liquid.waves.cross.x, v.liquid.waves.cross.y);
    put(v.liquid.waves.dimple_xz.x, v.liquid.waves.dimple_xz.y, v.liquid.waves.dimple_radius, v.liquid.waves.dimple_depth);
    put3(v.liquid.n);
    put3(v.liquid_absorption.fast);
    put3(v.liquid_absorption.slow);
    put3(v.liquid_absorption.share);
    put(v.params.glass.ior, v.params.liquid.ior, v.params.liquid.haze);
    put3(v.params.glass.absorption);
    put3(v.params.liquid.haze_color);
    // A head collapses all the time (a few mm a minute): its height in steps of 0.5 mm, or
    // the map was traced again every frame of every beer (in the browser, a draft a frame:
    // most of a frame's CPU). A step changes the light under the glass by a few per cent
    // of what crosses the head.
    const auto coarse = [](double x, double step) { return std::round(x / step) * step; };
    put(coarse(v.foam.thickness, 5e-4), coarse(v.foam.dome, 0.02), v.params.foam.density, v.params.foam.bubble_size,
        v.params.foam.detail);
    put(coarse(v.foam.crater_depth, 0.1), coarse(v.foam.crater_xz.x, 2e-3), coarse(v.foam.crater_xz.y, 2e-3),
        coarse(v.foam.crater_radius, 1e-3));  // (a pour's dimple: its stream retraces the map anyway)
    put(geo.vessels[i].clip.x, geo.vessels[i].clip.y, geo.vessels[i].clip.z, geo.vessels[i].clip.w);
    // Its decals (they cast shadows): each layer's file by name and its placement and look.
    for (const DecalParams* d : {&v.params.decal_outer, &v.params.decal_inner}) {
      put(double(std::hash<std::string>{}(d->file) % 1000003), d->kind, d->angle, d->height, d->width, d->repeat,
          d->opacity, d->roughness);
      put3(d->color);
    }
  }
  // The droplets as the march sees them, and each cloud by its points' version (a new one
  // whenever they move: an animated cloud is traced again each frame it moves).
  put(f.droplets.size(), f.clouds.size());
  for (const DropletsFrame& d : f.droplets) {
    put(int(d.field.kernel), d.field.blend, d.field.noise_amplitude, d.field.noise_frequency, d.field.spheres.size());
    for (const DropletSphere& sp : d.field.spheres) put(sp.centre.x, sp.centre.y, sp.centre.z, sp.radius);
    put(d.params.ior);
    put3(d.params.absorption);
  }
  for (const CloudFrame& c : f.clouds) {
    k.push_back(double(c.version));  // exact: versions are counts
    put(c.material, c.threshold, c.glow_depth, c.temperature, c.ior);
    put3(c.absorption);
    put3(c.color);
  }
  return k;
}

}  // namespace draught
