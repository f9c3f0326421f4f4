#include "core/environment/environment_sampling.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
constexpr double kUniformShare = 0.1;  // of the probability, spread evenly over the sphere
}  // namespace

double EnvironmentSampler::row_cos(int j) const { return std::cos(kPi * j / height_); }

EnvironmentSampler::EnvironmentSampler(const Studio& studio) {
  if (!studio.image) return;
  studio_ = &studio;
  const EnvironmentMap& map = *studio.image;
  size_t level = 0;
  while (level + 1 < map.levels.size() && map.levels[level].width > 256) ++level;
  const HdrImage& img = map.levels[level];
  width_ = img.width;
  height_ = img.height;
  std::vector<double> luminance(size_t(width_) * size_t(height_));
  for (int j = 0; j < height_; ++j)
    for (int i = 0; i < width_; ++i) {
      const glm::vec3 c = img.at(i, j);
      luminance[size_t(j) * size_t(width_) + size_t(i)] = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    }
  // A texel's weight is the brightest of it and its eight neighbours (across the seam, not
  // past the poles): the bilinear look-up inside a texel blends only those, so the light
  // seen anywhere in it is at most its weight. Weighted by its own luminance alone, the
  // texels around a small lamp were picked at the uniform share's rate while seeing a good
  // part of the lamp, and single samples carried 2 % of a 200,000-sample estimate.
  std::vector<double> weight(luminance.size());
  double total = 0;
  for (int j = 0; j < height_; ++j) {
    const double solid = (row_cos(j) - row_cos(j + 1)) * 2 * kPi / width_;
    for (int i = 0; i < width_; ++i) {
      double brightest = 0;
      for (int dj = -1; dj <= 1; ++dj) {
        const int jj = std::clamp(j + dj, 0, height_ - 1);
        for (int di = -1; di <= 1; ++di)
          brightest = std::max(brightest, luminance[size_t(jj) * size_t(width_) + size_t((i + di + width_) % width_)]);
      }
      const double w = brightest * solid;
      weight[size_t(j) * size_t(width_) + size_t(i)] = w;
      total += w;
    }
  }
  texel_p_.resize(weight.size());
  for (int j = 0; j < height_; ++j) {
    const double solid = (row_cos(j) - row_cos(j + 1)) * 2 * kPi / width_;
    for (int i = 0; i < width_; ++i) {
      const size_t k = size_t(j) * size_t(width_) + size_t(i);
      const double lit = total > 0 ? weight[k] / total : 0.0;
      texel_p_[k] = (1 - kUniformShare) * lit + kUniformShare * solid / (4 * kPi);
    }
  }
  row_cdf_.assign(size_t(height_) + 1, 0.0);
  col_cdf_.assign(size_t(height_) * (size_t(width_) + 1), 0.0);
  for (int j = 0; j < height_; ++j) {
    double row = 0;
    double* cdf = &col_cdf_[size_t(j) * (size_t(width_) + 1)];
    for (int i = 0; i < width_; ++i) {
      row += texel_p_[size_t(j) * size_t(width_) + size_t(i)];
      cdf[i + 1] = row;
    }
    for (int i = 1; i <= width_; ++i) cdf[i] /= row;
    row_cdf_[size_t(j) + 1] = row_cdf_[size_t(j)] + row;
  }
  for (double& c : row_cdf_) c /= row_cdf_.back();
}

glm::dvec3 EnvironmentSampler::sample(double u1, double u2, double u3, double u4, double& pdf) const {
  const int j = std::clamp(int(std::upper_bound(row_cdf_.begin(), row_cdf_.end(), u1) - row_cdf_.begin()) - 1, 0, height_ - 1);
  const double* cdf = &col_cdf_[size_t(j) * (size_t(width_) + 1)];
  const int i = std::clamp(int(std::upper_bound(cdf, cdf + width_ + 1, u2) - cdf) - 1, 0, width_ - 1);
  // Uniform in solid angle within the texel: uniform across, cos theta uniform down.
  const double u = (i + u3) / width_;
  const double cos_t = row_cos(j) + (row_cos(j + 1) - row_cos(j)) * u4;
  const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t)), a = 2 * kPi * (u - 0.5);
  const glm::dvec3 e(sin_t * std::sin(a), cos_t, -sin_t * std::cos(a));
  const double solid = (row_cos(j) - row_cos(j + 1)) * 2 * kPi / width_;
  pdf = texel_p_[size_t(j) * size_t(width_) + size_t(i)] / solid;
  return studio_->world_direction(e);
}

double EnvironmentSampler::pdf(const glm::dvec3& d) const {
  if (empty()) return 0;
  const glm::dvec2 uv = equirect_uv(studio_->image_direction(d));
  const int i = std::clamp(int(uv.x * width_), 0, width_ - 1), j = std::clamp(int(uv.y * height_), 0, height_ - 1);
  const double solid = (row_cos(j) - row_cos(j + 1)) * 2 * kPi / width_;
  return texel_p_[size_t(j) * size_t(width_) + size_t(i)] / solid;
}

}  // namespace draught
