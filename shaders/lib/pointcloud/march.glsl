// A point cloud's surface, F = sum (1 - |p - c|^2 / R^2)^3 = threshold over the points
// whose support holds p, marched through the cloud's BVH in the data textures u_cloud_points,
// u_cloud_attrs, u_cloud_nodes (src/interface/objects.def, gpu/cloud_textures). GLSL twin
// of core/pointcloud/field.cpp's float march (the same function names and steps;
// tests/gpu/test_cloud_march.cpp compares them). docs/POINT_CLOUDS.md.
#ifndef LIB_POINTCLOUD_MARCH_GLSL
#define LIB_POINTCLOUD_MARCH_GLSL
#include "generated/constants.glsl"
#include "generated/objects.glsl"
#include "lib/common/math.glsl"

// One cloud of the shared textures (core: CloudRef, filled from its CloudRange).
struct CloudRef {
  int root;           // its root node; < 0: empty
  float threshold;    // the surface's level of F
  float min_support;  // its smallest support radius (m): the step's scale
  vec3 lo;            // its root box (m, world)
  vec3 hi;
};

ivec2 cloud_texel(int i) { return ivec2(i % CLOUD_TEXTURE_WIDTH, i / CLOUD_TEXTURE_WIDTH); }
vec4 cloud_point(int i) { return texelFetch(u_cloud_points, cloud_texel(i), 0); }
vec4 cloud_attr(int i) { return texelFetch(u_cloud_attrs, cloud_texel(i), 0); }
// A node's two texels: (lo, index), (hi, count); both in one row (the width is even).
void cloud_node(int n, out vec4 a, out vec4 b) {
  a = texelFetch(u_cloud_nodes, cloud_texel(2 * n), 0);
  b = texelFetch(u_cloud_nodes, cloud_texel(2 * n + 1), 0);
}

// Twin of box_entry: the entry into [lo, hi] within [tmin, tmax]; INF when it misses.
float cloud_box_entry(vec3 lo, vec3 hi, vec3 o, vec3 inv, float tmin, float tmax) {
  vec3 ta = (lo - o) * inv, tb = (hi - o) * inv;
  vec3 mn = min(ta, tb), mx = max(ta, tb);
  float t0 = max(max(mn.x, mn.y), max(mn.z, tmin)), t1 = min(min(mx.x, mx.y), min(mx.z, tmax));
  return t0 <= t1 ? t0 : INF;
}

// Twin of TreeQueries::field: F (w) and grad F (xyz) at p; with_attrs also returns the
// k-weighted temperature and colour; with_ahead also the lower bounds on F over the
// segments from p to near_end and to far_end (twin: CloudAhead in field.cpp, which says
// why they hold).
vec4 cloud_field_ahead(CloudRef c, vec3 p, bool with_attrs, out vec4 attrs, bool with_ahead, vec3 near_end,
                       vec3 far_end, out vec2 bounds) {
  float f = 0.0;
  vec3 grad = vec3(0.0);
  vec4 acc = vec4(0.0);
  bounds = vec2(0.0);
  int stack[CLOUD_MAX_DEPTH + 1];
  int sp = 0;
  stack[sp++] = c.root;
  while (sp > 0) {
    int n = stack[--sp];
    vec4 a, b;
    cloud_node(n, a, b);
    if (any(lessThan(p, a.xyz)) || any(greaterThan(p, b.xyz))) continue;
    int index = int(a.w), count = int(b.w);
    if (count > 0) {
      // A leaf's points in a loop of constant count, which the compiler unrolls: llvmpipe
      // counts every iteration of every loop of a pixel against one budget of 65535.
      // (CloudTexels::append refuses a tree with larger leaves.)
      for (int j = 0; j < CLOUD_LEAF_SIZE; ++j) {
        if (j >= count) continue;
        int i = index + j;
        vec4 pt = cloud_point(i);
        vec3 q = p - pt.xyz;
        float inv_r2 = 1.0 / (pt.w * pt.w), u = dot(q, q) * inv_r2;
        if (u >= 1.0) continue;
        float w = 1.0 - u, k = w * w * w;
        f += k;
        grad += (-6.0 * w * w * inv_r2) * q;
        if (with_attrs) acc += k * cloud_attr(i);
        if (with_ahead) {
          vec3 qn = near_end - pt.xyz, qf = far_end - pt.xyz;
          vec2 wa = 1.0 - min(max(vec2(u), vec2(dot(qn, qn), dot(qf, qf)) * inv_r2), 1.0);
          bounds += wa * wa * wa;
        }
      }
    } else {
      stack[sp++] = index;
      stack[sp++] = n + 1;
    }
  }
  attrs = f > 0.0 ? acc / f : vec4(0.0);
  return vec4(grad, f);
}
vec4 cloud_field_at(CloudRef c, vec3 p, bool with_attrs, out vec4 attrs) {
  vec2 unused;
  return cloud_field_ahead(c, p, with_attrs, attrs, false, p, p, unused);
}

// Twin of TreeQueries::next_entry: the smallest t >= tmin below limit where o + t d is
// in a support (ordered: the nearer child first, boxes beyond the best pruned); INF: none.
float cloud_next_entry(CloudRef c, vec3 o, vec3 d, float tmin, float limit) {
  vec3 inv = 1.0 / d;
  float best = limit;
  int stack[CLOUD_MAX_DEPTH + 1];
  float entry[CLOUD_MAX_DEPTH + 1];
  int sp = 0;
  vec4 a, b;
  cloud_node(c.root, a, b);
  float e0 = cloud_box_entry(a.xyz, b.xyz, o, inv, tmin, best);
  if (e0 == INF) return INF;
  stack[0] = c.root;
  entry[0] = e0;
  sp = 1;
  while (sp > 0) {
    --sp;
    if (!(entry[sp] < best)) continue;
    int n = stack[sp];
    cloud_node(n, a, b);
    int index = int(a.w), count = int(b.w);
    if (count > 0) {
      for (int j = 0; j < CLOUD_LEAF_SIZE; ++j) {  // (unrolled, as above)
        if (j >= count) continue;
        vec4 pt = cloud_point(index + j);
        vec3 q = o - pt.xyz;
        float bq = dot(q, d), disc = bq * bq - (dot(q, q) - pt.w * pt.w);
        if (!(disc > 0.0)) continue;
        float sq = sqrt(disc), t0 = -bq - sq, t1 = -bq + sq;
        if (t1 >= tmin) best = min(best, max(t0, tmin));
      }
      continue;
    }
    vec4 la, lb, ra, rb;
    cloud_node(n + 1, la, lb);
    cloud_node(index, ra, rb);
    float el = cloud_box_entry(la.xyz, lb.xyz, o, inv, tmin, best);
    float er = cloud_box_entry(ra.xyz, rb.xyz, o, inv, tmin, best);
    bool left_near = el <= er;
    float e_far = left_near ? er : el, e_near = left_near ? el : er;
    int far_node = left_near ? index : n + 1, near_node = left_near ? n + 1 : index;
    if (e_far < best) {
      stack[sp] = far_node;
      entry[sp++] = e_far;
    }
    if (e_near < best) {
      stack[sp] = near_node;
      entry[sp++] = e_near;
    }
  }
  return best < limit ? best : INF;
}

// Twin of hermite_min: the minimum of the cubic Hermite interpolant on [0, 1] of (g0, m0)
// and (g1, m1), m0 < 0 < m1; returns u, its value in `value`.
float cloud_hermite_min(float g0, float m0, float g1, float m1, out float value) {
  float a = 6.0 * g0 + 3.0 * m0 - 6.0 * g1 + 3.0 * m1, b = -6.0 * g0 - 4.0 * m0 + 6.0 * g1 - 2.0 * m1;
  float lo = 0.0, hi = 1.0;
  for (int k = 0; k < 10; ++k) {
    float u = 0.5 * (lo + hi);
    if ((a * u + b) * u + m0 < 0.0) lo = u;
    else hi = u;
  }
  float u = 0.5 * (lo + hi), u2 = u * u, u3 = u2 * u;
  value = (2.0 * u3 - 3.0 * u2 + 1.0) * g0 + (u3 - 2.0 * u2 + u) * m0 + (-2.0 * u3 + 3.0 * u2) * g1 + (u3 - u2) * m1;
  return u;
}

// sgn (threshold - F) at o + t d and its slope; INF where no support holds the point
// (outside only). With `ahead` (a step's end inside), also how far the march may stride
// from there: the stride (far_reach) or half of it where the lower bound over it clears
// the threshold, else one step h (twin: march's `sample` with a stride in field.cpp).
float cloud_g_stride(CloudRef c, vec3 o, vec3 d, float t, float sgn, bool inside, bool ahead, float h,
                     float far_reach, out float slope, out float stride) {
  vec4 unused;
  vec2 bounds;
  vec4 s = cloud_field_ahead(c, o + t * d, false, unused, ahead, o + (t + 0.5 * far_reach) * d, o + (t + far_reach) * d,
                             bounds);
  slope = sgn * -dot(s.xyz, d);
  float sure = CLOUD_STRIDE_MARGIN * c.threshold;
  stride = !ahead ? h : bounds.y > sure ? far_reach : bounds.x > sure ? 0.5 * far_reach : h;
  return s.w == 0.0 && !inside ? INF : sgn * (c.threshold - s.w);
}
float cloud_g(CloudRef c, vec3 o, vec3 d, float t, float sgn, bool inside, out float slope) {
  float unused;
  return cloud_g_stride(c, o, d, t, sgn, inside, false, 0.0, 0.0, slope, unused);
}

// Twin of field.cpp's cloud_bracket_crossing: the crossing lies between t (g > 0 there,
// slope its derivative; INF, in no support, is F = 0 with zero slope) and end
// (g_end <= 0), the bracket the refinements narrow.
void cloud_bracket_crossing(float threshold, float t, float g, float slope, float end, float g_end, float slope_end,
                            out bool found, out float a, out float b, out float ga, out float gb, out float sa,
                            out float sb) {
  found = true;
  a = t;
  b = end;
  ga = g == INF ? threshold : g;
  sa = g == INF ? 0.0 : slope;
  gb = g_end;
  sb = slope_end;
}

// Twin of hermite_root: a root in (0, 1) of the cubic Hermite interpolant of (g0, m0) at 0
// and (g1, m1) at 1 (g0 > 0 >= g1): Newton's steps from the secant's root, each kept
// inside the bracket the signs so far leave (else its middle is taken).
float cloud_hermite_root(float g0, float m0, float g1, float m1) {
  float c2 = -3.0 * g0 - 2.0 * m0 + 3.0 * g1 - m1, c3 = 2.0 * g0 + m0 - 2.0 * g1 + m1;
  float lo = 0.0, hi = 1.0, u = g0 / (g0 - g1);
  for (int k = 0; k < 10; ++k) {
    float p = ((c3 * u + c2) * u + m0) * u + g0, dp = (3.0 * c3 * u + 2.0 * c2) * u + m0;
    if (p > 0.0) lo = u;
    else hi = u;
    float next = u - p / dp;
    u = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return u;
}

// Twin of march_cloud: the first crossing of F = threshold along o + t d (d unit), t in
// [tmin, tmax], from outside or (inside) the exit; its normal normalize(-grad F) and the
// k-weighted (temperature, r, g, b).
bool march_cloud(CloudRef c, vec3 o, vec3 d, float tmin, float tmax, bool inside, out float t_hit, out vec3 n,
                 out vec4 attrs) {
  t_hit = INF;
  n = vec3(0.0);
  attrs = vec4(0.0);
  if (c.root < 0 || !(c.min_support > 0.0)) return false;
  vec3 inv = 1.0 / d;
  vec3 ta = (c.lo - o) * inv, tb = (c.hi - o) * inv;
  vec3 mn = min(ta, tb), mx = max(ta, tb);
  float t0 = inside ? tmin : max(max(mn.x, mn.y), max(mn.z, tmin));
  float t1 = min(min(mx.x, mx.y), min(mx.z, tmax));
  if (!inside && !(t0 <= t1)) return false;
  float h = CLOUD_STEP_FRACTION * c.min_support, sgn = inside ? -1.0 : 1.0;
  float far_reach = float(CLOUD_STRIDE_STEPS) * h;
  float t = t0, slope, stride;  // stride: how far the sample at t lets the march go
  float g = cloud_g_stride(c, o, d, t, sgn, inside, inside, h, far_reach, slope, stride);
  bool found = g <= 0.0;
  float a = t, b = t, ga = 0.0, gb = 0.0, sa = 0.0, sb = 0.0;
  for (int i = 0; i < CLOUD_MAX_STEPS; ++i) {
    if (found) break;
    if (g == INF) {
      float te = cloud_next_entry(c, o, d, t, t1);
      if (te == INF) return false;
      t = max(t, te);
      g = c.threshold;
      slope = 0.0;
    }
    float next = min(t + stride, t1), sn, stride_next;
    float gn = cloud_g_stride(c, o, d, next, sgn, inside, inside, h, far_reach, sn, stride_next);
    float gv = gn == INF ? c.threshold : gn;
    if (gv <= 0.0) {
      cloud_bracket_crossing(c.threshold, t, g, slope, next, gv, sn, found, a, b, ga, gb, sa, sb);
    } else if (stride == h && slope < 0.0 && sn > 0.0) {
      float predicted;
      float u = cloud_hermite_min(g, slope * (next - t), gv, sn * (next - t), predicted);
      if (predicted < 0.1 * c.threshold) {
        float tm = t + u * (next - t), sm;
        float gm = cloud_g(c, o, d, tm, sgn, inside, sm);
        if (gm <= 0.0) cloud_bracket_crossing(c.threshold, t, g, slope, tm, gm, sm, found, a, b, ga, gb, sa, sb);
      }
    }
    if (found) {
      for (int k = 0; k < CLOUD_REFINEMENTS; ++k) {  // (twin: field.cpp says why)
        float u = 0.5;  // (k is the same in every pixel: the halvings skip the cubic's root)
        if (k >= CLOUD_BISECTIONS) u = clamp(cloud_hermite_root(ga, sa * (b - a), gb, sb * (b - a)), 1.0 / 64.0, 63.0 / 64.0);
        float m = a + u * (b - a), sm;
        float gm = cloud_g(c, o, d, m, sgn, inside, sm);
        if (gm <= 0.0) {
          b = m;
          gb = gm;
          sb = sm;
        } else {
          a = m;
          ga = gm;
          sa = sm;
        }
      }
      break;
    }
    if (next >= t1) return false;
    t = next;
    g = gn;
    slope = sn;
    stride = stride_next;
  }
  if (!found && !inside) return false;
  if (!found) {  // out of steps (or of llvmpipe's loop budget) inside: leave straight on (twin: field.cpp)
    t_hit = t;
    cloud_field_at(c, o + t * d, true, attrs);
    n = -d;
    return true;
  }
  // The cubic through the narrowed bracket's ends meets the level (twin: field.cpp says why).
  t_hit = a + (b - a) * cloud_hermite_root(ga, sa * (b - a), gb, sb * (b - a));
  vec4 s = cloud_field_at(c, o + t_hit * d, true, attrs);
  n = length(s.xyz) > 0.0 ? -normalize(s.xyz) : vec3(0.0);
  return true;
}

#endif  // LIB_POINTCLOUD_MARCH_GLSL
