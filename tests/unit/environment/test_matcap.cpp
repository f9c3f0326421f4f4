// The MatCap tier's lit sphere (core/environment/matcap): a furnace (a constant
// surroundings' MatCap is that constant everywhere), its orientation (a light above shows
// at its top), its mapping both ways, and its PNG's loader.
#include "core/environment/matcap.hpp"
#include "core/io/files.hpp"
#include "core/io/image.hpp"
#include "core/params/params.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace draught {
namespace {

SceneParams constant_surroundings(glm::vec3 c) {
  SceneParams p = default_params();
  p.env.mode = int(EnvMode::Constant);
  p.env.color = c;
  p.env.floor = false;
  p.light.power = p.strips.power = p.backlight.power = 0;
  return p;
}

TEST(MatCap, ConstantSurroundingsGiveAUniformMatCapOfTheirValue) {
  const SceneParams p = constant_surroundings({0.3f, 0.5f, 0.7f});
  const LightRig rig = light_rig(p, {0, 0.08, 0});
  const MatCap m = bake_matcap(p, rig, backdrop_surface(p.env, rig.aim), rig.aim, 64);
  ASSERT_EQ(m.size, 64);
  for (const glm::vec3& c : m.rgb) {
    EXPECT_NEAR(c.r, 0.3f, 1e-6f);
    EXPECT_NEAR(c.g, 0.5f, 1e-6f);
    EXPECT_NEAR(c.b, 0.7f, 1e-6f);
  }
}

TEST(MatCap, ALightAboveShowsAtTheTop) {
  SceneParams p = constant_surroundings(glm::vec3(0.01f));
  p.light.power = 50.0f;
  p.light.shape = int(LightShape::Sphere);
  p.light.direction = {0, 1, 0};
  p.light.distance = 0.6f;
  p.light.width = 0.3f;
  const LightRig rig = light_rig(p, {0, 0.08, 0});
  ASSERT_EQ(rig.lights.size(), 1u);
  const MatCap m = bake_matcap(p, rig, backdrop_surface(p.env, rig.aim), rig.aim, 64);
  auto band = [&](int y0, int y1) {
    double sum = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < m.size; ++x) sum += m.at(x, y).g;
    return sum / ((y1 - y0) * m.size);
  };
  EXPECT_GT(band(0, 16), 20 * band(48, 64));  // rows run top-down: the top quarter is lit
  // Where the normal halfway between the view and up looks, the light itself.
  const MatCapView view = matcap_view();
  const glm::dvec3 up = glm::normalize(glm::dvec3(0, 1, 0) + view.back);
  const glm::dvec2 uv = matcap_uv({glm::dot(up, view.right), glm::dot(up, view.up), glm::dot(up, view.back)});
  EXPECT_LT(uv.y, 0.5);
  const glm::vec3 c = m.at(int(uv.x * m.size), int(uv.y * m.size));
  EXPECT_NEAR(c.g, float(rig.lights[0].radiance.g), 1e-3f * float(rig.lights[0].radiance.g));
}

TEST(MatCap, NormalsAndCoordinatesAreInverse) {
  for (double u : {0.1, 0.35, 0.5, 0.8})
    for (double v : {0.2, 0.5, 0.7}) {
      const glm::dvec3 n = matcap_normal(u, v);
      EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
      const glm::dvec2 back = matcap_uv(n);
      EXPECT_NEAR(back.x, u, 1e-12);
      EXPECT_NEAR(back.y, v, 1e-12);
    }
  EXPECT_NEAR(matcap_normal(0.5, 0.0).y, 1.0, 1e-12);  // v = 0 is the top
  EXPECT_NEAR(matcap_normal(0.0, 0.0).z, 0.0, 1e-12);  // outside the disk: its rim
}

TEST(MatCap, AnImageIsReadInLinearLight) {
  Image img{8, 8, std::vector<std::uint8_t>(8 * 8 * 4, 255)};
  for (size_t i = 0; i < img.rgba.size(); i += 4) img.rgba[i + 1] = 188;  // sRGB 188: linear 0.5
  const MatCap m = matcap_from_image(img);
  ASSERT_EQ(m.size, kMatCapSize);
  EXPECT_NEAR(m.at(100, 30).r, 1.0f, 1e-6f);
  EXPECT_NEAR(m.at(100, 30).g, 0.5f, 5e-3f);
}

TEST(MatCap, ABrokenFileIsRefusedNamingIt) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "draught_matcap_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path bad = dir / "broken.png";
  std::ofstream(bad) << "\x89PNG\r\n\x1a\n this is not the rest of a PNG";
  try {
    check_matcap_image(bad.string());
    FAIL() << "a broken PNG was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.png"), std::string::npos) << e.what();
  }
  try {
    check_matcap_image((dir / "missing.png").string());
    FAIL() << "a missing file was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
  }
  // Through the parameter table: the error names the field, and the value is not taken.
  Params p = default_params();
  EXPECT_THROW(set_param(p, *find_param("matcap.file"), ParamValue(bad.string())), std::exception);
  EXPECT_EQ(p.matcap.file, "");
  check_matcap_image("");  // none: the bake
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace draught
