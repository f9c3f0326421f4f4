// env.mode image on the GPU: the picture's environment (shaders/lib/environment/image.glsl)
// against its twin in core (Studio::sky with its image), ray by ray, turned, scaled and
// blurred; the furnace under a constant image; the image uploaded once, not every frame.
#include "color_difference.hpp"
#include "core/environment/studio.hpp"
#include "core/io/hdr_image.hpp"
#include "core/scene/camera.hpp"
#include "gpu/scene_data.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace draught::test {
namespace {

constexpr int kEnvW = 96, kEnvH = 72;

// An image with features everywhere (smooth, so a float ray's tiny error stays tiny in
// value): stripes across, bands down, a different pattern per channel, within [0.05, 0.9].
std::string patterned_image() {
  static const std::string path = [] {
    const int w = 128, h = 64;
    HdrImage img{w, h, std::vector<glm::vec3>(size_t(w) * size_t(h))};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double u = (x + 0.5) / w, v = (y + 0.5) / h;
        img.rgb[size_t(y) * size_t(w) + size_t(x)] =
            glm::vec3(0.45 + 0.4 * std::sin(2 * M_PI * 3 * u), 0.45 + 0.4 * std::cos(2 * M_PI * 2 * v),
                      0.45 + 0.4 * std::sin(2 * M_PI * (5 * u + 3 * v)));
      }
    const auto p = std::filesystem::temp_directory_path() / ("draught-gpu-env-" + std::to_string(::getpid()) + ".hdr");
    write_radiance_hdr(p, img);
    return p.string();
  }();
  return path;
}

// The environment alone: no floor, the glass far out of sight, linear output.
FrameState environment_frame_of(const std::string& image, std::vector<std::string> sets) {
  sets.insert(sets.end(), {"env.mode=image", "env.image=" + image, "env.floor=false", "render.tonemap=none",
                           "render.exposure=1", "render.supersample=1", "camera.auto_frame=false",
                           "bubbles.max_bubbles=0"});
  FrameState f = scene_frame({"lager", "pint", sets, {"eye=0,0.1,0.4", "target=0.2,0.15,-0.3", "vfov=100"}});
  for (VesselFrame& v : f.vessels) v.pose.position.x += 50.0;
  return f;
}

TEST(EnvironmentImageTwin, ThePictureSeesWhatCoreSees) {
  Gpu& g = gpu_instance();
  struct Case {
    const char* name;
    std::vector<std::string> sets;
  };
  for (const Case& c : {Case{"plain", {}}, Case{"turned and scaled", {"env.rotation=-63", "env.intensity=0.8"}},
                        Case{"blurred", {"env.blur=12", "env.rotation=150"}}}) {
    const FrameState f = environment_frame_of(patterned_image(), c.sets);
    const Studio studio(f.params);
    ASSERT_TRUE(studio.image);
    const Image img = g.renderer->render(f, kEnvW, kEnvH);
    const CameraBasis cam = camera_basis(f, kEnvW, kEnvH);
    double worst = 0, sum = 0;
    for (int y = 0; y < kEnvH; ++y)
      for (int x = 0; x < kEnvW; ++x) {
        const glm::dvec3 want = studio.sky(camera_ray(cam, x + 0.5, y + 0.5, kEnvW, kEnvH).d);
        for (int k = 0; k < 3; ++k) {
          const double e = std::abs(srgb8_to_linear(img.px(x, y)[k]) - want[k]);
          worst = std::max(worst, e);
          sum += e;
        }
      }
    std::printf("environment image twin, %s: worst %.4f, mean %.5f (linear)\n", c.name, worst, sum / (3.0 * kEnvW * kEnvH));
    // One 8-bit step at 0.9 is 0.0035 in linear light; half floats round at 5e-4.
    EXPECT_LT(worst, 0.01) << c.name;
    EXPECT_LT(sum / (3.0 * kEnvW * kEnvH), 0.002) << c.name;
  }
  // The test can fail: the image turned the other way is another picture.
  const FrameState a = environment_frame_of(patterned_image(), {"env.rotation=30"});
  const FrameState b = environment_frame_of(patterned_image(), {"env.rotation=-30"});
  const Image ia = g.renderer->render(a, kEnvW, kEnvH), ib = g.renderer->render(b, kEnvW, kEnvH);
  int differ = 0;
  for (size_t i = 0; i < ia.rgba.size(); ++i) differ += std::abs(int(ia.rgba[i]) - int(ib.rgba[i])) > 8;
  EXPECT_GT(differ, int(ia.rgba.size() / 4));
}

TEST(EnvironmentImageTwin, UnderAConstantImageANonAbsorbingGlassIsInvisible) {
  static const std::string path = [] {
    HdrImage img{64, 32, std::vector<glm::vec3>(64 * 32, glm::vec3(0.5f, 0.4f, 0.3f))};
    const auto p = std::filesystem::temp_directory_path() / ("draught-gpu-furnace-" + std::to_string(::getpid()) + ".hdr");
    write_radiance_hdr(p, img);
    return p.string();
  }();
  SceneRequest req{"lager", "pint"};
  req.sets = {"env.mode=image", "env.image=" + path, "env.floor=false", "render.tonemap=none", "render.exposure=1",
              "glass.absorption=0,0,0", "liquid.fill=0", "render.max_events=24", "bubbles.carbonation=0"};
  const Image img = gpu_instance().renderer->render(scene_frame(req), 64, 64);
  double worst = 0;
  const glm::vec3 env(0.5f, 0.4f, 0.3f);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(srgb8_to_linear(img.px(x, y)[c]) / env[c] - 1.0));
  EXPECT_LT(worst, 0.02);
}

TEST(EnvironmentImageTwin, TheImageIsUploadedOnceNotEveryFrame) {
  gpu_instance();  // the GL context the textures are made in
  gpu::SceneTextures textures;
  const FrameState f = environment_frame_of("bar", {});
  textures.update(f, 64, 64);
  EXPECT_TRUE(textures.environment_uploaded());
  textures.update(f, 64, 64);
  EXPECT_FALSE(textures.environment_uploaded());
  textures.update(environment_frame_of("bar", {"env.rotation=20", "env.intensity=2"}), 64, 64);  // the same image, seen otherwise
  EXPECT_FALSE(textures.environment_uploaded());
  textures.update(environment_frame_of("studio", {}), 64, 64);
  EXPECT_TRUE(textures.environment_uploaded());
}

}  // namespace
}  // namespace draught::test
