// The drink's body in a vessel: Beer-Lambert absorption along the path and
// single-scattering haze, both closed-form over a straight segment (no marching).
#ifndef LIB_LIQUID_BODY_GLSL
#define LIB_LIQUID_BODY_GLSL
#include "lib/scene/objects.glsl"

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

// Light scattered towards the eye by haze along the segment (single scattering of the
// sky's light and the rig's lights, each a distant light from the glass's middle: the
// quarter of its irradiance an isotropic scatterer sends per steradian over pi; all reach
// the inside already tinted by the drink): the record's haze_light, computed in
// gpu/scene_data.cpp once per frame. colour: what the drink's colour passes of the
// segment (drink_onward), whose effective absorption the haze shares the segment with.
vec3 haze_inscatter(Vessel v, vec3 colour, float dist) {
  float s = v.liquid.haze;
  if (s <= 0.0) return vec3(0.0);
  vec3 tau = -log(max(colour, vec3(1e-30))) + s * dist;  // the segment's optical depth
  return v.liquid.haze_light * (s * dist / max(tau, vec3(1e-12))) * (1.0 - colour * exp(-s * dist));
}

#endif  // LIB_LIQUID_BODY_GLSL
