#include "core/pointcloud/field.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>

namespace draught {

double cloud_support_scale(double threshold) { return 1.0 / std::sqrt(1.0 - std::cbrt(threshold)); }

// ---- the reference ----
namespace {

struct RefSupport {
  glm::dvec3 c{0.0};
  double R2 = 0;
  std::size_t i = 0;
};

// The points' supports the ray crosses within [tmin, tmax] and the ends of their spans.
void ref_supports(const PointCloud& cloud, double scale, glm::dvec3 o, glm::dvec3 d, double tmin, double tmax,
                  std::vector<RefSupport>& out, std::vector<double>& breaks) {
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const glm::dvec3 c(cloud.position[i]);
    const double R = scale * double(cloud.radius_of(i));
    const glm::dvec3 q = o - c;
    const double b = glm::dot(q, d), disc = b * b - (glm::dot(q, q) - R * R);
    if (disc <= 0) continue;
    const double sq = std::sqrt(disc), t0 = -b - sq, t1 = -b + sq;
    if (t1 < tmin || t0 > tmax) continue;
    out.push_back({c, R * R, i});
    if (t0 > tmin) breaks.push_back(t0);
    if (t1 < tmax) breaks.push_back(t1);
  }
}

struct RefRay {
  const std::vector<RefSupport>& s;
  glm::dvec3 o, d;
  double thr, sgn;
  // g = sgn (threshold - F) and dg/dt.
  double g(double t, double* dg = nullptr) const {
    const glm::dvec3 p = o + t * d;
    double f = 0, df = 0;
    for (const RefSupport& r : s) {
      const glm::dvec3 q = p - r.c;
      const double u = glm::dot(q, q) / r.R2;
      if (u >= 1.0) continue;
      const double w = 1.0 - u;
      f += w * w * w;
      df += -6.0 * w * w * glm::dot(q, d) / r.R2;
    }
    if (dg) *dg = -sgn * df;
    return sgn * (thr - f);
  }
};

// The reference's scan: the first t where g <= 0 (nullopt: none), and the smallest g seen.
std::optional<double> ref_scan(const RefRay& ray, std::vector<double> breaks, double tmin, double tmax,
                               double& gmin) {
  breaks.push_back(tmin);
  breaks.push_back(tmax);
  std::sort(breaks.begin(), breaks.end());
  gmin = ray.g(tmin);
  if (gmin <= 0) return tmin;
  auto root = [&](double a, double b) {
    for (int k = 0; k < 100 && b - a > 0; ++k) {
      const double m = 0.5 * (a + b);
      if (ray.g(m) <= 0) b = m;
      else a = m;
    }
    return b;
  };
  for (std::size_t j = 0; j + 1 < breaks.size(); ++j) {
    const double u0 = breaks[j], u1 = breaks[j + 1];
    if (!(u1 > u0)) continue;
    constexpr int kCuts = 16;
    for (int k = 0; k < kCuts; ++k) {
      const double a = u0 + (u1 - u0) * k / kCuts, b = k + 1 == kCuts ? u1 : u0 + (u1 - u0) * (k + 1) / kCuts;
      double da, db;
      ray.g(a, &da);
      const double gb = ray.g(b, &db);
      gmin = std::min(gmin, gb);
      if (gb <= 0) return root(a, b);
      if (da < 0 && db > 0) {
        double lo = a, hi = b;
        for (int it = 0; it < 80; ++it) {
          const double m = 0.5 * (lo + hi);
          double dm;
          ray.g(m, &dm);
          if (dm < 0) lo = m;
          else hi = m;
        }
        const double m = 0.5 * (lo + hi), gm = ray.g(m);
        gmin = std::min(gmin, gm);
        if (gm <= 0) return root(a, m);
      }
    }
  }
  return std::nullopt;
}

}  // namespace

double cloud_field_reference(const PointCloud& cloud, double threshold, glm::dvec3 p) {
  const double scale = cloud_support_scale(threshold);
  double f = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double R = scale * double(cloud.radius_of(i));
    const glm::dvec3 q = p - glm::dvec3(cloud.position[i]);
    f += cloud_kernel(glm::dot(q, q) / (R * R));
  }
  return f;
}

glm::dvec3 cloud_gradient_reference(const PointCloud& cloud, double threshold, glm::dvec3 p) {
  const double scale = cloud_support_scale(threshold);
  glm::dvec3 g(0.0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double R = scale * double(cloud.radius_of(i)), R2 = R * R;
    const glm::dvec3 q = p - glm::dvec3(cloud.position[i]);
    const double s = glm::dot(q, q) / R2;
    if (s < 1.0) g += -6.0 * (1.0 - s) * (1.0 - s) * q / R2;
  }
  return g;
}

std::optional<CloudReferenceHit> march_cloud_reference(const PointCloud& cloud, double threshold, glm::dvec3 o,
                                                       glm::dvec3 d, double tmin, double tmax, bool inside) {
  const double scale = cloud_support_scale(threshold);
  std::vector<RefSupport> s;
  std::vector<double> breaks;
  ref_supports(cloud, scale, o, d, tmin, tmax, s, breaks);
  const RefRay ray{s, o, d, threshold, inside ? -1.0 : 1.0};
  double gmin;
  const std::optional<double> t = ref_scan(ray, breaks, tmin, tmax, gmin);
  if (!t) return std::nullopt;
  CloudReferenceHit h;
  h.t = *t;
  const glm::dvec3 p = o + h.t * d;
  glm::dvec3 grad(0.0);
  double wsum = 0;
  glm::dvec4 a(0.0);
  for (const RefSupport& r : s) {
    const glm::dvec3 q = p - r.c;
    const double u = glm::dot(q, q) / r.R2;
    if (u >= 1.0) continue;
    const double w = 1.0 - u, k = w * w * w;
    grad += -6.0 * w * w * q / r.R2;
    wsum += k;
    const double temp = cloud.temperature.empty() ? 0.0 : double(cloud.temperature[r.i]);
    const glm::dvec3 col = cloud.color.empty() ? glm::dvec3(0.0) : glm::dvec3(cloud.color[r.i]);
    a += k * glm::dvec4(temp, col);
  }
  h.n = glm::length(grad) > 0 ? -glm::normalize(grad) : glm::dvec3(0.0);
  h.attrs = wsum > 0 ? a / wsum : glm::dvec4(0.0);
  return h;
}

double cloud_ray_extreme_reference(const PointCloud& cloud, double threshold, glm::dvec3 o, glm::dvec3 d,
                                   double tmin, double tmax, bool inside) {
  const double scale = cloud_support_scale(threshold);
  std::vector<RefSupport> s;
  std::vector<double> breaks;
  ref_supports(cloud, scale, o, d, tmin, tmax, s, breaks);
  // A threshold no F reaches (outside) or every F passes (inside): the scan runs to the end.
  const double sgn = inside ? -1.0 : 1.0, far = inside ? -1.0 : 1e30;
  const RefRay ray{s, o, d, far, sgn};
  double gmin;
  ref_scan(ray, breaks, tmin, tmax, gmin);
  return far - sgn * gmin;
}

// ---- the float twin ----
namespace {

glm::vec4 point_texel(const CloudTexels& tx, int i) {
  const float* p = &tx.points[std::size_t(i) * 4];
  return {p[0], p[1], p[2], p[3]};
}

glm::vec4 attr_texel(const CloudTexels& tx, int i) {
  const std::uint16_t* a = &tx.attrs[std::size_t(i) * 4];
  return {glm::unpackHalf1x16(a[0]), glm::unpackHalf1x16(a[1]), glm::unpackHalf1x16(a[2]),
          glm::unpackHalf1x16(a[3])};
}

struct NodeTexels {
  glm::vec4 a, b;  // (lo, index), (hi, count)
};
NodeTexels node_texels(const CloudTexels& tx, int n) {
  const float* p = &tx.nodes[std::size_t(n) * 8];
  return {{p[0], p[1], p[2], p[3]}, {p[4], p[5], p[6], p[7]}};
}

bool in_box(const NodeTexels& nd, glm::vec3 p) {
  return p.x >= nd.a.x && p.y >= nd.a.y && p.z >= nd.a.z && p.x <= nd.b.x && p.y <= nd.b.y && p.z <= nd.b.z;
}

// The entry of o + t d into the box within [tmin, tmax]; INFINITY when it misses.
float box_entry(glm::vec3 lo, glm::vec3 hi, glm::vec3 o, glm::vec3 inv, float tmin, float tmax) {
  const glm::vec3 ta = (lo - o) * inv, tb = (hi - o) * inv;
  const glm::vec3 mn = glm::min(ta, tb), mx = glm::max(ta, tb);
  const float t0 = std::max(std::max(mn.x, mn.y), std::max(mn.z, tmin));
  const float t1 = std::min(std::min(mx.x, mx.y), std::min(mx.z, tmax));
  return t0 <= t1 ? t0 : INFINITY;
}

// A lower bound on F over the segments from a sample point p to two points ahead of it,
// p + reach d (twin: cloud_field_at's `ahead` in march.glsl). Every point of a segment is
// no farther from a centre than the farther of the segment's ends (distance is convex),
// and the kernel falls with distance, so a support that holds p adds at least
// k(max(|p - c|, |end - c|)) everywhere on the segment; supports that do not hold p add
// something or nothing. A march from inside that finds a bound above the threshold cannot
// leave the surface before that end (docs/POINT_CLOUDS.md).
struct CloudAhead {
  glm::vec3 near_end, far_end;  // p + reach d for the two reaches
  float near_bound = 0, far_bound = 0;
};

// One point's share: adds its kernel (and gradient) at p, and to the bounds ahead when
// asked; returns the kernel.
float add_point(glm::vec3 centre, float inv_r2, glm::vec3 p, CloudSample& s, CloudAhead* ahead = nullptr) {
  const glm::vec3 q = p - centre;
  const float u = glm::dot(q, q) * inv_r2;
  if (u >= 1.0f) return 0.0f;
  const float w = 1.0f - u;
  s.f += w * w * w;
  s.grad += (-6.0f * w * w * inv_r2) * q;
  if (ahead) {
    const glm::vec3 qn = ahead->near_end - centre, qf = ahead->far_end - centre;
    const float wn = 1.0f - std::min(std::max(u, glm::dot(qn, qn) * inv_r2), 1.0f);
    const float wf = 1.0f - std::min(std::max(u, glm::dot(qf, qf) * inv_r2), 1.0f);
    ahead->near_bound += wn * wn * wn;
    ahead->far_bound += wf * wf * wf;
  }
  return w * w * w;
}
float add_point(glm::vec4 c, glm::vec3 p, CloudSample& s, CloudAhead* ahead = nullptr) {
  return add_point(glm::vec3(c), 1.0f / (c.w * c.w), p, s, ahead);
}

// The span of o + t d (d unit) in point c's support; false when it misses.
bool support_span(glm::vec4 c, glm::vec3 o, glm::vec3 d, float& t0, float& t1) {
  const glm::vec3 q = o - glm::vec3(c);
  const float b = glm::dot(q, d), disc = b * b - (glm::dot(q, q) - c.w * c.w);
  if (!(disc > 0.0f)) return false;
  const float sq = std::sqrt(disc);
  t0 = -b - sq;
  t1 = -b + sq;
  return true;
}

// Depth first through the tree from `root`, in the shader's order (a node's first child,
// n + 1, before its second): `enter(node)` decides whether to go into a node, `leaf(i)`
// sees each point texel of the leaves entered.
template <class Enter, class Leaf>
void walk_tree(const CloudTexels& tx, int root, Enter enter, Leaf leaf) {
  int stack[kCloudMaxDepth + 1];
  int sp = 0;
  stack[sp++] = root;
  while (sp > 0) {
    const int n = stack[--sp];
    const NodeTexels nd = node_texels(tx, n);
    if (!enter(nd)) continue;
    const int index = int(nd.a.w), count = int(nd.b.w);
    if (count > 0) {
      for (int i = index; i < index + count; ++i) leaf(i);
    } else {
      stack[sp++] = index;
      stack[sp++] = n + 1;
    }
  }
}

// Nearest first through the tree from `root` along o + t d (inv = 1 / d): a node is
// entered while its box's entry, from `from` on, is below `bound()` (which the leaves may
// lower as they go), its nearer child next (the farther pushed first); `leaf(i)` sees each
// point texel of the leaves entered. The shader's ordered nearest-entry traversal.
template <class Bound, class Leaf>
void walk_nearest_first(const CloudTexels& tx, int root, glm::vec3 o, glm::vec3 inv, float from, Bound bound, Leaf leaf) {
  int stack[kCloudMaxDepth + 1];
  float entry[kCloudMaxDepth + 1];
  int sp = 0;
  {
    const NodeTexels r = node_texels(tx, root);
    const float e = box_entry(r.a, r.b, o, inv, from, bound());
    if (e == INFINITY) return;
    stack[sp] = root;
    entry[sp++] = e;
  }
  while (sp > 0) {
    --sp;
    if (!(entry[sp] < bound())) continue;
    const int n = stack[sp];
    const NodeTexels nd = node_texels(tx, n);
    const int index = int(nd.a.w), count = int(nd.b.w);
    if (count > 0) {
      for (int i = index; i < index + count; ++i) leaf(i);
      continue;
    }
    const float lim = bound();
    const NodeTexels l = node_texels(tx, n + 1), r = node_texels(tx, index);
    const float el = box_entry(l.a, l.b, o, inv, from, lim), er = box_entry(r.a, r.b, o, inv, from, lim);
    const bool left_near = el <= er;
    const float e_far = left_near ? er : el, e_near = left_near ? el : er;
    const int far = left_near ? index : n + 1, near = left_near ? n + 1 : index;
    if (e_far < lim) {
      stack[sp] = far;
      entry[sp++] = e_far;
    }
    if (e_near < lim) {
      stack[sp] = near;
      entry[sp++] = e_near;
    }
  }
}

// Each point whose support the segment [a, b] of o + t d (d unit, inv = 1 / d) crosses:
// found(i, t0, t1), its span on the ray.
template <class Found>
void supports_on_segment(const CloudTexels& tx, int root, glm::vec3 o, glm::vec3 d, glm::vec3 inv, float a, float b,
                         Found found) {
  walk_tree(
      tx, root, [&](const NodeTexels& nd) { return box_entry(nd.a, nd.b, o, inv, a, b) != INFINITY; },
      [&](int i) {
        float t0, t1;
        if (support_span(point_texel(tx, i), o, d, t0, t1) && t1 >= a && t0 <= b) found(i, t0, t1);
      });
}

// Queries through the tree (the shader's way).
struct TreeQueries {
  const CloudTexels& tx;
  const CloudRef& c;
  void focus(float, float) const {}
  CloudSample field(glm::vec3 p, float /*t on the march's ray*/, glm::vec4* attrs, CloudAhead* ahead = nullptr) const {
    CloudSample s;
    glm::vec4 a(0.0f);
    walk_tree(
        tx, c.root, [&](const NodeTexels& nd) { return in_box(nd, p); },
        [&](int i) {
          const float k = add_point(point_texel(tx, i), p, s, ahead);
          if (attrs && k > 0.0f) a += k * attr_texel(tx, i);
        });
    if (attrs) *attrs = s.f > 0.0f ? a / s.f : glm::vec4(0.0f);
    return s;
  }
  float next_entry(glm::vec3 o, glm::vec3 d, float tmin, float limit) const {
    float best = limit;
    walk_nearest_first(
        tx, c.root, o, 1.0f / d, tmin, [&] { return best; },
        [&](int i) {
          float t0, t1;
          if (support_span(point_texel(tx, i), o, d, t0, t1) && t1 >= tmin) best = std::min(best, std::max(t0, tmin));
        });
    return best < limit ? best : INFINITY;
  }
};

// Queries along one ray through the tree, in one traversal a ray. The tree is opened in
// the order the ray enters its boxes (the boxes met and not yet opened, sorted by their
// entries, the nearest opened first), only as far along the ray as the march has come;
// the supports of the leaves opened wait in a list, with their spans on the ray, until
// the march has passed them. A step [a, b] opens every box entered before b (a support
// inside a box is entered no earlier than the box), and its samples (its end, a dip, the
// refinements) sum the supports waiting there whose spans overlap the step, in texel
// order: the leaves' depth-first order, the per-sample point query's order (the GLSL
// twin's), so a sample sums the same points in the same order and gets the same value. A
// jump over empty space opens boxes until none left could hold an entry before the
// nearest known one. What is saved is the walks: each node is opened at most once a ray,
// however many steps, jumps and samples the march makes.
class TreeRayQueries {
 public:
  TreeRayQueries(const CloudTexels& t, const CloudRef& r, glm::vec3 o_, glm::vec3 d_)
      : tx(t), c(r), o(o_), d(d_), inv(1.0f / d_), pad(1e-3f * kCloudStepFraction * r.min_support) {
    ahead.clear();
    waiting.clear();
    focused.clear();
    float t0, t1;
    if (box_span(node(c.root), -INFINITY, t0, t1)) push_box(c.root, t0, t1);
  }

  // The samples to come lie in [a, b] (a never less than an earlier step's).
  void focus(float a, float b) const {
    pass(a);
    open_while([&](float entry) { return entry <= b + pad; });
    fa = a;
    fb = b;
    focused.clear();
    for (const Support& s : waiting)
      if (s.t0 <= b + pad) focused.push_back(s);
  }
  CloudSample field(glm::vec3 p, float t, glm::vec4* attrs, CloudAhead* ahead = nullptr) const {
    if (!(t >= fa && t <= fb)) {
      if (!(t - pad >= behind)) return TreeQueries{tx, c}.field(p, t, attrs, ahead);
      focus(t, t);  // (the march's first sample, at the root box)
    }
    CloudSample s;
    glm::vec4 a(0.0f);
    for (const Support& f : focused) {
      const float k = add_point(f.centre, f.inv_r2, p, s, ahead);
      if (attrs && k > 0.0f) a += k * attr_texel(tx, f.i);
    }
    if (attrs) *attrs = s.f > 0.0f ? a / s.f : glm::vec4(0.0f);
    return s;
  }
  // The first support entry at or after tmin below limit (as TreeQueries::next_entry
  // finds it): boxes are opened while one could be entered before the best entry known.
  float next_entry(glm::vec3, glm::vec3, float tmin, float limit) const {
    pass(tmin);
    Nearest best{tmin, limit};
    for (const Support& s : waiting) best.see(s.t0, s.t1);
    // The leaves opened from here on lower it as their supports join, so no support is
    // scanned twice.
    while (!ahead.empty() && ahead.back().entry < best.entry)
      open_nearest([&](float entry) { return entry < best.entry; }, &best);
    return best.entry < limit ? best.entry : INFINITY;
  }

 private:
  struct Box {
    float entry, exit;
    int node;
  };
  struct Support {
    glm::vec3 centre;
    float inv_r2;  // as add_point takes it
    float t0, t1;  // its span on the ray
    int i;         // its texel
  };
  const CloudTexels& tx;
  const CloudRef& c;
  glm::vec3 o, d, inv;
  float pad;  // a thousandth of a step: rounding in the spans cannot drop a support
  mutable float behind = -INFINITY;  // the march has passed every t below this (less pad)
  mutable float fa = INFINITY, fb = -INFINITY;
  // (The three lists live as long as the thread, so that a ray allocates nothing: one
  // TreeRayQueries a thread at a time, as march_cloud makes them.)
  std::vector<Box>& ahead = lists().ahead;          // boxes met, not yet opened, by entry, the nearest last
  std::vector<Support>& waiting = lists().waiting; // supports of the leaves opened, not yet passed, by texel
  std::vector<Support>& focused = lists().focused; // those the current step's samples sum
  struct Lists {
    std::vector<Box> ahead;
    std::vector<Support> waiting, focused;
  };
  static Lists& lists() {
    thread_local Lists l;
    return l;
  }

  const float* node(int n) const { return &tx.nodes[std::size_t(n) * 8]; }
  // The span of the ray in node n's box from `from` on; false when it misses.
  bool box_span(const float* n, float from, float& t0, float& t1) const {
    const float ax = (n[0] - o.x) * inv.x, bx = (n[4] - o.x) * inv.x;
    const float ay = (n[1] - o.y) * inv.y, by = (n[5] - o.y) * inv.y;
    const float az = (n[2] - o.z) * inv.z, bz = (n[6] - o.z) * inv.z;
    t0 = std::max(std::max(std::min(ax, bx), std::min(ay, by)), std::max(std::min(az, bz), from));
    t1 = std::min(std::min(std::max(ax, bx), std::max(ay, by)), std::max(az, bz));
    return t0 <= t1;
  }
  void push_box(int n, float t0, float t1) const {
    // Sorted, the nearest last: a new box is entered no earlier than the one just opened,
    // so it goes in near the end.
    std::size_t k = ahead.size();
    ahead.push_back({t0, t1, n});
    for (; k > 0 && ahead[k - 1].entry < t0; --k) ahead[k] = ahead[k - 1];
    ahead[k] = {t0, t1, n};
  }
  // The march is at t: the supports it has passed leave the list.
  void pass(float t) const {
    if (t - pad > behind) {
      behind = t - pad;
      std::erase_if(waiting, [&](const Support& s) { return s.t1 < behind; });
    }
  }
  // Opens the box the ray enters first: a leaf's supports join the list (in texel order),
  // an inner node's children's boxes the boxes ahead. Boxes the march has passed are dropped.
  // An inner node's nearer child that would come straight back off the list (entered no
  // later than every box ahead, and wanted by go_on) is opened at once instead: the same
  // boxes in the same order, without the list's sorting.
  // The nearest entry at or after `from` of the supports seen (next_entry's jump).
  struct Nearest {
    float from, entry;
    void see(float t0, float t1) {
      if (t1 >= from) entry = std::min(entry, std::max(t0, from));
    }
  };
  // `nearest`, when given, sees each support a leaf adds.
  template <class While>
  void open_nearest(While go_on, Nearest* nearest = nullptr) const {
    Box b = ahead.back();
    ahead.pop_back();
    for (;;) {
      if (b.exit < behind) return;
      const float* n = node(b.node);
      const int index = int(n[3]), count = int(n[7]);
      if (count > 0) {
        for (int i = index; i < index + count; ++i) {
          const glm::vec4 p = point_texel(tx, i);
          float t0, t1;
          if (!support_span(p, o, d, t0, t1) || t1 < behind) continue;
          // In texel order: shifted in from the end by hand (a leaf's texels mostly
          // follow those waiting; vector::insert's memmove cost 7 % of the march).
          const Support s{glm::vec3(p), 1.0f / (p.w * p.w), t0, t1, i};
          if (nearest) nearest->see(t0, t1);
          std::size_t k = waiting.size();
          waiting.push_back(s);
          for (; k > 0 && waiting[k - 1].i > i; --k) waiting[k] = waiting[k - 1];
          waiting[k] = s;
        }
        return;
      }
      float l0, l1, r0, r1;
      const bool l = box_span(node(b.node + 1), behind, l0, l1), r = box_span(node(index), behind, r0, r1);
      // The farther first: the nearer then goes in at the end.
      Box near;
      if (l && r && l0 < r0) {
        push_box(index, r0, r1);
        near = {l0, l1, b.node + 1};
      } else if (l && r) {
        push_box(b.node + 1, l0, l1);
        near = {r0, r1, index};
      } else if (l || r) {
        near = l ? Box{l0, l1, b.node + 1} : Box{r0, r1, index};
      } else {
        return;
      }
      if (!(ahead.empty() || near.entry <= ahead.back().entry) || !go_on(near.entry)) {
        push_box(near.node, near.entry, near.exit);
        return;
      }
      b = near;
    }
  }
  template <class While>
  void open_while(While go_on) const {
    while (!ahead.empty() && go_on(ahead.back().entry)) open_nearest(go_on);
  }
};

// Queries by looping over every point of the cloud (the benchmark's baseline).
struct AllPointQueries {
  const CloudTexels& tx;
  const CloudRange& range;
  void focus(float, float) const {}
  CloudSample field(glm::vec3 p, float /*t on the march's ray*/, glm::vec4* attrs, CloudAhead* ahead = nullptr) const {
    CloudSample s;
    glm::vec4 a(0.0f);
    for (int i = range.first_point; i < range.first_point + range.point_count; ++i) {
      const float k = add_point(point_texel(tx, i), p, s, ahead);
      if (attrs && k > 0.0f) a += k * attr_texel(tx, i);
    }
    if (attrs) *attrs = s.f > 0.0f ? a / s.f : glm::vec4(0.0f);
    return s;
  }
  float next_entry(glm::vec3 o, glm::vec3 d, float tmin, float limit) const {
    float best = limit;
    for (int i = range.first_point; i < range.first_point + range.point_count; ++i) {
      float t0, t1;
      if (support_span(point_texel(tx, i), o, d, t0, t1) && t1 >= tmin) best = std::min(best, std::max(t0, tmin));
    }
    return best < limit ? best : INFINITY;
  }
};

// The minimum of the cubic Hermite interpolant of (g0, m0) at 0 and (g1, m1) at 1 (slopes
// per unit of u, m0 < 0 < m1): its derivative's root by bisection, as u in (0, 1).
float hermite_min(float g0, float m0, float g1, float m1, float& value) {
  const float a = 6.0f * g0 + 3.0f * m0 - 6.0f * g1 + 3.0f * m1, b = -6.0f * g0 - 4.0f * m0 + 6.0f * g1 - 2.0f * m1;
  float lo = 0.0f, hi = 1.0f;
  for (int k = 0; k < 10; ++k) {
    const float u = 0.5f * (lo + hi);
    if ((a * u + b) * u + m0 < 0.0f) lo = u;
    else hi = u;
  }
  const float u = 0.5f * (lo + hi), u2 = u * u, u3 = u2 * u;
  value = (2.0f * u3 - 3.0f * u2 + 1.0f) * g0 + (u3 - 2.0f * u2 + u) * m0 + (-2.0f * u3 + 3.0f * u2) * g1 +
          (u3 - u2) * m1;
  return u;
}

// The crossing lies between t (g > 0 there, slope its derivative; INFINITY, in no support,
// is F = 0 with zero slope) and end (g_end <= 0): the bracket the refinements narrow. One
// helper for a step's and a dip's crossing, as in the GLSL twin.
void cloud_bracket_crossing(float threshold, float t, float g, float slope, float end, float g_end, float slope_end,
                            bool& found, float& a, float& b, float& ga, float& gb, float& sa, float& sb) {
  found = true;
  a = t;
  b = end;
  ga = g == INFINITY ? threshold : g;
  sa = g == INFINITY ? 0.0f : slope;
  gb = g_end;
  sb = slope_end;
}

// A root in (0, 1) of the cubic Hermite interpolant of (g0, m0) at 0 and (g1, m1) at 1
// (g0 > 0 >= g1: one lies between): Newton's steps on the cubic from the secant's root,
// each kept inside the bracket the signs so far leave (else its middle is taken).
float hermite_root(float g0, float m0, float g1, float m1) {
  const float c2 = -3.0f * g0 - 2.0f * m0 + 3.0f * g1 - m1, c3 = 2.0f * g0 + m0 - 2.0f * g1 + m1;
  float lo = 0.0f, hi = 1.0f, u = g0 / (g0 - g1);
  for (int k = 0; k < 10; ++k) {
    const float p = ((c3 * u + c2) * u + m0) * u + g0, dp = (3.0f * c3 * u + 2.0f * c2) * u + m0;
    if (p > 0.0f) lo = u;
    else hi = u;
    const float next = u - p / dp;
    u = next > lo && next < hi ? next : 0.5f * (lo + hi);
  }
  return u;
}

template <class Q>
std::optional<CloudHit> march(const Q& q, const CloudRef& c, glm::vec3 o, glm::vec3 d, float tmin, float tmax,
                              bool inside) {
  if (c.root < 0 || !(c.min_support > 0.0f)) return std::nullopt;
  const glm::vec3 inv = 1.0f / d;
  const glm::vec3 ta = (c.lo - o) * inv, tb = (c.hi - o) * inv;
  const glm::vec3 mn = glm::min(ta, tb), mx = glm::max(ta, tb);
  // Outside the root box F = 0: a march from outside starts at the box, one from inside
  // at tmin (where F < threshold is an exit at once).
  const float t0 = inside ? tmin : std::max(std::max(mn.x, mn.y), std::max(mn.z, tmin));
  const float t1 = std::min(std::min(mx.x, mx.y), std::min(mx.z, tmax));
  if (!inside && !(t0 <= t1)) return std::nullopt;
  const float h = kCloudStepFraction * c.min_support, sgn = inside ? -1.0f : 1.0f;
  // Inside, a step's sample also bounds F from below over a stride and half a stride
  // ahead (CloudAhead): the march strides as far as a bound clears the threshold, since it
  // cannot leave before (no sign change, no dip to look for).
  const float far_reach = float(kCloudStrideSteps) * h, near_reach = 0.5f * far_reach;
  CloudHit hit;
  auto sample = [&](float t, float& slope, float* stride = nullptr) {
    CloudAhead ahead;
    if (stride) ahead.near_end = o + (t + near_reach) * d, ahead.far_end = o + (t + far_reach) * d;
    const CloudSample s = q.field(o + t * d, t, nullptr, stride ? &ahead : nullptr);
    ++hit.queries;
    slope = sgn * -glm::dot(s.grad, d);
    if (stride) {
      const float sure = kCloudStrideMargin * c.threshold;
      *stride = ahead.far_bound > sure ? far_reach : ahead.near_bound > sure ? near_reach : h;
    }
    return s.f == 0.0f && !inside ? INFINITY : sgn * (c.threshold - s.f);  // INFINITY: in no support
  };
  float t = t0, slope, stride = h;  // stride: how far the sample at t lets the march go
  float g = sample(t, slope, inside ? &stride : nullptr);
  bool found = g <= 0.0f;
  float a = t, b = t, ga = 0.0f, gb = 0.0f, sa = 0.0f, sb = 0.0f;
  for (int i = 0; i < kCloudMaxSteps && !found; ++i) {
    ++hit.steps;
    if (g == INFINITY) {
      // In no support: nothing can cross before the next support's entry, where F = 0
      // with zero slope (the kernel is C2 where it ends).
      const float te = q.next_entry(o, d, t, t1);
      ++hit.queries;
      if (te == INFINITY) return std::nullopt;
      t = std::max(t, te);
      g = c.threshold;
      slope = 0.0f;
    }
    const float next = std::min(t + stride, t1);
    q.focus(t, next);  // this step's samples lie in [t, next]
    float sn, stride_next = h;
    float gn = sample(next, sn, inside ? &stride_next : nullptr);
    const float gv = gn == INFINITY ? c.threshold : gn;
    if (gv <= 0.0f) {
      cloud_bracket_crossing(c.threshold, t, g, slope, next, gv, sn, found, a, b, ga, gb, sa, sb);
    } else if (stride == h && slope < 0.0f && sn > 0.0f) {
      // A dip between the samples: where the Hermite cubic says it comes within a tenth of
      // the threshold, look at its bottom.
      float predicted;
      const float u = hermite_min(g, slope * (next - t), gv, sn * (next - t), predicted);
      if (predicted < 0.1f * c.threshold) {
        const float tm = t + u * (next - t);
        float sm;
        const float gm = sample(tm, sm);
        if (gm <= 0.0f) cloud_bracket_crossing(c.threshold, t, g, slope, tm, gm, sm, found, a, b, ga, gb, sa, sb);
      }
    }
    if (found) {
      // The first samples halve the bracket (a shrink the cubic alone does not promise);
      // the rest go where the cubic through its ends (values and slopes) crosses the
      // level, kept off the ends.
      for (int k = 0; k < kCloudRefinements; ++k) {
        const float u = k < kCloudBisections
                            ? 0.5f
                            : std::clamp(hermite_root(ga, sa * (b - a), gb, sb * (b - a)), 1.0f / 64.0f, 63.0f / 64.0f);
        const float m = a + u * (b - a);
        float sm;
        const float gm = sample(m, sm);
        if (gm <= 0.0f) b = m, gb = gm, sb = sm;
        else a = m, ga = gm, sa = sm;
      }
      break;
    }
    if (next >= t1) return std::nullopt;
    t = next;
    g = gn;
    slope = sn;
    stride = stride_next;
  }
  if (!found && !inside) return std::nullopt;
  if (!found) {
    // Out of steps inside (a long chord through a dense blob; on llvmpipe, out of its loop
    // budget): the path leaves where it is, straight on, rather than being lost inside.
    hit.t = t;
    glm::vec4 attrs;
    q.field(o + hit.t * d, hit.t, &attrs);
    hit.n = -d;
    hit.attrs = attrs;
    return hit;
  }
  // The crossing where the cubic through the narrowed bracket's ends meets the level
  // (within 0.3 um of the double reference's at worst in the tests, most far closer). A
  // path crossing here marches on from 2 um beyond, well on the side it believes it is on
  // (a path starting on the wrong side would cross back at once).
  hit.t = a + (b - a) * hermite_root(ga, sa * (b - a), gb, sb * (b - a));
  glm::vec4 attrs;
  const CloudSample s = q.field(o + hit.t * d, hit.t, &attrs);
  ++hit.queries;
  hit.n = glm::length(s.grad) > 0.0f ? -glm::normalize(s.grad) : glm::vec3(0.0f);
  hit.attrs = attrs;
  return hit;
}

}  // namespace

CloudRef cloud_ref(const CloudRange& r, float threshold) { return {r.root, threshold, r.min_support, r.lo, r.hi}; }

CloudSample cloud_field(const CloudTexels& tx, const CloudRef& c, glm::vec3 p) {
  if (c.root < 0) return {};
  return TreeQueries{tx, c}.field(p, 0.0f, nullptr);
}

glm::vec4 cloud_attrs(const CloudTexels& tx, const CloudRef& c, glm::vec3 p) {
  if (c.root < 0) return glm::vec4(0.0f);
  glm::vec4 a;
  TreeQueries{tx, c}.field(p, 0.0f, &a);
  return a;
}

float cloud_next_entry(const CloudTexels& tx, const CloudRef& c, glm::vec3 o, glm::vec3 d, float tmin, float limit) {
  if (c.root < 0) return INFINITY;
  return TreeQueries{tx, c}.next_entry(o, d, tmin, limit);
}

std::vector<int> cloud_supports_crossed(const CloudTexels& tx, const CloudRef& c, glm::vec3 o, glm::vec3 d,
                                        float tmin, float tmax) {
  std::vector<int> out;
  if (c.root < 0) return out;
  supports_on_segment(tx, c.root, o, d, 1.0f / d, tmin, tmax, [&](int i, float, float) { out.push_back(i); });
  return out;
}

std::optional<CloudHit> march_cloud(const CloudTexels& tx, const CloudRef& c, glm::vec3 o, glm::vec3 d, float tmin,
                                    float tmax, bool inside) {
  return march(TreeRayQueries{tx, c, o, d}, c, o, d, tmin, tmax, inside);
}

std::optional<CloudHit> march_cloud_all_points(const CloudTexels& tx, const CloudRef& c, const CloudRange& range,
                                               glm::vec3 o, glm::vec3 d, float tmin, float tmax, bool inside) {
  return march(AllPointQueries{tx, range}, c, o, d, tmin, tmax, inside);
}

}  // namespace draught
