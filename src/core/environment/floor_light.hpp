// The floor's direct light with the glasses' shadows and caustics: a map over a rect of the
// floor y = 0 holding the irradiance (W/m^2, RGB) the studio's lights (FrameState::lights)
// give each point, computed by tracing the actual geometry.
//
// Each texel is the exact unoccluded irradiance (AreaLight::irradiance_factor) plus a traced
// change: photons leave each light towards each glass's bounding sphere (and the spheres
// around the droplets and each cloud) and follow the reference intersector and marches with
// the path tracer's media rules (Fresnel choosing reflection or refraction, Beer-Lambert in
// glass, drink, water and blob, the drink's haze scattering, the head's optical depth;
// core/reference/bodies for the droplets and clouds). A photon that meets an object adds
// its power where it reaches the floor and subtracts it where its straight line would have
// reached it, so the map is exact far from the objects and its noise stays near them.
// Rising and big bubbles are ignored (the head is taken without its big bubbles), as is
// light the head scatters; a hot blob's own glow is not traced here (the picture adds it
// as a sphere's light: core/pointcloud/glow_light). The picture's twin reads the map as a
// texture: shaders/lib/environment/floor_light.glsl.
#pragma once

#include "core/scene/frame.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace draught {

// Photons over all lights and glasses for a still: the default pint under the rig in about
// 1.3 s on two busy cores, its noise about 1 % of the floor's light near the glass
// (docs/REFERENCE.md, "Shadows and caustics"); the eye does not see that on a floor.
inline constexpr int kFloorPhotonsStill = 500000;
// Once an interactive scene holds still: five times faster, about 2 % noise.
inline constexpr int kFloorPhotonsInteractive = 100000;

// The clouds' photons: this share of the budget, on top of it (a cloud's photon costs tens
// of a glass's).
inline constexpr double kCloudPhotonShare = 0.125;

struct FloorLightSettings {
  int photons = kFloorPhotonsStill;  // over all lights, glasses and droplets
  std::uint64_t seed = 1;
  int threads = 0;                   // 0: the hardware's, at most kFloorLightLanes
  double texel = 0.0025;             // m, the finest texel; coarser when the rect is big
  int max_resolution = 512;          // texels along either side
  int gather_rays = 32;              // per node of the surroundings' shadow (0: none)
  // In batches (FloorLightTrace): the rays each batch adds to every node until all are in
  // (0: all in the first). The same factor however they are split.
  int gather_rays_per_batch = 0;
};

// Where the traced power went, summed over every photon that met a glass (W, per channel).
struct FloorLightStats {
  glm::dvec3 hit{0.0};       // carried by the photons that met a glass
  glm::dvec3 landed{0.0};    // reached the floor
  glm::dvec3 removed{0.0};   // subtracted where the straight lines reached the floor
  glm::dvec3 absorbed{0.0};  // by glass, drink and head
  glm::dvec3 escaped{0.0};   // left the scene or reached the sweep's curve or wall, less what
                             // would have reached those along its straight line anyway
  glm::dvec3 outside{0.0};   // of the change (landed - removed), what fell outside the rect
  int photons = 0;           // traced
  double seconds = 0;
};

struct FloorLightMap {
  glm::dvec2 origin{0.0};  // world (x, z) of the rect's corner
  glm::dvec2 size{0.0};    // m along x and z
  int width = 0, height = 0;
  // Per texel (row-major, row j along z, texel centres): the traced change (W/m^2), and
  // what the picture reads, the light over the unoccluded light per channel (1 where no
  // photon changed it: the unoccluded light is evaluated only where one did, most of a
  // draft's time otherwise).
  std::vector<glm::vec3> change;
  std::vector<glm::vec3> factor;
  // The surroundings' shadow: per texel, the light the floor gathers from the
  // surroundings (EnvironmentFrame::surround: the sky and the lit paper) through the
  // glasses over what it gathers with nothing in between. (Under an image: from the
  // image less the patches the photons trace, and as a share of the image's whole light
  // as `factor` is, 1 - share x (1 - gathered / open): the floor's light is
  // that whole light times factor + surround_factor - 1.) Gathered, not traced from the
  // light: at every kGatherStep-th texel near the glasses, gather_rays cosine-weighted directions (a
  // shifted Sobol' set) followed through glass, drink, head, droplets and clouds with
  // the photons' media rules, each bringing what is left of the surroundings' radiance
  // where its path leaves them; bilinear between. So it is never below 0, exactly 1 where
  // nothing is in the way, and its noise is a few per cent. The picture multiplies the
  // paper's own bounce by it: the glasses' soft shadow round their feet, tinted by what
  // the drink lets through.
  std::vector<glm::vec3> surround_factor;
  FloorLightStats stats;
  LightRig lights;             // whose unoccluded light the texels change
  bool even = false;           // under an image: its light is the same everywhere,
  glm::dvec3 even_light{0.0};  // this

  bool empty() const { return width == 0 || height == 0; }
  double texel_area() const { return size.x / width * (size.y / height); }
  glm::dvec2 texel_centre(int i, int j) const;
  // The exact irradiance with nothing in between at texel (i, j), and the map's (that plus
  // the change, at least 0).
  glm::dvec3 unoccluded(int i, int j) const;
  glm::dvec3 at(int i, int j) const;
  // The map at world (x, z), bilinear between texel centres as GL's linear filter, clamped
  // to the edge.
  glm::dvec3 sample(double x, double z) const;
  // The surroundings' factor there, the same way.
  glm::dvec3 surround_sample(double x, double z) const;
};

// Under an environment image (env.mode image) the photons come from its brightest patches
// of sky: the kImageFloorEmitters patches (of a 32 x 16 level, about 11 degrees) giving the
// floor the most light, each a sphere light that far away covering the patch's solid angle
// with its radiance. Their photons change the image's whole, even light on the floor
// (its spherical harmonics) near the glasses: the shadows of what lights the floor most.
inline constexpr size_t kImageFloorEmitters = 16;
inline constexpr int kImageFloorEmitterWidth = 32;  // the patches' level, at most this wide
// The lights whose photons the map traces: the rig's, or an image's patches.
LightRig floor_emitters(const FrameState&);

// The irradiance the rig gives floor point p (y = 0) with nothing in between.
glm::dvec3 unoccluded_floor_irradiance(const LightRig&, const glm::dvec3& p);

// The settings of a draft of `photons` photons while a scene moves: on texels twice as wide
// (a quarter of the exact open light to evaluate, most of a draft's time, and a draft's
// few photons spread over fewer, less noisy texels).
FloorLightSettings floor_light_draft(FloorLightSettings full, int photons);

// The map of the frame (empty when there is no floor, no light or no object).
FloorLightMap compute_floor_light(const FrameState&, const FloorLightSettings& = {});

// A map traced in batches, for interactive apps that refine it over frames rather than
// stall one: each batch an estimate of its own with settings.photons photons (each pair's
// Halton sequence going on where the last batch stopped), the map the mean of the batches
// so far (its stats the means too, stats.photons the count traced). One batch is
// compute_floor_light's map. Keeps a copy of the frame. A batch only traces: the lanes
// it added to are merged into the map when the map is next asked for, so an app that
// shows every few batches pays for a merge (a pass over every texel) only then.
class FloorLightTrace {
 public:
  FloorLightTrace(const FrameState&, const FloorLightSettings&);
  ~FloorLightTrace();
  FloorLightTrace(const FloorLightTrace&) = delete;
  FloorLightTrace& operator=(const FloorLightTrace&) = delete;

  void add_batch();
  int batches() const;
  const FloorLightMap& map() const;  // the mean of every batch so far (merged if it is not)
  // The map as last merged, with no merge: its rect (origin, size, texels) is the trace's
  // from the start, for what needs only that each frame.
  const FloorLightMap& last_merged() const;
  FloorLightMap release();  // the map, moved out: the trace takes no more batches

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Everything the map depends on, as numbers rounded to 1e-5 (of a metre, or of the unit:
// nothing a picture shows): poses, glass shapes, liquid surfaces,
// drink, glass and head parameters, cross-sections, the droplets, the clouds' versions, the
// lights, the floor. Equal inputs give
// an equal map, so a renderer recomputes it only when these change.
std::vector<double> floor_light_inputs(const FrameState&);

}  // namespace draught
