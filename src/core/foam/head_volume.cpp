#include "core/foam/head_volume.hpp"

#include "core/math/noise.hpp"
#include "core/reference/optics.hpp"
#include "core/scene/frame.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
// The ring of denser foam around a big bubble: density x (1 + k exp(-((dist - r) / (0.45 r))^2)).
double ring_gain(const PlacedBubble& b) { return b.popped ? 0.6 : 1.8; }
constexpr double kRingWidth = 0.45;
// Beyond this many ring widths a ring adds less than 2e-4 (exp(-9)): it no longer counts
// towards another bubble's bound.
constexpr double kRingReach = 3.0;
// Beyond this many ring widths 1 + gain exp(-ring^2) rounds to exactly 1 in double
// (1.8 exp(-40) = 7.6e-18, under half of 1's ulp, 1.1e-16): skipping it changes nothing.
// 4 radii from the centre is 6.67 widths out, beyond it.
constexpr double kRingSkip = 6.33;
static_assert(kRingSkip * kRingSkip > 40 && 1 + kRingSkip * kRingWidth < 4);
// Bubbles at the liquid are 1 + kGrowth times their size at the top; the top is soft over
// kSoftTop of the thickness (FOAM_GROWTH and FOAM_SOFT_TOP in shaders/lib/foam/head.glsl).
constexpr double kGrowth = 1.5;
constexpr double kSoftTop = 0.12;
}  // namespace

double foam_reflectance(double a, double g) {
  a = std::clamp(a, 0.0, 1.0);
  const double s = std::sqrt((1 - a) / std::max(1 - a * g, 1e-12));
  return (1 - s) * (1 - 0.139 * s) / (1 + 1.17 * s);
}

glm::dvec3 foam_single_scattering_albedo(const glm::dvec3& reflectance, double g) {
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    // R falls monotonically from 1 (s = 0) to 0 (s = 1): bisect on s, then a from s.
    const double target = std::clamp(reflectance[c], 0.0, 1.0);
    double lo = 0, hi = 1;
    for (int i = 0; i < 60; ++i) {
      const double s = 0.5 * (lo + hi);
      ((1 - s) * (1 - 0.139 * s) / (1 + 1.17 * s) > target ? lo : hi) = s;
    }
    const double s2 = 0.25 * (lo + hi) * (lo + hi);
    out[c] = (1 - s2) / (1 - s2 * g);
  }
  return out;
}

double wall_diffuse_transmittance(double glass_ior) {
  double sum = 0.0;
  for (int k = 0; k < 8; ++k) {
    const double t = 1.0 - fresnel_dielectric(std::sqrt((k + 0.5) / 8.0), 1.0, glass_ior);
    sum += t * t;
  }
  return sum / 8.0;
}

double drink_mean_chord(const VesselFrame& vf) {
  if (!vf.has_liquid || vf.liquid_fraction <= 0) return 0;
  const double volume = vf.liquid_fraction * vf.vessel.cavity_volume();
  const double depth = std::max(vf.vessel.fill_height(vf.liquid_fraction) - vf.vessel.base, 1e-6);
  const double r = std::sqrt(volume / (std::numbers::pi * depth));
  return 2 * r * depth / (r + depth);  // 4 pi r^2 h / (2 pi r^2 + 2 pi r h)
}

HeadVolume::HeadVolume(const VesselFrame& vf, const VesselGeometry& geometry) {
  present_ = has_head(vf);
  if (!present_) return;
  vessel_ = &vf.vessel;
  liquid_ = vf.liquid;
  clip_ = geometry.clip;
  foam_ = &vf.foam;
  radius_ = vf.liquid.waves.radius;
  const FoamParams& fp = vf.params.foam;
  density_ = fp.density;
  bubble_size_ = std::max<double>(fp.bubble_size, 1e-6);
  detail_ = fp.detail;
  bubbles_ = vf.big_bubbles;
  // The bound: the noise adds at most 0.8 x detail; each bubble's ring multiplies by
  // (1 + gain), and rings that reach one another multiply together.
  double rings = 1;
  for (const PlacedBubble& a : bubbles_) {
    double m = 1 + ring_gain(a);
    for (const PlacedBubble& b : bubbles_)
      if (&a != &b && glm::length(a.centre - b.centre) < (1 + kRingReach * kRingWidth) * (a.radius + b.radius))
        m *= 1 + ring_gain(b);
    rings = std::max(rings, m);
  }
  majorant_ = density_ * (1 + 0.8 * detail_) * rings * 1.001;
}

double HeadVolume::thickness_at(double x, double z) const { return foam_->thickness_at(x, z, radius_); }

double HeadVolume::density(const glm::dvec3& p) const {
  if (!present_) return 0;
  const double height = liquid_.level(p), top = thickness_at(p.x, p.z);
  if (height < 0 || height > top || p.y > vessel_->height || std::hypot(p.x, p.z) > vessel_->inner_radius(p.y) ||
      glm::dot(glm::dvec3(clip_), p) > clip_.w)
    return 0;
  // Bubbles are bigger low in the head (they coarsen as liquid drains out of it), and the
  // extinction goes as 1 / their size: the wet foam low in the head is the more
  // translucent. A soft top. (As foam_growth and foam_density in shaders/lib/foam/head.glsl.)
  const double grow = 1 + kGrowth * (1 - height / top);
  double d = density_ / grow * std::max(1 + 1.6 * detail_ * (value_noise(glm::vec3(p / (bubble_size_ * grow))) - 0.5), 0.0);
  d *= std::clamp((top - height) / (kSoftTop * top), 0.0, 1.0);
  for (const PlacedBubble& b : bubbles_) {
    // A ring farther than kRingSkip widths multiplies d by exactly 1 (below): a bubble more
    // than 4 radii away is passed over without its square root or its exp (whose
    // underflow, for the far ones, took libm's slow path).
    const glm::dvec3 q = p - b.centre;
    if (glm::dot(q, q) > 16 * b.radius * b.radius) continue;
    const double dist = glm::length(q);
    if (dist < b.radius) return 0;  // inside a big bubble, or the void a popped one left
    const double ring = (dist - b.radius) / (kRingWidth * b.radius);
    if (ring < kRingSkip) d *= 1 + ring_gain(b) * std::exp(-ring * ring);
  }
  return d;
}

bool HeadVolume::interval(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) const {
  if (!present_) return false;
  const glm::dvec3 n = liquid_.n;
  const SurfaceWaves& w = liquid_.waves;
  const double waves = std::fabs(w.ring) + std::fabs(w.cross.x) + std::fabs(w.cross.y) + w.dimple_depth;
  const double top_max = foam_->thickness * (1 + std::fabs(foam_->dome)) * foam_->crater_headroom() + waves + 0.006;
  const double h0 = glm::dot(n, o) - liquid_.offset, dh = glm::dot(n, d);
  if (std::fabs(dh) > 1e-12) {
    const double ta = (-waves - h0) / dh, tb = (top_max - h0) / dh;
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  } else if (h0 < -waves || h0 > top_max) {
    return false;
  }
  // The cavity's bounding cylinder: the glass's bound radius, from the cavity floor to the rim.
  const double y0 = vessel_->base, y1 = vessel_->height;
  if (std::fabs(d.y) > 1e-12) {
    const double ta = (y0 - o.y) / d.y, tb = (y1 - o.y) / d.y;
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  } else if (o.y < y0 || o.y > y1) {
    return false;
  }
  const double R = vessel_->bound_radius;
  const double a = d.x * d.x + d.z * d.z, b = o.x * d.x + o.z * d.z, c = o.x * o.x + o.z * o.z - R * R;
  if (a > 1e-18) {
    const double disc = b * b - a * c;
    if (disc <= 0) return false;
    const double s = std::sqrt(disc);
    t0 = std::max(t0, (-b - s) / a);
    t1 = std::min(t1, (-b + s) / a);
  } else if (c > 0) {
    return false;
  }
  return t1 > t0;
}

bool HeadVolume::hit_cap(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1, double& t_hit,
                         glm::dvec3& n) const {
  bool found = false;
  for (const PlacedBubble& b : bubbles_) {
    if (b.popped) continue;
    const glm::dvec3 oc = o - b.centre;
    const double bb = glm::dot(oc, d), disc = bb * bb - (glm::dot(oc, oc) - b.radius * b.radius);
    if (disc <= 0) continue;
    const double s = std::sqrt(disc);
    for (double t : {-bb - s, -bb + s}) {  // the near side, or the far side from inside
      if (t <= t0 || t >= t1) continue;
      const glm::dvec3 p = o + t * d;
      // Only the cap that stands out of the head's top, and not where the glass is cut away.
      if (liquid_.level(p) < thickness_at(p.x, p.z) || glm::dot(glm::dvec3(clip_), p) > clip_.w) continue;
      t1 = t;
      t_hit = t;
      n = (p - b.centre) / b.radius;
      found = true;
      break;
    }
  }
  return found;
}

}  // namespace draught
