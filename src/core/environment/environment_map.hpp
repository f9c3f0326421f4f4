// An equirectangular HDR environment as light by direction, with a chain of ever
// blurrier levels so rough glass, the liquid's surface and the foam's ambient light can
// read it at the level of detail they need. The C++ twin of shaders/lib/environment/
// image.glsl: the same mapping from direction to texel, the same filtering (bilinear in a
// level, linear between levels), so the GPU's picture and the reference agree.
#pragma once

#include "core/io/hdr_image.hpp"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace draught {

// The smallest environment accepted, and the smallest level of the chain.
inline constexpr int kMinEnvironmentWidth = 8;

// Where direction d (unit; +y up) lands in an equirectangular image, u across (wrapping)
// and v down, both in [0, 1]: the image's centre is seen looking along -z (behind a glass
// seen from the default camera), +x is to its right, the top row straight up.
glm::dvec2 equirect_uv(const glm::dvec3& d);
// Its inverse: the unit direction seen at (u, v).
glm::dvec3 equirect_direction(const glm::dvec2& uv);

struct EnvironmentMap {
  std::vector<HdrImage> levels;  // [0] the image, each next half the size down to 8 x 4

  // Radiance from direction d (unit) at level of detail `lod` (0: the image; 1: half its
  // resolution; fractions blend two levels; clamped to the chain).
  glm::dvec3 radiance(const glm::dvec3& d, double lod = 0) const;
  int width() const { return levels.empty() ? 0 : levels.front().width; }
  int height() const { return levels.empty() ? 0 : levels.front().height; }
};

// The level of detail whose texels span `angle` radians around the equator (0 for
// angles finer than the image's own texels).
double environment_lod(const EnvironmentMap&, double angle);

// The chain of an equirectangular image (twice as wide as high, at least 8 x 4); `name`
// (the file) begins the InputError for any other shape.
EnvironmentMap make_environment_map(HdrImage image, const std::string& name);
EnvironmentMap read_environment_map(const std::filesystem::path&);

}  // namespace draught
