#include "core/bubbles/bubbles.hpp"

#include "core/math/hash.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kHair = 1e-4;        // m: sites sit this far off the glass
constexpr double kSkin = 1e-6;        // m: bubbles keep this clearance (float rounding)
constexpr double kSiteRate = 15.0;    // bubbles/s of the busiest site at carbonation 1
constexpr double kMaxThreshold = 0.5; // carbonation a site needs before it emits, at most
constexpr double kEtchedRate = 3.0;   // an etched site emits this many times faster
constexpr double kEtchedRing = 0.003; // m: radius of the etched ring
constexpr double kBubbleGrowth = 10.0;  // 1/m: relative growth per metre risen at carbonation 1 (x2 over 10 cm)
constexpr double kMaxRadius = 1.5e-3; // m
// Rise speed. Small bubbles follow Stokes' law for a rigid sphere (surfactants make
// drink bubbles behave so): v = 2 g r^2 / (9 nu), nu ~ 1e-6 m^2/s for water-like drinks,
// so 2.2 cm/s at r = 0.1 mm. Larger ones leave the Stokes regime and saturate near
// 25 cm/s (measured terminal velocities of ~1 mm bubbles in water); the two are blended
// harmonically, then clamped to [1, 30] cm/s.
constexpr double kStokes = 2.0 * 9.81 / (9.0 * 1e-6);  // 1/(m s)
constexpr double kSpeedCap = 0.25, kMinSpeed = 0.01, kMaxSpeed = 0.30;  // m/s
constexpr double kMinWobbleHz = 2.0, kMaxWobbleHz = 5.0;

double speed(double r) {
  const double stokes = kStokes * r * r;
  return std::clamp(1.0 / (1.0 / stokes + 1.0 / kSpeedCap), kMinSpeed, kMaxSpeed);
}

}  // namespace

BubbleField::BubbleField(const BubbleSettings& s, const Vessel& v) : settings_(s), vessel_(v) {
  const auto clean = [](float x, float lo, float hi, float fallback) {
    return std::isfinite(x) ? std::clamp(x, lo, hi) : fallback;
  };
  settings_.carbonation = clean(s.carbonation, 0.0f, 1.0f, 0.0f);
  settings_.size = clean(s.size, 1e-5f, 1e-3f, 2e-4f);
  settings_.sites = std::clamp(s.sites, 0, 10000);
  settings_.max_bubbles = std::clamp(s.max_bubbles, 0, 100000);
  const double c = settings_.carbonation;
  growth_ = kBubbleGrowth * (0.25 + 0.75 * c);  // more dissolved CO2 feeds the bubbles faster
  valid_ = vessel_.r_inner.size() >= 2 && vessel_.dy > 0 && vessel_.height > vessel_.base &&
           std::isfinite(vessel_.height) && std::isfinite(vessel_.base);
  if (!valid_) return;

  const auto seed = std::uint64_t(std::uint32_t(settings_.seed));
  const double base = vessel_.base, top = std::max(base, 0.9 * vessel_.height);
  const double floor_r = std::max(0.9 * vessel_.inner_radius(base), 0.0);
  // Wall and floor sites in proportion to their areas.
  double mean_r = 0;
  for (int i = 0; i < 8; ++i) mean_r += vessel_.inner_radius(base + (top - base) * (i + 0.5) / 8) / 8;
  const double wall_area = kTwoPi * mean_r * (top - base), floor_area = 0.5 * kTwoPi * floor_r * floor_r;
  const double p_wall = wall_area / std::max(wall_area + floor_area, 1e-12);
  for (int i = 0; i < settings_.sites; ++i) {
    const auto h = [&](int k) { return hash01(seed, std::uint64_t(i), 0, std::uint64_t(k)); };
    BubbleSite site;
    const double a = kTwoPi * h(2);
    if (h(0) < p_wall) {
      const double y = base + (top - base) * h(1);
      const double r = std::max(vessel_.inner_radius(y) - kHair, 0.0);
      site.p = {r * std::cos(a), y, r * std::sin(a)};
    } else {
      const double r = floor_r * std::sqrt(h(1));
      site.p = {r * std::cos(a), base + kHair, r * std::sin(a)};
    }
    // A cavity needs enough supersaturation to grow a bubble past its critical radius:
    // each site starts at its own threshold and speeds up with the CO2 above it.
    const double threshold = kMaxThreshold * h(4);
    site.rate = kSiteRate * (0.25 + 0.75 * h(3)) * std::max(c - threshold, 0.0) / (1.0 - threshold);
    sites_.push_back(site);
  }
  if (s.etched_base) {
    const double ring = std::min(kEtchedRing, 0.5 * vessel_.inner_radius(base));
    const double a0 = kTwoPi * hash01(seed, ~0ull, 0, 0);
    for (int i = 0; i < kEtchedSites; ++i) {
      const double a = a0 + kTwoPi * i / kEtchedSites;
      BubbleSite site;
      site.p = {ring * std::cos(a), base + kHair, ring * std::sin(a)};
      site.rate = kEtchedRate * kSiteRate * c * (0.8 + 0.2 * hash01(seed, ~0ull, 0, std::uint64_t(i) + 1));
      site.etched = true;
      sites_.push_back(site);
    }
  }
}

void BubbleField::clear() {
  tracks_.clear();
  bubbles_.clear();
  pops_.clear();
  for (auto& s : sites_) s.pending = 0;
}

double BubbleField::radius(const Track& t) const { return std::min(t.r0 * (1.0 + growth_ * t.risen), kMaxRadius); }

bool BubbleField::confine(glm::dvec3& p, double r) const {
  if (!valid_ || !all_finite(p)) return false;
  p.y = std::max(p.y, vessel_.base + r + kSkin);
  if (p.y + r + kSkin > vessel_.height) return false;  // out over the rim
  // The narrowest radius over the sphere's height span: conservative on sloped walls.
  const double wall = std::min({vessel_.inner_radius(p.y - r), vessel_.inner_radius(p.y), vessel_.inner_radius(p.y + r)});
  const double room = wall - r - kSkin;
  if (room < 0) return false;
  const double rho = std::hypot(p.x, p.z);
  if (rho > room) p.x *= room / rho, p.z *= room / rho;
  return true;
}

bool BubbleField::advance(Track& t, Bubble& b, double dt, const LiquidPlane& surface) {
  const glm::dvec3 before = t.path;
  t.path += up_ * (speed(radius(t)) * dt);
  t.age += dt;
  double r = radius(t);
  bool inside = confine(t.path, r);
  if (inside) t.risen += std::max(glm::dot(t.path - before, up_), 0.0);  // a bubble held by the glass does not grow
  r = radius(t);
  // Small bubbles zigzag in a plane perpendicular to up: amplitude ~ radius, a few Hz.
  const double w = std::sin(kTwoPi * t.freq * t.age + t.phase) * r;
  glm::dvec3 p = t.path + w * (std::cos(t.phase) * e1_ + std::sin(t.phase) * e2_);
  inside = inside && confine(p, r);
  b.p = glm::vec3(p);
  b.radius = float(r);
  b.age = float(t.age);
  const double level = surface.level(p);
  if (inside && level + r < 0) return true;
  // Popped: record where it breaks the surface if the sphere reaches it (not when the
  // level fell away from it, or the surface is garbage).
  if (std::isfinite(level) && level < r && level >= -r) pops_.push_back(glm::vec3(p - level * surface.n));
  return false;
}

void BubbleField::step(double dt, const LiquidPlane& surface, const glm::dvec3& up_local) {
  pops_.clear();
  if (!(dt > 0)) return;
  dt = std::min(dt, kMaxStep);
  // Any finite non-zero direction will do (scaled first: huge or tiny ones normalise too).
  const double m = std::max({std::abs(up_local.x), std::abs(up_local.y), std::abs(up_local.z)});
  if (all_finite(up_local) && m > 0) {
    up_ = glm::normalize(up_local / m);
    const glm::dvec3 a = std::abs(up_.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
    e1_ = glm::normalize(glm::cross(up_, a));
    e2_ = glm::cross(up_, e1_);
  }

  // Move everything, dropping the popped bubbles (stable order: oldest first).
  size_t n = 0;
  for (size_t i = 0; i < tracks_.size(); ++i) {
    if (!advance(tracks_[i], bubbles_[i], dt, surface)) continue;
    tracks_[n] = tracks_[i];
    bubbles_[n++] = bubbles_[i];
  }
  tracks_.resize(n);
  bubbles_.resize(n);

  // Emit. Each bubble is born when its site's accumulator crossed a whole number and has
  // risen for the rest of the step, so streams stay evenly spaced at any step size.
  const auto seed = std::uint64_t(std::uint32_t(settings_.seed));
  for (size_t s = 0; s < sites_.size(); ++s) {
    BubbleSite& site = sites_[s];
    if (!(site.rate > 0) || !(surface.level(site.p) < 0)) continue;  // dry or still
    site.pending += site.rate * dt;
    while (site.pending >= 1) {
      site.pending -= 1;
      const std::uint64_t k = ++site.emitted;
      if (int(tracks_.size()) >= settings_.max_bubbles) continue;  // full: this emission is skipped
      const auto h = [&](int c) { return hash01(seed, s, k, std::uint64_t(c)); };
      Track t;
      t.r0 = settings_.size * (0.6 + 0.4 * settings_.carbonation) * (0.8 + 0.4 * h(0));
      t.phase = kTwoPi * h(1);
      t.freq = kMinWobbleHz + (kMaxWobbleHz - kMinWobbleHz) * h(2);
      t.path = site.p;
      if (!confine(t.path, t.r0) || !(surface.level(t.path) + t.r0 < 0)) continue;  // no room here
      Bubble b;
      if (advance(t, b, site.pending / site.rate, surface)) tracks_.push_back(t), bubbles_.push_back(b);
    }
  }
}

}  // namespace draught
