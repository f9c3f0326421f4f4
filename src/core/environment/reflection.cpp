#include "core/environment/reflection.hpp"

#include "core/environment/image_patches.hpp"
#include "core/environment/sphere_grid.hpp"
#include "core/math/constants.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace draught {

namespace {

// An environment image's glint: its brightest patch (a texel of the level nearest 64 wide,
// about 6 degrees), the direction to it and the irradiance it gives facing it.
void image_glint(const Studio& studio, EnvironmentFrame& f) {
  double best = 0;
  for (const ImagePatch& p : image_patches(studio, 64).patches) {
    const glm::dvec3 e = p.irradiance();
    if (e.x + e.y + e.z <= best) continue;
    best = e.x + e.y + e.z;
    f.glint_dir = glm::vec3(p.dir);
    f.glint = glm::vec3(e);
  }
}

}  // namespace

namespace {

// Where a direction from `at` meets the backdrop, as a cell of a rows x 2 rows grid sees
// it: the point and its normal, its albedo / pi, what the rig gives it (each light's share
// through `passes`), the sky the paper hides there (each times the cell's solid angle)
// and the harmonics, with the cosine's bands, of the direction.
struct BackdropPatch {
  glm::dvec3 p, n, albedo, rig, hidden;
  std::array<double, 9> y;
};

template <class F>
void for_each_backdrop_patch(const Studio& studio, const LightRig& rig, const BackdropSurface& backdrop,
                             const glm::dvec3& at, int rows, const LightPasses& passes, F&& f) {
  for_each_sphere_cell(rows, 2 * rows, [&](const glm::dvec3& d, double weight) {
    double t;
    glm::dvec3 n;
    if (!backdrop.intersect(at, d, 0.0, t, n)) return;
    const glm::dvec3 p = at + t * d;
    glm::dvec3 lit(0.0);
    if (passes) {
      for (const AreaLight& l : rig.lights) lit += l.radiance * l.irradiance_factor(p, n) * passes(p, l.center);
    } else {
      lit = rig.irradiance(p, n);
    }
    BackdropPatch patch{p, n, backdrop.albedo(p) / std::numbers::pi * weight, lit, studio.sky(d) * weight,
                        SkyIrradiance::basis(d)};
    for (int k = 0; k < 9; ++k) patch.y[size_t(k)] *= kCosineBand[size_t(k)];
    f(patch);
  });
}

}  // namespace

SkyIrradiance surround_irradiance(const Studio& studio, const SkyIrradiance& sky, const LightRig& rig,
                                  const BackdropSurface& backdrop, const PaperBounceMap& bounce, const glm::dvec3& at) {
  if (!backdrop.present) return sky;
  // The backdrop's patches of a 32 x 64 grid, each lit by the rig and by the paper's own
  // bounce where it is.
  SkyIrradiance out = sky;
  for_each_backdrop_patch(studio, rig, backdrop, at, 32, {}, [&](const BackdropPatch& patch) {
    const glm::dvec3 change = patch.albedo * (patch.rig + bounce.at(backdrop, patch.p)) - patch.hidden;
    for (int k = 0; k < 9; ++k) out.coef[size_t(k)] += change * patch.y[size_t(k)];
  });
  return out;
}

SkyIrradiance backdrop_share(const Studio& studio, const LightRig& rig, const BackdropSurface& backdrop,
                             const PaperBounceMap& bounce, const glm::dvec3& at, int rows, const LightPasses& passes) {
  SkyIrradiance share;
  if (!backdrop.present) return share;
  for_each_backdrop_patch(studio, rig, backdrop, at, rows, passes, [&](const BackdropPatch& patch) {
    const glm::dvec3 change = patch.albedo * (patch.rig + bounce.at(backdrop, patch.p)) - patch.hidden;
    for (int k = 0; k < 9; ++k) share.coef[size_t(k)] += change * patch.y[size_t(k)];
  });
  return share;
}

glm::dvec3 mean_radiance(const SkyIrradiance& s) {
  // The mean of E(n) over all n is its band-0 term, pi times the mean radiance.
  return s.coef[0] * SkyIrradiance::basis({0, 1, 0})[0] / std::numbers::pi;
}

namespace {

// A point's view differs from the centre's by the backdrop's share, taken on a coarser grid
// than the surround's (16 x 32: the paper lit by the surround already converged, so one
// pass) at both.
constexpr int kSeenFromRows = 16;

}  // namespace

SkyIrradiance environment_seen_from(const EnvironmentFrame& f, const SceneParams& p, const LightRig& rig,
                                    const BackdropSurface& backdrop, const glm::dvec3& at, const LightPasses& passes) {
  SkyIrradiance there = f.media.surround;  // (without a backdrop both shares are zero)
  const SkyIrradiance moved =
      backdrop_share(Studio(p), rig, backdrop, *f.paper_bounce, at, kSeenFromRows, passes);
  for (size_t k = 0; k < there.coef.size(); ++k) there.coef[k] += moved.coef[k] - f.centre_share.coef[k];
  return there;
}

EnvironmentFrame environment_frame(const SceneParams& p, const LightRig& rig, const BackdropSurface& backdrop,
                                   const std::vector<glm::dvec3>& seen_from, const LightPasses& passes) {
  EnvironmentFrame f;
  const Studio studio(p);
  f.sky = sky_irradiance(studio);
  // (A transparent picture's too: the studio lights its objects as it lights the opaque
  // picture's, a cutout of the same photograph; it only draws no floor.)
  f.paper_bounce = std::make_shared<const PaperBounceMap>(paper_bounce_map(rig, backdrop, f.sky, rig.aim));
  f.surround = surround_irradiance(studio, f.sky, rig, backdrop, *f.paper_bounce, rig.aim);
  f.media = media_light(studio, rig, f.surround);
  if (backdrop.present) f.centre_share = backdrop_share(studio, rig, backdrop, *f.paper_bounce, rig.aim, kSeenFromRows);
  for (const glm::dvec3& at : seen_from) f.media_seen_from.push_back(environment_seen_from(f, p, rig, backdrop, at, passes));
  f.image = studio.image;
  f.rotation_cos = float(studio.rotation_cos);
  f.rotation_sin = float(studio.rotation_sin);
  f.blur_lod = float(studio.blur_lod);
  f.intensity = p.env.intensity;
  // The sky's mean radiance over the sphere is its band-0 coefficient's share.
  glm::dvec3 mean = mean_radiance(f.sky);
  // Each light over the solid angle it covers at the centre (for a small light the
  // irradiance factor facing it is that solid angle), a 4 pi-th of the sphere.
  double best = 0;
  glm::dvec3 floor_light(0.0);  // irradiance on the backdrop under the centre
  const glm::dvec3 under(rig.aim.x, 0.0, rig.aim.z);
  for (const AreaLight& l : rig.lights) {
    const glm::dvec3 to = glm::normalize(l.center - rig.aim);
    const double facing = l.irradiance_factor(rig.aim, to);
    mean += l.radiance * facing / (4 * kPi);
    const glm::dvec3 e = l.radiance * facing;
    if (e.x + e.y + e.z > best) {
      best = e.x + e.y + e.z;
      f.glint_dir = glm::vec3(to);
      f.glint = glm::vec3(e);
    }
    floor_light += l.radiance * l.irradiance_factor(under, {0, 1, 0});
  }
  if (studio.image) image_glint(studio, f);
  // The backdrop fills about the lower half of what a bubble sees: lit paper.
  if (backdrop.present && p.env.mode != int(EnvMode::Constant))
    mean += 0.5 * backdrop.albedo(under) / kPi * (floor_light + f.sky.at({0, 1, 0}));
  f.reflected = glm::vec3(mean);
  return f;
}

}  // namespace draught
