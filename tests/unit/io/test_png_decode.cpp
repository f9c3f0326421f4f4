// The strict PNG decoder (decals): a good PNG decodes to what was written; a missing
// file, a file that is not a PNG, one without pixels, one too large and one damaged or cut
// short anywhere are refused with the file's name and what was expected, and never crash.
#include "core/io/files.hpp"
#include "core/io/image.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>

namespace draught {
namespace {

Image pattern(int w, int h) {
  Image img{w, h, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.px(x, y);
      p[0] = std::uint8_t(x * 37), p[1] = std::uint8_t(y * 53), p[2] = std::uint8_t(x * y), p[3] = std::uint8_t(255 - x);
    }
  return img;
}

std::string png_error_of(std::string_view bytes, const std::string& name = "logo.png", int max_side = kMaxPngSide) {
  try {
    decode_png(bytes, name, max_side);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The CRC of a chunk's type and data, as PNG writes it (to build files by hand).
std::uint32_t crc(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xFFFFFFFFu;
}
std::string be32(std::uint32_t v) {
  return {char(v >> 24), char((v >> 16) & 0xFF), char((v >> 8) & 0xFF), char(v & 0xFF)};
}
std::string chunk(const std::string& type, const std::string& data) {
  return be32(std::uint32_t(data.size())) + type + data + be32(crc(type + data));
}
// A PNG whose header says w x h (the image data of a valid 1 x 1 image follows).
std::string with_header_size(std::uint32_t w, std::uint32_t h) {
  const std::string good = encode_png(pattern(1, 1));
  std::string ihdr = be32(w) + be32(h) + std::string("\x08\x06\x00\x00\x00", 5);
  return good.substr(0, 8) + chunk("IHDR", ihdr) + good.substr(8 + 25);
}

TEST(PngDecode, DecodesWhatWasWritten) {
  const Image img = pattern(7, 5);
  const Image out = decode_png(encode_png(img), "logo.png");
  ASSERT_EQ(out.width, 7);
  ASSERT_EQ(out.height, 5);
  EXPECT_EQ(out.rgba, img.rgba);
}

TEST(PngDecode, DecodesEveryColourTypeAndDepth) {
  // The fuzzer's seeds: grey 1 and 8 bits, grey and alpha at 16 bits, a palette with
  // transparency, interlaced RGB and RGBA, each as RGBA.
  const auto dir = test::preset_source_dir().parent_path() / "fuzz" / "seeds" / "decal_image";
  const Image pal = decode_png(read_whole_file(dir / "palette-trns-4x4.png", kMaxPngFileBytes, "a PNG"), "p.png");
  ASSERT_EQ(pal.width, 4);
  EXPECT_EQ(std::vector<std::uint8_t>(pal.px(1, 0), pal.px(1, 0) + 4), (std::vector<std::uint8_t>{0, 255, 0, 128}));
  const Image grey16 = decode_png(read_whole_file(dir / "grey-alpha-16-3x3.png", kMaxPngFileBytes, "a PNG"), "g.png");
  EXPECT_EQ(grey16.px(2, 0)[0], 40000 >> 8);  // stb keeps the high byte
  EXPECT_EQ(grey16.px(0, 2)[3], (65535 - 40000) >> 8);
  const Image bits = decode_png(read_whole_file(dir / "grey-1bit-9x2.png", kMaxPngFileBytes, "a PNG"), "b.png");
  EXPECT_EQ(bits.px(0, 0)[0], 255);
  EXPECT_EQ(bits.px(1, 0)[0], 0);
  EXPECT_EQ(bits.px(8, 0)[0], 255);
  const Image dot = decode_png(read_whole_file(dir / "rgb-interlaced-1x1.png", kMaxPngFileBytes, "a PNG"), "i.png");
  EXPECT_EQ(std::vector<std::uint8_t>(dot.rgba.begin(), dot.rgba.end()), (std::vector<std::uint8_t>{10, 200, 30, 255}));
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_NO_THROW(decode_png(read_whole_file(e.path(), kMaxPngFileBytes, "a PNG"), e.path().string())) << e.path();
}

TEST(PngDecode, RefusesWhatIsNotAPng) {
  EXPECT_TRUE(test::has(png_error_of(""), {"logo.png", "expected a PNG image", "an empty file"}));
  EXPECT_TRUE(test::has(png_error_of("hello, world"), {"logo.png", "expected a PNG image", "not an image"}));
  EXPECT_TRUE(test::has(png_error_of("\xFF\xD8\xFF\xE0 JFIF"), {"logo.png", "a JPEG image"}));
  EXPECT_TRUE(test::has(png_error_of("GIF89a...."), {"a GIF image"}));
  EXPECT_TRUE(test::has(png_error_of("RIFF....WEBPVP8 "), {"a WebP image"}));
  EXPECT_TRUE(test::has(png_error_of("RIFF\r"), {"expected a PNG image"}));  // shorter than a RIFF header (fuzz_decal_image)
  EXPECT_TRUE(test::has(png_error_of("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"), {"a Radiance HDR image"}));
  EXPECT_TRUE(test::has(png_error_of("<svg xmlns=...>"), {"SVG", "rasterise it to a PNG"}));
  EXPECT_TRUE(test::has(png_error_of("\x89PN"), {"logo.png", "damaged", "signature"}));
}

TEST(PngDecode, RefusesAnImageWithoutPixels) {
  EXPECT_TRUE(test::has(png_error_of(with_header_size(0, 10)), {"logo.png", "no pixels", "0 x 10"}));
  EXPECT_TRUE(test::has(png_error_of(with_header_size(10, 0)), {"no pixels", "10 x 0"}));
}

TEST(PngDecode, RefusesAnImageTooLarge) {
  // The header is read before any pixel: a 100000 x 100000 claim costs nothing.
  EXPECT_TRUE(test::has(png_error_of(with_header_size(100000, 100000)),
                        {"logo.png", "100000 x 100000 pixels", "larger than the 4096 x 4096"}));
  // A real one just over the limit (the limit given smaller, to keep the test quick).
  EXPECT_TRUE(test::has(png_error_of(encode_png(pattern(65, 3)), "logo.png", 64), {"65 x 3 pixels", "64 x 64"}));
  EXPECT_EQ(png_error_of(encode_png(pattern(64, 3)), "logo.png", 64), "");
  EXPECT_EQ(kMaxPngSide, 4096);
}

TEST(PngDecode, RefusesAFileCutShortAnywhere) {
  const std::string good = encode_png(pattern(9, 6));
  for (size_t n = 1; n < good.size(); ++n) {
    const std::string e = png_error_of(good.substr(0, n));
    ASSERT_FALSE(e.empty()) << "a file cut to " << n << " of " << good.size() << " bytes was accepted";
    ASSERT_TRUE(test::has(e, {"logo.png", "damaged"})) << "cut to " << n;
  }
}

TEST(PngDecode, RefusesDamagedData) {
  const std::string good = encode_png(pattern(9, 6));
  // Every byte after the signature changed in turn: each is caught (a checksum, a length,
  // a chunk type), never decoded into a picture that was not written.
  for (size_t i = 8; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = char(bad[i] ^ 0x5A);
    const std::string e = png_error_of(bad);
    ASSERT_FALSE(e.empty()) << "byte " << i << " changed was accepted";
    ASSERT_TRUE(test::has(e, {"logo.png"})) << e;
  }
  std::string bad = good;
  bad[8 + 8 + 13 + 4 + 8 + 2] ^= 1;  // inside the first IDAT's data
  EXPECT_TRUE(test::has(png_error_of(bad), {"damaged", "IDAT", "checksum"}));
}

TEST(PngDecode, RefusesAChunkThatIsNotPng) {
  const std::string good = encode_png(pattern(2, 2));
  // An unknown critical chunk before the data.
  const std::string bad = good.substr(0, 33) + chunk("QQQQ", "x") + good.substr(33);
  EXPECT_TRUE(test::has(png_error_of(bad), {"unknown critical chunk", "QQQQ"}));
  // An unknown ancillary chunk is skipped, as PNG says.
  EXPECT_EQ(png_error_of(good.substr(0, 33) + chunk("qqQQ", "x") + good.substr(33)), "");
  // A bit depth no colour type has.
  std::string depth = good;
  depth[8 + 8 + 8] = 3;
  depth.replace(8 + 8 + 13, 4, be32(crc(depth.substr(12, 17))));
  EXPECT_TRUE(test::has(png_error_of(depth), {"bit depth 3", "not a PNG format"}));
}

TEST(PngDecode, ErrorsBeginWithTheFilesName) {
  const std::string e = png_error_of("nope", "caf\xC3\xA9/logo.png");
  EXPECT_EQ(e.rfind("caf\xC3\xA9/logo.png: ", 0), 0u) << e;
}

}  // namespace
}  // namespace draught
