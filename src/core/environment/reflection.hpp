// What the surroundings give the renderer beyond its own per-pixel look-ups: estimates
// that are physics of the environment, computed once per frame on the CPU.
#pragma once

#include "core/environment/backdrop.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/media_light.hpp"
#include "core/environment/paper_bounce.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/params/params.hpp"

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace draught {

struct EnvironmentFrame {
  // The radiance a small mirror-like sphere (a rising bubble) reflects on average: the
  // mean of everything around the scene's centre (the sky, each light over the solid
  // angle it covers there, the lit backdrop below and behind). The bubble pass scales it
  // by each bubble's Fresnel reflectance.
  glm::vec3 reflected{0.0f};
  // The light whose glint a bubble shows: the one giving the scene's centre the most
  // light; the direction towards it and that irradiance (0 without lights).
  glm::vec3 glint_dir{0, 1, 0};
  glm::vec3 glint{0.0f};
  // The sky's irradiance (spherical harmonics) for the backdrop.
  SkyIrradiance sky;
  // What the heads and the haze are lit by besides the lights themselves: the sky, and the
  // lit backdrop where it hides the sky, seen from the scene's centre (surround_irradiance).
  SkyIrradiance surround;
  // The paper's own bounce where each point of it is (core/environment/paper_bounce): what
  // the backdrop is lit by besides the rig, as the picture draws it and as the heads and
  // the haze see it. Made by environment_frame (environment_seen_from needs it).
  std::shared_ptr<const PaperBounceMap> paper_bounce;
  // What the heads and the haze are lit by, split into lights and the rest: the rig and the
  // surround, or under an image its brightest patches and the surround less them.
  MediaLight media;
  // media.surround as seen from each point environment_frame was given (each head's
  // middle): the backdrop's part seen from there instead of from the scene's centre (a
  // head near the top of a pint sees the sweep's paper from twice the height); the image
  // and the sky are at infinity, the same from anywhere.
  std::vector<SkyIrradiance> media_seen_from;
  // The backdrop's share of the surround seen from the scene's centre on the grid the
  // points' views are taken on (16 x 32): each view is media.surround plus its own share
  // less this one, so the grid's own error cancels (environment_seen_from).
  SkyIrradiance centre_share;
  // env.mode image: the environment and how it is seen (Studio's image, rotation, blur).
  std::shared_ptr<const EnvironmentMap> image;
  float rotation_cos = 1, rotation_sin = 0, blur_lod = 0, intensity = 1;
};

// What of a light's straight path from one point to another arrives (1: all of it): the
// scene's objects between them (assemble_frame: each glass's drink as a column).
using LightPasses = std::function<glm::dvec3(const glm::dvec3& from, const glm::dvec3& to)>;

// The scene's surroundings, and media.surround seen from each point of seen_from (in
// media_seen_from, in that order), the light's paths to the backdrop through `passes`.
EnvironmentFrame environment_frame(const SceneParams&, const LightRig&, const BackdropSurface&,
                                   const std::vector<glm::dvec3>& seen_from = {}, const LightPasses& passes = {});
// media.surround seen from `at` instead of the scene's centre, for a frame environment_frame
// made from the same parameters, rig and backdrop: what environment_frame puts in
// media_seen_from (assemble_frame's cache takes the views one at a time).
SkyIrradiance environment_seen_from(const EnvironmentFrame&, const SceneParams&, const LightRig&,
                                    const BackdropSurface&, const glm::dvec3& at, const LightPasses& passes = {});

// The light around point `at` besides the rig's lights: the sky's harmonics `sky`, and
// where a direction from `at` meets the backdrop, the backdrop's radiance instead of the
// sky's (its albedo / pi times the rig's unoccluded irradiance and the paper's own bounce
// there, `bounce`), so a head above a lit sweep, and the sweep itself, get the light the
// paper throws back, as the reference's do. The correction is projected over a grid of
// directions (64 x 32): the backdrop's light changes slowly, and irradiance keeps only
// its low frequencies.
SkyIrradiance surround_irradiance(const Studio&, const SkyIrradiance& sky, const LightRig&, const BackdropSurface&,
                                  const PaperBounceMap& bounce, const glm::dvec3& at);

// The backdrop's share of surround_irradiance seen from `at`, in one pass: where a
// direction of a rows x 2 rows grid meets the backdrop, its radiance (the rig's
// unoccluded irradiance and the paper's own bounce there, `bounce`, times albedo / pi)
// less the sky it hides. Zero without a backdrop.
SkyIrradiance backdrop_share(const Studio&, const LightRig&, const BackdropSurface&, const PaperBounceMap& bounce,
                             const glm::dvec3& at, int rows, const LightPasses& passes = {});

// The mean radiance over the whole sphere that harmonics of irradiance hold (their band-0
// share): what an isotropic scatterer (the haze) receives per steradian.
glm::dvec3 mean_radiance(const SkyIrradiance&);

}  // namespace draught
