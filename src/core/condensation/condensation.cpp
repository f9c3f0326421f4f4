#include "core/condensation/condensation.hpp"

#include "core/math/noise.hpp"
#include "core/math/random.hpp"
#include "core/math/constants.hpp"
#include "core/math/smoothstep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace draught {

namespace {

constexpr double kBelowFloor = 0.012;   // m: the band starts this far below the cavity's floor (the glass's base is cold too)
constexpr double kLowest = 0.002;       // m: and no lower than this above the foot (the coaster's wet ring is not drawn)
constexpr double kFogFadeTop = 0.006;   // m: the fog thins out over this below the band's top
constexpr double kBeadFadeTop = 0.004;  // m: and so do the beads
constexpr double kShedLength = 0.15;    // m: a running bead keeps exp(-distance / this) of its water
constexpr double kRefogSeconds = 45;    // s: how fast a trail fogs over again (at the default growth)
constexpr double kStopFraction = 0.85;  // a running bead shrunk below this of slide_radius is pinned again
constexpr long kFullMergeSteps = 15;     // every half second every bead is checked for touching another (growth is slow)
constexpr int kSeedBeads = 1, kSeedSize = 2, kSeedStep = 3, kSeedNew = 4;  // the random streams

// Into [-pi, pi).
double wrap(double a) { return a - 2 * kPi * std::floor((a + kPi) / (2 * kPi)); }

// A standard normal deviate (Box-Muller) from two uniforms.
double normal(Rng& rng) {
  const double u = std::max(rng.uniform(), 1e-12), v = rng.uniform();
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * v);
}

// Distance from q to the segment a-b, minus r (a capsule), in the wall's metres.
double capsule(glm::dvec2 q, glm::dvec2 a, glm::dvec2 b, double r) {
  const glm::dvec2 ab = b - a;
  const double t = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(q - (a + t * ab)) - r;
}

}  // namespace

double bead_volume(double radius, double contact_angle) {
  const double c = std::cos(contact_angle), R = radius / std::sin(contact_angle);
  return kPi / 3 * R * R * R * (2 + c) * (1 - c) * (1 - c);
}

Condensation::Condensation(const CondensationParams& p, const Vessel& vessel, double level)
    : params_(p), vessel_(vessel) {
  state_.contact_angle = float(glm::radians(std::clamp(double(p.contact_angle), 20.0, 90.0)));
  const double top = std::min(level + double(p.margin), vessel.height - 2 * vessel.rim_minor);
  state_.band = {std::max(kLowest, vessel.base - kBelowFloor), top};
  state_.fog.assign(size_t(kFogAngles) * kFogRows, 0.0f);
  fog_target_ = state_.fog;
  if (state_.band.empty()) return;  // an empty glass (or one too short): dry
  seed_fog();
  seed_beads();
  merged_upto_ = state_.beads.size();  // (seeded apart: none touch)
  aged_ = std::clamp(double(p.age), 0.0, 600.0);
  const long aging = std::lround(aged_ / kStep);
  aged_ = double(aging) * kStep;
  for (long i = 0; i < aging; ++i) step();
}

double Condensation::wall_radius(double y) const { return vessel_.outer_radius(y); }

double Condensation::arc(const Bead& a, const Bead& b) const {
  return wall_radius(0.5 * (a.y + b.y)) * wrap(b.angle - a.angle);
}

double Condensation::hand_print(double a, double y) const {
  if (!params_.hand) return 0;
  // The wall's metres from the palm's centre: across (around the wall) and up.
  const glm::dvec2 q{wall_radius(y) * wrap(a - glm::radians(double(params_.hand_angle))), y - params_.hand_height};
  // The palm, and the fingers wrapped round the glass to one side, the thumb to the other.
  double d = glm::length(q / glm::dvec2(0.028, 0.042)) - 1.0;
  d *= 0.028;
  constexpr double heights[4] = {0.027, 0.009, -0.01, -0.028}, lengths[4] = {0.075, 0.085, 0.08, 0.062};
  for (int f = 0; f < 4; ++f)
    d = std::min(d, capsule(q, {0.015, heights[f]}, {0.015 + lengths[f], heights[f] - 0.004}, 0.0085));
  d = std::min(d, capsule(q, {-0.015, 0.012}, {-0.06, 0.03}, 0.01));
  return smoothstep(0.002, -0.001, d);
}

void Condensation::seed_fog() {
  const CondensationBand& b = state_.band;
  const double cover = std::clamp(double(params_.coverage), 0.0, 1.0);
  for (int r = 0; r < kFogRows; ++r) {
    const double y = b.y0 + (r + 0.5) / kFogRows * (b.y1 - b.y0);
    const double fade = smoothstep(b.y1, b.y1 - kFogFadeTop, y) * smoothstep(b.y0, b.y0 + 0.003, y);
    const double radius = wall_radius(y);
    for (int c = 0; c < kFogAngles; ++c) {
      const double a = -kPi + (c + 0.5) * 2 * kPi / kFogAngles;
      // Patchy: denser and thinner breath over a few centimetres (seamless round the axis).
      const glm::vec3 at = glm::vec3(glm::dvec3(radius * std::sin(a), y, radius * std::cos(a)) * 60.0) +
                           glm::vec3(float(params_.seed % 997) * 1.37f);
      const double patch = 0.75 + 0.5 * value_noise(at);
      fog_target_[size_t(r) * kFogAngles + c] =
          float(std::clamp(cover * patch, 0.0, 1.0) * fade * (1 - hand_print(a, y)));
    }
  }
  state_.fog = fog_target_;
}

void Condensation::seed_beads() {
  const CondensationBand& b = state_.band;
  const double size = std::clamp(double(params_.size), 0.0002, 0.004);
  const double spread = std::clamp(double(params_.spread), 0.0, 1.2);
  // Seeded beads have not run yet: all below the size that runs (runs come from growth
  // and merging, a few at a time, as on a glass just out of the fridge).
  const double largest = 0.9 * std::clamp(double(params_.slide_radius), 0.001, 0.006);
  const int count = std::clamp(params_.count, 0, 8000);
  // Beads never overlap (touching ones would have merged): a new bead that would is left
  // out, found through a grid of cells as wide as the largest bead.
  const double cell = 2 * largest;
  const double widest = std::max({wall_radius(b.y0), wall_radius(0.5 * (b.y0 + b.y1)), wall_radius(b.y1)});
  const int across = std::max(1, int(2 * kPi * widest / cell)), rows = std::max(1, int((b.y1 - b.y0) / cell) + 1);
  std::vector<std::vector<int>> cells(size_t(across) * size_t(rows));
  auto cell_of = [&](double a, double y, int& c, int& r) {
    c = std::clamp(int((a + kPi) / (2 * kPi) * across), 0, across - 1);
    r = std::clamp(int((y - b.y0) / cell), 0, rows - 1);
  };
  for (int i = 0; i < count; ++i) {
    Rng rng(std::uint64_t(params_.seed), kSeedBeads, std::uint64_t(i));
    Bead bead;
    bead.angle = -kPi + 2 * kPi * rng.uniform();
    bead.y = b.y0 + (b.y1 - b.y0) * rng.uniform();
    const double keep = smoothstep(b.y1, b.y1 - kBeadFadeTop, bead.y);
    if (rng.uniform() >= keep || hand_print(bead.angle, bead.y) > 0.5) continue;
    Rng sizes(std::uint64_t(params_.seed), kSeedSize, std::uint64_t(i));
    bead.radius = std::clamp(size * std::exp(spread * normal(sizes)), 0.15 * size, largest);
    int c, r;
    cell_of(bead.angle, bead.y, c, r);
    bool free = true;
    for (int dr = -1; dr <= 1 && free; ++dr)
      for (int dc = -1; dc <= 1 && free; ++dc) {
        if (r + dr < 0 || r + dr >= rows) continue;
        for (int j : cells[size_t(r + dr) * size_t(across) + size_t(((c + dc) % across + across) % across)]) {
          const Bead& o = state_.beads[size_t(j)];
          const double x = arc(bead, o), y = o.y - bead.y;
          if (x * x + y * y < (bead.radius + o.radius) * (bead.radius + o.radius)) {
            free = false;
            break;
          }
        }
      }
    if (!free) continue;
    cells[size_t(r) * size_t(across) + size_t(c)].push_back(int(state_.beads.size()));
    state_.beads.push_back(bead);
  }
}

void Condensation::place_bead(const Bead& b) {
  if (state_.band.empty() || !(b.radius > 0) || !std::isfinite(b.angle) || !std::isfinite(b.y)) return;
  Bead c = b;
  c.angle = wrap(c.angle);
  c.y = std::clamp(c.y, state_.band.y0, state_.band.y1);
  c.radius = std::min(c.radius, 0.02);
  state_.beads.push_back(c);
  ++state_.version;
}

void Condensation::advance_to(double t) {
  if (state_.band.empty()) return;
  while (time() + kStep <= t + 1e-9) step();
}

void Condensation::step() {
  ++steps_;
  if (state_.band.empty()) return;
  grow_and_nucleate();
  slide();
  merge(steps_ % kFullMergeSteps == 0);
  refog();
  ++state_.version;
}

void Condensation::grow_and_nucleate() {
  const double growth = std::clamp(double(params_.growth), 0.0, 1e-4);
  for (Bead& b : state_.beads)
    if (!b.sliding) b.radius += growth * kStep;
  if (growth <= 0) return;
  // New beads where the fog is: as many a second as keeps a wall of `count` beads whose
  // merging thins them (one in 25 of them a second at the default growth).
  const double size = std::clamp(double(params_.size), 0.0002, 0.004);
  const double rate = std::clamp(params_.count, 0, 8000) / 25.0 * growth / 4e-6;
  Rng rng(std::uint64_t(params_.seed), kSeedNew, std::uint64_t(steps_));
  const int n = int(rate * kStep + rng.uniform());
  const CondensationBand& band = state_.band;
  for (int i = 0; i < n; ++i) {
    Bead b;
    b.angle = -kPi + 2 * kPi * rng.uniform();
    b.y = band.y0 + (band.y1 - band.y0) * rng.uniform();
    b.radius = size * (0.25 + 0.2 * rng.uniform());
    const double target = fog_target_[size_t(std::clamp(int((b.y - band.y0) / (band.y1 - band.y0) * kFogRows), 0, kFogRows - 1)) * kFogAngles +
                                      size_t(std::clamp(int((b.angle + kPi) / (2 * kPi) * kFogAngles), 0, kFogAngles - 1))];
    if (target > 0.05 && fog_cell(b.angle, b.y) >= 0.5 * target) state_.beads.push_back(b);
  }
}

void Condensation::slide() {
  const double slide_radius = std::clamp(double(params_.slide_radius), 0.001, 0.006);
  std::vector<Bead>& beads = state_.beads;
  for (size_t i = 0; i < beads.size(); ++i) {
    Bead& b = beads[i];
    if (!b.sliding && b.radius > slide_radius) b.sliding = true;
    if (!b.sliding) continue;
    // Heavier beads run faster (a few centimetres a second: a pint's wall in a few seconds).
    const double v = std::min(0.15, 0.012 + 0.06 * (b.radius / slide_radius - 1));
    const double was = b.y, dy = v * kStep;
    b.y -= dy;
    // A trail meanders a little: the glass's wetting is not even.
    Rng rng(std::uint64_t(params_.seed), kSeedStep, std::uint64_t(steps_) * 8192 + i % 8192);
    b.angle = wrap(b.angle + (rng.uniform() - 0.5) * 0.5 * dy / wall_radius(b.y));
    const double before = b.radius;
    b.radius *= std::cbrt(std::exp(-dy / kShedLength));
    shed_ += bead_volume(before, state_.contact_angle) - bead_volume(b.radius, state_.contact_angle);
    clear_fog(b.angle, b.y, was, 0.8 * b.radius);
    if (b.radius < kStopFraction * slide_radius) b.sliding = false;
  }
  // Beads run off the band's foot.
  const double floor = state_.band.y0;
  size_t k = 0, old_kept = 0;
  for (size_t i = 0; i < beads.size(); ++i) {
    if (beads[i].y - 0.5 * beads[i].radius < floor) {
      drained_ += bead_volume(beads[i].radius, state_.contact_angle);
      continue;
    }
    old_kept += i < merged_upto_;
    beads[k++] = beads[i];
  }
  beads.resize(k);
  merged_upto_ = old_kept;  // (the new beads stay after the old)
}

void Condensation::merge(bool everything) {
  std::vector<Bead>& beads = state_.beads;
  // Which beads may touch another: all of them now and then (growth is slow), else the
  // running ones and the new ones (and what merged in the pass before).
  std::vector<char> look(beads.size(), 0);
  for (size_t i = 0; i < beads.size(); ++i) look[i] = everything || beads[i].sliding || i >= merged_upto_;
  const CondensationBand& band = state_.band;
  for (int pass = 0; pass < 8 && beads.size() > 1; ++pass) {
    // A grid of cells as wide as the largest bead: touching beads are in neighbouring cells.
    // At most 512 cells a side (wider cells are as right, only slower): with no bead of
    // any size yet, cells of a bead's width would be tens of millions of cells a step.
    double largest = 0;
    for (const Bead& b : beads) largest = std::max(largest, b.radius);
    const double widest = std::max({wall_radius(band.y0), wall_radius(0.5 * (band.y0 + band.y1)), wall_radius(band.y1)});
    const double cell = std::max({2 * largest, 2 * kPi * widest / 512, (band.y1 - band.y0) / 512});
    const int across = std::max(1, int(2 * kPi * widest / cell)), rows = std::max(1, int((band.y1 - band.y0 + 2 * cell) / cell) + 1);
    auto row_of = [&](double y) { return std::clamp(int((y - band.y0 + cell) / cell), 0, rows - 1); };
    auto col_of = [&](double a) { return std::clamp(int((wrap(a) + kPi) / (2 * kPi) * across), 0, across - 1); };
    grid_.resize(size_t(across) * size_t(rows));
    for (std::vector<int>& g : grid_) g.clear();
    for (size_t i = 0; i < beads.size(); ++i) grid_[size_t(row_of(beads[i].y)) * size_t(across) + size_t(col_of(beads[i].angle))].push_back(int(i));
    std::vector<char> gone(beads.size(), 0), grew(beads.size(), 0);
    bool merged = false;
    for (size_t i = 0; i < beads.size(); ++i) {
      if (!look[i] || gone[i]) continue;
      const int r = row_of(beads[i].y), c = col_of(beads[i].angle);
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if (r + dr < 0 || r + dr >= rows || (across < 3 && dc != 0)) continue;
          for (int j : grid_[size_t(r + dr) * size_t(across) + size_t(((c + dc) % across + across) % across)]) {
            if (size_t(j) == i || gone[size_t(j)] || (everything && size_t(j) < i && look[size_t(j)])) continue;
            Bead &a = beads[i], &b = beads[size_t(j)];
            const double x = arc(a, b), up = b.y - a.y;
            if (x * x + up * up >= (a.radius + b.radius) * (a.radius + b.radius)) continue;
            // One bead of both volumes at their centre of mass (a fixed contact angle: volume ~ r^3).
            const double va = a.radius * a.radius * a.radius, vb = b.radius * b.radius * b.radius, w = vb / (va + vb);
            a.angle = wrap(a.angle + w * wrap(b.angle - a.angle));
            a.y += w * up;
            a.radius = std::cbrt(va + vb);
            a.sliding = a.sliding || b.sliding;
            gone[size_t(j)] = 1;
            grew[i] = 1;
            merged = true;
          }
        }
    }
    if (!merged) break;
    size_t k = 0;
    for (size_t i = 0; i < beads.size(); ++i)
      if (!gone[i]) {
        look[k] = grew[i];  // a bead that grew may touch another now
        beads[k++] = beads[i];
      }
    beads.resize(k);
    look.resize(k);
    everything = false;
  }
  merged_upto_ = beads.size();
}

void Condensation::refog() {
  const double growth = std::clamp(double(params_.growth), 0.0, 1e-4);
  if (growth <= 0) return;
  const float k = float(1 - std::exp(-kStep / kRefogSeconds * growth / 4e-6));
  for (size_t i = 0; i < state_.fog.size(); ++i) state_.fog[i] += (fog_target_[i] - state_.fog[i]) * k;
}

float Condensation::fog_cell(double a, double y) const {
  const CondensationBand& b = state_.band;
  const int r = std::clamp(int((y - b.y0) / (b.y1 - b.y0) * kFogRows), 0, kFogRows - 1);
  const int c = std::clamp(int((wrap(a) + kPi) / (2 * kPi) * kFogAngles), 0, kFogAngles - 1);
  return state_.fog[size_t(r) * kFogAngles + c];
}

void Condensation::clear_fog(double angle, double y_low, double y_high, double half_width) {
  const CondensationBand& b = state_.band;
  const double row_height = (b.y1 - b.y0) / kFogRows;
  const int r0 = std::max(0, int(std::floor((y_low - half_width - b.y0) / row_height))),
            r1 = std::min(kFogRows - 1, int(std::ceil((y_high + half_width - b.y0) / row_height)));
  for (int r = r0; r <= r1; ++r) {
    const double y = b.y0 + (r + 0.5) * row_height;
    const double up = y < y_low ? y_low - y : (y > y_high ? y - y_high : 0.0);
    const double radius = wall_radius(y);
    const double cell = 2 * kPi / kFogAngles;
    const int reach = int(std::ceil((half_width / radius) / cell)) + 1;
    const int c0 = int(std::floor((wrap(angle) + kPi) / cell));
    for (int dc = -reach; dc <= reach; ++dc) {
      const int c = ((c0 + dc) % kFogAngles + kFogAngles) % kFogAngles;
      const double a = -kPi + (c + 0.5) * cell;
      const double across = radius * wrap(a - angle);
      const double d = std::sqrt(across * across + up * up);
      state_.fog[size_t(r) * kFogAngles + c] *= float(smoothstep(0.55 * half_width, half_width, d));
    }
  }
}

double Condensation::bead_water() const {
  double v = 0;
  for (const Bead& b : state_.beads) v += bead_volume(b.radius, state_.contact_angle);
  return v;
}

}  // namespace draught
