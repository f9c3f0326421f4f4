#include "core/foam/foam.hpp"

#include "core/math/hash.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace draught {

namespace {
constexpr double kLacingStep = 0.008;  // the level falls this far between two rings
}  // namespace

// The parameters are in their table ranges (checked when they were set): no clamping here.
FoamState::FoamState(const FoamParams& p) : params_(p), age_(p.age) {}

void FoamState::pour() {
  age_ = 0;
  drop_ = 0;
  last_level_ = lace_level_ = -1;
  lacing_.clear();
}

double FoamState::thickness() const {
  const double h = params_.height, rise = params_.rise_time, half = params_.half_life;
  // Builds during the pour (overshooting a little), settles, then collapses.
  const double built = 1.0 - std::exp(-3.0 * age_ / rise);
  const double after = std::max(age_ - rise, 0.0);
  const double overshoot = 1.0 + 0.35 * std::min(age_ / rise, 1.0) * std::exp(-after / (2.0 * rise));
  return h * built * overshoot * std::exp2(-after / half);
}

void FoamState::step(double dt, double level, double radius) {
  if (!(dt > 0) || !std::isfinite(level)) return;
  age_ += std::min(dt, 1.0);
  if (last_level_ >= 0 && level < last_level_) drop_ += last_level_ - level;
  last_level_ = level;
  if (lace_level_ < 0 || level > lace_level_) lace_level_ = level;  // refilled: start over there
  // Each time the level has fallen a step, the foam's top leaves a ring on the glass.
  const double t = thickness();
  if (params_.lacing > 0 && t > 0.001 && level < lace_level_ - kLacingStep) {
    lacing_.push_back(lace_level_ + t * (1.0 - 0.5 * params_.dome));
    if (int(lacing_.size()) > kMaxLacing) lacing_.erase(lacing_.begin());
    lace_level_ = level;
  }
  (void)radius;
}

BigBubble FoamState::bubble(int slot, double radius) const {
  const auto seed = std::uint64_t(params_.seed);
  // Each slot lives through generations: grow, sit shining, pop, heal, start again.
  const double period = 5.0 + 8.0 * hash01(seed, std::uint64_t(slot), 0, 0);
  const double phase = period * hash01(seed, std::uint64_t(slot), 0, 1);
  const double x = (age_ + phase) / period;
  const auto gen = std::uint64_t(std::floor(x));
  const double u = x - std::floor(x);
  BigBubble b;
  const double a = 2.0 * std::numbers::pi * hash01(seed, std::uint64_t(slot), gen, 2);
  const double r = 0.8 * radius * std::sqrt(hash01(seed, std::uint64_t(slot), gen, 3));
  b.xz = r * glm::dvec2(std::cos(a), std::sin(a));
  const double size = std::min(0.0015 + 0.003 * hash01(seed, std::uint64_t(slot), gen, 4), 0.45 * thickness());
  if (u < 0.15) {
    b.radius = size * u / 0.15;
  } else if (u < 0.7) {
    b.radius = size;
  } else {
    b.popped = true;
    b.radius = size * (1.0 - (u - 0.7) / 0.3);  // the void heals
  }
  return b;
}

double FoamFrame::thickness_at(double x, double z, double radius) const {
  const double u2 = std::min((x * x + z * z) / std::max(radius * radius, 1e-12), 1.5);
  double t = thickness * std::max(1.0 + dome * (1.0 - 2.0 * u2), 0.1);
  if (crater_depth > 0 && crater_radius > 0) {
    const double s = glm::length(glm::dvec2(x, z) - crater_xz) / crater_radius, c = (s - kCraterCollarAt) / 0.5;
    t *= 1 - crater_depth * (std::exp(-s * s) - kCraterCollar * std::exp(-c * c));
  }
  return t;
}

std::vector<PlacedBubble> place_big_bubbles(const FoamFrame& fo, const glm::dvec3& n, double offset,
                                            double surface_radius) {
  std::vector<PlacedBubble> out;
  for (const BigBubble& b : fo.bubbles) {
    // The surface's height over (x, z), then up the normal to the head's top, less 30 %
    // of the radius (the cap stands out by 70 %).
    const double y = (offset - n.x * b.xz.x - n.z * b.xz.y) / std::max(n.y, 1e-3);
    const glm::dvec3 c = glm::dvec3(b.xz.x, y, b.xz.y) + n * (fo.thickness_at(b.xz.x, b.xz.y, surface_radius) - 0.3 * b.radius);
    out.push_back({c, b.radius, b.popped});
  }
  return out;
}

FoamFrame FoamState::frame(double radius) const {
  FoamFrame f;
  f.thickness = thickness();
  // Concave as the level drops (the head clings to the glass), domed while it builds.
  const double building = std::exp(-age_ / double(params_.rise_time));
  f.dome = std::clamp(double(params_.dome) + 0.15 * building, -0.5, 0.5);
  f.dome = f.dome + (-0.4 - f.dome) * std::clamp(drop_ / 0.02, 0.0, 1.0);
  f.lacing = lacing_;
  if (f.thickness > 0.002)
    for (int i = 0; i < std::min(params_.big_bubbles, kMaxBubbles); ++i) {
      BigBubble b = bubble(i, radius);
      if (b.radius > 1e-5) f.bubbles.push_back(b);
    }
  return f;
}

}  // namespace draught
