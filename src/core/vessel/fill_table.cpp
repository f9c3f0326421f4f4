#include "core/vessel/fill_table.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

constexpr double kFlat = 1e-7;  // |sin(tilt)| below this: the plane is horizontal

// 6-point Gauss-Legendre on [-1, 1].
constexpr std::array<double, 6> kGaussX = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                           0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr std::array<double, 6> kGaussW = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                           0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

// A horizontal slice: disk of radius r cut by the line x = x0; the part x <= x0.
// Returns its area and d(area)/d(x0) (the chord length).
void slice(double r, double x0, double& area, double& chord) {
  if (x0 >= r) {
    area = kPi * r * r;
    chord = 0;
  } else if (x0 <= -r) {
    area = chord = 0;
  } else {
    const double h = std::sqrt(r * r - x0 * x0);
    area = r * r * std::acos(-x0 / r) + x0 * h;
    chord = 2 * h;
  }
}

struct VolumeAndArea {
  double volume = 0;  // below the plane
  double area = 0;    // d(volume)/d(offset): the surface's area inside the cavity
};

// The plane is horizontal: the cavity below (cos > 0) or above (cos < 0) one height.
VolumeAndArea horizontal_cut(const Vessel& v, double c, double offset) {
  const double total = v.cavity_volume();
  if (std::abs(c) < 1e-300) return {offset >= 0 ? total : 0.0, 0.0};
  const double y = offset / c;
  const double below = v.cavity_volume_below(y);
  const double r = (y > v.base && y < v.height) ? v.inner_radius(y) : 0.0;
  return {c > 0 ? below : total - below, kPi * r * r / std::abs(c)};
}

// The volume below the plane in the cavity; `extend` > 0 continues the cavity above the
// rim as a cylinder of the rim's radius that high (see build_fill_table).
VolumeAndArea integrate(const Vessel& v, double tilt, double offset, double extend = 0) {
  const double s = std::sin(tilt), c = std::cos(tilt);
  if (std::abs(s) < kFlat) return horizontal_cut(v, c, offset);
  VolumeAndArea out;
  auto x_cut = [&](double y) { return (offset - c * y) / s; };
  // One slab whose radius is linear in y.
  auto slab = [&](double y0, double y1, double r0, double r1) {
    const double a0 = x_cut(y0), a1 = x_cut(y1);
    if (a0 >= r0 && a1 >= r1) {  // the whole slab is below the plane
      out.volume += kPi * (y1 - y0) / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1);
      return;
    }
    if (a0 <= -r0 && a1 <= -r1) return;  // none of it
    // x_cut -/+ r are linear in y: where they change sign the integrand has a kink.
    double cuts[4] = {y0, y1, y1, y1};
    int n = 1;
    for (double sign : {1.0, -1.0}) {
      const double f0 = a0 - sign * r0, f1 = a1 - sign * r1;
      if ((f0 < 0) != (f1 < 0)) cuts[n++] = y0 + (y1 - y0) * f0 / (f0 - f1);
    }
    if (n == 3 && cuts[1] > cuts[2]) std::swap(cuts[1], cuts[2]);
    cuts[n++] = y1;
    for (int p = 0; p + 1 < n; ++p) {
      const double lo = cuts[p], hi = cuts[p + 1], half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
      if (half <= 0) continue;
      for (size_t g = 0; g < kGaussX.size(); ++g) {
        const double y = mid + half * kGaussX[g];
        const double r = r0 + (r1 - r0) * (y - y0) / (y1 - y0);
        double area, chord;
        slice(r, x_cut(y), area, chord);
        out.volume += half * kGaussW[g] * area;
        out.area += half * kGaussW[g] * chord / std::abs(s);
      }
    }
  };
  for (int k = 0; k < Vessel::kSegments; ++k) {
    const double y0 = std::max(k * v.dy, v.base), y1 = std::min((k + 1) * v.dy, v.height);
    if (y1 > y0) slab(y0, y1, v.inner_radius(y0), v.inner_radius(y1));
  }
  if (extend > 0) slab(v.height, v.height + extend, v.inner_radius(v.height), v.inner_radius(v.height));
  return out;
}

double fraction_axis(int j) {
  const double u = double(j) / (FillTable::kVolumes - 1);
  return u * u * (3 - 2 * u);
}

// Inverts the monotone V(offset) sampled with its derivative: cubic Hermite per cell,
// Newton (with bisection fallback) inside the cell.
double invert_hermite(const std::vector<double>& d, const std::vector<VolumeAndArea>& f, double target) {
  if (target <= f.front().volume) return d.front();
  if (target >= f.back().volume) return d.back();
  size_t i = size_t(std::upper_bound(f.begin(), f.end(), target,
                                     [](double t, const VolumeAndArea& e) { return t < e.volume; }) -
                    f.begin()) - 1;
  i = std::min(i, f.size() - 2);
  const double h = d[i + 1] - d[i], v0 = f[i].volume, v1 = f[i + 1].volume;
  const double m0 = f[i].area * h, m1 = f[i + 1].area * h;
  auto hermite = [&](double t, double& dv) {
    const double t2 = t * t, t3 = t2 * t;
    dv = (6 * t2 - 6 * t) * v0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * v1 + (3 * t2 - 2 * t) * m1;
    return (2 * t3 - 3 * t2 + 1) * v0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * v1 + (t3 - t2) * m1;
  };
  double lo = 0, hi = 1, t = (target - v0) / std::max(v1 - v0, 1e-300);
  for (int it = 0; it < 30; ++it) {
    double dv;
    const double err = hermite(t, dv) - target;
    (err < 0 ? lo : hi) = t;
    if (std::abs(err) < 1e-15 * std::max(1.0, std::abs(target))) break;
    double next = dv > 0 ? t - err / dv : -1;
    t = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  return d[i] + t * h;
}

}  // namespace

double volume_below_plane(const Vessel& v, double tilt, double offset) { return integrate(v, tilt, offset).volume; }

namespace {
void offset_range_extended(const Vessel& v, double tilt, double extend, double& lo, double& hi) {
  const double s = std::abs(std::sin(tilt)), c = std::cos(tilt);
  auto extent = [&](double y) {
    const double r = v.inner_radius(std::min(y, v.height));
    lo = std::min(lo, c * y - s * r);
    hi = std::max(hi, c * y + s * r);
  };
  lo = 1e300, hi = -1e300;
  extent(v.base);
  extent(v.height);
  if (extend > 0) extent(v.height + extend);
  for (int k = 0; k <= Vessel::kSegments; ++k)
    if (k * v.dy > v.base && k * v.dy < v.height) extent(k * v.dy);
}
}  // namespace

void offset_range(const Vessel& v, double tilt, double& lo, double& hi) { offset_range_extended(v, tilt, 0, lo, hi); }

double plane_offset_for_volume(const Vessel& v, double tilt, double volume) {
  double lo, hi;
  offset_range(v, tilt, lo, hi);
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (volume_below_plane(v, tilt, mid) < volume ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double rim_offset(const Vessel& v, double tilt) {
  return std::cos(tilt) * v.height - std::abs(std::sin(tilt)) * v.inner_radius(v.height);
}

FillTable build_fill_table(const Vessel& v) {
  FillTable t;
  t.cavity_volume = v.cavity_volume();
  t.vessel = v;
  t.offset.resize(size_t(FillTable::kTilts) * FillTable::kVolumes);
  constexpr int kSamples = 48;  // offsets per tilt where V and dV/doffset are integrated
  std::vector<double> d(kSamples);
  std::vector<VolumeAndArea> f(kSamples);
  for (int i = 0; i < FillTable::kTilts; ++i) {
    const double tilt = FillTable::kMaxTilt * i / (FillTable::kTilts - 1);
    // Rows for tipped glasses (up to 90 degrees) see the cavity continued above the rim,
    // so the offset stays smooth across the spill limit and interpolating between a row
    // that is below capacity and one that is past it stays accurate. Below capacity
    // the continuation is entirely above the plane, so it changes no valid entry.
    const bool flat = std::abs(std::sin(tilt)) < kFlat;
    const double extend = (!flat && std::cos(tilt) > 1e-6) ? 2.0 * v.inner_radius(v.height) : 0.0;
    double lo, hi;
    offset_range_extended(v, tilt, extend, lo, hi);
    for (int m = 0; m < kSamples; ++m) {
      // Chebyshev-like spacing: denser at both ends, where the volume changes slowly.
      const double u = 0.5 - 0.5 * std::cos(kPi * m / (kSamples - 1));
      d[size_t(m)] = lo + (hi - lo) * u;
      f[size_t(m)] = integrate(v, tilt, d[size_t(m)], extend);
    }
    for (int j = 0; j < FillTable::kVolumes; ++j)
      t.offset[size_t(i * FillTable::kVolumes + j)] = float(invert_hermite(d, f, fraction_axis(j) * t.cavity_volume));
  }
  return t;
}

double FillTable::offset_at(double tilt, double fraction) const {
  const double ti = std::clamp(std::abs(tilt) / kMaxTilt, 0.0, 1.0) * (kTilts - 1);
  // Inverse of the column spacing u^2 (3 - 2u).
  const double u = 0.5 - std::sin(std::asin(1.0 - 2.0 * std::clamp(fraction, 0.0, 1.0)) / 3.0);
  const double vj = u * (kVolumes - 1);
  const int i = std::min(int(ti), kTilts - 2), j = std::min(int(vj), kVolumes - 2);
  const double fi = ti - i, fj = vj - j;
  auto row = [&](int r) { return (1 - fj) * offset[size_t(r * kVolumes + j)] + fj * offset[size_t(r * kVolumes + j + 1)]; };
  // Interpolate across tilts what is left after the plane through the upright level
  // (row 0) is taken out: for straight walls that remainder does not change with tilt.
  const double level = row(0);
  auto rest = [&](int r) { return row(r) - std::cos(r * kMaxTilt / (kTilts - 1)) * level; };
  return std::cos(std::abs(tilt)) * level + (1 - fi) * rest(i) + fi * rest(i + 1);
}

double FillTable::capacity_at(double tilt) const {
  tilt = std::clamp(std::abs(tilt), 0.0, kMaxTilt);
  const double cap = volume_below_plane(vessel, tilt, rim_offset(vessel, tilt)) / std::max(cavity_volume, 1e-300);
  return std::clamp(cap, 0.0, 1.0);
}

}  // namespace draught
