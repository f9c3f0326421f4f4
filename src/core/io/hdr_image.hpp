// High-dynamic-range images in linear light (float RGB, rows top-down): Radiance .hdr
// through stb_image and OpenEXR .exr through tinyexr. Environments are read with it.
#pragma once

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace draught {

struct HdrImage {
  int width = 0, height = 0;
  std::vector<glm::vec3> rgb;  // width * height, linear, rows top-down
  const glm::vec3& at(int x, int y) const { return rgb[size_t(y) * size_t(width) + size_t(x)]; }
};

// The largest HDR image accepted, per side and in all: an equirectangular 8k environment.
inline constexpr int kMaxHdrImageWidth = 8192;
inline constexpr int kMaxHdrImageHeight = 4096;
// The largest value a texel keeps: half float's largest, as the GPU stores it. Larger
// values, infinities and NaNs are clamped (NaN and negatives to 0); `clamped` counts them.
inline constexpr float kMaxHdrValue = 65504.0f;

struct HdrDecodeReport {
  size_t clamped = 0;  // texel channels that were not finite, negative or above kMaxHdrValue
};

// Decodes a whole file's bytes; `name` (the file) begins every error. Throws InputError
// saying what was expected: an HDR format, a size in range, an undamaged file. An 8-bit
// image (PNG, JPEG, ...) is refused by name: it cannot hold the light of a real scene.
HdrImage decode_hdr_image(std::string_view bytes, const std::string& name, HdrDecodeReport* report = nullptr);
HdrImage read_hdr_image(const std::filesystem::path&, HdrDecodeReport* report = nullptr);

// The Radiance .hdr bytes of an image (RLE RGBE, as stb_image_write makes them), and
// the file written atomically.
std::string encode_radiance_hdr(const HdrImage&);
void write_radiance_hdr(const std::filesystem::path&, const HdrImage&);

// The OpenEXR .exr bytes of an image (32-bit float R, G and B, ZIP-compressed: the
// values exactly as given), and the file written atomically. Native builds only (as
// reading: hdr_image_reads_exr); elsewhere they throw InputError.
std::string encode_exr(const HdrImage&);
void write_exr(const std::filesystem::path&, const HdrImage&);

// Whether this build reads OpenEXR (the web build does not: no zlib there).
bool hdr_image_reads_exr();

}  // namespace draught
