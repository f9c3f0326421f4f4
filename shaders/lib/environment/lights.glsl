// The studio's area lights in the picture: the rig of at most MAX_LIGHTS rects
// (softboxes, front side only) and spheres in frame.light_*. Twins of
// core/environment/lights.cpp (AreaLight::intersect, AreaLight::irradiance_factor) and
// what a ray sees of them (lights_seen). Lights are emitters only: they cast no shadow.
#ifndef LIB_ENVIRONMENT_LIGHTS_GLSL
#define LIB_ENVIRONMENT_LIGHTS_GLSL
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/screen.glsl"

struct AreaLight {
  bool sphere;
  vec3 center, normal, half_u, half_v;
  float radius;
  vec3 radiance;
  vec3 extent;  // a rect's |half_u|, |half_v| and area (core computes them once per frame)
  bool camera_visible;  // seen by the camera's own rays (frame.light_half_v w)
};

// The renderer compiles the sphere lights' code in only for a rig that has one
// (gpu/renderer.cpp): llvmpipe would run it for every light a pixel tests.
#ifndef SPHERE_LIGHTS
#define SPHERE_LIGHTS 0
#endif

// The rig, read from the Frame block once per pixel (init_lights, first in main) and held:
// on llvmpipe a uniform block's member costs a load and a broadcast to every lane at each
// read, and the lights are read by every look at the surroundings.
AreaLight g_lights[MAX_LIGHTS];
int g_light_count;  // lights in use (frame.light_count)

void init_lights() {
  g_light_count = frame.light_count;
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    vec4 c = frame.light_center[i], n = frame.light_normal[i];
    g_lights[i] = AreaLight(SPHERE_LIGHTS != 0 && n.w > 0.5, c.xyz, n.xyz, frame.light_half_u[i].xyz,
                            frame.light_half_v[i].xyz, c.w, frame.light_radiance[i].rgb, frame.light_extent[i].xyz,
                            frame.light_half_v[i].w > 0.5);
  }
}

AreaLight area_light(int i) { return g_lights[i]; }

// The nearer t > tmin where a ray meets a sphere from outside it.
bool light_hit_sphere(vec3 c, float r, vec3 o, vec3 d, float tmin, out float t) {
  vec3 oc = o - c;
  float b = dot(oc, d), cc = dot(oc, oc) - r * r;
  t = INF;
  if (cc <= 0.0) return false;  // inside: a lamp is not seen from within
  float disc = b * b - cc;
  if (disc < 0.0) return false;
  t = -b - sqrt(disc);
  return t > tmin;
}

// The nearest t > tmin where the ray o + t d (d unit) meets the light's emitting side.
// Twin of AreaLight::intersect.
bool intersect(AreaLight l, vec3 o, vec3 d, float tmin, out float t) {
  if (l.sphere) return light_hit_sphere(l.center, l.radius, o, d, tmin, t);
  t = INF;
  float denom = dot(d, l.normal);
  if (denom >= 0.0) return false;  // parallel, or its back
  t = dot(l.center - o, l.normal) / denom;
  if (!(t > tmin)) return false;
  vec3 q = o + t * d - l.center;
  return abs(dot(q, l.half_u)) <= dot(l.half_u, l.half_u) && abs(dot(q, l.half_v)) <= dot(l.half_v, l.half_v);
}

// Lambert's term of one edge a -> b (unit vectors) of a polygon seen from the origin:
// the angle theta it subtends times the cosine of its plane's normal with n, as
// dot(n, a x b) theta / sin(theta). theta / sin(theta) by Heitz et al.'s rational fit
// (LTC, 2016: relative error 1.5e-6 below theta = 3.1), no arc tangent: the backdrop
// evaluates this for every light at every pixel.
float lambert_edge(vec3 a, vec3 b, vec3 n) {
  float x = dot(a, b), y = abs(x);
  float v = (0.8543985 + (0.4965155 + 0.0145206 * y) * y) / (3.4175940 + (4.1616724 + y) * y);
  float theta_sin = x > 0.0 ? v : 0.5 * inversesqrt(max(1.0 - x * x, 1e-7)) - v;  // theta / (2 pi sin theta)
  return 2.0 * PI * theta_sin * dot(n, cross(a, b));
}

// Edge a -> b (unit, heights ha, hb over the surface's plane) of the polygon clipped to
// the surface's upper half (Sutherland-Hodgman, streamed: a convex polygon leaves the
// half-space once, at `leave`, and comes back once, at `enter`). A point of the chord
// between two unit vectors lies on their great circle, so the crossing is found on the
// chord and normalised.
void clipped_edge(vec3 a, vec3 b, float ha, float hb, vec3 n, inout float sum, inout vec3 leave, inout vec3 enter) {
  if (ha >= 0.0 && hb >= 0.0) {
    sum += lambert_edge(a, b, n);
  } else if (ha >= 0.0 || hb >= 0.0) {
    vec3 q = normalize(a + (b - a) * (ha / (ha - hb)));
    if (ha >= 0.0) {
      sum += lambert_edge(a, q, n);
      leave = q;
    } else {
      sum += lambert_edge(q, b, n);
      enter = q;
    }
  }
}

// The irradiance the whole light gives point x of a surface of unit normal n, per unit
// radiance, with nothing in between (pi times the form factor): a rect's polygon clipped
// to the surface's hemisphere (Lambert), a sphere by Snyder's formula, the horizon
// included. Zero behind a rect. Twin of AreaLight::irradiance_factor.
// A sphere of unit radiance (centre c, radius r) by Snyder's formula, the horizon
// included. Twin of sphere_irradiance_factor in core/environment/lights.
float sphere_irradiance_factor(vec3 c, float r, vec3 x, vec3 n) {
  vec3 w = c - x;
  float d2 = dot(w, w);
  if (d2 <= r * r) return PI;
  float sin2 = r * r / d2, cos_t = dot(n, w) * inversesqrt(d2);
  if (cos_t * cos_t > sin2) return PI * sin2 * max(cos_t, 0.0);
  float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
  float xx = sqrt(1.0 / sin2 - 1.0);
  float y = clamp(-xx * cos_t / max(sin_t, 1e-12), -1.0, 1.0);
  float s = sin_t * sqrt(1.0 - y * y);
  return max(0.0, (cos_t * acos(y) - xx * s) * sin2 + atan(s / xx));
}

float irradiance_factor(AreaLight l, vec3 x, vec3 n) {
  if (l.sphere) return sphere_irradiance_factor(l.center, l.radius, x, n);
  if (dot(x - l.center, l.normal) <= 0.0) return 0.0;  // behind the softbox
  vec3 c0 = normalize(l.center - l.half_u - l.half_v - x), c1 = normalize(l.center + l.half_u - l.half_v - x);
  vec3 c2 = normalize(l.center + l.half_u + l.half_v - x), c3 = normalize(l.center - l.half_u + l.half_v - x);
  vec4 h = vec4(dot(n, c0), dot(n, c1), dot(n, c2), dot(n, c3));
  if (all(lessThan(h, vec4(0.0)))) return 0.0;  // wholly below the horizon
  float sum = 0.0;
  vec3 leave = vec3(0.0), enter = vec3(0.0);
  clipped_edge(c0, c1, h.x, h.y, n, sum, leave, enter);
  clipped_edge(c1, c2, h.y, h.z, n, sum, leave, enter);
  clipped_edge(c2, c3, h.z, h.w, n, sum, leave, enter);
  clipped_edge(c3, c0, h.w, h.x, n, sum, leave, enter);
  if (any(lessThan(h, vec4(0.0)))) sum += lambert_edge(leave, enter, n);  // along the horizon
  return 0.5 * abs(sum);
}

// The irradiance factor of a light seen as a point at its centre: its solid angle (area
// over distance squared, foreshortened) times the cosine at x, for the backdrop a glass
// mirrors (a few per cent of a pixel: the exact polygon would cost the most there).
float irradiance_factor_far(AreaLight l, vec3 x, vec3 n) {
  vec3 w = l.center - x;
  float d2 = dot(w, w), inv = inversesqrt(d2);
  float cos_s = max(dot(n, w) * inv, 0.0);
  if (l.sphere) return PI * l.radius * l.radius / max(d2, l.radius * l.radius) * cos_s;
  return l.extent.z * max(-dot(l.normal, w) * inv, 0.0) * cos_s / d2;
}

// The irradiance the first `count` lights of the rig give x (normal n) with nothing in
// between: radiance x irradiance_factor summed. The whole rig (count = frame.light_count)
// is the twin of core LightRig::irradiance. A count, not a branch around the call:
// llvmpipe runs both sides of a branch for every pixel, but leaves a loop as soon as all
// its pixels have, so a count of 0 costs nothing.
vec3 rig_irradiance(vec3 x, vec3 n, int count) {
  vec3 e = vec3(0.0);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= count) break;
    AreaLight l = area_light(i);
    e += l.radiance * irradiance_factor(l, x, n);
  }
  return e;
}

// The same with each light taken as a point (irradiance_factor_far).
vec3 rig_irradiance_far(vec3 x, vec3 n, int count) {
  vec3 e = vec3(0.0);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= count) break;
    AreaLight l = area_light(i);
    e += l.radiance * irradiance_factor_far(l, x, n);
  }
  return e;
}

// How much of a box [-1, 1] at coordinate s is seen with its edge spread over +-w
// (symmetric about the edge, so the box's area is kept).
float soft_box(float s, float w) { return 1.0 - smoothstep(1.0 - w, 1.0 + w, abs(s)); }

// The nearest light front (or the screen card's) the ray o + t d (d unit) meets before t_max: rgb its radiance,
// a the part of the pixel's ray it covers (its edges spread by the GGX roughness of the
// surface that sent the ray, symmetrically so its solid angle and its light are kept; a
// hair at least, against aliasing). t: where, INF for none. Behind a partly covering
// front the caller sees what lies beyond it with 1 - a. `camera`: the ray is the camera's
// own (no surface met yet), which passes the lights kept out of the shot (camera_visible
// false; the reference's Tracer::nearest_light does the same).
vec4 lights_seen(vec3 o, vec3 d, float roughness, float t_max, bool camera, out float t) {
  t = INF;
  vec4 seen = vec4(0.0);
  float a = roughness * roughness;  // GGX alpha: the reflected lobe is about 2 alpha wide
  float spread = max(0.0015, 2.0 * a);  // radians either side of an edge
  // Every light is tested whole, with no bounds first and no early way out: llvmpipe
  // runs all of it for every pixel anyway, so each test more is only more work.
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    AreaLight l = area_light(i);
    vec3 w = l.center - o;
    float ti, cover;
    bool front;
    if (l.sphere) {
      float d2 = dot(w, w);
      ti = dot(w, d);
      float sin2 = l.radius * l.radius / d2, cos_r = sqrt(max(1.0 - sin2, 0.0));
      float edge = min(spread * sqrt(sin2), 1.0 - cos_r);
      cover = smoothstep(cos_r - edge, cos_r + edge, ti * inversesqrt(d2));
      front = d2 > l.radius * l.radius && ti > 0.0;  // (a lamp is not seen from within)
      ti -= l.radius;
    } else {
      float denom = dot(d, l.normal);
      ti = dot(w, l.normal) / denom;
      vec3 q = ti * d - w;
      float lu = l.extent.x, lv = l.extent.y;
      cover = soft_box(dot(q, l.half_u) / (lu * lu), spread * ti / lu) *
              soft_box(dot(q, l.half_v) / (lv * lv), spread * ti / lv);
      front = denom < 0.0 && ti > 0.0;  // its emitting side, ahead
    }
    if (i < g_light_count && (l.camera_visible || !camera) && front && cover > 0.0 && ti < t && ti < t_max) {
      t = ti;
      seen = vec4(l.radiance, cover);
    }
  }
#if defined(SCREEN) && SCREEN == 1
  seen = screen_with_light(seen, o, d, roughness, t_max, t);  // the screen card, a front like a light's
#endif
  return seen;
}

// What a ray from o sees of the surroundings without the backdrop (from inside a glass
// or a drink, where the way out is not traced): a light's front, else the sky.
vec3 lights_and_sky(vec3 o, vec3 d, float roughness) {
#if defined(SCREEN) && SCREEN == 2
  return sky_seen(d, roughness);  // the AR view: the rig's lights show only in outer reflections
#endif
  float tl;
  vec4 light = lights_seen(o, d, roughness, INF, false, tl);
  return light.rgb * light.a + sky_seen(d, roughness) * (1.0 - light.a);
}

#endif  // LIB_ENVIRONMENT_LIGHTS_GLSL
