// A hazy drink (a hefeweizen, a cloudy amber) as diffusion lights it: the haze scatters
// isotropically (liquid.haze per metre, albedo liquid.haze_color) in a drink that absorbs
// (its colour), so the light inside falls off from the wall inwards with diffusion's
// kappa = sqrt(3 sigma_a sigma_t), and an infinite cylinder of radius R held at the
// surroundings' radiance at its extrapolated radius R + reach has the field
// I0(kappa r) / I0(kappa (R + reach)) (the modified Bessel function of order 0). The
// glass wall is the boundary as it is for the head's side (lib/foam/head.glsl): the
// extrapolation distance 2 / (3 sigma_t) times (2 - T_d) / T_d, T_d what the wall lets
// through of even light (wall_diffuse_transmittance). Each light enters through the wall
// on its side (Fresnel there) and falls off as kappa along its way in. The picture's
// twin is haze_inscatter in shaders/lib/liquid/body.glsl; the reference path tracer
// follows every scattering instead (docs/REFERENCE.md measures the two).
#pragma once

#include <glm/glm.hpp>

namespace draught {

struct HazeDiffusion {
  glm::dvec3 kappa{0.0};  // 1/m: the diffuse light's decay (never below the drink's absorption)
  glm::dvec3 reach{0.0};  // m: how far beyond the wall the field is held at the surroundings'
};
// haze: scattering per metre; albedo: its single-scattering albedo; absorption: the
// drink's effective absorption per metre (its colour); glass_ior: the wall's. A haze that
// absorbs nothing (albedo 1, a colourless drink) has kappa 0: in even light it holds that
// light everywhere (the furnace).
HazeDiffusion haze_diffusion(double haze, const glm::dvec3& albedo, const glm::dvec3& absorption, double glass_ior);

// The modified Bessel functions I0(x) e^-x and I1(x) e^-x (x >= 0; scaled so that a deep
// drink's kappa R does not overflow). Twin of bessel_i0_scaled in lib/liquid/body.glsl.
double bessel_i0_scaled(double x);
double bessel_i1_scaled(double x);

// The field's share at radius r of a cylinder of radius R (r <= R), per channel: the
// C++ twin of haze_field in lib/liquid/body.glsl (which takes I0 from Abramowitz and
// Stegun's polynomials; this from its series).
glm::dvec3 haze_field(const HazeDiffusion&, double r, double R);
// Its mean over the cylinder's cross-section (the MatCap tier's haze, which takes one
// light for the whole drink).
glm::dvec3 haze_field_mean(const HazeDiffusion&, double R);

}  // namespace draught
