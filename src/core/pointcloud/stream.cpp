#include "core/pointcloud/stream.hpp"

#include "core/pointcloud/field.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

void check_stream_field(double v, double lo, double hi, const char* field) {
  if (!(v >= lo && v <= hi))
    throw std::invalid_argument(std::string("stream: ") + field + " is " + std::to_string(v) +
                                ", expected " + std::to_string(lo) + " to " + std::to_string(hi));
}

}  // namespace

void PourStream::Sum::add(double x) {
  const double t = s + x;
  c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
  s = t;
}

PourStream::PourStream(const StreamParams& p, glm::dvec3 origin, glm::dvec3 velocity,
                       double target_height)
    : p_(p) {
  check_stream_field(p.gravity, 0.1, 30, "gravity");
  check_stream_field(p.wobble, 0, 0.5, "wobble");
  check_stream_field(p.wobble_hz, 0, 50, "wobble_hz");
  check_stream_field(p.overlap, 0.1, 1, "overlap");
  check_stream_field(p.min_speed, 0.01, 2, "min_speed");
  check_stream_field(p.max_radius, 1e-4, 0.1, "max_radius");
  check_stream_field(p.capillary, 0, 1e-3, "capillary");
  set_origin(origin, velocity);
  set_target_height(target_height);
}

void PourStream::set_flow(double t, double q) {
  check_stream_field(q, 0, 1e3, "flow");
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
  if (!all_finite(position) || !all_finite(velocity))
    throw std::invalid_argument("stream: origin position or velocity is not finite");
  origin_ = position;
  velocity_ = velocity;
  lip_.reset();
}

void PourStream::set_target_height(double y) {
  if (!std::isfinite(y)) throw std::invalid_argument("stream: target height is not finite");
  target_ = y;
}

namespace {
// How much of a sheet's width is left at a time after launch (1 -> 0 at close).
double open_part(double a, double close) { return close > 0 ? std::max(0.0, 1.0 - a / close) : 0.0; }

// The lone-blob radius at which a line of blobs `spacing` apart draws a tube of radius r
// where F = level. The field of supports R in a line of density 1 / spacing is, at a
// distance rho from it, (32 / 35) (R / spacing) (1 - rho^2 / R^2)^(7/2) (the kernel
// integrated along the line): a slow stream's close parcels would otherwise draw it up to
// the supports' width, 2.2 times too wide. A line too sparse to reach r keeps r (beads).
double line_blob_radius(double r, double spacing, double level) {
  const double scale = cloud_support_scale(kCloudThreshold), density = 32.0 / 35.0 / spacing;
  auto drawn = [&](double R) {  // the tube's radius for supports R
    const double x = level / (density * R);
    return x >= 1 ? 0.0 : R * std::sqrt(1 - std::pow(x, 2.0 / 7.0));
  };
  double lo = r, hi = scale * r;
  if (!(spacing > 0) || drawn(hi) <= r) return r;
  // 24 halvings of [r, 2.2 r]: 1e-7 of r, below the float the cloud keeps (cloud() runs
  // every frame, a bisection per blob).
  for (int i = 0; i < 24; ++i) (drawn(0.5 * (lo + hi)) < r ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi) / scale;
}
}  // namespace

glm::dvec3 PourStream::at(const Parcel& q, double t) const {
  const double a = t - q.born;
  return q.origin + q.launch * a + glm::dvec3(0, -0.5 * p_.gravity * a * a, 0);
}

glm::dvec3 PourStream::velocity_of(const Parcel& q, double t) const {
  return q.launch + glm::dvec3(0, -p_.gravity * (t - q.born), 0);
}

void PourStream::set_lip(const StreamLip& lip) {
  if (!all_finite(lip.centre) || !all_finite(lip.up) || !all_finite(lip.outward) || !std::isfinite(lip.radius))
    throw std::invalid_argument("stream: lip is not finite");
  if (!(lip.radius > 0) || std::abs(glm::length(lip.up) - 1) > 1e-6 || std::abs(glm::length(lip.outward) - 1) > 1e-6 ||
      std::abs(glm::dot(lip.up, lip.outward)) > 1e-6)
    throw std::invalid_argument("stream: lip needs a radius > 0 and unit up and outward directions at right angles");
  lip_ = lip;
}

PourStream::Sheet PourStream::sheet(double q) const {
  if (!lip_ || !(q > 0)) return {};
  // The rim rises k s^2 along it from its lowest point; a rim held level spills around half
  // of it at most.
  const double r = lip_->radius, sin_tilt = std::sqrt(std::max(0.0, 1 - lip_->up.y * lip_->up.y));
  const double k = sin_tilt / (2 * r), widest = 0.5 * M_PI * r, shape = std::sqrt(p_.gravity) * 3 * M_PI / 8;
  Sheet s;
  if (k > 0) {
    s.depth = std::sqrt(q * std::sqrt(k) / shape);
    s.half_width = std::sqrt(s.depth / k);
  }
  if (!(k > 0) || s.half_width > widest) {
    s.half_width = widest;
    s.depth = std::pow(q / (shape * widest), 2.0 / 3.0);
  }
  return s;
}

double PourStream::fastest_speed(double launch_speed, double from_height) const {
  const double drop = std::max(0.0, from_height - target_);
  return std::max(std::sqrt(launch_speed * launch_speed + 2 * p_.gravity * drop), p_.min_speed);
}

void PourStream::emit_from_spout(double t0, double t1, double q_max) {
  // Spacing where the stream is fastest (at the target) within `overlap` of its blob
  // radius there: v dt <= overlap sqrt(Q / (pi v)).
  const double v_max = fastest_speed(glm::length(velocity_), origin_.y);
  const double r_min = std::sqrt(q_max / (M_PI * v_max));
  const double interval = p_.overlap * r_min / v_max;
  const int n = std::clamp(static_cast<int>(std::ceil(kStep / interval)), 1, kMaxPerStep);
  // The wobble's two directions, across the launch (or across the fall).
  const double speed = glm::length(velocity_);
  const glm::dvec3 dir = speed > 1e-9 ? velocity_ / speed : glm::dvec3(0, -1, 0);
  glm::dvec3 e1 = glm::cross(dir, glm::dvec3(0, 1, 0));
  e1 = glm::length(e1) > 1e-6 ? glm::normalize(e1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e2 = glm::normalize(glm::cross(dir, e1));
  emit_slices(t0, t1, n, origin_, velocity_, e1, e2, nullptr);
}

void PourStream::emit_slices(double t0, double t1, int n, glm::dvec3 origin, glm::dvec3 launch, glm::dvec3 e1,
                             glm::dvec3 e2, const std::shared_ptr<const SheetShape>& sheet) {
  // n parcels over the step, each with the flow's integral over its interval, their launch
  // wobbling across it (two sines).
  for (int k = 0; k < n; ++k) {
    const double a = t0 + kStep * k / n, b = k + 1 == n ? t1 : t0 + kStep * (k + 1) / n;
    const double v = flow_integral(a, b);
    if (!(v > 0)) continue;
    const double w = 2 * M_PI * p_.wobble_hz * b;
    const glm::dvec3 wobble =
        p_.wobble * (std::sin(w + 0.3) * e1 + std::sin(1.618 * w + 1.1) * e2) * std::sqrt(0.5);
    emitted_.add(v);
    parcels_.push_back(Parcel{b, origin, launch + wobble, v, v / (b - a), kStep / n, sheet});
  }
}

void PourStream::emit_over_lip(double t0, double t1, double q_max) {
  const StreamLip& lip = *lip_;
  const Sheet sh = sheet(q_max);
  const glm::dvec3 side = glm::normalize(glm::cross(lip.up, lip.outward));
  // kAcross strips of equal width; strip j passes its share of the flow,
  // (1 - u^2)^(3/2) at its middle u = s / half_width.
  // The sheet leaves clear of the rim: its middle a depth's half outside the rim's edge and
  // above it. Every strip sets off from there at the sheet's mean speed (flow-weighted
  // mean of the critical sqrt(g d): 128 / (45 pi) sqrt(g h)), its offset closing.
  const glm::dvec3 middle = lip.centre + (lip.radius + 0.5 * sh.depth) * lip.outward + 0.5 * sh.depth * lip.up;
  const double v0 = 128.0 / (45.0 * M_PI) * std::sqrt(p_.gravity * sh.depth);
  auto shape = std::make_shared<SheetShape>();
  shape->gap = 2 * sh.half_width / kAcross;
  double total = 0;
  for (int j = 0; j < kAcross; ++j) {
    const double u = 2.0 * (j + 0.5) / kAcross - 1.0, phi = u * sh.half_width / lip.radius;
    const glm::dvec3 at =
        lip.centre + (lip.radius + 0.5 * sh.depth) * (std::cos(phi) * lip.outward + std::sin(phi) * side) +
        0.5 * sh.depth * lip.up;
    shape->spread.push_back(at - middle);
    shape->share.push_back(std::pow(1 - u * u, 1.5));
    total += shape->share.back();
  }
  for (double& w : shape->share) w /= total;
  // The sides come in at the Taylor-Culick speed sqrt(2 sigma / (rho d)) of the sheet's
  // mean depth d, which falling thins as d0 v0 / v (v about g t): they meet when the
  // integral of sqrt(2 sigma g t / (rho d0 v0)) dt is the half width, at
  // close = (1.5 half_width / sqrt(2 sigma g / (rho d0 v0)))^(2/3).
  const double d0 = 2.0 / 3.0 * sh.depth;
  shape->close = p_.capillary > 0
                     ? std::pow(1.5 * sh.half_width / std::sqrt(2 * p_.capillary * p_.gravity / (d0 * v0)), 2.0 / 3.0)
                     : 1e9;
  // Slices spaced as a spout's would be for the whole flow: where the sheet is open its
  // strips are drawn at least 0.8 of their spacing across, wider than this along; once
  // closed, the rope is the whole flow's.
  const double v_max = fastest_speed(v0, middle.y);
  const double r_min = std::sqrt(q_max / (M_PI * v_max));
  const int slices = std::clamp(static_cast<int>(std::ceil(kStep * v_max / (p_.overlap * r_min))), 1, kMaxPerStep);
  const glm::dvec3 e2 = glm::normalize(glm::cross(lip.outward, side));
  emit_slices(t0, t1, slices, middle, v0 * lip.outward, side, e2, shape);
}

void PourStream::step() {
  const double t0 = time(), t1 = t0 + kStep;
  if (flow_integral(t0, t1) > 0) {
    double q_max = flow(t0);
    for (const auto& [from, value] : schedule_)
      if (from > t0 && from < t1) q_max = std::max(q_max, value);
    if (lip_)
      emit_over_lip(t0, t1, q_max);
    else
      emit_from_spout(t0, t1, q_max);
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

double PourStream::rope_radius() const {
  if (parcels_.empty()) return 0;
  std::vector<double> r;
  r.reserve(parcels_.size());
  const double t = time();
  for (const Parcel& q : parcels_)
    r.push_back(std::sqrt(q.flow / (M_PI * std::max(glm::length(velocity_of(q, t)), p_.min_speed))));
  std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
  return std::min(r[r.size() / 2], p_.max_radius);
}

std::optional<PourStream::Landing> PourStream::landing() const {
  const double t = time();
  for (const Parcel& q : parcels_) {  // oldest first
    if (!(q.flow > 0)) continue;
    const double speed = std::max(glm::length(velocity_of(q, t)), p_.min_speed);
    Landing l;
    l.position = at(q, t);
    l.position.y = target_;
    l.radius = std::min(std::sqrt(q.flow / (M_PI * speed)), p_.max_radius);
    l.flow = q.flow;
    return l;
  }
  return std::nullopt;
}

PointCloud PourStream::cloud() const {
  PointCloud c;
  c.default_radius = static_cast<float>(p_.max_radius);
  const double t = time();
  for (const Parcel& q : parcels_) {
    const glm::dvec3 at_t = at(q, t), v = velocity_of(q, t);
    const double speed = std::max(glm::length(v), p_.min_speed);
    const double whole = std::min(std::sqrt(q.flow / (M_PI * speed)), p_.max_radius);
    const double open = q.sheet ? open_part(t - q.born, q.sheet->close) : 0.0;
    const double spacing = speed * q.interval;  // to the next slice
    if (open <= 0) {
      c.position.emplace_back(at_t);
      c.radius.push_back(static_cast<float>(line_blob_radius(whole, spacing, kCloudThreshold)));
      c.velocity.emplace_back(v);
      continue;
    }
    // An open slice: a line of blobs per strip, its offset closing. Each strip's tube is
    // drawn at least 0.8 of the strips' spacing wide (so that the sheet holds together
    // where it is thinner), and tends to the radius at which the n strips, met, draw the
    // closed slice's tube: n coincident lines reach F = T where one line reaches T / n.
    const double n = double(q.sheet->spread.size());
    const double met = line_blob_radius(whole, spacing, kCloudThreshold / n);
    for (std::size_t j = 0; j < q.sheet->spread.size(); ++j) {
      const double share = std::sqrt(q.flow * q.sheet->share[j] / (M_PI * speed));
      const double drawn = line_blob_radius(std::max(share, 0.8 * q.sheet->gap * open), spacing, kCloudThreshold);
      c.position.emplace_back(at_t + q.sheet->spread[j] * open);
      c.radius.push_back(static_cast<float>(std::min(open * drawn + (1 - open) * met, p_.max_radius)));
      c.velocity.emplace_back(v - q.sheet->spread[j] / q.sheet->close);
    }
  }
  return c;
}

}  // namespace draught
