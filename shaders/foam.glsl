// The foam head: a volume on the liquid surface up to the head's top (core/foam.hpp),
// marched only along the stretch of a ray inside it. Beer's-law opacity per step,
// Henyey-Greenstein single scattering of the key light plus multi-scatter terms at
// halved optical depth, self-shadowing from the distance light travels through the
// head (no shadow rays), micro-bubble detail from value noise, big bubbles as voids
// with a denser ring around them, and lacing rings left on the glass.

// Compiled in only for frames with a head (gpu/renderer.cpp builds the variants).
#ifndef FOAM_HEAD
#define FOAM_HEAD 0
#endif


// The head's thickness above the liquid at (x, z): domed or concave.
float foam_thickness_at(vec2 xz) {
  float u2 = min(dot(xz, xz) / (u_waves.w * u_waves.w), 1.5);
  return u_foam.x * max(1.0 + u_foam.y * (1.0 - 2.0 * u2), 0.1);
}


float hash13(vec3 p) {
  p = fract(p * 0.1031);
  p += dot(p, p.zyx + 31.32);
  return fract((p.x + p.y) * p.z);
}

float value_noise(vec3 x) {
  vec3 i = floor(x), f = fract(x);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(hash13(i), hash13(i + vec3(1, 0, 0)), f.x), mix(hash13(i + vec3(0, 1, 0)), hash13(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(hash13(i + vec3(0, 0, 1)), hash13(i + vec3(1, 0, 1)), f.x), mix(hash13(i + vec3(0, 1, 1)), hash13(i + vec3(1, 1, 1)), f.x), f.y),
             f.z);
}

// Extinction at p; `height` is p's height above the liquid, `top` the head's thickness there.
float foam_density(vec3 p, float height, float top) {
  if (height < 0.0 || height > top || p.y > u_vessel.x || length(p.xz) > inner_radius(p.y) || clipped(p)) return 0.0;
  // Bubbles are bigger low in the head (they coarsen as liquid drains out of it).
  float scale = u_foam_detail.y * (1.0 + 1.5 * (1.0 - height / top));
  float d = u_foam.z * max(1.0 + 1.6 * u_foam_detail.z * (value_noise(p / scale) - 0.5), 0.0);
  d *= clamp((top - height) / (0.12 * top), 0.0, 1.0);  // a soft top, a crisp underside
  for (int i = 0; i < int(u_foam_detail.w); ++i) {
    float r = abs(u_bubbles[i].w), dist = length(p - u_bubbles[i].xyz);
    if (dist < r) return 0.0;  // inside a big bubble, or the void a popped one left
    float ring = (dist - r) / (0.45 * r);
    d *= 1.0 + (u_bubbles[i].w < 0.0 ? 0.6 : 1.8) * exp(-ring * ring);
  }
  return d;
}

float hg_phase(float c, float g) {
  float g2 = g * g;
  return (1.0 - g2) / (4.0 * PI * pow(max(1.0 + g2 - 2.0 * g * c, 1e-4), 1.5));
}

// Light scattered towards -d at p (per unit scattering), self-shadowed analytically by
// the foam between p and the outside: through the head's top (depth below it) or
// through the glass wall beside it (side), whichever is shorter.
vec3 foam_light(vec3 d, vec3 l, float depth, float side) {
  vec3 n = u_liquid_plane.xyz;
  float sin_l = length(l - n * dot(n, l));
  float tau_l = u_foam.z * min(depth / max(dot(n, l), 0.15), side / max(sin_l, 0.15));
  float tau_a = u_foam.z * min(depth, side);
  float c = dot(l, d), g = u_foam_color.w, w = u_foam_detail.x;
  // Multiple scattering: two more terms, each with half the weight and anisotropy and a
  // much smaller optical depth. Foam's bubble films barely absorb, so light diffuses
  // centimetres into a head that is opaque to a straight ray (tau ~ 20).
  float key = hg_phase(c, g) * exp(-tau_l);
  key += w * (0.5 * hg_phase(c, 0.5 * g) * exp(-0.08 * tau_l) + 0.25 * hg_phase(c, 0.25 * g) * exp(-0.02 * tau_l)) * 4.0;
  float sky = exp(-tau_a) + w * (0.5 * exp(-0.08 * tau_a) + 0.25 * exp(-0.02 * tau_a)) * 2.0;
  return u_foam_color.rgb * (u_light_color.rgb * u_light_dir.w * key + ambient_light() * sky) * 1.25;
}

// Per-pixel jitter of the march start (interleaved gradient noise): no layered banding.
float march_jitter() { return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715)))); }

int g_foam_steps = 0;  // march steps this pixel took (cost view)

// The part of [t0, t1] along o + t d where the head (or a big bubble's cap) can be: the
// slab from the lowest wave to the highest top, inside the cavity's bounding cylinder.
bool foam_interval(vec3 o, vec3 d, inout float t0, inout float t1) {
  vec3 n = u_liquid_plane.xyz;
  float top_max = u_foam.x * (1.0 + abs(u_foam.y)) + abs(u_waves.x) + abs(u_waves.y) + abs(u_waves.z) + 0.006;
  float h0 = dot(n, o) - g_liquid_offset, dh = dot(n, d);
  float lo = -abs(u_waves.x) - abs(u_waves.y) - abs(u_waves.z);
  if (abs(dh) > 1e-9) {
    float ta = (lo - h0) / dh, tb = (top_max - h0) / dh;
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
  } else if (h0 < lo || h0 > top_max) {
    return false;
  }
  vec2 tr;
  if (!clip_to_bounds(o, d, u_vessel.y, u_vessel.x, u_rim.z, t0, tr)) return false;
  t0 = tr.x;
  t1 = min(t1, tr.y);
  return t1 > t0;
}

// Marches the head along o + t d for t in [t0, t1] (a stretch through air, already cut to
// foam_interval). Adds the light it scatters to `radiance` and attenuates `thr`.
void march_foam(vec3 o, vec3 d, float t0, float t1, vec3 l, inout vec3 radiance, inout vec3 thr) {
  float len = t1 - t0;
  int steps = int(clamp(len * u_foam.z * 0.5, 6.0, 40.0));
  float dt = len / float(steps);
  float t = t0 + dt * march_jitter();
  for (int i = 0; i < 40; ++i) {
    if (i >= steps) break;
    ++g_foam_steps;
    vec3 p = o + t * d;
    float height = liquid_level(p), top = foam_thickness_at(p.xz);
    float sigma = foam_density(p, height, top);
    if (sigma > 0.0) {
      float trans = exp(-sigma * dt);
      float side = max(inner_radius(p.y) - length(p.xz), 0.0);
      // Wetter, creamier foam low in the head: a little darker than its top.
      float wet = mix(0.72, 1.0, clamp(height / top, 0.0, 1.0));
      radiance += thr * wet * foam_light(d, l, max(top - height, 0.0), side) * (1.0 - trans);
      thr *= trans;
      if (max(thr.r, max(thr.g, thr.b)) < 1e-3) {
        thr = vec3(0.0);
        return;
      }
    }
    t += dt;
  }
}

// A big bubble's cap is a thin soap film: it mirrors the surroundings at grazing angles.
void bubble_caps(vec3 o, vec3 d, float t0, float t1, vec3 l, inout vec3 radiance, inout vec3 thr) {
  for (int i = 0; i < int(u_foam_detail.w); ++i) {
    if (u_bubbles[i].w < 0.0) continue;  // popped
    vec3 c = u_bubbles[i].xyz;
    float r = u_bubbles[i].w;
    vec3 oc = o - c;
    float b = dot(oc, d), disc = b * b - (dot(oc, oc) - r * r);
    if (disc <= 0.0) continue;
    float t = -b - sqrt(disc);
    if (t <= t0 || t >= t1) continue;
    vec3 p = o + t * d;
    if (liquid_level(p) < foam_thickness_at(p.xz) || clipped(p)) continue;  // only the cap above the foam
    vec3 nn = normalize(p - c);
    float F = fresnel_dielectric(abs(dot(nn, d)), 1.0, 1.33);
    float film = 2.0 * F / (1.0 + F);  // two faces of the film
    vec3 refl = reflect(d, nn);
    radiance += thr * (film * studio_sky(to_world_dir(refl)) +
                       u_light_color.rgb * u_light_dir.w * 2.0 * ggx_specular(nn, -d, l, 0.04));
    thr *= 1.0 - film;
  }
}

// Lacing: thin foam left on the inner wall where the head's top used to be.
float lacing_cover(vec3 p) {
  float cover = 0.0;
  for (int i = 0; i < int(u_lacing_info.x); ++i) {
    float y = u_lacing[i / 4][i % 4];
    float band = (p.y - y) / 0.0012;
    float lace = value_noise(vec3(atan(p.z, p.x) * 9.0, p.y * 900.0, float(i) * 3.7));
    cover = max(cover, exp(-band * band) * smoothstep(0.35, 0.75, lace));
  }
  return cover * u_lacing_info.y;
}
