#include "core/io/image.hpp"

#include "core/io/files.hpp"
#include "core/text/echo.hpp"
#include "core/io/bytes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <stb_image.h>
#include <stb_image_write.h>

namespace draught {

Image downsample(const Image& in, int f) {
  if (f <= 1) return in;
  // sRGB codes -> linear light; the mean goes back through the inverse, rounded.
  Image out{in.width / f, in.height / f, {}};
  out.rgba.resize(size_t(out.width) * size_t(out.height) * 4);
  const double n = double(f * f);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      double sum[4] = {0, 0, 0, 0};
      for (int j = 0; j < f; ++j)
        for (int i = 0; i < f; ++i) {
          const std::uint8_t* p = in.px(x * f + i, y * f + j);
          for (int c = 0; c < 3; ++c) sum[c] += srgb8_to_linear(p[c]);
          sum[3] += p[3];
        }
      std::uint8_t* o = out.px(x, y);
      for (int c = 0; c < 3; ++c) o[c] = linear_to_srgb8(sum[c] / n);
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

namespace {

// CRC-32 of the PNG specification (the zlib polynomial), for each chunk's checksum: the
// web build has no zlib.
std::uint32_t crc32(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

// What a file that is not a PNG is, by its first bytes.
std::string what_it_is(std::string_view b) {
  auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
  if (b.empty()) return "an empty file";
  if (starts("\xFF\xD8\xFF")) return "a JPEG image";
  if (starts("GIF8")) return "a GIF image";
  if (starts("BM")) return "a BMP image";
  if (starts("RIFF") && b.size() >= 12 && b.substr(8, 4) == "WEBP") return "a WebP image";
  if (starts("#?RADIANCE") || starts("#?RGBE")) return "a Radiance HDR image";
  if (starts(std::string_view("\x76\x2f\x31\x01", 4))) return "an OpenEXR image";
  if (starts("<?xml") || starts("<svg")) return "an SVG or XML file (rasterise it to a PNG first)";
  if (starts("{")) return "a JSON file";
  return "not an image draught reads";
}

const char* valid_depths(int colour_type) {
  switch (colour_type) {
    case 0: return "\x01\x02\x04\x08\x10";  // grey
    case 2: return "\x08\x10";              // RGB
    case 3: return "\x01\x02\x04\x08";      // palette
    case 4: return "\x08\x10";              // grey + alpha
    case 6: return "\x08\x10";              // RGBA
  }
  return nullptr;
}

}  // namespace

Image decode_png(std::string_view b, const std::string& name, int max_side) {
  static constexpr std::string_view kSignature{"\x89PNG\r\n\x1a\n", 8};
  if (b.substr(0, 8) != kSignature) {
    if (b.size() < 8 && kSignature.substr(0, b.size()) == b && !b.empty())
      throw InputError(name + ": a damaged PNG: it ends within its signature");
    throw InputError(name + ": expected a PNG image, but this is " + what_it_is(b));
  }
  auto damaged = [&](const std::string& what) { return InputError(name + ": a damaged PNG: " + what); };
  size_t at = 8;
  bool header = false, data = false, end = false;
  long long width = 0, height = 0;
  for (int index = 0; !end; ++index) {
    if (b.size() - at < 12) throw damaged(at == b.size() ? "it ends before its IEND chunk (the file is cut short)"
                                                        : "it ends within a chunk's header (the file is cut short)");
    const std::uint32_t length = be32(b, at);
    const std::string_view type = b.substr(at + 4, 4);
    for (char c : type)
      if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) throw damaged("chunk " + std::to_string(index) + " has no valid type");
    const std::string tname(type);
    if (length > 0x7FFFFFFFu || b.size() - at - 12 < length)
      throw damaged("chunk " + tname + " ends past the end of the file (the file is cut short)");
    if (crc32(b.substr(at + 4, 4 + size_t(length))) != be32(b, at + 8 + length))
      throw damaged("chunk " + tname + "'s checksum does not match its data");
    const std::string_view body = b.substr(at + 8, length);
    if (index == 0 && tname != "IHDR") throw damaged("it does not begin with an IHDR chunk");
    if (tname == "IHDR") {
      if (index != 0) throw damaged("a second IHDR chunk");
      if (length != 13) throw damaged("its IHDR chunk is " + std::to_string(length) + " bytes, not 13");
      width = be32(body, 0);
      height = be32(body, 4);
      const int depth = static_cast<unsigned char>(body[8]), colour = static_cast<unsigned char>(body[9]);
      const char* depths = valid_depths(colour);
      if (!depths || std::string_view(depths).find(char(depth)) == std::string_view::npos)
        throw damaged("colour type " + std::to_string(colour) + " with bit depth " + std::to_string(depth) +
                      " is not a PNG format");
      if (body[10] != 0 || body[11] != 0 || (body[12] != 0 && body[12] != 1))
        throw damaged("unknown compression, filter or interlace method in its IHDR chunk");
      if (width < 1 || height < 1)
        throw InputError(name + ": the image has no pixels (" + std::to_string(width) + " x " + std::to_string(height) + ")");
      if (width > max_side || height > max_side)
        throw InputError(name + ": " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels, larger than the " + std::to_string(max_side) + " x " + std::to_string(max_side) +
                         " draught reads (scale it down)");
      header = true;
    } else if (tname == "IDAT") {
      data = true;
    } else if (tname == "IEND") {
      end = true;
    } else if (!(type[0] & 0x20) && tname != "PLTE") {
      throw damaged("an unknown critical chunk " + quote_input(make_valid_utf8(tname)));
    }
    at += 12 + size_t(length);
  }
  if (!header || !data) throw damaged("it has no image data (IDAT chunk)");
  int w = 0, h = 0, n = 0;
  stbi_uc* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(b.data()), int(std::min<size_t>(at, size_t(std::numeric_limits<int>::max()))), &w, &h, &n, 4);
  if (!px) throw damaged(std::string("its image data cannot be decoded (") + stbi_failure_reason() + ")");
  Image img{w, h, std::vector<std::uint8_t>(px, px + size_t(w) * size_t(h) * 4)};
  stbi_image_free(px);
  if (w != width || h != height) throw damaged("its image data does not match its header's size");
  return img;
}

}  // namespace draught
