// The pour's stream: volume conserved to rounding, every parcel arrives once the flow
// stops, the front falls freely, the stream thins downwards and stays joined, it is
// deterministic, and bad input is refused by name.
#include "core/pointcloud/stream.hpp"

#include "core/pointcloud/field.hpp"

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

// The radius at which the stream's field falls to the threshold, out from its axis (x = z
// = 0) at height y: the stream's width as it is drawn.
double drawn_radius(const PointCloud& c, double y) {
  double lo = 0, hi = 0.05;
  for (int i = 0; i < 50; ++i) {
    const double m = 0.5 * (lo + hi);
    (cloud_field_reference(c, kCloudThreshold, {m, y, 0}) >= kCloudThreshold ? lo : hi) = m;
  }
  return lo;
}

TEST(PourStream, ThinsDownwardsAndStaysJoined) {
  StreamParams p;
  p.wobble = 0;
  PourStream s = pour(p);
  s.advance(0.5);  // steady: the stream reaches the glass after 0.25 s
  const PointCloud c = s.cloud();
  ASSERT_GT(c.size(), 100u);
  // Parcels are in emission order: oldest (lowest, fastest) first; neighbours overlap.
  for (std::size_t i = 1; i < c.size(); ++i) {
    EXPECT_LT(c.position[i - 1].y, c.position[i].y);
    EXPECT_LE(c.radius[i - 1], c.radius[i]);
    EXPECT_LT(glm::length(c.position[i] - c.position[i - 1]), std::min(c.radius[i], c.radius[i - 1]));
  }
  // Continuity: the stream is drawn sqrt(Q / (pi v)) wide, v from the fall, near the spout
  // (slow, its parcels close together) as far down (fast, far apart), joined all along.
  double last = 1;
  for (double y : {0.28, 0.25, 0.2, 0.15, 0.1, 0.05, 0.01}) {
    const double v = std::sqrt(2 * p.gravity * (0.3 - y)), r = drawn_radius(c, y);
    EXPECT_NEAR(r / std::sqrt(5e-5 / (M_PI * v)), 1.0, 0.02) << y;
    EXPECT_LT(r, last) << y;
    last = r;
  }
}

// A glass's rim of radius 4 cm, tipped 50 degrees about z towards +x, 20 cm above the floor.
StreamLip tipped_rim() {
  const double th = 50 * M_PI / 180;
  StreamLip lip;
  lip.centre = {0, 0.2, 0};
  lip.up = {std::sin(th), std::cos(th), 0};
  lip.outward = {std::cos(th), -std::sin(th), 0};
  lip.radius = 0.04;
  return lip;
}

TEST(PourStream, OverALipTheFlowLeavesAsASheetThatClosesIntoARope) {
  StreamParams p;
  p.wobble = 0;
  PourStream s(p, {}, {}, 0.0);
  s.set_lip(tipped_rim());
  // The weir: the sheet's depth and width pass the flow, Q = sqrt(g) (3 pi / 8) h^(3/2) a,
  // with the rim risen by the depth at the sheet's sides (k a^2 = h, k = sin 50 / 2R).
  const double q = 8e-5, k = std::sin(50 * M_PI / 180) / 0.08;
  const PourStream::Sheet sh = s.sheet(q);
  EXPECT_NEAR(std::sqrt(p.gravity) * 3 * M_PI / 8 * std::pow(sh.depth, 1.5) * sh.half_width / q, 1.0, 1e-9);
  EXPECT_NEAR(k * sh.half_width * sh.half_width / sh.depth, 1.0, 1e-9);
  EXPECT_GT(sh.half_width, 0.02);  // a tongue some 6 cm wide, 8 mm deep
  EXPECT_LT(sh.depth, 0.01);
  // A rim held level spills around half of it.
  StreamLip level = tipped_rim();
  level.up = {0, 1, 0};
  level.outward = {1, 0, 0};
  PourStream flat(p, {}, {}, 0.0);
  flat.set_lip(level);
  EXPECT_DOUBLE_EQ(flat.sheet(q).half_width, 0.5 * M_PI * 0.04);

  s.set_flow(0, q);
  s.advance(0.4);  // steady: it reaches the floor in about 0.2 s
  const PointCloud c = s.cloud();
  // Across the fall (z), the sheet is as wide as the lip where it leaves and a rope lower down.
  auto width_near = [&](double y) {
    double lo = 1, hi = -1;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (std::abs(c.position[i].y - y) < 0.004) {
        lo = std::min(lo, double(c.position[i].z));
        hi = std::max(hi, double(c.position[i].z));
      }
    return hi - lo;
  };
  EXPECT_GT(width_near(0.16), 0.03);
  EXPECT_LT(width_near(0.16), 2 * sh.half_width);
  EXPECT_LT(width_near(0.02), 1e-6);
  // The rope is drawn as wide as continuity gives the whole flow: find its axis at y = 0.03
  // (between the slices about it), then where the field falls to the threshold along z.
  const double y = 0.03;
  double x = 0, vy = 0;
  for (std::size_t i = 1; i < c.size(); ++i)
    if ((c.position[i - 1].y - y) * (c.position[i].y - y) <= 0) {
      const double u = (y - c.position[i - 1].y) / (c.position[i].y - c.position[i - 1].y);
      x = c.position[i - 1].x + u * (c.position[i].x - c.position[i - 1].x);
      vy = c.velocity[i].y;
    }
  const double vx = std::sqrt(p.gravity * sh.depth) * 128 / (45 * M_PI) * std::cos(50 * M_PI / 180);
  const double speed = std::hypot(vx, vy);
  double lo = 0, hi = 0.05;
  for (int i = 0; i < 50; ++i) {
    const double m = 0.5 * (lo + hi);
    (cloud_field_reference(c, kCloudThreshold, {x, y, m}) >= kCloudThreshold ? lo : hi) = m;
  }
  EXPECT_NEAR(lo / std::sqrt(q / (M_PI * speed)), 1.0, 0.05);
  // Volume is kept: what left is on the floor or in the air.
  EXPECT_NEAR((s.arrived_volume() + s.in_flight_volume()) / s.emitted_volume(), 1.0, 1e-12);
  EXPECT_NEAR(s.emitted_volume() / (q * 0.4), 1.0, 1e-9);
  EXPECT_GT(s.arrived_volume(), 0.0);
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
  StreamLip lip;
  lip.outward = {0, 1, 0};  // not in the rim's plane
  EXPECT_TRUE(names([&] { s.set_lip(lip); }, "lip"));
  lip.outward = {1, 0, 0};
  lip.radius = 0;
  EXPECT_TRUE(names([&] { s.set_lip(lip); }, "lip"));
  StreamParams p;
  p.gravity = 0;
  EXPECT_TRUE(names([&] { PourStream bad(p); }, "gravity"));
  p = {};
  p.overlap = 5;
  EXPECT_TRUE(names([&] { PourStream bad(p); }, "overlap"));
}

}  // namespace
}  // namespace draught
