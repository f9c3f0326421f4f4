#include "core/io/video_source.hpp"

#include "core/io/files.hpp"
#include "core/io/image.hpp"
#include "core/io/process.hpp"
#include "core/text/echo.hpp"
#include "core/io/bytes.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <stdexcept>

#ifndef __EMSCRIPTEN__
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace draught {

namespace fs = std::filesystem;

namespace {

std::string size_text(long long w, long long h) { return std::to_string(w) + " x " + std::to_string(h); }

void check_frame_size(const std::string& file, long long w, long long h) {
  if (w < 1 || h < 1) throw InputError(file + ": frames of " + size_text(w, h) + " pixels: a frame has no pixels");
  if (w > kMaxVideoSide || h > kMaxVideoSide || w * h > kMaxVideoPixels)
    throw InputError(file + ": frames of " + size_text(w, h) + " pixels, larger than a screen shows (at most " +
                     std::to_string(kMaxVideoSide) + " a side and 4096 x 2160 in all; scale it down: 1920 x 1080 is "
                     "plenty)");
}

// The frames a source keeps decoded: the one shown, and a few around it (a timeline that
// holds or steps back a frame, a benchmark that alternates).
constexpr size_t kKeptFrames = 4;

struct KeptFrames {
  std::deque<std::pair<int, std::shared_ptr<const Image>>> frames;
  std::shared_ptr<const Image> find(int index) const {
    for (const auto& [i, img] : frames)
      if (i == index) return img;
    return nullptr;
  }
  void keep(int index, std::shared_ptr<const Image> img) {
    frames.emplace_front(index, std::move(img));
    if (frames.size() > kKeptFrames) frames.pop_back();
  }
};

// ---- PNG sequences ----

// Natural order: runs of digits compare as numbers, so frame_2 comes before frame_10.
bool natural_less(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool da = std::isdigit(static_cast<unsigned char>(a[i])), db = std::isdigit(static_cast<unsigned char>(b[j]));
    if (da && db) {
      size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie]))) ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je]))) ++je;
      // Leading zeros aside, the longer run is the larger number.
      size_t ia = i, jb = j;
      while (ia + 1 < ie && a[ia] == '0') ++ia;
      while (jb + 1 < je && b[jb] == '0') ++jb;
      if (ie - ia != je - jb) return ie - ia < je - jb;
      const int c = a.compare(ia, ie - ia, b, jb, je - jb);
      if (c != 0) return c < 0;
      i = ie, j = je;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

bool is_png_name(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".png";
}

// The first bytes of a frame file (its PNG header), refusing what is no regular file.
std::string read_head(const fs::path& p, size_t n) {
  std::error_code ec;
  const auto st = fs::status(p, ec);
  if (!fs::is_regular_file(st))
    throw InputError(p.string() + ": " + (fs::exists(st) ? "is not a regular file" : "no such file") +
                     ", expected a PNG frame");
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(p.string() + ": cannot open file: " + std::strerror(errno));
  std::string head(n, '\0');
  in.read(head.data(), std::streamsize(n));
  head.resize(size_t(in.gcount()));
  return head;
}

class PngSequence : public VideoSource {
 public:
  PngSequence(std::string name, std::vector<fs::path> files) : files_(std::move(files)) {
    name_ = std::move(name);
    if (files_.empty()) throw std::logic_error("PngSequence: no frames");
    if (files_.size() > size_t(kMaxSequenceFrames))
      throw InputError(name_ + ": " + std::to_string(files_.size()) + " frames, more than the " +
                       std::to_string(kMaxSequenceFrames) + " a PNG sequence may have");
    info_.kind = "PNG sequence";
    info_.codec = "png";
    info_.frames = int(files_.size());
    // Every frame's header now (the same size for all), the first one decoded whole.
    for (size_t i = 0; i < files_.size(); ++i) {
      int w = 0, h = 0;
      png_header_size(read_head(files_[i], 33), files_[i].string(), w, h);
      if (i == 0) {
        info_.width = w, info_.height = h;
      } else if (w != info_.width || h != info_.height) {
        throw InputError(files_[i].string() + ": " + size_text(w, h) + " pixels, expected " +
                         size_text(info_.width, info_.height) + " like the sequence's first frame (" +
                         files_[0].filename().string() + ")");
      }
    }
    frame(0);
  }

  std::shared_ptr<const Image> frame(int index) override {
    if (index < 0 || index >= int(files_.size())) return nullptr;
    if (auto kept = kept_.find(index)) return kept;
    const fs::path& p = files_[size_t(index)];
    Image img = decode_png_frame(read_whole_file(p, kMaxFrameFileBytes, "a PNG frame"), p.string());
    if (img.width != info_.width || img.height != info_.height)
      throw InputError(p.string() + ": " + size_text(img.width, img.height) + " pixels, expected " +
                       size_text(info_.width, info_.height) + " like the sequence's first frame");
    auto shared = std::make_shared<const Image>(std::move(img));
    kept_.keep(index, shared);
    return shared;
  }

 private:
  std::vector<fs::path> files_;
  KeptFrames kept_;
};

const char* kSourceExpected =
    "expected a video file, a folder of PNG frames, a pattern such as clip/frame_%04d.png or a PNG file";

std::unique_ptr<VideoSource> open_folder(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!is_png_name(it->path())) continue;
    names.push_back(it->path().filename().string());
    if (names.size() > size_t(kMaxSequenceFrames))
      throw InputError(dir.string() + ": more than the " + std::to_string(kMaxSequenceFrames) +
                       " PNG frames a sequence may have");
  }
  if (ec) throw InputError(dir.string() + ": cannot list the folder: " + ec.message());
  if (names.empty())
    throw InputError(dir.string() + ": no PNG frames in the folder (expected files such as frame_0001.png)");
  std::sort(names.begin(), names.end(), natural_less);
  std::vector<fs::path> files;
  for (const auto& n : names) files.push_back(dir / n);
  return std::make_unique<PngSequence>(dir.string(), std::move(files));
}

// clip/frame_%04d.png: one %d or %0Nd (N up to 9) and no other %, numbered from the first
// of 0 to 4 that exists (as ffmpeg's image2 reads them) up to the first missing number.
std::unique_ptr<VideoSource> open_pattern(const std::string& pattern) {
  const size_t at = pattern.find('%');
  size_t end = at + 1;
  int width = 0;
  if (end < pattern.size() && pattern[end] == '0') {
    ++end;
    if (end < pattern.size() && pattern[end] >= '1' && pattern[end] <= '9') width = pattern[end++] - '0';
  }
  if (end >= pattern.size() || pattern[end] != 'd' || pattern.find('%', end) != std::string::npos)
    throw InputError(shorten(pattern, kEchoPathBytes) +
                     ": expected a pattern with one %d or %0Nd (N from 1 to 9) for the frame number, such as "
                     "clip/frame_%04d.png");
  const std::string before = pattern.substr(0, at), after = pattern.substr(end + 1);
  auto name = [&](long n) {
    std::string digits = std::to_string(n);
    if (int(digits.size()) < width) digits.insert(0, size_t(width) - digits.size(), '0');
    return fs::path(before + digits + after);
  };
  auto exists = [](const fs::path& p) {
    std::error_code ec;
    return fs::exists(fs::symlink_status(p, ec));
  };
  long first = 0;
  while (first <= 4 && !exists(name(first))) ++first;
  if (first > 4)
    throw InputError(shorten(pattern, kEchoPathBytes) + ": no frames: none of " + name(0).string() + " to " +
                     name(4).filename().string() + " exists (a pattern's first frame is numbered 0 to 4)");
  std::vector<fs::path> files;
  for (long n = first; exists(name(n)); ++n) {
    files.push_back(name(n));
    if (files.size() > size_t(kMaxSequenceFrames))
      throw InputError(shorten(pattern, kEchoPathBytes) + ": more than the " + std::to_string(kMaxSequenceFrames) +
                       " frames a PNG sequence may have");
  }
  return std::make_unique<PngSequence>(pattern, std::move(files));
}

// ---- videos, through ffmpeg ----

#ifndef __EMSCRIPTEN__

// The first two different things a tool wrote to its error stream (a temporary file),
// without its "[h264 @ 0x55d1...]" prefixes (addresses that differ every run).
std::string first_lines(std::FILE* f) {
  if (!f) return "";
  std::rewind(f);
  char buf[4096];
  const size_t n = std::fread(buf, 1, sizeof buf, f);
  const std::string text(buf, n);
  std::vector<std::string> lines;
  for (size_t at = 0; at < text.size() && lines.size() < 2;) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(at, end - at);
    at = end + 1;
    while (!line.empty() && line.front() == '[') {
      const size_t close = line.find("] ");
      if (close == std::string::npos || line.find(" @ 0x") > close) break;
      line.erase(0, close + 2);
    }
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.')) line.pop_back();
    if (!line.empty() && std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
  }
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "; ") + l;
  return shorten(make_valid_utf8(out), 300);
}

// Runs a tool to its end; stdout collected (at most `max_out` bytes), stderr into `err`.
// Returns the wait status.
int run_collect(const std::vector<std::string>& args, std::string& out, std::FILE* err, size_t max_out) {
  int fds[2];
  make_pipe(fds);
  pid_t pid;
  try {
    pid = spawn_process(args, -1, fds[1], err ? fileno(err) : -1);
  } catch (...) {
    close(fds[0]);
    close(fds[1]);
    throw;
  }
  close(fds[1]);
  char buf[4096];
  for (;;) {
    const size_t n = read_fully(fds[0], buf, sizeof buf);
    if (out.size() < max_out) out.append(buf, std::min(n, max_out - out.size()));
    if (n < sizeof buf) break;
  }
  close(fds[0]);
  return wait_process(pid);
}

struct TempFile {
  std::FILE* f = std::tmpfile();
  ~TempFile() {
    if (f) std::fclose(f);
  }
};

bool exited_ok(int status) { return WIFEXITED(status) && WEXITSTATUS(status) == 0; }

class FfmpegVideo : public VideoSource {
 public:
  FfmpegVideo(const fs::path& file, std::string ffmpeg, VideoInfo info) : file_(file), ffmpeg_(std::move(ffmpeg)) {
    name_ = file.string();
    info_ = std::move(info);
    bytes_ = size_t(info_.width) * size_t(info_.height) * 4;
    if (!frame(0)) throw InputError(name_ + ": no frames: ffmpeg decoded none from its video stream");
  }
  ~FfmpegVideo() override { stop(); }

  std::shared_ptr<const Image> frame(int index) override {
    if (index < 0) return nullptr;
    if (auto kept = kept_.find(index)) return kept;
    if (info_.frames >= 0 && index >= info_.frames) return nullptr;
    // Frames just ahead are read through; anything else starts ffmpeg again at the frame
    // (its select filter drops the frames before it without sending them here).
    constexpr int kReadAhead = 48;
    if (pid_ < 0 || index < next_ || index - next_ > kReadAhead) start(index);
    while (next_ <= index) {
      auto img = std::make_shared<Image>();
      if (!read_next(*img)) {
        end_of_stream();
        return nullptr;
      }
      if (next_ == index) kept_.keep(next_, img);
      ++next_;
    }
    return kept_.find(index);
  }

 private:
  void start(int first) {
    stop();
    std::vector<std::string> args = {ffmpeg_, "-nostdin", "-hide_banner", "-loglevel", "error", "-i", file_.string(),
                                      "-map", "0:v:0", "-an", "-sn", "-dn",
                                      // Every decoded frame once, in order: frame n is the nth.
                                      "-vsync", "passthrough"};
    if (first > 0) args.insert(args.end(), {"-vf", "select=gte(n\\," + std::to_string(first) + ")"});
    // The same colours on every machine (no CPU-specific rounding), at the probed size.
    args.insert(args.end(), {"-sws_flags", "bicubic+accurate_rnd+full_chroma_int+bitexact", "-s",
                             std::to_string(info_.width) + "x" + std::to_string(info_.height), "-pix_fmt", "rgba",
                             "-f", "rawvideo", "-"});
    err_ = std::tmpfile();
    int fds[2];
    make_pipe(fds);
    try {
      pid_ = spawn_process(args, -1, fds[1], err_ ? fileno(err_) : -1);
    } catch (const std::exception& e) {
      close(fds[0]);
      close(fds[1]);
      throw InputError(name_ + ": " + e.what());
    }
    close(fds[1]);
    out_ = fds[0];
    first_ = next_ = first;
  }

  void stop() {
    if (out_ >= 0) close(out_);
    out_ = -1;
    if (pid_ > 0) kill_process(pid_);
    pid_ = -1;
    if (err_) std::fclose(err_);
    err_ = nullptr;
  }

  bool read_next(Image& img) {
    img.width = info_.width;
    img.height = info_.height;
    img.rgba.resize(bytes_);
    size_t got = 0;
    try {
      got = read_fully(out_, img.rgba.data(), bytes_);
    } catch (const std::exception& e) {
      failed("reading frame " + std::to_string(next_) + ": " + e.what());
    }
    if (got == bytes_) return true;
    if (got > 0) failed("frame " + std::to_string(next_) + " came incomplete");
    return false;
  }

  // The stream ended before next_: ffmpeg's status says whether it ended well.
  void end_of_stream() {
    close(out_);
    out_ = -1;
    const int status = wait_process(pid_);
    pid_ = -1;
    if (!exited_ok(status)) failed("ffmpeg could not decode frame " + std::to_string(next_));
    if (err_) std::fclose(err_);
    err_ = nullptr;
    if (next_ > first_ || first_ == 0) {
      info_.frames = next_;
    } else {
      // Started past the end of a video of unknown length: count its frames from the start.
      start(0);
      Image scratch;
      while (read_next(scratch)) ++next_;
      end_of_stream();
    }
    if (info_.frames == 0) throw InputError(name_ + ": no frames: ffmpeg decoded none from its video stream");
  }

  [[noreturn]] void failed(const std::string& what) {
    const std::string said = first_lines(err_);
    stop();
    throw InputError(name_ + ": an undecodable video: " + what + (said.empty() ? "" : " (ffmpeg: " + said + ")"));
  }

  fs::path file_;
  std::string ffmpeg_;
  size_t bytes_ = 0;
  pid_t pid_ = -1;
  int out_ = -1;
  std::FILE* err_ = nullptr;  // ffmpeg's messages (a file: a pipe it filled could block it)
  int first_ = 0, next_ = 0;  // where this run of ffmpeg started, and the frame it sends next
  KeptFrames kept_;
};

std::string find_ffprobe(const std::string& ffmpeg) {
  const fs::path beside = fs::path(ffmpeg).parent_path() / "ffprobe";
  if (access(beside.c_str(), X_OK) == 0) return beside.string();
  return find_executable("ffprobe");
}

std::unique_ptr<VideoSource> open_video(const fs::path& file) {
  const std::string name = file.string();
  const std::string ffmpeg = find_ffmpeg(name);
  if (ffmpeg.empty())
    throw InputError(name + ": ffmpeg was not found on PATH, and it decodes videos (Debian: apt install ffmpeg); "
                            "a PNG sequence needs none");
  const std::string ffprobe = find_ffprobe(ffmpeg);
  if (ffprobe.empty())
    throw InputError(name + ": ffprobe (which comes with ffmpeg) was not found beside " + ffmpeg + " or on PATH");
  TempFile err;
  std::string report;
  const int status = run_collect({ffprobe, "-v", "error", "-select_streams", "v:0", "-show_entries",
                                  "stream=codec_type,codec_name,width,height,avg_frame_rate,r_frame_rate,nb_frames:"
                                  "stream_side_data=rotation",
                                  "-of", "default=noprint_wrappers=1", file.string()},
                                 report, err.f, 64 * 1024);
  if (!exited_ok(status)) {
    const std::string said = first_lines(err.f);
    throw InputError(name + ": not a video (" + std::string(kSourceExpected) + ")" +
                     (said.empty() ? "" : "; ffprobe: " + said));
  }
  return std::make_unique<FfmpegVideo>(file, ffmpeg, parse_video_probe(report, name));
}

#else

std::unique_ptr<VideoSource> open_video(const fs::path& file) {
  throw InputError(file.string() +
                   ": the web page decodes no video files itself: choose the video on the page, which plays it in a "
                   "<video> element");
}

#endif

// What a file that is no PNG is, by its first bytes (for the message).
std::string other_kind(std::string_view b) {
  if (b.substr(0, 3) == "\xFF\xD8\xFF") return " (it is a JPEG)";
  if (b.substr(0, 4) == "GIF8") return " (it is a GIF)";
  if (b.size() >= 8 && b.substr(4, 4) == "ftyp") return " (it is an MP4 or MOV video: give it as a video file)";
  if (b.substr(0, 4) == "\x1A\x45\xDF\xA3") return " (it is a Matroska or WebM video: give it as a video file)";
  return "";
}

}  // namespace

void png_header_size(std::string_view b, const std::string& file, int& width, int& height) {
  static constexpr std::string_view kSignature{"\x89PNG\r\n\x1a\n", 8};
  if (b.substr(0, kSignature.size()) != kSignature)
    throw InputError(file + ": not a PNG file, expected a PNG frame" + other_kind(b));
  if (b.size() < 33) throw InputError(file + ": a truncated PNG: the file ends inside its header");
  if (be32(b, 8) != 13 || b.substr(12, 4) != "IHDR")
    throw InputError(file + ": a damaged PNG: its first chunk is not a 13-byte IHDR");
  const long long w = be32(b, 16), h = be32(b, 20);
  check_frame_size(file, w, h);
  width = int(w);
  height = int(h);
}

Image decode_png_frame(std::string_view bytes, const std::string& file) {
  int w = 0, h = 0;
  png_header_size(bytes, file, w, h);
  if (bytes.size() > kMaxFrameFileBytes)
    throw InputError(file + ": larger than the limit of " + std::to_string(kMaxFrameFileBytes >> 20) +
                     " MiB for a PNG frame");
  // The strict decoder checks every chunk (its length within the file, its checksum)
  // before stb sees the bytes: stb would otherwise allocate what a chunk claims (a
  // 300-byte file claiming a gigabyte of image data asked for 2 GiB; fuzz_video_source).
  try {
    return decode_png(bytes, file, kMaxVideoSide);
  } catch (const InputError& e) {
    std::string why = e.what();
    for (const std::string& prefix : {file + ": ", std::string("a damaged PNG: ")})
      if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
    throw InputError(file + ": an undecodable PNG (" + why + ")");
  }
}

VideoInfo parse_video_probe(std::string_view report, const std::string& file) {
  std::map<std::string, std::string, std::less<>> values;
  for (size_t at = 0; at < report.size();) {
    size_t end = report.find('\n', at);
    if (end == std::string_view::npos) end = report.size();
    std::string_view line = report.substr(at, end - at);
    at = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq > 64) continue;  // not a key=value line
    // (Values are echoed in messages: made valid UTF-8, whatever the file's metadata held.)
    values.emplace(make_valid_utf8(line.substr(0, eq)), make_valid_utf8(line.substr(eq + 1, 200)));
  }
  auto value = [&](const char* key) -> std::string {
    const auto it = values.find(key);
    return it == values.end() ? std::string() : it->second;
  };
  if (value("codec_type") != "video")
    throw InputError(file + ": not a video: it has no video stream (" + std::string(kSourceExpected) + ")");
  auto integer = [&](const char* key, long long& out) {
    const std::string v = value(key);
    if (v.empty() || v.size() > 12 || v.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::stoll(v);
    return true;
  };
  long long w = 0, h = 0;
  if (!integer("width", w) || !integer("height", h))
    throw InputError(file + ": an undecodable video: its video stream has no frame size (width " +
                     quote_input(value("width")) + ", height " + quote_input(value("height")) + ")");
  // A phone's portrait video is stored sideways with a rotation that ffmpeg applies.
  const std::string rotation = value("rotation");
  if (rotation == "90" || rotation == "-90" || rotation == "270" || rotation == "-270") std::swap(w, h);
  check_frame_size(file, w, h);
  VideoInfo info;
  info.kind = "video";
  info.codec = shorten(make_valid_utf8(value("codec_name")), 32);
  info.width = int(w);
  info.height = int(h);
  // The average rate when it is known (variable-rate streams), else the stream's base rate.
  auto rate = [&](const char* key) {
    const std::string v = value(key);
    const size_t slash = v.find('/');
    if (slash == std::string::npos || slash == 0 || slash > 12 || v.size() - slash - 1 > 12 || v.size() <= slash + 1)
      return 0.0;
    const std::string num = v.substr(0, slash), den = v.substr(slash + 1);
    if (num.find_first_not_of("0123456789") != std::string::npos || den.find_first_not_of("0123456789") != std::string::npos)
      return 0.0;
    const double d = std::stod(den), r = d > 0 ? std::stod(num) / d : 0.0;
    return std::isfinite(r) && r > 0 && r <= 1000 ? r : 0.0;
  };
  info.fps = rate("avg_frame_rate");
  if (info.fps == 0) info.fps = rate("r_frame_rate");
  if (info.fps == 0)
    throw InputError(file + ": an undecodable video: no frame rate from 0 to 1000 frames per second (avg_frame_rate " +
                     quote_input(value("avg_frame_rate")) + ", r_frame_rate " + quote_input(value("r_frame_rate")) + ")");
  long long frames = 0;
  if (integer("nb_frames", frames)) {
    if (frames == 0) throw InputError(file + ": no frames: its video stream is empty");
    // A container's count is a hint (edit lists can change it): the decoder counts for
    // itself once it reaches the end. Huge counts are left unknown.
  }
  return info;
}

std::unique_ptr<VideoSource> open_video_source(const fs::path& source) {
  const std::string name = source.string();
  if (name.empty()) throw InputError("a screen source: expected a file or folder, got \"\"");
  if (name.find('%') != std::string::npos) return open_pattern(name);
  std::error_code ec;
  const auto st = fs::status(source, ec);
  if (!fs::exists(st))
    throw InputError(shorten(name, kEchoPathBytes) + ": no such file or folder (" + kSourceExpected + ")");
  if (fs::is_directory(st)) return open_folder(source);
  if (!fs::is_regular_file(st))
    throw InputError(shorten(name, kEchoPathBytes) + ": is not a regular file (" + kSourceExpected + ")");
  if (is_png_name(source)) return std::make_unique<PngSequence>(name, std::vector<fs::path>{source});
  return open_video(source);
}

}  // namespace draught
