#include "core/reference/intersect.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

int solve_cubic(double a, double b, double c, double roots[3]) {
  const double Q = (a * a - 3 * b) / 9, R = (2 * a * a * a - 9 * a * b + 27 * c) / 54;
  const double Q3 = Q * Q * Q;
  if (R * R < Q3) {
    const double th = std::acos(std::clamp(R / std::sqrt(Q3), -1.0, 1.0)), sq = -2 * std::sqrt(Q);
    for (int k = 0; k < 3; ++k) roots[k] = sq * std::cos((th + 2 * std::numbers::pi * k) / 3) - a / 3;
    std::sort(roots, roots + 3);
    return 3;
  }
  double A = -std::copysign(std::cbrt(std::fabs(R) + std::sqrt(R * R - Q3)), R);
  double B = A != 0 ? Q / A : 0;
  roots[0] = A + B - a / 3;
  return 1;
}

namespace {
int solve_quadratic(double a, double b, double c, double out[2]) {
  // a x^2 + b x + c = 0, stable form
  if (std::fabs(a) < 1e-300) {
    if (std::fabs(b) < 1e-300) return 0;
    out[0] = -c / b;
    return 1;
  }
  double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  double s = std::sqrt(disc);
  double q = -0.5 * (b + std::copysign(s, b));
  double x0 = q / a, x1 = q != 0 ? c / q : x0;
  out[0] = std::min(x0, x1);
  out[1] = std::max(x0, x1);
  return 2;
}
}  // namespace

int solve_quartic(double b, double c, double d, double e, double roots[4]) {
  // Depress: x = y - b/4  ->  y^4 + p y^2 + q y + r = 0, then Ferrari.
  const double b2 = b * b;
  const double p = c - 3 * b2 / 8;
  const double q = d - b * c / 2 + b2 * b / 8;
  const double r = e - b * d / 4 + b2 * c / 16 - 3 * b2 * b2 / 256;
  int n = 0;
  double tmp[2];
  // Ferrari needs the resolvent's positive root m; when q ~ 0, m ~ 0 and q / sqrt(m)
  // is all cancellation error. Then solve the biquadratic y^4 + p y^2 + r (q dropped)
  // and let the Newton polish below restore the small q term.
  const double scale = std::max({1.0, std::fabs(p), std::sqrt(std::fabs(r))});
  double m = 0;
  if (std::fabs(q) > 1e-14 * scale * std::sqrt(scale)) {
    double cub[3];
    int k = solve_cubic(p, p * p / 4 - r, -q * q / 8, cub);
    m = cub[0];
    for (int i = 1; i < k; ++i) m = std::max(m, cub[i]);
  }
  if (m <= 1e-12 * scale) {
    int k = solve_quadratic(1, p, r, tmp);
    for (int i = 0; i < k; ++i)
      if (tmp[i] >= 0) {
        roots[n++] = std::sqrt(tmp[i]);
        roots[n++] = -std::sqrt(tmp[i]);
      }
  } else {
    const double s = std::sqrt(2 * m);
    int k1 = solve_quadratic(1, -s, p / 2 + m + q / (2 * s), tmp);
    for (int i = 0; i < k1; ++i) roots[n++] = tmp[i];
    int k2 = solve_quadratic(1, s, p / 2 + m - q / (2 * s), tmp);
    for (int i = 0; i < k2; ++i) roots[n++] = tmp[i];
  }
  for (int i = 0; i < n; ++i) {
    double x = roots[i] - b / 4;
    for (int it = 0; it < 3; ++it) {  // Newton polish on the original polynomial
      double f = (((x + b) * x + c) * x + d) * x + e;
      double df = ((4 * x + 3 * b) * x + 2 * c) * x + d;
      if (df == 0) break;
      x -= f / df;
    }
    roots[i] = x;
  }
  std::sort(roots, roots + n);
  return n;
}

int intersect_cone(const Ray& ray, double r0, double r1, double y0, double y1, double tmin, double out[2]) {
  const double s = (r1 - r0) / (y1 - y0);
  const double c0 = r0 + s * (ray.o.y - y0), c1 = s * ray.d.y;
  const double A = ray.d.x * ray.d.x + ray.d.z * ray.d.z - c1 * c1;
  const double B = 2 * (ray.o.x * ray.d.x + ray.o.z * ray.d.z - c0 * c1);
  const double C = ray.o.x * ray.o.x + ray.o.z * ray.o.z - c0 * c0;
  double t[2];
  int k = solve_quadratic(A, B, C, t), n = 0;
  for (int i = 0; i < k; ++i) {
    double y = ray.o.y + t[i] * ray.d.y;
    if (t[i] > tmin && y >= y0 && y <= y1 && c0 + c1 * t[i] >= 0) out[n++] = t[i];
  }
  return n;
}

int intersect_torus(const Ray& ray, double R, double r, double cy, double out[4]) {
  const glm::dvec3 o = ray.o - glm::dvec3(0, cy, 0), d = ray.d;
  const double m = glm::dot(o, o), nn = glm::dot(o, d), K = m + R * R - r * r;
  const double a3 = 4 * nn;
  const double a2 = 4 * nn * nn + 2 * K - 4 * R * R * (1 - d.y * d.y);
  const double a1 = 4 * nn * K - 8 * R * R * (nn - o.y * d.y);
  const double a0 = K * K - 4 * R * R * (m - o.y * o.y);
  return solve_quartic(a3, a2, a1, a0, out);
}

namespace {

// The slab [ylo, yhi] and the cylinder r <= rad along the ray, as [t0, t1].
bool clip_to_bounds(const Ray& ray, double ylo, double yhi, double rad, double tmin, double& t0, double& t1) {
  t0 = tmin;
  t1 = std::numeric_limits<double>::infinity();
  if (std::fabs(ray.d.y) < 1e-12) {
    if (ray.o.y < ylo || ray.o.y > yhi) return false;
  } else {
    double a = (ylo - ray.o.y) / ray.d.y, b = (yhi - ray.o.y) / ray.d.y;
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  const double A = ray.d.x * ray.d.x + ray.d.z * ray.d.z;
  const double B = ray.o.x * ray.d.x + ray.o.z * ray.d.z;
  const double C = ray.o.x * ray.o.x + ray.o.z * ray.o.z - rad * rad;
  if (A < 1e-18) {
    if (C > 0) return false;
  } else {
    double disc = B * B - A * C;
    if (disc < 0) return false;
    double s = std::sqrt(disc);
    t0 = std::max(t0, (-B - s) / A);
    t1 = std::min(t1, (-B + s) / A);
  }
  return t0 <= t1;
}

bool inside_body(const Vessel& v, double r, double y) {
  if (y < 0 || y > v.height || r > v.outer_radius(y)) return false;
  return y < v.base || r >= v.inner_radius(y);
}

}  // namespace

Hit hit_wall(const Vessel& v, bool inner, const Ray& ray, double tmin) {
  const auto& knots = inner ? v.r_inner : v.r_outer;
  const double ylo = inner ? v.base : 0.0, yhi = v.height;
  double t0, t1;
  if (!clip_to_bounds(ray, ylo, yhi, v.bound_radius, tmin, t0, t1)) return {};
  const int last = Vessel::kSegments - 1;
  int k0 = std::clamp(int(std::floor(ray.at(t0).y / v.dy)), 0, last);
  int k1 = std::clamp(int(std::floor(ray.at(t1).y / v.dy)), 0, last);
  const int step = k1 >= k0 ? 1 : -1;
  // Frustums the ray cannot cross are passed over unsolved (a path down through a drink,
  // a photon passing a glass, walk many). Along the ray's line the distance from the axis,
  // rho, is convex and a frustum's radius linear between its knots, so the line is
  // - inside a frustum where it is well inside at both knot heights (rho - R is convex
  //   and negative at both ends);
  // - outside it where its closest approach to the axis between the knot heights is well
  //   beyond the larger knot radius.
  // (Margins of a millionth: far beyond the roundings, so the hits are the same.)
  const bool steep = std::fabs(ray.d.y) > 1e-6;
  const double inv_dy = steep ? 1 / ray.d.y : 0.0;
  const double dd = ray.d.x * ray.d.x + ray.d.z * ray.d.z, od = ray.o.x * ray.d.x + ray.o.z * ray.d.z;
  const double t_near = dd > 0 ? -od / dd : 0.0;  // the line's closest approach to the axis
  struct Knot {
    double t, rho2, r2;
  };
  auto knot = [&](int i) {
    const double t = (i * v.dy - ray.o.y) * inv_dy;
    const double x = ray.o.x + t * ray.d.x, z = ray.o.z + t * ray.d.z, r = knots[size_t(i)];
    return Knot{t, x * x + z * z, r * r};
  };
  auto passed_over = [&](const Knot& a, const Knot& b) {
    if (a.rho2 < a.r2 * (1 - 1e-6) && b.rho2 < b.r2 * (1 - 1e-6)) return true;
    double rho2_min = std::min(a.rho2, b.rho2);
    if (t_near > std::min(a.t, b.t) && t_near < std::max(a.t, b.t)) {
      const double x = ray.o.x + t_near * ray.d.x, z = ray.o.z + t_near * ray.d.z;
      rho2_min = x * x + z * z;
    }
    return rho2_min > std::max(a.r2, b.r2) * (1 + 1e-6);
  };
  Knot entry = steep ? knot(step > 0 ? k0 : k0 + 1) : Knot{};  // the knot the walk enters the segment at
  for (int k = k0;; k += step) {
    if (steep) {
      const Knot exit = knot(step > 0 ? k + 1 : k);
      const bool skip = passed_over(entry, exit);
      entry = exit;
      if (skip) {
        if (k == k1) break;
        continue;
      }
    }
    double ts[2];
    int n = intersect_cone(ray, knots[size_t(k)], knots[size_t(k) + 1], k * v.dy, (k + 1) * v.dy, tmin, ts);
    for (int i = 0; i < n; ++i) {
      glm::dvec3 p = ray.at(ts[i]);
      double r = std::hypot(p.x, p.z);
      if (p.y < ylo || p.y > yhi || v.inside_torus(r, p.y)) continue;
      // The smooth normal of the profile (Vessel::wall_slope), on the exact frustum.
      const double s = v.wall_slope(inner, k, p.y / v.dy - k);
      glm::dvec3 n = r > 0 ? glm::normalize(glm::dvec3(p.x / r, -s, p.z / r)) : glm::dvec3(0, -1, 0);
      return {ts[i], inner ? -n : n, inner ? Material::GlassInner : Material::GlassOuter};
    }
    if (k == k1) break;
  }
  return {};
}

Hit hit_rim(const Vessel& v, const Ray& ray, double tmin) {
  double t0, t1;
  if (!clip_to_bounds(ray, v.height - v.rim_minor, v.height + v.rim_minor, v.rim_major + v.rim_minor, tmin, t0,
                      t1))
    return {};
  // Solve from a nearby origin, scaled by the major radius, for float-friendly numbers.
  const double R = v.rim_major;
  Ray local{(ray.at(t0) - glm::dvec3(0, v.height, 0)) / R, ray.d};
  double ts[4];
  int n = intersect_torus(local, 1.0, v.rim_minor / R, 0.0, ts);
  for (int i = 0; i < n; ++i) {
    double t = t0 + ts[i] * R;
    if (t <= tmin) continue;
    glm::dvec3 p = ray.at(t);
    double r = std::hypot(p.x, p.z);
    if (p.y < v.height && inside_body(v, r, p.y)) continue;
    glm::dvec3 c = r > 0 ? glm::dvec3(p.x / r * v.rim_major, v.height, p.z / r * v.rim_major)
                         : glm::dvec3(0, v.height, 0);
    return {t, glm::normalize(p - c), Material::Rim};
  }
  return {};
}

namespace {
Hit hit_disk(const Ray& ray, double y, double rad, double tmin, glm::dvec3 n, Material m) {
  if (std::fabs(ray.d.y) < 1e-15) return {};
  double t = (y - ray.o.y) / ray.d.y;
  if (t <= tmin) return {};
  glm::dvec3 p = ray.at(t);
  if (p.x * p.x + p.z * p.z > rad * rad) return {};
  return {t, n, m};
}

void keep_nearest(Hit& best, const Hit& h) {
  if (h.valid() && h.t < best.t) best = h;
}
}  // namespace

Hit hit_liquid_surface(const Vessel& v, const LiquidPlane& l, const Ray& ray, double tmin) {
  const double dn = glm::dot(l.n, ray.d);
  if (std::fabs(dn) < 1e-15) return {};
  // From the plane, Newton steps onto the waves (they are small and smooth).
  double t = (l.offset - glm::dot(l.n, ray.o)) / dn;
  for (int it = 0; it < (l.waves.flat() ? 0 : 4); ++it) {
    const glm::dvec3 p = ray.at(t);
    const glm::dvec2 g = l.waves.gradient(p.x, p.z);
    const double slope = dn - (g.x * ray.d.x + g.y * ray.d.z);
    if (std::fabs(slope) < 1e-12) break;
    t -= l.level(p) / slope;
  }
  const glm::dvec3 p = ray.at(t);
  if (!(t > tmin) || p.y <= v.base || p.y >= v.height || std::hypot(p.x, p.z) >= v.inner_radius(p.y)) return {};
  const glm::dvec2 g = l.waves.gradient(p.x, p.z);
  return {t, glm::normalize(l.n - glm::dvec3(g.x, 0, g.y)), Material::LiquidSurface};
}

Hit hit_vessel(const VesselGeometry& s, const Ray& world_ray, double tmin) {
  const Vessel& v = *s.vessel;
  const glm::dquat to_local = glm::inverse(s.pose.orientation);
  const Ray ray{to_local * (world_ray.o - s.pose.position), to_local * world_ray.d};
  // The sphere around the glass's bounding cylinder first: most rays of a scene miss
  // most glasses (a cheap test before two walls, a torus and the discs).
  const double half = 0.5 * (v.height + v.rim_minor);
  const glm::dvec3 oc = ray.o - glm::dvec3(0, half, 0);
  const double b = glm::dot(oc, ray.d), r2 = half * half + v.bound_radius * v.bound_radius;
  const double c = glm::dot(oc, oc) - r2;
  if (c > 0 && (b > 0 || b * b < c)) return Hit{};
  // A surface's first hit that is not cut away by the cross-section.
  auto kept = [&](auto&& hit_from) {
    double from = tmin;
    for (int i = 0; i < 16; ++i) {
      const Hit h = hit_from(from);
      if (!h.valid() || !s.clipped(ray.at(h.t))) return h;
      from = h.t + 1e-9;
    }
    return Hit{};
  };
  Hit best;
  keep_nearest(best, kept([&](double t) { return hit_wall(v, false, ray, t); }));
  keep_nearest(best, kept([&](double t) { return hit_wall(v, true, ray, t); }));
  keep_nearest(best, kept([&](double t) { return hit_rim(v, ray, t); }));
  keep_nearest(best, kept([&](double t) {
    return hit_disk(ray, 0.0, v.r_outer.front(), t, {0, -1, 0}, Material::GlassBottom);
  }));
  keep_nearest(best, kept([&](double t) {
    return hit_disk(ray, v.base, v.inner_radius(v.base), t, {0, 1, 0}, Material::CavityFloor);
  }));
  keep_nearest(best, kept([&](double t) { return hit_liquid_surface(v, s.liquid, ray, t); }));
  // The cut face, where the plane passes through glass or liquid.
  const glm::dvec3 cn(s.clip);
  if (glm::dot(cn, cn) > 0.5 && std::fabs(glm::dot(cn, ray.d)) > 1e-15) {
    const double t = (s.clip.w - glm::dot(cn, ray.o)) / glm::dot(cn, ray.d);
    const glm::dvec3 p = ray.at(t);
    const double r = std::hypot(p.x, p.z);
    const bool in_glass = p.y >= 0 && p.y <= v.height && r <= v.outer_radius(p.y) &&
                          (p.y < v.base || r >= v.inner_radius(p.y));
    const bool in_liquid = !in_glass && p.y > v.base && p.y < v.height && r < v.inner_radius(p.y) && s.liquid.below(p);
    if (t > tmin && (in_glass || v.inside_torus(r, p.y)))
      keep_nearest(best, {t, cn, Material::ClipGlass});
    else if (t > tmin && in_liquid)
      keep_nearest(best, {t, cn, Material::ClipLiquid});
  }
  best.n = s.pose.orientation * best.n;
  return best;
}

Hit first_hit(const SceneGeometry& s, const Ray& world_ray, double tmin) {
  Hit best;
  for (size_t i = 0; i < s.vessels.size(); ++i) {
    Hit h = hit_vessel(s.vessels[i], world_ray, tmin);
    h.object = int(i);
    keep_nearest(best, h);
  }
  double t;
  glm::dvec3 n;
  if (s.backdrop.intersect(world_ray.o, world_ray.d, tmin, t, n) && t < best.t) {
    // Where a glass stands on the floor, its foot is the surface.
    bool on_foot = false;
    for (const VesselGeometry& g : s.vessels) {
      const glm::dvec3 p = glm::inverse(g.pose.orientation) * (world_ray.at(t) - g.pose.position);
      on_foot = on_foot || (std::fabs(p.y) < 1e-6 && std::hypot(p.x, p.z) <= g.vessel->r_outer.front());
    }
    if (!on_foot) keep_nearest(best, {t, n, Material::Floor, -1});
  }
  return best;
}

DecalHit decal_hit(const VesselGeometry& s, const Hit& h, const Ray& world_ray) {
  if (!s.decals || (h.m != Material::GlassOuter && h.m != Material::GlassInner)) return {};
  const int layer = h.m == Material::GlassInner ? 1 : 0;
  const glm::dvec3 local = glm::inverse(s.pose.orientation) * (world_ray.at(h.t) - s.pose.position);
  const std::optional<glm::dvec2> uv = decal_uv(*s.vessel, s.decals->arcs, s.decals->layers[size_t(layer)], local);
  if (!uv) return {};
  return {layer, *uv};
}

}  // namespace draught
