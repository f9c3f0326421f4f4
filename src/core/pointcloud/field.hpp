// The surface of a point cloud: point i (centre c_i, support radius R_i) adds
// k(s) = (1 - s)^3 for s = |p - c_i|^2 / R_i^2 < 1 (C2 where the support ends), F = sum k_i,
// the surface is F = threshold, its normal normalize(-grad F), its temperature and colour
// the k-weighted means of the points'. F sums exactly the points whose support holds p, so
// no result depends on how a tree splits them (docs/POINT_CLOUDS.md).
//
// Two implementations: the reference (double, every point, no tree: for tests and
// probes) and the float twin of shaders/lib/pointcloud/march.glsl, which reads the texel
// arrays of core/pointcloud/cloud_texels.hpp step by step as the shader does.
#pragma once

#include "core/pointcloud/cloud.hpp"
#include "core/pointcloud/cloud_texels.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace draught {

inline constexpr int kCloudMaxSteps = contract::kCloudMaxSteps;
inline constexpr int kCloudBisections = contract::kCloudBisections;
inline constexpr int kCloudRefinements = contract::kCloudRefinements;
inline constexpr float kCloudStepFraction = contract::kCloudStepFraction;
inline constexpr int kCloudStrideSteps = contract::kCloudStrideSteps;
inline constexpr float kCloudStrideMargin = contract::kCloudStrideMargin;
inline constexpr float kCloudThreshold = contract::kCloudThreshold;

// The support radius over the blob radius: a lone point of blob radius r is a sphere of
// radius r at F = threshold when R = r / sqrt(1 - threshold^(1/3)) (2.2014 for 0.5).
double cloud_support_scale(double threshold);

// The kernel (1 - s)^3 for s < 1, else 0.
inline double cloud_kernel(double s) { return s < 1.0 ? (1.0 - s) * (1.0 - s) * (1.0 - s) : 0.0; }

// ---- the reference: double precision, every point of the cloud (world positions) ----
double cloud_field_reference(const PointCloud&, double threshold, glm::dvec3 p);
glm::dvec3 cloud_gradient_reference(const PointCloud&, double threshold, glm::dvec3 p);

struct CloudReferenceHit {
  double t = 0;
  glm::dvec3 n{0.0};      // normalize(-grad F)
  glm::dvec4 attrs{0.0};  // k-weighted temperature, r, g, b (0 where the cloud gives none)
};
// The first crossing of F = threshold along o + t d (d unit), t in [tmin, tmax]: from
// outside (F rises through it) or, inside = true, from F >= threshold (the exit). F along
// the ray is a polynomial of degree 6 between the ends of the supports it crosses; each
// piece is cut in 16 and every sign change of F - threshold, and every minimum of the
// distance to it found through its derivative's sign change, is bisected to the bit.
std::optional<CloudReferenceHit> march_cloud_reference(const PointCloud&, double threshold, glm::dvec3 o, glm::dvec3 d,
                                                       double tmin, double tmax, bool inside);
// How close F comes to the threshold from the start side over [tmin, tmax]: the largest F
// (inside false) or the smallest (true) along the ray, found as march_cloud_reference finds
// crossings. Tests call a disagreement "tangent" when this is near the threshold.
double cloud_ray_extreme_reference(const PointCloud&, double threshold, glm::dvec3 o, glm::dvec3 d, double tmin,
                                   double tmax, bool inside);

// ---- the float twin of lib/pointcloud/march.glsl over CloudTexels ----
struct CloudRef {
  int root = -1;            // the cloud's root node in the shared arrays (-1: empty)
  float threshold = kCloudThreshold;
  float min_support = 0;    // the cloud's smallest support radius (m)
  glm::vec3 lo{0.0f}, hi{0.0f};  // its root box
};
CloudRef cloud_ref(const CloudRange&, float threshold = kCloudThreshold);

struct CloudSample {
  float f = 0;
  glm::vec3 grad{0.0f};
};
// F and grad F at p from the points whose support holds p (the tree's point query).
CloudSample cloud_field(const CloudTexels&, const CloudRef&, glm::vec3 p);
// The k-weighted temperature and colour at p (0 where no support holds p).
glm::vec4 cloud_attrs(const CloudTexels&, const CloudRef&, glm::vec3 p);
// The smallest t >= tmin at which o + t d (d unit) is in a support, below limit: the
// ordered nearest-entry traversal (near child first, boxes beyond the best pruned).
// INFINITY when there is none.
float cloud_next_entry(const CloudTexels&, const CloudRef&, glm::vec3 o, glm::vec3 d, float tmin, float limit);
// The point texels whose support the ray crosses within [tmin, tmax], through the tree
// (tests: traversal equals brute force), in the order the traversal meets them.
std::vector<int> cloud_supports_crossed(const CloudTexels&, const CloudRef&, glm::vec3 o, glm::vec3 d, float tmin,
                                        float tmax);

struct CloudHit {
  float t = 0;
  glm::vec3 n{0.0f};
  glm::vec4 attrs{0.0f};
  int steps = 0;    // loop iterations used
  int queries = 0;  // point and entry queries made
};
// The march (docs/POINT_CLOUDS.md): clip to the root box; outside every support, jump
// to the next support entry; inside, steps of kCloudStepFraction * min_support, each
// sample a point query; a sign change of F - threshold, or a dip towards it that the
// samples' values and slopes predict (the cubic Hermite minimum, sampled when predicted
// within a tenth of the threshold), is narrowed by kCloudRefinements samples (the first
// kCloudBisections at its middle, the rest at the root of the cubic Hermite interpolant
// of the bracket's ends) and the crossing placed at that cubic's root. A march from
// inside strides kCloudStrideSteps steps (or half of them) where its sample's lower bound
// on F over the stride clears the threshold: it cannot leave before. At most
// kCloudMaxSteps iterations. Twin: march_cloud in lib/pointcloud/march.glsl, which makes
// each sample a point query; here the tree is opened once a ray, in the order the ray
// enters its boxes, and each sample sums the supports met that overlap its step (the same
// points in the same order, so the same value).
std::optional<CloudHit> march_cloud(const CloudTexels&, const CloudRef&, glm::vec3 o, glm::vec3 d, float tmin,
                                    float tmax, bool inside);
// The same march with every query a loop over all the cloud's points (the benchmark's
// baseline: what the tree saves).
std::optional<CloudHit> march_cloud_all_points(const CloudTexels&, const CloudRef&, const CloudRange&, glm::vec3 o,
                                               glm::vec3 d, float tmin, float tmax, bool inside);

}  // namespace draught
