#include "core/io/hdr_image.hpp"

#include "core/io/files.hpp"
#include "core/text/echo.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#ifndef DRAUGHT_HAS_EXR  // set by the native build, which links Debian's tinyexr
#define DRAUGHT_HAS_EXR 0
#endif
#if DRAUGHT_HAS_EXR
#include <tinyexr.h>
#endif

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace draught {

namespace {

bool starts_with(std::string_view bytes, std::string_view magic) { return bytes.substr(0, magic.size()) == magic; }

// What an 8-bit file is, by its first bytes (for the error that refuses it).
const char* ldr_kind(std::string_view b) {
  if (starts_with(b, "\x89PNG")) return "a PNG";
  if (starts_with(b, "\xFF\xD8\xFF")) return "a JPEG";
  if (starts_with(b, "GIF8")) return "a GIF";
  if (starts_with(b, "BM")) return "a BMP";
  return nullptr;
}

constexpr std::string_view kExrMagic{"\x76\x2f\x31\x01", 4};

void check_size(const std::string& name, long long w, long long h) {
  if (w < 1 || h < 1)
    throw InputError(name + ": the image has no pixels (" + std::to_string(w) + " x " + std::to_string(h) + ")");
  if (w > kMaxHdrImageWidth || h > kMaxHdrImageHeight)
    throw InputError(name + ": " + std::to_string(w) + " x " + std::to_string(h) + " pixels, larger than the " +
                     std::to_string(kMaxHdrImageWidth) + " x " + std::to_string(kMaxHdrImageHeight) +
                     " draught reads (scale it down: 4096 x 2048 is plenty for an environment)");
}

// Keeps every channel finite, non-negative and within half float; counts what it changed.
float clamp_channel(float v, size_t& clamped) {
  if (std::isnan(v) || v < 0.0f) {
    ++clamped;
    return 0.0f;
  }
  if (v > kMaxHdrValue) {
    ++clamped;
    return kMaxHdrValue;
  }
  return v;
}

HdrImage from_floats(const float* px, int w, int h, int channels, HdrDecodeReport* report) {
  HdrImage img{w, h, std::vector<glm::vec3>(size_t(w) * size_t(h))};
  size_t clamped = 0;
  for (size_t i = 0; i < img.rgb.size(); ++i)
    for (int c = 0; c < 3; ++c) img.rgb[i][c] = clamp_channel(px[i * size_t(channels) + size_t(c)], clamped);
  if (report) report->clamped = clamped;
  return img;
}

// A Radiance file's layout, read the way stb_image reads it, and its pixel data walked
// through before stb decodes it: stb trusts the data (a truncated file loops forever on
// a run of length zero, or decodes missing pixels as black), so every scanline is
// checked to be whole and well-formed first. Throws InputError naming what is wrong.
void check_radiance(std::string_view b, const std::string& name) {
  auto damaged = [&](const std::string& what) { return InputError(name + ": a damaged Radiance HDR file: " + what); };
  size_t at = 0;
  auto line = [&]() -> std::string_view {
    const size_t end = b.find('\n', at);
    if (end == std::string_view::npos) throw damaged("its header ends before the image size");
    const std::string_view l = b.substr(at, end - at);
    at = end + 1;
    return l;
  };
  line();  // #?RADIANCE or #?RGBE (the caller checked)
  bool rgbe = false;
  for (std::string_view l = line(); !l.empty(); l = line())
    if (l == "FORMAT=32-bit_rle_rgbe") rgbe = true;
  if (!rgbe) throw InputError(name + ": a Radiance HDR file that is not FORMAT=32-bit_rle_rgbe (the only format read)");
  const std::string size_line(line());
  long long h = 0, w = 0;
  char rest[2] = {};
  if (std::sscanf(size_line.c_str(), "-Y %lld +X %lld%1c", &h, &w, rest) != 2)
    throw InputError(name + ": a Radiance HDR file whose size line is not \"-Y height +X width\" (got " +
                     quote_input(make_valid_utf8(size_line)) + ")");
  check_size(name, w, h);
  const size_t need_flat = size_t(w) * size_t(h) * 4;
  if (w < 8 || w >= 32768) {  // stored flat, 4 bytes a pixel
    if (b.size() - at < need_flat) throw damaged("it ends before its last pixel");
    return;
  }
  auto byte = [&]() -> unsigned {
    if (at >= b.size()) throw damaged("it ends before its last scanline");
    return static_cast<unsigned char>(b[at++]);
  };
  for (long long y = 0; y < h; ++y) {
    const size_t start = at;
    const unsigned c1 = byte(), c2 = byte(), hi = byte();
    if (c1 != 2 || c2 != 2 || (hi & 0x80)) {
      // A flat scanline: stb then decodes the whole image as flat from here.
      if (b.size() - start < need_flat) throw damaged("it ends before its last pixel");
      return;
    }
    if (((hi << 8) | byte()) != unsigned(w)) throw damaged("scanline " + std::to_string(y) + " is not the image's width");
    for (int channel = 0; channel < 4; ++channel)
      for (long long x = 0; x < w;) {
        const unsigned count = byte();
        const long long n = count > 128 ? count - 128 : count;
        if (n == 0 || n > w - x) throw damaged("a run of " + std::to_string(n) + " pixels in scanline " + std::to_string(y));
        if (count > 128) {
          byte();
        } else {
          if (b.size() - at < size_t(n)) throw damaged("it ends before its last scanline");
          at += size_t(n);
        }
        x += n;
      }
  }
}

HdrImage decode_radiance(std::string_view bytes, const std::string& name, HdrDecodeReport* report) {
  check_radiance(bytes, name);
  int w = 0, h = 0, n = 0;
  float* px = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &n, 3);
  if (!px) throw InputError(name + ": a damaged Radiance HDR file: " + stbi_failure_reason());
  HdrImage img = from_floats(px, w, h, 3, report);
  stbi_image_free(px);
  return img;
}

#if DRAUGHT_HAS_EXR
// tinyexr's message, freed; it may quote the file's own bytes (a channel's name), so it
// is made valid UTF-8 and capped like any echo of input.
std::string exr_error(const char* err) {
  std::string s = err ? err : "unknown error";
  if (err) FreeEXRErrorMessage(err);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (char& c : s)
    if (c == '\n') c = ' ';
  return shorten(make_valid_utf8(s), 200);
}

// One channel's value at texel i of a decoded buffer (HALF was asked for as FLOAT).
float exr_value(const unsigned char* channel, int type, size_t i) {
  if (type == TINYEXR_PIXELTYPE_UINT) return float(reinterpret_cast<const unsigned*>(channel)[i]);
  return reinterpret_cast<const float*>(channel)[i];
}

// The header and image of one decode, freed whatever happens (tinyexr's own
// LoadEXRFromMemory leaks the header when a file is damaged).
struct ExrDecode {
  EXRHeader header;
  EXRImage image;
  ExrDecode() {
    InitEXRHeader(&header);
    InitEXRImage(&image);
  }
  ~ExrDecode() {
    FreeEXRImage(&image);
    FreeEXRHeader(&header);
  }
};

// The header's attributes as the file lists them (name, type, a 4-byte little-endian size,
// the value), checked where Debian's tinyexr 1.0.1 trusts them: it reads a "tiles" value
// as 9 bytes whatever its size (a heap over-read, found by fuzz_hdr_image). The walk stops
// at the header's end or where the file ends; tinyexr reports the damage it then meets.
void check_exr_attributes(std::string_view bytes, const std::string& name) {
  size_t at = 8;  // past the magic number and the version field
  while (at < bytes.size() && bytes[at] != '\0') {
    const size_t name_end = bytes.find('\0', at);
    if (name_end == std::string_view::npos) return;
    const size_t type_end = bytes.find('\0', name_end + 1);
    if (type_end == std::string_view::npos || type_end + 5 > bytes.size()) return;
    const auto* s = reinterpret_cast<const unsigned char*>(bytes.data() + type_end + 1);
    const std::uint32_t size = std::uint32_t(s[0]) | std::uint32_t(s[1]) << 8 | std::uint32_t(s[2]) << 16 |
                               std::uint32_t(s[3]) << 24;
    if (bytes.substr(at, name_end - at) == "tiles" && size != 9)
      throw InputError(name + ": a damaged OpenEXR header: its \"tiles\" attribute holds " + std::to_string(size) +
                       " bytes (expected 9)");
    if (size > bytes.size() - (type_end + 5)) return;
    at = type_end + 5 + size;
  }
}

HdrImage decode_exr(std::string_view bytes, const std::string& name, HdrDecodeReport* report) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS)
    throw InputError(name + ": a damaged OpenEXR header (its version field)");
  if (version.multipart || version.non_image)
    throw InputError(name + ": a multi-part or deep OpenEXR file; expected a single-part scanline or tiled image");
  check_exr_attributes(bytes, name);
  ExrDecode exr;
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&exr.header, &version, data, bytes.size(), &err) != TINYEXR_SUCCESS)
    throw InputError(name + ": a damaged OpenEXR header: " + exr_error(err));
  // The size first, before a pixel is decoded or allocated.
  const EXRBox2i& win = exr.header.data_window;
  const long long w = (long long)win.max_x - win.min_x + 1, h = (long long)win.max_y - win.min_y + 1;
  check_size(name, w, h);
  // PIZ is refused: Debian's tinyexr 1.0.1 writes past a buffer when PIZ data is
  // damaged (found by fuzz_hdr_image). ZIP, the common choice, and the rest are read.
  const int codec = exr.header.compression_type;
  if (codec != TINYEXR_COMPRESSIONTYPE_NONE && codec != TINYEXR_COMPRESSIONTYPE_RLE &&
      codec != TINYEXR_COMPRESSIONTYPE_ZIPS && codec != TINYEXR_COMPRESSIONTYPE_ZIP)
    throw InputError(name + ": an OpenEXR image compressed with " +
                     (codec == TINYEXR_COMPRESSIONTYPE_PIZ ? std::string("PIZ") : "codec " + std::to_string(codec)) +
                     ", which draught does not read; save it with ZIP, ZIPS, RLE or no compression");
  // Every chunk (a block of scanlines, or a tile) has an 8-byte entry in the file's
  // offset table: a count the file cannot hold is damage, refused before tinyexr sizes
  // its tables by it.
  const size_t table_entries = bytes.size() / 8;
  if (exr.header.chunk_count < 0 || size_t(exr.header.chunk_count) > table_entries)
    throw InputError(name + ": a damaged OpenEXR header: more chunks than the file can hold");
  if (exr.header.tiled) {
    const long long tx = exr.header.tile_size_x, ty = exr.header.tile_size_y;
    if (tx < 1 || ty < 1 || ((w + tx - 1) / tx) * ((h + ty - 1) / ty) > (long long)table_entries)
      throw InputError(name + ": a damaged OpenEXR header: more tiles than the file can hold");
  }
  // Which channels are the colour: R, G, B, or Y alone for a grey image.
  int rgb[3] = {-1, -1, -1}, y = -1;
  for (int c = 0; c < exr.header.num_channels; ++c) {
    const std::string_view n = exr.header.channels[c].name;
    if (n == "R") rgb[0] = c;
    if (n == "G") rgb[1] = c;
    if (n == "B") rgb[2] = c;
    if (n == "Y") y = c;
    if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) {
    if (y < 0) throw InputError(name + ": an OpenEXR image with no R, G and B channels (nor Y); expected a colour image");
    rgb[0] = rgb[1] = rgb[2] = y;
  }
  // tinyexr 1.0.1 sets the image's channel count only once decoding succeeds, so when a
  // damaged file fails half-way its own clean-up frees no channel: set it up front.
  exr.image.num_channels = exr.header.num_channels;
  if (LoadEXRImageFromMemory(&exr.image, &exr.header, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
    InitEXRImage(&exr.image);  // tinyexr has freed what it decoded (and left the pointers)
    throw InputError(name + ": a damaged OpenEXR file: " + exr_error(err));
  }
  const EXRImage& im = exr.image;
  if (im.width != w || im.height != h)
    throw InputError(name + ": a damaged OpenEXR file: its data window and pixels disagree");
  std::vector<float> px(size_t(w) * size_t(h) * 3, 0.0f);
  auto put = [&](size_t dst, const unsigned char* const* channels, size_t src) {
    for (int k = 0; k < 3; ++k)
      px[dst * 3 + size_t(k)] = exr_value(channels[rgb[k]], exr.header.requested_pixel_types[rgb[k]], src);
  };
  if (exr.header.tiled) {  // level 0's tiles, each put where it belongs
    const int tw = exr.header.tile_size_x, th = exr.header.tile_size_y;
    for (int t = 0; t < im.num_tiles; ++t) {
      const EXRTile& tile = im.tiles[t];
      if (tile.level_x != 0 || tile.level_y != 0) continue;
      if (tile.width > tw || tile.height > th)
        throw InputError(name + ": a damaged OpenEXR file: a tile larger than the tile size");
      for (int j = 0; j < tile.height; ++j)
        for (int i = 0; i < tile.width; ++i) {
          const long long x = (long long)tile.offset_x * tw + i, yy = (long long)tile.offset_y * th + j;
          if (x < 0 || yy < 0 || x >= w || yy >= h)
            throw InputError(name + ": a damaged OpenEXR file: a tile lies outside the image");
          put(size_t(yy) * size_t(w) + size_t(x), tile.images, size_t(j) * size_t(tw) + size_t(i));
        }
    }
  } else {
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) put(i, im.images, i);
  }
  return from_floats(px.data(), int(w), int(h), 3, report);
}
#endif

}  // namespace

bool hdr_image_reads_exr() { return DRAUGHT_HAS_EXR != 0; }

HdrImage decode_hdr_image(std::string_view bytes, const std::string& name, HdrDecodeReport* report) {
  if (bytes.empty()) throw InputError(name + ": the file is empty; expected a Radiance .hdr or OpenEXR .exr image");
  if (bytes.size() > kMaxImageFileBytes) throw InputError(name + ": larger than the limit for an image");
  if (starts_with(bytes, "#?RADIANCE") || starts_with(bytes, "#?RGBE")) return decode_radiance(bytes, name, report);
  if (starts_with(bytes, kExrMagic)) {
#if DRAUGHT_HAS_EXR
    return decode_exr(bytes, name, report);
#else
    throw InputError(name + ": an OpenEXR image, which this build does not read; convert it to a Radiance .hdr");
#endif
  }
  if (const char* kind = ldr_kind(bytes))
    throw InputError(name + ": " + kind + " image holds 8-bit colour, not light; expected a high-dynamic-range "
                     "Radiance .hdr or OpenEXR .exr image");
  throw InputError(name + ": not an HDR image; expected a Radiance .hdr (it begins \"#?RADIANCE\") or an "
                   "OpenEXR .exr image");
}

HdrImage read_hdr_image(const std::filesystem::path& path, HdrDecodeReport* report) {
  return decode_hdr_image(read_whole_file(path, kMaxImageFileBytes, "an image"), path.string(), report);
}

std::string encode_radiance_hdr(const HdrImage& img) {
  std::string out;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
  };
  std::vector<float> px(img.rgb.size() * 3);
  for (size_t i = 0; i < img.rgb.size(); ++i)
    for (int c = 0; c < 3; ++c) px[i * 3 + size_t(c)] = img.rgb[i][c];
  stbi_write_hdr_to_func(sink, &out, img.width, img.height, 3, px.data());
  return out;
}

void write_radiance_hdr(const std::filesystem::path& path, const HdrImage& img) {
  write_file_atomic(path, encode_radiance_hdr(img));
}

std::string encode_exr(const HdrImage& img) {
#if DRAUGHT_HAS_EXR
  if (img.width < 1 || img.height < 1 || img.rgb.size() != size_t(img.width) * size_t(img.height))
    throw InputError("encode_exr: an image of " + std::to_string(img.width) + " x " + std::to_string(img.height) +
                     " pixels with " + std::to_string(img.rgb.size()) + " values");
  // EXR lists channels by name, in ASCII order: B, G, R.
  std::vector<float> planes[3];
  for (int c = 0; c < 3; ++c) {
    planes[c].resize(img.rgb.size());
    for (size_t i = 0; i < img.rgb.size(); ++i) planes[c][i] = img.rgb[i][2 - c];
  }
  float* pointers[3] = {planes[0].data(), planes[1].data(), planes[2].data()};
  EXRImage image;
  InitEXRImage(&image);
  image.num_channels = 3;
  image.images = reinterpret_cast<unsigned char**>(pointers);
  image.width = img.width;
  image.height = img.height;
  EXRHeader header;
  InitEXRHeader(&header);
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
  header.num_channels = 3;
  EXRChannelInfo channels[3] = {};
  int types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
  for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];
  header.channels = channels;
  header.pixel_types = types;
  header.requested_pixel_types = types;
  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &err);
  if (size == 0 || !memory) throw InputError("encode_exr: " + exr_error(err));
  std::string out(reinterpret_cast<const char*>(memory), size);
  std::free(memory);
  return out;
#else
  (void)img;
  throw InputError("this build writes no OpenEXR images; write a Radiance .hdr");
#endif
}

void write_exr(const std::filesystem::path& path, const HdrImage& img) { write_file_atomic(path, encode_exr(img)); }

}  // namespace draught
