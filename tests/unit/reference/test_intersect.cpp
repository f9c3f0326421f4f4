// The reference intersector: polynomial solvers against known roots, cone and torus
// intersections against closed forms and brute-force root finding, and the vessel's
// hits against a brute-force march of a point classifier.
#include "core/reference/intersect.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace draught {
namespace {

using glm::dvec3;

// ---------------------------------------------------------------- brute force --

// Roots of f on [a, b]: sign changes on a uniform grid, refined by bisection.
template <class F>
std::vector<double> brute_roots(F f, double a, double b, int n) {
  std::vector<double> roots;
  double t0 = a, f0 = f(a);
  for (int i = 1; i <= n; ++i) {
    const double t1 = a + (b - a) * i / n, f1 = f(t1);
    if (f0 == 0) {
      roots.push_back(t0);
    } else if ((f0 < 0) != (f1 < 0) && f1 != 0) {
      double lo = t0, hi = t1, flo = f0;
      for (int k = 0; k < 200 && hi - lo > 1e-16 * std::max(1.0, std::fabs(lo)); ++k) {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm < 0) == (flo < 0)) lo = mid, flo = fm;
        else hi = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    t0 = t1, f0 = f1;
  }
  return roots;
}

dvec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    dvec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-6) return glm::normalize(v);
  }
}

// ------------------------------------------------------------------ solvers --

TEST(SolveCubic, ThreeDistinctRealRoots) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int trial = 0; trial < 500; ++trial) {
    double r[3] = {u(rng), u(rng), u(rng)};
    std::sort(r, r + 3);
    if (r[1] - r[0] < 0.05 || r[2] - r[1] < 0.05) continue;  // well separated
    const double a = -(r[0] + r[1] + r[2]), b = r[0] * r[1] + r[0] * r[2] + r[1] * r[2], c = -r[0] * r[1] * r[2];
    double out[3];
    ASSERT_EQ(solve_cubic(a, b, c, out), 3) << r[0] << " " << r[1] << " " << r[2];
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], r[i], 1e-9);
  }
}

TEST(SolveCubic, OneRealRootAndAComplexPair) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-5, 5), pos(0.1, 4);
  for (int trial = 0; trial < 500; ++trial) {
    // (x - r)(x^2 + p x + q) with p^2 < 4 q.
    const double r = u(rng), p = u(rng), q = p * p / 4 + pos(rng);
    const double a = p - r, b = q - r * p, c = -r * q;
    double out[3];
    ASSERT_EQ(solve_cubic(a, b, c, out), 1);
    EXPECT_NEAR(out[0], r, 1e-9);
  }
}

TEST(SolveCubic, KnownExamples) {
  double out[3];
  // x^3 - 6x^2 + 11x - 6 = (x-1)(x-2)(x-3)
  ASSERT_EQ(solve_cubic(-6, 11, -6, out), 3);
  EXPECT_NEAR(out[0], 1, 1e-12);
  EXPECT_NEAR(out[1], 2, 1e-12);
  EXPECT_NEAR(out[2], 3, 1e-12);
  // x^3 - 8 = (x - 2)(x^2 + 2x + 4)
  ASSERT_EQ(solve_cubic(0, 0, -8, out), 1);
  EXPECT_NEAR(out[0], 2, 1e-12);
  // x^3 + x = x (x^2 + 1)
  ASSERT_EQ(solve_cubic(0, 1, 0, out), 1);
  EXPECT_NEAR(out[0], 0, 1e-12);
}

void expand_quartic(const double r[4], double& b, double& c, double& d, double& e) {
  b = -(r[0] + r[1] + r[2] + r[3]);
  c = r[0] * r[1] + r[0] * r[2] + r[0] * r[3] + r[1] * r[2] + r[1] * r[3] + r[2] * r[3];
  d = -(r[0] * r[1] * r[2] + r[0] * r[1] * r[3] + r[0] * r[2] * r[3] + r[1] * r[2] * r[3]);
  e = r[0] * r[1] * r[2] * r[3];
}

TEST(SolveQuartic, FourDistinctRealRoots) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-4, 4);
  int tested = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    double r[4] = {u(rng), u(rng), u(rng), u(rng)};
    std::sort(r, r + 4);
    if (r[1] - r[0] < 0.05 || r[2] - r[1] < 0.05 || r[3] - r[2] < 0.05) continue;
    ++tested;
    double b, c, d, e, out[4];
    expand_quartic(r, b, c, d, e);
    ASSERT_EQ(solve_quartic(b, c, d, e, out), 4) << r[0] << " " << r[1] << " " << r[2] << " " << r[3];
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(out[i], r[i], 1e-8);
  }
  EXPECT_GT(tested, 500);
}

TEST(SolveQuartic, TwoRealRootsAndAComplexPair) {
  std::mt19937 rng(10);
  std::uniform_real_distribution<double> u(-4, 4), pos(0.1, 4);
  for (int trial = 0; trial < 1000; ++trial) {
    double r0 = u(rng), r1 = u(rng);
    if (r0 > r1) std::swap(r0, r1);
    if (r1 - r0 < 0.05) continue;
    // (x - r0)(x - r1)(x^2 + p x + q), p^2 < 4 q
    const double p = u(rng), q = p * p / 4 + pos(rng);
    const double s = -(r0 + r1), m = r0 * r1;  // x^2 + s x + m
    const double b = s + p, c = m + s * p + q, d = s * q + m * p, e = m * q;
    double out[4];
    ASSERT_EQ(solve_quartic(b, c, d, e, out), 2) << r0 << " " << r1 << " p=" << p << " q=" << q;
    EXPECT_NEAR(out[0], r0, 1e-8);
    EXPECT_NEAR(out[1], r1, 1e-8);
  }
}

TEST(SolveQuartic, NoRealRoots) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-4, 4), pos(0.1, 4);
  for (int trial = 0; trial < 500; ++trial) {
    const double p1 = u(rng), q1 = p1 * p1 / 4 + pos(rng), p2 = u(rng), q2 = p2 * p2 / 4 + pos(rng);
    const double b = p1 + p2, c = q1 + q2 + p1 * p2, d = p1 * q2 + p2 * q1, e = q1 * q2;
    double out[4];
    EXPECT_EQ(solve_quartic(b, c, d, e, out), 0);
  }
}

TEST(SolveQuartic, NearlyBiquadraticWithAComplexPair) {
  // ((x - s)^2 - a^2)((x - s)^2 + b^2): real roots s +- a and the complex pair
  // s +- ib. The depressed quartic has q == 0 exactly, but rounding in the
  // coefficients leaves a tiny q, which must not lose the real roots.
  int failures = 0;
  for (double s : {0.0, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0}) {
    for (double a : {0.01, 0.1, 0.3, 0.7}) {
      for (double bb : {0.5, 1.0, 2.0}) {
        const double P = bb * bb - a * a, Q = -a * a * bb * bb;  // y^4 + P y^2 + Q, y = x - s
        const double B = -4 * s, C = 6 * s * s + P, D = -4 * s * s * s - 2 * P * s, E = s * s * s * s + P * s * s + Q;
        double out[4];
        const int n = solve_quartic(B, C, D, E, out);
        const bool ok = n == 2 && std::fabs(out[0] - (s - a)) < 1e-7 && std::fabs(out[1] - (s + a)) < 1e-7;
        if (!ok && ++failures <= 8)
          ADD_FAILURE() << "s=" << s << " a=" << a << " b=" << bb << ": got " << n << " roots"
                        << (n > 0 ? ", first " + std::to_string(out[0]) : std::string());
      }
    }
  }
  EXPECT_EQ(failures, 0) << "of 84 quartics";
}

TEST(SolveQuartic, SymmetricRootsTakeTheBiquadraticPath) {
  double out[4];
  // (x^2 - 1)(x^2 - 4) = x^4 - 5x^2 + 4
  ASSERT_EQ(solve_quartic(0, -5, 0, 4, out), 4);
  EXPECT_NEAR(out[0], -2, 1e-12);
  EXPECT_NEAR(out[1], -1, 1e-12);
  EXPECT_NEAR(out[2], 1, 1e-12);
  EXPECT_NEAR(out[3], 2, 1e-12);
  // Shifted by 3: roots 1, 2, 4, 5 (the depressed quartic has q == 0).
  const double r[4] = {1, 2, 4, 5};
  double b, c, d, e;
  expand_quartic(r, b, c, d, e);
  ASSERT_EQ(solve_quartic(b, c, d, e, out), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out[i], r[i], 1e-10);
  // (x^2 + 1)(x^2 + 4): none.
  EXPECT_EQ(solve_quartic(0, 5, 0, 4, out), 0);
  // (x^2 - 1)(x^2 + 4): +-1.
  ASSERT_EQ(solve_quartic(0, 3, 0, -4, out), 2);
  EXPECT_NEAR(out[0], -1, 1e-12);
  EXPECT_NEAR(out[1], 1, 1e-12);
}

// ------------------------------------------------------------------- cones --

TEST(IntersectCone, CylinderMatchesClosedForm) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1, 1), rad(0.2, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double R = rad(rng), y0 = u(rng) * 0.5 - 0.5, y1 = y0 + rad(rng);
    // Aim near the wall so that most rays hit.
    const double phi = M_PI * u(rng), ra = R * (1 + 0.5 * u(rng));
    const dvec3 aim(ra * std::cos(phi), y0 + (y1 - y0) * (0.5 + 0.5 * u(rng)), ra * std::sin(phi));
    const dvec3 o = dvec3(u(rng), u(rng), u(rng)) * 2.0;
    Ray ray{o, glm::normalize(aim - o)};
    const double tmin = trial % 3 == 0 ? 0.5 : 1e-9;
    // Closed form: |o_xz + t d_xz|^2 = R^2.
    std::vector<double> expected;
    const double A = ray.d.x * ray.d.x + ray.d.z * ray.d.z;
    const double B = 2 * (ray.o.x * ray.d.x + ray.o.z * ray.d.z);
    const double C = ray.o.x * ray.o.x + ray.o.z * ray.o.z - R * R;
    const double disc = B * B - 4 * A * C;
    if (A < 1e-6 || disc <= 1e-9) continue;  // parallel to the axis or near-tangent
    for (double t : {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)}) {
      const double y = ray.o.y + t * ray.d.y;
      if (t > tmin && y >= y0 && y <= y1) expected.push_back(t);
    }
    double out[2];
    const int n = intersect_cone(ray, R, R, y0, y1, tmin, out);
    ASSERT_EQ(n, int(expected.size())) << "trial " << trial;
    for (int i = 0; i < n; ++i) EXPECT_NEAR(out[i], expected[size_t(i)], 1e-10);
    hits += n;
  }
  EXPECT_GT(hits, 1000);
}

TEST(IntersectCone, ConeClosedForms) {
  double out[2];
  // 45-degree cone r = y (apex at the origin), horizontal ray at height h, offset c
  // from the axis: (t - L)^2 + c^2 = h^2.
  {
    const double h = 0.6, c = 0.2, L = 2.0;
    Ray ray{dvec3(-L, h, c), dvec3(1, 0, 0)};
    ASSERT_EQ(intersect_cone(ray, 0.0, 1.0, 0.0, 1.0, 0.0, out), 2);
    EXPECT_NEAR(out[0], L - std::sqrt(h * h - c * c), 1e-12);
    EXPECT_NEAR(out[1], L + std::sqrt(h * h - c * c), 1e-12);
    // Only the far hit past tmin.
    ASSERT_EQ(intersect_cone(ray, 0.0, 1.0, 0.0, 1.0, L, out), 1);
    EXPECT_NEAR(out[0], L + std::sqrt(h * h - c * c), 1e-12);
    // Outside the height range: none.
    Ray above{dvec3(-L, 1.5, c), dvec3(1, 0, 0)};
    EXPECT_EQ(intersect_cone(above, 0.0, 1.0, 0.0, 1.0, 0.0, out), 0);
  }
  // A vertical ray at x = a meets r = r0 + s (y - y0) at y = y0 + (a - r0) / s.
  {
    const double r0 = 0.03, r1 = 0.045, y0 = 0.01, y1 = 0.16, a = 0.04;
    const double s = (r1 - r0) / (y1 - y0);
    Ray up{dvec3(a, -1.0, 0.0), dvec3(0, 1, 0)};
    ASSERT_EQ(intersect_cone(up, r0, r1, y0, y1, 0.0, out), 1);
    EXPECT_NEAR(out[0], 1.0 + y0 + (a - r0) / s, 1e-12);
  }
  // The mirrored nappe (negative radius) is not part of the cone: the double cone
  // r = y - 0.5 for y in [0, 1] only exists above y = 0.5.
  {
    Ray ray{dvec3(-2, 0.2, 0), dvec3(1, 0, 0)};
    EXPECT_EQ(intersect_cone(ray, -0.5, 0.5, 0.0, 1.0, 0.0, out), 0);
  }
}

TEST(IntersectCone, RandomConesMatchBruteForce) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1), rad(0.1, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const double r0 = rad(rng), r1 = rad(rng), y0 = u(rng) * 0.3, y1 = y0 + 0.3 + rad(rng);
    const double s = (r1 - r0) / (y1 - y0);
    const double phi = M_PI * u(rng), f = 0.5 + 0.5 * u(rng), ra = (r0 + f * (r1 - r0)) * (1 + 0.3 * u(rng));
    const dvec3 aim(ra * std::cos(phi), y0 + f * (y1 - y0), ra * std::sin(phi));
    const dvec3 o = dvec3(u(rng), u(rng), u(rng)) * 2.0;
    Ray ray{o, glm::normalize(aim - o)};
    auto g = [&](double t) {
      const dvec3 p = ray.at(t);
      return std::hypot(p.x, p.z) - (r0 + s * (p.y - y0));
    };
    // The part of the ray inside the slab y0 <= y <= y1.
    double ta = 0, tb = 8;
    if (std::fabs(ray.d.y) > 1e-9) {
      const double a = (y0 - ray.o.y) / ray.d.y, b = (y1 - ray.o.y) / ray.d.y;
      ta = std::max(ta, std::min(a, b));
      tb = std::min(tb, std::max(a, b));
    } else if (ray.o.y < y0 || ray.o.y > y1) {
      continue;
    }
    std::vector<double> expected;
    if (ta < tb) expected = brute_roots(g, ta, tb, 20000);
    // Skip near-tangent rays: the brute force cannot resolve close root pairs.
    bool close = false;
    for (size_t i = 1; i < expected.size(); ++i) close |= expected[i] - expected[i - 1] < 1e-3;
    if (close) continue;
    double out[2];
    const int n = intersect_cone(ray, r0, r1, y0, y1, 0.0, out);
    ASSERT_EQ(n, int(expected.size())) << "trial " << trial;
    for (int i = 0; i < n; ++i) EXPECT_NEAR(out[i], expected[size_t(i)], 1e-9);
    hits += n;
  }
  EXPECT_GT(hits, 200);
}

// ------------------------------------------------------------------- torus --

double torus_f(const dvec3& p, double R, double r) {
  const double k = glm::dot(p, p) + R * R - r * r;
  return k * k - 4 * R * R * (p.x * p.x + p.z * p.z);
}

double torus_distance(const dvec3& p, double R, double r) {
  return std::fabs(std::hypot(std::hypot(p.x, p.z) - R, p.y) - r);
}

struct TorusCheck {
  int brute = 0, reported = 0;
};

// Every sign change of the implicit function along the ray is reported (within
// `tol`), and every reported root lies on the torus.
TorusCheck check_torus_ray(const Ray& ray, double R, double r, double cy, int samples, double tol,
                           bool exact_count) {
  double out[4];
  const int n = intersect_torus(ray, R, r, cy, out);
  const dvec3 c(0, cy, 0);
  const double span = glm::length(ray.o - c) + R + r + 0.1 * R;
  auto f = [&](double t) { return torus_f(ray.at(t) - c, R, r); };
  const std::vector<double> brute = brute_roots(f, -span, span, samples);
  EXPECT_LE(n, 4);
  for (int i = 1; i < n; ++i) EXPECT_LE(out[i - 1], out[i]) << "roots not ascending";
  for (int i = 0; i < n; ++i)
    EXPECT_LT(torus_distance(ray.at(out[i]) - c, R, r), tol * R)
        << "reported root t=" << out[i] << " is not on the torus; o=" << ray.o.x << "," << ray.o.y << ","
        << ray.o.z << " d=" << ray.d.x << "," << ray.d.y << "," << ray.d.z;
  for (double tb : brute) {
    double best = 1e300;
    for (int i = 0; i < n; ++i) best = std::min(best, std::fabs(out[i] - tb));
    EXPECT_LT(best, tol * R) << "missed root t=" << tb << "; o=" << ray.o.x << "," << ray.o.y << ","
                             << ray.o.z << " d=" << ray.d.x << "," << ray.d.y << "," << ray.d.z << " R=" << R
                             << " r=" << r;
  }
  if (exact_count) {
    EXPECT_EQ(n, int(brute.size()));
  }
  return {int(brute.size()), n};
}

TEST(IntersectTorus, RandomRaysMatchBruteForce) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1, 1), minor(0.03, 0.6);
  int total = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double R = 1.0, r = minor(rng), cy = u(rng);
    // Aim at a random point near the tube so most rays hit.
    const double phi = M_PI * u(rng);
    const dvec3 aim = dvec3(std::cos(phi) * R, cy, std::sin(phi) * R) + dvec3(u(rng), u(rng), u(rng)) * (1.5 * r);
    const dvec3 o = trial % 4 == 0 ? aim + random_unit(rng) * (0.5 * r)  // starts near/inside the tube
                                   : aim + random_unit(rng) * (1.5 + 2 * std::fabs(u(rng)));
    const Ray ray{o, glm::normalize(aim - o + dvec3(1e-9, 0, 0))};
    total += check_torus_ray(ray, R, r, cy, 20000, 1e-8, /*exact_count=*/false).brute;
  }
  EXPECT_GT(total, 400);
}

TEST(IntersectTorus, RaysThroughTheAxis) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-1, 1);
  const double R = 1.0, r = 0.25;
  for (int trial = 0; trial < 200; ++trial) {
    // Through a point on the axis, any direction (includes exactly horizontal ones,
    // where the quartic is biquadratic).
    const double yaxis = trial % 5 == 0 ? 0.0 : 0.3 * u(rng);
    dvec3 d = random_unit(rng);
    if (trial % 3 == 0) d = glm::normalize(dvec3(d.x, 0.0, d.z));
    const Ray ray{dvec3(0, yaxis, 0) - 3.0 * d, d};
    const TorusCheck c = check_torus_ray(ray, R, r, 0.0, 40000, 1e-8, false);
    if (std::fabs(yaxis) < 0.2 && std::fabs(d.y) < 0.05) {
      EXPECT_EQ(c.brute, 4);
    }
  }
  // Along the axis itself: the hole, no hits.
  double out[4];
  EXPECT_EQ(intersect_torus(Ray{dvec3(0, -3, 0), dvec3(0, 1, 0)}, R, r, 0.0, out), 0);
  // Horizontal through the centre: t = 3 +- (R + r), 3 +- (R - r).
  ASSERT_EQ(intersect_torus(Ray{dvec3(-3, 0.5, 0), dvec3(1, 0, 0)}, R, r, 0.5, out), 4);
  EXPECT_NEAR(out[0], 3 - R - r, 1e-12);
  EXPECT_NEAR(out[1], 3 - R + r, 1e-12);
  EXPECT_NEAR(out[2], 3 + R - r, 1e-12);
  EXPECT_NEAR(out[3], 3 + R + r, 1e-12);
  // Vertical through the tube centre: y = cy +- r.
  ASSERT_EQ(intersect_torus(Ray{dvec3(R, -2, 0), dvec3(0, 1, 0)}, R, r, 0.0, out), 2);
  EXPECT_NEAR(out[0], 2 - r, 1e-10);
  EXPECT_NEAR(out[1], 2 + r, 1e-10);
}

TEST(IntersectTorus, NearGrazingRays) {
  // Rays tangent to the surface at a random point, pushed a little into the tube: a
  // close pair of roots near the tangent point.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(-1, 1);
  const double R = 1.0;
  for (int trial = 0; trial < 120; ++trial) {
    const double r = 0.1 + 0.3 * std::fabs(u(rng));
    const double phi = M_PI * u(rng), theta = M_PI * u(rng);
    const dvec3 ring(std::cos(phi), 0, std::sin(phi));
    const dvec3 N = std::cos(theta) * ring + dvec3(0, std::sin(theta), 0);  // surface normal
    const dvec3 P = R * ring + r * N;
    const dvec3 T = glm::normalize(glm::cross(N, random_unit(rng)));
    const double delta = r * 1e-4 * (1 + std::fabs(u(rng)));
    const Ray ray{P - delta * N - 3.0 * T, T};
    const TorusCheck c = check_torus_ray(ray, R, r, 0.0, 400000, 1e-6, false);
    EXPECT_GE(c.brute, 2);
  }
  // Exactly tangent: whatever is reported must lie on the torus.
  double out[4];
  const Ray top{dvec3(-3, 0.25, 0.3), dvec3(1, 0, 0)};
  const int n = intersect_torus(top, 1.0, 0.25, 0.0, out);
  for (int i = 0; i < n; ++i) EXPECT_LT(torus_distance(top.at(out[i]), 1.0, 0.25), 1e-6);
}

TEST(IntersectTorus, HorizontalRaysThroughTheTube) {
  // A horizontal ray in the torus's mid-plane at distance c from the axis meets it
  // where the distance to the axis is R + r (and R - r when c < R - r):
  // (t - L)^2 + c^2 = (R +- r)^2. With d.y == 0 the depressed quartic is (nearly)
  // biquadratic; nearly horizontal rays are included.
  const double R = 1.0, r = 0.25, L = 3.0;
  int failures = 0;
  for (int i = 0; i < 200; ++i) {
    const double c = (R + r) * (i + 0.5) / 200.0;
    for (double tilt : {0.0, 1e-9, 1e-7, 1e-6}) {
      const Ray ray{dvec3(-L, -tilt * L, c), glm::normalize(dvec3(1, tilt, 0))};
      std::vector<double> expected;
      const double wo = std::sqrt((R + r) * (R + r) - c * c);
      expected.push_back(L - wo);
      if (c < R - r) {
        const double wi = std::sqrt((R - r) * (R - r) - c * c);
        expected.push_back(L - wi);
        expected.push_back(L + wi);
      }
      expected.push_back(L + wo);
      std::sort(expected.begin(), expected.end());
      double out[4];
      const int n = intersect_torus(ray, R, r, 0.0, out);
      bool ok = n == int(expected.size());
      for (int k = 0; ok && k < n; ++k) ok = std::fabs(out[k] - expected[size_t(k)]) < 1e-6;
      if (!ok && ++failures <= 8) {
        std::ostringstream got;
        for (int k = 0; k < n; ++k) got << " " << out[k];
        ADD_FAILURE() << "c=" << c << " tilt=" << tilt << ": expected " << expected.size()
                      << " roots from " << expected.front() << " to " << expected.back() << ", got " << n << ":"
                      << got.str();
      }
    }
  }
  EXPECT_EQ(failures, 0) << "of 800 rays";
}

TEST(IntersectTorus, RimScaleInMetres) {
  // The torus at the size of a glass rim, in world units.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  const double R = 0.0415, r = 0.0018, cy = 0.145;
  for (int trial = 0; trial < 200; ++trial) {
    const double phi = M_PI * u(rng);
    const dvec3 aim = dvec3(std::cos(phi) * R, cy, std::sin(phi) * R) + dvec3(u(rng), u(rng), u(rng)) * (1.5 * r);
    const dvec3 o = aim + random_unit(rng) * 0.3;
    const Ray ray{o, glm::normalize(aim - o)};
    check_torus_ray(ray, R, r, cy, 40000, 1e-7, false);
  }
}

// ------------------------------------------------------------------ vessel --

enum class Region { Air, Glass, Liquid, Floor };

struct TestScene {
  Vessel v;
  SceneGeometry g;
};

// The point classifier that defines the geometry: the glass body (walls and base
// between the outer and inner profiles) united with the rim torus; the liquid is the
// rest of the cavity below the plane.
Region classify(const SceneGeometry& scene, const dvec3& p) {
  const VesselGeometry& s = scene.vessels.front();
  const bool floor = scene.backdrop.present;  // the endless checker floor y = 0
  const Vessel& v = *s.vessel;
  const double r = std::hypot(p.x, p.z), y = p.y;
  const bool body = y >= 0 && y <= v.height && r <= v.outer_radius(y) && (y < v.base || r >= v.inner_radius(y));
  if (body || v.inside_torus(r, y)) return Region::Glass;
  if (y > v.base && y < v.height && r < v.inner_radius(y) && glm::dot(s.liquid.n, p) < s.liquid.offset)
    return Region::Liquid;
  if (floor && y < 0 && r > v.r_outer.front()) return Region::Floor;
  return Region::Air;
}

const char* region_name(Region r) {
  switch (r) {
    case Region::Air: return "air";
    case Region::Glass: return "glass";
    case Region::Liquid: return "liquid";
    case Region::Floor: return "floor";
  }
  return "?";
}

// Where the ray is inside the box around the glass (with a margin), as [t0, t1].
bool box_span(const Vessel& v, const Ray& ray, double tmin, double& t0, double& t1) {
  const double B = v.bound_radius + 0.005;
  const dvec3 lo(-B, -0.005, -B), hi(B, v.height + v.rim_minor + 0.005, B);
  t0 = tmin, t1 = 10.0;
  for (int a = 0; a < 3; ++a) {
    if (std::fabs(ray.d[a]) < 1e-15) {
      if (ray.o[a] < lo[a] || ray.o[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - ray.o[a]) / ray.d[a], tb = (hi[a] - ray.o[a]) / ray.d[a];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  return t0 < t1;
}

// Numerical gradient of a scalar field (unnormalised).
template <class F>
dvec3 gradient(F f, const dvec3& p, double h = 1e-7) {
  return dvec3(f(p + dvec3(h, 0, 0)) - f(p - dvec3(h, 0, 0)), f(p + dvec3(0, h, 0)) - f(p - dvec3(0, h, 0)),
               f(p + dvec3(0, 0, h)) - f(p - dvec3(0, 0, h))) /
         (2 * h);
}

// Checks one first_hit result against the classifier. Returns a description of the
// first problem, or "" when the hit is right.
std::string check_first_hit(const SceneGeometry& scene, const Ray& ray, double tmin, const Hit& hit) {
  const VesselGeometry& s = scene.vessels.front();
  const SceneGeometry& whole = scene;
  const Vessel& v = *s.vessel;
  std::ostringstream head, err;
  head.precision(17);
  err.precision(17);
  head << "ray o=(" << ray.o.x << "," << ray.o.y << "," << ray.o.z << ") d=(" << ray.d.x << "," << ray.d.y << ","
      << ray.d.z << "): ";
  // 1. No crossing before the hit: march the classifier from the start.
  double t0, t1;
  const double end = hit.valid() ? hit.t : 10.0;
  const Region start = classify(whole, ray.at(tmin + 1e-9));
  if (box_span(v, ray, tmin, t0, t1)) {
    t1 = std::min(t1, end - 1e-7);
    const double step = 1e-5;
    for (double t = std::max(t0, tmin + 1e-9); t < t1; t += step) {
      const Region here = classify(whole, ray.at(t));
      if (here != start) {
        err << "reported " << (hit.valid() ? material_name(hit.m) : "no hit") << " at t=" << hit.t
            << " but the ray goes from " << region_name(start) << " into " << region_name(here)
            << " earlier, at t=" << t;
        return head.str() + err.str();
      }
    }
  }
  if (!hit.valid()) {
    if (start != Region::Air) return head.str() + "no hit, but the ray starts in " + region_name(start);
    return "";
  }
  // 2. The hit point lies on the surface its material names; the normal is unit
  //    length and perpendicular to that surface.
  const dvec3 p = ray.at(hit.t);
  const double r = std::hypot(p.x, p.z);
  if (std::fabs(glm::length(hit.n) - 1) > 1e-12) return head.str() + "normal not unit length";
  auto parallel = [&](const dvec3& g) {
    return glm::length(glm::cross(glm::normalize(g), hit.n)) < 1e-5;
  };
  switch (hit.m) {
    case Material::GlassOuter:
    case Material::GlassInner: {
      const bool inner = hit.m == Material::GlassInner;
      auto F = [&](const dvec3& q) {
        return std::hypot(q.x, q.z) - (inner ? v.inner_radius(q.y) : v.outer_radius(q.y));
      };
      if (std::fabs(F(p)) > 1e-9) err << "wall hit off the wall by " << F(p);
      else if (p.y < (inner ? v.base : 0.0) - 1e-12 || p.y > v.height + 1e-12) err << "wall hit outside its height";
      else if (v.inside_torus(r, p.y)) err << "wall hit inside the rim torus";
      else {
        // The profile's smooth normal (Vessel::wall_slope: continuous across knots), which
        // stays within a degree of the frustum's own on this glass.
        const int k = std::clamp(int(std::floor(p.y / v.dy)), 0, Vessel::kSegments - 1);
        const double slope = v.wall_slope(inner, k, p.y / v.dy - k);
        const dvec3 smooth = (inner ? -1.0 : 1.0) * glm::normalize(dvec3(p.x / r, -slope, p.z / r));
        const bool off_knot = std::fabs(p.y / v.dy - std::round(p.y / v.dy)) > 1e-4;  // one-sided gradient there
        if (glm::length(hit.n - smooth) > 1e-9) err << "wall normal is not the profile's smooth normal";
        else if (off_knot && std::fabs(glm::dot(glm::normalize(gradient(F, p)), hit.n)) < std::cos(glm::radians(1.0)))
          err << "wall normal more than a degree from the wall's";
      }
      break;
    }
    case Material::Rim: {
      auto G = [&](const dvec3& q) { return std::hypot(std::hypot(q.x, q.z) - v.rim_major, q.y - v.height); };
      if (std::fabs(G(p) - v.rim_minor) > 1e-9) err << "rim hit off the torus by " << G(p) - v.rim_minor;
      else if (!parallel(gradient(G, p))) err << "rim normal not perpendicular to the torus";
      break;
    }
    case Material::GlassBottom:
      if (std::fabs(p.y) > 1e-12 || r > v.r_outer.front() + 1e-12) err << "bottom hit off the foot disk";
      else if (!parallel(dvec3(0, 1, 0))) err << "bottom normal not vertical";
      break;
    case Material::CavityFloor:
      if (std::fabs(p.y - v.base) > 1e-12 || r > v.inner_radius(v.base) + 1e-12)
        err << "cavity floor hit off the floor disk";
      else if (!parallel(dvec3(0, 1, 0))) err << "cavity floor normal not vertical";
      break;
    case Material::LiquidSurface:
      if (std::fabs(glm::dot(s.liquid.n, p) - s.liquid.offset) > 1e-12) err << "liquid hit off the plane";
      else if (r >= v.inner_radius(p.y)) err << "liquid hit outside the cavity";
      else if (glm::length(hit.n - s.liquid.n) > 1e-12) err << "liquid normal is not the plane normal";
      break;
    case Material::ClipGlass:
    case Material::ClipLiquid:
      if (std::fabs(glm::dot(dvec3(s.clip), p) - s.clip.w) > 1e-9) err << "cut-face hit off the clip plane";
      else if (!parallel(dvec3(s.clip))) err << "cut-face normal not the clip plane's";
      break;
    case Material::Floor:
      if (std::fabs(p.y) > 1e-12 || r <= v.r_outer.front()) err << "floor hit not on the floor";
      else if (glm::length(hit.n - dvec3(0, 1, 0)) > 1e-12) err << "floor normal not up";
      break;
    case Material::None: break;
    case Material::Droplet: break;  // not a vessel surface (tests/unit/droplets)
    case Material::Cloud: break;    // not a vessel surface (tests/unit/pointcloud)
  }
  if (!err.str().empty()) return head.str() + err.str() + " (" + material_name(hit.m) + ")";
  // 3. It is a crossing, and the normal points out of the glass (glass surfaces) or
  //    up (liquid, floor). Only for rays that cross at a clear angle.
  const double cosang = std::fabs(glm::dot(ray.d, hit.n));
  if (cosang > 0.02) {
    const double e = 1e-6;
    const Region before = classify(whole, ray.at(hit.t - e)), after = classify(whole, ray.at(hit.t + e));
    if (before == after)
      return head.str() + "no region change across the hit (" + material_name(hit.m) + ", " + region_name(before) + ")";
    const Region pos = classify(whole, p + 1e-7 * hit.n), neg = classify(whole, p - 1e-7 * hit.n);
    const bool glass_surface = hit.m != Material::LiquidSurface && hit.m != Material::Floor;
    if (glass_surface && !(neg == Region::Glass && pos != Region::Glass))
      return head.str() + "normal of " + material_name(hit.m) + " does not point out of the glass";
    if (hit.m == Material::LiquidSurface && !(neg == Region::Liquid && pos != Region::Liquid))
      return head.str() + "liquid normal does not point out of the liquid";
  }
  return "";
}

TestScene pint_scene(double liquid_offset, dvec3 liquid_n = {0, 1, 0}, bool floor = false) {
  TestScene s{test::preset_vessel("pint"), {}};
  VesselGeometry vg;
  vg.vessel = &s.v;
  vg.liquid.n = glm::normalize(liquid_n);
  vg.liquid.offset = liquid_offset;
  s.g.vessels = {vg};
  s.g.backdrop.present = floor;
  s.g.backdrop.kind = Backdrop::Checker;
  s.g.backdrop.plane = true;
  return s;
}

// Random rays of several kinds around and inside the pint glass.
std::vector<Ray> vessel_rays(const Vessel& v, std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Ray> rays;
  auto in_cylinder = [&](double rmax, double ylo, double yhi) {
    const double phi = 2 * M_PI * u(rng), rr = rmax * std::sqrt(u(rng));
    return dvec3(rr * std::cos(phi), ylo + (yhi - ylo) * u(rng), rr * std::sin(phi));
  };
  for (int i = 0; i < n; ++i) {
    const int kind = i % 6;
    dvec3 o, d;
    if (kind <= 1) {  // from far outside at the glass
      o = dvec3(0, 0.07, 0) + random_unit(rng) * 0.35;
      d = glm::normalize(in_cylinder(v.bound_radius, -0.002, v.height + 0.004) - o);
    } else if (kind == 2) {  // from inside the cavity
      const double y = v.base + (v.height - v.base) * (0.02 + 0.96 * u(rng));
      o = in_cylinder(0.95 * v.inner_radius(y), y, y);
      d = random_unit(rng);
    } else if (kind == 3) {  // from inside the glass (wall or base)
      if (u(rng) < 0.5) {
        const double y = v.height * u(rng), phi = 2 * M_PI * u(rng);
        const double rr = v.inner_radius(y) + (v.outer_radius(y) - v.inner_radius(y)) * (0.1 + 0.8 * u(rng));
        o = dvec3(rr * std::cos(phi), y, rr * std::sin(phi));
        if (y < v.base) o = in_cylinder(0.95 * v.outer_radius(y), y, y);
      } else {
        o = in_cylinder(0.9 * v.r_outer.front(), 0.05 * v.base, 0.95 * v.base);
      }
      d = random_unit(rng);
    } else if (kind == 4) {  // through the axis
      const double y = v.height * (1.2 * u(rng) - 0.05);
      d = random_unit(rng);
      if (u(rng) < 0.5) d = glm::normalize(dvec3(d.x, 0.02 * d.y, d.z));
      o = dvec3(0, y, 0) - 0.3 * d;
    } else {  // near-grazing: horizontal, tangent to the outer wall or over the rim
      const double phi = 2 * M_PI * u(rng);
      const dvec3 dir(std::cos(phi), 0, std::sin(phi)), side(-dir.z, 0, dir.x);
      double y, off;
      if (u(rng) < 0.5) {
        y = v.height * (0.05 + 0.9 * u(rng));
        off = v.outer_radius(y) + 1e-6 * (2 * u(rng) - 1);
      } else {
        y = v.height + v.rim_minor * (1 - 1e-4 * u(rng));
        off = v.rim_major * u(rng);
      }
      o = side * off + dvec3(0, y, 0) - 0.3 * dir;
      d = dir;
    }
    rays.push_back({o, d});
  }
  return rays;
}

TEST(VesselHits, FirstHitIsOnTheSurfaceAndNothingIsSkipped) {
  std::mt19937 rng(21);
  const TestScene s = pint_scene(-1.0);  // empty glass, no floor
  int counts[8] = {};
  int failures = 0;
  for (const Ray& ray : vessel_rays(s.v, rng, 1800)) {
    const Hit hit = first_hit(s.g, ray);
    ++counts[int(hit.m)];
    const std::string problem = check_first_hit(s.g, ray, 1e-7, hit);
    if (!problem.empty() && ++failures <= 10) ADD_FAILURE() << problem;
  }
  EXPECT_EQ(failures, 0);
  // Every glass surface was exercised.
  for (Material m : {Material::GlassOuter, Material::GlassInner, Material::Rim, Material::GlassBottom,
                     Material::CavityFloor})
    EXPECT_GT(counts[int(m)], 10) << material_name(m);
}

TEST(VesselHits, HorizontalRaysAcrossTheRim) {
  // Exactly horizontal rays at the height of the bead (d.y == 0 makes the torus
  // quartic biquadratic after depression), at every offset from the axis.
  const TestScene s = pint_scene(-1.0);
  const Vessel& v = s.v;
  int failures = 0, rim_hits = 0;
  for (double fy : {-0.9, -0.5, 0.0, 0.3, 0.6, 0.9, 0.999}) {
    for (int i = 0; i <= 120; ++i) {
      const double c = (v.rim_major + v.rim_minor) * i / 120.0;
      for (double ang : {0.0, 0.7, 2.1, 4.0}) {
        const dvec3 d(std::cos(ang), 0, std::sin(ang)), side(-d.z, 0, d.x);
        for (double back : {0.3, 0.0}) {  // from outside, and from beside the axis
          const Ray ray{side * c + dvec3(0, v.height + fy * v.rim_minor, 0) - back * d, d};
          const Hit hit = first_hit(s.g, ray);
          rim_hits += hit.m == Material::Rim;
          const std::string problem = check_first_hit(s.g, ray, 1e-7, hit);
          if (!problem.empty() && ++failures <= 10) ADD_FAILURE() << problem;
        }
      }
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(rim_hits, 1000);
}

TEST(VesselHits, FirstHitWithLiquidAndFloor) {
  std::mt19937 rng(22);
  const Vessel probe = test::preset_vessel("pint");
  const double level = probe.fill_height(0.6);
  for (dvec3 n : {dvec3(0, 1, 0), dvec3(0.15, 1, -0.1)}) {
    const TestScene s = pint_scene(level * glm::normalize(n).y, n, /*floor=*/true);
    int counts[8] = {};
    int failures = 0;
    for (const Ray& ray : vessel_rays(s.v, rng, 1200)) {
      if (ray.o.y < 0) continue;  // would start inside the floor
      const Hit hit = first_hit(s.g, ray);
      ++counts[int(hit.m)];
      const std::string problem = check_first_hit(s.g, ray, 1e-7, hit);
      if (!problem.empty() && ++failures <= 10) ADD_FAILURE() << problem;
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(counts[int(Material::LiquidSurface)], 10);
    EXPECT_GT(counts[int(Material::Floor)], 10);
  }
}

TEST(VesselHits, HitWallIsOnTheWallAndFirst) {
  std::mt19937 rng(23);
  const Vessel v = test::preset_vessel("pint");
  for (bool inner : {false, true}) {
    const auto& radius = [&](double y) { return inner ? v.inner_radius(y) : v.outer_radius(y); };
    const double ylo = inner ? v.base : 0.0;
    int hits = 0;
    for (const Ray& ray : vessel_rays(v, rng, 900)) {
      const Hit h = hit_wall(v, inner, ray, 1e-7);
      // Brute force: the first sign change of hypot(x, z) - R(y) inside the wall's
      // height range and outside the rim torus.
      double t0, t1, first = 1e300;
      if (box_span(v, ray, 1e-7, t0, t1)) {
        auto F = [&](double t) {
          const dvec3 p = ray.at(t);
          return std::hypot(p.x, p.z) - radius(p.y);
        };
        auto valid = [&](double t) {
          const dvec3 p = ray.at(t);
          return p.y >= ylo && p.y <= v.height && !v.inside_torus(std::hypot(p.x, p.z), p.y);
        };
        const double step = 1e-5;
        for (double t = t0; t + step < t1; t += step) {
          if (valid(t) && valid(t + step) && (F(t) < 0) != (F(t + step) < 0)) {
            first = t;
            break;
          }
        }
      }
      if (h.valid()) {
        ++hits;
        EXPECT_EQ(h.m, inner ? Material::GlassInner : Material::GlassOuter);
        const dvec3 p = ray.at(h.t);
        EXPECT_NEAR(std::hypot(p.x, p.z), radius(p.y), 1e-9);
        EXPECT_GE(p.y, ylo - 1e-12);
        EXPECT_LE(p.y, v.height + 1e-12);
        EXPECT_LE(h.t, first + 1e-5) << "an earlier wall crossing exists at t=" << first;
      } else {
        EXPECT_EQ(first, 1e300) << "missed a wall crossing at t=" << first << " (inner=" << inner << ")";
      }
    }
    EXPECT_GT(hits, 300);
  }
}

// hit_wall passes over the frustums the ray's line cannot cross (well inside at both
// knots, or its closest approach beyond the larger knot radius); the hit must be exactly
// the nearest root every frustum gives (intersect_cone on each, the same checks), for
// paths through the drink up and down, steep and shallow, and for rays from around the
// glass aimed at it and past it, in a straight pint, a tulip's bowl and a wine glass's.
TEST(VesselHits, HitWallIsTheNearestFrustumRoot) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const char* glass : {"pint", "tulip", "wine"}) {
    const Vessel v = test::preset_vessel(glass);
    for (bool inner : {true, false}) {
      const auto& knots = inner ? v.r_inner : v.r_outer;
      const double ylo = inner ? v.base : 0.0;
      int hits = 0;
      for (int trial = 0; trial < 4000; ++trial) {
        Ray ray;
        if (trial % 2) {  // from inside the cavity
          const double y = v.base + (v.height - v.base) * (0.02 + 0.96 * u(rng));
          const double r = v.inner_radius(y) * std::sqrt(u(rng)) * 0.98, phi = 2 * M_PI * u(rng);
          const double dy = (trial % 4 == 1 ? -1.0 : 1.0) * (trial % 3 == 0 ? 0.05 + 0.2 * u(rng) : 0.3 + 0.7 * u(rng));
          const double a = 2 * M_PI * u(rng), h = std::sqrt(1 - dy * dy);
          ray = {dvec3(r * std::cos(phi), y, r * std::sin(phi)), dvec3(h * std::cos(a), dy, h * std::sin(a))};
        } else {  // from 20 cm around, at a point in or near the glass's bounding cylinder
          const double phi = 2 * M_PI * u(rng), r = 1.3 * v.bound_radius * std::sqrt(u(rng));
          const dvec3 aim(r * std::cos(phi), v.height * (1.1 * u(rng) - 0.05), r * std::sin(phi));
          const dvec3 o = aim + random_unit(rng) * 0.2;
          ray = {o, glm::normalize(aim - o)};
        }
        double nearest = std::numeric_limits<double>::infinity();
        for (int k = 0; k < Vessel::kSegments; ++k) {
          double ts[2];
          const int n = intersect_cone(ray, knots[size_t(k)], knots[size_t(k) + 1], k * v.dy, (k + 1) * v.dy, 1e-7, ts);
          for (int i = 0; i < n; ++i) {
            const dvec3 p = ray.at(ts[i]);
            if (p.y < ylo || p.y > v.height || v.inside_torus(std::hypot(p.x, p.z), p.y)) continue;
            nearest = std::min(nearest, ts[i]);
          }
        }
        const Hit hit = hit_wall(v, inner, ray, 1e-7);
        if (std::isinf(nearest)) {
          EXPECT_FALSE(hit.valid()) << glass << " inner=" << inner << " trial " << trial;
        } else {
          ++hits;
          ASSERT_TRUE(hit.valid()) << glass << " inner=" << inner << " trial " << trial;
          EXPECT_EQ(hit.t, nearest) << glass << " inner=" << inner << " trial " << trial;
        }
      }
      EXPECT_GT(hits, 1500) << glass << " inner=" << inner;
    }
  }
}

TEST(VesselHits, HitRimIsOnTheTorusAndFirst) {
  std::mt19937 rng(24);
  const Vessel v = test::preset_vessel("pint");
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 600; ++i) {
    const double phi = M_PI * u(rng);
    const dvec3 aim = dvec3(std::cos(phi) * v.rim_major, v.height, std::sin(phi) * v.rim_major) +
                      dvec3(u(rng), u(rng), u(rng)) * (1.5 * v.rim_minor);
    const dvec3 o = aim + random_unit(rng) * (i % 3 == 0 ? 0.003 : 0.3);
    const Ray ray{o, glm::normalize(aim - o)};
    const Hit h = hit_rim(v, ray, 1e-7);
    // Brute force: the first entry into/exit from the torus that is not inside the
    // glass body below the rim plane.
    auto visible = [&](const dvec3& p) {
      const double r = std::hypot(p.x, p.z);
      const bool body = p.y <= v.height && p.y >= 0 && r <= v.outer_radius(p.y) &&
                        (p.y < v.base || r >= v.inner_radius(p.y));
      return !(p.y < v.height && body);
    };
    auto G = [&](double t) {
      const dvec3 p = ray.at(t);
      return std::hypot(std::hypot(p.x, p.z) - v.rim_major, p.y - v.height) - v.rim_minor;
    };
    double first = 1e300;
    const double step = 2e-6, tend = glm::length(aim - o) + 0.02;
    for (double t = 1e-7; t < tend; t += step)
      if ((G(t) < 0) != (G(t + step) < 0) && visible(ray.at(t)) && visible(ray.at(t + step))) {
        first = t;
        break;
      }
    if (h.valid()) {
      ++hits;
      EXPECT_EQ(h.m, Material::Rim);
      EXPECT_NEAR(G(h.t), 0.0, 1e-9);
      EXPECT_LE(h.t, first + step + 1e-9) << "an earlier rim crossing exists";
    } else {
      EXPECT_EQ(first, 1e300) << "missed a rim crossing";
    }
  }
  EXPECT_GT(hits, 200);
}

TEST(VesselHits, MaterialsOfSimpleRays) {
  const TestScene empty = pint_scene(-1.0);
  const Vessel& v = empty.v;
  // Down the axis into an empty glass: the cavity floor, normal up.
  Hit h = first_hit(empty.g, Ray{dvec3(0, 0.5, 0), dvec3(0, -1, 0)});
  EXPECT_EQ(h.m, Material::CavityFloor);
  EXPECT_NEAR(h.t, 0.5 - v.base, 1e-12);
  EXPECT_NEAR(h.n.y, 1.0, 1e-12);
  // With liquid: the liquid surface first.
  const double level = v.fill_height(0.5);
  const TestScene full = pint_scene(level);
  h = first_hit(full.g, Ray{dvec3(0, 0.5, 0), dvec3(0, -1, 0)});
  EXPECT_EQ(h.m, Material::LiquidSurface);
  EXPECT_NEAR(h.t, 0.5 - level, 1e-12);
  EXPECT_NEAR(h.n.y, 1.0, 1e-12);
  // Up the axis from below the foot (no floor): the bottom, normal down.
  h = first_hit(empty.g, Ray{dvec3(0, -0.05, 0), dvec3(0, 1, 0)});
  EXPECT_EQ(h.m, Material::GlassBottom);
  EXPECT_NEAR(h.t, 0.05, 1e-12);
  EXPECT_NEAR(h.n.y, -1.0, 1e-12);
  // Horizontal towards the axis: the outer wall at r = outer_radius(y), normal outward.
  const double y = 0.07;
  h = first_hit(empty.g, Ray{dvec3(-0.3, y, 0), dvec3(1, 0, 0)});
  EXPECT_EQ(h.m, Material::GlassOuter);
  EXPECT_NEAR(h.t, 0.3 - v.outer_radius(y), 1e-12);
  EXPECT_LT(h.n.x, 0);
  // From inside the wall: the inner wall, normal pointing into the cavity.
  const double mid = 0.5 * (v.outer_radius(y) + v.inner_radius(y));
  h = first_hit(empty.g, Ray{dvec3(-mid, y, 0), dvec3(1, 0, 0)});
  EXPECT_EQ(h.m, Material::GlassInner);
  EXPECT_NEAR(h.t, mid - v.inner_radius(y), 1e-12);
  EXPECT_GT(h.n.x, 0);
  // Straight down onto the bead: the rim, at its top, normal up.
  h = first_hit(empty.g, Ray{dvec3(v.rim_major, 0.5, 0), dvec3(0, -1, 0)});
  EXPECT_EQ(h.m, Material::Rim);
  EXPECT_NEAR(h.t, 0.5 - v.height - v.rim_minor, 1e-10);
  EXPECT_NEAR(h.n.y, 1.0, 1e-9);
  // The floor, beside the glass.
  const TestScene floor = pint_scene(-1.0, {0, 1, 0}, true);
  h = first_hit(floor.g, Ray{dvec3(0.2, 0.3, 0), dvec3(0, -1, 0)});
  EXPECT_EQ(h.m, Material::Floor);
  EXPECT_NEAR(h.t, 0.3, 1e-12);
  EXPECT_NEAR(h.n.y, 1.0, 1e-12);
  // Nothing: up into the sky.
  h = first_hit(floor.g, Ray{dvec3(0.2, 0.3, 0), dvec3(0, 1, 0)});
  EXPECT_EQ(h.m, Material::None);
  EXPECT_FALSE(h.valid());
}

TEST(VesselHits, WallNormalIsContinuousAcrossSegmentKnots) {
  // Rays just below and just above each knot of curved bowls meet the wall with the same
  // normal (no contour bands); the segments' own normals differ there.
  for (const char* glass : {"wine", "tulip"}) {
    const Vessel v = test::preset_vessel(glass);
    double worst = 0, worst_segment = 0;
    for (int k = Vessel::kSegments / 2; k < Vessel::kSegments - 4; ++k) {
      const double y = k * v.dy;
      const auto& r = v.r_outer;
      const double s0 = (r[size_t(k)] - r[size_t(k) - 1]) / v.dy, s1 = (r[size_t(k) + 1] - r[size_t(k)]) / v.dy;
      const dvec3 n0 = glm::normalize(dvec3(1, -s0, 0)), n1 = glm::normalize(dvec3(1, -s1, 0));
      worst_segment = std::max(worst_segment, glm::length(n0 - n1));
      dvec3 n[2];
      for (int side = 0; side < 2; ++side) {
        const Ray ray{dvec3(0.3, y + (side ? 1e-9 : -1e-9), 0.001), dvec3(-1, 0, 0)};
        const Hit h = hit_wall(v, false, ray, 1e-7);
        ASSERT_EQ(h.m, Material::GlassOuter) << glass << " knot " << k;
        n[side] = h.n;
      }
      worst = std::max(worst, glm::length(n[0] - n[1]));
    }
    EXPECT_LT(worst, 1e-6) << glass << ": the normal jumps at a knot";
    EXPECT_GT(worst_segment, 1e-3) << glass << ": the bowl should be curved";
  }
}

TEST(VesselHits, MaterialIdsAreTheDocumentedNumbers) {
  // The shader writes the same numbers in its material debug output.
  EXPECT_EQ(int(Material::None), 0);
  EXPECT_EQ(int(Material::Floor), 1);
  EXPECT_EQ(int(Material::GlassOuter), 2);
  EXPECT_EQ(int(Material::GlassInner), 3);
  EXPECT_EQ(int(Material::Rim), 4);
  EXPECT_EQ(int(Material::GlassBottom), 5);
  EXPECT_EQ(int(Material::CavityFloor), 6);
  EXPECT_EQ(int(Material::LiquidSurface), 7);
  EXPECT_STREQ(material_name(Material::GlassOuter), "glass-outer");
  EXPECT_STREQ(material_name(Material::LiquidSurface), "liquid-surface");
}

}  // namespace
}  // namespace draught
