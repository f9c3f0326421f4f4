// The drink over time: a shake dies out to an exact, level rest; a tipped glass settles
// level; sloshing keeps the volume and stays inside the glass; tipping spills down to
// what the glass holds; hostile input stays finite; the same input gives the same states.
#include "core/sim/simulation.hpp"

#include "core/params/preset.hpp"
#include "core/math/constants.hpp"
#include "core/math/vectors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

namespace draught {
namespace {

constexpr double kDt = Simulation::kStep;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
double deg(double d) { return d * kPi / 180; }

Params lager_in_pint(float fill) {
  Params p = resolve_scene({"lager", "pint", {}, {}});
  p.liquid.fill = fill;
  return p;
}

// Horizontal shake x = A sin(w t) along `dir` until `until`, then still; the acceleration
// is the position's second derivative.
struct ShakeDriver : InputDriver {
  double amplitude, omega, until;
  glm::dvec3 dir{1, 0, 0};
  ShakeDriver(double a, double w, double u, glm::dvec3 d = {1, 0, 0}) : amplitude(a), omega(w), until(u), dir(d) {}
  const char* name() const override { return "shake"; }
  MotionSample sample(double t) override {
    MotionSample m;
    m.time = t;
    if (t < until) {
      m.pose.position = dir * amplitude * std::sin(omega * t);
      m.linear_acceleration = -dir * amplitude * omega * omega * std::sin(omega * t);
    }
    return m;
  }
};

// Tips the glass by angle(t) towards +X, standing on the floor on its foot rim; rates and
// accelerations by central differences of the pose.
struct TipDriver : InputDriver {
  std::function<double(double)> angle;
  double foot;
  TipDriver(std::function<double(double)> a, double f) : angle(std::move(a)), foot(f) {}
  const char* name() const override { return "tip"; }
  Pose pose(double t) const { return tipped_on_floor(tilt_orientation(angle(t), 0.0), foot); }
  MotionSample sample(double t) override {
    const double h = 1e-4;
    MotionSample m;
    m.time = t;
    m.pose = pose(t);
    m.angular_velocity = glm::dvec3(0, 0, -1) * (angle(t + h) - angle(t - h)) / (2 * h);  // up x (+X)
    m.linear_acceleration = (pose(t + h).position - 2.0 * m.pose.position + pose(t - h).position) / (h * h);
    return m;
  }
};

// 0 before t0, `to` after t0 + len, smoothstep between.
double ramp(double t, double t0, double len, double to) {
  const double u = std::clamp((t - t0) / len, 0.0, 1.0);
  return to * u * u * (3 - 2 * u);
}

// Angle between the surface's normal in the world and world up, degrees.
double world_normal_angle(const Simulation& sim) {
  const glm::dvec3 n = sim.motion().pose.orientation * sim.surface().n;
  return std::atan2(std::hypot(n.x, n.z), n.y) * 180 / kPi;
}

// How far the rim circle stands clear of the liquid (plane + waves): min of level() over
// the rim; negative means liquid above the rim somewhere.
double rim_clearance(const Simulation& sim) {
  const Vessel& v = sim.vessel();
  const double R = v.inner_radius(v.height);
  double clear = kInf;
  for (int i = 0; i < 360; ++i) {
    const double a = 2 * kPi * i / 360;
    clear = std::min(clear, sim.surface().level({R * std::cos(a), v.height, R * std::sin(a)}));
  }
  return clear;
}

// The liquid's volume in a glass whose inner radius grows with height (the pint): a
// fine grid of vertical columns; each column is inside the cavity from floor(r) up to
// the rim, and in the liquid below where level() crosses 0 (level is linear in y).
struct ColumnVolume {
  std::vector<double> x, z, floor;
  double cell = 0, top = 0;
  explicit ColumnVolume(const Vessel& v, int n = 500) {
    top = v.height;
    const double R = v.inner_radius(v.height);
    cell = 2 * R / n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double cx = -R + (i + 0.5) * cell, cz = -R + (j + 0.5) * cell, r = std::hypot(cx, cz);
        if (r > R) continue;
        double lo = v.base, hi = v.height;  // lowest y with inner_radius(y) >= r
        if (v.inner_radius(lo) >= r) hi = lo;
        for (int k = 0; k < 60 && hi > lo; ++k) (v.inner_radius(0.5 * (lo + hi)) < r ? lo : hi) = 0.5 * (lo + hi);
        x.push_back(cx), z.push_back(cz), floor.push_back(hi);
      }
  }
  double operator()(const LiquidPlane& L) const {
    double sum = 0;
    for (size_t k = 0; k < x.size(); ++k) {
      const double surface = -L.level({x[k], 0.0, z[k]}) / L.n.y;
      sum += std::max(std::min(surface, top) - floor[k], 0.0);
    }
    return sum * cell * cell;
  }
};

bool all_finite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// Everything a renderer reads is finite and physical.
void expect_sane(const Simulation& sim, const std::string& when) {
  SCOPED_TRACE(when);
  const SloshState& s = sim.slosh();
  EXPECT_TRUE(all_finite(s.slope) && all_finite(s.slope_rate) && all_finite(s.cross) && all_finite(s.cross_rate));
  EXPECT_TRUE(std::isfinite(s.ring) && std::isfinite(s.ring_rate));
  EXPECT_TRUE(std::isfinite(sim.energy()));
  EXPECT_TRUE(std::isfinite(sim.time()));
  EXPECT_GE(sim.fraction(), 0.0);
  EXPECT_LE(sim.fraction(), 1.0);
  EXPECT_TRUE(std::isfinite(sim.spilled()) && sim.spilled() >= 0);
  const LiquidPlane& L = sim.surface();
  EXPECT_TRUE(all_finite(L.n) && std::isfinite(L.offset));
  EXPECT_NEAR(glm::length(L.n), 1.0, 1e-9);
  EXPECT_TRUE(std::isfinite(L.waves.ring) && all_finite(L.waves.cross) && std::isfinite(L.waves.radius));
  EXPECT_TRUE(all_finite(sim.motion().pose.position));
  if (sim.fraction() > 1e-4) {  // 0.1 mm: the table's accuracy, far below a pixel
    EXPECT_GE(rim_offset(sim.vessel(), sim.frame().liquid_tilt) - L.offset, -1e-4) << "plane above the rim";
    EXPECT_GE(rim_clearance(sim), -1e-4) << "plane + waves above the rim";
  }
}

TEST(Simulation, ShakeDiesOutToAnExactLevelRest) {
  Simulation sim(lager_in_pint(0.86f));
  ShakeDriver shake(0.01, 2 * kPi * 2.0, 1.5);  // 1 cm at 2 Hz: three whole periods
  std::vector<double> energy;
  for (int i = 1; i <= int(14.0 / kDt); ++i) {
    sim.advance(shake, i * kDt);
    energy.push_back(sim.energy());
  }
  const size_t shake_end = size_t(1.5 / kDt);
  EXPECT_GT(*std::max_element(energy.begin(), energy.begin() + shake_end), 0.1) << "the shake must move the drink";
  // 0.25 s windows after the shake: the mean falls until it is exactly zero.
  double last = kInf;
  for (size_t w = shake_end; w + 60 <= energy.size(); w += 60) {
    double mean = 0;
    for (size_t i = w; i < w + 60; ++i) mean += energy[i] / 60;
    if (last > 0) EXPECT_LT(mean, last) << "window at t = " << (w + 1) * kDt;
    else EXPECT_EQ(mean, 0.0) << "window at t = " << (w + 1) * kDt;
    last = mean;
  }
  // ~10 when the shake ends, then e^(-2 zeta w t) with zeta 0.06, w ~ 20 rad/s: ~1e-10
  // after 12 s, where the model snaps to rest.
  const size_t after = shake_end + size_t(12.0 / kDt) - 1;
  EXPECT_LT(energy[after], 1e-9);
  EXPECT_TRUE(at_rest(sim.slosh())) << "still moving at t = " << sim.time();
  EXPECT_EQ(sim.energy(), 0.0);
  EXPECT_LT(world_normal_angle(sim), 0.01);
  EXPECT_EQ(sim.surface().waves.ring, 0.0);
  EXPECT_EQ(sim.surface().waves.cross, glm::dvec2(0.0));
  EXPECT_EQ(sim.spilled(), 0.0);
}

TEST(Simulation, TippedGlassSettlesLevelAndKeepsItsVolume) {
  const Params p = lager_in_pint(0.6f);
  Simulation sim(p);
  TipDriver tip([](double t) { return ramp(t, 0.2, 0.8, deg(25)); }, sim.vessel().outer_radius(0));
  double max_angle = 0;
  for (int i = 1; i <= int(1.0 / kDt); ++i) {
    sim.advance(tip, i * kDt);
    max_angle = std::max(max_angle, world_normal_angle(sim));
  }
  EXPECT_GT(max_angle, 0.5) << "tipping must disturb the surface";
  for (int i = int(1.0 / kDt) + 1; i <= int(12.0 / kDt); ++i) sim.advance(tip, i * kDt);
  EXPECT_NEAR(tilt_angle(sim.motion().pose.orientation), deg(25), 1e-9);
  EXPECT_LT(world_normal_angle(sim), 0.01);
  EXPECT_NEAR(sim.frame().liquid_tilt, deg(25), deg(0.01)) << "level in the world = 25 deg in the glass";
  EXPECT_TRUE(at_rest(sim.slosh()));
  EXPECT_EQ(sim.fraction(), double(p.liquid.fill)) << "nothing spilled, nothing lost";
  EXPECT_EQ(sim.spilled(), 0.0);
  // The plane really holds that volume: the reference integrator agrees within 0.1 %.
  const double held = volume_below_plane(sim.vessel(), sim.frame().liquid_tilt, sim.surface().offset);
  EXPECT_NEAR(held / sim.vessel().cavity_volume(), sim.fraction(), 1e-3);
}

TEST(Simulation, SloshingKeepsVolumeAndStaysInsideTheGlass) {
  Simulation sim(lager_in_pint(0.5f));
  const ColumnVolume volume(sim.vessel());
  const double cavity = sim.vessel().cavity_volume();
  // The integrator itself, at rest: the upright level holds the fill.
  EXPECT_NEAR(volume(sim.surface()) / cavity, 0.5, 1e-3);
  // Near the first mode (~3.5 Hz at this level), 1.5 cm diagonally: vigorous, yet below the rim.
  ShakeDriver shake(0.015, 2 * kPi * 3.0, 2.0, glm::normalize(glm::dvec3(1, 0, 0.6)));
  double worst = 0, max_slope = 0, max_wave = 0, min_clear = kInf;
  for (int i = 1; i <= int(3.0 / kDt); ++i) {
    sim.advance(shake, i * kDt);
    const LiquidPlane& L = sim.surface();
    max_slope = std::max(max_slope, glm::length(sim.slosh().slope));
    max_wave = std::max({max_wave, std::abs(L.waves.ring), glm::length(L.waves.cross)});
    min_clear = std::min(min_clear, rim_clearance(sim));
    if (i % 8 == 0) {
      ASSERT_GT(L.n.y, 0.2);
      worst = std::max(worst, std::abs(volume(L) / cavity - sim.fraction()) / sim.fraction());
    }
  }
  ASSERT_EQ(sim.spilled(), 0.0) << "this shake must not spill";
  EXPECT_GT(max_slope, 0.3) << "the shake must be vigorous";
  EXPECT_GT(max_wave, 0.002) << "and raise waves";
  EXPECT_LE(worst, 0.01) << "volume drift while sloshing, relative";
  EXPECT_GT(min_clear, 0.0) << "liquid above the rim";
}

TEST(Simulation, RefillWhileSloshingStaysBelowTheRim) {
  // Waves are limited by the headroom between surface and rim; a refill to the brim in
  // the middle of a slosh takes that headroom away at once. Refill a copy at every step.
  Simulation sim(lager_in_pint(0.5f));
  ShakeDriver shake(0.015, 2 * kPi * 3.0, 10.0, glm::normalize(glm::dvec3(1, 0, 0.6)));
  double max_wave = 0, min_clear = kInf, at = 0;
  for (int i = 1; i <= int(1.5 / kDt); ++i) {
    sim.advance(shake, i * kDt);
    max_wave = std::max({max_wave, std::abs(sim.surface().waves.ring), glm::length(sim.surface().waves.cross)});
    Simulation refilled = sim;
    refilled.set_fraction(1.0);
    ASSERT_LE(refilled.fraction(), refilled.fill_table().capacity_at(refilled.frame().liquid_tilt) + 1e-12);
    if (rim_clearance(refilled) < min_clear) min_clear = rim_clearance(refilled), at = sim.time();
  }
  ASSERT_GT(max_wave, 0.002) << "the shake must raise waves";
  EXPECT_GE(min_clear, -1e-4) << "plane + waves above the rim after a refill at t = " << at;
}

TEST(Simulation, SpilledCountsFromTheLastFill) {
  // Pours into a glass held tipped far past the rim spill almost everything each time;
  // what is reported is the spill of the drink in the glass now (since the last fill),
  // never more than was poured, not a sum over the pours (which reached 538.8 %).
  const Params p = lager_in_pint(0.86f);
  Simulation sim(p);
  TipDriver tip([](double t) { return ramp(t, 0.0, 1.0, deg(110)); }, sim.vessel().outer_radius(0));
  double t = 0;
  for (int pour = 0; pour < 6; ++pour) {
    for (const double end = t + 1.5; t < end;) sim.advance(tip, t += kDt);
    ASSERT_GT(sim.spilled(), 0.5) << "pour " << pour << ": a glass held at 110 degrees spills most of it";
    ASSERT_LE(sim.spilled(), double(p.liquid.fill) + 1e-12) << "pour " << pour;
    ASSERT_NEAR(sim.fraction() + sim.spilled(), double(p.liquid.fill), 1e-12) << "pour " << pour;
    sim.pour();  // it spills at once, but only from the new drink
    EXPECT_NEAR(sim.fraction() + sim.spilled(), double(p.liquid.fill), 1e-12) << "a pour starts the count again";
  }
  sim.advance(tip, t += kDt);
  sim.set_fraction(0.3);
  EXPECT_NEAR(sim.fraction() + sim.spilled(), 0.3, 1e-12) << "so does a refill";
}

TEST(Simulation, TippingSpillsDownToCapacityAndNeverRefills) {
  const Params p = lager_in_pint(0.86f);
  Simulation sim(p);
  // Tip slowly to 60 deg, hold, then stand it back up.
  TipDriver tip([](double t) { return ramp(t, 0.0, 4.0, deg(60)) - ramp(t, 8.0, 2.0, deg(60)); },
                sim.vessel().outer_radius(0));
  double prev = sim.fraction(), at_60 = 0, spilled_at_60 = 0, upright = 0;
  for (int i = 1; i <= int(22.0 / kDt); ++i) {
    sim.advance(tip, i * kDt);
    ASSERT_LE(sim.fraction(), prev) << "the volume grew by itself at t = " << sim.time();
    ASSERT_NEAR(sim.fraction() + sim.spilled(), double(p.liquid.fill), 1e-12) << "volume is conserved";
    ASSERT_LE(sim.fraction(), sim.fill_table().capacity_at(sim.frame().liquid_tilt) + 1e-12);
    prev = sim.fraction();
    if (i == int(7.9 / kDt)) at_60 = sim.fraction(), spilled_at_60 = sim.spilled();
    if (i == int(10.5 / kDt)) upright = sim.fraction();
  }
  const double cap60 = sim.fill_table().capacity_at(deg(60));
  EXPECT_GT(spilled_at_60, 0.3);
  EXPECT_LE(at_60, cap60 + 1e-12);
  EXPECT_GT(at_60, cap60 - 0.02) << "a slow tip spills little more than the static excess";
  // Tipping back jolts the surface the other way a little (it may spill a bit more).
  EXPECT_GT(upright, at_60 - 0.02);
  EXPECT_EQ(sim.fraction(), upright) << "standing upright, nothing changes by itself";
  EXPECT_TRUE(at_rest(sim.slosh()));
  EXPECT_LT(world_normal_angle(sim), 0.01);
}

// Feeds a scripted list of hostile samples, one per step, then still.
struct HostileDriver : InputDriver {
  std::vector<MotionSample> script;
  size_t next = 0;
  const char* name() const override { return "hostile"; }
  MotionSample sample(double t) override {
    MotionSample m = next < script.size() ? script[next++] : MotionSample{};
    if (!std::isnan(m.time)) m.time = t;
    return m;
  }
};

TEST(Simulation, ExtremeInputsStayFiniteAndInsideTheGlass) {
  Simulation sim(lager_in_pint(0.86f));
  HostileDriver d;
  auto add = [&](auto edit) {
    MotionSample m;
    edit(m);
    for (int i = 0; i < 30; ++i) d.script.push_back(m);
  };
  add([](MotionSample& m) { m.pose.orientation = glm::dquat(kNaN, 0, 0, 0); });
  add([](MotionSample& m) { m.pose.orientation = glm::dquat(0, 0, 0, 0); });
  add([](MotionSample& m) { m.pose.orientation = glm::dquat(kInf, 1, 0, 0); });
  add([](MotionSample& m) { m.linear_acceleration = {kNaN, 1, 0}; });
  add([](MotionSample& m) { m.linear_acceleration = {kInf, -kInf, 0}; });
  add([](MotionSample& m) { m.angular_velocity = {0, kNaN, kInf}; });
  add([](MotionSample& m) { m.linear_acceleration = {1e6, 0, -1e6}; });
  add([](MotionSample& m) { m.linear_acceleration = {0, -1e6, 0}; });  // free fall and beyond
  add([](MotionSample& m) { m.angular_velocity = {1e6, 1e6, 0}; });
  add([](MotionSample& m) { m.pose.position = {1e300, kNaN, -kInf}; });
  add([](MotionSample& m) { m.time = kNaN; });
  for (int i = 0; i < 240; ++i) {  // a 1e6 m/s^2 square wave, flipping every step
    MotionSample m;
    m.linear_acceleration = {i % 2 ? 1e6 : -1e6, 0, i % 3 ? 1e6 : -1e6};
    m.angular_velocity = {0, 0, i % 2 ? 1e6 : -1e6};
    m.pose.orientation = tilt_orientation(deg(i % 2 ? 40 : -40), 0.0);
    d.script.push_back(m);
  }
  add([](MotionSample& m) { m.pose.orientation = tilt_orientation(deg(170), 1.0); });  // upside down: empties
  for (int i = 1; i <= int(d.script.size()); ++i) {
    sim.advance(d, i * kDt);
    if (!::testing::Test::HasFailure()) expect_sane(sim, "script step " + std::to_string(i));  // first failure only
  }
  // Time: a 1000 s gap is skipped, not simulated; backwards and NaN times do nothing.
  const double t = sim.time();
  sim.advance(d, t + 1000);
  EXPECT_NEAR(sim.time(), t + 1000, 1e-6);
  expect_sane(sim, "after a 1000 s gap");
  sim.advance(d, -5.0);
  sim.advance(d, kNaN);
  sim.advance(d, kInf);
  sim.advance(d, -kInf);
  EXPECT_NEAR(sim.time(), t + 1000, 1e-6);
  expect_sane(sim, "after backwards / NaN / Inf times");
  sim.step(MotionSample{}, kNaN);
  sim.step(MotionSample{}, kInf);
  sim.step(MotionSample{}, -1.0);
  expect_sane(sim, "after NaN / Inf / negative drink rates");
  sim.set_fraction(kNaN);
  expect_sane(sim, "after set_fraction(NaN)");
  sim.set_fraction(5.0);
  expect_sane(sim, "after set_fraction(5)");
  // Still again: it comes to an exact, level rest.
  for (int i = 1; i <= int(12.0 / kDt); ++i) sim.step(MotionSample{});
  EXPECT_TRUE(at_rest(sim.slosh()));
  EXPECT_LT(world_normal_angle(sim), 0.01);
}

TEST(Simulation, SameInputGivesBitIdenticalStates) {
  auto run = [](std::vector<double>& out) {
    Simulation sim(lager_in_pint(0.8f));
    ShakeDriver shake(0.012, 2 * kPi * 2.7, 2.0, glm::normalize(glm::dvec3(1, 0, -0.4)));
    TipDriver tip([](double t) { return ramp(t, 2.0, 1.0, deg(35)); }, 0.03);
    for (int i = 1; i <= 900; ++i) {
      sim.advance(i < 450 ? static_cast<InputDriver&>(shake) : tip, i * kDt, i > 700 ? 0.05 : 0.0);
      const SloshState& s = sim.slosh();
      const LiquidPlane& L = sim.surface();
      for (double v : {s.slope.x, s.slope.y, s.slope_rate.x, s.slope_rate.y, s.ring, s.ring_rate, s.cross.x,
                       s.cross.y, s.cross_rate.x, s.cross_rate.y, L.n.x, L.n.y, L.n.z, L.offset, sim.fraction(),
                       sim.spilled(), sim.energy(), sim.time()})
        out.push_back(v);
    }
  };
  std::vector<double> a, b;
  run(a);
  run(b);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  // And the run is not trivially constant.
  EXPECT_NE(a[0], a[a.size() - 18]);
}

}  // namespace
}  // namespace draught
