// Reading HDR images: Radiance .hdr and OpenEXR .exr decode to linear light; broken,
// 8-bit, empty and oversized files are refused with the file's name and what was
// expected; values a GPU cannot hold are clamped and counted.
#include "core/io/files.hpp"
#include "core/io/hdr_image.hpp"

#include "test_common.hpp"

#include <stb_image_write.h>
#include <tinyexr.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <unistd.h>

namespace draught {
namespace {

namespace fs = std::filesystem;

// A w x h image of distinct values (bright ones included: HDR is the point).
std::vector<float> pattern(int w, int h, int channels) {
  std::vector<float> px(size_t(w) * size_t(h) * size_t(channels));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c)
        px[(size_t(y) * size_t(w) + size_t(x)) * size_t(channels) + size_t(c)] =
            c == 3 ? 1.0f : 0.05f * float(1 + x) * float(1 + c) + 3.0f * float(y);
  return px;
}

std::string radiance_bytes(int w, int h, const std::vector<float>& rgb) {
  std::string out;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
  };
  EXPECT_TRUE(stbi_write_hdr_to_func(sink, &out, w, h, 3, rgb.data()));
  return out;
}

std::string hdr_error_of(std::string_view bytes, const std::string& name = "env.hdr") {
  try {
    decode_hdr_image(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

class HdrImageFiles : public test::TempDirTest {
 protected:
  HdrImageFiles() : TempDirTest("draught-hdr") {}
  // An RGBA float EXR of the pattern (tinyexr writes it), read back as bytes.
  std::string exr_bytes(int w, int h, const std::vector<float>& rgba) {
    const fs::path p = dir_ / "image.exr";
    const char* err = nullptr;
    EXPECT_EQ(SaveEXR(rgba.data(), w, h, 4, 0, p.c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
    return read_whole_file(p, kMaxImageFileBytes, "an image");
  }
};

TEST(HdrImage, ARadianceFileDecodesToItsLinearValues) {
  const std::vector<float> px = pattern(6, 3, 3);
  const HdrImage img = decode_hdr_image(radiance_bytes(6, 3, px), "env.hdr");
  ASSERT_EQ(img.width, 6);
  ASSERT_EQ(img.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 6; ++x)
      for (int c = 0; c < 3; ++c)  // RGBE keeps 8 bits of mantissa per pixel's exponent
        EXPECT_NEAR(img.at(x, y)[c], px[size_t(y * 6 + x) * 3 + size_t(c)], 0.01f * img.at(x, y)[2] + 1e-6f)
            << x << "," << y << "," << c;
  EXPECT_GT(img.at(5, 2).b, 6.0f);  // not clipped at 1: still high dynamic range
}

TEST_F(HdrImageFiles, AnOpenExrFileDecodesToItsExactValues) {
  ASSERT_TRUE(hdr_image_reads_exr());
  const std::vector<float> px = pattern(5, 4, 4);
  const HdrImage img = decode_hdr_image(exr_bytes(5, 4, px), "env.exr");
  ASSERT_EQ(img.width, 5);
  ASSERT_EQ(img.height, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(img.at(x, y)[c], px[size_t(y * 5 + x) * 4 + size_t(c)]);
}

// What encode_exr writes reads back bit for bit (32-bit floats: the stored references
// of the reference comparisons rely on it), tiny and bright values alike.
TEST_F(HdrImageFiles, AnEncodedExrReadsBackBitForBit) {
  HdrImage img;
  img.width = 37;  // odd sizes: not a multiple of ZIP's 16-line blocks
  img.height = 21;
  img.rgb.resize(size_t(img.width) * size_t(img.height));
  for (size_t i = 0; i < img.rgb.size(); ++i)
    img.rgb[i] = glm::vec3(1e-7f * float(i), std::sqrt(float(i)) * 1.234567f, 60000.0f - 7.0f * float(i));
  const fs::path p = dir_ / "written.exr";
  write_exr(p, img);
  const HdrImage back = read_hdr_image(p);
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  for (size_t i = 0; i < img.rgb.size(); ++i) ASSERT_EQ(back.rgb[i], img.rgb[i]) << i;
}

TEST(HdrImage, AnImageWithoutPixelsIsNotEncoded) {
  HdrImage img;
  EXPECT_THROW(encode_exr(img), InputError);
  img.width = img.height = 2;  // four pixels promised, none given
  EXPECT_THROW(encode_exr(img), InputError);
}

TEST_F(HdrImageFiles, NonFiniteNegativeAndHugeValuesAreClampedAndCounted) {
  std::vector<float> px = pattern(4, 2, 4);
  px[0] = std::numeric_limits<float>::quiet_NaN();
  px[1] = std::numeric_limits<float>::infinity();
  px[2] = -2.0f;
  px[4] = 1e9f;
  HdrDecodeReport report;
  const HdrImage img = decode_hdr_image(exr_bytes(4, 2, px), "env.exr", &report);
  EXPECT_EQ(report.clamped, 4u);
  EXPECT_EQ(img.at(0, 0), glm::vec3(0.0f, kMaxHdrValue, 0.0f));
  EXPECT_EQ(img.at(1, 0).r, kMaxHdrValue);
  EXPECT_FLOAT_EQ(img.at(1, 0).g, px[5]);  // the rest untouched
}

TEST_F(HdrImageFiles, ATruncatedFileIsRefusedAsDamaged) {
  const std::string hdr = radiance_bytes(64, 32, pattern(64, 32, 3));
  EXPECT_TRUE(test::has(hdr_error_of(hdr.substr(0, hdr.size() / 2)), {"env.hdr", "damaged Radiance HDR"}));
  EXPECT_TRUE(test::has(hdr_error_of(hdr.substr(0, 20)), {"env.hdr", "damaged Radiance HDR"}));
  const std::string exr = exr_bytes(64, 32, pattern(64, 32, 4));
  EXPECT_TRUE(test::has(hdr_error_of(exr.substr(0, exr.size() / 2), "env.exr"), {"env.exr", "damaged OpenEXR"}));
  EXPECT_TRUE(test::has(hdr_error_of(exr.substr(0, 12), "env.exr"), {"env.exr", "damaged OpenEXR"}));
}

TEST(HdrImage, MalformedRunsAndHeadersAreRefusedNotDecoded) {
  // stb_image alone loops forever on a run of zero pixels (what a file cut short reads as).
  const std::string head = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 64\n";
  EXPECT_TRUE(test::has(hdr_error_of(head + std::string("\x02\x02\x00\x40\x00", 5)), {"env.hdr", "a run of 0 pixels"}));
  EXPECT_TRUE(test::has(hdr_error_of(head + std::string("\x02\x02\x00\x40\xFF\x01", 6)), {"env.hdr", "a run of 127 pixels"}));
  EXPECT_TRUE(test::has(hdr_error_of(head + std::string("\x02\x02\x00\x20", 4)), {"scanline 0 is not the image's width"}));
  EXPECT_TRUE(test::has(hdr_error_of("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 64\n"), {"env.hdr", "not FORMAT=32-bit_rle_rgbe"}));
  EXPECT_TRUE(test::has(hdr_error_of("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 1 +X 64\n"), {"env.hdr", "-Y height +X width"}));
  // A small image is stored flat, 4 bytes a pixel: all of them must be there.
  EXPECT_TRUE(test::has(hdr_error_of("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n" + std::string(31, '\x01')),
                        {"env.hdr", "ends before its last pixel"}));
}

// A tiled header whose "tiles" attribute is shorter than its 9 bytes: tinyexr 1.0.1 reads 9
// whatever the size (fuzz_hdr_image; fuzz/regressions/hdr_image/exr-tiles-attribute-short).
TEST(HdrImage, AShortTilesAttributeIsRefusedBeforeTinyexrReadsIt) {
  const std::string magic("\x76\x2f\x31\x01", 4), tiled_version("\x02\x02\x00\x00", 4);
  const std::string four_bytes("\x04\x00\x00\x00", 4);
  const std::string file = magic + tiled_version + std::string("tiles\0tiledesc\0", 15) + four_bytes + "abcd" +
                           std::string(1, '\0');
  EXPECT_TRUE(test::has(hdr_error_of(file, "env.exr"), {"env.exr", "damaged OpenEXR", "\"tiles\"", "4 bytes", "expected 9"}));
}

TEST(HdrImage, EightBitImagesAreRefusedByName) {
  EXPECT_TRUE(test::has(hdr_error_of(std::string("\x89PNG\r\n\x1a\n", 8) + std::string(40, '\0'), "sky.png"),
                        {"sky.png", "a PNG image holds 8-bit colour", "Radiance .hdr or OpenEXR .exr"}));
  EXPECT_TRUE(test::has(hdr_error_of("\xFF\xD8\xFF\xE0 jpeg", "sky.hdr"), {"sky.hdr", "a JPEG"}));
}

TEST(HdrImage, EmptyAndUnknownFilesSayWhatWasExpected) {
  EXPECT_TRUE(test::has(hdr_error_of(""), {"env.hdr", "empty", "Radiance .hdr or OpenEXR .exr"}));
  EXPECT_TRUE(test::has(hdr_error_of("{\"preset\": 1}"), {"env.hdr", "not an HDR image", "#?RADIANCE"}));
}

TEST(HdrImage, ATooLargeImageIsRefusedBeforeItIsDecoded) {
  // A header for 16k x 8k and no pixels: refused by its size, not by missing data.
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n";
  EXPECT_TRUE(test::has(hdr_error_of(header), {"env.hdr", "16384 x 8192", "larger than the 8192 x 4096"}));
}

TEST(HdrImage, ReadingAFileNamesItAndTheLimit) {
  try {
    read_hdr_image("/nonexistent/studio.hdr");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::has(e.what(), {"/nonexistent/studio.hdr", "cannot open"}));
  }
}

}  // namespace
}  // namespace draught
