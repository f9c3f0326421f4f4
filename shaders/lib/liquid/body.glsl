// The drink's body in a vessel: Beer-Lambert absorption along the path and
// single-scattering haze, both closed-form over a straight segment (no marching).
#ifndef LIB_LIQUID_BODY_GLSL
#define LIB_LIQUID_BODY_GLSL
#include "lib/optics/fresnel.glsl"
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"

// The drink's colour (core DrinkAbsorption's twin): in each channel two bands of its
// spectrum, T(L) = share e^(-fast L) + (1 - share) e^(-slow L). A path keeps how the light
// it still carries is shared between the bands (`left`: the fast band's share; `share`
// as it enters the drink): `dist` more of the drink passes left e^(-fast dist) + (1 -
// left) e^(-slow dist), and `left` is shared anew, so a path's stretches multiply to T of
// their sum (a thin edge of red wine crimson, its deep middle still red, as the spectrum
// gives; one coefficient per channel is exact at one length only).
vec3 drink_onward(ObjectBody b, inout vec3 left, float dist) {
  vec3 ef = exp(-b.absorption_fast * dist), es = exp(-b.absorption_slow * dist);
  vec3 t = left * ef + (1.0 - left) * es;
  left = left * ef / max(t, vec3(1e-30));
  return t;
}
vec3 drink_transmittance(ObjectBody b, float dist) {
  vec3 left = b.absorption_share;
  return drink_onward(b, left, dist);
}

// Transmittance of a straight path of length dist in the medium of vessel v (glass g),
// `left` the shares of the drink's colour bands on the path (drink_onward).
vec3 medium_transmittance(Vessel v, ObjectGlass g, int medium, vec3 left, float dist) {
  if (medium == MEDIUM_GLASS) return exp(-g.glass_absorption * dist);
  if (medium == MEDIUM_LIQUID) return drink_onward(v.body, left, dist) * exp(-v.liquid.haze * dist);
  return vec3(1.0);
}

// I0(x) e^-x for x >= 0 per channel (Abramowitz and Stegun 9.8.1 and 9.8.2, relative
// error under 2e-7): the twin of core/liquid/haze.cpp's i0_scaled.
vec3 bessel_i0_scaled(vec3 x) {
  vec3 t = x / 3.75, t2 = t * t, u = 3.75 / max(x, vec3(3.75));
  vec3 small = (1.0 + t2 * (3.5156229 + t2 * (3.0899424 + t2 * (1.2067492 + t2 * (0.2659732 + t2 * (0.0360768 + t2 * 0.0045813)))))) * exp(-x);
  vec3 large = (0.39894228 + u * (0.01328592 + u * (0.00225319 + u * (-0.00157565 + u * (0.00916281 + u * (-0.02057706 +
               u * (0.02635537 + u * (-0.01647633 + u * 0.00392377)))))))) / sqrt(max(x, vec3(3.75)));
  return mix(large, small, lessThan(x, vec3(3.75)));
}

// The haze's diffusion field at radius r of the drink's cross-section of radius R: the
// share of the surroundings' light there, I0(kappa r) / I0(kappa (R + reach)) (core
// haze_field's twin).
vec3 haze_field(ObjectHaze h, float r, float R) {
  vec3 inner = h.haze_kappa * min(r, R), outer = h.haze_kappa * (R + h.haze_reach);
  return bessel_i0_scaled(inner) / bessel_i0_scaled(outer) * exp(inner - outer);
}

// The renderer compiles the haze's light in (HAZE 1) only when some drink of the frame is
// hazy: software rasterizers pay for code where a uniform branch skips it (the clear pint
// 15 % slower with it).
#ifndef HAZE
#define HAZE 0
#endif

// The haze's samples along a segment: the field taken at the middles of equal parts, each
// part's in-scattering integrated exactly under its transmittance (4 parts: within 0.2 of
// CIEDE2000 of 8 on the hefeweizen against the reference).
#define HAZE_PARTS 4

// Light scattered towards the eye by the haze along the segment o + t d, t in [0, dist]
// (o, d in the world; isotropic scattering of the surroundings' light and the lights', each
// falling off inwards from the wall as diffusion's kappa: core/liquid/haze.hpp). colour:
// what the drink's colour passes of the segment (drink_onward), whose effective
// absorption the haze shares the segment with.
vec3 haze_inscatter(Vessel v, vec3 colour, float dist, vec3 o, vec3 d) {
#if HAZE
  float s = v.liquid.haze;
  // A loop of no trips where the drink is clear, which llvmpipe leaves at once where no
  // pixel of a group is in a hazy drink.
  int parts = s > 0.0 ? HAZE_PARTS : 0, count = frame.media_light_count;
  ObjectHaze h;
  vec3 ol, dl, tau, sum = vec3(0.0), before = vec3(1.0);
  for (int k = 0; k < parts; ++k) {
    if (k == 0) {
      h = fetch_object_haze(v.row);
      ol = to_local_point(v, o);
      dl = to_local_dir(v, d);
      tau = -log(max(colour, vec3(1e-30))) + s * dist;  // the segment's optical depth
    }
    vec3 after = exp(-tau * (float(k + 1) / float(HAZE_PARTS)));
    vec3 p = ol + (dist * (float(k) + 0.5) / float(HAZE_PARTS)) * dl;
    float R = inner_radius(v, p.y);
    vec3 light = h.haze_surround * haze_field(h, length(p.xz), R);
    for (int i = 0; i < count; ++i) {
      // Each light's irradiance over 4 pi, in through the wall towards it (Fresnel from
      // air into the drink there), then inwards over the way to p.
      vec4 lit = object_lit_by(v.row, i);
      vec3 l = to_local_dir(v, lit.xyz);
      float a = dot(l.xz, l.xz), b = dot(p.xz, l.xz), c = dot(p.xz, p.xz) - R * R;
      float way = a > 1e-8 ? max((-b + sqrt(max(b * b - a * c, 0.0))) / a, 0.0) : 0.0;
      vec2 wall = p.xz + way * l.xz;
      float cos_in = dot(wall, l.xz) / max(length(wall), 1e-9);
      light += frame.media_light_radiance[i].rgb * (lit.w / (4.0 * PI)) *
               (1.0 - fresnel_dielectric(clamp(cos_in, 0.0, 1.0), 1.0, v.liquid.ior)) * exp(-h.haze_kappa * way);
    }
    sum += light * (before - after);
    before = after;
  }
  return parts > 0 ? h.haze_albedo * (s * dist / max(tau, vec3(1e-12))) * sum : vec3(0.0);
#else
  return vec3(0.0);
#endif
}

#endif  // LIB_LIQUID_BODY_GLSL
