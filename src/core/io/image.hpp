// 8-bit RGBA images, rows top-down; PNG in and out through stb.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace draught {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4
  std::uint8_t* px(int x, int y) { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
  const std::uint8_t* px(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

// Box filter over factor x factor blocks (supersampling resolve), averaged in linear
// light: the sRGB codes are decoded, averaged and encoded again, so an edge between
// black and white comes out as half the light (188), not half the code (128).
Image downsample(const Image&, int factor);
std::string encode_png(const Image&);
void write_png(const std::filesystem::path&, const Image&);  // atomic
Image read_png(const std::filesystem::path&);                // throws InputError

}  // namespace draught
