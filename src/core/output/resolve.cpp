#include "core/output/resolve.hpp"

#include "core/output/tonemap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {

Image resolve_linear(const std::vector<float>& samples, int width, int height, int factor, int tonemap) {
  if (width < 0 || height < 0 || factor < 1 ||
      samples.size() != size_t(width) * size_t(height) * size_t(factor) * size_t(factor) * 4)
    throw std::invalid_argument("resolve_linear: " + std::to_string(samples.size()) + " sample values for " +
                                std::to_string(width) + " x " + std::to_string(height) + " pixels of " +
                                std::to_string(factor) + " x " + std::to_string(factor) + " samples");
  Image out{width, height, std::vector<std::uint8_t>(size_t(width) * size_t(height) * 4)};
  const size_t row = size_t(width) * size_t(factor) * 4;
  const double n = double(factor) * double(factor);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum[4] = {0, 0, 0, 0};
      for (int j = 0; j < factor; ++j) {
        const float* s = &samples[size_t(y * factor + j) * row + size_t(x) * size_t(factor) * 4];
        for (int i = 0; i < factor * 4; ++i) {
          const double v = s[i];
          sum[i % 4] += std::isfinite(v) ? v : 0.0;  // (a half float's overflow counts as none)
        }
      }
      std::uint8_t* o = out.px(x, y);
      for (int c = 0; c < 3; ++c) o[c] = display_code(sum[c] / n, tonemap);
      o[3] = std::uint8_t(std::lround(std::clamp(sum[3] / n, 0.0, 1.0) * 255.0));
    }
  return out;
}

}  // namespace draught
