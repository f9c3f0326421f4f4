// MP4, WebM and GIF output through ffmpeg. Frames stream into ffmpeg on a pipe; memory
// stays flat whatever the length:
//   MP4: one ffmpeg, raw RGBA -> H.264 in a temporary -> renamed onto the output.
//   WebM: the same, VP9; a transparent picture's with its alpha (yuva420p: the frames
//        in straight alpha, as the browsers composite it), the cutout in motion.
//   (An MP4 drops alpha: a transparent picture's premultiplied frames over black; a GIF
//   keeps one bit of it, ffmpeg's palette making pixels under half coverage clear.)
//   GIF: one palette for the whole clip needs every frame before the first can be
//        written, and ffmpeg's one-pass palettegen/paletteuse holds them all in memory.
//        So: raw RGBA -> a lossless FFV1 temporary; then palettegen over that file ->
//        a palette temporary; then paletteuse over the file and the palette -> GIF.
// ffmpeg dies with the CLI (PR_SET_PDEATHSIG; the signal handler kills it too), runs in
// its own process group (Ctrl+C reaches only draught, which cleans up), and its
// temporaries are removed on every path out.
#pragma once

#include "core/io/image.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace draught::cli {

class Encoder {
 public:
  // `dest`: the file to write (links resolved); `shown`: the -o the user gave, for messages;
  // `transparent`: the frames are a transparent picture's (a WebM keeps their alpha).
  Encoder(const std::filesystem::path& dest, const std::string& shown, int width, int height, double fps,
          bool transparent = false);
  ~Encoder();
  Encoder(const Encoder&) = delete;
  Encoder& operator=(const Encoder&) = delete;

  void write(const Image&);  // the renderer's samples (premultiplied where transparent)
  // Ends the stream, runs the remaining passes and renames the result onto `dest`.
  void finish();

 private:
  void write_bytes(const std::vector<std::uint8_t>&);  // into ffmpeg's pipe, whole
  std::filesystem::path temporary();
  void run_to_end(std::vector<std::string> args);  // a pass that reads files, not the pipe
  void wait_for_child(const char* what);
  void remove_temporaries();

  std::filesystem::path dest_;
  std::string shown_, ffmpeg_;
  bool gif_ = false;
  bool alpha_ = false;  // a WebM of a transparent picture: its frames in straight alpha
  std::filesystem::path part_, frames_, palette_;  // output, GIF's lossless frames and palette
  std::vector<std::filesystem::path> temporaries_;
  pid_t pid_ = -1;
  int fd_ = -1;
};

}  // namespace draught::cli
