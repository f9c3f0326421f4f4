// Analytic intersections with a vessel (lib/scene/objects.glsl), in its local
// frame: frustum segments of the outer and inner wall, the rim torus, the base disks.
// Twin of core/reference/intersect.cpp (hit_wall, hit_rim, hit_disk), which the GPU
// probes compare with pixel by pixel.
#ifndef LIB_VESSEL_INTERSECT_GLSL
#define LIB_VESSEL_INTERSECT_GLSL
#include "lib/common/math.glsl"
#include "lib/scene/objects.glsl"

// Texel k of the vessel's knot row: (r_outer[k], r_inner[k], r_outer[k + 1], r_inner[k + 1]).
vec4 segment_knots(Vessel v, int k) { return texelFetch(u_knots, ivec2(k, v.shape.knot_row), 0); }

float outer_radius(Vessel v, float y) {
  float s = clamp(y * v.shape.inv_dy, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  vec4 kn = segment_knots(v, k);
  return mix(kn.x, kn.z, s - float(k));
}

float inner_radius(Vessel v, float y) {
  float s = clamp(y * v.shape.inv_dy, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  vec4 kn = segment_knots(v, k);
  return mix(kn.y, kn.w, s - float(k));
}

bool inside_torus(Vessel v, float r, float y) {
  vec2 q = vec2(r - v.shape.rim_major, y - v.body.height);
  return dot(q, q) < v.shape.rim_minor * v.shape.rim_minor;
}

bool inside_body(Vessel v, float r, float y) {
  float s = clamp(y * v.shape.inv_dy, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  vec4 kn = segment_knots(v, k);  // one fetch for both walls
  vec2 radii = mix(kn.xy, kn.zw, s - float(k));  // outer, inner
  return y >= 0.0 && y <= v.body.height && r <= radii.x && (y < v.shape.base || r >= radii.y);
}

// Slab ylo..yhi and cylinder r <= rad along the ray, as [t0, t1]: the vessel's axis is
// y, so this is cylinder_span (lib/scene/objects.glsl) about that axis, from tmin.
bool clip_to_bounds(vec3 o, vec3 d, float ylo, float yhi, float rad, float tmin, out vec2 tr) {
  if (!cylinder_span(o, d, vec3(0.0, ylo, 0.0), vec3(0.0, 1.0, 0.0), rad, yhi - ylo, tr)) return false;
  tr.x = max(tr.x, tmin);
  return tr.x <= tr.y;
}

// The wall's slope dr/dy at fraction f of segment k, for its normal: each knot's slope is
// the mean of the two segments it joins (a crease, normals more than acos(CREASE_COS)
// apart, keeps each segment's own), interpolated along the segment, so normals are
// continuous along a curved bowl (no contour bands) on the exact frustum. Twin of
// Vessel::wall_slope (core/vessel/vessel.cpp). Only the hit pays the two extra fetches.
float knot_slope(float other, float own) {
  float c = (1.0 + other * own) * inversesqrt((1.0 + other * other) * (1.0 + own * own));
  return c >= CREASE_COS ? 0.5 * (other + own) : own;
}
float wall_slope(Vessel v, int k, float f, bool inner) {
  vec4 here = segment_knots(v, k), lo = segment_knots(v, max(k - 1, 0)), hi = segment_knots(v, min(k + 1, SEGMENTS - 1));
  vec3 rise = inner ? vec3(lo.w - lo.y, here.w - here.y, hi.w - hi.y) : vec3(lo.z - lo.x, here.z - here.x, hi.z - hi.x);
  vec3 s = rise * v.shape.inv_dy;
  float below = k > 0 ? knot_slope(s.x, s.y) : s.y;
  float above = k < SEGMENTS - 1 ? knot_slope(s.z, s.y) : s.y;
  return mix(below, above, clamp(f, 0.0, 1.0));
}

// Walks the frustum segments the ray crosses, in the order it crosses them, and
// returns the first valid hit (segments partition y and y(t) is monotonic).
Hit hit_wall(Vessel v, vec3 o, vec3 d, bool inner, float tmin) {
  float ylo = inner ? v.shape.base : 0.0, yhi = v.body.height;
  vec2 tr;
  if (!clip_to_bounds(o, d, ylo, yhi, v.bounds.bound_radius, tmin, tr)) return no_hit();
  int k0 = clamp(int(floor((o.y + tr.x * d.y) * v.shape.inv_dy)), 0, SEGMENTS - 1);
  int k1 = clamp(int(floor((o.y + tr.y * d.y) * v.shape.inv_dy)), 0, SEGMENTS - 1);
  int stp = k1 >= k0 ? 1 : -1;
  int count = abs(k1 - k0) + 1;
  // Solved from where the ray enters the vessel's bounds, t = tr.x + u (as hit_rim is),
  // not from its origin: from the camera a metre away the coefficients are ~1 m^2 and
  // cancel down to the glass's ~1e-3 m^2, which left the hit up to 4e-5 m off the wall
  // (measured), more than the next search's tmin (2e-6 m): the path met the same wall
  // again or went on from beyond it, and the flight was speckled with dark pixels
  // (tests/gpu/test_speckle.cpp). From the bounds the round-off is the glass's size's,
  // wherever the camera stands.
  vec3 ob = o + tr.x * d;
  float A0 = dot(d.xz, d.xz), B0 = dot(ob.xz, d.xz), C0 = dot(ob.xz, ob.xz);
  // A hit on the boundary between two segments must not slip through the crack that
  // float round-off opens there: each segment reaches a hair (1e-4 of its height) into
  // its neighbours; adjacent cones meet at the shared knot, so the surface is the same.
  float crack = 1e-4 * v.shape.dy;
  int k = k0, hit_k = -1;
  float hit_u = INF;
  for (int i = 0; i < count && hit_k < 0; ++i, k += stp) {
    ++g_cost;
    vec4 kn = segment_knots(v, k);
    float r0 = inner ? kn.y : kn.x;
    float r1 = inner ? kn.w : kn.z;
    float y0 = float(k) * v.shape.dy, y1 = y0 + v.shape.dy;
    float s = (r1 - r0) * v.shape.inv_dy;
    float c0 = r0 + s * (ob.y - y0), c1 = s * d.y;
    vec2 ts;
    int n = solve_quadratic(A0 - c1 * c1, 2.0 * (B0 - c0 * c1), C0 - c0 * c0, ts);
    for (int j = 0; j < 2; ++j) {
      if (j >= n) break;
      float u = ts[j];
      vec3 p = ob + u * d;
      if (tr.x + u <= tmin || p.y < y0 - crack || p.y > y1 + crack || c0 + c1 * u < 0.0) continue;
      if (p.y < ylo || p.y > yhi) continue;
      float r = length(p.xz);
      if (inside_torus(v, r, p.y) || clipped(v, p)) continue;
      hit_u = u;
      hit_k = k;
      break;
    }
  }
  if (hit_k < 0) return no_hit();
  // The normal once, after the walk (llvmpipe pays for all of a loop's body each trip).
  vec3 p = ob + hit_u * d;
  float r = length(p.xz);
  float slope = wall_slope(v, hit_k, p.y * v.shape.inv_dy - float(hit_k), inner);
  vec3 nrm = r > 0.0 ? normalize(vec3(p.x / r, -slope, p.z / r)) : vec3(0.0, -1.0, 0.0);
  return Hit(tr.x + hit_u, inner ? -nrm : nrm, inner ? M_GLASS_INNER : M_GLASS_OUTER, v.row);
}

// The rim bead: a torus around the axis at the wall top; only where it is outside the body.
Hit hit_rim(Vessel v, vec3 o, vec3 d, float tmin) {
  float R = v.shape.rim_major, rr = v.shape.rim_minor, H = v.body.height;
  vec2 tr;
  if (!clip_to_bounds(o, d, H - rr, H + rr, R + rr, tmin, tr)) return no_hit();
  // Solve from the bound entry, in units of the major radius (keeps floats well scaled).
  ++g_cost;
  vec3 lo = (o + tr.x * d - vec3(0.0, H, 0.0)) / R;
  float r = rr / R;
  float m = dot(lo, lo), nn = dot(lo, d), K = m + 1.0 - r * r;
  vec4 ts = solve_quartic(4.0 * nn, 4.0 * nn * nn + 2.0 * K - 4.0 * (1.0 - d.y * d.y),
                          4.0 * nn * K - 8.0 * (nn - lo.y * d.y), K * K - 4.0 * (m - lo.y * lo.y));
  Hit best = no_hit();
  for (int i = 0; i < 4; ++i) {
    if (ts[i] >= INF) continue;
    float t = tr.x + ts[i] * R;
    if (t <= tmin || t >= best.t) continue;
    vec3 p = o + t * d;
    float pr = length(p.xz);
    if ((p.y < H && inside_body(v, pr, p.y)) || clipped(v, p)) continue;
    vec3 c = pr > 0.0 ? vec3(p.x / pr * R, H, p.z / pr * R) : vec3(0.0, H, 0.0);
    best = Hit(t, normalize(p - c), M_RIM, v.row);
  }
  return best;
}

Hit hit_disk(Vessel v, vec3 o, vec3 d, float y, float rad, float tmin, vec3 n, int m) {
  if (abs(d.y) < 1e-12) return no_hit();
  float t = (y - o.y) / d.y;
  vec3 p = o + t * d;
  if (t <= tmin || dot(p.xz, p.xz) > rad * rad || clipped(v, p)) return no_hit();
  return Hit(t, n, m, v.row);
}

#endif  // LIB_VESSEL_INTERSECT_GLSL
