// 8-bit RGBA images, rows top-down; PNG in and out through stb.
#pragma once

#include "core/math/srgb.hpp"  // (the 8-bit codes of its pictures)

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace draught {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4
  std::uint8_t* px(int x, int y) { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
  const std::uint8_t* px(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

// Box filter over factor x factor blocks of display values (a transparent picture's
// supersamples, each already tone mapped; opaque ones are resolved before the tone map:
// core/output/resolve), averaged in linear light: the sRGB codes are decoded, averaged
// and encoded again, so an edge between black and white comes out as half the light
// (188), not half the code (128).
Image downsample(const Image&, int factor);
std::string encode_png(const Image&);
void write_png(const std::filesystem::path&, const Image&);  // atomic
Image read_png(const std::filesystem::path&);                // throws InputError

// The largest PNG a user may give (decals): 4096 pixels a side, and a file of at most
// kMaxPngFileBytes (a 4096 x 4096 RGBA PNG that does not compress is 64 MiB).
inline constexpr int kMaxPngSide = 4096;
inline constexpr std::uintmax_t kMaxPngFileBytes = 80u << 20;

// Decodes a whole PNG file's bytes, strictly: the signature, every chunk's length and
// checksum, the header's size (1 .. max_side pixels a side) and format, image data and
// the end chunk are checked before stb decodes it (stb trusts a file cut short and
// decodes what is missing as black). Throws InputError beginning with `name` and saying
// what was expected: not a PNG (naming what it is instead), no pixels, too large,
// damaged or cut short. Any colour type and bit depth comes out as 8-bit RGBA.
Image decode_png(std::string_view bytes, const std::string& name, int max_side = kMaxPngSide);

}  // namespace draught
