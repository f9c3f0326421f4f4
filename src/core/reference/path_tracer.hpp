// The project's own reference: an unbiased CPU Monte Carlo path tracer over the reference
// geometry (core/reference/intersect). It renders the same frame as the GPU (scene,
// camera, glass, drink, head, lights, studio, backdrop) from the physics alone:
// - glass and liquid surfaces are smooth dielectrics (Fresnel picks reflection or
//   refraction); glass and drink absorb by Beer-Lambert; a hazy drink scatters
//   (isotropic, its haze colour the albedo), sampled by spectral free-flight sampling;
// - the head is a heterogeneous medium (core/foam/head_volume: the picture's density
//   field) with the foam colour as single-scattering albedo and Henyey-Greenstein phase,
//   sampled by delta tracking; its big bubbles' caps are thin films;
// - the rig's area lights (core/environment/lights) are sampled by next event estimation
//   from the backdrop and the head, one light per vertex chosen by the light it gives,
//   combined with the other paths by multiple importance sampling; the studio is an
//   environment of its own radiance;
// - the backdrop (core/environment/backdrop: the sweep or the checker floor) is
//   Lambertian; the checker fades into the studio's ground as the picture's does;
// - the screen (core/environment/screen): a card is an emitter with its frame's texel
//   radiance, found by the paths alone (not light-sampled, so it lights the backdrop only
//   through paths that happen to meet it); as the background it is what a path that
//   leaves the scene sees;
// - droplets (core/droplets) and point clouds (core/pointcloud) are found by the
//   project's own marches (march_droplets; march_cloud, the picture's float march through
//   the cloud's tree); in the air the nearest of every vessel, droplet and cloud surface
//   is taken, so a path goes from a droplet into a glass and back. Their surfaces are
//   smooth dielectrics (roughness not simulated), their bodies absorb by Beer-Lambert, a
//   cloud point's colour tints the light crossing there, and molten glass glows along
//   each chord by Kirchhoff's law with the picture's model (cloud_chord; the glow is
//   found by the paths alone).
// Left out: the drink's rising bubbles and the lacing on the wall (the picture draws both).
// docs/REFERENCE.md says how to use it and what it is for.
#pragma once

#include "core/io/hdr_image.hpp"
#include "core/io/image.hpp"
#include "core/scene/frame.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace draught {

struct ReferenceSettings {
  int samples = 64;          // paths per pixel
  int threads = 0;           // 0: one per hardware thread
  int max_surfaces = 64;     // interfaces a path may cross or reflect off
  int max_scatters = 20000;  // scattering events in media (a head is ~20 mean free paths deep)
  std::uint64_t seed = 1;
  // Called from the worker threads (serialised) as rows complete: rows done, of rows.
  std::function<void(int, int)> progress;
};

// Linear radiance per pixel, rows top-down (before exposure and tone mapping).
struct RadianceImage {
  int width = 0, height = 0;
  std::vector<glm::dvec3> pixels;
  double seconds = 0;  // wall time of the render
  glm::dvec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const glm::dvec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

RadianceImage render_reference(const FrameState&, int width, int height, const ReferenceSettings&);

// The picture: exposure, tone map and sRGB as the GPU's output (core/output/tonemap).
Image display_image(const RadianceImage&, const RenderParams&);

// The radiance itself, scene-linear, as 32-bit floats (what `draught render --reference
// -o NAME.exr` writes, and the tests keep: before exposure and the tone map).
HdrImage radiance_hdr_image(const RadianceImage&);

}  // namespace draught
