// env.mode image: an HDR environment as the scene's surroundings. The studio reads it
// turned, scaled and blurred; its light on diffuse surfaces (spherical harmonics) is the
// image's; it replaces the rig's lights; the sweep is only a floor under it; the floor's
// photons come from its brightest patches; and a file that cannot be used is refused
// where it is given, changing nothing.
#include "core/environment/backdrop.hpp"
#include "core/environment/environment_files.hpp"
#include "core/environment/environment_sampling.hpp"
#include "core/environment/floor_light.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/reflection.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/environment/studio.hpp"
#include "core/io/files.hpp"
#include "core/math/random.hpp"
#include "core/params/preset.hpp"
#include "core/scene/frame.hpp"

#include "environment/image_scene_test.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

namespace draught {
namespace {

class EnvironmentImage : public test::ImageSceneTest {
 protected:
  EnvironmentImage() : ImageSceneTest("draught-env-image") {}

  // A 64 x 32 image of `base` with one bright texel in direction `bright` (image space).
  std::string write_image(const std::string& name, glm::vec3 base, glm::dvec3 bright = {0, 0, 0},
                          glm::vec3 value = glm::vec3(0)) {
    std::vector<glm::ivec2> texels;
    if (glm::length(bright) > 0) {
      const glm::dvec2 uv = equirect_uv(glm::normalize(bright));
      texels.push_back({std::min(kWidth - 1, int(uv.x * kWidth)), std::min(kHeight - 1, int(uv.y * kHeight))});
    }
    return ImageSceneTest::write_image(name, base, texels, value);
  }
};

TEST_F(EnvironmentImage, TheStudioSeesTheImageTurnedAndScaled) {
  const glm::dvec3 e = glm::normalize(glm::dvec3(0.3, 0.2, -0.9));  // the bright texel, in the image
  SceneParams p = image_scene(write_image("one.hdr", glm::vec3(0.1f), e, glm::vec3(50.0f)));
  const Studio plain(p);
  EXPECT_GT(plain.sky(e).r, 5.0);  // (bilinear: the texel's direction sees part of it)
  EXPECT_NEAR(plain.sky({0, -1, 0}).r, 0.1, 1e-3);
  p.env.rotation = 90.0f;  // counter-clockwise seen from above: -z (behind the glass) turns to -x
  p.env.intensity = 2.0f;
  const Studio turned(p);
  const glm::dvec3 world(e.z, e.y, -e.x);  // e turned 90 degrees about +y
  EXPECT_NEAR(turned.sky(world).r, 2 * plain.sky(e).r, 1e-6 * plain.sky(e).r);
  EXPECT_NEAR(glm::length(turned.world_direction(turned.image_direction(world)) - world), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(turned.world_direction(e) - world), 0.0, 1e-12);
  EXPECT_NEAR(turned.sky({0, -1, 0}).r, 0.2, 2e-3);
}

TEST_F(EnvironmentImage, BlurAndRoughnessReadBlurrierLevels) {
  const glm::dvec3 e = glm::normalize(glm::dvec3(0.0, 0.1, -1.0));
  SceneParams p = image_scene(write_image("one.hdr", glm::vec3(0.0f), e, glm::vec3(100.0f)));
  const double sharp = Studio(p).sky(e).r;
  EXPECT_DOUBLE_EQ(Studio(p).sky(e, 0.0).r, sharp);
  EXPECT_LT(Studio(p).sky(e, 0.5).r, 0.5 * sharp);  // a rough surface spreads the lamp
  p.env.blur = 20.0f;
  const Studio blurred(p);
  // 20 degrees across a 64-wide image (5.6 degrees per texel): about level 1.8.
  EXPECT_NEAR(blurred.blur_lod, std::log2(glm::radians(20.0) * 64 / (2 * kPi)), 1e-9);
  EXPECT_LT(blurred.sky(e).r, 0.5 * sharp);
}

TEST_F(EnvironmentImage, AConstantImageGivesEveryNormalPiTimesItsRadiance) {
  const Studio s(image_scene(write_image("grey.hdr", glm::vec3(0.5f, 0.25f, 1.0f))));
  const SkyIrradiance sky = sky_irradiance(s);
  for (const glm::dvec3& n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(1, 2, 3))}) {
    const glm::dvec3 e = sky.at(n);
    EXPECT_NEAR(e.r, kPi * 0.5, 1e-3 * kPi);
    EXPECT_NEAR(e.g, kPi * 0.25, 1e-3 * kPi);
    EXPECT_NEAR(e.b, kPi * 1.0, 1e-3 * kPi);
  }
}

TEST_F(EnvironmentImage, ALampInTheImageLightsWhatFacesIt) {
  // A lamp overhead (in the image; turned, it stays overhead) gives a surface facing up
  // its radiance times its solid angle, and one facing down (almost) nothing.
  const std::string file = write_image("lamp.hdr", glm::vec3(0.0f), {0, 1, 0}, glm::vec3(1000.0f));
  const Studio s(image_scene(file));
  const SkyIrradiance sky = sky_irradiance(s);
  EXPECT_GT(sky.at({0, 1, 0}).r, 5 * sky.at({0, -1, 0}).r);
  // The texel's solid angle: a top-row texel of a 64 x 32 image.
  const double solid = (1 - std::cos(kPi / 32)) * 2 * kPi / 64;
  EXPECT_NEAR(sky.at({0, 1, 0}).r, 1000 * solid, 0.15 * 1000 * solid);  // (9 harmonics smooth a point lamp)
}

TEST_F(EnvironmentImage, TheImageReplacesTheRigAndTheSweepIsOnlyAFloor) {
  const std::string file = write_image("lamp.hdr", glm::vec3(0.05f), glm::dvec3(0.5, 0.8, -0.3), glm::vec3(800.0f));
  const FrameState f = make_frame([&] {
    Params p = default_params();
    static_cast<SceneParams&>(p) = image_scene(file);
    return p;
  }());
  EXPECT_TRUE(f.lights.lights.empty());
  ASSERT_TRUE(f.environment.image);
  EXPECT_TRUE(f.backdrop.plane);  // no wall hides the image's horizon
  // The bubbles' glint comes from the lamp.
  EXPECT_GT(glm::dot(glm::dvec3(f.environment.glint_dir), glm::normalize(glm::dvec3(0.5, 0.8, -0.3))), 0.98);
  // The floor's photons come from the brightest patches, the lamp first.
  const LightRig emitters = floor_emitters(f);
  ASSERT_EQ(emitters.lights.size(), kImageFloorEmitters);
  const glm::dvec3 to_lamp = glm::normalize(emitters.lights[0].center - emitters.aim);
  EXPECT_GT(glm::dot(to_lamp, glm::normalize(glm::dvec3(0.5, 0.8, -0.3))), 0.98);
  for (const AreaLight& l : emitters.lights) EXPECT_GT(l.center.y, emitters.aim.y);  // only what reaches the floor
  // The map: the image's even light far from the glass, a shadow beside it, away from the lamp.
  FloorLightSettings s;
  s.photons = 60000;
  const FloorLightMap map = compute_floor_light(f, s);
  ASSERT_FALSE(map.empty());
  const double open = f.environment.sky.at({0, 1, 0}).r;
  EXPECT_NEAR(map.unoccluded(0, 0).r, open, 1e-6 * open);
  const glm::dvec3 foot = f.vessels[0].pose.position;
  const glm::dvec3 away = glm::normalize(glm::dvec3(-0.5, 0, 0.3));  // the lamp's shadow falls this way
  const glm::dvec3 shadow = foot + away * 0.09;
  EXPECT_LT(map.sample(shadow.x, shadow.z).r, 0.8 * open);
}

TEST_F(EnvironmentImage, AFileThatCannotBeUsedIsRefusedAndChangesNothing) {
  const auto text = dir_ / "notes.hdr";
  std::ofstream(text) << "not an image";
  Params p = default_params();
  const ParamDesc& d = *find_param("env.image");
  for (const std::string& bad : {text.string(), (dir_ / "missing.hdr").string(), std::string("no-such-shipped-name"),
                                 std::string("")}) {
    try {
      set_param(p, d, bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const ParamError& e) {
      EXPECT_EQ(e.field, "env.image");
      if (!bad.empty()) {
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
      }
    }
    EXPECT_EQ(p.env.image, "studio");  // unchanged
  }
  // In a preset, the whole preset is refused, naming the file and the field.
  const auto preset = dir_ / "bad.json";
  std::ofstream(preset) << R"({"draught_preset": 1, "kind": "scene", "name": "bad", "params": {"env": {"mode": "image", "image": ")"
                        << text.string() << R"("}}})";
  try {
    load_preset(preset);
    ADD_FAILURE() << "a preset naming a broken environment loaded";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::has(e.what(), {"bad.json", "env.image", "notes.hdr", "not an HDR image"})) << e.what();
  }
}

TEST_F(EnvironmentImage, AFileDeletedWhileInUseKeepsWhatWasRead) {
  const std::string file = write_image("gone.hdr", glm::vec3(0.3f));
  const auto before = load_environment(file);
  std::filesystem::remove(file);
  EXPECT_EQ(load_environment(file).get(), before.get());
  EXPECT_THROW(load_environment((dir_ / "never.hdr").string()), InputError);
}

TEST_F(EnvironmentImage, SamplingFollowsTheImagesLightAndItsDensityIsRight) {
  const glm::dvec3 lamp = glm::normalize(glm::dvec3(-0.4, 0.7, 0.2));
  SceneParams p = image_scene(write_image("lamp.hdr", glm::vec3(0.02f, 0.03f, 0.04f), lamp, glm::vec3(500.0f)));
  p.env.rotation = 35.0f;
  const Studio studio(p);
  const EnvironmentSampler sampler(studio);
  ASSERT_FALSE(sampler.empty());
  Rng rng(7, 0, 0);
  const int n = 200000;
  glm::dvec3 estimate(0.0);
  double largest = 0;  // the largest single sample (red)
  int towards_lamp = 0;
  const glm::dvec3 lamp_world = studio.world_direction(lamp);
  for (int k = 0; k < n; ++k) {
    double pdf, u[4];
    for (double& x : u) x = rng.uniform();  // in order (arguments' order is the compiler's)
    const glm::dvec3 d = sampler.sample(u[0], u[1], u[2], u[3], pdf);
    ASSERT_NEAR(glm::length(d), 1.0, 1e-9);
    ASSERT_NEAR(pdf, sampler.pdf(d), 1e-9 * pdf);  // the density it reports is the one it samples by
    const glm::dvec3 value = studio.sky(d) / pdf;
    estimate += value;
    largest = std::max(largest, value.r);
    towards_lamp += glm::dot(d, lamp_world) > std::cos(glm::radians(8.0));
  }
  estimate /= n;
  // Against the image's integral over the sphere, texel by texel (4 pi x the mean radiance).
  const SkyIrradiance sky = sky_irradiance(studio);
  const glm::dvec3 integral = sky.coef[0] * SkyIrradiance::basis({0, 1, 0})[0] / kPi * 4.0 * kPi;
  // Within 1.5 %: eight seeds in both orders of the four uniforms came within 0.7 %.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(estimate[c], integral[c], 0.015 * integral[c]) << c;
  // No sample carries much of the estimate: the texels beside the lamp, which the bilinear
  // look-up lights with part of it, are picked for it (25 here, 9 x the mean; by each
  // texel's own light alone they were picked at the uniform share's rate: 12,000, and the
  // estimate of a seed 13 % off).
  EXPECT_LT(largest, 20 * integral.r);
  EXPECT_GT(towards_lamp, n / 2);  // the lamp gives most of the light: most samples go there
  // The density integrates to one over the sphere: summed over cells of a finer grid, each
  // inside one of its texels, times their exact solid angles (in the image's own frame).
  const Studio plain(image_scene(write_image("lamp2.hdr", glm::vec3(0.02f), lamp, glm::vec3(500.0f))));
  const EnvironmentSampler straight(plain);
  double total = 0;
  const int w = 512, h = 256;
  for (int j = 0; j < h; ++j) {
    const double solid = (std::cos(kPi * j / h) - std::cos(kPi * (j + 1) / h)) * 2 * kPi / w;
    for (int i = 0; i < w; ++i) total += straight.pdf(equirect_direction({(i + 0.5) / w, (j + 0.5) / h})) * solid;
  }
  EXPECT_NEAR(total, 1.0, 1e-9);
}

TEST(ShippedEnvironments, LoadByNameAndAreKept) {
  for (const char* name : {"studio", "bar"}) {
    const auto a = load_environment(name), b = load_environment(name);
    EXPECT_EQ(a.get(), b.get()) << name << " was read twice";
    EXPECT_GE(a->width(), 512);
    EXPECT_EQ(resolve_environment(name).filename().string(), std::string(name) + ".hdr");
  }
}

}  // namespace
}  // namespace draught
