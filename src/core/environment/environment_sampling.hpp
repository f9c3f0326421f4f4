// Directions towards an environment image chosen in proportion to its light: how the
// reference path tracer samples an HDR environment's light at each vertex (with multiple
// importance sampling against the vertex's own direction), so a small bright lamp in the
// image lights the floor and the head without a storm of fireflies.
//
// The density is piecewise constant over the texels of the image's first level at most 256
// wide: a texel is chosen in proportion to the brightest mean luminance of it and its eight
// neighbours (what the bilinear look-up can blend into it) times its solid angle, plus a
// tenth of the sphere's uniform share, then a direction uniform in solid angle within it.
#pragma once

#include "core/environment/studio.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

class EnvironmentSampler {
 public:
  explicit EnvironmentSampler(const Studio&);  // empty unless the studio has an image
  bool empty() const { return width_ == 0; }
  // A world direction (unit) from four uniforms in [0, 1), and its density per solid angle.
  glm::dvec3 sample(double u1, double u2, double u3, double u4, double& pdf) const;
  // The density with which sample() picks world direction d (unit).
  double pdf(const glm::dvec3& d) const;

 private:
  const Studio* studio_ = nullptr;
  int width_ = 0, height_ = 0;
  std::vector<double> row_cdf_;   // height + 1 entries, 0 .. 1
  std::vector<double> col_cdf_;   // per row, width + 1 entries, 0 .. 1
  std::vector<double> texel_p_;   // probability of each texel
  double row_cos(int j) const;    // cos theta at the top of row j
};

}  // namespace draught
