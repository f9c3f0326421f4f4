// libFuzzer target: what the screen's sources read from untrusted files (core/io/
// video_source): a PNG frame (its header checked, then decoded by stb_image) and the
// report ffprobe writes about a video (key=value lines whose values come from the file's
// own metadata). Each must accept the bytes or throw InputError naming the file.
#include "fuzz_common.hpp"

#include "core/io/video_source.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace draught;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const Image img = decode_png_frame(bytes, fuzz::kFile);
    if (img.width < 1 || img.height < 1 || img.width > kMaxVideoSide || img.height > kMaxVideoSide ||
        img.rgba.size() != size_t(img.width) * size_t(img.height) * 4)
      fuzz::finding("a decoded frame breaks the limits", "");
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  try {
    const VideoInfo info = parse_video_probe(bytes, fuzz::kFile);
    if (info.width < 1 || info.height < 1 || info.width > kMaxVideoSide || info.height > kMaxVideoSide ||
        !(info.fps > 0 && info.fps <= 1000) || info.codec.size() > 40)
      fuzz::finding("a probe report passed with values out of range", "");
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  return 0;
}
