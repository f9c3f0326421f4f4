#include "core/io/image.hpp"

#include "core/io/files.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

namespace draught {

Image downsample(const Image& in, int f) {
  if (f <= 1) return in;
  Image out{in.width / f, in.height / f, {}};
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int j = 0; j < f; ++j)
          for (int i = 0; i < f; ++i) sum += in.px(x * f + i, y * f + j)[c];
        out.px(x, y)[c] = std::uint8_t((sum + f * f / 2) / (f * f));
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
