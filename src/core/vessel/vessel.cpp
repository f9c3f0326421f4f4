#include "core/vessel/vessel.hpp"

#include "core/vessel/profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
double lerp_knots(const std::vector<double>& k, double dy, double y) {
  const int n = int(k.size()) - 1;
  double s = std::clamp(y / dy, 0.0, double(n));
  int i = std::min(int(s), n - 1);
  double f = s - i;
  return k[size_t(i)] * (1 - f) + k[size_t(i) + 1] * f;
}

// A segment's slope at its knot with a neighbour: the mean of the two (uniform knots:
// the central difference), unless their normals (1, -own) and (1, -other) meet at a
// crease; then its own.
double knot_slope(double other, double own) {
  const double c = (1 + other * own) / std::sqrt((1 + other * other) * (1 + own * own));
  return c >= contract::kCreaseCos ? 0.5 * (other + own) : own;
}

double frustum_volume(double r0, double r1, double h) {
  return std::numbers::pi * h / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1);
}
}  // namespace

double Vessel::outer_radius(double y) const { return lerp_knots(r_outer, dy, y); }
double Vessel::inner_radius(double y) const { return lerp_knots(r_inner, dy, y); }

double Vessel::wall_slope(bool inner, int k, double f) const {
  const std::vector<double>& r = inner ? r_inner : r_outer;
  const int last = kSegments - 1;
  k = std::clamp(k, 0, last);
  auto seg = [&](int i) { return (r[size_t(i) + 1] - r[size_t(i)]) / dy; };
  const double s = seg(k);
  const double below = k > 0 ? knot_slope(seg(k - 1), s) : s;
  const double above = k < last ? knot_slope(seg(k + 1), s) : s;
  f = std::clamp(f, 0.0, 1.0);
  return below * (1 - f) + above * f;
}

bool Vessel::inside_torus(double r, double y) const {
  const double a = r - rim_major, b = y - height;
  return a * a + b * b < rim_minor * rim_minor;
}

double Vessel::cavity_volume_below(double h) const {
  h = std::clamp(h, base, height);
  double v = 0;
  for (int k = 0; k < kSegments; ++k) {
    double y0 = std::max(k * dy, base), y1 = std::min((k + 1) * dy, h);
    if (y1 <= y0) continue;
    v += frustum_volume(inner_radius(y0), inner_radius(y1), y1 - y0);
  }
  return v;
}

double Vessel::cavity_volume() const { return cavity_volume_below(height); }

double Vessel::fill_height(double fraction) const {
  const double target = std::clamp(fraction, 0.0, 1.0) * cavity_volume();
  // The segment the level lies in, by the whole segments' volumes below it (summed as
  // cavity_volume_below sums them), then bisection within it: the volume below a height
  // there is that sum and one frustum, so a solve costs a pass over the segments instead
  // of one per step (drink_aim solves each glass's every frame).
  double below = 0, y0 = base, lo = base, hi = height;
  bool within = false;
  for (int k = 0; k < kSegments && !within; ++k) {
    const double a = std::max(k * dy, base), b = std::min((k + 1) * dy, height);
    if (b <= a) continue;
    const double whole = frustum_volume(inner_radius(a), inner_radius(b), b - a);
    if (below + whole >= target) {
      y0 = lo = a;
      hi = b;
      within = true;
    } else {
      below += whole;
    }
  }
  if (!within) return target >= below ? height : base;  // (a NaN fraction: the floor, as before)
  const double r0 = inner_radius(y0);
  for (int i = 0; i < 64; ++i) {
    const double mid = 0.5 * (lo + hi);
    (below + frustum_volume(r0, inner_radius(mid), mid - y0) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Vessel build_vessel(const GlassParams& g) {
  ProfileCurve curve(g.profile);
  Vessel v;
  v.height = curve.height();
  v.dy = v.height / Vessel::kSegments;
  const double wall = g.wall_thickness;
  // The table keeps base_thickness >= 1 mm; what it cannot know is the glass's height.
  v.base = std::min(double(g.base_thickness), v.height - 0.01);
  for (int k = 0; k <= Vessel::kSegments; ++k) {
    double r = curve.radius(k * v.dy);
    v.r_outer.push_back(r);
    v.r_inner.push_back(std::max(r - wall, 0.0));
  }
  const double top = v.r_outer.back();
  v.rim_minor = std::clamp(double(g.rim_radius), 0.5 * wall, 2.0 * wall);
  v.rim_major = top - 0.5 * wall;
  v.bound_radius = std::max(*std::max_element(v.r_outer.begin(), v.r_outer.end()), v.rim_major + v.rim_minor);
  return v;
}

}  // namespace draught
