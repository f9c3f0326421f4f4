// The light heads and haze take (core/environment/media_light): the rig and the surround
// in the studio; under an environment image its brightest patches as lights, their light
// taken out of the harmonics so nothing is counted twice, and an even image left whole.
#include "core/environment/environment_files.hpp"
#include "core/environment/media_light.hpp"
#include "core/environment/reflection.hpp"
#include "core/params/preset.hpp"
#include "core/scene/frame.hpp"

#include "environment/image_scene_test.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace draught {
namespace {

class MediaLightTest : public test::ImageSceneTest {
 protected:
  MediaLightTest() : ImageSceneTest("draught-media-light") {}

  // The default scene under a 64 x 32 image of `base` with `value` at the texels listed.
  SceneParams image_scene(glm::vec3 base, std::vector<glm::ivec2> bright = {}, glm::vec3 value = glm::vec3(0)) {
    return ImageSceneTest::image_scene(write_image("image" + std::to_string(count_++) + ".hdr", base, bright, value));
  }
  int count_ = 0;
};

TEST_F(MediaLightTest, TheStudioGivesTheRigAndTheSurround) {
  const FrameState f = make_frame(default_params());
  const MediaLight& m = f.environment.media;
  ASSERT_EQ(m.lights.size(), f.lights.lights.size());
  for (size_t i = 0; i < m.lights.size(); ++i) {
    EXPECT_EQ(m.lights[i].center, f.lights.lights[i].center);
    EXPECT_EQ(m.lights[i].radiance, f.lights.lights[i].radiance);
  }
  for (size_t k = 0; k < 9; ++k) EXPECT_EQ(m.surround.coef[k], f.environment.surround.coef[k]);
}

// A head sees the surroundings from its own middle (VesselFrame::head_surround), not
// from the scene's centre: the pint's head, near the top of the glass (14 cm against
// 7.5), sees the sweep's paper from higher up, and the light facing the camera's side
// falls by a sixth (measured: 0.84 of the centre's; the sides 0.94-0.96, the sky 0.93).
// Without a backdrop the two views are the same: the sky is at infinity.
TEST_F(MediaLightTest, AHeadSeesTheSurroundingsFromItsMiddle) {
  const FrameState f = make_frame(default_params());
  ASSERT_GT(f.vessels[0].foam.thickness, 1e-3);
  const glm::dvec3 head = head_middle(f.vessels[0]);
  EXPECT_GT(head.y, f.lights.aim.y + 0.05);
  const SkyIrradiance& centre = f.environment.media.surround;
  const SkyIrradiance& there = f.vessels[0].head_surround;
  EXPECT_LT(there.at({0, 0, 1}).y, 0.9 * centre.at({0, 0, 1}).y);
  EXPECT_LT(there.at({1, 0, 0}).y, 0.98 * centre.at({1, 0, 0}).y);

  Params no_floor = default_params();
  no_floor.env.floor = false;
  const FrameState g = make_frame(no_floor);
  for (size_t k = 0; k < 9; ++k)
    EXPECT_EQ(g.vessels[0].head_surround.coef[k], g.environment.media.surround.coef[k]) << "coefficient " << k;
}

// The glasses' shadows in a head's view of the paper (drink_columns): a light's path
// through a stout's column arrives dark, through a lager's paler, beside them whole, and
// above the drink (through the head's air) whole.
TEST_F(MediaLightTest, ADrinkShadowsTheLightThroughItsColumn) {
  const auto columns = [](const char* drink) { return drink_columns(make_frame(resolve_scene({drink, "pint", {}, {}})).vessels); };
  const LightPasses stout = columns("stout"), lager = columns("lager");
  const glm::dvec3 floor_behind(0.3, 0.0, -0.3), light(-1.0, 0.06, 1.0);  // through the foot of the column
  EXPECT_LT(stout(floor_behind, light).r, 0.05);
  EXPECT_GT(lager(floor_behind, light).r, 0.3);
  EXPECT_LT(lager(floor_behind, light).b, lager(floor_behind, light).r);
  EXPECT_EQ(stout({0.3, 0.0, 0.3}, {1.0, 0.06, 1.0}), glm::dvec3(1.0));   // beside the glass
  EXPECT_EQ(stout({0.3, 0.3, -0.3}, {-1.0, 0.3, 1.0}), glm::dvec3(1.0));  // above the drink
}

TEST_F(MediaLightTest, AnEvenImageHasNoLights) {
  const SceneParams p = image_scene(glm::vec3(0.4f));
  const MediaLight m = media_light(Studio(p), LightRig{}, SkyIrradiance{});
  EXPECT_TRUE(m.lights.empty());
}

TEST_F(MediaLightTest, ALampBecomesALightAndLeavesTheHarmonics) {
  // A lamp above and to the side (texel (40, 6) of 64 x 32: about 34 degrees from the
  // zenith), 2000 times the even sky. The 32 x 16 level holds it in one texel, (20, 3).
  const SceneParams p = image_scene(glm::vec3(0.05f), {{40, 6}}, glm::vec3(100.0f));
  const Studio studio(p);
  const SkyIrradiance sky = sky_irradiance(studio);
  const MediaLight m = media_light(studio, LightRig{}, sky);
  ASSERT_EQ(m.lights.size(), 1u);
  const AreaLight& l = m.lights[0];
  const glm::dvec3 to = glm::normalize(l.center);
  const glm::dvec3 lamp = studio.world_direction(equirect_direction({40.5 / 64, 6.5 / 32}));
  EXPECT_GT(glm::dot(to, lamp), std::cos(6.0 * kPi / 180));  // within the level's texel
  // Its light is the lamp's texel's (the image's full level), and its own sky's (the 32 x 16
  // level's texel is four of the image's).
  const auto texel = [](int j, int rows, int cols) {
    return (std::cos(kPi * j / rows) - std::cos(kPi * (j + 1) / rows)) * 2 * kPi / cols;
  };
  const double e = l.radiance.r * l.irradiance_factor({0, 0, 0}, to);
  const double lamp_e = 100 * texel(6, 32, 64), sky_e = 0.05 * (texel(6, 32, 64) + 2 * texel(7, 32, 64));
  EXPECT_NEAR(e, lamp_e + sky_e, 1e-3 * e);
  // Before, facing the lamp saw it through the harmonics; after, only the even sky is
  // left: pi x 0.05 whatever the normal, but for the four texels taken with it.
  EXPECT_GT(sky.at(lamp).r, 3 * kPi * 0.05);
  for (glm::dvec3 n : {lamp, -lamp, glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0)})
    EXPECT_NEAR(m.surround.at(n).r, kPi * 0.05, 0.03 * kPi * 0.05) << n.x << " " << n.y << " " << n.z;
  // And the whole is the same light: the mean radiance the harmonics hold less what the
  // light gives, spread over the sphere (the light moved, none made or lost).
  EXPECT_NEAR(mean_radiance(m.surround).r + e / (4 * kPi), mean_radiance(sky).r, 1e-5 * mean_radiance(sky).r);
}

TEST_F(MediaLightTest, ALampAcrossTwoTexelsIsOneLightAndAtMostFourAreTaken) {
  // Six lamps, two of them side by side in the 32 x 16 level: five lights, four taken.
  const SceneParams p = image_scene(glm::vec3(0.05f), {{4, 4}, {6, 4}, {20, 10}, {36, 4}, {50, 8}, {60, 20}},
                                    glm::vec3(80.0f));
  const Studio studio(p);
  const MediaLight m = media_light(studio, LightRig{}, sky_irradiance(studio));
  ASSERT_EQ(m.lights.size(), size_t(4));
  for (size_t a = 0; a < m.lights.size(); ++a)
    for (size_t b = a + 1; b < m.lights.size(); ++b)
      EXPECT_LT(glm::dot(glm::normalize(m.lights[a].center), glm::normalize(m.lights[b].center)),
                std::cos(15.0 * kPi / 180));
}

TEST_F(MediaLightTest, TheBarsLampsLightItsHeads) {
  Params p = default_params();
  set_param(p, *find_param("env.mode"), std::string("image"));
  set_param(p, *find_param("env.image"), std::string("bar"));
  const FrameState f = make_frame(p);
  const MediaLight& m = f.environment.media;
  EXPECT_GE(m.lights.size(), 1u);
  for (const AreaLight& l : m.lights) {
    const glm::dvec3 to = glm::normalize(l.center - f.lights.aim);
    std::printf("bar light: towards (%.2f, %.2f, %.2f), radiance %.2f, irradiance facing it %.3f\n", to.x, to.y, to.z,
                l.radiance.g, l.radiance.g * l.irradiance_factor(f.lights.aim, to));
  }
  std::printf("bar surround facing up: before %.3f, without the lights %.3f\n", f.environment.surround.at({0, 1, 0}).g,
              m.surround.at({0, 1, 0}).g);
}

}  // namespace
}  // namespace draught
