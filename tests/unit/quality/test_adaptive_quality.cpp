// The adaptive quality's decisions (core/quality), driven by a model of a device's frame
// times instead of a clock: what the browser test of an emulated phone cannot assert on a
// shared machine whose load changes under it (a budget derived from one moment's speed).
#include "core/quality/adaptive_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace draught {
namespace {

// A device: a full-tier frame costs ms_per_mpx per megapixel drawn, the MatCap tier a fifth
// of that (docs/PERFORMANCE.md), a capped number of interactions 70 %; plus a fixed overhead.
struct Device {
  double display_pixels;  // at scale 1
  double ms_per_mpx;
  double overhead_ms = 2;
  double jitter = 0;  // relative spread of each frame's time
  uint32_t state = 12345;

  double next_uniform() {  // [0, 1), a fixed sequence
    state = state * 1664525u + 1013904223u;
    return (state >> 8) * (1.0 / 16777216.0);
  }
  double frame_ms(const AdaptiveQuality& q) {
    const double mpx = display_pixels * q.scale * q.scale * 1e-6;
    double cost = mpx * ms_per_mpx / (q.matcap ? AdaptiveQuality::kMatCapCostRatio : 1.0);
    if (q.events_cap) cost *= 0.7;
    const double wobble = 1 + jitter * (2 * next_uniform() - 1);
    return (overhead_ms + cost) * wobble;
  }
};

// An emulated phone's display: 390 x 844 CSS pixels at a device pixel ratio of 3.
constexpr double kPhonePixels = 390.0 * 844.0 * 9.0;

struct Outcome {
  AdaptiveQuality q;
  int last_change = 0;  // the frame of the last change of scale, tier or cap
};

Outcome run(Device device, double budget_ms, bool matcap_fallback, int frames = 2000) {
  Outcome o;
  o.q.budget_ms = budget_ms;
  o.q.matcap_fallback = matcap_fallback;
  o.q.start(device.display_pixels);
  for (int i = 0; i < frames; ++i) {
    const double scale = o.q.scale;
    const bool matcap = o.q.matcap;
    const int cap = o.q.events_cap;
    o.q.update(device.frame_ms(o.q));
    if (o.q.scale != scale || o.q.matcap != matcap || o.q.events_cap != cap) o.last_change = i;
  }
  return o;
}

// About half a megapixel, but the full tier not below 50 % while it may fall to MatCap.
TEST(AdaptiveQuality, StartsAtAboutHalfAMegapixel) {
  const auto start = [](double pixels, bool fallback) {
    AdaptiveQuality q;
    q.matcap_fallback = fallback;
    q.start(pixels);
    return q.scale;
  };
  EXPECT_DOUBLE_EQ(start(kPhonePixels, false), 0.4);  // sqrt(0.5 / 2.96) = 0.41
  EXPECT_DOUBLE_EQ(start(kPhonePixels, true), AdaptiveQuality::kMatCapBelow);
  EXPECT_DOUBLE_EQ(start(640 * 480, true), 1.0);
  EXPECT_DOUBLE_EQ(start(7680.0 * 4320.0, false), AdaptiveQuality::kMinScale);
}

// The phone the browser test emulates, on a device where the full tier misses the budget
// even at 50 % resolution: with the MatCap tier it settles at a higher resolution scale than
// the full tier alone, and both settle (no change in the last half of the run).
TEST(AdaptiveQuality, APhoneSettlesAtAHigherScaleWithTheMatCapTier) {
  // 30 ms a megapixel in the full tier: 50 % of the phone (0.74 Mpx) takes 24 ms, over a
  // 16 ms budget; the MatCap tier holds it at 80 % (1.9 Mpx, 13 ms).
  const Device phone{kPhonePixels, 30.0};
  const Outcome full = run(phone, 16.0, false);
  const Outcome matcap = run(phone, 16.0, true);
  EXPECT_FALSE(full.q.matcap);
  EXPECT_TRUE(matcap.q.matcap);
  EXPECT_GT(matcap.q.scale, full.q.scale + 0.2) << "MatCap " << matcap.q.scale << ", full " << full.q.scale;
  EXPECT_LT(full.last_change, 1000);
  EXPECT_LT(matcap.last_change, 1000);
  // Each holds the budget where it settled.
  EXPECT_LT(Device(phone).frame_ms(full.q), 16.0 * 1.15);
  EXPECT_LT(Device(phone).frame_ms(matcap.q), 16.0 * 1.15);
}

// Frame times that wobble +-25 % from frame to frame (a shared machine) do not make it hunt:
// it still settles, and still higher with the MatCap tier.
TEST(AdaptiveQuality, WobblingFrameTimesDoNotMakeItHunt) {
  Device phone{kPhonePixels, 30.0};
  phone.jitter = 0.25;
  const Outcome full = run(phone, 16.0, false, 4000);
  const Outcome matcap = run(phone, 16.0, true, 4000);
  EXPECT_LT(full.last_change, 2000);
  EXPECT_LT(matcap.last_change, 2000);
  EXPECT_TRUE(matcap.q.matcap);
  EXPECT_GT(matcap.q.scale, full.q.scale);
}

// A device that holds the budget at full resolution climbs to it and never falls to MatCap.
TEST(AdaptiveQuality, AFastDeviceClimbsToFullResolutionInTheFullTier) {
  const Outcome o = run(Device{kPhonePixels, 2.0}, 16.0, true);  // 3 Mpx: 8 ms
  EXPECT_DOUBLE_EQ(o.q.scale, AdaptiveQuality::kMaxScale);
  EXPECT_FALSE(o.q.matcap);
  EXPECT_EQ(o.q.events_cap, 0);
}

// A budget nothing can hold: the full tier alone ends at the smallest scale with the
// interactions capped; with the fall, the MatCap tier at the smallest scale.
TEST(AdaptiveQuality, AnUnholdableBudgetEndsAtTheSmallestScale) {
  const Device slow{kPhonePixels, 3000.0, 50.0};
  const Outcome full = run(slow, 2.0, false, 300);
  EXPECT_DOUBLE_EQ(full.q.scale, AdaptiveQuality::kMinScale);
  EXPECT_EQ(full.q.events_cap, AdaptiveQuality::kCapEvents);
  EXPECT_FALSE(full.q.matcap);
  const Outcome matcap = run(slow, 2.0, true, 300);
  EXPECT_DOUBLE_EQ(matcap.q.scale, AdaptiveQuality::kMinScale);
  EXPECT_TRUE(matcap.q.matcap);
  EXPECT_EQ(matcap.q.events_cap, 0);
}

// When the device gets faster (another tab closed), the full tier comes back at 50 %.
TEST(AdaptiveQuality, TheFullTierComesBackWhenTheDeviceGetsFaster) {
  Device device{kPhonePixels, 30.0};
  Outcome o = run(device, 16.0, true);
  ASSERT_TRUE(o.q.matcap);
  device.ms_per_mpx = 3.0;  // ten times faster: the full tier holds 50 % in 4 ms
  for (int i = 0; i < 200; ++i) o.q.update(device.frame_ms(o.q));
  EXPECT_FALSE(o.q.matcap);
  EXPECT_GE(o.q.scale, AdaptiveQuality::kMatCapBelow);
}

// One slow frame (a shader compiled) moves nothing; neither do a hidden tab's gap nor NaN.
TEST(AdaptiveQuality, OneSlowFrameAndNonsenseTimesMoveNothing) {
  const Device device{kPhonePixels, 10.0};  // holds 50 %, not 100 %: settles in between
  Outcome o = run(device, 16.0, true);
  const AdaptiveQuality before = o.q;
  o.q.update(400.0);
  for (double bad : {0.0, -5.0, 60000.0, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity()})
    o.q.update(bad);
  for (int i = 0; i < 30; ++i) o.q.update(Device(device).frame_ms(o.q));
  EXPECT_DOUBLE_EQ(o.q.scale, before.scale);
  EXPECT_EQ(o.q.matcap, before.matcap);
  EXPECT_TRUE(std::isfinite(o.q.ema_ms));
}

// Pinned (not adaptive): frame times are shown but change nothing; the pin is clamped and
// lifts a cap. Adapting again starts from the pinned scale.
TEST(AdaptiveQuality, APinnedScaleStaysUntilItAdaptsAgain) {
  AdaptiveQuality q;
  q.events_cap = AdaptiveQuality::kCapEvents;
  q.pin(0.75);
  EXPECT_EQ(q.events_cap, 0);
  for (int i = 0; i < 100; ++i) q.update(500.0);
  EXPECT_DOUBLE_EQ(q.scale, 0.75);
  EXPECT_FALSE(q.matcap);
  EXPECT_NEAR(q.shown_ms, 500.0, 1e-9);
  q.pin(9.0);
  EXPECT_DOUBLE_EQ(q.scale, 2.0);
  q.pin(0.75);
  q.adapt();
  for (int i = 0; i < 100; ++i) q.update(500.0);  // far over the 33 ms budget
  EXPECT_LT(q.scale, 0.75);
}

// Turning the fall off leaves the MatCap tier at once; the full tier then goes below 50 %.
TEST(AdaptiveQuality, TurningTheFallOffLeavesTheMatCapTier) {
  const Device phone{kPhonePixels, 30.0};
  Outcome o = run(phone, 16.0, true);
  ASSERT_TRUE(o.q.matcap);
  o.q.allow_matcap(false);
  EXPECT_FALSE(o.q.matcap);
  for (int i = 0; i < 1000; ++i) o.q.update(Device(phone).frame_ms(o.q));
  EXPECT_FALSE(o.q.matcap);
  EXPECT_LT(o.q.scale, AdaptiveQuality::kMatCapBelow);
}

}  // namespace
}  // namespace draught
