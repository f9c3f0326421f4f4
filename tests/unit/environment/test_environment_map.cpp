// Equirectangular environments: the direction-to-texel mapping, filtering within and
// between levels, a chain that keeps the light's total, and the shapes refused.
#include "core/environment/environment_map.hpp"
#include "core/io/files.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught {
namespace {

constexpr double kPi = 3.14159265358979323846;

HdrImage filled(int w, int h, glm::vec3 c) { return HdrImage{w, h, std::vector<glm::vec3>(size_t(w) * size_t(h), c)}; }

std::string map_error_of(int w, int h) {
  try {
    make_environment_map(filled(w, h, glm::vec3(1)), "bar.exr");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(EnvironmentMap, TheMappingPutsBehindTheGlassInTheCentreAndUpAtTheTop) {
  EXPECT_NEAR(equirect_uv({0, 0, -1}).x, 0.5, 1e-12);
  EXPECT_NEAR(equirect_uv({0, 0, -1}).y, 0.5, 1e-12);
  EXPECT_NEAR(equirect_uv({1, 0, 0}).x, 0.75, 1e-12);  // +x to the right of the centre
  EXPECT_NEAR(equirect_uv({-1, 0, 0}).x, 0.25, 1e-12);
  EXPECT_NEAR(equirect_uv({0, 1, 0}).y, 0.0, 1e-12);
  EXPECT_NEAR(equirect_uv({0, -1, 0}).y, 1.0, 1e-12);
  EXPECT_NEAR(equirect_uv(glm::normalize(glm::dvec3(0, 1, -1))).y, 0.25, 1e-12);
}

TEST(EnvironmentMap, EachTexelIsSeenInItsOwnDirection) {
  HdrImage img = filled(16, 8, glm::vec3(0));
  img.rgb[size_t(2 * 16 + 12)] = glm::vec3(5, 6, 7);  // row 2 of 8, column 12 of 16
  const EnvironmentMap map = make_environment_map(img, "x.hdr");
  // The texel's centre: u = 12.5 / 16, v = 2.5 / 8.
  const double phi = (12.5 / 16 - 0.5) * 2 * kPi, theta = 2.5 / 8 * kPi;
  const glm::dvec3 d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
  EXPECT_NEAR(map.radiance(d).r, 5.0, 1e-9);
  EXPECT_NEAR(map.radiance(d).b, 7.0, 1e-9);
  EXPECT_NEAR(map.radiance(-d).r, 0.0, 1e-9);
}

TEST(EnvironmentMap, BilinearFilteringWrapsAcrossTheSeam) {
  HdrImage img = filled(16, 8, glm::vec3(0));
  for (int y = 0; y < 8; ++y) img.rgb[size_t(y * 16)] = glm::vec3(2);  // the first column
  const EnvironmentMap map = make_environment_map(img, "x.hdr");
  // Looking along +z is the seam (u = 0 = 1): halfway between the last column and the first.
  EXPECT_NEAR(map.radiance({0, 0, 1}).r, 1.0, 1e-9);
}

TEST(EnvironmentMap, TheChainHalvesDownToTheSmallestAndKeepsTheMeanRadiance) {
  HdrImage img = filled(64, 32, glm::vec3(0));
  for (size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = glm::vec3(float(i % 7), float(i % 3), 1.0f);
  const EnvironmentMap map = make_environment_map(img, "x.hdr");
  ASSERT_EQ(map.levels.size(), 4u);  // 64, 32, 16, 8 wide
  EXPECT_EQ(map.levels.back().width, 8);
  EXPECT_EQ(map.levels.back().height, 4);
  auto mean = [](const HdrImage& l) {
    glm::dvec3 s(0);
    for (const glm::vec3& c : l.rgb) s += glm::dvec3(c);
    return s / double(l.rgb.size());
  };
  for (const HdrImage& l : map.levels) {
    EXPECT_NEAR(mean(l).r, mean(map.levels[0]).r, 1e-5);
    EXPECT_NEAR(mean(l).g, mean(map.levels[0]).g, 1e-5);
  }
}

TEST(EnvironmentMap, FractionalLevelsBlendTwoLevelsAndLevelsAreClamped) {
  HdrImage img = filled(16, 8, glm::vec3(0));
  img.rgb[size_t(3 * 16 + 7)] = glm::vec3(8);  // one bright texel near the centre
  const EnvironmentMap map = make_environment_map(img, "x.hdr");
  ASSERT_EQ(map.levels.size(), 2u);
  const glm::dvec2 uv{7.5 / 16, 3.5 / 8};
  const double phi = (uv.x - 0.5) * 2 * kPi, theta = uv.y * kPi;
  const glm::dvec3 d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
  const double sharp = map.radiance(d, 0).r, blurred = map.radiance(d, 1).r;
  EXPECT_NEAR(sharp, 8.0, 1e-9);
  EXPECT_LT(blurred, sharp);
  EXPECT_GT(blurred, 0.0);
  EXPECT_NEAR(map.radiance(d, 0.25).r, 0.75 * sharp + 0.25 * blurred, 1e-9);
  EXPECT_NEAR(map.radiance(d, 7).r, blurred, 1e-9);
  EXPECT_NEAR(map.radiance(d, -3).r, sharp, 1e-9);
}

TEST(EnvironmentMap, ShapesThatAreNotAnEquirectangularImageAreRefused) {
  EXPECT_TRUE(test::has(map_error_of(1, 1), {"bar.exr", "1 x 1", "twice as wide as high"}));
  EXPECT_TRUE(test::has(map_error_of(300, 200), {"bar.exr", "300 x 200", "twice as wide as high"}));
  EXPECT_TRUE(test::has(map_error_of(4, 2), {"bar.exr", "4 x 2", "at least 8 x 4"}));
  EXPECT_EQ(map_error_of(8, 4), "");
}

}  // namespace
}  // namespace draught
