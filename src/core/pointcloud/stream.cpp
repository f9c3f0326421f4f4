#include "core/pointcloud/stream.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

void check(double v, double lo, double hi, const char* field) {
  if (!(v >= lo && v <= hi))
    throw std::invalid_argument(std::string("stream: ") + field + " is " + std::to_string(v) +
                                ", expected " + std::to_string(lo) + " to " + std::to_string(hi));
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void PourStream::Sum::add(double x) {
  const double t = s + x;
  c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
  s = t;
}

PourStream::PourStream(const StreamParams& p, glm::dvec3 origin, glm::dvec3 velocity,
                       double target_height)
    : p_(p) {
  check(p.gravity, 0.1, 30, "gravity");
  check(p.wobble, 0, 0.5, "wobble");
  check(p.wobble_hz, 0, 50, "wobble_hz");
  check(p.overlap, 0.1, 1, "overlap");
  check(p.min_speed, 0.01, 2, "min_speed");
  check(p.max_radius, 1e-4, 0.1, "max_radius");
  set_origin(origin, velocity);
  set_target_height(target_height);
}

void PourStream::set_flow(double t, double q) {
  check(q, 0, 1e3, "flow");
  if (!std::isfinite(t)) throw std::invalid_argument("stream: flow time is not finite");
  t = std::max(t, time());
  auto it = std::lower_bound(schedule_.begin(), schedule_.end(), t,
                             [](const auto& e, double v) { return e.first < v; });
  if (it != schedule_.end() && it->first == t)
    it->second = q;
  else
    schedule_.insert(it, {t, q});
}

double PourStream::flow(double t) const {
  double q = 0;
  for (const auto& [from, value] : schedule_) {
    if (from > t) break;
    q = value;
  }
  return q;
}

double PourStream::flow_integral(double a, double b) const {
  // The schedule is piecewise constant: sum each piece's overlap with [a, b].
  double sum = 0;
  for (std::size_t i = 0; i < schedule_.size(); ++i) {
    const double lo = std::max(a, schedule_[i].first);
    const double hi = std::min(b, i + 1 < schedule_.size() ? schedule_[i + 1].first : b);
    if (hi > lo) sum += schedule_[i].second * (hi - lo);
  }
  return sum;
}

void PourStream::set_origin(glm::dvec3 position, glm::dvec3 velocity) {
  if (!finite(position) || !finite(velocity))
    throw std::invalid_argument("stream: origin position or velocity is not finite");
  origin_ = position;
  velocity_ = velocity;
}

void PourStream::set_target_height(double y) {
  if (!std::isfinite(y)) throw std::invalid_argument("stream: target height is not finite");
  target_ = y;
}

glm::dvec3 PourStream::at(const Parcel& q, double t) const {
  const double a = t - q.born;
  return q.origin + q.launch * a + glm::dvec3(0, -0.5 * p_.gravity * a * a, 0);
}

glm::dvec3 PourStream::velocity_of(const Parcel& q, double t) const {
  return q.launch + glm::dvec3(0, -p_.gravity * (t - q.born), 0);
}

void PourStream::step() {
  const double t0 = time(), t1 = t0 + kStep;
  const double volume = flow_integral(t0, t1);
  if (volume > 0) {
    // Spacing where the stream is fastest (at the target) within `overlap` of its blob
    // radius there: v dt <= overlap sqrt(Q / (pi v)).
    double q_max = flow(t0);
    for (const auto& [from, value] : schedule_)
      if (from > t0 && from < t1) q_max = std::max(q_max, value);
    const double drop = std::max(0.0, origin_.y - target_);
    const double v_max = std::max(std::sqrt(glm::dot(velocity_, velocity_) + 2 * p_.gravity * drop), p_.min_speed);
    const double r_min = std::sqrt(q_max / (M_PI * v_max));
    const double interval = p_.overlap * r_min / v_max;
    const int n = std::clamp(static_cast<int>(std::ceil(kStep / interval)), 1, kMaxPerStep);
    // The wobble's two directions, across the launch (or across the fall).
    const double speed = glm::length(velocity_);
    const glm::dvec3 dir = speed > 1e-9 ? velocity_ / speed : glm::dvec3(0, -1, 0);
    glm::dvec3 e1 = glm::cross(dir, glm::dvec3(0, 1, 0));
    e1 = glm::length(e1) > 1e-6 ? glm::normalize(e1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 e2 = glm::normalize(glm::cross(dir, e1));
    for (int k = 0; k < n; ++k) {
      const double a = t0 + kStep * k / n, b = k + 1 == n ? t1 : t0 + kStep * (k + 1) / n;
      const double v = flow_integral(a, b);
      if (!(v > 0)) continue;
      const double w = 2 * M_PI * p_.wobble_hz * b;
      const glm::dvec3 wobble =
          p_.wobble * (std::sin(w + 0.3) * e1 + std::sin(1.618 * w + 1.1) * e2) * std::sqrt(0.5);
      Parcel parcel{b, origin_, velocity_ + wobble, v, v / (b - a)};
      emitted_.add(v);
      parcels_.push_back(parcel);
    }
  }
  ++steps_;
  // Absorb what has reached the catching plane (keeping the rest in emission order).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < parcels_.size(); ++i) {
    if (at(parcels_[i], time()).y <= target_)
      arrived_.add(parcels_[i].volume);
    else
      parcels_[kept++] = parcels_[i];
  }
  parcels_.resize(kept);
}

void PourStream::advance(double seconds) {
  if (!(seconds > 0)) return;
  pending_ += seconds;
  while (pending_ >= kStep * (1 - 1e-9)) {
    step();
    pending_ -= kStep;
  }
}

double PourStream::in_flight_volume() const {
  Sum s;
  for (const Parcel& q : parcels_) s.add(q.volume);
  return s.value();
}

PointCloud PourStream::cloud() const {
  PointCloud c;
  c.default_radius = static_cast<float>(p_.max_radius);
  const double t = time();
  for (const Parcel& q : parcels_) {
    const glm::dvec3 v = velocity_of(q, t);
    const double speed = std::max(glm::length(v), p_.min_speed);
    c.position.emplace_back(at(q, t));
    c.radius.push_back(static_cast<float>(std::min(std::sqrt(q.flow / (M_PI * speed)), p_.max_radius)));
    c.velocity.emplace_back(v);
  }
  return c;
}

}  // namespace draught
