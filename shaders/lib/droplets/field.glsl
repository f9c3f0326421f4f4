// The droplet field: spheres blended by a smooth minimum, displaced by value noise, and
// the march that finds its surface. GLSL twin of core/droplets/field.cpp (the same
// function names, in float; tests/gpu/test_droplets.cpp probes them against it). The
// spheres and parameters are the frame's (frame.droplet_*, gpu/scene_data.cpp);
// compiled only into frames with droplets (DROPLETS).
#ifndef LIB_DROPLETS_FIELD_GLSL
#define LIB_DROPLETS_FIELD_GLSL
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/common/noise.glsl"

const float DROPLET_SKIM = 4.0 * DROPLET_HIT_EPS;  // core: kDropletSkim
const float DROPLET_RELAX = 1.6;                   // core: kDropletRelax
const int DROPLET_REFINEMENTS = 3;                 // core: kDropletRefinements
// Samples of one march at most: the start, two a step, the refinements.
const int DROPLET_MAX_SAMPLES = 2 * DROPLET_MAX_STEPS + DROPLET_REFINEMENTS + 1;

// Twin of droplet_smin: the quadratic smooth minimum and the weight of a in its gradient.
float droplet_smin(float a, float b, float k, out float wa) {
  if (!(k > 0.0)) {
    wa = a <= b ? 1.0 : 0.0;
    return min(a, b);
  }
  float h = max(k - abs(a - b), 0.0) / k;
  wa = a < b ? 1.0 - 0.5 * h : 0.5 * h;
  return min(a, b) - 0.25 * k * h * h;
}

// Twin of droplet_exp_width.
float droplet_exp_width(float k) { return k / (4.0 * log(2.0)); }

// Twin of droplet_noise: value noise in [0, 1] (hash13 at the corners) and its gradient.
vec4 droplet_noise(vec3 x) {
  vec3 i = floor(x), f = x - i;
  vec3 u = f * f * (3.0 - 2.0 * f), du = 6.0 * f * (1.0 - f);
  float a000 = hash13(i), a100 = hash13(i + vec3(1, 0, 0)), a010 = hash13(i + vec3(0, 1, 0));
  float a110 = hash13(i + vec3(1, 1, 0)), a001 = hash13(i + vec3(0, 0, 1)), a101 = hash13(i + vec3(1, 0, 1));
  float a011 = hash13(i + vec3(0, 1, 1)), a111 = hash13(i + vec3(1, 1, 1));
  float k1 = a100 - a000, k2 = a010 - a000, k3 = a001 - a000;
  float k4 = a000 - a100 - a010 + a110, k5 = a000 - a010 - a001 + a011, k6 = a000 - a100 - a001 + a101;
  float k7 = -a000 + a100 + a010 - a110 + a001 - a101 - a011 + a111;
  float n = a000 + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z + k6 * u.z * u.x + k7 * u.x * u.y * u.z;
  vec3 g = du * vec3(k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z, k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x,
                     k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y);
  return vec4(n, g);
}

// A sphere's distance and its gradient.
float droplet_sphere(int i, vec3 p, out vec3 g) {
  vec4 s = frame.droplet_spheres[i];
  vec3 q = p - s.xyz;
  float len = length(q);
  g = len > 0.0 ? q / len : vec3(0.0, 1.0, 0.0);
  return len - s.w;
}

// Twin of droplet_field_parts: (value, gradient) at p, and in blend the spheres' blend
// before the noise (1-Lipschitz: where it exceeds A no surface lies within blend - A).
vec4 droplet_field_parts(vec3 p, out float blend) {
  float d;
  vec3 grad;
  if (frame.droplet_kernel == 1) {
    float m = INF;
    vec3 g;
    for (int i = 0; i < MAX_DROPLETS; ++i)
      if (i < frame.droplet_count) m = min(m, droplet_sphere(i, p, g));
    float w = droplet_exp_width(frame.droplet_blend), sum = 0.0;
    grad = vec3(0.0);
    for (int i = 0; i < MAX_DROPLETS; ++i) {
      if (i >= frame.droplet_count) break;
      float di = droplet_sphere(i, p, g);
      float e = w > 0.0 ? exp(-(di - m) / w) : (di == m ? 1.0 : 0.0);
      sum += e;
      grad += e * g;
    }
    d = w > 0.0 ? m - w * log(sum) : m;
    grad /= sum;
  } else {
    d = droplet_sphere(0, p, grad);
    for (int i = 1; i < MAX_DROPLETS; ++i) {
      if (i >= frame.droplet_count) break;
      vec3 g;
      float di = droplet_sphere(i, p, g), wa;
      d = droplet_smin(d, di, frame.droplet_blend, wa);
      grad = wa * grad + (1.0 - wa) * g;
    }
  }
  blend = d;
  if (frame.droplet_noise_amplitude > 0.0) {
    vec4 nz = droplet_noise(p * frame.droplet_noise_frequency);
    d += frame.droplet_noise_amplitude * (2.0 * nz.x - 1.0);
    grad += 2.0 * frame.droplet_noise_amplitude * frame.droplet_noise_frequency * nz.yzw;
  }
  return vec4(d, grad);
}

// Twin of droplet_field: (value, gradient) at p.
vec4 droplet_field(vec3 p) {
  float blend;
  return droplet_field_parts(p, blend);
}

float droplet_value(vec3 p) { return droplet_field(p).x; }

// Twin of droplet_sphere_span: the part of [t0, t1] along o + t d (d of unit length)
// from where it first enters one of the spheres grown by frame.droplet_margin (the
// field's reach and the box's skim margin, from core) to where it last leaves one. The surface lies within them, so a
// march may start and end there: a line through the gaps of a stretched trail, which its
// box holds, marches nothing.
bool droplet_sphere_span(vec3 o, vec3 d, inout float t0, inout float t1) {
  float grow = frame.droplet_margin, s0 = INF, s1 = -INF;
  for (int i = 0; i < MAX_DROPLETS; ++i) {
    if (i >= frame.droplet_count) break;
    vec4 s = frame.droplet_spheres[i];
    float r = s.w + grow;
    vec3 q = o - s.xyz;
    float b = dot(q, d), disc = b * b - (dot(q, q) - r * r);
    if (r > 0.0 && disc >= 0.0) {
      float h = sqrt(disc);
      s0 = min(s0, -b - h);
      s1 = max(s1, -b + h);
    }
  }
  t0 = max(t0, s0);
  t1 = min(t1, s1);
  return t0 <= t1;
}

// Twin of march_droplets: the first crossing along o + t d in [tmin, tmax], from outside
// (inside false) or from within a droplet; the same samples as the reference, in the
// same order. One field sample per iteration of a single loop (the start, a relaxed step,
// its fallback, a skim, each Illinois step narrowing a crossing): llvmpipe and SwiftShader
// run a loop's body under a mask for every pixel of a SIMD group while any of them needs
// it, and code behind an untaken branch too, so a march whose step sampled twice and held
// its sixteen bisections in a loop of their own cost a SIMD group about eighteen samples
// for every step any of its pixels took (docs/PERFORMANCE.md, "Droplets").
const int DROPLET_MODE_START = 0, DROPLET_MODE_RELAXED = 1, DROPLET_MODE_STEP = 2, DROPLET_MODE_REFINE = 3;
bool march_droplets(vec3 o, vec3 d, float tmin, float tmax, bool inside, out float t_hit, out vec3 n) {
  t_hit = INF;
  n = vec3(0.0);
  vec3 inv = 1.0 / d;
  vec3 ta = (frame.droplet_bound_lo - o) * inv, tb = (frame.droplet_bound_hi - o) * inv;
  vec3 lo = min(ta, tb), hi = max(ta, tb);
  float t0 = max(max(lo.x, lo.y), max(lo.z, tmin)), t1 = min(min(hi.x, hi.y), min(hi.z, tmax));
  bool spans = t0 <= t1 && droplet_sphere_span(o, d, t0, t1);
  float L = frame.droplet_lipschitz, A = frame.droplet_noise_amplitude, sgn = inside ? -1.0 : 1.0;
  // t: the march's point (value >= 0 there, gradient gt), r: the radius free of the
  // surface around it; x: the next sample; e: the far end of a bracket being refined, wt
  // and we the values its line uses (halved at an end kept twice in a row), kept the end
  // kept last (+1 t, -1 e).
  float t = t0, r = 0.0, x = t0, e = t0, vt = 0.0, ve = 0.0, wt = 0.0, we = 0.0;
  vec3 gt = vec3(0.0), ge = vec3(0.0);
  int mode = DROPLET_MODE_START, count = 0, kept = 0;
  bool going = spans, hit = false, plain = false;
  for (int i = 0; i < DROPLET_MAX_SAMPLES; ++i) {
    if (!going) break;
    float blend;
    vec4 f = droplet_field_parts(o + x * d, blend);
    float v = sgn * f.x, rx = max(v / L, sgn * blend - A);
    if (mode == DROPLET_MODE_REFINE) {
      ++count;
      if (v < 0.0) {
        e = x;
        ve = v;
        we = v;
        ge = f.yzw;
        if (kept > 0) wt *= 0.5;
        kept = 1;
      } else {
        t = x;
        vt = v;
        wt = v;
        gt = f.yzw;
        if (kept < 0) we *= 0.5;
        kept = -1;
      }
      if (count == DROPLET_REFINEMENTS) {
        hit = true;
        going = false;
        float w = vt / (vt - ve);
        t_hit = t + (e - t) * w;
        n = mix(gt, ge, w);
      } else {
        x = t + (e - t) * (wt / (wt - we));
      }
    } else {
      bool crossed = v < 0.0;
      // A relaxed step is kept where it did not land inside and the free spheres at
      // both ends overlap; else the safe step from t is sampled next.
      if (mode == DROPLET_MODE_RELAXED && (crossed || r + rx < x - t)) {
        x = t + r;
        mode = DROPLET_MODE_STEP;
        plain = true;  // and the step after it a safe one without a try
      } else if (mode == DROPLET_MODE_START && crossed) {
        hit = true;  // starts on the surface (within rounding)
        going = false;
        t_hit = x;
        n = f.yzw;
      } else if (x > t1) {
        going = false;
      } else if (crossed) {
        e = x;
        ve = v;
        we = v;
        wt = vt;
        kept = 0;
        ge = f.yzw;
        x = t + (e - t) * (wt / (wt - we));
        mode = DROPLET_MODE_REFINE;
        count = 0;
      } else if (count == DROPLET_MAX_STEPS) {
        going = false;
      } else {
        // Advance to x and plan the next step: a skim where the value is below eps, else
        // the relaxed step (the safe one after a failed try).
        t = x;
        vt = v;
        gt = f.yzw;
        r = rx;
        bool skim = v < DROPLET_HIT_EPS, relaxed = !skim && !plain;
        x = skim ? t + DROPLET_SKIM : t + (relaxed ? DROPLET_RELAX : 1.0) * r;
        mode = relaxed ? DROPLET_MODE_RELAXED : DROPLET_MODE_STEP;
        plain = false;
        ++count;
      }
    }
  }
  if (hit) n = normalize(n);
  return hit;
}

#endif  // LIB_DROPLETS_FIELD_GLSL
