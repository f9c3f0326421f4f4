#include "core/output/resolve.hpp"

#include "core/output/tonemap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {

void check_sample_count(const char* who, const std::vector<float>& samples, int width, int height, int factor) {
  if (width < 0 || height < 0 || factor < 1 ||
      samples.size() != size_t(width) * size_t(height) * size_t(factor) * size_t(factor) * 4)
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(samples.size()) + " sample values for " +
                                std::to_string(width) + " x " + std::to_string(height) + " pixels of " +
                                std::to_string(factor) + " x " + std::to_string(factor) + " samples");
}

void block_mean(const float* first, size_t row, int factor, double mean[4]) {
  double sum[4] = {0, 0, 0, 0};
  for (int j = 0; j < factor; ++j) {
    const float* s = first + size_t(j) * row;
    for (int i = 0; i < factor * 4; ++i) {
      const double v = s[i];
      sum[i % 4] += std::isfinite(v) ? v : 0.0;  // (a half float's overflow counts as none)
    }
  }
  const double n = double(factor) * double(factor);
  for (int c = 0; c < 4; ++c) mean[c] = sum[c] / n;
}

std::vector<double> sample_means(const std::vector<float>& samples, int width, int height, int factor) {
  check_sample_count("resolve_linear", samples, width, height, factor);
  std::vector<double> means(size_t(width) * size_t(height) * 4);
  const size_t row = size_t(width) * size_t(factor) * 4;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      block_mean(&samples[size_t(y * factor) * row + size_t(x) * size_t(factor) * 4], row, factor,
                 &means[(size_t(y) * size_t(width) + size_t(x)) * 4]);
  return means;
}

Image display_means(const std::vector<double>& means, int width, int height, int tonemap) {
  Image out{width, height, std::vector<std::uint8_t>(size_t(width) * size_t(height) * 4)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double* m = &means[(size_t(y) * size_t(width) + size_t(x)) * 4];
      std::uint8_t* o = out.px(x, y);
      for (int c = 0; c < 3; ++c) o[c] = display_code(m[c], tonemap);
      o[3] = std::uint8_t(std::lround(std::clamp(m[3], 0.0, 1.0) * 255.0));
    }
  return out;
}

Image resolve_linear(const std::vector<float>& samples, int width, int height, int factor, int tonemap) {
  return display_means(sample_means(samples, width, height, factor), width, height, tonemap);
}

}  // namespace draught
