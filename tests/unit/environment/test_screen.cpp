// The screen (core/environment/screen): which frame shows at which time (screen.start,
// playing, fps, loop, and a timeline's play, seek and stop), where the card stands and
// what it shows where, the background's look-up across the camera's picture plane (seen
// directly it gives the picture back through the output transform), screen.source
// refused where it is given, and the reference path tracer seeing the card.
#include "core/environment/screen.hpp"
#include "core/io/files.hpp"
#include "core/output/tonemap.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/reference/path_tracer.hpp"
#include "core/scene/frame.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught::test {
namespace {

namespace fs = std::filesystem;

// Frame k: a flat colour of its own (its red channel is 10 k + 5, so the frame shown can
// be read back from any pixel).
Image flat_frame(int k, int w = 8, int h = 4) {
  Image img{w, h, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4, 255)};
  for (int i = 0; i < w * h; ++i) {
    img.rgba[size_t(i) * 4] = std::uint8_t(10 * k + 5);
    img.rgba[size_t(i) * 4 + 1] = 100;
    img.rgba[size_t(i) * 4 + 2] = 50;
  }
  return img;
}

class ScreenTest : public TempDirTest {
 protected:
  ScreenTest() : TempDirTest("draught-screen") {}
  // A sequence of n flat frames.
  std::string sequence(int n) {
    for (int k = 0; k < n; ++k) write_png(dir_ / ("f_" + std::to_string(k) + ".png"), flat_frame(k));
    return dir_.string();
  }
  // The frame the screen shows, by its red channel.
  static int shown(const ScreenFrame& s) { return s.picture ? (s.picture->rgba[0] - 5) / 10 : -1; }
};

TEST(ScreenFrameIndex, FloorsTheTimeWrapsOrHolds) {
  EXPECT_EQ(screen_frame_index(0.0, 25, 10, true), 0);
  EXPECT_EQ(screen_frame_index(0.039, 25, 10, true), 0);
  EXPECT_EQ(screen_frame_index(0.04, 25, 10, true), 1);  // exactly on a frame's start
  EXPECT_EQ(3, screen_frame_index(13 / 25.0, 25, 10, true));
  EXPECT_EQ(9, screen_frame_index(13 / 25.0, 25, 10, false));
  EXPECT_EQ(13, screen_frame_index(13 / 25.0, 25, -1, false));  // length unknown yet
  for (int i = 0; i < 2000; ++i) EXPECT_EQ(screen_frame_index(i / 30.0, 30, -1, true), i) << i;
}

TEST_F(ScreenTest, TheFrameShownFollowsStartPlayingAndFps) {
  SceneParams p;
  p.screen.mode = int(ScreenMode::Card);
  p.screen.source = sequence(6);
  p.screen.fps = 2;  // half a second a frame
  const glm::dvec3 aim(0, 0.07, 0);
  EXPECT_EQ(shown(screen_frame(p, aim, 0.0)), 0);
  EXPECT_EQ(shown(screen_frame(p, aim, 1.2)), 2);
  EXPECT_EQ(shown(screen_frame(p, aim, 3.1)), 0);  // looped: 6 frames, 3 seconds
  p.screen.loop = false;
  EXPECT_EQ(shown(screen_frame(p, aim, 7.0)), 5);  // held at the last
  p.screen.start = 1.0f;
  EXPECT_EQ(shown(screen_frame(p, aim, 0.0)), 2);
  p.screen.playing = false;
  EXPECT_EQ(shown(screen_frame(p, aim, 2.0)), 2);  // held at screen.start
  p.screen.fps = 0;                                // a sequence's own rate: 25 per second
  p.screen.playing = true;
  p.screen.start = 0;
  EXPECT_EQ(shown(screen_frame(p, aim, 0.1)), 2);
  // The frame is the source's own object: the GPU uploads it once.
  EXPECT_EQ(screen_frame(p, aim, 0.1).picture.get(), screen_frame(p, aim, 0.11).picture.get());
  // Off: nothing is read, nothing shown.
  p.screen.mode = int(ScreenMode::Off);
  EXPECT_FALSE(screen_frame(p, aim, 0.0).picture);
}

TEST_F(ScreenTest, TimelinesStartSeekAndStopTheSource) {
  const Timeline tl = parse_timeline(R"({"draught_timeline": 1, "duration": 10, "actions": [
      {"at": 1, "action": "play", "from": 0},
      {"at": 3, "action": "seek", "to": 10},
      {"at": 4, "action": "stop"},
      {"at": 6, "action": "play"},
      {"at": 8, "action": "play", "from": 2.5}]})",
                                     "t.json");
  // screen.playing false: held at screen.start (0.5) until the play at 1.
  const auto at = [&](double t) { return tl.screen_position_at(t, 0.5, false); };
  EXPECT_DOUBLE_EQ(at(0.0), 0.5);
  EXPECT_DOUBLE_EQ(at(0.99), 0.5);
  EXPECT_DOUBLE_EQ(at(1.0), 0.0);
  EXPECT_DOUBLE_EQ(at(2.5), 1.5);
  EXPECT_DOUBLE_EQ(at(3.0), 10.0);
  EXPECT_DOUBLE_EQ(at(3.75), 10.75);
  EXPECT_DOUBLE_EQ(at(5.0), 11.0);  // stopped at 4
  EXPECT_DOUBLE_EQ(at(7.0), 12.0);  // playing on from where it stood
  EXPECT_DOUBLE_EQ(at(9.0), 3.5);
  // Without actions the source plays with the scene from screen.start.
  const Timeline none = parse_timeline(R"({"draught_timeline": 1, "duration": 2, "actions": []})", "n.json");
  EXPECT_DOUBLE_EQ(none.screen_position_at(1.25, 2.0, true), 3.25);
  // scene_at resolves the position into the frame's screen, in double precision.
  Scene s = single_glass_scene(default_params());
  s.params.screen.start = 0.5f;
  s.params.screen.playing = false;
  EXPECT_DOUBLE_EQ(tl.scene_at(2.5, s).params.screen.timeline_position, 1.5);
}

TEST(ScreenTimeline, MistakesInScreenActionsAreNamed) {
  auto error = [](const std::string& actions) {
    try {
      parse_timeline(R"({"draught_timeline": 1, "duration": 4, "actions": [)" + actions + "]}", "v.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_TRUE(has(error(R"({"at": 1, "action": "seek"})"), {"v.json", "actions[0].to", "missing"}));
  EXPECT_TRUE(has(error(R"({"at": 1, "action": "play", "from": -2})"), {"v.json", "actions[0].from", "seconds into the source"}));
  EXPECT_TRUE(has(error(R"({"at": 1, "action": "stop", "object": 0})"), {"v.json", "actions[0].object", "takes no object"}));
  EXPECT_TRUE(has(error(R"({"at": 1, "action": "stop", "duration": 2})"), {"v.json", "actions[0].duration", "unknown key"}));
  EXPECT_TRUE(has(error(R"({"at": 1, "action": "rewind"})"), {"v.json", "play, seek, stop", "rewind"}));
}

TEST_F(ScreenTest, TheCardFacesTheSceneAndShowsThePictureTheRightWayRound) {
  // A picture whose left half is red and top row is green: u runs right, v runs down, as
  // seen from the scene.
  Image img{4, 2, std::vector<std::uint8_t>(32, 255)};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      std::uint8_t* px = img.px(x, y);
      px[0] = x < 2 ? 255 : 0;
      px[1] = y == 0 ? 255 : 0;
      px[2] = 0;
    }
  write_png(dir_ / "lr.png", img);
  SceneParams p;
  p.screen.mode = int(ScreenMode::Card);
  p.screen.source = (dir_ / "lr.png").string();
  p.screen.direction = {0, 0, -1};
  p.screen.distance = 0.5f;
  p.screen.width = 0.4f;
  const ScreenFrame s = screen_frame(p, glm::dvec3(0, 0.1, 0), 0.0);
  EXPECT_NEAR(glm::length(s.center - glm::dvec3(0, 0.1, -0.5)), 0.0, 1e-6);
  EXPECT_NEAR(s.normal.z, 1.0, 1e-9);                  // faces the scene
  EXPECT_NEAR(2 * glm::length(s.half_v), 0.2, 1e-6);  // height from the picture's 2:1
  // From the scene's centre, a ray to the upper left of the card.
  double t;
  glm::dvec2 uv;
  const glm::dvec3 o(0, 0.1, 0);
  ASSERT_TRUE(s.intersect(o, glm::normalize(glm::dvec3(-0.15, 0.07, -0.5)), 0.0, t, uv));
  EXPECT_NEAR(t, glm::length(glm::dvec3(-0.15, 0.07, -0.5)), 1e-6);
  EXPECT_LT(uv.x, 0.5);
  EXPECT_LT(uv.y, 0.5);
  EXPECT_GT(s.texel(uv).r, 0.9);  // red: the picture's left
  EXPECT_GT(s.texel(uv).g, 0.5);  // green: its top
  ASSERT_TRUE(s.intersect(o, glm::normalize(glm::dvec3(0.15, -0.07, -0.5)), 0.0, t, uv));
  EXPECT_LT(s.texel(uv).r, 0.1);
  EXPECT_LT(s.texel(uv).g, 0.5);
  // Not from behind, not beside it.
  EXPECT_FALSE(s.intersect(glm::dvec3(0, 0.1, -1), glm::dvec3(0, 0, 1), 0.0, t, uv));
  EXPECT_FALSE(s.intersect(o, glm::normalize(glm::dvec3(0.3, 0, -0.5)), 0.0, t, uv));
  // The card's radiance: brightness times the texel, in linear light.
  ASSERT_TRUE(s.intersect(o, glm::dvec3(0, 0, -1), 0.0, t, uv));
  EXPECT_NEAR(uv.x, 0.5, 1e-9);
  EXPECT_NEAR(s.card_radiance(glm::dvec2(0.1, 0.25)).r, 1.0, 1e-9);
}

TEST_F(ScreenTest, TheBackgroundSeenDirectlyIsThePictureAsItWasTaken) {
  // A picture of many levels; a camera of the same aspect: every pixel's ray looks up its
  // own pixel, and the output transform undone gives back the byte.
  const int w = 32, h = 16;
  Image img{w, h, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4, 255)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* px = img.px(x, y);
      px[0] = std::uint8_t(8 * x);
      px[1] = std::uint8_t(16 * y);
      px[2] = std::uint8_t((x * 37 + y * 11) % 256);
    }
  write_png(dir_ / "bg.png", img);
  Params params = default_params();
  params.screen.mode = int(ScreenMode::Background);
  params.screen.source = (dir_ / "bg.png").string();
  const FrameState f = make_frame(params);
  EXPECT_FALSE(f.params.env.floor);  // the picture is the surroundings
  EXPECT_FALSE(f.backdrop.present);
  const CameraBasis cam = camera_basis(f, w, h);
  for (const int tonemap : {int(Tonemap::Aces), int(Tonemap::None)}) {
    RenderParams r = f.params.render;
    r.tonemap = tonemap;
    int worst = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Ray ray = camera_ray(cam, x + 0.5, y + 0.5, w, h);
        const glm::dvec2 uv = f.screen.background_uv(ray.d, cam);
        EXPECT_NEAR(uv.x, (x + 0.5) / w, 1e-6);
        EXPECT_NEAR(uv.y, (y + 0.5) / h, 1e-6);
        const glm::u8vec3 out = display_rgb8(f.screen.background_radiance(ray.d, cam, r), r);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(out[c]) - int(img.px(x, y)[c])));
      }
    EXPECT_LE(worst, 1) << "tonemap " << tonemap;
  }
  // A wider view than the picture: the picture covers it, cropped top and bottom.
  const CameraBasis wide = camera_basis(f, 4 * h, h);
  const glm::dvec2 top = f.screen.background_uv(camera_ray(wide, 2 * h, 0.0, 4 * h, h).d, wide);
  EXPECT_NEAR(top.y, 0.25, 1e-6);
  // Behind the camera: mirrored to the front, inside the picture.
  const glm::dvec2 back = f.screen.background_uv(-glm::dvec3(cam.forward), cam);
  EXPECT_NEAR(back.x, 0.5, 1e-9);
  EXPECT_NEAR(back.y, 0.5, 1e-9);
}

TEST(ScreenOutput, AcesInverseUndoesAces) {
  for (double y = 0.0; y <= 1.0; y += 0.01) EXPECT_NEAR(aces_filmic(aces_filmic_inverse(y)), y, 1e-9) << y;
  EXPECT_NEAR(aces_filmic_inverse(1.0), 7.24, 0.01);
}

TEST_F(ScreenTest, SourcesAreRefusedWhereTheyAreGivenAndNothingChanges) {
  const ParamDesc* d = find_param("screen.source");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->type, ParamType::File);
  Params p = default_params();
  EXPECT_NO_THROW(set_param(p, *d, std::string()));  // "": the app streams the picture
  try {
    set_param(p, *d, (dir_ / "missing.mp4").string());
    ADD_FAILURE() << "a missing video was taken";
  } catch (const ParamError& e) {
    EXPECT_TRUE(has(e.what(), {"screen.source", "missing.mp4", "no such file"}));
  }
  EXPECT_EQ(p.screen.source, "");  // unchanged
  try {
    set_param(p, *d, std::string("no-such-clip"));
    ADD_FAILURE() << "an unknown shipped clip was taken";
  } catch (const ParamError& e) {
    EXPECT_TRUE(has(e.what(), {"no shipped video named 'no-such-clip'", "videos"}));
  }
  set_param(p, *d, sequence(3));
  EXPECT_EQ(p.screen.source, dir_.string());
}

TEST_F(ScreenTest, TheReferenceSeesTheCard) {
  // The card straight ahead of the camera, filling the view; nothing else lights the
  // scene: every pixel is the card's radiance.
  write_png(dir_ / "card.png", flat_frame(7));
  Params p = default_params();
  p.env.mode = int(EnvMode::Constant);
  p.env.color = glm::vec3(0);
  p.env.floor = false;
  p.light.power = p.strips.power = p.backlight.power = 0;
  p.screen.mode = int(ScreenMode::Card);
  p.screen.source = (dir_ / "card.png").string();
  p.screen.direction = {0, 0, -1};
  p.screen.distance = 0.6f;
  p.screen.width = 3.0f;
  p.screen.brightness = 2.0f;
  p.camera.auto_frame = false;
  p.camera.eye = {50.0f, 0.075f, 0.4f};  // the glass far out of the view
  p.camera.target = {50.0f, 0.075f, 0.0f};
  FrameState f = make_frame(p);
  ReferenceSettings s;
  s.samples = 2;
  s.threads = 2;
  const RadianceImage img = render_reference(f, 12, 12, s);
  const glm::dvec3 want = 2.0 * glm::dvec3(srgb_to_linear(75 / 255.0), srgb_to_linear(100 / 255.0), srgb_to_linear(50 / 255.0));
  // The card stands at the scene's centre's depth - 0.6 m, 50 m to the left of this
  // camera: it is not seen; moved with the camera it is.
  EXPECT_LT(img.at(6, 6).r, 1e-9);
  f.screen.center.x += 50.0;
  const RadianceImage seen = render_reference(f, 12, 12, s);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen.at(x, y)[c], want[c], 1e-6) << x << "," << y;
}

}  // namespace
}  // namespace draught::test
