// env.reflections (gpu/reflection_panoramas, lib/environment/reflections.glsl): each
// glass's surroundings rendered from its middle without it; reflections off a glass's
// outside look there, so glasses mirror each other. Furnace: in an even world with
// nothing that absorbs, the flight stays invisible with its panoramas on. A glass's
// panorama shows its neighbours, not itself, in the studio and in the AR view (a camera
// picture as the background). Only the glasses change in the picture, and the rate
// decides when the panoramas are drawn again.
#include "color_difference.hpp"
#include "gpu_fixture.hpp"

#include "core/io/image.hpp"
#include "gpu/reflection_panoramas.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <unistd.h>

namespace draught::test {
namespace {

std::vector<std::string> with_reflections(std::vector<std::string> sets, bool on) {
  sets.push_back(std::string("env.reflections=") + (on ? "true" : "false"));
  return sets;
}

// Level 0 of a panorama at direction d (bilinear as the picture reads it is not needed:
// the nearest texel).
glm::vec3 panorama_at(const gpu::ReflectionPanoramas& p, const std::vector<float>& px, glm::dvec3 d) {
  const glm::dvec2 st = gpu::panorama_st(glm::normalize(d));
  const int x = std::clamp(int(st.x * p.width()), 0, p.width() - 1), y = std::clamp(int(st.y * p.height()), 0, p.height() - 1);
  const float* t = &px[(size_t(y) * size_t(p.width()) + size_t(x)) * 4];
  return {t[0], t[1], t[2]};
}

TEST(ReflectionPanoramas, TheMappingAndItsInverseAgree) {
  for (glm::dvec3 d : {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0.3, 0.8, 0.2), glm::dvec3(-0.5, -0.7, 0.1)}) {
    d = glm::normalize(d);
    EXPECT_NEAR(glm::length(gpu::panorama_dir(gpu::panorama_st(d)) - d), 0.0, 1e-12);
  }
  EXPECT_NEAR(gpu::panorama_st({0, -1, 0}).y, 0.0, 1e-12);  // the first row drawn looks straight down
  EXPECT_NEAR(gpu::panorama_st({0, 0, -1}).x, 0.5, 1e-12);  // the middle looks along -z, as an image's
}

TEST(ReflectionPanoramas, AnEvenWorldKeepsTheFlightInvisible) {
  // The furnace of tests/gpu/test_furnace.cpp for the flight, heads and drinks clear: every
  // panorama is the even world, so the reflections looked up there are too.
  const std::vector<std::string> furnace = {
      "env.mode=constant", "env.floor=false", "env.color=0.5,0.4,0.3", "light.power=0", "strips.power=0",
      "backlight.power=0", "render.tonemap=none", "render.exposure=1", "glass.absorption=0,0,0", "liquid.srm=0",
      "liquid.ebc=0", "liquid.absorption=0,0,0", "liquid.haze=0", "bubbles.carbonation=0", "render.max_events=24",
      "foam.height=0", "condensation.enabled=false"};
  Gpu& g = gpu_instance();
  const FrameState f = make_frame(flight_scene(FlightView::AtAnAngle, with_reflections(furnace, true)));
  ASSERT_TRUE(f.params.env.reflections);
  const Image img = g.renderer->render(f, 96, 64);
  ASSERT_EQ(g.renderer->reflection_panoramas().layers(), 4);
  const glm::vec3 env(0.5f, 0.4f, 0.3f);
  double worst = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(srgb8_to_linear(img.px(x, y)[c]) / env[c] - 1.0));
  std::printf("flight in the furnace with reflections: worst pixel %.4f of the world\n", worst);
  EXPECT_LT(worst, 0.02);
  // And the panoramas themselves: the even world everywhere, no glass (its own left out).
  const gpu::ReflectionPanoramas& p = g.renderer->reflection_panoramas();
  for (int k = 0; k < 4; ++k) {
    const std::vector<float> px = p.read(k);
    double off = 0;
    for (size_t i = 0; i < px.size(); i += 4)
      for (int c = 0; c < 3; ++c) off = std::max(off, std::fabs(double(px[i + size_t(c)]) / env[c] - 1.0));
    EXPECT_LT(off, 0.02) << "panorama " << k;
  }
}

TEST(ReflectionPanoramas, AGlassSeesItsNeighboursNotItself) {
  Gpu& g = gpu_instance();
  // The pilsner (x = -0.18) looks along +x at the amber ale (x = -0.06) in the flight; in a
  // scene of the pilsner alone it sees the studio there. Away from the row (-x, +z) both
  // see the studio alike: the pilsner itself is not in its own panorama.
  Scene flight = flight_scene(FlightView::StraightOn, {"env.reflections=true"});
  const FrameState all = make_frame(flight);
  g.renderer->render(all, 64, 48);
  const gpu::ReflectionPanoramas& p = g.renderer->reflection_panoramas();
  ASSERT_EQ(p.layers(), 4);
  const std::vector<float> with_others = p.read(0);
  Scene alone = flight;
  alone.objects.resize(1);
  g.renderer->render(make_frame(alone), 64, 48);
  ASSERT_EQ(p.layers(), 1);
  const std::vector<float> by_itself = p.read(0);
  const glm::dvec3 towards_ale(1, -0.05, 0), away(-1, 0.1, 0.6);
  const glm::vec3 ale = panorama_at(p, with_others, towards_ale), studio = panorama_at(p, by_itself, towards_ale);
  std::printf("towards the ale: with it (%.3f %.3f %.3f), without (%.3f %.3f %.3f)\n", ale.r, ale.g, ale.b, studio.r,
              studio.g, studio.b);
  EXPECT_GT(ale.r, 1.3f * ale.b);           // the amber drink
  EXPECT_LT(ale.b, 0.7f * studio.b);        // darker than the white studio there
  const glm::vec3 a = panorama_at(p, with_others, away), b = panorama_at(p, by_itself, away);
  EXPECT_NEAR(a.g, b.g, 0.03f * b.g + 1e-3f);
}

TEST(ReflectionPanoramas, InTheARViewTheGlassesMirrorEachOtherToo) {
  // screen.mode=background: a phone's camera picture is the whole background, no floor.
  // The pilsner's panorama still shows the amber ale beside it, and away from the row the
  // same surroundings as the pilsner's alone (the picture, read where the AR view reads
  // that direction).
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("draught-gpu-ar-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Image pic{16, 9, std::vector<std::uint8_t>(16 * 9 * 4, 255)};
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* q = pic.px(x, y);
      q[0] = std::uint8_t(90 + 5 * x), q[1] = 160, q[2] = std::uint8_t(120 + 10 * y);
    }
  write_png(dir / "camera.png", pic);
  Gpu& g = gpu_instance();
  const std::vector<std::string> ar = {"screen.mode=background", "screen.source=" + (dir / "camera.png").string()};
  Scene flight = flight_scene(FlightView::StraightOn, with_reflections(ar, true));
  const FrameState all = make_frame(flight);
  const Image with_panoramas = g.renderer->render(all, 64, 48);
  const gpu::ReflectionPanoramas& p = g.renderer->reflection_panoramas();
  ASSERT_EQ(p.layers(), 4);
  const std::vector<float> with_others = p.read(0);
  for (float v : with_others) ASSERT_TRUE(std::isfinite(v));
  Scene alone = flight;
  alone.objects.resize(1);
  g.renderer->render(make_frame(alone), 64, 48);
  const std::vector<float> by_itself = p.read(0);
  const glm::dvec3 towards_ale(1, -0.05, 0), away(-1, 0.1, 0.6);
  const glm::vec3 ale = panorama_at(p, with_others, towards_ale), open = panorama_at(p, by_itself, towards_ale);
  const glm::vec3 a = panorama_at(p, with_others, away), b = panorama_at(p, by_itself, away);
  std::printf("AR: towards the ale (%.3f %.3f %.3f), alone (%.3f %.3f %.3f); away (%.3f %.3f %.3f), alone (%.3f %.3f %.3f)\n",
              ale.r, ale.g, ale.b, open.r, open.g, open.b, a.r, a.g, a.b, b.r, b.g, b.b);
  // The ale is there: a dark drink against the picture, as in the AR view itself (an amber
  // drink absorbs the picture's blue-green behind it).
  EXPECT_LT(ale.g, 0.5f * open.g);
  EXPECT_GT(ale.r, ale.g);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 0.03f * b[k] + 1e-3f);
  // And the picture differs from the same view without panoramas only on the glasses'
  // outsides (the background is the camera's picture either way).
  const Image without = g.renderer->render(make_frame(flight_scene(FlightView::StraightOn, with_reflections(ar, false))), 64, 48);
  int changed = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) changed += std::abs(int(with_panoramas.px(x, y)[c]) - int(without.px(x, y)[c])) > 8;
  EXPECT_GT(changed, 0);
  std::filesystem::remove_all(dir);
}

TEST(ReflectionPanoramas, OnlyTheGlassesChangeAndTheyMirrorEachOther) {
  Gpu& g = gpu_instance();
  // (Adaptive supersampling off: which pixels it draws again follows the glasses' pixels,
  // so a background pixel next to them may take 4 x 4 samples in one picture, not the other.)
  const FrameState off =
      make_frame(flight_scene(FlightView::AtAnAngle, {"env.reflections=false", "render.adaptive_supersample=1"}));
  const FrameState on =
      make_frame(flight_scene(FlightView::AtAnAngle, {"env.reflections=true", "render.adaptive_supersample=1"}));
  const int w = 160, h = 110;
  const Image a = g.renderer->render(off, w, h), b = g.renderer->render(on, w, h);
  const gpu::DebugImage first = g.renderer->render_debug(on, w, h, gpu::DebugView::Material);
  const auto background = [&](int x, int y) {
    const int m = int(first.px(x, y)[1]);
    return m == int(contract::Material::None) || m == int(contract::Material::Floor);
  };
  int background_changed = 0, glass_changed = 0, glass = 0;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      int diff = 0;
      for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(a.px(x, y)[c]) - int(b.px(x, y)[c])));
      bool around = true;  // (a pixel at a glass's edge takes some of the glass: supersampled)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) around = around && background(x + dx, y + dy);
      if (around) {
        if (diff > 0) ++background_changed;
      } else if (!background(x, y)) {
        ++glass;
        if (diff > 8) ++glass_changed;
      }
    }
  std::printf("reflections: %d of %d glass pixels changed by more than 8 levels; background changed: %d\n",
              glass_changed, glass, background_changed);
  // (The rising bubbles are sprites over the picture and see no reflections.)
  EXPECT_EQ(background_changed, 0);
  EXPECT_GT(glass_changed, glass / 50);
}

TEST(ReflectionPanoramas, ACutoutsGlassesMirrorEachOtherAsTheOpaquePicturesDo) {
  // --transparent: the panoramas are the opaque world's (the studio and the neighbours, not
  // the page's clear), and the glasses' outsides show them: the floor too, with the
  // shadows and caustics the opaque picture's light map gives it (a transparent picture
  // traced none before, and its mirrored floor was lit by the rig alone).
  Gpu& g = gpu_instance();
  const gpu::ReflectionPanoramas& p = g.renderer->reflection_panoramas();
  g.renderer->render(make_frame(flight_scene(FlightView::StraightOn, {"env.reflections=true"})), 64, 48);
  ASSERT_EQ(p.layers(), 4);
  const std::vector<float> opaque = p.read(0);
  const auto cutout = [](bool reflections) {
    return make_frame(flight_scene(FlightView::StraightOn,
                                   with_reflections({"render.transparent=true", "render.adaptive_supersample=1"}, reflections)));
  };
  const int drawn = p.draws();
  const Image with = g.renderer->render(cutout(true), 64, 48);
  ASSERT_EQ(p.draws(), drawn + 4);  // (drawn for the cutout, not left from the opaque picture)
  const std::vector<float> transparent = p.read(0);
  ASSERT_EQ(transparent.size(), opaque.size());
  // Every direction the same light: above, the studio and the neighbours; below, the lit
  // floor with the glasses' shadows and caustics.
  double worst = 0, sum_below_t = 0, sum_below_o = 0, darkest_floor = INFINITY, darkest_opaque = INFINITY;
  for (int y = 0; y < p.height(); ++y) {
    const double up = gpu::panorama_dir({0.5, (y + 0.5) / p.height()}).y;
    for (int x = 0; x < p.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = (size_t(y) * size_t(p.width()) + size_t(x)) * 4 + size_t(c);
        worst = std::max(worst, std::fabs(double(transparent[i]) - double(opaque[i])) / (double(opaque[i]) + 0.01));
        if (up < 0.0) sum_below_t += transparent[i], sum_below_o += opaque[i];
        if (up < -0.9) {
          darkest_floor = std::min(darkest_floor, double(transparent[i]));
          darkest_opaque = std::min(darkest_opaque, double(opaque[i]));
        }
      }
  }
  std::printf("cutout's panorama against the opaque picture's: worst %.2e relative, below the horizon %.4f of its "
              "light; the floor below at least %.3f (opaque %.3f)\n", worst, sum_below_t / sum_below_o, darkest_floor,
              darkest_opaque);
  EXPECT_LT(worst, 0.01);
  EXPECT_NEAR(sum_below_t / sum_below_o, 1.0, 0.005);
  EXPECT_GT(darkest_floor, 0.1);  // the studio's lit floor, not the page's clear
  const glm::vec3 ale = panorama_at(p, transparent, glm::dvec3(1, -0.05, 0));
  EXPECT_GT(ale.r, 1.3f * ale.b);  // the amber ale beside the pilsner, as in the opaque picture's
  const Image without = g.renderer->render(cutout(false), 64, 48);
  int changed = 0, clear = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      clear += with.px(x, y)[3] == 0 && without.px(x, y)[3] == 0;
      for (int c = 0; c < 4; ++c) changed += std::abs(int(with.px(x, y)[c]) - int(without.px(x, y)[c])) > 8;
    }
  std::printf("cutout with reflections: %d samples changed by more than 8 levels, %d pixels clear in both\n", changed, clear);
  EXPECT_GT(changed, 0);
  EXPECT_GT(clear, 64 * 48 / 3);  // (the page still shows round the glasses)
}

TEST(ReflectionPanoramas, TheRateDecidesWhenTheyAreDrawnAgain) {
  Gpu& g = gpu_instance();
  Scene s = flight_scene(FlightView::StraightOn, {"env.reflections=true", "env.reflections_rate=2"});
  FrameState f = make_frame(s);
  const gpu::ReflectionPanoramas& p = g.renderer->reflection_panoramas();
  f.time = 10.05;
  g.renderer->render(f, 32, 24);
  const int first = p.draws();
  f.time = 10.3;  // the same half second
  g.renderer->render(f, 32, 24);
  EXPECT_EQ(p.draws(), first);
  f.time = 10.6;  // the next
  g.renderer->render(f, 32, 24);
  EXPECT_EQ(p.draws(), first + 4);
  f.params.env.reflections_rate = 0;  // every frame
  g.renderer->render(f, 32, 24);
  g.renderer->render(f, 32, 24);
  EXPECT_EQ(p.draws(), first + 12);
}

}  // namespace
}  // namespace draught::test
