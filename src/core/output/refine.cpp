#include "core/output/refine.hpp"

#include "core/output/resolve.hpp"
#include "core/output/tonemap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {

std::vector<PixelRun> pixels_to_refine(const std::vector<float>& samples, int width, int height, int factor,
                                       int tonemap, double threshold) {
  check_sample_count("pixels_to_refine", samples, width, height, factor);
  std::vector<PixelRun> runs;
  if (factor < 2) return runs;  // one sample: nothing to disagree
  const size_t row = size_t(width) * size_t(factor) * 4;
  std::vector<char> differs(size_t(width) * size_t(height), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // (display_code rises with the light: the extremes' codes are the codes' extremes.)
      double lo[4] = {1e300, 1e300, 1e300, 1e300}, hi[4] = {-1e300, -1e300, -1e300, -1e300};
      for (int j = 0; j < factor; ++j) {
        const float* s = &samples[size_t(y * factor + j) * row + size_t(x) * size_t(factor) * 4];
        for (int i = 0; i < factor; ++i)
          for (int c = 0; c < 4; ++c) {
            const double v = std::isfinite(s[i * 4 + c]) ? double(s[i * 4 + c]) : 0.0;
            lo[c] = std::min(lo[c], v);
            hi[c] = std::max(hi[c], v);
          }
      }
      bool d = false;
      for (int c = 0; c < 3; ++c) d = d || display_code(hi[c], tonemap) - display_code(lo[c], tonemap) > threshold;
      d = d || 255.0 * (hi[3] - lo[3]) > threshold;  // an edge of a transparent picture's coverage
      differs[size_t(y) * size_t(width) + size_t(x)] = d;
    }
  // A pixel next to one whose samples disagree takes more too: detail thinner than the
  // samples' spacing that one pixel's samples caught may pass between its neighbour's.
  std::vector<char> refine(differs.size(), 0);
  // (Measured on the reference comparisons, docs/REFERENCE.md: without it the bar's glass
  // was 4.15 / 6.97, with it 2.31 / 4.97, as with 4 x 4 samples everywhere.)
  constexpr int kReach = 1;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      bool any = false;
      for (int j = std::max(0, y - kReach); j <= std::min(height - 1, y + kReach) && !any; ++j)
        for (int i = std::max(0, x - kReach); i <= std::min(width - 1, x + kReach) && !any; ++i)
          any = differs[size_t(j) * size_t(width) + size_t(i)];
      refine[size_t(y) * size_t(width) + size_t(x)] = any;
    }
  for (int y = 0; y < height; ++y) {
    int start = -1;
    for (int x = 0; x <= width; ++x) {
      const bool r = x < width && refine[size_t(y) * size_t(width) + size_t(x)];
      if (r && start < 0) start = x;
      if (!r && start >= 0) {
        runs.push_back({start, y, x - start});
        start = -1;
      }
    }
  }
  return runs;
}

std::vector<float> samples_from_display(const Image& img) {
  static const std::array<float, 256> decoded = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = float(srgb_to_linear(i / 255.0));
    return t;
  }();
  std::vector<float> s(img.rgba.size());
  for (size_t i = 0; i < img.rgba.size(); ++i) s[i] = i % 4 == 3 ? float(img.rgba[i] / 255.0) : decoded[img.rgba[i]];
  return s;
}

long pixels_in(const std::vector<PixelRun>& runs) {
  long n = 0;
  for (const PixelRun& r : runs) n += r.length;
  return n;
}

Image resolve_refined(const std::vector<float>& samples, int width, int height, int factor,
                      const RefinedSamples& refined, int tonemap) {
  std::vector<double> means = sample_means(samples, width, height, factor);
  const int fine = refined.fine;
  if (fine < 1 || refined.rgba.size() != size_t(pixels_in(refined.runs)) * size_t(fine) * size_t(fine) * 4)
    throw std::invalid_argument("resolve_refined: " + std::to_string(refined.rgba.size()) +
                                " fine sample values for " + std::to_string(pixels_in(refined.runs)) +
                                " pixels of " + std::to_string(fine) + " x " + std::to_string(fine) + " samples");
  size_t at = 0;  // the run's first sample value
  for (const PixelRun& r : refined.runs) {
    if (r.y < 0 || r.y >= height || r.x < 0 || r.length < 0 || r.x + r.length > width)
      throw std::invalid_argument("resolve_refined: the run of " + std::to_string(r.length) + " pixels at (" +
                                  std::to_string(r.x) + ", " + std::to_string(r.y) + ") leaves the " +
                                  std::to_string(width) + " x " + std::to_string(height) + " picture");
    const size_t row = size_t(r.length) * size_t(fine) * 4;
    for (int k = 0; k < r.length; ++k)
      block_mean(&refined.rgba[at + size_t(k) * size_t(fine) * 4], row, fine,
                 &means[(size_t(r.y) * size_t(width) + size_t(r.x + k)) * 4]);
    at += row * size_t(fine);
  }
  return display_means(means, width, height, tonemap);
}

}  // namespace draught
