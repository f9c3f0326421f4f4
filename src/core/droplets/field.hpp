// A metaball field of droplets: up to kMaxDroplets spheres blended by a smooth minimum,
// optionally displaced by value noise, as a signed distance bound. The reference in
// double precision; GLSL twin shaders/lib/droplets/field.glsl (same function names).
// docs/DROPLETS.md. Reusable by anything that beads water (a trail, condensation).
#pragma once

#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace draught {

inline constexpr int kMaxDroplets = contract::kMaxDroplets;
inline constexpr int kDropletMaxSteps = contract::kDropletMaxSteps;
inline constexpr double kDropletHitEps = contract::kDropletHitEps;

// How the spheres blend: Polynomial is the quadratic smooth minimum folded sphere by
// sphere (local: spheres farther apart than the blend width do not touch, the result is
// their plain min); Exponential is -w log sum exp(-d_i / w) over all spheres (order free,
// but it lowers the field everywhere by up to w log N).
enum class BlendKernel : int { Polynomial = 0, Exponential = 1 };

struct DropletSphere {
  glm::dvec3 centre{0.0};  // world, m
  double radius = 0;       // m
};

struct DropletField {
  std::vector<DropletSphere> spheres;  // at most kMaxDroplets
  BlendKernel kernel = BlendKernel::Polynomial;
  double blend = 0.01;            // m: the blend width (k of the smooth minimum)
  double noise_amplitude = 0;     // m: the displacement is A (2 n(f p) - 1), n in [0, 1]
  double noise_frequency = 50;    // 1/m
};

// A value and its gradient.
struct FieldSample {
  double d = 0;
  glm::dvec3 grad{0.0};
  double blend = 0;  // the spheres' blend before the noise: d - blend is within [-A, A]
};

// The quadratic smooth minimum of a and b with blend width k (> 0), and the weight of a
// in its gradient (the weight of b is 1 - wa): wa in [0, 1], so blending never makes a
// gradient longer than its inputs'. smin(a, b) = smin(b, a); |a - b| >= k: min(a, b).
double droplet_smin(double a, double b, double k, double& wa);
// The exponential kernel's width for blend width k: two equal distances are lowered by
// k / 4, as by the quadratic one.
double droplet_exp_width(double k);

// Value noise (the hash of core/math/noise.hpp, smoothstep-interpolated, in [0, 1]) and
// its analytic gradient: (n, dn/dx, dn/dy, dn/dz). Its gradient is at most 1.5 sqrt(3)
// long (smoothstep's slope is at most 1.5 per axis, corner values differ by at most 1).
glm::dvec4 droplet_noise(glm::dvec3 x);

// The field's value (a lower bound on the distance to its surface, divided by the
// Lipschitz bound below) and its analytic gradient (not normalised) at p.
FieldSample droplet_field(const DropletField&, glm::dvec3 p);
double droplet_value(const DropletField&, glm::dvec3 p);

// The Lipschitz bound L of the blended and displaced field: every sphere's distance is
// 1-Lipschitz; both kernels' gradients are convex combinations of their inputs' (weights
// in [0, 1] summing to 1), so the blend is 1-Lipschitz; the noise adds at most
// 2 A f 1.5 sqrt(3). L = 1 + 3 sqrt(3) A f. A march stepping value / L never oversteps.
double droplet_lipschitz(const DropletField&);

// How far below min_i |p - c_i| - r_i the blend can take the field: the quadratic fold
// lowers it by less than k (induction: smin(D, d) >= min(D, d) - k when D >= m - k), the
// exponential one by at most w log N. The surface lies within the spheres grown by
// this plus the noise amplitude.
double droplet_reach(const DropletField&);

struct DropletBounds {
  glm::dvec3 lo{0.0}, hi{0.0};
  bool empty = true;
};
// The box around the union of the spheres grown by droplet_reach (the field is positive
// outside it).
DropletBounds droplet_bounds(const DropletField&);

struct DropletHit {
  double t = 0;
  glm::dvec3 n{0.0};  // unit outward normal (the field's gradient)
  int steps = 0;
};

// The first crossing of the field's surface along o + t d (d unit) for t in [tmin, tmax]:
// from outside (inside = false: the field goes from + to -) or from inside a droplet
// (inside = true). The ray is clipped to droplet_bounds and then to droplet_sphere_span
// (a line through the gaps of a stretched trail marches nothing). Around each point the march
// knows a radius free of the surface: value / L (Lipschitz), or where the spheres' blend
// b (before the noise, 1-Lipschitz) exceeds the noise amplitude A, b - A if larger (the
// surface needs b <= A), so far from the droplets the steps are the blend's distance, not
// a fraction of it. A step is that radius (it never passes the surface), over-relaxed by
// kDropletRelax where the free spheres at both ends overlap (after a try that fails, the
// safe step and then one more without a try), and where the value is below
// kDropletHitEps a skim step of kDropletSkim; every step's end is sampled, and a sign
// change there (a bracket no longer than a skim) is narrowed by kDropletRefinements
// steps of the Illinois method (regula falsi, the value at an end kept twice in a row
// halved) and the hit placed by the line through the bracket's ends (it lies on the
// surface to within a nanometre, not within eps of it; its normal is the bracket ends'
// gradients mixed at the same share). What
// a skim step can miss: a dip through the surface shorter than the skim, i.e. less than
// skim^2 kappa / 8 deep for curvature kappa (under a micrometre for droplets of
// millimetres; tests/unit/droplets). At most kDropletMaxSteps steps.
// Twin: march_droplets in lib/droplets/field.glsl (float, the same samples in the same
// order, one per iteration of a single loop).
inline constexpr double kDropletSkim = 4.0 * kDropletHitEps;
inline constexpr int kDropletRefinements = 3;
inline constexpr double kDropletRelax = 1.6;
std::optional<DropletHit> march_droplets(const DropletField&, glm::dvec3 o, glm::dvec3 d, double tmin,
                                         double tmax, bool inside);

// The span [t0, t1] of o + t d inside the box (false: it misses or lies before tmin).
bool droplet_box_span(const DropletBounds&, glm::dvec3 o, glm::dvec3 d, double tmin, double tmax, double& t0,
                      double& t1);

// How far the spheres are grown for droplet_sphere_span: droplet_reach and the box's
// margin, 2 kDropletSkim (the renderer's frame.droplet_margin).
double droplet_margin(const DropletField&);

// Narrows [t0, t1] of o + t d (d unit) to where it first enters one of the spheres grown by
// droplet_margin and last leaves one (false: it meets none there). The surface lies
// within them. Twin: droplet_sphere_span (GLSL).
bool droplet_sphere_span(const DropletField&, glm::dvec3 o, glm::dvec3 d, double& t0, double& t1);

}  // namespace draught
