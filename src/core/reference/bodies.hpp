// The marched bodies of a frame as the reference traces them: the droplets and the clouds'
// blobs, found by the project's own marches (core/droplets march_droplets, core/pointcloud
// march_cloud through each cloud's tree) and crossed as smooth dielectrics. One code for
// the path tracer's paths and the floor light's photons.
#pragma once

#include "core/pointcloud/cloud_scene.hpp"
#include "core/pointcloud/field.hpp"
#include "core/reference/media.hpp"
#include "core/scene/frame.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace draught {

class Rng;

// Where a path (the reference tracer's) or a photon (the floor light's) starts again past
// the analytic surface it left.
inline constexpr double kRestartEps = 1e-7;

// The same as kRestartEps for the marched surfaces: the clouds' march is the picture's float one,
// its hits placed to about a tenth of a micrometre, so a path leaving one starts 2 um on,
// as the picture's does (a march from the wrong side stops at once).
inline constexpr double kBodyMarchEps = 2e-6;

inline constexpr int kBoundsPerCloud = 8;

class MarchedBodies {
 public:
  // smooth: the droplets without their surface noise (the floor's photons: ripples of a
  // millimetre do not show in a shadow, and the noise is most of the march's cost).
  explicit MarchedBodies(const FrameState&, bool smooth = false);
  MarchedBodies(const MarchedBodies&) = delete;
  MarchedBodies& operator=(const MarchedBodies&) = delete;

  bool empty() const { return !droplets_ && cloud_refs_.empty(); }

  // The nearest surface along the ray for a path in `medium` (of object `obj`), as the
  // picture's search (lib/scene/trace.glsl) takes them: in the air every vessel of `geo`,
  // the backdrop and every body; in a glass or a drink the vessels; in a droplet or a
  // cloud's blob only its own surface (the objects are taken not to overlap).
  Hit nearest(const SceneGeometry& geo, const Ray&, double eps, MediumKind medium, int obj, glm::dvec4& attrs) const;

  // Narrows h to a droplet's or a cloud's surface nearer than it (Material::Droplet, or
  // Material::Cloud with h.object the cloud). From the air every body is marched, from
  // inside a droplet or a blob (medium, obj) only its own. attrs: a cloud hit's temperature
  // and colour (the march's k-weighted means).
  void march(const Ray&, MediumKind medium, int obj, Hit& h, glm::dvec4& attrs) const;

  // The surface h of a body, crossed from `medium`: a smooth dielectric (Fresnel chooses
  // reflection or refraction, total internal reflection included); a cloud point's colour
  // tints the light that crosses there, as the picture's shade_cloud does. True when the
  // path reflected off it from the air.
  bool cross(const Hit& h, const glm::dvec4& attrs, Ray&, MediumKind& medium, int& obj, glm::dvec3& thr, Rng&) const;

  // Along t inside a body (medium Droplet, or Cloud obj): Beer-Lambert; in a cloud the
  // chord ending where the temperature is `kelvin` (0: the points give none there) also
  // glows, by the picture's model (shade_cloud, passes/path.frag.glsl): a grey visible
  // extinction kappa, 0 at 700 K rising linearly to 1 / glow_depth at 1100 K and above,
  // that emits as much as it absorbs (Kirchhoff): the chord adds (1 - exp(-kappa t)) x
  // glow x kGlowPerNit x the blackbody's luminance-scaled colour to L (weighted by thr)
  // at the temperature where the chord ends; the coloured absorption dims what lies
  // beyond, not the glow.
  void chord(MediumKind medium, int obj, double t, double kelvin, glm::dvec3& thr, glm::dvec3& L) const;

  // Spheres around the bodies, what the floor's photons aim at: the droplets' box, and for
  // each cloud the boxes of up to kBoundsPerCloud nodes of its tree that hold all its points
  // (a tall thin stream in one sphere would send most photons past it).
  struct Bound {
    glm::dvec3 centre{0.0};
    double radius = 0;
    bool cloud = false;  // a cloud's (its march costs tens of a glass's intersections)
  };
  std::vector<Bound> bounds() const;

 private:
  const FrameState& frame_;
  std::optional<DropletsFrame> droplets_;  // the frame's droplets (at most one object)
  CloudScene clouds_;                        // the frame's clouds as the picture's march reads them
  std::vector<CloudRef> cloud_refs_;
};

}  // namespace draught
