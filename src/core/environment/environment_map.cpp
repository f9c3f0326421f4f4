#include "core/environment/environment_map.hpp"

#include "core/io/files.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

glm::dvec2 equirect_uv(const glm::dvec3& d) {
  const double u = 0.5 + std::atan2(d.x, -d.z) / (2 * kPi);
  const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
  return {u, v};
}

glm::dvec3 equirect_direction(const glm::dvec2& uv) {
  const double theta = uv.y * kPi, a = 2 * kPi * (uv.x - 0.5);  // a = atan2(x, -z)
  return {std::sin(theta) * std::sin(a), std::cos(theta), -std::sin(theta) * std::cos(a)};
}

double environment_lod(const EnvironmentMap& m, double angle) {
  if (m.levels.empty() || !(angle > 0)) return 0;
  const double texel = 2 * kPi / m.width();
  return std::clamp(std::log2(angle / texel), 0.0, double(m.levels.size() - 1));
}

namespace {

// Bilinear in one level at (u, v): wraps across, clamps at the poles (as the GPU's
// REPEAT and CLAMP_TO_EDGE), texel centres at (i + 0.5) / size.
glm::dvec3 bilinear(const HdrImage& img, glm::dvec2 uv) {
  const double x = uv.x * img.width - 0.5, y = std::clamp(uv.y * img.height - 0.5, 0.0, img.height - 1.0);
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  auto wrap = [&](long long i) { return int(((i % img.width) + img.width) % img.width); };
  const int x0 = wrap((long long)fx), x1 = wrap((long long)fx + 1);
  const int y0 = int(fy), y1 = std::min(y0 + 1, img.height - 1);
  const glm::dvec3 top = glm::mix(glm::dvec3(img.at(x0, y0)), glm::dvec3(img.at(x1, y0)), ax);
  const glm::dvec3 bottom = glm::mix(glm::dvec3(img.at(x0, y1)), glm::dvec3(img.at(x1, y1)), ax);
  return glm::mix(top, bottom, ay);
}

// The next level: each texel the mean of the 2 x 2 it covers (an odd last row or column
// is left out).
HdrImage half(const HdrImage& in) {
  HdrImage out{in.width / 2, in.height / 2, {}};
  out.rgb.resize(size_t(out.width) * size_t(out.height));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      out.rgb[size_t(y) * size_t(out.width) + size_t(x)] =
          0.25f * (in.at(2 * x, 2 * y) + in.at(2 * x + 1, 2 * y) + in.at(2 * x, 2 * y + 1) + in.at(2 * x + 1, 2 * y + 1));
  return out;
}

}  // namespace

glm::dvec3 EnvironmentMap::radiance(const glm::dvec3& d, double lod) const {
  const glm::dvec2 uv = equirect_uv(d);
  lod = std::clamp(lod, 0.0, double(levels.size() - 1));
  const int l0 = int(std::floor(lod));
  const int l1 = std::min(l0 + 1, int(levels.size()) - 1);
  const glm::dvec3 a = bilinear(levels[size_t(l0)], uv);
  return l1 == l0 ? a : glm::mix(a, bilinear(levels[size_t(l1)], uv), lod - l0);
}

EnvironmentMap make_environment_map(HdrImage image, const std::string& name) {
  const int w = image.width, h = image.height;
  if (w != 2 * h)
    throw InputError(name + ": " + std::to_string(w) + " x " + std::to_string(h) +
                     " pixels; an equirectangular environment is exactly twice as wide as high");
  if (w < kMinEnvironmentWidth)
    throw InputError(name + ": " + std::to_string(w) + " x " + std::to_string(h) + " pixels; an environment needs at least " +
                     std::to_string(kMinEnvironmentWidth) + " x " + std::to_string(kMinEnvironmentWidth / 2));
  EnvironmentMap map;
  map.levels.push_back(std::move(image));
  // Halve (rounding down, as a GL mip chain does) while the result is no smaller than
  // the minimum.
  while (map.levels.back().width / 2 >= kMinEnvironmentWidth)
    map.levels.push_back(half(map.levels.back()));
  return map;
}

EnvironmentMap read_environment_map(const std::filesystem::path& path) {
  return make_environment_map(read_hdr_image(path), path.string());
}

}  // namespace draught
