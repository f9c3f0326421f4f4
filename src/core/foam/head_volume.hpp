// The head as a participating medium: its extinction at a point of the glass's frame (the
// C++ twin of foam_thickness_at and foam_density in shaders/lib/foam/head.glsl), where
// along a ray it can be (foam_interval), and a bound on its extinction for
// free-flight sampling. The reference path tracer samples scattering in it; the picture
// marches the same field.
#pragma once

#include "core/foam/foam.hpp"
#include "core/reference/intersect.hpp"

#include <vector>

namespace draught {

struct VesselFrame;

// The colour of a foam is what a deep head shows under even light: its diffuse
// reflectance R, built up by hundreds of scatterings. The single-scattering albedo a that
// gives it is very near 1 (a white head: R = 0.97 needs a = 0.9998). Diffusion theory
// for a semi-infinite medium (van de Hulst; Jensen et al. 2001) ties them:
//   R = (1 - s)(1 - 0.139 s) / (1 + 1.17 s),  s = sqrt((1 - a) / (1 - a g)),
// inverted here per channel (R in [0, 1], g the Henyey-Greenstein anisotropy).
double foam_reflectance(double single_scattering_albedo, double g);
glm::dvec3 foam_single_scattering_albedo(const glm::dvec3& reflectance, double g);

// How far light from below travels through the drink to reach the head's underside: the
// mean chord 4 V / S of a cylinder with the liquid's volume and depth (Cauchy: the mean
// length of isotropic lines across a convex body, which diffuse light follows). 0 when
// there is no liquid. The picture's head tints its underside's light by the drink over it.
double drink_mean_chord(const VesselFrame& vf);

// What a glass wall (two faces, air on both sides) lets through of even light: the
// cosine-weighted mean over incidence of (1 - F)^2, by 8 midpoints in cos^2 (0.84 for
// ior 1.5). The head's side face takes its light through the wall
// (lib/foam/head.glsl, the object record's wall_diffuse).
double wall_diffuse_transmittance(double glass_ior);

class HeadVolume {
 public:
  // The head of vessel frame `vf` cut by `clip` (a VesselGeometry's); empty() when the
  // vessel has no head (as the renderer's has_head).
  HeadVolume(const VesselFrame& vf, const VesselGeometry& geometry);
  bool empty() const { return !present_; }
  // Extinction per metre at p (glass frame).
  double density(const glm::dvec3& p) const;
  // A bound on density() everywhere (for delta and ratio tracking).
  double majorant() const { return majorant_; }
  // Cuts [t0, t1] of the local ray o + t d to where the head can be: the slab from the
  // lowest wave to the highest top, inside the cavity's bounding cylinder. False: nowhere.
  bool interval(const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) const;
  // The head's thickness above the liquid at (x, z).
  double thickness_at(double x, double z) const;
  // The big bubbles' caps (shiny films standing out of the head's top) along the local
  // ray within (t0, t1): the nearest cap's t and outward normal. False: none.
  bool hit_cap(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1, double& t, glm::dvec3& n) const;

 private:
  bool present_ = false;
  const Vessel* vessel_ = nullptr;
  LiquidPlane liquid_;
  glm::dvec4 clip_{0, 0, 0, 1};
  const FoamFrame* foam_ = nullptr;  // its thickness_at (the dome, a pour's crater); the frame's, as vessel_
  double radius_ = 1;   // the surface's, for the dome
  double density_ = 0, bubble_size_ = 1, detail_ = 0;
  double majorant_ = 0;
  std::vector<PlacedBubble> bubbles_;
};

}  // namespace draught
