// The foam head: it builds after a pour with a bounded overshoot, then halves every
// half_life; lager collapses faster than stout; no height gives no head; lacing rings are
// left one per ~8 mm as the level drops (none when standing, refilling or lacing = 0);
// the head turns concave as the level drops; big bubbles stay in bounds, pop and come
// back; the same seed gives the same frames; extreme input keeps the head finite.
#include "core/foam/foam.hpp"
#include "core/params/preset.hpp"
#include "core/sim/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace draught {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kLevel = 0.1, kRadius = 0.03;

FoamParams drink_foam(const std::string& drink) { return resolve_scene({drink, "", {}, {}}).foam; }

void run(FoamState& f, double seconds, double dt = 0.05) {
  for (long i = 0, n = std::lround(seconds / dt); i < n; ++i) f.step(dt, kLevel, kRadius);
}

void expect_same(const FoamFrame& a, const FoamFrame& b) {
  EXPECT_EQ(a.thickness, b.thickness);
  EXPECT_EQ(a.dome, b.dome);
  EXPECT_EQ(a.lacing, b.lacing);
  ASSERT_EQ(a.bubbles.size(), b.bubbles.size());
  for (size_t i = 0; i < a.bubbles.size(); ++i) {
    EXPECT_EQ(a.bubbles[i].xz, b.bubbles[i].xz);
    EXPECT_EQ(a.bubbles[i].radius, b.bubbles[i].radius);
    EXPECT_EQ(a.bubbles[i].popped, b.bubbles[i].popped);
  }
}

// A lager in a pint, poured, standing still for a few seconds.
struct Pint {
  Simulation sim;
  explicit Pint(float lacing = 0.5f) : sim(make(lacing)) {
    sim.pour();
    stand(5.0);
  }
  static Params make(float lacing) {
    Params p = resolve_scene({"lager", "pint", {}, {}});
    p.foam.lacing = lacing;
    return p;
  }
  double level() const { return sim.fill_table().offset_at(0, sim.fraction()); }
  void stand(double s) { for (int i = 0; i < int(s / Simulation::kStep); ++i) sim.step(MotionSample{}); }
  std::vector<double> lacing() const { return sim.foam().frame(kRadius).lacing; }
};

TEST(Foam, BuildsAfterPourWithBoundedOvershootNearRiseTime) {
  FoamParams p = default_params().foam;
  FoamState f(p);
  f.pour();
  EXPECT_EQ(f.thickness(), 0.0);
  double peak = 0, peak_t = 0, prev = 0;
  for (int i = 1; i <= 2000; ++i) {  // 20 s at 0.01 s
    f.step(0.01, kLevel, kRadius);
    const double t = f.thickness();
    if (f.age() <= p.rise_time) {
      EXPECT_GT(t, prev) << "still building at " << f.age();
    }
    if (t > peak) peak = t, peak_t = f.age();
    prev = t;
  }
  EXPECT_GE(peak, p.height);
  EXPECT_LE(peak, 1.4 * p.height);
  EXPECT_GE(peak_t, 0.5 * p.rise_time);
  EXPECT_LE(peak_t, 2.0 * p.rise_time);
}

TEST(Foam, HalvesEveryHalfLifeOnceSettled) {
  for (const char* drink : {"lager", "stout", "amber-ale"}) {
    const FoamParams p = drink_foam(drink);
    for (double t0 : {30.0, 100.0}) {
      FoamState f(p);
      f.pour();
      run(f, t0);
      const double a = f.thickness();
      run(f, p.half_life, 0.25);
      ASSERT_GT(a, 0) << drink;
      EXPECT_NEAR(f.thickness() / a, 0.5, 0.005) << drink << " from t = " << t0;
    }
  }
}

TEST(Foam, LagerCollapsesFasterThanStout) {
  const FoamParams lager = drink_foam("lager"), stout = drink_foam("stout");
  ASSERT_EQ(lager.half_life, 120.0f);
  ASSERT_EQ(stout.half_life, 900.0f);
  FoamState a(lager), b(stout);
  a.pour(), b.pour();
  run(a, 300), run(b, 300);
  const double ra = a.thickness() / lager.height, rb = b.thickness() / stout.height;
  EXPECT_LT(ra, rb);
  EXPECT_NEAR(ra, std::exp2(-(300 - lager.rise_time) / 120.0), 0.02 * ra);
  EXPECT_NEAR(rb, std::exp2(-(300 - stout.rise_time) / 900.0), 0.02 * rb);
}

TEST(Foam, ZeroHeightGivesNoHead) {
  FoamParams p = default_params().foam;
  p.height = 0;
  FoamState f(p);
  f.pour();
  for (int i = 0; i < 600; ++i) {
    f.step(0.05, kLevel - 0.0001 * i, kRadius);  // falling level
    const FoamFrame fr = f.frame(kRadius);
    ASSERT_EQ(fr.thickness, 0.0) << "at " << f.age();
    ASSERT_TRUE(fr.bubbles.empty()) << "at " << f.age();
    ASSERT_TRUE(fr.lacing.empty()) << "at " << f.age();
  }
}

TEST(Foam, LacingRingsRecordedAsLevelDrops) {
  Pint pint;
  ASSERT_TRUE(pint.lacing().empty()) << "standing after a pour left rings";
  const double l0 = pint.level();
  int rings = 0;
  std::vector<double> prev = pint.lacing();
  auto sip = [&](double until_drop) {
    while (l0 - pint.level() < until_drop && pint.sim.fraction() > 0) {
      pint.sim.step(MotionSample{}, 0.1);
      const std::vector<double> now = pint.lacing();
      if (now == prev) continue;
      ++rings;
      ASSERT_LE(int(now.size()), FoamState::kMaxLacing);
      if (!prev.empty()) {
        EXPECT_LT(now.back(), prev.back()) << "ring " << rings << " not below the previous";
      }
      EXPECT_GT(now.back(), pint.level());  // left above the liquid, by about the head
      EXPECT_LT(now.back(), pint.level() + 0.0085 + 1.5 * pint.sim.frame().params.foam.height);
      for (size_t i = 1; i < now.size(); ++i) EXPECT_LT(now[i], now[i - 1]);
      prev = now;
    }
  };
  sip(0.05);  // 5 cm: fewer rings than the cap
  const double drop = l0 - pint.level();
  EXPECT_NEAR(rings, drop / 0.008, 1.0) << "drop " << drop;
  EXPECT_EQ(int(pint.lacing().size()), rings);
  sip(1.0);  // drink it all
  EXPECT_GT(rings, FoamState::kMaxLacing);
  EXPECT_EQ(int(pint.lacing().size()), FoamState::kMaxLacing);
  const std::vector<double> before = pint.lacing();
  pint.stand(3.0);
  EXPECT_EQ(pint.lacing(), before) << "standing still added rings";
  pint.sim.set_fraction(0.8);
  pint.stand(3.0);
  EXPECT_EQ(pint.lacing(), before) << "refilling added rings";
}

TEST(Foam, NoLacingWhenLacingIsZero) {
  Pint pint(0.0f);
  for (int i = 0; i < 2400 && pint.sim.fraction() > 0.1; ++i) {
    pint.sim.step(MotionSample{}, 0.1);
    ASSERT_TRUE(pint.lacing().empty()) << "at fraction " << pint.sim.fraction();
  }
  EXPECT_LT(pint.sim.fraction(), 0.15);
}

TEST(Foam, DomedAfterPourConcaveOnceLevelDrops) {
  Pint pint;
  const float dome = pint.sim.frame().params.foam.dome;
  pint.sim.pour();
  pint.sim.step(MotionSample{});
  EXPECT_GE(pint.sim.frame().foam.dome, dome);
  pint.stand(5.0);
  EXPECT_GT(pint.sim.frame().foam.dome, 0.0);
  const double l0 = pint.level();
  while (l0 - pint.level() < 0.021) pint.sim.step(MotionSample{}, 0.1);
  EXPECT_LT(pint.sim.frame().foam.dome, 0.0);
  pint.sim.pour();  // a fresh head: domed again, no rings
  pint.sim.step(MotionSample{});
  EXPECT_GE(pint.sim.frame().foam.dome, dome);
  EXPECT_TRUE(pint.sim.frame().foam.lacing.empty());
}

TEST(Foam, BigBubblesStayInBoundsPopAndComeBack) {
  for (int wanted : {6, 1, 50}) {
    for (float height : {0.015f, 0.004f}) {  // a thin head limits the bubbles' size
      FoamParams p = default_params().foam;
      p.big_bubbles = wanted, p.height = height;
      FoamState f(p);
      f.pour();
      int popped = 0, back = 0, max_count = 0;
      for (int i = 0; i < 1200; ++i) {  // 60 s
        f.step(0.05, kLevel, kRadius);
        for (double radius : {kRadius, 0.01}) {
          const FoamFrame fr = f.frame(radius);
          ASSERT_LE(int(fr.bubbles.size()), std::min(wanted, FoamState::kMaxBubbles));
          max_count = std::max(max_count, int(fr.bubbles.size()));
          for (const BigBubble& b : fr.bubbles) {
            EXPECT_LE(glm::length(b.xz), 0.8 * radius * (1 + 1e-9));
            EXPECT_GT(b.radius, 0.0);
            EXPECT_LE(b.radius, 0.45 * fr.thickness * (1 + 1e-9));
            if (b.popped) {
              ++popped;
            } else if (popped > 0) {
              ++back;
            }
          }
        }
      }
      EXPECT_GT(max_count, 0) << wanted << " " << height;
      EXPECT_GT(popped, 0) << "no bubble ever popped";
      EXPECT_GT(back, 0) << "no bubble after one popped";
    }
  }
}

TEST(Foam, SameSeedSameFramesOtherSeedOtherBubbles) {
  FoamParams p = default_params().foam;
  p.big_bubbles = 8;
  FoamState a(p), b(p);
  p.seed = 2;
  FoamState c(p);
  a.pour(), b.pour(), c.pour();
  int differ = 0;
  for (int i = 0; i < 400; ++i) {
    const double level = kLevel - 0.0001 * i;
    a.step(0.05, level, kRadius), b.step(0.05, level, kRadius), c.step(0.05, level, kRadius);
    const FoamFrame fa = a.frame(kRadius), fc = c.frame(kRadius);
    expect_same(fa, b.frame(kRadius));
    if (fa.bubbles.size() != fc.bubbles.size() ||
        !std::equal(fa.bubbles.begin(), fa.bubbles.end(), fc.bubbles.begin(),
                    [](const BigBubble& x, const BigBubble& y) { return x.xz == y.xz; }))
      ++differ;
  }
  EXPECT_GT(differ, 300) << "seed 2 gives mostly the same bubbles as seed 1";
  // Two simulations driven the same way give the same heads.
  Pint x, y;
  for (int i = 0; i < 1200; ++i) x.sim.step(MotionSample{}, 0.05), y.sim.step(MotionSample{}, 0.05);
  expect_same(x.sim.frame().foam, y.sim.frame().foam);
  EXPECT_FALSE(x.sim.frame().foam.lacing.empty());
}

TEST(Foam, ExtremeParamsStayFinite) {
  FoamParams p = default_params().foam;
  // The extremes the table allows (it refuses anything beyond them; the foam does not clamp).
  const ParamDesc &rise_row = *find_param("foam.rise_time"), &half_row = *find_param("foam.half_life");
  p.height = find_param("foam.height")->max, p.big_bubbles = 12, p.lacing = 1.0f;
  for (float rise : {rise_row.min, rise_row.max}) {
    for (float half : {half_row.min, half_row.max}) {
      p.rise_time = rise, p.half_life = half;
      FoamState f(p);
      f.pour();
      const double dts[] = {1e-6, 0.01, 1e9, 1e300, kInf, kNaN, -1.0, 0.0};
      const double levels[] = {0.1, kNaN, 0.05, kInf, -kInf, 1e300, 0.0, 0.02};
      for (int i = 0; i < 400; ++i) {
        f.step(dts[i % 8], levels[(i / 8) % 8], kRadius);
        const FoamFrame fr = f.frame(kRadius);
        ASSERT_TRUE(std::isfinite(fr.thickness)) << i;
        ASSERT_GE(fr.thickness, 0.0) << i;
        ASSERT_LE(fr.thickness, 1.4 * p.height) << i;
        ASSERT_TRUE(std::isfinite(fr.dome)) << i;
        ASSERT_LE(int(fr.lacing.size()), FoamState::kMaxLacing);
        for (double l : fr.lacing) ASSERT_TRUE(std::isfinite(l)) << i;
        for (const BigBubble& b : fr.bubbles)
          ASSERT_TRUE(std::isfinite(b.radius) && std::isfinite(b.xz.x) && std::isfinite(b.xz.y)) << i;
      }
    }
  }
}

}  // namespace
}  // namespace draught
