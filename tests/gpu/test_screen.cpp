// The screen on the GPU (shaders/lib/environment/screen.glsl, gpu/screen_texture): the card
// and the background against their twins in core ray by ray; a PNG sequence seen through
// a pint of lager renders, at each time of a timeline that plays, seeks and stops it, the
// frame core expects, pixel by pixel along paths traced in double precision; frames are
// uploaded only when another one comes, into the texture not drawn from.
#include "color_difference.hpp"
#include "core/io/image.hpp"
#include "core/output/tonemap.hpp"
#include "core/reference/intersect.hpp"
#include "core/scene/camera.hpp"
#include "gpu/screen_texture.hpp"
#include "gpu_fixture.hpp"
#include "reference_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace draught::test {
namespace {

namespace fs = std::filesystem;

// Frame k of the test sequence (16 x 9): red rises left to right, blue falls top to bottom
// (so a picture turned or flipped by the glass is told apart), green is the frame's own.
constexpr int kPicW = 16, kPicH = 9;
Image sequence_frame(int k) {
  Image img{kPicW, kPicH, std::vector<std::uint8_t>(size_t(kPicW) * kPicH * 4, 255)};
  for (int y = 0; y < kPicH; ++y)
    for (int x = 0; x < kPicW; ++x) {
      std::uint8_t* p = img.px(x, y);
      p[0] = std::uint8_t(30 + 14 * x);
      p[1] = std::uint8_t(20 + 45 * k);
      p[2] = std::uint8_t(230 - 22 * y);
    }
  return img;
}

// frame_0000.png .. frame_0005.png, written once per process.
std::string sequence_pattern() {
  static const std::string pattern = [] {
    const fs::path dir = fs::temp_directory_path() / ("draught-gpu-screen-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (int k = 0; k < 6; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.png", k);
      write_png(dir / name, sequence_frame(k));
    }
    return (dir / "frame_%04d.png").string();
  }();
  return pattern;
}

// What lights the scene: the screen only (a black sky, no lights, no floor); linear output.
std::vector<std::string> screen_only(std::vector<std::string> sets) {
  sets.insert(sets.begin(), {"env.mode=constant", "env.color=0,0,0", "env.floor=false", "light.power=0",
                             "strips.power=0", "backlight.power=0", "render.tonemap=none", "render.exposure=1",
                             "render.supersample=1", "foam.height=0", "bubbles.max_bubbles=0", "camera.auto_frame=false",
                             "screen.source=" + sequence_pattern()});
  return sets;
}
const std::vector<std::string> kCamera = {"eye=0,0.08,0.45", "target=0,0.075,0", "vfov=28"};

constexpr int kScreenW = 96, kScreenH = 96;

double linear(const Image& img, int x, int y, int c) { return srgb8_to_linear(img.px(x, y)[c]); }

TEST(ScreenTwin, TheCardSeenDirectlyIsWhatCoreSees) {
  FrameState f = scene_frame({"lager", "pint",
                              screen_only({"screen.mode=card", "screen.direction=0.2,0.1,-1", "screen.distance=0.3",
                                           "screen.width=0.3", "screen.brightness=0.9", "screen.start=0.2"}),
                              kCamera});
  for (VesselFrame& v : f.vessels) v.pose.position.x += 50.0;  // the glass out of the view
  ASSERT_TRUE(f.screen.picture);
  const Image img = gpu_instance().renderer->render(f, kScreenW, kScreenH);
  const CameraBasis cam = camera_basis(f, kScreenW, kScreenH);
  double worst = 0, sum = 0;
  int seen = 0, outside = 0;
  for (int y = 0; y < kScreenH; ++y)
    for (int x = 0; x < kScreenW; ++x) {
      const Ray r = camera_ray(cam, x + 0.5, y + 0.5, kScreenW, kScreenH);
      double t;
      glm::dvec2 uv;
      if (!f.screen.intersect(r.o, r.d, 0.0, t, uv)) {
        outside += linear(img, x, y, 0) < 0.002;
        continue;
      }
      if (std::min({uv.x, uv.y, 1 - uv.x, 1 - uv.y}) < 0.03) continue;  // its soft edge
      const glm::dvec3 want = f.screen.card_radiance(uv);
      for (int c = 0; c < 3; ++c) {
        const double e = std::abs(linear(img, x, y, c) - want[c]);
        worst = std::max(worst, e);
        sum += e;
      }
      ++seen;
    }
  std::printf("screen card twin: %d pixels, worst %.4f, mean %.5f (linear)\n", seen, worst, sum / (3.0 * seen));
  EXPECT_GT(seen, kScreenW * kScreenH / 4);
  EXPECT_GT(outside, kScreenW * kScreenH / 10);  // and black beside it
  EXPECT_LT(worst, 0.015);
  EXPECT_LT(sum / (3.0 * seen), 0.003);
}

TEST(ScreenTwin, TheBackgroundSeenDirectlyIsThePictureAsItWasTaken) {
  // The AR view: around the glass the camera's picture comes out as it went in, through
  // the ACES tone map and the exposure (undone by the screen).
  FrameState f = scene_frame({"lager", "pint",
                              {"screen.mode=background", "screen.source=" + sequence_pattern(), "screen.start=0.12",
                               "render.supersample=1", "bubbles.max_bubbles=0"},
                              kCamera});
  EXPECT_FALSE(f.params.env.floor);
  for (VesselFrame& v : f.vessels) v.pose.position.x += 50.0;
  const int w = kPicW * 4, h = kPicH * 4;
  const Image img = gpu_instance().renderer->render(f, w, h);
  const CameraBasis cam = camera_basis(f, w, h);
  int worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Ray r = camera_ray(cam, x + 0.5, y + 0.5, w, h);
      const glm::u8vec3 want = display_rgb8(f.screen.background_radiance(r.d, cam, f.params.render), f.params.render);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(img.px(x, y)[c]) - int(want[c])));
    }
  // And core's look-up is the picture: at a texel's centre, the texel.
  const Ray centre = camera_ray(cam, 4 * 5 + 2.0, 4 * 3 + 2.0, w, h);
  const glm::u8vec3 texel = display_rgb8(f.screen.background_radiance(centre.d, cam, f.params.render), f.params.render);
  const Image pic = sequence_frame(3);  // 0.12 s at 25 frames a second
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(texel[c]), int(pic.px(5, 3)[c]), 1);
  std::printf("screen background twin: worst %d of 255\n", worst);
  EXPECT_LE(worst, 3);
}

// The light of a camera ray that reaches the card through the glasses, traced as the path
// pass follows it (refraction, total internal reflection, Beer-Lambert), in double
// precision with core's intersector: the card's radiance where the path meets it times
// what crossing and absorption leave. `signature` lists the surfaces met, so pixels whose
// neighbours take another route (silhouettes, where a float and a double ray may part) can
// be left out. False when the path does not end on the card.
bool through_the_glass(const FrameState& f, const SceneGeometry& geo, Ray r, int frame_shown, glm::dvec3& light,
                       std::string& signature, bool& in_liquid) {
  MediumKind medium = MediumKind::Air;
  int object = -1;
  glm::dvec3 thr(1.0);
  glm::dvec3 left(-1.0);  // the shares of the drink's colour bands (DrinkAbsorption::onward); < 0: none yet
  in_liquid = false;
  for (int e = 0; e < f.params.render.max_events; ++e) {
    const Hit h = next_surface(geo, r, medium, object, e == 0 ? 0.0 : 2e-6);
    if (!h.valid()) {
      if (medium != MediumKind::Air) return false;
      double t;
      glm::dvec2 uv;
      if (!f.screen.intersect(r.o, r.d, 0.0, t, uv) || std::min({uv.x, uv.y, 1 - uv.x, 1 - uv.y}) < 0.04) return false;
      // The frame asked for, looked up as core looks it up.
      ScreenFrame s = f.screen;
      s.picture = std::make_shared<const Image>(sequence_frame(frame_shown));
      light = thr * s.card_radiance(uv);
      return true;
    }
    signature += char('a' + int(h.m));
    if (h.m == Material::Floor) return false;
    const VesselFrame& v = f.vessels[size_t(h.object)];
    if (medium == MediumKind::Glass) thr *= glm::exp(-glm::dvec3(v.params.glass.absorption) * h.t);
    if (medium == MediumKind::Liquid) {
      if (left.x < 0) left = glm::dvec3(v.liquid_absorption.share);
      thr *= v.liquid_absorption.onward(left, h.t);
    }
    const PathTurn turn = turn_at(f, h, r, medium, object);
    if (turn.crossed) {
      thr *= 1.0 - turn.fresnel;
      in_liquid = in_liquid || turn.medium == MediumKind::Liquid;
    }
    r = turn.ray;
    medium = turn.medium;
    object = turn.object;
  }
  return false;
}

TEST(ScreenThroughTheGlass, APngSequenceShowsTheExpectedFrameAtEachTime) {
  // Half a second a frame; the timeline starts it at 0.5 s from its second frame, seeks to
  // its fifth at 2 s and stops at 2.6 s.
  const Timeline tl = parse_timeline(R"({"draught_timeline": 1, "name": "screen", "duration": 4, "actions": [
      {"at": 0.5, "action": "play", "from": 0.5},
      {"at": 2.0, "action": "seek", "to": 2.0},
      {"at": 2.6, "action": "stop"}]})",
                                     "screen-test.json");
  const Scene scene = resolve_scene_objects({"lager", "pint",
                                             screen_only({"screen.mode=card", "screen.fps=2", "screen.playing=false",
                                                          "screen.direction=0,0.05,-1", "screen.distance=0.25",
                                                          "screen.width=0.5", "screen.brightness=2"}),
                                             kCamera});
  struct Moment {
    double t;
    int frame;
  };
  // Held at frame 0 until 0.5 s; then 1 at 0.5, 2 at 1.0, 3 at 1.5; seek: 4 at 2.0, 5 at
  // 2.5, held there from 2.6 on.
  for (const Moment m : {Moment{0.25, 0}, Moment{0.6, 1}, Moment{1.2, 2}, Moment{2.1, 4}, Moment{3.5, 5}}) {
    const FrameState f = draught::timeline_frame(tl, scene, m.t);
    ASSERT_EQ(f.screen.index, m.frame) << "at " << m.t;
    const Image img = gpu_instance().renderer->render(f, kScreenW, kScreenH);
    const CameraBasis cam = camera_basis(f, kScreenW, kScreenH);
    const SceneGeometry geo = scene_geometry(f);
    std::vector<std::string> sig(size_t(kScreenW) * kScreenH);
    std::vector<glm::dvec3> want(size_t(kScreenW) * kScreenH, glm::dvec3(-1.0)), other(size_t(kScreenW) * kScreenH);
    std::vector<char> liquid(size_t(kScreenW) * kScreenH, 0);
    for (int y = 0; y < kScreenH; ++y)
      for (int x = 0; x < kScreenW; ++x) {
        const size_t i = size_t(y) * kScreenW + size_t(x);
        const Ray r = camera_ray(cam, x + 0.5, y + 0.5, kScreenW, kScreenH);
        bool in_liquid = false;
        if (!through_the_glass(f, geo, r, m.frame, want[i], sig[i], in_liquid)) want[i] = glm::dvec3(-1.0);
        liquid[i] = in_liquid;
        std::string unused;
        through_the_glass(f, geo, r, (m.frame + 3) % 6, other[i], unused, in_liquid);
      }
    int probed = 0, close = 0;
    double err = 0, err_other = 0;
    for (int y = 1; y + 1 < kScreenH; ++y)
      for (int x = 1; x + 1 < kScreenW; ++x) {
        const size_t i = size_t(y) * kScreenW + size_t(x);
        if (want[i].r < 0 || !liquid[i]) continue;  // through the drink only
        bool steady = true;
        for (const size_t j : {i - 1, i + 1, i - size_t(kScreenW), i + size_t(kScreenW)}) steady = steady && sig[j] == sig[i] && want[j].r >= 0;
        if (!steady) continue;
        ++probed;
        double worst = 0;
        for (int c = 0; c < 3; ++c) {
          const double got = linear(img, x, y, c), e = std::abs(got - want[i][c]);
          worst = std::max(worst, e - 0.08 * want[i][c]);  // the reflections the pass adds: a few per cent
          err += e;
          err_other += std::abs(got - other[i][c]);
        }
        close += worst < 0.01;
      }
    std::printf("through the glass at %.2f s (frame %d): %d pixels probed, %d close, mean error %.4f (another frame: %.4f)\n",
                m.t, m.frame, probed, close, err / (3.0 * probed), err_other / (3.0 * probed));
    EXPECT_GT(probed, 600) << "at " << m.t;
    EXPECT_GT(close, probed * 95 / 100) << "at " << m.t;
    EXPECT_LT(err / (3.0 * probed), 0.01) << "at " << m.t;
    // The test can fail: another frame is far from the picture.
    EXPECT_GT(err_other, 4 * err) << "at " << m.t;
  }
}

TEST(ScreenUpload, AFrameIsUploadedOnceIntoTheTextureNotDrawnFrom) {
  Gpu& g = gpu_instance();
  gpu::ScreenTexture& tex = g.renderer->screen_texture();
  const Scene scene = resolve_scene_objects({"lager", "pint", screen_only({"screen.mode=card", "screen.fps=2"}), kCamera});
  FrameState a = make_frame(scene);
  const int before = tex.uploads();
  g.renderer->render(a, 32, 32);
  const int after_first = tex.uploads();
  const unsigned drawn = tex.front_texture();
  g.renderer->render(a, 32, 32);
  g.renderer->render(a, 32, 32);
  EXPECT_EQ(tex.uploads(), after_first) << "the same frame again: nothing uploaded";
  EXPECT_LE(after_first - before, 1);
  // The next frame goes into the other texture; the one the last draw read is left alone.
  Scene later = scene;
  later.params.screen.start = 0.5f;
  const FrameState b = make_frame(later);
  ASSERT_NE(b.screen.picture, a.screen.picture);
  g.renderer->render(b, 32, 32);
  EXPECT_EQ(tex.uploads(), after_first + 1);
  EXPECT_NE(tex.front_texture(), drawn);
  g.renderer->render(a, 32, 32);  // back to the first frame: another upload, into the other texture again
  EXPECT_EQ(tex.front_texture(), drawn);
  EXPECT_EQ(tex.width(), kPicW);
  EXPECT_EQ(tex.height(), kPicH);
}

}  // namespace
}  // namespace draught::test
