// Moving pictures for the screen (core/environment/screen): a video file decoded by
// Debian's ffmpeg binary (raw RGBA frames on a pipe: no FFmpeg library is linked, the same
// binary the CLI's MP4 export runs), or a PNG sequence (a folder of PNGs, or a pattern such
// as clip/frame_%04d.png). Frames are asked for by index, never by the wall clock, so what
// a screen shows at time t is a function of t (timelines render deterministically).
//
// Strict: a source is checked when it is opened (a video probed and its first frame
// decoded; every frame of a sequence a PNG of the same size), and every error names the
// file and what was expected: missing, not a video, undecodable, no frames, too large.
#pragma once

#include "core/io/image.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace draught {

// The largest frame a source may have: 4096 pixels a side and 4096 x 2160 (DCI 4K) in all,
// 35 MB of RGBA a frame.
inline constexpr int kMaxVideoSide = 4096;
inline constexpr long long kMaxVideoPixels = 4096LL * 2160;
// The most frames a PNG sequence may have (an hour at 25 fps is 90,000).
inline constexpr int kMaxSequenceFrames = 100000;
// The largest PNG read as one frame (an uncompressed 4096 x 2160 RGBA is 35 MB).
inline constexpr std::uintmax_t kMaxFrameFileBytes = 64u << 20;

struct VideoInfo {
  std::string kind;   // "video" or "PNG sequence"
  std::string codec;  // a video's codec (h264, vp9, ...); "png" for a sequence
  int width = 0, height = 0;
  double fps = 0;   // the video's own frame rate; 0 for a PNG sequence, which has none
  int frames = -1;  // the number of frames; -1 while unknown (a video not yet read to its end)
};

class VideoSource {
 public:
  virtual ~VideoSource() = default;
  const VideoInfo& info() const { return info_; }
  const std::string& name() const { return name_; }
  // Frame `index` (from 0), the same object while it is kept (frames are compared by
  // identity: the GPU uploads a frame only when it is another one). nullptr past the last
  // frame; info().frames then says how many there are. Throws InputError naming the file
  // for a frame that cannot be decoded.
  virtual std::shared_ptr<const Image> frame(int index) = 0;

 protected:
  VideoInfo info_;
  std::string name_;  // the file or pattern, as messages name it
};

// Opens `source`: a folder (its PNG files, in natural order: frame_2 before frame_10), a
// pattern with one %d or %0Nd (numbered from the first of 0 to 4 that exists, up to the
// first missing number), a single .png file (a still), or a video file (ffmpeg). Throws
// InputError naming the file and what was expected.
std::unique_ptr<VideoSource> open_video_source(const std::filesystem::path& source);

// ---- the parts that read untrusted bytes (fuzzed: fuzz/fuzz_video_source.cpp) ----

// What ffprobe reports of a file's first video stream, as key=value lines (ffprobe -of
// default=noprint_wrappers=1): the size, frame rate, frame count and codec. Throws
// InputError naming `file` when there is no video stream or a value is out of range.
VideoInfo parse_video_probe(std::string_view report, const std::string& file);

// The size a PNG's header gives (its signature and IHDR chunk), checked against the
// limits; throws InputError naming `file` for anything that is no PNG or too large.
void png_header_size(std::string_view bytes, const std::string& file, int& width, int& height);

// A whole PNG decoded to RGBA (16-bit and palette PNGs too), strictly: its header first,
// then the data; throws InputError naming `file` and what is wrong.
Image decode_png_frame(std::string_view bytes, const std::string& file);

}  // namespace draught
