// The screen's sources (core/io/video_source): PNG sequences (folders in natural order,
// patterns) and videos through ffmpeg, frame by index; every broken input refused with
// the file's name and what was expected.
#include "core/io/files.hpp"
#include "core/io/image.hpp"
#include "core/io/process.hpp"
#include "core/io/video_source.hpp"
#include "core/text/echo.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace draught::test {
namespace {

namespace fs = std::filesystem;

// Frame k of the test clips: a flat colour of its own with a bar whose place moves, so
// frames are told apart by colour and by place.
Image test_frame(int k, int w = 32, int h = 18) {
  Image img{w, h, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.px(x, y);
      const bool bar = x == (3 * k) % w;
      p[0] = std::uint8_t(bar ? 255 : (37 * k + 20) % 256);
      p[1] = std::uint8_t(bar ? 255 : (91 * k + 60) % 256);
      p[2] = std::uint8_t(bar ? 255 : (17 * k + 200) % 256);
      p[3] = 255;
    }
  return img;
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

// Runs a shell command (ffmpeg making test videos); true when it succeeded.
bool shell(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()) == 0; }

class VideoSourceTest : public TempDirTest {
 protected:
  VideoSourceTest() : TempDirTest("draught-video") {}
  // frame_1.png .. frame_N.png (unpadded: natural order must put frame_2 before frame_10).
  fs::path sequence(int n, const std::string& name = "frames") {
    const fs::path dir = dir_ / name;
    fs::create_directories(dir);
    for (int k = 0; k < n; ++k) write_png(dir / ("frame_" + std::to_string(k + 1) + ".png"), test_frame(k));
    return dir;
  }
  // A lossless video of the test frames (FFV1 in Matroska): decoded, it gives them back
  // byte for byte.
  fs::path lossless_video(int n, const std::string& name = "clip.mkv") {
    const fs::path dir = sequence(n, "src-" + name);
    const fs::path out = dir_ / name;
    EXPECT_TRUE(shell("ffmpeg -nostdin -y -loglevel error -framerate 10 -start_number 1 -i '" +
                      (dir / "frame_%d.png").string() + "' -c:v ffv1 -pix_fmt bgr0 '" + out.string() + "'"));
    return out;
  }
  std::string error_of(const fs::path& p) {
    try {
      open_video_source(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

bool same_pixels(const Image& a, const Image& b) { return a.width == b.width && a.height == b.height && a.rgba == b.rgba; }

TEST_F(VideoSourceTest, AFolderOfPngsPlaysInNaturalOrder) {
  const auto src = open_video_source(sequence(12));
  EXPECT_EQ(src->info().kind, "PNG sequence");
  EXPECT_EQ(src->info().frames, 12);
  EXPECT_EQ(src->info().width, 32);
  EXPECT_EQ(src->info().fps, 0.0);
  for (int k : {0, 1, 9, 10, 11, 3}) {
    const auto f = src->frame(k);
    ASSERT_TRUE(f);
    EXPECT_TRUE(same_pixels(*f, test_frame(k))) << "frame " << k;  // frame_10 is the tenth, not the second
  }
  EXPECT_EQ(src->frame(12), nullptr);
  EXPECT_EQ(src->frame(-1), nullptr);
  // The same frame is the same object while it is kept (the GPU uploads by identity).
  EXPECT_EQ(src->frame(3).get(), src->frame(3).get());
}

TEST_F(VideoSourceTest, APatternNumbersFromItsFirstFrameToTheFirstGap) {
  const fs::path dir = dir_ / "p";
  fs::create_directories(dir);
  for (int n : {1, 2, 3, 5}) write_png(dir / ("shot_" + std::string(n < 10 ? "00" : "0") + std::to_string(n) + ".png"), test_frame(n));
  const auto src = open_video_source((dir / "shot_%03d.png").string());
  EXPECT_EQ(src->info().frames, 3);  // 1, 2, 3; 5 is past the gap
  EXPECT_TRUE(same_pixels(*src->frame(0), test_frame(1)));
  EXPECT_TRUE(same_pixels(*src->frame(2), test_frame(3)));
  EXPECT_TRUE(has(error_of(dir / "shot_%s.png"), {"shot_%s.png", "%d or %0Nd"}));
  EXPECT_TRUE(has(error_of(dir / "other_%03d.png"), {"other_%03d.png", "no frames", "other_000.png"}));
}

TEST_F(VideoSourceTest, ASinglePngIsAStill) {
  write_png(dir_ / "still.png", test_frame(4));
  const auto src = open_video_source(dir_ / "still.png");
  EXPECT_EQ(src->info().frames, 1);
  EXPECT_TRUE(same_pixels(*src->frame(0), test_frame(4)));
}

TEST_F(VideoSourceTest, BrokenSequencesAreRefusedNamingTheFrame) {
  EXPECT_TRUE(has(error_of(dir_ / "nothing-here"), {"nothing-here", "no such file or folder", "expected a video file"}));
  fs::create_directories(dir_ / "empty");
  write_bytes(dir_ / "empty" / "notes.txt", "no frames here");
  EXPECT_TRUE(has(error_of(dir_ / "empty"), {"empty", "no PNG frames"}));

  // A frame of another size.
  const fs::path mixed = sequence(3, "mixed");
  write_png(mixed / "frame_4.png", test_frame(4, 16, 16));
  EXPECT_TRUE(has(error_of(mixed), {"frame_4.png", "16 x 16", "expected 32 x 18"}));
  // Text named .png, a JPEG named .png, a truncated PNG, a PNG whose data is damaged.
  const fs::path bad = sequence(2, "bad");
  write_bytes(bad / "frame_3.png", "hello, I am text");
  EXPECT_TRUE(has(error_of(bad), {"frame_3.png", "not a PNG file"}));
  write_bytes(bad / "frame_3.png", std::string("\xFF\xD8\xFF\xE0 jpeg", 9));
  EXPECT_TRUE(has(error_of(bad), {"frame_3.png", "not a PNG", "JPEG"}));
  const std::string png = encode_png(test_frame(2));
  write_bytes(bad / "frame_3.png", png.substr(0, 20));
  EXPECT_TRUE(has(error_of(bad), {"frame_3.png", "truncated PNG"}));
  // The header passes; the data is cut short: found when the frame is decoded (at once for
  // the first frame, when shown for the others).
  write_bytes(bad / "frame_1.png", png.substr(0, png.size() / 2));
  fs::remove(bad / "frame_3.png");
  EXPECT_TRUE(has(error_of(bad), {"frame_1.png", "undecodable PNG"}));
  write_bytes(bad / "frame_1.png", png);
  write_bytes(bad / "frame_2.png", png.substr(0, png.size() / 2));
  const auto src = open_video_source(bad);
  try {
    src->frame(1);
    ADD_FAILURE() << "a damaged frame was decoded";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.what(), {"frame_2.png", "undecodable PNG"}));
  }
}

TEST_F(VideoSourceTest, HugeFramesAreRefusedFromTheHeader) {
  // A PNG header that claims 5000 x 3000 pixels: refused before any pixel is decoded.
  std::string png = encode_png(test_frame(0));
  auto put32 = [&](size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) png[at + size_t(i)] = char((v >> (24 - 8 * i)) & 0xFF);
  };
  put32(16, 5000);
  put32(20, 3000);
  write_bytes(dir_ / "huge.png", png);
  EXPECT_TRUE(has(error_of(dir_ / "huge.png"), {"huge.png", "5000 x 3000", "larger than a screen shows", "4096"}));
  put32(16, 0);
  write_bytes(dir_ / "empty.png", png);
  EXPECT_TRUE(has(error_of(dir_ / "empty.png"), {"empty.png", "no pixels"}));
}

// A chunk that claims a gigabyte the file does not hold is refused from the chunk list,
// before the decoder allocates what it claims (fuzz_video_source's out-of-memory finding).
TEST_F(VideoSourceTest, AChunkClaimingMoreThanTheFileIsRefusedNotAllocated) {
  const std::string png = encode_png(test_frame(0));
  const size_t iend = png.size() - 12;
  std::string bad = png.substr(0, iend) + std::string("\x3F\xFF\xFF\xF0IDAT", 8) + std::string(40, 'x') + png.substr(iend);
  try {
    decode_png_frame(bad, "claims.png");
    ADD_FAILURE() << "a PNG whose chunk runs past the file was decoded";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.what(), {"claims.png", "undecodable PNG", "past the end of the file"})) << e.what();
  }
}

TEST_F(VideoSourceTest, AVideoIsDecodedFrameByIndex) {
  if (find_executable("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  const auto src = open_video_source(lossless_video(30));
  EXPECT_EQ(src->info().kind, "video");
  EXPECT_EQ(src->info().codec, "ffv1");
  EXPECT_EQ(src->info().width, 32);
  EXPECT_EQ(src->info().height, 18);
  EXPECT_DOUBLE_EQ(src->info().fps, 10.0);
  // In order, a step ahead, far ahead (ffmpeg restarted at the frame), back, and again.
  for (int k : {0, 1, 2, 5, 27, 3, 3, 29, 0}) {
    const auto f = src->frame(k);
    ASSERT_TRUE(f) << "frame " << k;
    EXPECT_TRUE(same_pixels(*f, test_frame(k))) << "frame " << k;
  }
  EXPECT_EQ(src->frame(30), nullptr);
  EXPECT_EQ(src->info().frames, 30);  // known once the end was read
  // A source opened afresh and asked past its end first learns its length all the same.
  const auto again = open_video_source(dir_ / "clip.mkv");
  EXPECT_EQ(again->frame(45), nullptr);
  EXPECT_EQ(again->info().frames, 30);
  EXPECT_TRUE(same_pixels(*again->frame(29), test_frame(29)));
}

TEST_F(VideoSourceTest, BrokenVideosAreRefusedSayingWhatIsWrong) {
  if (find_executable("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  // Missing; text; an audio file; a video cut in half; frames too large.
  EXPECT_TRUE(has(error_of(dir_ / "missing.mp4"), {"missing.mp4", "no such file"}));
  write_bytes(dir_ / "notes.mp4", "this is not a video at all\n");
  EXPECT_TRUE(has(error_of(dir_ / "notes.mp4"), {"notes.mp4", "not a video"}));
  ASSERT_TRUE(shell("ffmpeg -nostdin -y -loglevel error -f lavfi -i sine=duration=0.5 '" + (dir_ / "tone.wav").string() + "'"));
  EXPECT_TRUE(has(error_of(dir_ / "tone.wav"), {"tone.wav", "not a video", "no video stream"}));
  ASSERT_TRUE(shell("ffmpeg -nostdin -y -loglevel error -f lavfi -i testsrc2=size=64x36:rate=10:duration=2 -pix_fmt "
                    "yuv420p '" + (dir_ / "whole.mp4").string() + "'"));
  const std::string whole = read_whole_file(dir_ / "whole.mp4", 1 << 24, "a video");
  // An MP4's index comes last (no faststart): without it the file is no video at all.
  write_bytes(dir_ / "half.mp4", whole.substr(0, whole.size() / 2));
  EXPECT_TRUE(has(error_of(dir_ / "half.mp4"), {"half.mp4", "not a video"}));
  // Its index first and whole, its frames damaged: ffprobe finds a video, no frame decodes.
  ASSERT_TRUE(shell("ffmpeg -nostdin -y -loglevel error -f lavfi -i testsrc2=size=64x36:rate=10:duration=2 -pix_fmt "
                    "yuv420p -movflags +faststart '" + (dir_ / "fast.mp4").string() + "'"));
  std::string damaged = read_whole_file(dir_ / "fast.mp4", 1 << 24, "a video");
  const size_t mdat = damaged.find("mdat");
  ASSERT_NE(mdat, std::string::npos);
  const size_t data = damaged.size() - mdat;
  for (size_t i = mdat + 8 + data / 10; i + data / 10 < damaged.size(); ++i) damaged[i] = char(0x5A);
  write_bytes(dir_ / "damaged.mp4", damaged);
  const std::string msg = error_of(dir_ / "damaged.mp4");
  EXPECT_TRUE(has(msg, {"damaged.mp4"})) << msg;
  EXPECT_TRUE(has(msg, {"undecodable video", "frame 0", "ffmpeg:"}));
  ASSERT_TRUE(shell("ffmpeg -nostdin -y -loglevel error -f lavfi -i color=c=red:size=4200x64:rate=5:duration=0.2 -c:v "
                    "ffv1 '" + (dir_ / "wide.mkv").string() + "'"));
  EXPECT_TRUE(has(error_of(dir_ / "wide.mkv"), {"wide.mkv", "4200 x 64", "larger than a screen shows"}));
}

TEST_F(VideoSourceTest, WithoutFfmpegAVideoSaysWhatIsMissing) {
  // DRAUGHT_FFMPEG pinned to something that is no program: the message says so.
  write_bytes(dir_ / "clip.mp4", "whatever");
  ::setenv("DRAUGHT_FFMPEG", (dir_ / "no-ffmpeg").c_str(), 1);
  const std::string msg = error_of(dir_ / "clip.mp4");
  ::unsetenv("DRAUGHT_FFMPEG");
  EXPECT_TRUE(has(msg, {"clip.mp4", "DRAUGHT_FFMPEG", "not an executable ffmpeg"}));
}

TEST(VideoProbe, ReadsTheStreamAndRefusesWhatIsNoVideo) {
  const VideoInfo v = parse_video_probe(
      "codec_name=h264\ncodec_type=video\nwidth=1280\nheight=720\nr_frame_rate=30000/1001\navg_frame_rate=0/0\n"
      "nb_frames=N/A\n",
      "a.mp4");
  EXPECT_EQ(v.width, 1280);
  EXPECT_EQ(v.height, 720);
  EXPECT_NEAR(v.fps, 29.97, 0.01);  // the average is unknown: the base rate
  EXPECT_EQ(v.frames, -1);
  // A portrait phone video: stored sideways, turned by ffmpeg.
  const VideoInfo p = parse_video_probe(
      "codec_type=video\nwidth=1920\nheight=1080\navg_frame_rate=30/1\nside_data_type=Display Matrix\nrotation=-90\n", "p.mov");
  EXPECT_EQ(p.width, 1080);
  EXPECT_EQ(p.height, 1920);
  auto error = [](const std::string& report) {
    try {
      parse_video_probe(report, "x.mp4");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_TRUE(has(error(""), {"x.mp4", "no video stream"}));
  EXPECT_TRUE(has(error("codec_type=audio\n"), {"x.mp4", "no video stream"}));
  EXPECT_TRUE(has(error("codec_type=video\nwidth=abc\nheight=10\navg_frame_rate=25/1\n"), {"x.mp4", "no frame size"}));
  EXPECT_TRUE(has(error("codec_type=video\nwidth=100\nheight=10\navg_frame_rate=0/0\nr_frame_rate=1/0\n"), {"x.mp4", "no frame rate"}));
  EXPECT_TRUE(has(error("codec_type=video\nwidth=10000\nheight=10\navg_frame_rate=25/1\n"), {"x.mp4", "larger"}));
  EXPECT_TRUE(has(error("codec_type=video\nwidth=100\nheight=10\navg_frame_rate=25/1\nnb_frames=0\n"), {"x.mp4", "no frames"}));
  // A file's metadata echoed in a message is made valid UTF-8 (found by fuzz_video_source).
  const std::string broken = error(std::string("codec_type=video\nwidth=4\x89P\x14\0\0t\nheight=10\n", 38));
  EXPECT_TRUE(has(broken, {"x.mp4", "no frame size"}));
  EXPECT_EQ(make_valid_utf8(broken), broken);
}

}  // namespace
}  // namespace draught::test
