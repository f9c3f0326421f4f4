// The light the backdrop's paper receives besides the rig's direct light: the sky's, less
// what the paper hides of it, and the paper's own, gathered where each point of it is. A
// point of the floor beside the glass sees the lit floor and wall around it; one on the
// floor 5 m off sees mostly the sky. (Lighting every point by what surrounds the scene's
// centre made the far paper as bright as the near: under a black sky the heads' sides,
// which see that paper, came out 1.4-1.8 times the reference's, and the paper far off
// twice as bright. docs/REFERENCE.md, "The paper's own light".)
//
// A coarse map over the unrolled sweep (backdrop_light's coordinates: x across, s along
// floor -> curve -> wall), 3 m round the scene's aim each way, 16 x 16 texels (about 40 cm
// for the default sweep: the bounce changes over the paper's own distances): at each texel the sky's harmonics plus, over a
// cosine-weighted grid of 6 x 12 directions round the texel's normal, where a direction
// meets the paper, the paper's radiance there (albedo / pi times the rig's light and that
// point's own bounce, from the map) instead of the sky's smooth radiance; three rounds
// from the sky alone, each one bounce more (a fine gather of the exact lights agrees
// within 10 %). Beyond the map the paper takes each light as a point and the bounce of the
// map's edge. The picture's backdrop reads it (frame.paper_bounce, lib/environment/
// backdrop_light.glsl paper_bounce: the twin of PaperBounceMap::at), and the heads' and the
// haze's surroundings are made of it (core/environment/reflection).
#pragma once

#include "core/environment/backdrop.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/environment/sweep_grid.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

inline constexpr int kPaperBounceTexels = contract::kPaperBounceTexels;  // along x and along s

struct PaperBounceMap : SweepGrid {
  std::vector<glm::dvec3> bounce;  // irradiance at texel centres (the rig's light units)
  std::vector<glm::dvec3> rig;     // the rig's exact light there (what the paper's radiance is made of)

  // The bounce at backdrop point p: bilinear between texel centres, the edge's beyond
  // them (0 from an empty map: no backdrop).
  glm::dvec3 at(const BackdropSurface&, const glm::dvec3& p) const;
};

// The map for this rig and sky (sky_irradiance) on this backdrop round `aim`. Empty
// without a backdrop.
PaperBounceMap paper_bounce_map(const LightRig&, const BackdropSurface&, const SkyIrradiance& sky, const glm::dvec3& aim);

}  // namespace draught
