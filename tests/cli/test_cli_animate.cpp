// End-to-end tests of `draught render --timeline`: PNG sequences, MP4 / GIF through
// ffmpeg, the progress bar, timelines given as files, and the flags that do not mix.
// Small images and few frames throughout: CI has two cores.
#include "cli_helpers.hpp"

#include "core/io/image.hpp"

#include <cstdio>

namespace draught_cli_test {
namespace {

// The frames a PNG-sequence render should write: frame_00000.png ... frame_{n-1}.png.
std::string expected_frames(int n) {
  std::vector<std::string> names;
  for (int i = 0; i < n; ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "frame_%05d.png", i);
    names.push_back(buf);
  }
  return join(names);
}

// The spilled percentage the final "wrote ..." line reports, or -1 when there is none.
double spilled_percent(const std::string& out) {
  const std::string percent = first_group(out, R"(spilled\s+([0-9]+(?:\.[0-9]+)?)\s*%)");
  return percent.empty() ? -1 : std::stod(percent);
}

// Number of pixels whose RGBA differs between two images of the same size.
int differing_pixels(const draught::Image& a, const draught::Image& b) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (!std::equal(a.px(x, y), a.px(x, y) + 4, b.px(x, y))) ++n;
  return n;
}

class Animate : public CliTest {
 protected:
  // `render --timeline <timeline> --supersample 1 <args...>`: fast defaults of 48x48,
  // 4 fps and 1 s unless the args say otherwise.
  RunResult animate(const std::string& timeline, std::vector<std::string> args,
                    const std::map<std::string, std::optional<std::string>>& env = {}) {
    auto has = [&](const char* opt) { return std::find(args.begin(), args.end(), opt) != args.end(); };
    std::vector<std::string> a = {"render", "--timeline", timeline};
    if (!has("--size")) a.insert(a.end(), {"--size", "48x48"});
    if (!has("--fps")) a.insert(a.end(), {"--fps", "4"});
    if (!has("--duration") && !has("--full")) a.insert(a.end(), {"--duration", "1"});
    if (!has("--supersample")) a.insert(a.end(), {"--supersample", "1"});
    std::erase(args, std::string("--full"));
    a.insert(a.end(), args.begin(), args.end());
    return draught(a, env);
  }
  // A folder for PNG frames, as the user would spell it (trailing slash).
  std::string frames_dir(const std::string& name) const { return (out() / name).string() + "/"; }
};

// ---------------------------------------------------------------- PNG sequences

TEST_F(Animate, WritesNumberedPngFramesOfRequestedSize) {
  auto r = animate("gentle-tilt", {"-o", frames_dir("frames")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "frames")), expected_frames(4)) << "wrong frames, or stray files";
  EXPECT_EQ(join(list_tree(out())),
            "frames, frames/frame_00000.png, frames/frame_00001.png, frames/frame_00002.png, frames/frame_00003.png")
      << "files outside the frames folder";
  EXPECT_TRUE(contains(r.out, "wrote")) << r.describe();
  EXPECT_TRUE(contains(r.out, (out() / "frames").string())) << "does not say where the frames are\n" << r.describe();
  EXPECT_TRUE(matches(r.out, R"(\b4 frames\b)")) << "no frame count\n" << r.describe();
  for (int i = 0; i < 4; ++i) {
    const fs::path p = out() / "frames" / ("frame_0000" + std::to_string(i) + ".png");
    PngInfo info = png_info(p);
    ASSERT_EQ(info.error, "");
    EXPECT_EQ(info.width, 48u) << p;
    EXPECT_EQ(info.height, 48u) << p;
    draught::Image img = draught::read_png(p);
    EXPECT_EQ(img.width, 48) << p;
    EXPECT_EQ(img.height, 48) << p;
  }
}

TEST_F(Animate, NonSquareSizeAndFrameCountFollowFpsTimesDuration) {
  auto r = animate("gentle-tilt", {"--size", "40x24", "--fps", "3", "--duration", "2", "-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "f")), expected_frames(6));
  EXPECT_TRUE(matches(r.out, R"(\b6 frames\b)")) << r.describe();
  PngInfo info = png_info(out() / "f" / "frame_00005.png");
  ASSERT_EQ(info.error, "");
  EXPECT_EQ(info.width, 40u);
  EXPECT_EQ(info.height, 24u);
}

TEST_F(Animate, FirstFrameIsTheStillOfTheTimelinesScene) {
  // gentle-tilt starts upright with the camera not yet moved, on the timeline's lager:
  // frame 0 is what `render --preset lager` draws.
  auto a = animate("gentle-tilt", {"--duration", "0.25", "-o", frames_dir("f")});
  ASSERT_EQ(a.exit_code, 0) << a.describe();
  const fs::path still = out() / "still.png";
  auto s = draught({"render", "--preset", "lager", "--size", "48x48", "--supersample", "1", "-o", still.string()});
  ASSERT_EQ(s.exit_code, 0) << s.describe();
  const auto frame = draught::read_png(out() / "f" / "frame_00000.png");
  const auto ref = draught::read_png(still);
  ASSERT_EQ(frame.width, ref.width);
  ASSERT_EQ(frame.height, ref.height);
  EXPECT_EQ(differing_pixels(frame, ref), 0) << "frame 0 of gentle-tilt is not the still lager in its pint";
}

TEST_F(Animate, IsDeterministic) {
  for (const char* d : {"a", "b"}) {
    auto r = animate("shake-and-settle", {"--duration", "1.5", "-o", frames_dir(d)});
    ASSERT_EQ(r.exit_code, 0) << r.describe();
  }
  const auto a = list_tree(out() / "a");
  ASSERT_EQ(join(a), expected_frames(6));
  ASSERT_EQ(join(list_tree(out() / "b")), join(a));
  for (auto& f : a)
    EXPECT_EQ(read_file(out() / "a" / f), read_file(out() / "b" / f)) << f << " differs between two identical runs";
}

TEST_F(Animate, MotionShowsAndTiltUntilSpillSpills) {
  // The whole default duration (8 s) at 2 fps and 32x32: tiny, but the glass tips past
  // its rim and stands back up.
  auto r = animate("tilt-until-spill", {"--full", "--size", "32x32", "--fps", "2", "-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "f")), expected_frames(16));
  EXPECT_TRUE(matches(r.out, R"(\b16 frames\b)")) << r.describe();
  const double spilled = spilled_percent(r.out);
  EXPECT_GT(spilled, 0.0) << "tilt-until-spill spilled nothing (or says nothing about it)\n" << r.describe();
  EXPECT_LE(spilled, 100.0) << r.describe();
  const auto first = draught::read_png(out() / "f" / "frame_00000.png");
  const auto tipped = draught::read_png(out() / "f" / "frame_00009.png");  // t = 4.5 s, leaning ~60 degrees
  ASSERT_EQ(first.width, tipped.width);
  EXPECT_GT(differing_pixels(first, tipped), 32 * 32 / 20) << "frame 9 looks like frame 0: nothing moved";
}

TEST_F(Animate, SpilledIsOfTheLastPourNotASumOverPours) {
  // Five pours (instant fills) into a glass held at 120 degrees: each spills nearly all of it. The
  // readout is the spill since the last pour (at most what was poured), not a sum over
  // the pours, which read "spilled 538.8 % of the glass".
  write_file(in() / "pours.json",
             R"({"draught_timeline": 1, "name": "pours", "duration": 6, "actions": [
                 {"at": 0, "action": "tilt", "angle": 120, "duration": 0.5},
                 {"at": 1, "action": "pour", "duration": 0}, {"at": 2, "action": "pour", "duration": 0},
                 {"at": 3, "action": "pour", "duration": 0}, {"at": 4, "action": "pour", "duration": 0},
                 {"at": 5, "action": "pour", "duration": 0}]})");
  auto r = animate((in() / "pours.json").string(), {"--size", "16x16", "--fps", "1", "--full", "-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const double spilled = spilled_percent(r.out);
  EXPECT_GT(spilled, 50.0) << "the last pour spilled most of the drink\n" << r.describe();
  EXPECT_LE(spilled, 100.0) << r.describe();
}

TEST_F(Animate, GentleTiltDoesNotSpill) {
  auto r = animate("gentle-tilt", {"--size", "16x16", "--fps", "1", "--full", "-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "f")), expected_frames(6));
  EXPECT_EQ(spilled_percent(r.out), 0.0) << "a 14 degree tilt of a lager should not spill\n" << r.describe();
}

// ---------------------------------------------------------------- video through ffmpeg

TEST_F(Animate, WritesMp4ThroughFfmpeg) {
  const fs::path mp4 = out() / "clip.mp4";
  auto r = animate("gentle-tilt", {"-o", mp4.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "wrote " + mp4.string())) << r.describe();
  const std::string b = read_file(mp4);
  ASSERT_GT(b.size(), 100u) << "empty or tiny MP4";
  EXPECT_EQ(b.substr(4, 4), "ftyp") << "not an MP4 (no ftyp box first)";
  EXPECT_EQ(join(list_tree(out())), "clip.mp4") << "leftover .part or other files";
}

TEST_F(Animate, WritesMp4OfOddSize) {
  // H.264 in yuv420p needs even sizes: odd ones are padded, not refused.
  const fs::path mp4 = out() / "odd.mp4";
  auto r = animate("gentle-tilt", {"--size", "31x17", "--duration", "0.5", "-o", mp4.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const std::string b = read_file(mp4);
  ASSERT_GT(b.size(), 100u);
  EXPECT_EQ(b.substr(4, 4), "ftyp");
  EXPECT_EQ(join(list_tree(out())), "odd.mp4");
}

// The first frame of a WebM decoded with its alpha (libvpx's decoder: ffmpeg's own VP9
// decoder drops the alpha plane), RGBA rows; empty when ffmpeg cannot decode it.
// A WebM's frames as RGBA bytes, one after another (all, or the first `frames`), decoded by
// libvpx (ffmpeg's own VP9 decoder drops the alpha plane).
std::vector<std::uint8_t> webm_frames(const fs::path& webm, int frames = 0) {
  const std::string cmd = "ffmpeg -nostdin -v error -c:v libvpx-vp9 -i '" + webm.string() + "'" +
                          (frames > 0 ? " -frames:v " + std::to_string(frames) : std::string()) +
                          " -pix_fmt rgba -f rawvideo - 2>/dev/null";
  std::vector<std::uint8_t> bytes;
  if (FILE* f = popen(cmd.c_str(), "r")) {
    std::uint8_t buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, f)) > 0;) bytes.insert(bytes.end(), buf, buf + n);
    pclose(f);
  }
  return bytes;
}

TEST_F(Animate, WritesTransparentWebmWithItsAlpha) {
  // The cutout in motion: VP9 with an alpha plane, the frames in straight alpha.
  const fs::path webm = out() / "cutout.webm";
  auto r = animate("gentle-tilt", {"--transparent", "-o", webm.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "wrote " + webm.string())) << r.describe();
  const std::string b = read_file(webm);
  ASSERT_GT(b.size(), 100u) << "empty or tiny WebM";
  EXPECT_EQ(b.substr(0, 4), "\x1A\x45\xDF\xA3") << "not a Matroska/WebM file (no EBML header)";
  EXPECT_TRUE(contains(b, "webm")) << "the EBML header does not name the webm doc type";
  EXPECT_EQ(join(list_tree(out())), "cutout.webm") << "leftover .part or other files";
  const std::vector<std::uint8_t> px = webm_frames(webm, 1);
  ASSERT_EQ(px.size(), size_t(48 * 48 * 4)) << "ffmpeg could not decode the WebM's first frame";
  auto at = [&](int x, int y) { return &px[(size_t(y) * 48 + size_t(x)) * 4]; };
  EXPECT_LT(at(0, 0)[3], 8) << "a corner (nothing there) is not transparent";
  const std::uint8_t* lager = at(24, 27);
  EXPECT_GT(lager[3], 180) << "the drink is not covered";
  EXPECT_GT(lager[0], 140) << "the lager is dark: " << int(lager[0]) << " " << int(lager[1]) << " " << int(lager[2]);
  EXPECT_GT(lager[0], lager[2] + 60) << "the lager is not gold";
}

TEST_F(Animate, AWebmKeepsAlphaWhenATimelineMakesThePictureTransparent) {
  // Opaque at the start, transparent from a set action on: the WebM has its alpha plane.
  write_file(in() / "cut.json",
             R"({"draught_timeline": 1, "name": "cut", "preset": "lager", "duration": 1, "actions": [
                 {"at": 0.5, "action": "set", "param": "render.transparent", "value": true}]})");
  const fs::path webm = out() / "cut.webm";
  auto r = animate((in() / "cut.json").string(), {"-o", webm.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const std::vector<std::uint8_t> px = webm_frames(webm);
  const size_t frame = 48 * 48 * 4;
  ASSERT_EQ(px.size(), 4 * frame) << "ffmpeg could not decode the WebM's four frames";
  EXPECT_EQ(px[3], 255) << "the first frame (opaque) is not";
  const std::uint8_t* last = &px[3 * frame];
  EXPECT_LT(last[3], 8) << "the last frame's corner (nothing there) is not transparent";
  const std::uint8_t* lager = &last[(27 * 48 + 24) * 4];
  EXPECT_GT(lager[3], 180) << "the drink is not covered";
  EXPECT_GT(lager[0], lager[2] + 60) << "the lager is not gold";
}

TEST_F(Animate, WritesOpaqueWebm) {
  const fs::path webm = out() / "clip.webm";
  auto r = animate("gentle-tilt", {"--size", "31x17", "--duration", "0.5", "-o", webm.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(read_file(webm).substr(0, 4), "\x1A\x45\xDF\xA3");
  const std::vector<std::uint8_t> px = webm_frames(webm, 1);
  ASSERT_EQ(px.size(), size_t(31 * 17 * 4)) << "odd sizes are kept (VP9 takes them)";
  EXPECT_EQ(px[3], 255) << "an opaque picture's WebM is opaque";
}

TEST_F(Animate, WritesGifThroughFfmpeg) {
  const fs::path gif = out() / "sub" / "clip.gif";
  auto r = animate("gentle-tilt", {"-o", gif.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const std::string b = read_file(gif);
  ASSERT_GT(b.size(), 13u) << "empty GIF";
  EXPECT_EQ(b.substr(0, 6), "GIF89a");
  // 48x48 little-endian in the logical screen descriptor.
  EXPECT_EQ(uint8_t(b[6]) | (uint8_t(b[7]) << 8), 48);
  EXPECT_EQ(uint8_t(b[8]) | (uint8_t(b[9]) << 8), 48);
  EXPECT_EQ(join(list_tree(out())), "sub, sub/clip.gif") << "leftover .part or other files";
}

TEST_F(Animate, MissingFfmpegFromEnvironmentIsAnError) {
  const fs::path mp4 = out() / "clip.mp4";
  auto r = animate("gentle-tilt", {"-o", mp4.string()}, {{"DRAUGHT_FFMPEG", (in() / "no-such-ffmpeg").string()}});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"ffmpeg", mp4.string()});
  EXPECT_FALSE(fs::exists(mp4));
}

TEST_F(Animate, MissingFfmpegOnPathIsAnError) {
  fs::create_directories(in() / "empty-bin");
  const fs::path mp4 = out() / "clip.mp4";
  auto r = animate("gentle-tilt", {"-o", mp4.string()},
                   {{"DRAUGHT_FFMPEG", std::nullopt}, {"PATH", (in() / "empty-bin").string()}});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"ffmpeg", mp4.string()});
  EXPECT_FALSE(fs::exists(mp4));
}

TEST_F(Animate, FailingFfmpegLeavesNothingBehind) {
  // An "ffmpeg" that exits with an error at once: the frames cannot be written, and no
  // .part file (nor a half video) may stay.
  const fs::path fake = in() / "ffmpeg";
  write_file(fake, "#!/bin/sh\necho 'fake ffmpeg: refusing' >&2\nexit 3\n");
  fs::permissions(fake, fs::perms::owner_all);
  const fs::path mp4 = out() / "clip.mp4";
  auto r = animate("gentle-tilt", {"-o", mp4.string()}, {{"DRAUGHT_FFMPEG", fake.string()}});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"ffmpeg"});
  EXPECT_FALSE(fs::exists(mp4));
}

// ---------------------------------------------------------------- progress

TEST_F(Animate, ProgressBarOnStderr) {
  auto r = animate("gentle-tilt", {"--progress", "-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  for (const char* s : {"frames", "fps", "left", "4/4", "[", "#"})
    EXPECT_TRUE(contains(r.err, s)) << "progress bar lacks \"" << s << "\"\n" << r.describe();
  EXPECT_FALSE(contains(r.out, "left")) << "progress bar on stdout\n" << r.describe();
  // The last redraw is the complete bar, ended by a newline.
  const auto last = r.err.rfind('\r');
  ASSERT_NE(last, std::string::npos) << "bar is not redrawn in place\n" << r.describe();
  const std::string final_bar = r.err.substr(last + 1);
  EXPECT_TRUE(contains(final_bar, "4/4")) << final_bar;
  EXPECT_TRUE(contains(final_bar, "[" + std::string(28, '#') + "]")) << "last bar is not full: " << final_bar;
  EXPECT_TRUE(final_bar.ends_with("\n")) << final_bar;
}

TEST_F(Animate, NoProgressBarWhenNotATerminalAndNotAsked) {
  auto r = animate("gentle-tilt", {"-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_FALSE(contains(r.err, "4/4")) << r.describe();
  EXPECT_FALSE(contains(r.err, "left")) << r.describe();
}

// ---------------------------------------------------------------- timelines as files, flags

TEST_F(Animate, TimelineFromJsonFile) {
  const fs::path tl = in() / "mine.json";
  write_file(tl, R"({
  "draught_timeline": 1,
  "name": "mine",
  "preset": "lager",
  "duration": 1,
  "actions": [
    { "at": 0, "action": "tilt", "angle": 30, "toward": 90, "duration": 0.75 },
    { "at": 0.25, "action": "sip", "amount": 0.2, "duration": 0.5, "ease": "linear" },
    { "at": 0, "action": "set", "param": "liquid.srm", "value": 40, "duration": 0.75 }
  ]
})");
  auto r = animate(tl.string(), {"-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  ASSERT_EQ(join(list_tree(out() / "f")), expected_frames(4));
  const auto first = draught::read_png(out() / "f" / "frame_00000.png");
  const auto last = draught::read_png(out() / "f" / "frame_00003.png");
  EXPECT_GT(differing_pixels(first, last), 48 * 48 / 20) << "tilt, sip and colour change left the image as it was";

  // The same scene with no set action: the darker beer (srm 4 -> 40) must show by the end.
  const fs::path plain = in() / "plain.json";
  write_file(plain, R"({ "draught_timeline": 1, "name": "plain", "preset": "lager", "duration": 1,
    "actions": [ { "at": 0, "action": "tilt", "angle": 30, "toward": 90, "duration": 0.75 },
                 { "at": 0.25, "action": "sip", "amount": 0.2, "duration": 0.5, "ease": "linear" } ] })");
  auto r2 = animate(plain.string(), {"-o", frames_dir("g")});
  ASSERT_EQ(r2.exit_code, 0) << r2.describe();
  EXPECT_NE(read_file(out() / "f" / "frame_00003.png"), read_file(out() / "g" / "frame_00003.png"))
      << "set liquid.srm made no difference";
}

TEST_F(Animate, TimelineFileDefaultsToItsOwnFpsAndDuration) {
  const fs::path tl = in() / "short.json";
  write_file(tl, R"({ "draught_timeline": 1, "name": "short", "duration": 0.5, "fps": 6,
    "actions": [ { "at": 0, "action": "rotate", "degrees": 90, "duration": 0.5 } ] })");
  auto r = draught({"render", "--timeline", tl.string(), "--size", "16x16", "--supersample", "1", "-o", frames_dir("f")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "f")), expected_frames(3)) << "0.5 s at 6 fps is 3 frames";
  EXPECT_TRUE(contains(r.out, "6 fps")) << r.describe();
}

TEST_F(Animate, PresetFlagWinsOverTimelineScene) {
  auto lager = animate("gentle-tilt", {"--duration", "0.25", "-o", frames_dir("lager")});
  ASSERT_EQ(lager.exit_code, 0) << lager.describe();
  auto stout = animate("gentle-tilt", {"--duration", "0.25", "--preset", "stout", "-o", frames_dir("stout")});
  ASSERT_EQ(stout.exit_code, 0) << stout.describe();
  ASSERT_EQ(join(list_tree(out() / "lager")), expected_frames(1));
  ASSERT_EQ(join(list_tree(out() / "stout")), expected_frames(1));
  const auto a = draught::read_png(out() / "lager" / "frame_00000.png");
  const auto b = draught::read_png(out() / "stout" / "frame_00000.png");
  EXPECT_GT(differing_pixels(a, b), 48 * 48 / 20) << "--preset stout was ignored: frame 0 is the timeline's lager";
}

TEST_F(Animate, SetFlagAppliesUnderTheTimeline) {
  auto a = animate("gentle-tilt", {"--duration", "0.25", "-o", frames_dir("a")});
  ASSERT_EQ(a.exit_code, 0) << a.describe();
  auto b = animate("gentle-tilt", {"--duration", "0.25", "--set", "liquid.fill=0.3", "-o", frames_dir("b")});
  ASSERT_EQ(b.exit_code, 0) << b.describe();
  EXPECT_NE(read_file(out() / "a" / "frame_00000.png"), read_file(out() / "b" / "frame_00000.png"))
      << "--set liquid.fill=0.3 was ignored with --timeline";
}

// ---------------------------------------------------------------- flags that do not mix

TEST_F(Animate, FpsWithoutTimelineIsAnError) {
  auto r = draught({"render", "--size", "16x16", "--fps", "10", "-o", (out() / "x.png").string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"--fps", "--timeline"});
}

TEST_F(Animate, DurationOrProgressWithoutTimelineIsAnError) {
  for (std::vector<std::string> extra : {std::vector<std::string>{"--duration", "2"}, {"--progress"}}) {
    std::vector<std::string> args = {"render", "--size", "16x16", "-o", (out() / "x.png").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    auto r = draught(args);
    EXPECT_EQ(r.exit_code, 1) << r.describe();
    expect_failure(r, {extra[0], "--timeline"});
  }
}

TEST_F(Animate, DebugWithTimelineIsAnError) {
  auto r = animate("gentle-tilt", {"--debug", "depth", "-o", frames_dir("f")});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"--debug", "--timeline"});
}

TEST_F(Animate, PngOutputWithTimelineIsAnError) {
  const fs::path png = out() / "frames.png";
  auto r = animate("gentle-tilt", {"-o", png.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {png.string(), "folder", ".mp4", ".gif"});
}

TEST_F(Animate, FpsOutOfRangeIsAnError) {
  auto r = animate("gentle-tilt", {"--fps", "0", "-o", frames_dir("f")});
  EXPECT_NE(r.exit_code, 0) << r.describe();
  expect_failure(r, {"--fps"});
}

}  // namespace
}  // namespace draught_cli_test
