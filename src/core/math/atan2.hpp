// atan2 in a few multiplies, for the light sums that take millions of them (a rect light's
// irradiance is four of them a point: the backdrop's light map sums about three million
// such points a frame's set-up; glibc's atan2 was half of that time). Within 1e-15 rad of
// std::atan2 everywhere (tests/unit/environment/test_lights.cpp).
#pragma once

#include <cmath>
#include <numbers>

namespace draught {

inline double atan2_fast(double y, double x) {
  constexpr double kPi = std::numbers::pi;
  const double ay = std::fabs(y), ax = std::fabs(x);
  if (ay == 0 && ax == 0) return std::atan2(y, x);  // the signed zeros' conventions
  if (!std::isfinite(ay) || !std::isfinite(ax)) return std::atan2(y, x);
  // The angle of (ax, ay) in [0, pi / 4] from r = min / max in [0, 1], brought within
  // tan(pi / 16) of a multiple of pi / 8: atan(r) = c + atan((r - tan c) / (1 + r tan c)).
  const bool steep = ay > ax;
  const double r = steep ? ax / ay : ay / ax;
  double c = 0, t = r;
  constexpr double kTan8 = 0.41421356237309503;  // tan(pi / 8)
  if (r > 0.66817863791929888) {                 // tan(3 pi / 16)
    c = kPi / 4;
    t = (r - 1) / (r + 1);
  } else if (r > 0.19891236737965800) {  // tan(pi / 16)
    c = kPi / 8;
    t = (r - kTan8) / (1 + r * kTan8);
  }
  // atan(t) = t - t^3 / 3 + t^5 / 5 - ...: with |t| <= tan(pi / 16) the first term left
  // out, t^23 / 23, is under 4e-18 (an alternating series errs by less than it), below
  // double's rounding: a light's sum of edges can cancel to a small part of its terms, and
  // the path tracer picks lights by these sums.
  const double s = t * t;
  double p = 1.0 / 21;
  p = -1.0 / 19 + s * p;
  p = 1.0 / 17 + s * p;
  p = -1.0 / 15 + s * p;
  p = 1.0 / 13 + s * p;
  p = -1.0 / 11 + s * p;
  p = 1.0 / 9 + s * p;
  p = -1.0 / 7 + s * p;
  p = 1.0 / 5 + s * p;
  p = -1.0 / 3 + s * p;
  p = 1 + s * p;
  double a = c + t * p;
  if (steep) a = kPi / 2 - a;
  if (x < 0) a = kPi - a;
  return std::copysign(a, y);
}

}  // namespace draught
