// Analytic intersections with the vessel: frustum segments of the outer and inner
// wall, the rim torus, the base disks. Mirrors core/intersect.cpp (the reference).

float outer_radius(float y) {
  float s = clamp(y * u_vessel.w, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  return mix(u_knots[k].x, u_knots[k + 1].x, s - float(k));
}

float inner_radius(float y) {
  float s = clamp(y * u_vessel.w, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  return mix(u_knots[k].y, u_knots[k + 1].y, s - float(k));
}

bool inside_torus(float r, float y) {
  vec2 q = vec2(r - u_rim.x, y - u_vessel.x);
  return dot(q, q) < u_rim.y * u_rim.y;
}

bool inside_body(float r, float y) {
  if (y < 0.0 || y > u_vessel.x || r > outer_radius(y)) return false;
  return y < u_vessel.y || r >= inner_radius(y);
}

// Slab ylo..yhi and cylinder r <= rad along the ray, as [t0, t1].
bool clip_to_bounds(vec3 o, vec3 d, float ylo, float yhi, float rad, float tmin, out vec2 tr) {
  tr = vec2(tmin, INF);
  if (abs(d.y) < 1e-9) {
    if (o.y < ylo || o.y > yhi) return false;
  } else {
    float a = (ylo - o.y) / d.y, b = (yhi - o.y) / d.y;
    tr.x = max(tr.x, min(a, b));
    tr.y = min(tr.y, max(a, b));
  }
  float A = dot(d.xz, d.xz), B = dot(o.xz, d.xz), C = dot(o.xz, o.xz) - rad * rad;
  if (A < 1e-12) {
    if (C > 0.0) return false;
  } else {
    float disc = B * B - A * C;
    if (disc < 0.0) return false;
    float s = sqrt(disc);
    tr.x = max(tr.x, (-B - s) / A);
    tr.y = min(tr.y, (-B + s) / A);
  }
  return tr.x <= tr.y;
}

// Real roots of a x^2 + b x + c, ascending (numerically stable form).
int solve_quadratic(float a, float b, float c, out vec2 x) {
  x = vec2(INF);
  if (abs(a) < 1e-20) {
    if (abs(b) < 1e-20) return 0;
    x = vec2(-c / b, INF);
    return 1;
  }
  float disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 0;
  float sq = sqrt(disc);
  float q = -0.5 * (b + (b >= 0.0 ? sq : -sq));
  float x0 = q / a, x1 = q != 0.0 ? c / q : x0;
  x = vec2(min(x0, x1), max(x0, x1));
  return 2;
}

// Walks the frustum segments the ray crosses, in the order it crosses them, and
// returns the first valid hit (segments partition y and y(t) is monotonic).
Hit hit_wall(vec3 o, vec3 d, bool inner, float tmin) {
  float ylo = inner ? u_vessel.y : 0.0, yhi = u_vessel.x;
  vec2 tr;
  if (!clip_to_bounds(o, d, ylo, yhi, u_rim.z, tmin, tr)) return no_hit();
  int k0 = clamp(int(floor((o.y + tr.x * d.y) * u_vessel.w)), 0, SEGMENTS - 1);
  int k1 = clamp(int(floor((o.y + tr.y * d.y) * u_vessel.w)), 0, SEGMENTS - 1);
  int stp = k1 >= k0 ? 1 : -1;
  int count = abs(k1 - k0) + 1;
  float A0 = dot(d.xz, d.xz), B0 = dot(o.xz, d.xz), C0 = dot(o.xz, o.xz);
  int k = k0;
  for (int i = 0; i < count; ++i, k += stp) {
    ++g_cost;
    float r0 = inner ? u_knots[k].y : u_knots[k].x;
    float r1 = inner ? u_knots[k + 1].y : u_knots[k + 1].x;
    float y0 = float(k) * u_vessel.z, y1 = y0 + u_vessel.z;
    float s = (r1 - r0) * u_vessel.w;
    float c0 = r0 + s * (o.y - y0), c1 = s * d.y;
    vec2 ts;
    int n = solve_quadratic(A0 - c1 * c1, 2.0 * (B0 - c0 * c1), C0 - c0 * c0, ts);
    for (int j = 0; j < 2; ++j) {
      if (j >= n) break;
      float t = ts[j];
      vec3 p = o + t * d;
      if (t <= tmin || p.y < y0 || p.y > y1 || c0 + c1 * t < 0.0) continue;
      if (p.y < ylo || p.y > yhi) continue;
      float r = length(p.xz);
      if (inside_torus(r, p.y) || clipped(p)) continue;
      vec3 nrm = r > 0.0 ? normalize(vec3(p.x / r, -s, p.z / r)) : vec3(0.0, -1.0, 0.0);
      return Hit(t, inner ? -nrm : nrm, inner ? M_GLASS_INNER : M_GLASS_OUTER);
    }
  }
  return no_hit();
}

// Real roots of x^3 + a x^2 + b x + c: returns the largest.
float cubic_largest_root(float a, float b, float c) {
  float Q = (a * a - 3.0 * b) / 9.0, R = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
  float Q3 = Q * Q * Q;
  if (R * R < Q3) {
    float th = acos(clamp(R / sqrt(Q3), -1.0, 1.0));
    float sq = -2.0 * sqrt(Q);
    return max(max(sq * cos(th / 3.0), sq * cos((th + 2.0 * PI) / 3.0)), sq * cos((th - 2.0 * PI) / 3.0)) -
           a / 3.0;
  }
  float A = -sign(R) * pow(abs(R) + sqrt(R * R - Q3), 1.0 / 3.0);
  float B = A != 0.0 ? Q / A : 0.0;
  return A + B - a / 3.0;
}

// Real roots of x^4 + b x^3 + c x^2 + d x + e (Ferrari), Newton-polished; unsorted,
// missing roots are INF.
vec4 solve_quartic(float b, float c, float d, float e) {
  float b2 = b * b;
  float p = c - 3.0 * b2 / 8.0;
  float q = d - b * c / 2.0 + b2 * b / 8.0;
  float r = e - b * d / 4.0 + b2 * c / 16.0 - 3.0 * b2 * b2 / 256.0;
  vec4 roots = vec4(INF);
  vec2 x;
  // Near q = 0 Ferrari's m -> 0 and q / sqrt(m) is noise: solve the biquadratic instead
  // and let the Newton polish restore q (as core/intersect.cpp).
  float scale = max(1.0, max(abs(p), sqrt(abs(r))));
  float m = abs(q) > 1e-7 * scale * sqrt(scale) ? cubic_largest_root(p, p * p / 4.0 - r, -q * q / 8.0) : 0.0;
  if (m <= 1e-6 * scale) {
    int k = solve_quadratic(1.0, p, r, x);
    if (k > 0 && x.x >= 0.0) roots.xy = vec2(sqrt(x.x), -sqrt(x.x));
    if (k > 1 && x.y >= 0.0) roots.zw = vec2(sqrt(x.y), -sqrt(x.y));
  } else {
    float s = sqrt(2.0 * m);
    if (solve_quadratic(1.0, -s, p / 2.0 + m + q / (2.0 * s), x) > 0) roots.xy = x;
    if (solve_quadratic(1.0, s, p / 2.0 + m - q / (2.0 * s), x) > 0) roots.zw = x;
  }
  for (int i = 0; i < 4; ++i) {
    if (roots[i] >= INF) continue;
    float z = roots[i] - b / 4.0;
    for (int it = 0; it < 2; ++it) {
      float f = (((z + b) * z + c) * z + d) * z + e;
      float df = ((4.0 * z + 3.0 * b) * z + 2.0 * c) * z + d;
      if (df != 0.0) z -= f / df;
    }
    roots[i] = z;
  }
  return roots;
}

// The rim bead: a torus around the axis at the wall top; only where it is outside the body.
Hit hit_rim(vec3 o, vec3 d, float tmin) {
  float R = u_rim.x, rr = u_rim.y, H = u_vessel.x;
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
    if ((p.y < H && inside_body(pr, p.y)) || clipped(p)) continue;
    vec3 c = pr > 0.0 ? vec3(p.x / pr * R, H, p.z / pr * R) : vec3(0.0, H, 0.0);
    best = Hit(t, normalize(p - c), M_RIM);
  }
  return best;
}

Hit hit_disk(vec3 o, vec3 d, float y, float rad, float tmin, vec3 n, int m) {
  if (abs(d.y) < 1e-12) return no_hit();
  float t = (y - o.y) / d.y;
  vec3 p = o + t * d;
  if (t <= tmin || dot(p.xz, p.xz) > rad * rad || clipped(p)) return no_hit();
  return Hit(t, n, m);
}

// The liquid surface: a plane whose offset keeps the volume (from the fill table, looked
// up once per frame in the vertex shader, fill_table.glsl), plus the slosh waves.
flat in float v_liquid_offset;
float g_liquid_offset = -1.0;  // set once per pixel by init_liquid()

void init_liquid() { g_liquid_offset = v_liquid_offset; }

// The renderer compiles this shader twice: with SURFACE_WAVES 1 for a moving surface and
// 0 for a still one, which then carries no wave code at all (software rasterizers pay
// for code even where a branch skips it; still drinks are the common case).
#ifndef SURFACE_WAVES
#define SURFACE_WAVES 0
#endif

// Beyond 1.25 radii the shapes hold their value there (as core/slosh.cpp).
float wave_height(vec2 xz) {
  vec2 q = xz / u_waves.w;
  float u2 = dot(q, q);
  if (u2 > 1.5625) {
    q *= 1.25 / sqrt(u2);
    u2 = 1.5625;
  }
  return u_waves.x * (1.0 - 3.0 * u2 + 1.5 * u2 * u2) + u_waves.y * (q.x * q.x - q.y * q.y) + u_waves.z * 2.0 * q.x * q.y;
}

vec2 wave_gradient(vec2 xz) {
  vec2 q = xz / u_waves.w;
  float len = length(q);
  bool held = len > 1.25;  // chain rule through the pull-in (as core/slosh.cpp)
  vec2 c = held ? q * (1.25 / len) : q;
  float dr = u_waves.x * (-6.0 + 6.0 * dot(c, c));
  vec2 g = vec2(dr * c.x + 2.0 * u_waves.y * c.x + 2.0 * u_waves.z * c.y,
                dr * c.y - 2.0 * u_waves.y * c.y + 2.0 * u_waves.z * c.x);
  if (held) {
    vec2 dir = q / len;
    g = (1.25 / len) * (g - dir * dot(dir, g));
  }
  return g / u_waves.w;
}

// Signed height of p over the surface: negative in the liquid.
float liquid_level(vec3 p) {
  float level = dot(u_liquid_plane.xyz, p) - g_liquid_offset;
#if SURFACE_WAVES
  level -= wave_height(p.xz);
#endif
  return level;
}

Hit hit_liquid_surface(vec3 o, vec3 d, float tmin) {
  if (u_liquid.w < 0.5) return no_hit();
  vec3 n = u_liquid_plane.xyz;
  float dn = dot(n, d);
  if (abs(dn) < 1e-12) return no_hit();
  float t = (g_liquid_offset - dot(n, o)) / dn;
#if SURFACE_WAVES
  for (int it = 0; it < 4; ++it) {  // Newton steps from the plane onto the waves
    vec3 p = o + t * d;
    vec2 g = wave_gradient(p.xz);
    float slope = dn - dot(g, d.xz);
    if (abs(slope) < 1e-12) break;
    t -= liquid_level(p) / slope;
  }
#endif
  vec3 p = o + t * d;
  if (t <= tmin || p.y <= u_vessel.y || p.y >= u_vessel.x || length(p.xz) >= inner_radius(p.y) || clipped(p))
    return no_hit();
#if SURFACE_WAVES
  vec2 g = wave_gradient(p.xz);
  return Hit(t, normalize(n - vec3(g.x, 0.0, g.y)), M_LIQUID_SURFACE);
#else
  return Hit(t, n, M_LIQUID_SURFACE);
#endif
}

// The floor is world y = 0: in the glass's frame a plane through the foot's contact.
Hit hit_floor(vec3 o, vec3 d, float tmin) {
  if (u_env.w < 0.5) return no_hit();
  vec3 up = to_local_dir(vec3(0.0, 1.0, 0.0));
  float dn = dot(up, d);
  if (dn >= 0.0) return no_hit();
  float t = (-u_pose_pos.y - dot(up, o)) / dn;
  vec3 p = o + t * d;
  // Where the glass stands on the floor, its foot is the surface.
  if (t <= tmin || (abs(p.y) < 1e-5 && length(p.xz) <= u_rim.w)) return no_hit();
  return Hit(t, up, M_FLOOR);
}

// The cut face of the cross-section, where the plane passes through glass or liquid.
// Its normal points out of what is kept, like every glass surface's.
Hit hit_clip_cap(vec3 o, vec3 d, float tmin) {
  float dn = dot(u_clip.xyz, d);
  if (abs(dn) < 1e-12) return no_hit();
  float t = (u_clip.w - dot(u_clip.xyz, o)) / dn;
  if (t <= tmin) return no_hit();
  vec3 p = o + t * d;
  float r = length(p.xz);
  if (inside_body(r, p.y) || inside_torus(r, p.y)) return Hit(t, u_clip.xyz, M_CLIP_GLASS);
  bool in_cavity = p.y > u_vessel.y && p.y < u_vessel.x && r < inner_radius(p.y);
  if (in_cavity && u_liquid.w > 0.5 && dot(u_liquid_plane.xyz, p) < g_liquid_offset) return Hit(t, u_clip.xyz, M_CLIP_LIQUID);
  return no_hit();
}

void keep_nearest(inout Hit best, Hit h) {
  if (h.t < best.t) best = h;
}

// The nearest surface from inside the given medium: only surfaces that bound it.
Hit scene_hit(vec3 o, vec3 d, int medium, float tmin) {
  Hit best = no_hit();
  if (medium != LIQUID) {
    keep_nearest(best, hit_wall(o, d, false, tmin));
    keep_nearest(best, hit_rim(o, d, tmin));
    keep_nearest(best, hit_disk(o, d, 0.0, u_rim.w, tmin, vec3(0.0, -1.0, 0.0), M_GLASS_BOTTOM));
  }
  keep_nearest(best, hit_wall(o, d, true, tmin));
  keep_nearest(best, hit_disk(o, d, u_vessel.y, u_glass.z, tmin, vec3(0.0, 1.0, 0.0), M_CAVITY_FLOOR));
  if (medium != GLASS) keep_nearest(best, hit_liquid_surface(o, d, tmin));
  if (medium == AIR) keep_nearest(best, hit_floor(o, d, tmin));
  if (dot(u_clip.xyz, u_clip.xyz) > 0.5) keep_nearest(best, hit_clip_cap(o, d, tmin));  // a cross-section
  return best;
}
