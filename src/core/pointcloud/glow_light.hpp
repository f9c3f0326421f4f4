// The light a hot cloud casts on the floor and the backdrop around it: the cloud taken as
// a sphere of even radiance (its glowing middle and extent, its points' mean emission
// through the mean chord of a sphere). The picture adds it to the backdrop's light,
// unshadowed (lib/environment/floor.glsl clouds_glow_irradiance); the reference path
// tracer finds the same light by following paths that meet the glowing body
// (core/reference/bodies, MarchedBodies::chord). docs/POINT_CLOUDS.md.
#pragma once

#include "core/pointcloud/cloud_object.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

struct GlowSphere {
  glm::dvec3 centre{0.0};    // world, m
  double radius = 0;         // m (0: the cloud casts no glow)
  glm::dvec3 radiance{0.0};  // the picture's radiance its surface sends out, per channel
  bool empty() const { return !(radius > 0) || !(radiance.x + radiance.y + radiance.z > 0); }
};

// The picture's blackbody table (the Frame block's `blackbody`: contract::kBlackbodyEntries
// from kBlackbodyMinK to kBlackbodyMaxK), built once.
const std::vector<glm::vec4>& picture_blackbody_table();
// The blackbody's radiance in cd/m^2 of luminance at `kelvin`, as that table gives it
// (blackbody_table_lookup, what the shader does).
glm::dvec3 glow_table(double kelvin);
// Hot glass's visible extinction (1/m) at `kelvin`: 0 at 700 K rising to 1 / glow_depth
// at 1100 K and above (0 without a glow depth). Twin of the shader's (lib/pointcloud).
double hot_glass_extinction(double kelvin, double glow_depth);

// The points sampled for it: evenly strided over the cloud, at most this many (a million
// points cost what 4096 do).
inline constexpr std::size_t kGlowSamples = 4096;

// A cloud's glow as a sphere: centred on its points' centroid, as wide as a uniform ball
// with their spread (sqrt(5/3) times the RMS distance to the centroid) plus a point's
// blob radius; its radiance the points' mean blackbody emission (glow x kGlowPerNit x
// the table's colour, MarchedBodies::chord's) times the emissivity of a sphere's mean
// chord 4 R / 3 at each point's visible extinction, and the part the surface lets out at
// normal incidence (1 - F0). Empty for a cloud without glow, without points or too cool
// to glow (700 K and below).
GlowSphere cloud_glow_sphere(const CloudFrame&);

}  // namespace draught
