#include "encoder.hpp"

#include "cleanup.hpp"
#include "core/io/files.hpp"
#include "core/io/process.hpp"
#include "core/io/temporaries.hpp"
#include "core/output/cutout.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace draught::cli {

namespace fs = std::filesystem;

Encoder::Encoder(const fs::path& dest, const std::string& shown, int w, int h, double fps, bool transparent)
    : dest_(dest), shown_(shown) {
  ffmpeg_ = find_ffmpeg("-o " + shown);
  if (ffmpeg_.empty())
    throw InputError("-o " + shown +
                     ": ffmpeg was not found on PATH (Debian: apt install ffmpeg); or write PNG frames with -o DIR/");
  gif_ = dest.extension() == ".gif";
  const bool webm = dest.extension() == ".webm";
  alpha_ = webm && transparent;
  part_ = temporary();
  char size[32], rate[32];
  std::snprintf(size, sizeof size, "%dx%d", w, h);
  std::snprintf(rate, sizeof rate, "%g", fps);
  std::vector<std::string> args = {ffmpeg_, "-nostdin", "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt",
                                   "rgba",  "-s",       size, "-r",        rate,    "-i", "-"};
  if (gif_) {  // lossless, so the palette and the GIF see exactly the rendered frames
    frames_ = temporary();
    palette_ = temporary();
    args.insert(args.end(), {"-c:v", "ffv1", "-f", "nut", frames_.string()});
  } else if (webm) {  // VP9 at constant quality (-b:v 0), its alpha in the side plane
    args.insert(args.end(), {"-c:v", "libvpx-vp9", "-pix_fmt", alpha_ ? "yuva420p" : "yuv420p", "-b:v", "0", "-crf",
                             "30", "-deadline", "good", "-cpu-used", "4", "-row-mt", "1", "-f", "webm", part_.string()});
  } else {
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
                             "18", "-movflags", "+faststart", "-f", "mp4", part_.string()});
  }
  int fds[2];
  make_pipe(fds);
  try {
    pid_ = spawn_process(args, fds[0]);
  } catch (...) {
    close(fds[0]);
    close(fds[1]);
    remove_temporaries();
    throw;
  }
  set_child_process(pid_);
  close(fds[0]);
  fd_ = fds[1];
  std::signal(SIGPIPE, SIG_IGN);  // a dying ffmpeg makes write() fail instead of killing us
}

Encoder::~Encoder() {
  if (fd_ >= 0) close(fd_);
  if (pid_ > 0) {  // unfinished (an error): stop it rather than let it complete a file
    kill_process(pid_);
    set_child_process(0);
  }
  remove_temporaries();
}

fs::path Encoder::temporary() {
  fs::path p = temporary_path_beside(dest_);
  temporary_created(p, false);
  temporaries_.push_back(p);
  return p;
}

void Encoder::remove_temporaries() {
  for (auto& p : temporaries_) {
    std::error_code ec;
    fs::remove(p, ec);
    temporary_gone(p);
  }
  temporaries_.clear();
}

void Encoder::write(const Image& picture) {
  if (alpha_) return write_bytes(straight_alpha(picture).rgba);
  write_bytes(picture.rgba);
}

void Encoder::write_bytes(const std::vector<std::uint8_t>& bytes) {
  const std::uint8_t* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("ffmpeg stopped reading frames for " + shown_ + " (see its message above)");
    p += n, left -= size_t(n);
  }
}

void Encoder::wait_for_child(const char* what) {
  const int status = wait_process(pid_);
  pid_ = -1;
  set_child_process(0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("ffmpeg failed " + std::string(what) + " " + shown_ + " (see its message above)");
}

void Encoder::run_to_end(std::vector<std::string> args) {
  args.insert(args.begin(), {ffmpeg_, "-nostdin", "-y", "-loglevel", "error"});
  pid_ = spawn_process(args);
  set_child_process(pid_);
  wait_for_child("writing");
}

void Encoder::finish() {
  close(fd_);
  fd_ = -1;
  wait_for_child("writing");
  if (gif_) {  // one palette for the whole clip keeps the colours of the drink
    run_to_end({"-i", frames_.string(), "-vf", "palettegen=stats_mode=full", "-c:v", "rawvideo", "-f", "nut",
                palette_.string()});
    run_to_end({"-i", frames_.string(), "-i", palette_.string(), "-lavfi", "[0:v][1:v]paletteuse=dither=sierra2_4a",
                "-loop", "0", "-f", "gif", part_.string()});
  }
  std::error_code ec;
  fs::rename(part_, dest_, ec);
  if (ec) throw InputError("-o " + shown_ + ": cannot write: " + ec.message());
  remove_temporaries();  // the rest; part_ is gone already
}

}  // namespace draught::cli
