// The pour's stream: volume conserved to rounding, every parcel arrives once the flow
// stops, the front falls freely, the stream thins downwards and stays joined, it is
// deterministic, and bad input is refused by name.
#include "core/pointcloud/stream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

// A pour from 0.3 m above the glass's bottom, straight down from rest.
PourStream pour(StreamParams p = {}) {
  PourStream s(p, {0, 0.3, 0}, {0, 0, 0}, 0.0);
  s.set_flow(0, 5e-5);  // 50 ml/s
  return s;
}

TEST(PourStream, ConservesVolumeAndEverythingArrives) {
  PourStream s(StreamParams{}, {0.02, 0.25, 0}, {0.1, 0.05, 0}, 0.0);
  s.set_flow(0.0, 3e-5);
  s.set_flow(0.5, 8e-5);
  s.set_flow(1.003, 1e-6);  // mid-step changes are integrated exactly
  s.set_flow(1.5, 0.0);
  double worst = 0, level = 0;
  for (int i = 0; i < 480; ++i) {
    s.advance(PourStream::kStep);
    // The glass fills, the rim tips.
    level = s.arrived_volume() / 0.004;  // a glass of 40 cm^2 cross-section
    s.set_target_height(level);
    s.set_origin({0.02 + 0.0001 * i, 0.25 - 0.0001 * i, 0}, {0.1, 0.05 - 0.0002 * i, 0});
    const double e = s.emitted_volume();
    worst = std::max(worst, std::abs(e - s.arrived_volume() - s.in_flight_volume()) / e);
  }
  EXPECT_LT(worst, 1e-12);
  // Emitted is the flow history's integral.
  const double total = 3e-5 * 0.5 + 8e-5 * 0.503 + 1e-6 * 0.497;
  EXPECT_NEAR(s.emitted_volume() / total, 1.0, 1e-12);
  // The flow stopped at 1.5 s; half a second later every parcel is in the glass.
  EXPECT_EQ(s.parcels(), 0u);
  EXPECT_EQ(s.in_flight_volume(), 0.0);
  EXPECT_NEAR(s.arrived_volume() / total, 1.0, 1e-12);
  EXPECT_GT(level, 0.01);
}

TEST(PourStream, FrontFallsFreely) {
  StreamParams p;
  p.wobble = 0;
  PourStream s = pour(p);
  for (int i = 1; i <= 48; ++i) {  // 0.2 s: the front falls 0.196 m of the 0.3
    s.advance(PourStream::kStep);
    const PointCloud c = s.cloud();
    ASSERT_FALSE(c.position.empty());
    double lowest = 1e9;
    for (auto& q : c.position) lowest = std::min(lowest, static_cast<double>(q.y));
    const double t = s.time();
    // The first parcel leaves within the first step.
    EXPECT_NEAR(0.3 - lowest, 0.5 * p.gravity * t * t, p.gravity * t * PourStream::kStep + 1e-6) << t;
    EXPECT_LE(0.3 - lowest, 0.5 * p.gravity * t * t + 1e-6);
  }
}

TEST(PourStream, ThinsDownwardsAndStaysJoined) {
  StreamParams p;
  p.wobble = 0;
  PourStream s = pour(p);
  s.advance(0.5);  // steady: the stream reaches the glass after 0.25 s
  const PointCloud c = s.cloud();
  ASSERT_GT(c.size(), 100u);
  // Parcels are in emission order: oldest (lowest, fastest) first.
  for (std::size_t i = 1; i < c.size(); ++i) {
    EXPECT_LT(c.position[i - 1].y, c.position[i].y);
    EXPECT_LE(c.radius[i - 1], c.radius[i]);
    // Neighbours overlap into one stream: closer than either's blob radius.
    EXPECT_LT(glm::length(c.position[i] - c.position[i - 1]), std::min(c.radius[i], c.radius[i - 1]));
  }
  // Continuity: at the bottom, r = sqrt(Q / (pi v)) with v from the fall.
  const double v = std::sqrt(2 * p.gravity * (0.3 - c.position[0].y));
  EXPECT_NEAR(c.radius[0], std::sqrt(5e-5 / (M_PI * v)), 1e-5);
  EXPECT_LT(c.radius[0], 0.5 * c.radius.back());
}

TEST(PourStream, WobblesDeterministically) {
  PourStream a = pour(), b = pour();
  a.advance(0.6);
  b.advance(0.2);
  b.advance(0.4);
  const PointCloud ca = a.cloud(), cb = b.cloud();
  EXPECT_EQ(ca.position, cb.position);
  EXPECT_EQ(ca.radius, cb.radius);
  // The wobble bends the stream sideways by millimetres, not centimetres.
  double side = 0;
  for (auto& q : ca.position) side = std::max(side, std::hypot(static_cast<double>(q.x), static_cast<double>(q.z)));
  EXPECT_GT(side, 5e-4);
  EXPECT_LT(side, 0.02);
}

TEST(PourStream, NoFlowNoParcelsAndBadInputRefused) {
  PourStream s(StreamParams{}, {0, 0.3, 0}, {0, 0, 0}, 0.0);
  s.advance(0.5);
  EXPECT_EQ(s.parcels(), 0u);
  EXPECT_EQ(s.emitted_volume(), 0.0);
  auto names = [](auto f, const std::string& field) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find(field) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(names([&] { s.set_flow(1, -1); }, "flow"));
  EXPECT_TRUE(names([&] { s.set_flow(1, std::nan("")); }, "flow"));
  EXPECT_TRUE(names([&] { s.set_target_height(INFINITY); }, "target height"));
  EXPECT_TRUE(names([&] { s.set_origin({0, NAN, 0}, {}); }, "origin"));
  StreamParams p;
  p.gravity = 0;
  EXPECT_TRUE(names([&] { PourStream bad(p); }, "gravity"));
  p = {};
  p.overlap = 5;
  EXPECT_TRUE(names([&] { PourStream bad(p); }, "overlap"));
}

}  // namespace
}  // namespace draught
