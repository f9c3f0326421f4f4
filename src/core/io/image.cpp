#include "core/io/image.hpp"

#include "core/io/files.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <stb_image.h>
#include <stb_image_write.h>

namespace draught {

Image downsample(const Image& in, int f) {
  if (f <= 1) return in;
  // sRGB code -> linear light, once; the mean goes back through the inverse, rounded.
  static const std::array<double, 256> to_linear = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[size_t(i)] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    return t;
  }();
  auto to_srgb8 = [](double c) {
    c = std::clamp(c, 0.0, 1.0);
    const double s = c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return std::uint8_t(std::lround(s * 255.0));
  };
  Image out{in.width / f, in.height / f, {}};
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  const double n = double(f * f);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      double sum[4] = {0, 0, 0, 0};
      for (int j = 0; j < f; ++j)
        for (int i = 0; i < f; ++i) {
          const std::uint8_t* p = in.px(x * f + i, y * f + j);
          for (int c = 0; c < 3; ++c) sum[c] += to_linear[p[c]];
          sum[3] += p[3];
        }
      std::uint8_t* o = out.px(x, y);
      for (int c = 0; c < 3; ++c) o[c] = to_srgb8(sum[c] / n);
      o[3] = std::uint8_t(std::lround(sum[3] / n));  // coverage is linear already
    }
  return out;
}

std::string encode_png(const Image& img) {
  std::string out;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
  };
  stbi_write_png_to_func(sink, &out, img.width, img.height, 4, img.rgba.data(), img.width * 4);
  return out;
}

void write_png(const std::filesystem::path& path, const Image& img) { write_file_atomic(path, encode_png(img)); }

Image read_png(const std::filesystem::path& path) {
  int w, h, n;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) throw InputError(path.string() + ": cannot read image: " + stbi_failure_reason());
  Image img{w, h, std::vector<std::uint8_t>(data, data + size_t(w) * size_t(h) * 4)};
  stbi_image_free(data);
  return img;
}

}  // namespace draught
