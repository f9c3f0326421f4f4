// Minor bubbles: they appear only with carbonation and plateau when births match pops;
// more carbonation gives more and bigger bubbles; every bubble stays entirely inside the
// liquid (upright, tilted, in a flute, under bad input); a bubble rises monotonically,
// grows and speeds up; pops happen at the surface and account for every lost bubble;
// the same seed gives bit-identical fields; etched sites ring the axis and emit faster.
#include "core/bubbles/bubbles.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

namespace draught {
namespace {

constexpr double kDt = 1.0 / 240.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN(), kInf = std::numeric_limits<double>::infinity();
constexpr double kR = 0.035, kBase = 0.01, kHeight = 0.15, kLevel = 0.11;
const glm::dvec3 kUp{0, 1, 0};

// A straight cylinder of inner radius kR, cavity y in [kBase, kHeight].
Vessel cylinder() {
  Vessel v;
  v.height = kHeight, v.base = kBase, v.dy = kHeight / Vessel::kSegments;
  v.r_inner.assign(Vessel::kSegments + 1, kR);
  v.r_outer.assign(Vessel::kSegments + 1, kR + 0.002);
  v.rim_major = kR + 0.001, v.rim_minor = 0.001, v.bound_radius = kR + 0.002;
  return v;
}

BubbleSettings settings(float carbonation, int seed = 7) {
  return BubbleSettings{carbonation, 60, false, 2e-4f, 5000, seed};
}

LiquidPlane plane(const glm::dvec3& n, const glm::dvec3& through) {
  LiquidPlane s;
  s.n = glm::normalize(n), s.offset = glm::dot(s.n, through);
  return s;
}
LiquidPlane flat(double level = kLevel) { return plane(kUp, {0, level, 0}); }

glm::dvec3 tilted(double deg, double azimuth_deg = 0) {
  const double t = deg * std::numbers::pi / 180, a = azimuth_deg * std::numbers::pi / 180;
  return {std::sin(t) * std::cos(a), std::cos(t), std::sin(t) * std::sin(a)};
}

// Entirely inside: 26 points on each sphere lie inside the cavity and below the surface.
void expect_inside(const BubbleField& f, const Vessel& v, const LiquidPlane& s) {
  for (const Bubble& b : f.bubbles()) {
    ASSERT_TRUE(std::isfinite(b.p.x) && std::isfinite(b.p.y) && std::isfinite(b.p.z) && b.radius > 0);
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k) {
          if (!i && !j && !k) continue;
          const glm::dvec3 q = glm::dvec3(b.p) + double(b.radius) * glm::normalize(glm::dvec3(i, j, k));
          ASSERT_LE(std::hypot(q.x, q.z), v.inner_radius(q.y)) << "through the wall at y " << q.y;
          ASSERT_GE(q.y, v.base) << "through the floor";
          ASSERT_LT(s.level(q), 0) << "above the surface";
        }
  }
}

// Steps for `seconds`; returns how many bubbles are alive then.
size_t run(BubbleField& f, double seconds, const LiquidPlane& s = flat(), glm::dvec3 up = kUp) {
  for (long i = 0; i < std::lround(seconds / kDt); ++i) f.step(kDt, s, up);
  return f.bubbles().size();
}

double mean_radius(const BubbleField& f) {
  double sum = 0;
  for (const Bubble& b : f.bubbles()) sum += b.radius;
  return sum / std::max(double(f.bubbles().size()), 1.0);
}

std::uint64_t emitted(const BubbleField& f) {
  return std::accumulate(f.sites().begin(), f.sites().end(), std::uint64_t(0), [](auto n, const BubbleSite& s) { return n + s.emitted; });
}

bool same(const BubbleField& a, const BubbleField& b) {
  return std::equal(a.bubbles().begin(), a.bubbles().end(), b.bubbles().begin(), b.bubbles().end(), [](const Bubble& x, const Bubble& y) {
    return x.p == y.p && x.radius == y.radius && x.age == y.age;
  });
}

TEST(Bubbles, AppearGrowInNumberThenPlateau) {
  BubbleField f(settings(0.8f), cylinder());
  const size_t early = run(f, 0.25), at8 = run(f, 7.75), at12 = run(f, 4.0);
  EXPECT_GT(early, 10u);
  EXPECT_GT(at8, 2 * early);
  EXPECT_NEAR(double(at12), double(at8), 0.1 * double(at8)) << "births should balance pops";
  // At the plateau the pops per second match the births per second.
  size_t pops = 0;
  const std::uint64_t born = emitted(f);
  for (int i = 0; i < 480; ++i) f.step(kDt, flat(), kUp), pops += f.pops().size();
  EXPECT_NEAR(double(pops), double(emitted(f) - born), 0.15 * double(pops));
}

TEST(Bubbles, StillWineHasNone) {
  BubbleField f(settings(0.0f), cylinder());
  for (int i = 0; i < 2400; ++i) {
    f.step(kDt, flat(), kUp);
    ASSERT_TRUE(f.bubbles().empty() && f.pops().empty());
  }
}

TEST(Bubbles, MoreCarbonationGivesMoreAndBiggerBubbles) {
  BubbleField low(settings(0.3f), cylinder()), high(settings(1.0f), cylinder());
  EXPECT_GT(run(high, 6.0), 2 * run(low, 6.0));
  EXPECT_GT(mean_radius(high), 1.3 * mean_radius(low));
}

TEST(Bubbles, StayInsideTheLiquid) {
  const Vessel v = cylinder();
  struct Case { const char* name; LiquidPlane s; glm::dvec3 up; };
  const Case cases[] = {{"upright", flat(), kUp},
                        {"tilted 20 deg", plane(tilted(20), {0, 0.09, 0}), tilted(20)},
                        {"sloshing: surface and up disagree", plane(tilted(20, 45), {0, 0.09, 0}), tilted(30, 200)},
                        {"shallow", flat(kBase + 0.01), tilted(10)}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    BubbleField f(settings(1.0f), v);
    for (int i = 0; i < 3000; ++i) {
      f.step(kDt, c.s, c.up);
      expect_inside(f, v, c.s);
      if (HasFatalFailure()) return;
    }
    EXPECT_GT(f.bubbles().size(), 5u);
  }
}

TEST(Bubbles, StayInsideAFlute) {
  const Vessel v = test::preset_vessel("flute");
  BubbleSettings st = settings(1.0f);
  st.etched_base = true;
  BubbleField f(st, v);
  const LiquidPlane s = plane(tilted(15), {0, v.fill_height(0.7), 0});
  for (int i = 0; i < 3000; ++i) {
    f.step(kDt, s, tilted(15));
    expect_inside(f, v, s);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(f.bubbles().size(), 20u);
}

// One site and room for one bubble: index 0 is the same bubble until it pops. Upright,
// and tilted (the bubble slides up the wall it meets).
TEST(Bubbles, ATrackedBubbleRisesGrowsAndSpeedsUp) {
  for (const glm::dvec3& up : {kUp, tilted(15)}) {
    BubbleSettings st = settings(1.0f, 3);
    st.sites = 1, st.max_bubbles = 1;
    BubbleField f(st, cylinder());
    const LiquidPlane s = plane(up, {0, kLevel, 0});
    while (f.bubbles().empty()) f.step(kDt, s, up);
    std::vector<Bubble> path{f.bubbles()[0]};
    for (;;) {
      f.step(kDt, s, up);
      if (f.bubbles().empty() || f.bubbles()[0].age < path.back().age) break;
      path.push_back(f.bubbles()[0]);
    }
    const auto height = [&](size_t i) { return glm::dot(glm::dvec3(path[i].p), up); };
    ASSERT_GT(path.size(), 100u);
    for (size_t i = 1; i < path.size(); ++i) {
      ASSERT_GT(height(i), height(i - 1)) << "step " << i;
      ASSERT_GE(path[i].radius, path[i - 1].radius) << "step " << i;
    }
    EXPECT_GT(-s.level(path.back().p), 0.0);
    EXPECT_LT(-s.level(path.back().p), 0.002) << "rose to the surface";
    EXPECT_GT(path.back().radius, 1.5f * path.front().radius);
    const size_t n = path.size();
    const double v0 = (height(10) - height(0)) / (10 * kDt), v1 = (height(n - 1) - height(n - 11)) / (10 * kDt);
    EXPECT_GT(v1, 1.5 * v0);
    EXPECT_GT(v0, 0.005);
    EXPECT_LT(v1, 0.31);
  }
}

// Bigger bubbles at birth rise faster: from the same site, they live shorter.
TEST(Bubbles, BiggerBubblesReachTheSurfaceSooner) {
  const auto lifetime = [](float size) {
    BubbleSettings st = settings(1.0f, 5);
    st.sites = 1, st.max_bubbles = 1, st.size = size;
    BubbleField f(st, cylinder());
    float age = 0;
    while (f.bubbles().empty()) f.step(kDt, flat(), kUp);
    while (!f.bubbles().empty()) age = f.bubbles()[0].age, f.step(kDt, flat(), kUp);
    return age;
  };
  ASSERT_LT(BubbleField(settings(1.0f, 5), cylinder()).sites()[0].p.y, kLevel - 0.05) << "a site deep enough";
  EXPECT_LT(lifetime(3e-4f), 0.6f * lifetime(1e-4f));
}

TEST(Bubbles, PopAtTheSurfaceAndAccountForEveryBubble) {
  const LiquidPlane s = flat();
  BubbleField f(settings(1.0f), cylinder());
  size_t total = 0;
  for (int i = 0; i < 2400; ++i) {
    const std::vector<Bubble> before = f.bubbles();
    const std::uint64_t born = emitted(f);
    f.step(kDt, s, kUp);
    total += f.pops().size();
    ASSERT_EQ(before.size() + (emitted(f) - born), f.bubbles().size() + f.pops().size()) << "step " << i;
    for (const glm::vec3& p : f.pops()) {
      EXPECT_NEAR(s.level(glm::dvec3(p)), 0.0, 1e-6);
      // It was a bubble just under the surface (or one born there this step).
      bool near = false;
      for (const Bubble& b : before)
        near = near || (glm::length(glm::dvec3(b.p - p)) < 3.0 * b.radius + 0.3 * kDt && s.level(b.p) > -2.0 * b.radius - 0.3 * kDt);
      for (const BubbleSite& site : f.sites())
        near = near || (std::hypot(site.p.x - p.x, site.p.z - p.z) < 1e-3 && kLevel - site.p.y < 1e-3 && kLevel > site.p.y);
      EXPECT_TRUE(near) << "pop with no bubble near it";
    }
  }
  EXPECT_GT(total, 200u);
}

TEST(Bubbles, SameSeedSameFieldOtherSeedDiffers) {
  BubbleField a(settings(0.9f, 11), cylinder()), b(settings(0.9f, 11), cylinder()), c(settings(0.9f, 12), cylinder());
  for (int i = 0; i < 2000; ++i) {
    const double dt = kDt * (1 + 0.5 * std::sin(i * 0.1));
    const glm::dvec3 up = tilted(10 * std::sin(i * 0.01));
    a.step(dt, flat(), up), b.step(dt, flat(), up), c.step(dt, flat(), up);
  }
  ASSERT_GT(a.bubbles().size(), 0u);
  EXPECT_TRUE(same(a, b));
  EXPECT_FALSE(same(a, c));
}

TEST(Bubbles, BadInputKeepsBubblesFiniteAndInside) {
  const Vessel v = cylinder();
  const LiquidPlane s = flat();
  BubbleField f(settings(1.0f), v), twin(settings(1.0f), v);
  run(f, 2.0), run(twin, 2.0);
  // Ignored: bad steps, and a garbage up (the previous one, kUp, is kept).
  for (double dt : {kNaN, -1.0, 0.0, -kNaN}) f.step(dt, s, kUp);
  for (const glm::dvec3& up : {glm::dvec3(kNaN, 1, 0), glm::dvec3(0.0), glm::dvec3(0, kInf, 0)})
    f.step(kDt, s, up), twin.step(kDt, s, kUp);
  EXPECT_TRUE(same(f, twin));
  // Huge steps, odd but valid directions (huge, tiny, down).
  for (double dt : {1e9, kInf, 0.5, kDt})
    for (const glm::dvec3& up : {glm::dvec3(1e300, 0, 0), glm::dvec3(1e-300, 1e-300, 0), glm::dvec3(0, -1, 0), kUp}) {
      f.step(dt, s, up);
      expect_inside(f, v, s);
      ASSERT_GT(f.bubbles().size(), 50u) << "bubbles survive";
    }
  // Garbage settings: still finite, still inside.
  BubbleField g(BubbleSettings{float(kNaN), -5, true, float(kNaN), -1, -3}, v);
  BubbleField h(BubbleSettings{1e9f, 100000, true, 1.0f, 100000000, 1}, v);
  for (int i = 0; i < 480; ++i) g.step(kDt, s, kUp), h.step(kDt, s, kUp);
  EXPECT_TRUE(g.bubbles().empty());
  expect_inside(h, v, s);
}

TEST(Bubbles, EmptyGlassEmitsNothingAndPopsWhatIsLeft) {
  BubbleField f(settings(1.0f), cylinder());
  ASSERT_GT(run(f, 3.0), 50u);
  LiquidPlane empty;  // offset -1: below the floor
  f.step(kDt, empty, kUp);
  EXPECT_TRUE(f.bubbles().empty());
  EXPECT_TRUE(f.pops().empty()) << "stranded bubbles vanish without a pop at a surface far away";
  const std::uint64_t born = emitted(f);
  EXPECT_EQ(run(f, 1.0, empty), 0u);
  EXPECT_EQ(emitted(f), born);
  f.clear();
  EXPECT_GT(run(f, 1.0), 10u);
  f.clear();
  EXPECT_TRUE(f.bubbles().empty());
}

TEST(Bubbles, EtchedRingSitsAroundTheAxisAndEmitsFaster) {
  BubbleSettings st = settings(1.0f);
  st.etched_base = true;
  BubbleField f(st, cylinder());
  run(f, 5.0);
  int ring = 0;
  double etched = 0, other = 0;
  for (const BubbleSite& s : f.sites()) {
    (s.etched ? etched : other) += double(s.emitted);
    if (!s.etched) continue;
    ++ring;
    EXPECT_NEAR(std::hypot(s.p.x, s.p.z), 0.003, 1e-6);
    EXPECT_NEAR(s.p.y, kBase, 2e-4);
  }
  ASSERT_EQ(ring, BubbleField::kEtchedSites);
  ASSERT_EQ(f.sites().size(), 60u + BubbleField::kEtchedSites);
  // Other sites include dry ones above the surface; compare with the wet ones' mean too.
  EXPECT_GT(etched / ring, 2.0 * other / 60);
  const auto wet = std::count_if(f.sites().begin(), f.sites().end(), [](const BubbleSite& s) { return !s.etched && s.p.y < kLevel; });
  EXPECT_GT(etched / ring, 2.0 * other / double(wet));
  EXPECT_EQ(BubbleField(settings(1.0f), cylinder()).sites().size(), 60u) << "no ring without etching";
}

}  // namespace
}  // namespace draught
