// The environments draught bakes: the studio's light is the same light as an image
// (its key softbox gives the irradiance it states), the bar is a dim room with bright
// lamps and a lit back bar, and both survive the trip through a Radiance file.
#include "core/environment/backdrop.hpp"
#include "core/environment/environment_bake.hpp"
#include "core/environment/environment_map.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/studio.hpp"
#include "core/io/files.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {
namespace {

// Irradiance on a surface with normal n from an equirectangular image: the sum over
// texels of radiance x cos x solid angle.
glm::dvec3 irradiance(const HdrImage& img, const glm::dvec3& n) {
  glm::dvec3 e(0);
  for (int y = 0; y < img.height; ++y) {
    const double theta = (y + 0.5) / img.height * kPi;
    const double d_omega = (2 * kPi / img.width) * (kPi / img.height) * std::sin(theta);
    for (int x = 0; x < img.width; ++x) {
      const double phi = ((x + 0.5) / img.width - 0.5) * 2 * kPi;
      const glm::dvec3 d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
      e += glm::dvec3(img.at(x, y)) * std::max(glm::dot(d, n), 0.0) * d_omega;
    }
  }
  return e;
}

SceneParams key_only(glm::vec3 dir, float power) {
  SceneParams s = default_params();
  s.env.sky_top = s.env.sky_horizon = s.env.ground = glm::vec3(0);
  s.env.strip_intensity = s.env.backdrop_glow = 0;
  s.strips.power = s.backlight.power = 0;
  s.env.floor = false;  // the key alone, not its light on the sweep too
  s.light.direction = dir;
  s.light.power = power;
  s.light.color = glm::vec3(1);
  return s;
}

// What the key gives the scene's centre, from core/environment/lights (exact).
double key_irradiance(const SceneParams& s, glm::dvec3 n) {
  const AreaLight key = place_light(s.light, glm::dvec3(0.0));
  return key.radiance.g * key.irradiance_factor(glm::dvec3(0.0), n);
}

TEST(EnvironmentBake, TheStudiosKeyGivesTheIrradianceItShould) {
  const SceneParams above = key_only({0, 1, 0}, 2.5f);
  const HdrImage up = bake_environment("studio", above, 512);
  EXPECT_NEAR(irradiance(up, {0, 1, 0}).r, key_irradiance(above, {0, 1, 0}), 0.02 * key_irradiance(above, {0, 1, 0}));
  const glm::vec3 tilted = glm::normalize(glm::vec3(0.6f, 0.7f, 0.4f));
  const SceneParams aside = key_only(tilted, 3.0f);
  const HdrImage side = bake_environment("studio", aside, 512);
  EXPECT_NEAR(irradiance(side, {0, 1, 0}).g, key_irradiance(aside, {0, 1, 0}), 0.02 * key_irradiance(aside, {0, 1, 0}));
  EXPECT_NEAR(irradiance(side, {0, -1, 0}).g, 0.0, 1e-9);  // nothing from below
}

TEST(EnvironmentBake, TheStudiosSkyIsTheProceduralSky) {
  SceneParams scene = default_params();
  scene.env.floor = false;  // nothing between the centre and the sky below
  const Studio studio(scene);
  const EnvironmentMap map = make_environment_map(bake_environment("studio", scene, 256), "studio");
  // Smooth parts of the sky (not the strips' edges, not the key): within 2 %.
  for (const glm::dvec3& d : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0.3, -0.6, -0.5)),
                              glm::normalize(glm::dvec3(-0.2, 0.3, 0.9)), glm::normalize(glm::dvec3(0.1, -0.95, 0.2))}) {
    const glm::dvec3 want = studio.sky(d), got = map.radiance(d);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 0.02 * want[c] + 1e-4) << d.x << " " << d.y << " " << d.z;
  }
}

TEST(EnvironmentBake, TheStudiosSweepIsLitByTheRigAndTheSky) {
  // Below and behind, the centre (8 cm above the floor) sees the paper sweep: its albedo
  // over pi times the light the rig and the sky give it there, not the sky's ground.
  const SceneParams scene = default_params();
  const EnvironmentMap map = make_environment_map(bake_environment("studio", scene, 512), "studio");
  const glm::dvec3 centre(0.0, 0.08, 0.0);
  const LightRig rig = light_rig(scene, centre);
  const BackdropSurface sweep = backdrop_surface(scene.env, centre);
  const SkyIrradiance sky = sky_irradiance(Studio(scene));
  for (const glm::dvec3& d : {glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(0.3, -0.6, -0.5)),
                              glm::normalize(glm::dvec3(0.1, 0.3, -1.0))}) {  // the floor, the floor, the wall
    double t;
    glm::dvec3 n;
    ASSERT_TRUE(sweep.intersect(centre, d, 0.0, t, n));
    const glm::dvec3 p = centre + t * d;
    const glm::dvec3 want = sweep.albedo(p) / kPi * (rig.irradiance(p, n) + sky.at(n)), got = map.radiance(d);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 0.03 * want[c]) << d.x << " " << d.y << " " << d.z;
    EXPECT_GT(got.g, 3 * Studio(scene).sky(d).g);  // lit paper, much brighter than the dim sky
  }
}

TEST(EnvironmentBake, TheBarIsADimRoomWithBrightLampsAndALitBackBar) {
  const HdrImage bar = bake_environment("bar", default_params(), 512);
  std::vector<float> lum;
  for (const glm::vec3& c : bar.rgb) {
    ASSERT_TRUE(std::isfinite(c.r + c.g + c.b));
    ASSERT_GE(std::min({c.r, c.g, c.b}), 0.0f);
    lum.push_back(0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b);
  }
  std::vector<float> sorted = lum;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_LT(sorted[sorted.size() / 2], 0.1f);  // most of the room is dark
  EXPECT_GT(sorted.back(), 20.0f);             // lamps
  // Warm: the lamps and the shelves are redder than they are blue.
  const glm::dvec3 e = irradiance(bar, {0, 0, 1});  // what a glass's front sees from behind it
  EXPECT_GT(e.r, 1.3 * e.b);
  // The back bar, behind the glass at eye height, is brighter than the wall beside it.
  const EnvironmentMap map = make_environment_map(bar, "bar");
  double back = 0, side = 0;
  for (int i = 0; i < 64; ++i) {
    const double az = (i / 63.0 - 0.5) * 1.6, el = glm::radians(5.0);
    back += glm::length(map.radiance({std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)}, 2));
    side += glm::length(map.radiance({std::cos(el) * std::sin(az + kPi), std::sin(el), -std::cos(el) * std::cos(az + kPi)}, 2));
  }
  EXPECT_GT(back, 4 * side);
}

TEST(EnvironmentBake, ABakedEnvironmentSurvivesARadianceFile) {
  const HdrImage bar = bake_environment("bar", default_params(), 64);
  const HdrImage back = decode_hdr_image(encode_radiance_hdr(bar), "bar.hdr");
  ASSERT_EQ(back.width, 64);
  ASSERT_EQ(back.height, 32);
  for (size_t i = 0; i < bar.rgb.size(); ++i)
    for (int c = 0; c < 3; ++c)  // RGBE: 8 bits of mantissa under the pixel's largest channel
      EXPECT_NEAR(back.rgb[i][c], bar.rgb[i][c], 0.01f * std::max({bar.rgb[i].r, bar.rgb[i].g, bar.rgb[i].b}) + 1e-6f);
}

TEST(EnvironmentBake, UnknownNamesAndWidthsAreRefused) {
  auto error_of = [](const std::string& name, int width) {
    try {
      bake_environment(name, default_params(), width);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_TRUE(test::has(error_of("disco", 64), {"\"disco\"", "studio or bar"}));
  EXPECT_TRUE(test::has(error_of("bar", 63), {"63", "even number from 8 to 8192"}));
  EXPECT_TRUE(test::has(error_of("bar", 16384), {"16384"}));
}

}  // namespace
}  // namespace draught

namespace draught {
namespace {

// The shipped files are what the code bakes today (re-bake with `draught environment bake`).
TEST(EnvironmentBake, TheShippedEnvironmentsAreTodaysBakes) {
  for (const std::string& name : baked_environment_names()) {
    const HdrImage shipped = read_hdr_image(test::preset_source_dir() / "environments" / (name + ".hdr"));
    // The studio is soft light and smooth paper: 512 wide keeps it, at a quarter of the
    // bytes (the web page embeds both); the bar's bottles want 1024.
    ASSERT_EQ(shipped.width, name == "studio" ? 512 : 1024) << name;
    const HdrImage baked = bake_environment(name, default_params(), shipped.width);
    size_t off = 0;
    for (size_t i = 0; i < baked.rgb.size(); ++i)
      for (int c = 0; c < 3; ++c)
        off += std::abs(shipped.rgb[i][c] - baked.rgb[i][c]) >
               0.01f * std::max({baked.rgb[i].r, baked.rgb[i].g, baked.rgb[i].b}) + 1e-6f;
    EXPECT_EQ(off, 0u) << name << ": re-bake presets/environments/" << name << ".hdr";
  }
}

}  // namespace
}  // namespace draught
