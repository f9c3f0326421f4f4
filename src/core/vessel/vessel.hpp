// The glass as the renderer sees it: the profile sampled at uniform heights into
// frustum segments (outer and inner wall), a flat base under the cavity and a torus
// bead on the rim. The GPU and the C++ reference intersector use exactly this data.
#pragma once

#include "core/params/params.hpp"
#include "generated/constants.hpp"

#include <vector>

namespace draught {

struct Vessel {
  static constexpr int kSegments = contract::kSegments;  // src/interface/constants.def
  double height = 0;   // top of the walls (rim torus centre height)
  double base = 0;     // cavity floor height
  double dy = 0;       // segment height
  std::vector<double> r_outer, r_inner;  // kSegments + 1 knots at y = k * dy; inner clamped at 0
  double rim_major = 0, rim_minor = 0;   // torus centred on the axis at y = height
  double bound_radius = 0;               // encloses walls and rim

  double outer_radius(double y) const;   // linear inside a segment
  double inner_radius(double y) const;
  // The wall's slope dr/dy for its normal at fraction f (0..1) of segment k: each knot's
  // slope is the mean of the two segments it joins (where they meet at a crease, more
  // than acos(CREASE_COS) apart, each keeps its own), interpolated along the segment.
  // Normals are then continuous along a curved bowl (no contour bands) while the surface
  // stays the exact frustum. GLSL twin: wall_slope in shaders/lib/vessel/intersect.glsl.
  double wall_slope(bool inner, int k, double f) const;
  double cavity_volume() const;               // from base to height
  double cavity_volume_below(double h) const;  // exact for the segmented profile
  double fill_height(double fraction) const;   // inverse of the above, fraction of the cavity
  bool inside_torus(double r, double y) const;
};

// Derives the vessel from the glass parameters. Rim radius is clamped to
// [wall/2, 2*wall] so the bead always joins both walls.
Vessel build_vessel(const GlassParams&);

}  // namespace draught
