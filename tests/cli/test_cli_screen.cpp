// End-to-end tests of the screen (screen.*): a missing or undecodable video is refused
// where it is given (a --set, a preset), naming the file, with nothing written; a timeline
// that plays, seeks and stops a PNG sequence renders the same frames every time, each
// showing the frame its time asks for; the shipped screen preset renders.
#include "cli_helpers.hpp"

#include "core/io/image.hpp"

namespace draught_cli_test {
namespace {

using Screen = CliTest;

// Frame k of the test sequence: one flat colour of its own.
draught::Image flat(int k) {
  draught::Image img{8, 4, std::vector<std::uint8_t>(8 * 4 * 4, 255)};
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = std::uint8_t(20 + 40 * k);
    img.rgba[i + 1] = std::uint8_t(200 - 30 * k);
    img.rgba[i + 2] = 90;
  }
  return img;
}

TEST_F(Screen, AMissingVideoIsRefusedNamingIt) {
  const std::string missing = (in() / "missing.mp4").string();
  expect_failure(render({"--set", "screen.mode=card", "--set", "screen.source=" + missing, "-o", (out() / "a.png").string()}),
                 {"--set screen.source=", "field 'screen.source'", "missing.mp4", "no such file"});
  // In a preset: the preset file, the field and the video are named.
  write_file(in() / "scene.json", R"({"draught_preset": 1, "kind": "scene", "name": "s",
      "params": {"screen": {"mode": "card", "source": ")" + missing + R"("}}})");
  expect_failure(render({"--preset", (in() / "scene.json").string(), "-o", (out() / "b.png").string()}),
                 {"scene.json", "screen.source", "missing.mp4", "no such file"});
}

TEST_F(Screen, AnUndecodableVideoIsRefusedSayingWhy) {
  write_file(in() / "clip.mp4", "not a video, only some text pretending\n");
  expect_failure(render({"--set", "screen.mode=background", "--set", "screen.source=" + (in() / "clip.mp4").string(), "-o",
                         (out() / "a.png").string()}),
                 {"clip.mp4", "not a video"});
  write_file(in() / "frames" / "frame_0001.png", "this is no PNG");
  expect_failure(render({"--set", "screen.mode=card", "--set", "screen.source=" + (in() / "frames").string(), "-o",
                         (out() / "b.png").string()}),
                 {"frame_0001.png", "not a PNG file"});
}

TEST_F(Screen, ATimelineOfAScreenIsDeterministicAndShowsTheFrameOfItsTime) {
  fs::create_directories(in() / "frames");
  for (int k = 0; k < 4; ++k) draught::write_png(in() / "frames" / ("frame_" + std::to_string(k) + ".png"), flat(k));
  // Two frames a second, held until 1 s, played from frame 1, stopped at 2.25 s (on frame 3).
  write_file(in() / "screen.json", R"({"draught_timeline": 1, "name": "screen", "duration": 3, "actions": [
      {"at": 1.0, "action": "play", "from": 0.5},
      {"at": 2.25, "action": "stop"}]})");
  // The card fills the view; its top-left corner is seen directly, beside the glass, in
  // linear output: the pixel is the frame's colour.
  const std::vector<std::string> args = {
      "render", "--timeline", (in() / "screen.json").string(), "--fps", "4", "--size", "24x24", "--supersample", "1",
      "--camera", "eye=0,0.08,0.45", "--camera", "target=0,0.075,0", "--set", "camera.auto_frame=false",
      "--set", "screen.mode=card", "--set", "screen.source=" + (in() / "frames").string(), "--set", "screen.fps=2",
      "--set", "screen.playing=false", "--set", "screen.direction=0,0,-1", "--set", "screen.distance=0.5",
      "--set", "screen.width=3", "--set", "env.floor=false", "--set", "render.tonemap=none",
      "--set", "render.exposure=1", "--set", "bubbles.max_bubbles=0", "--set", "strips.power=0"};
  auto run = [&](const std::string& folder) {
    std::vector<std::string> a = args;
    a.insert(a.end(), {"-o", (out() / folder).string() + "/"});
    const RunResult r = draught(a);
    EXPECT_EQ(r.exit_code, 0) << r.describe();
  };
  run("a");
  run("b");
  // t = i / 4: frame 0 up to 1 s; then 1 + floor(2 (t - 1)); held at 3 from 2.25 s.
  const int expected[12] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 3, 3};
  for (int i = 0; i < 12; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    const std::string a = read_file(out() / "a" / name), b = read_file(out() / "b" / name);
    ASSERT_FALSE(a.empty()) << name;
    EXPECT_EQ(a, b) << name << " differs between two runs";
    const draught::Image img = draught::read_png(out() / "a" / name);
    const std::uint8_t* px = img.px(0, 0);
    const draught::Image want = flat(expected[i]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(px[c]), int(want.rgba[size_t(c)]), 2) << name << " channel " << c;
  }
}

TEST_F(Screen, TheShippedScreenPresetRenders) {
  const fs::path png = out() / "screen.png";
  const RunResult r = render({"--preset", "screen-lager", "-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(png).width, 32u);
  const RunResult v = draught({"validate", (kSourceDir / "presets" / "scenes" / "screen-lager.json").string()});
  EXPECT_EQ(v.exit_code, 0) << v.describe();
}

}  // namespace
}  // namespace draught_cli_test
