// The fill table: the offset of the liquid's plane for a tilt and a volume fraction.
// Checked against closed forms (tilted cylinder, cone cut through its side), against
// brute-force Monte Carlo volumes in real glasses, and for capacity / spilling.
#include "core/vessel/fill_table.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace draught {
namespace {

double deg(double d) { return d * kPi / 180; }

// A vessel built by hand from an inner radius r(y) (knots at y = k * dy; r is linear
// between knots, so cylinders and cones with the apex on a knot are exact).
Vessel hand_vessel(double height, double base, const std::function<double(double)>& r) {
  Vessel v;
  v.height = height;
  v.base = base;
  v.dy = height / Vessel::kSegments;
  for (int k = 0; k <= Vessel::kSegments; ++k) {
    v.r_inner.push_back(std::max(r(k * v.dy), 0.0));
    v.r_outer.push_back(v.r_inner.back() + 0.002);
  }
  v.rim_major = v.r_inner.back() + 0.001, v.rim_minor = 0.001;
  v.bound_radius = v.rim_major + v.rim_minor;
  return v;
}

// ---- Tilted cylinder, radius R, cavity y in [b, H]; liquid where sin(t) x + cos(t) y < d.
// A column at x holds liquid up to h(x) = (d - sin(t) x) / cos(t) = h0 - m x (h0 the axis
// intercept, m = tan t), its cross-section is the chord 2 sqrt(R^2 - x^2). With
// F(e) = int 2 sqrt(R^2 - x^2) max(e - m x, 0) dx over [-R, R] (the liquid above a floor
// e below the axis intercept, no lid), clamping the column to [b, H] gives
// V = F(h0 - b) - F(h0 - H). F is the cylindrical wedge ("hoof"): the column is wet for
// x < x0 = e / m and
//   F = m int_{-R}^{x0} 2 sqrt(R^2 - x^2) (x0 - x) dx = m (x0 A(x0) + 2/3 (R^2 - x0^2)^(3/2)),
// A(x0) = R^2 acos(-x0 / R) + x0 sqrt(R^2 - x0^2) the disk's area left of x0;
// for x0 >= R it is the plain slab pi R^2 e. Valid for tilts in [0, 90) degrees.
struct Cylinder {
  double R, b, H;
  double cavity() const { return kPi * R * R * (H - b); }
  double wedge(double e, double m) const {
    if (m <= 0) return kPi * R * R * std::max(e, 0.0);
    const double x0 = e / m;
    if (x0 >= R) return kPi * R * R * e;
    if (x0 <= -R) return 0;
    const double h = std::sqrt(R * R - x0 * x0);
    const double area = R * R * std::acos(-x0 / R) + x0 * h;
    return m * (x0 * area + 2.0 / 3.0 * h * h * h);
  }
  double volume(double tilt, double d) const {
    const double m = std::tan(tilt), h0 = d / std::cos(tilt);
    return wedge(h0 - b, m) - wedge(h0 - H, m);
  }
  // The plane meets the base inside the cavity: the wet part of the floor ends at x0 < R.
  bool meets_base(double tilt, double d) const { return (d / std::cos(tilt) - b) < std::tan(tilt) * R; }
  Vessel vessel() const {
    return hand_vessel(H, b, [&](double) { return R; });
  }
};

// ---- FillCone, apex down at (0, b, 0), r = k (y - b) (a martini bowl). A plane that cuts
// only the side makes an elliptical section; the solid below is a cone over that
// ellipse, V = 1/3 * area * (distance from the apex to the plane) = pi/3 a e p, with
// p = d - cos(t) b. In the x-y plane the section meets the two generators x = +-k (y - b)
// at heights u1 = p / (cos t + k sin t), u2 = p / (cos t - k sin t) above the apex, so
// the major axis is 2a = |(k (u1 + u2), u1 - u2)|; at the ellipse's centre the cone's
// circle gives the minor half-axis e = sqrt(k^2 ((u1+u2)/2)^2 - (k (u1-u2)/2)^2) = k sqrt(u1 u2).
// Valid while the plane is less steep than the side (tan t < 1 / k) and below the rim
// (b + u2 <= H).
struct FillCone {
  double k, b, H;
  double cavity() const { return kPi / 3 * k * k * std::pow(H - b, 3); }
  double volume(double tilt, double d) const {
    const double s = std::sin(tilt), c = std::cos(tilt), p = d - c * b;
    if (p <= 0) return 0;
    const double u1 = p / (c + k * s), u2 = p / (c - k * s);
    const double a = 0.5 * std::hypot(k * (u1 + u2), u1 - u2), e = k * std::sqrt(u1 * u2);
    return kPi / 3 * a * e * p;
  }
  bool valid(double tilt, double d) const {
    const double c = std::cos(tilt), s = std::sin(tilt);
    return c - k * s > 1e-9 && b + (d - c * b) / (c - k * s) <= H * (1 + 1e-12);
  }
  Vessel vessel() const {
    return hand_vessel(H, b, [&](double y) { return k * (y - b); });
  }
};

const Cylinder kCyl{0.035, 0.01, 0.15};
// Apex on knot 12 so the segmented profile is exactly this cone; half-angle ~35 deg.
const FillCone kFillCone{0.7, 12 * 0.12 / Vessel::kSegments, 0.12};

// An independent brute-force check of the closed forms: midpoint rule over a fine x-z
// grid, each column's wet height between the cavity's floor (a function of r) and the plane.
double column_volume(double rmax, double tilt, double d, const std::function<double(double)>& floor_at_r,
                     double top, int n = 1500) {
  const double h = 2 * rmax / n, s = std::sin(tilt), c = std::cos(tilt);
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -rmax + (i + 0.5) * h, z = -rmax + (j + 0.5) * h, r = std::hypot(x, z);
      if (r > rmax) continue;
      const double lo = floor_at_r(r), hi = std::min((d - s * x) / c, top);
      sum += std::max(hi - lo, 0.0);
    }
  return sum * h * h;
}

TEST(FillTableClosedForm, CylinderWedgeMatchesNumericalIntegral) {
  const Cylinder& C = kCyl;
  auto floor = [&](double) { return C.b; };
  int base_cases = 0;
  for (double t : {0.0, 10.0, 40.0, 63.0, 80.0}) {
    for (double f : {0.05, 0.3, 0.6, 0.9}) {
      // A plane through the axis at the height holding f upright (tilted about it).
      const double d = std::cos(deg(t)) * (C.b + f * (C.H - C.b));
      base_cases += C.meets_base(deg(t), d);
      EXPECT_NEAR(C.volume(deg(t), d), column_volume(C.R, deg(t), d, floor, C.H), 2e-5 * C.cavity())
          << "tilt " << t << " f " << f;
    }
  }
  EXPECT_GE(base_cases, 3) << "the wedge branch must be exercised";
  // Upright: the plain slab.
  EXPECT_NEAR(C.volume(0, 0.08), kPi * C.R * C.R * (0.08 - C.b), 1e-15);
}

TEST(FillTableClosedForm, ConeSectionMatchesNumericalIntegral) {
  const FillCone& K = kFillCone;
  auto floor = [&](double r) { return K.b + r / K.k; };
  const double rim = K.k * (K.H - K.b);
  int checked = 0;
  for (double t : {0.0, 15.0, 33.0, 50.0}) {
    for (double f : {0.02, 0.2, 0.5}) {
      const double d = std::cos(deg(t)) * (K.b + f * (K.H - K.b));
      if (!K.valid(deg(t), d)) continue;
      ++checked;
      EXPECT_NEAR(K.volume(deg(t), d), column_volume(rim, deg(t), d, floor, K.H), 2e-5 * K.cavity())
          << "tilt " << t << " f " << f;
    }
  }
  EXPECT_GE(checked, 8) << "oblique sections must be exercised";
}

TEST(FillTableClosedForm, ReferenceIntegratorMatchesClosedForms) {
  // volume_below_plane is what the table is built from (and the reference for the
  // dense sweep below): it must agree with the closed forms far below the table's
  // 0.1 % (the reference solver's ~1e-6 bound).
  const Vessel vc = kCyl.vessel(), vk = kFillCone.vessel();
  double worst_c = 0, worst_k = 0;
  for (double t = 0; t < 89.9; t += 1.37)
    for (double u = 0.01; u < 1; u += 0.049) {
      double lo, hi;
      offset_range(vc, deg(t), lo, hi);
      const double dc = lo + u * (hi - lo);
      worst_c = std::max(worst_c, std::abs(volume_below_plane(vc, deg(t), dc) - kCyl.volume(deg(t), dc)));
      const double dk = u * rim_offset(vk, deg(t));
      if (kFillCone.valid(deg(t), dk))
        worst_k = std::max(worst_k, std::abs(volume_below_plane(vk, deg(t), dk) - kFillCone.volume(deg(t), dk)));
    }
  EXPECT_LE(worst_c, 1e-6 * kCyl.cavity());
  EXPECT_LE(worst_k, 1e-6 * kFillCone.cavity());
}

// ---- The table against the closed forms: many off-grid tilts and fractions, not spilled.
template <class Shape>
void check_table_against(const Shape& S, double max_tilt) {
  constexpr bool kCylinder = std::is_same_v<Shape, Cylinder>;
  const Vessel v = S.vessel();
  ASSERT_NEAR(v.cavity_volume(), S.cavity(), 1e-12 * S.cavity()) << "the hand-built vessel is the shape";
  const FillTable table = build_fill_table(v);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0, 1);
  int at_base = 0, bad = 0;
  double worst = 0, worst_t = 0, worst_f = 0;
  // Random states, then a grid that also covers the nearly full glass (q -> 1) densely.
  std::vector<std::pair<double, double>> tq;
  for (int n = 0; n < 3000; ++n) {
    const double t = max_tilt * U(rng);
    tq.emplace_back(t, U(rng));
  }
  for (double t = deg(0.05); t < max_tilt; t += deg(0.37))
    for (double q : {0.003, 0.05, 0.3, 0.6, 0.9, 0.97, 0.99, 0.997, 1.0}) tq.emplace_back(t, q);
  const int kStates = int(tq.size());
  for (const auto& [t, q] : tq) {
    // Not spilled: at most what the table says stays in, and what really stays in.
    const double cap = std::min(table.capacity_at(t), S.volume(t, rim_offset(v, t)) / S.cavity());
    const double f = cap * q;
    const double d = table.offset_at(t, f);
    double held = 0;
    if constexpr (kCylinder) {
      at_base += S.meets_base(t, d);
      held = S.volume(t, d);
    } else {
      // A table plane a hair above the rim (f at capacity) leaves the closed form's
      // domain: there the reference integrator (checked against it above) stands in.
      held = S.valid(t, d) ? S.volume(t, d) : volume_below_plane(v, t, d);
    }
    const double err = std::abs(held - f * S.cavity()) / S.cavity();
    bad += err > 1e-3;
    if (err > worst) worst = err, worst_t = t, worst_f = f;
  }
  EXPECT_LE(worst, 1e-3) << "worst at tilt " << worst_t / deg(1) << " deg, fraction " << worst_f << "; " << bad
                         << " of " << kStates << " states over 0.1 %";
  if (kCylinder) {
    EXPECT_GT(at_base, 300) << "states where the surface meets the base must be covered";
  }
}

TEST(FillTable, CylinderTableVolumeWithinATenthOfAPercent) { check_table_against(kCyl, deg(89.5)); }

TEST(FillTable, ConeTableVolumeWithinATenthOfAPercent) {
  // Past 90 deg - half-angle the plane would be steeper than the side: nothing stays in.
  check_table_against(kFillCone, std::atan(1 / kFillCone.k) - 1e-3);
}

TEST(FillTable, ReferenceSolverHitsTheClosedFormVolume) {
  const Vessel vc = kCyl.vessel(), vk = kFillCone.vessel();
  for (double t : {0.0, 7.3, 31.0, 58.1, 77.7, 88.0})
    for (double f : {0.01, 0.17, 0.5, 0.83}) {
      const double tc = deg(t), cap = kCyl.volume(tc, rim_offset(vc, tc)) / kCyl.cavity();
      if (f < cap) {
        const double d = plane_offset_for_volume(vc, tc, f * kCyl.cavity());
        EXPECT_NEAR(kCyl.volume(tc, d) / kCyl.cavity(), f, 1e-6) << "cylinder tilt " << t;
      }
      if (tc < std::atan(1 / kFillCone.k) && f < kFillCone.volume(tc, rim_offset(vk, tc)) / kFillCone.cavity()) {
        const double d = plane_offset_for_volume(vk, tc, f * kFillCone.cavity());
        ASSERT_TRUE(kFillCone.valid(tc, d));
        EXPECT_NEAR(kFillCone.volume(tc, d) / kFillCone.cavity(), f, 1e-6) << "cone tilt " << t;
      }
    }
}

// ---- Monte Carlo in the shipped wine glass and weizen vase.
// N points uniform in the cavity's bounding box; a state's volume is box * hits / N.
// The hit fraction p has standard error sqrt(p (1 - p) / N) <= 0.5 / sqrt(N) = 2.5e-4 of
// the box for N = 4e6; the cavities fill 52 % (weizen) and 59 % (wine) of their boxes,
// so that is <= 0.05 % of the glass: the 0.5 % tolerance is ~10 standard errors.
class FillTableMonteCarlo : public ::testing::TestWithParam<const char*> {};

TEST_P(FillTableMonteCarlo, TableVolumeWithinHalfAPercent) {
  const Vessel v = test::preset_vessel(GetParam());
  const FillTable table = build_fill_table(v);
  const double cavity = v.cavity_volume();
  double rmax = 0;
  for (int k = 0; k <= Vessel::kSegments; ++k)
    if (k * v.dy >= v.base - v.dy) rmax = std::max(rmax, v.r_inner[size_t(k)]);
  struct State {
    double tilt, fraction, offset;
    long hits = 0;
  };
  std::vector<State> states;
  for (double t : {0.0, 20.0, 47.0, 70.0, 84.0})
    for (double q : {0.1, 0.4, 0.7, 0.97}) {
      const double f = q * table.capacity_at(deg(t));
      states.push_back({deg(t), f, table.offset_at(deg(t), f)});
    }
  constexpr long kN = 4'000'000;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> ux(-rmax, rmax), uy(v.base, v.height);
  long in_cavity = 0;
  for (long i = 0; i < kN; ++i) {
    const double x = ux(rng), y = uy(rng), z = ux(rng);
    if (x * x + z * z > std::pow(v.inner_radius(y), 2)) continue;
    ++in_cavity;
    for (State& s : states) s.hits += std::sin(s.tilt) * x + std::cos(s.tilt) * y < s.offset;
  }
  const double box = 4 * rmax * rmax * (v.height - v.base);
  // The sampler itself: it finds the cavity's volume.
  EXPECT_NEAR(box * double(in_cavity) / kN, cavity, 2e-3 * cavity);
  for (const State& s : states) {
    const double mc = box * double(s.hits) / kN;
    EXPECT_NEAR(mc / cavity, s.fraction, 5e-3) << GetParam() << " tilt " << s.tilt / deg(1) << " f " << s.fraction;
  }
}

INSTANTIATE_TEST_SUITE_P(FillTableGlasses, FillTableMonteCarlo, ::testing::Values("wine", "weizen"));

// Monte Carlo is sparse; the reference integrator (checked against the closed forms
// above) sweeps every shipped glass densely, same 0.5 % bound.
TEST(FillTable, ShippedGlassesDenseSweepWithinHalfAPercent) {
  for (const char* g : {"pint", "nonic", "wine", "flute", "tulip", "weizen"}) {
    const Vessel v = test::preset_vessel(g);
    const FillTable table = build_fill_table(v);
    double worst = 0, worst_t = 0, worst_f = 0;
    for (double t = 0.3; t < 90; t += 1.7)
      for (double q = 0.0125; q < 1; q += 0.025) {
        const double f = q * table.capacity_at(deg(t));
        const double err = std::abs(volume_below_plane(v, deg(t), table.offset_at(deg(t), f)) / v.cavity_volume() - f);
        if (err > worst) worst = err, worst_t = t, worst_f = f;
      }
    EXPECT_LE(worst, 5e-3) << g << ": worst at tilt " << worst_t << " deg, fraction " << worst_f;
  }
}

// ---- Capacity and spilling.
TEST(FillTableCapacity, UprightHoldsEverything) {
  for (const char* g : {"pint", "wine", "weizen", "flute"})
    EXPECT_NEAR(build_fill_table(test::preset_vessel(g)).capacity_at(0), 1.0, 1e-6) << g;
  EXPECT_NEAR(build_fill_table(kCyl.vessel()).capacity_at(0), 1.0, 1e-6);
}

TEST(FillTableCapacity, CylinderCapacityFallsWithTiltAndMatchesClosedForm) {
  const Vessel v = kCyl.vessel();
  const FillTable table = build_fill_table(v);
  double prev = 1.0 + 1e-12, worst = 0, worst_t = 0;
  for (double t = 0.5; t < 89.9; t += 0.7) {
    const double cap = table.capacity_at(deg(t));
    EXPECT_LT(cap, prev) << "capacity must fall with tilt, tilt " << t;
    // Against the plane through the lowest rim point, closed form: the 0.1 % bound.
    const double err = std::abs(cap - kCyl.volume(deg(t), rim_offset(v, deg(t))) / kCyl.cavity());
    if (err > worst) worst = err, worst_t = t;
    prev = cap;
  }
  EXPECT_LE(worst, 1e-3) << "worst at tilt " << worst_t << " deg";
  EXPECT_LT(table.capacity_at(deg(90)), 1e-3) << "a cylinder on its side holds nothing";
  EXPECT_LT(table.capacity_at(deg(120)), 1e-6);
}

TEST(FillTableCapacity, WineGlassOnItsSideStillHoldsTheBulge) {
  // The bowl is wider than the rim: on its side, what lies beyond the rim's radius stays.
  // Independent integral: per height, the circular segment of the slice past x = r_rim.
  const Vessel v = test::preset_vessel("wine");
  const double a = v.inner_radius(v.height);
  const int n = 200000;
  const double h = (v.height - v.base) / n;
  double held = 0;
  for (int i = 0; i < n; ++i) {
    const double r = v.inner_radius(v.base + (i + 0.5) * h);
    if (r > a) held += r * r * std::acos(a / r) - a * std::sqrt(r * r - a * a);
  }
  held *= h / v.cavity_volume();
  const double cap = build_fill_table(v).capacity_at(deg(90));
  EXPECT_GT(held, 0.003);
  EXPECT_GT(cap, 0.0);
  EXPECT_NEAR(cap, held, 1e-3);
}

TEST(FillTableCapacity, AtCapacityTheSurfaceTouchesTheRim) {
  // At capacity the lowest rim point lies on the surface: the table's plane is the rim
  // plane, within a millimetre, and the volume between them is within the bound for
  // arbitrary profiles (0.5 %; the 0.1 % bound is for the cylinder and the cone). The
  // renderer also clamps the plane to the rim, so liquid never shows above it.
  for (const char* g : {"pint", "wine", "weizen"}) {
    const Vessel v = test::preset_vessel(g);
    const FillTable table = build_fill_table(v);
    double worst_d = 0, worst_v = 0, at_d = 0, at_v = 0;
    for (double t = 1.0; t < 88.5; t += 0.75) {
      const double cap = table.capacity_at(deg(t));
      if (cap < 1e-3) continue;
      const double d = table.offset_at(deg(t), cap), rim = rim_offset(v, deg(t));
      const double dv = std::abs(volume_below_plane(v, deg(t), d) - volume_below_plane(v, deg(t), rim));
      if (std::abs(d - rim) > worst_d) worst_d = std::abs(d - rim), at_d = t;
      if (dv > worst_v) worst_v = dv, at_v = t;
    }
    EXPECT_LE(worst_d, 1e-3) << g << ": worst offset at tilt " << at_d << " deg (metres)";
    EXPECT_LE(worst_v / table.cavity_volume, 5e-3) << g << ": worst volume at tilt " << at_v << " deg";
  }
}

}  // namespace
}  // namespace draught
