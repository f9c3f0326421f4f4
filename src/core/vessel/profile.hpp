// A designer's profile curve: r(y) through control points, smooth and without
// overshoot (monotone cubic Hermite, Fritsch-Carlson), so a glass never bulges
// past its control points.
#pragma once

#include "core/params/params.hpp"

namespace draught {

class ProfileCurve {
 public:
  explicit ProfileCurve(const Curve& points);  // points validated by the param table
  double radius(double y) const;               // clamps y to [0, height()]
  double height() const { return y_.back(); }

 private:
  std::vector<double> y_, r_, m_;  // knots and tangents dr/dy
};

}  // namespace draught
