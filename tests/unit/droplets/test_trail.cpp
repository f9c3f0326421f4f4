// The pointer trail: it follows, stretches behind a moving pointer, snaps back, is
// deterministic, survives hostile input; droplet parameters are checked as read.
#include "core/droplets/trail.hpp"
#include "core/io/files.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace draught {
namespace {

TEST(DropletTrail, GathersAtARestingPointer) {
  DropletTrail t;
  for (int i = 0; i < 240 * 3; ++i) t.step({0.05, 0.02});
  for (auto& x : t.positions()) EXPECT_LT(glm::length(x - glm::dvec2(0.05, 0.02)), 1e-4);
}

TEST(DropletTrail, StretchesWhileMovingAndSnapsBack) {
  DropletTrail t;
  double longest = 0;
  for (int i = 0; i < 120; ++i) {  // the pointer sweeps 0.2 m in half a second
    t.step({0.2 * i / 120.0, 0.0});
    longest = std::max(longest, glm::length(t.positions().front() - t.positions().back()));
  }
  EXPECT_GT(longest, 0.03);  // stretched
  // Stopped: the head overshoots the pointer (an elastic snap), then all gather.
  double past = 0;
  for (int i = 0; i < 240 * 3; ++i) {
    t.step({0.2, 0.0});
    past = std::max(past, t.positions().front().x - 0.2);
  }
  EXPECT_GT(past, 1e-4);
  EXPECT_LT(glm::length(t.positions().front() - t.positions().back()), 1e-3);
}

TEST(DropletTrail, IsDeterministicAndBounded) {
  DropletTrail a, b;
  for (int i = 0; i < 500; ++i) {
    const glm::dvec2 p{std::sin(i * 0.05) * 0.1, std::cos(i * 0.03) * 0.05};
    a.step(p);
    b.step(p);
  }
  EXPECT_EQ(a.positions(), b.positions());
  a.step({std::numeric_limits<double>::quiet_NaN(), 0.0});  // ignored
  a.step({1e30, 0.0});                                    // held at 10 m
  for (int i = 0; i < 2400; ++i) a.step({1e30, 1e30});
  for (auto& x : a.positions()) {
    EXPECT_TRUE(std::isfinite(x.x) && std::isfinite(x.y));
    EXPECT_LT(glm::length(x), 10.5);
  }
}

TEST(DropletTrail, SpheresTaperAlongTheTrailInTheirPlane) {
  DropletParams p;
  p.count = 4;
  p.radius = 0.02f;
  p.taper = 0.5f;
  DropletTrail t(p, {0.1, 0.05});
  const auto s = t.spheres({1.0f, 0.2f, 0.0f}, 90.0f);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_NEAR(s[0].radius, 0.02, 1e-9);
  EXPECT_NEAR(s[3].radius, 0.01, 1e-9);
  // yaw 90: the plane's x axis is world -z.
  EXPECT_NEAR(s[0].centre.x, 1.0, 1e-6);
  EXPECT_NEAR(s[0].centre.y, 0.25, 1e-6);
  EXPECT_NEAR(s[0].centre.z, -0.1, 1e-6);
  glm::dvec2 q;
  ASSERT_TRUE(droplet_plane_hit({1.0f, 0.2f, 0.0f}, 90.0f, {3.0, 0.25, -0.1}, {-1, 0, 0}, q));
  EXPECT_NEAR(q.x, 0.1, 1e-9);
  EXPECT_NEAR(q.y, 0.05, 1e-6);
}

TEST(DropletParams, ParsedWithClearErrors) {
  const auto j = nlohmann::json::parse(R"({"count": 12, "kernel": "exponential", "absorption": [1, 2, 3]})");
  const DropletParams p = parse_droplet_params(j, "s.json", "objects[1].droplets");
  EXPECT_EQ(p.count, 12);
  EXPECT_EQ(p.kernel, 1);
  EXPECT_EQ(p.absorption, glm::vec3(1, 2, 3));
  auto message = [](const char* text) {
    try {
      parse_droplet_params(nlohmann::json::parse(text), "s.json", "objects[1].droplets");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"({"blend": 1})"),
            "s.json: field 'objects[1].droplets.blend': expected a number in [0, 0.2] (m), got 1");
  EXPECT_EQ(message(R"({"count": 33})"),
            "s.json: field 'objects[1].droplets.count': expected a whole number in [1, 32], got 33");
  EXPECT_NE(message(R"({"blnd": 0.01})").find("did you mean 'blend'"), std::string::npos);
  EXPECT_NE(message(R"({"kernel": "cubic"})").find("expected \"polynomial\" or \"exponential\""), std::string::npos);
}

}  // namespace
}  // namespace draught
