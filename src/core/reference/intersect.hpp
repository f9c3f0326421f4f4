// The C++ reference intersector: the same analytic math as shaders/lib/vessel/ (GLSL twins
// intersect.glsl, vessel.glsl) and shaders/lib/scene/trace.glsl, in double precision.
// Tests compare the GPU's debug outputs against it pixel by pixel.
#pragma once

#include "core/environment/backdrop.hpp"

#include "core/scene/motion.hpp"
#include "core/liquid/slosh.hpp"
#include "core/vessel/decal.hpp"
#include "core/vessel/vessel.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <limits>
#include <memory>
#include <vector>

namespace draught {

struct Ray {
  glm::dvec3 o, d;  // d normalised
  glm::dvec3 at(double t) const { return o + t * d; }
};

// Material ids, declared once for C++ and GLSL in src/interface/constants.def: the
// shader's material debug output writes the same numbers.
using Material = contract::Material;
inline const char* material_name(Material m) { return contract::name_of(m); }

struct Hit {
  double t = std::numeric_limits<double>::infinity();
  glm::dvec3 n{0.0};  // glass surfaces: pointing out of the glass; liquid and floor: up
  Material m = Material::None;
  int object = -1;  // which vessel of the scene (first_hit); -1 for the floor or none
  bool valid() const { return m != Material::None; }
};

// Real roots of x^4 + b x^3 + c x^2 + d x + e, ascending; returns the count.
int solve_quartic(double b, double c, double d, double e, double roots[4]);
// Real roots of x^3 + a x^2 + b x + c; returns the count.
int solve_cubic(double a, double b, double c, double roots[3]);

// Ray against the cone r = r0 + (r1 - r0) (y - y0) / (y1 - y0) for y in [y0, y1].
// Returns up to 2 parameters t > tmin, ascending.
int intersect_cone(const Ray&, double r0, double r1, double y0, double y1, double tmin, double out[2]);
// Ray against a torus around the Y axis (major R, minor r, centre height cy); all roots.
int intersect_torus(const Ray&, double R, double r, double cy, double out[4]);

// The liquid, in the glass's local frame: the part of the cavity below the surface
// dot(n, p) = offset + waves.height(p.x, p.z).
struct LiquidPlane {
  glm::dvec3 n{0, 1, 0};
  double offset = -1;  // below the floor: no liquid
  SurfaceWaves waves;
  double level(const glm::dvec3& p) const {
    return glm::dot(n, p) - offset - (waves.flat() ? 0.0 : waves.height(p.x, p.z));
  }
  bool below(const glm::dvec3& p) const { return level(p) < 0; }
};

// One vessel of a scene as the reference intersector sees it: rays are in the world; the
// glass stands in it at `pose` (the floor is world y = 0).
struct VesselGeometry {
  const Vessel* vessel = nullptr;
  LiquidPlane liquid;
  Pose pose;
  glm::dvec4 clip{0, 0, 0, 1};  // cross-section (glass frame): dot(n, p) > offset is cut away; n = 0: none
  std::shared_ptr<const VesselDecals> decals;  // its decals, placed (scene_geometry with decals); null: none
  bool clipped(const glm::dvec3& local) const { return glm::dot(glm::dvec3(clip), local) > clip.w; }
};

// Every object of a scene, and what they stand on (the sweep or the checker floor).
struct SceneGeometry {
  std::vector<VesselGeometry> vessels;
  BackdropSurface backdrop;  // present = false: none
};

Hit hit_wall(const Vessel&, bool inner, const Ray&, double tmin);
Hit hit_rim(const Vessel&, const Ray&, double tmin);
// Where a ray first meets the liquid's (wavy) surface inside the cavity, local frame.
Hit hit_liquid_surface(const Vessel&, const LiquidPlane&, const Ray& local_ray, double tmin);
// Nearest surface of one vessel along the world ray (glass, liquid surface, cut faces);
// normals in the world.
Hit hit_vessel(const VesselGeometry&, const Ray& world_ray, double tmin = 1e-7);
// Nearest surface along the world ray over every object and the backdrop (Material::Floor:
// its floor, curve or wall); normals in the world.
Hit first_hit(const SceneGeometry&, const Ray&, double tmin = 1e-7);

// The decal a wall hit `h` of the world ray meets on its vessel (`s`: the geometry of
// h.object): its layer (0 the outer wall's, 1 the inner wall's; -1 none) and (u, v) over
// its image (core/vessel/decal.hpp decal_uv). GLSL twin: the Decal debug view
// (shaders/lib/vessel/decal.glsl decal_uv), compared by tests/gpu/test_decals.cpp.
struct DecalHit {
  int layer = -1;
  glm::dvec2 uv{0.0};
};
DecalHit decal_hit(const VesselGeometry& s, const Hit& h, const Ray& world_ray);

}  // namespace draught
