// The backdrop's light map: the rig's exact unoccluded irradiance (W/m^2, RGB) over the
// sweep (or the checker floor) near the scene, so the picture reads one filtered texel where
// it would sum four exact area lights per pixel. It depends only on the lights, the backdrop
// and the scene's aim (not on the glasses' poses), so a renderer computes it once per change
// of those. The glasses' shadows and caustics are the floor-light map's (floor_light.hpp),
// which multiplies this light inside its own rect.
//
// The sweep is unrolled along its profile: a point is (x across, s the arc length along
// floor -> quarter curve -> wall), s = 0 where the floor starts to curve, negative in front
// (on the floor s = z_curve - z), R pi / 2 where the wall starts. The checker floor uses the
// same s = z_curve - z. The picture's twin is shaders/lib/environment/backdrop_light.glsl.
#pragma once

#include "core/environment/backdrop.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/sweep_grid.hpp"
#include "core/scene/frame.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

// Where point p on the backdrop lies in the unrolled sweep: (x, s). Twin of
// backdrop_coords in backdrop_light.glsl.
glm::dvec2 backdrop_coords(const BackdropSurface&, const glm::dvec3& p);
// The inverse: the point at (x, s) and the backdrop's normal there.
glm::dvec3 backdrop_point(const BackdropSurface&, const glm::dvec2& xs, glm::dvec3& normal);

// Where filtering between texels errs by more than this part of the light (a light's edge
// through the paper: the strips stand through the curve), the map marks its texels and the
// picture sums the lights itself. 0.4 % is under half an 8-bit step after the tone map at
// any exposure and albedo: sRGB after ACES changes by at most 73 steps per unit of log
// light, 112 without ACES.
inline constexpr double kBackdropLightTolerance = 0.004;

// The map's reach around the scene's aim (metres): across, in front on the floor, up the
// wall (the checker: behind as far as in front); what a packshot frames. Beyond it the
// picture sums the lights itself.
struct BackdropLightSettings {
  double across = 1.0, front = 1.0, up = 1.2;
  // Texel (metres along x and s; along s fitted to the curve). Where filtering errs it is
  // distrusted anyway; 5 mm narrows those bands to about 0.5 % of the default map (1 cm:
  // 1.4 %) for about 0.2 s of computing on two cores.
  double texel = 0.005;
  int max_resolution = 2048;  // texels along either side (ES 3.0's guaranteed texture size)
  double tolerance = kBackdropLightTolerance;
  int guard = 0;  // rings of cells around a distrusted cell also distrusted
};

struct BackdropLightMap : SweepGrid {
  std::vector<glm::vec3> irradiance;  // W/m^2, row-major, row j along s, at texel centres
  // Per texel, 1 where filtering may be trusted in every cell it is a corner of, 0 where
  // not (a cell whose middle or edges' middles err by more than kBackdropLightTolerance,
  // and the cells around it): there, the exact sum.
  std::vector<float> trusted;

  // The part of the map's texels that are not trusted.
  double untrusted_fraction() const;
  // Whether (x, s) lies between the outermost texel centres (where filtering interpolates).
  bool covers(const glm::dvec2& xs) const;
  // The map at (x, s), bilinear between texel centres as GL's linear filter; a (trust)
  // below 1 says the picture takes the exact sum there.
  glm::dvec4 sample(const glm::dvec2& xs) const;
};

// The map for this rig on this backdrop around `aim` (empty when there is no backdrop or
// no light).
BackdropLightMap compute_backdrop_light(const LightRig&, const BackdropSurface&, const glm::dvec3& aim,
                                        const BackdropLightSettings& = {});
BackdropLightMap compute_backdrop_light(const FrameState&, const BackdropLightSettings& = {});

// The widest texel a map is computed on: a thumbnail's, and the interactive apps' drafts.
inline constexpr double kBackdropLightCoarsestTexel = 0.04;

// The map's texel for a width x height picture of the frame: `finest` (the settings' 5 mm),
// doubled while four of the picture's pixels at the scene's aim still span the doubled
// texel, up to kBackdropLightCoarsestTexel (4 cm). A thumbnail then computes a map up to 64 times
// smaller (a 16 x 16 picture of a pint: 4 cm texels, 50 x 70 instead of 400 x 549); the
// trust marks bound filtering's error at any texel, so a coarser map hands more of the
// picture to the exact sum instead of showing it less exactly.
double backdrop_light_texel(const FrameState&, int width, int height, double finest = BackdropLightSettings{}.texel);

// Everything the map depends on as numbers (the lights, the backdrop, the aim, the texel):
// equal inputs give an equal map, so a renderer recomputes it only when these change.
std::vector<double> backdrop_light_inputs(const FrameState&, double texel = BackdropLightSettings{}.texel);

}  // namespace draught
