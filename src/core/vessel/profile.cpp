#include "core/vessel/profile.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

ProfileCurve::ProfileCurve(const Curve& points) {
  for (auto& p : points) {
    y_.push_back(p.y);
    r_.push_back(p.x);
  }
  const size_t n = y_.size();
  std::vector<double> slope(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) slope[i] = (r_[i + 1] - r_[i]) / (y_[i + 1] - y_[i]);
  m_.assign(n, 0.0);
  m_[0] = slope[0];
  m_[n - 1] = slope[n - 2];
  for (size_t i = 1; i + 1 < n; ++i)
    m_[i] = slope[i - 1] * slope[i] <= 0 ? 0.0 : (slope[i - 1] + slope[i]) / 2;
  // Fritsch-Carlson limiter: keeps each piece monotone between its control points.
  for (size_t i = 0; i + 1 < n; ++i) {
    if (slope[i] == 0) {
      m_[i] = m_[i + 1] = 0;
      continue;
    }
    double a = m_[i] / slope[i], b = m_[i + 1] / slope[i];
    double s = a * a + b * b;
    if (s > 9) {
      double tau = 3 / std::sqrt(s);
      m_[i] = tau * a * slope[i];
      m_[i + 1] = tau * b * slope[i];
    }
  }
}

double ProfileCurve::radius(double y) const {
  y = std::clamp(y, y_.front(), y_.back());
  size_t i = size_t(std::upper_bound(y_.begin(), y_.end(), y) - y_.begin());
  i = std::clamp<size_t>(i, 1, y_.size() - 1) - 1;
  const double h = y_[i + 1] - y_[i], t = (y - y_[i]) / h;
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * r_[i] + (t3 - 2 * t2 + t) * h * m_[i] + (-2 * t3 + 3 * t2) * r_[i + 1] +
         (t3 - t2) * h * m_[i + 1];
}

}  // namespace draught
