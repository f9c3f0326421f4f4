#include "core/sim/simulation.hpp"

#include "core/liquid/beverage.hpp"
#include "core/math/vectors.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {
constexpr double kEmpty = 1e-4;  // below this fraction the glass shows no liquid

BubbleSettings bubble_settings(const BubbleParams& p) {
  return {p.carbonation, p.sites, p.etched_base, p.size, p.max_bubbles, p.seed};
}

bool same_bubbles(const BubbleParams& a, const BubbleParams& b) {
  return a.carbonation == b.carbonation && a.sites == b.sites && a.etched_base == b.etched_base && a.size == b.size &&
         a.max_bubbles == b.max_bubbles && a.seed == b.seed;
}

bool same_glass(const GlassParams& a, const GlassParams& b) {
  return a.profile == b.profile && a.wall_thickness == b.wall_thickness && a.base_thickness == b.base_thickness &&
         a.rim_radius == b.rim_radius;
}

}  // namespace

Simulation::Simulation(const VesselParams& p) : params_(p), foam_(p.foam), colour_(drink_absorption(p.liquid)) {
  rebuild_glass();
  fraction_ = p.liquid.fill;  // in [0, 0.98]: the table checked it
  env_.radius = vessel_.inner_radius(vessel_.height);
  update_surface();
  rebuild_condensation();
}

void Simulation::rebuild_glass() {
  vessel_ = build_vessel(params_.glass);
  table_ = std::make_shared<const FillTable>(build_fill_table(vessel_));
  rebuild_bubbles();
}

void Simulation::rebuild_bubbles() { bubbles_.emplace(bubble_settings(params_.bubbles), vessel_); }

void Simulation::set_params(const VesselParams& p) {
  const bool glass_changed = !same_glass(p.glass, params_.glass);
  const bool refill = p.liquid.fill != params_.liquid.fill;
  const bool bubbles_changed = !same_bubbles(p.bubbles, params_.bubbles);
  const bool condensation_changed = !(p.condensation == params_.condensation);
  const LiquidParams& l = params_.liquid;
  const bool colour_changed = p.liquid.ebc != l.ebc || p.liquid.srm != l.srm || p.liquid.wine != l.wine ||
                              p.liquid.absorption != l.absorption;
  params_ = p;
  if (colour_changed) colour_ = drink_absorption(p.liquid);  // a fit of a few ms: not every frame
  foam_.set_params(p.foam);
  if (glass_changed) rebuild_glass();
  else if (bubbles_changed) rebuild_bubbles();
  if (refill || glass_changed) fraction_ = p.liquid.fill;
  update_surface();
  if (refill || glass_changed || condensation_changed) rebuild_condensation();
}

void Simulation::rebuild_condensation() {
  condensation_.reset();
  condensation_frame_.reset();
  if (!params_.condensation.enabled) return;
  condensation_.emplace(params_.condensation, vessel_, table_->offset_at(0, fraction_));
  condensation_->advance_to(time_);
}

void Simulation::set_fraction(double fraction) {
  if (!std::isfinite(fraction)) return;
  fraction_ = std::clamp(fraction, 0.0, 1.0);
  spilled_ = 0;  // a new fill: what spills from now on is of this drink
  update_surface();
}

void Simulation::pour() {
  pour_.reset();
  crater_depth_ = 0;
  fraction_ = params_.liquid.fill;
  spilled_ = 0;  // a new fill: what spills from now on is of this drink
  foam_.pour();
  bubbles_->clear();
  update_surface();
}

namespace {
// Where the pour's spout stands: above the rim, a little behind the axis, so the stream
// lands near the middle of the surface with a slight arc.
constexpr double kSpoutAboveRim = 0.12;    // m
constexpr double kSpoutBehind = 0.35;      // of the rim's radius, towards -z
constexpr double kSpoutSpeed = 0.12;       // m/s forwards (+z) as the liquid leaves the spout
std::uint64_t stream_version() {
  static std::uint64_t counter = std::uint64_t(1) << 40;  // apart from the cloud objects' versions
  return ++counter;
}
}  // namespace

glm::dvec3 Simulation::world(const glm::dvec3& local) const {
  return motion_.pose.position + motion_.pose.orientation * local;
}

void Simulation::pour_over(double seconds) {
  if (!(seconds > 0)) {
    pour();
    return;
  }
  seconds = std::min(seconds, 30.0);
  fraction_ = 0;  // a fresh pour starts with an empty glass
  spilled_ = 0;
  bubbles_->clear();
  update_surface();
  const double volume = params_.liquid.fill * vessel_.cavity_volume();
  GlassStream s;
  const double rim = vessel_.rim_major;
  s.stream.set_origin(world(glm::dvec3(0, vessel_.height + kSpoutAboveRim, -kSpoutBehind * rim)),
                      motion_.pose.orientation * glm::dvec3(0, 0, kSpoutSpeed));
  s.stream.set_target_height(world(glm::dvec3(0, vessel_.base, 0)).y);
  s.stream.set_flow(0, volume / seconds);
  s.end = seconds;
  pour_ = std::move(s);
}

std::vector<CloudFrame> Simulation::streams() const {
  std::vector<CloudFrame> out;
  for (const std::optional<GlassStream>* s : {&pour_, &spill_}) {
    if (!*s || (*s)->stream.in_flight_volume() <= 0) continue;
    CloudFrame f;
    f.points = std::make_shared<const PointCloud>((*s)->stream.cloud());
    f.version = (*s)->version;
    f.material = int(CloudMaterial::Drink);
    f.glow = 0;
    f.ior = params_.liquid.ior;
    f.roughness = params_.liquid.roughness;
    // The drink's colour over the stream's own thickness: the mean chord of a round stream
    // (pi/2 of its radius; its blobs draw it as wide as continuity makes it).
    const double chord = std::clamp(0.5 * M_PI * (*s)->stream.rope_radius(), 1e-3, kColourPathMetres);
    f.absorption = liquid_absorption(params_.liquid, chord);
    out.push_back(std::move(f));
  }
  return out;
}

void Simulation::step_streams(double dt, double spilled_before) {
  const double cavity = vessel_.cavity_volume();
  // The level the stream lands on: the drink's surface where it crosses the axis (the
  // cavity's floor while the glass is empty).
  const double level = fraction_ > kEmpty ? axis_level() : vessel_.base;
  if (pour_) {
    GlassStream& s = *pour_;
    // (down in the dimple it opens there)
    s.stream.set_target_height(world(glm::dvec3(0, level - surface_.waves.dimple_depth, 0)).y);
    // The flow is a clock of its own (started at 0 by pour_over), in step with ours.
    const double t = s.stream.time() + dt;
    if (t >= s.end) s.stream.set_flow(s.end, 0);
    s.stream.advance(dt);
    const double arrived = s.stream.arrived_volume();
    if (s.counted == 0 && arrived > 0) foam_.pour();  // the head builds from the first splash
    fraction_ += (arrived - s.counted) / cavity;
    s.counted = arrived;
    s.version = stream_version();
    if (t >= s.end && s.stream.in_flight_volume() <= 0) pour_.reset();
  }
  // What spilled over the rim this step leaves as a stream from the rim's lowest point,
  // falling to the floor.
  const double spilled = (spilled_ - spilled_before) * cavity;
  if (spilled > 0 && !spill_) {
    spill_.emplace();
    spill_->stream.set_target_height(0.0);
  }
  if (spill_) {
    GlassStream& s = *spill_;
    // The rim is lowest against the surface's normal, opposite its lean (glass frame).
    StreamLip lip;
    lip.centre = world(glm::dvec3(0, vessel_.height, 0));
    lip.up = glm::normalize(motion_.pose.orientation * glm::dvec3(0, 1, 0));
    lip.outward = glm::normalize(motion_.pose.orientation * glm::dvec3(-std::cos(azimuth_), 0, -std::sin(azimuth_)));
    lip.radius = vessel_.rim_major + vessel_.rim_minor;
    s.stream.set_lip(lip);
    s.stream.set_flow(s.stream.time(), spilled / dt);
    s.stream.advance(dt);
    s.version = stream_version();
    if (spilled <= 0 && s.stream.in_flight_volume() <= 0) spill_.reset();
  }
}

void Simulation::step_crater(double dt) {
  // A stream of any pour's strength punches through a head (its dynamic pressure, about
  // 1 kPa at 1.5 m/s, is far above what a foam bears), and the foam it drags down opens
  // a dimple about two and a half of its radii wide. It opens in a tenth of a second and
  // flows back in about a third once the stream has passed.
  constexpr double kWidth = 2.5, kOpen = 0.1, kClose = 0.3;
  std::optional<PourStream::Landing> l;
  if (pour_) l = pour_->stream.landing();
  const double target = l ? FoamFrame::kMaxCraterDepth : 0.0;
  if (l) {
    const glm::dvec3 local = glm::inverse(motion_.pose.orientation) * (l->position - motion_.pose.position);
    crater_xz_ = {local.x, local.z};
    crater_radius_ = kWidth * l->radius;
    stream_radius_ = l->radius;
  }
  crater_depth_ += (target - crater_depth_) * (1 - std::exp(-dt / (target > crater_depth_ ? kOpen : kClose)));
  if (crater_depth_ < 0.01 && !l) crater_depth_ = 0;  // (a dimple of a hundredth is gone)
  place_dimple();
}

void Simulation::place_dimple() {
  // The drink's surface dips under the stream about as deep as the stream is thick (a
  // plunging jet's cavity at these speeds), never more than 0.4 of the drink's depth at
  // the axis (it must not reach the glass's floor), nor so far that its ring (0.14 of its
  // depth) would rise past the rim.
  SurfaceWaves& w = surface_.waves;
  const double open = crater_depth_ / FoamFrame::kMaxCraterDepth;
  const double limit = std::min(0.4 * (axis_level() - vessel_.base), 5.0 * headroom());
  w.dimple_xz = crater_xz_;
  w.dimple_radius = crater_radius_;
  w.dimple_depth = fraction_ > kEmpty && crater_radius_ > 0 ? std::max(open * std::min(stream_radius_, limit), 0.0) : 0.0;
}

void Simulation::settle_bubbles(double seconds) {
  const glm::dvec3 up = glm::inverse(motion_.pose.orientation) * glm::dvec3(0, 1, 0);
  for (double t = 0; t < std::min(seconds, 30.0); t += kStep) bubbles_->step(kStep, surface_, up);
}

void Simulation::update_surface() {
  // The surface normal: world up tilted by the slosh slope, seen from the glass.
  const glm::dvec3 n_world = glm::normalize(glm::dvec3(slosh_.slope.x, 1.0, slosh_.slope.y));
  const glm::dvec3 n = glm::normalize(glm::inverse(motion_.pose.orientation) * n_world);
  tilt_ = std::acos(std::clamp(n.y, -1.0, 1.0));
  azimuth_ = std::atan2(n.z, n.x);
  // Past the rim the excess spills; what stays is the new volume.
  const double capacity = table_->capacity_at(tilt_);
  if (fraction_ > capacity) {
    spilled_ += fraction_ - capacity;
    fraction_ = capacity;
  }
  surface_.n = n;
  // Never above the lowest rim point (the table is accurate to ~0.1 %; the rim is exact).
  surface_.offset = fraction_ > kEmpty ? std::min(table_->offset_at(tilt_, fraction_), rim_offset(vessel_, tilt_)) : -1.0;
  // Waves stay below the rim now, not only from the next step on (a refill, a spill).
  // Wave shapes reach at most 1 (ring) and 1.5625 (cross) anywhere on the surface.
  const double room = headroom();
  const double peak = std::abs(slosh_.ring) + 1.5625 * (std::abs(slosh_.cross.x) + std::abs(slosh_.cross.y));
  if (peak > 0.9 * room) {
    const double k = peak > 0 ? 0.9 * room / peak : 0.0;
    slosh_.ring *= k, slosh_.ring_rate *= k, slosh_.cross *= k, slosh_.cross_rate *= k;
  }
  // Where the surface crosses the axis: its radius and depth set the slosh frequency.
  surface_.waves.radius = std::max(vessel_.inner_radius(axis_level()), 1e-3);
  surface_.waves.ring = slosh_.ring;
  surface_.waves.cross = slosh_.cross;
  place_dimple();
}

double Simulation::axis_level() const {
  const double axis = surface_.n.y > 0.2 ? surface_.offset / surface_.n.y : vessel_.height;
  return std::clamp(axis, vessel_.base + 1e-4, vessel_.height);
}

double Simulation::headroom() const { return std::max(rim_offset(vessel_, tilt_) - surface_.offset, 0.0); }

SloshEnvironment Simulation::environment(const glm::dvec3& accel, double dt) const {
  SloshEnvironment e;
  // The surface rests perpendicular to the effective gravity g - a.
  const double gy = std::max(kGravity + accel.y, 0.2 * kGravity);
  glm::dvec2 level = glm::dvec2(accel.x, accel.z) / gy;
  e.max_slope = 1.5;  // ~56 degrees
  if (glm::length(level) > e.max_slope) level *= e.max_slope / glm::length(level);
  e.level_slope = level;
  e.level_rate = first_step_ ? glm::dvec2(0.0) : (level - level_) / dt;
  e.radius = surface_.waves.radius;
  e.depth = axis_level() - vessel_.base;
  // Waves stay below the rim: at most part of the headroom between surface and rim.
  e.max_wave = std::min(0.4 * headroom(), 0.25 * e.radius);
  return e;
}

void Simulation::step(const MotionSample& raw, double drink_rate) {
  MotionSample m = sanitize(raw);
  m.pose = resting_on_floor(m.pose, vessel_);  // whatever drives it, the glass does not sink into the floor
  const double dt = kStep;
  time_ += dt;
  // Acceleration of the liquid's middle: the glass's own plus what its rotation adds there.
  const double centre = 0.5 * (vessel_.base + axis_level());
  const glm::dvec3 r = m.pose.orientation * glm::dvec3(0, centre, 0);
  const glm::dvec3 w = m.angular_velocity;
  const glm::dvec3 alpha =
      first_step_ ? glm::dvec3(0.0) : clamp_length((w - motion_.angular_velocity) / dt, 2000.0);
  const glm::dvec3 accel = clamp_length(m.linear_acceleration + glm::cross(alpha, r) + glm::cross(w, glm::cross(w, r)), 200.0);
  env_ = environment(accel, dt);
  if (first_step_) slosh_.slope = env_.level_slope;
  step_slosh(slosh_, params_.liquid, env_, dt);
  level_ = env_.level_slope;
  motion_ = m;
  first_step_ = false;
  if (std::isfinite(drink_rate) && drink_rate > 0) fraction_ = std::max(fraction_ - drink_rate * dt, 0.0);
  const double spilled_before = spilled_;
  update_surface();
  if (pour_ || spill_ || spilled_ > spilled_before) {
    step_streams(dt, spilled_before);
    update_surface();
  }
  step_crater(dt);
  // The head follows the volume (the level the drink would have upright), not the slosh.
  const double level = table_->offset_at(0, fraction_);
  foam_.step(dt, level, vessel_.inner_radius(std::clamp(level, vessel_.base, vessel_.height)));
  // Bubbles rise against gravity: world up, seen from the glass.
  bubbles_->step(dt, surface_, glm::inverse(m.pose.orientation) * glm::dvec3(0, 1, 0));
  if (condensation_) condensation_->advance_to(time_);
}

void Simulation::place(const Pose& pose) { motion_.pose = pose; }

void Simulation::skip_to(double t) {
  if (std::isfinite(t) && t > time_) time_ = t;
}

void Simulation::advance(InputDriver& driver, double t, double drink_rate) {
  if (!std::isfinite(t)) return;
  if (t - time_ > kMaxCatchUp) time_ = t - kMaxCatchUp;
  while (time_ + kStep <= t + 1e-9) step(driver.sample(time_ + kStep), drink_rate);
}

double Simulation::energy() const { return slosh_energy(slosh_, params_.liquid, env_); }

VesselFrame Simulation::frame() const {
  VesselFrame f;
  f.params = params_;
  f.vessel = vessel_;
  f.fill_table = table_;
  f.pose = motion_.pose;
  f.liquid = surface_;
  f.liquid_tilt = tilt_;
  f.liquid_azimuth = azimuth_;
  f.liquid_fraction = fraction_;
  f.has_liquid = fraction_ > kEmpty;
  f.liquid_absorption = colour_;
  f.foam = foam_.frame(surface_.waves.radius);
  f.foam.crater_xz = crater_xz_;
  f.foam.crater_radius = crater_radius_;
  f.foam.crater_depth = crater_depth_;
  f.big_bubbles = place_big_bubbles(f.foam, surface_.n, surface_.offset, surface_.waves.radius);
  if (f.has_liquid) f.bubbles = bubbles_->bubbles();  // (an empty glass holds none: no drink to rise in)
  double sum = 0;
  for (double r : vessel_.r_outer) sum += r;
  f.mean_outer_radius = sum / double(vessel_.r_outer.size());
  if (condensation_) {
    if (!condensation_frame_ || condensation_frame_->version != condensation_->state().version)
      condensation_frame_ = std::make_shared<const CondensationState>(condensation_->state());
    f.condensation = condensation_frame_;
  }
  return f;
}

}  // namespace draught
