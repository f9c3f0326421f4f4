// `draught render --timeline`: plays a timeline through the simulation and writes a PNG
// sequence, or pipes the frames to ffmpeg for MP4 / GIF. Deterministic: fixed steps,
// and frame i is the state at exactly i / fps seconds.
#include "commands.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/sim/scene_simulation.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>

extern char** environ;

namespace draught::cli {

namespace {

namespace fs = std::filesystem;

std::string find_on_path(const std::string& exe) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (size_t start = 0; start <= dirs.size();) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / exe;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return "";
}

// ffmpeg reading raw RGBA frames on its stdin.
class Encoder {
 public:
  Encoder(const fs::path& out, int w, int h, double fps) {
    const char* pinned = std::getenv("DRAUGHT_FFMPEG");
    if (pinned && *pinned && access(pinned, X_OK) != 0)
      throw InputError("-o " + out.string() + ": DRAUGHT_FFMPEG=" + pinned + " is not an executable ffmpeg");
    const std::string ffmpeg = pinned && *pinned ? std::string(pinned) : find_on_path("ffmpeg");
    if (ffmpeg.empty())
      throw InputError("-o " + out.string() +
                       ": ffmpeg was not found on PATH (Debian: apt install ffmpeg); or write PNG frames with -o DIR/");
    part_ = out.string() + ".part";
    const bool gif = out.extension() == ".gif";
    char size[32], rate[32];
    std::snprintf(size, sizeof size, "%dx%d", w, h);
    std::snprintf(rate, sizeof rate, "%g", fps);
    std::vector<std::string> args = {ffmpeg, "-nostdin", "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgba",
                                     "-s", size, "-r", rate, "-i", "-"};
    if (gif) {  // one palette for the whole clip keeps the colours of the drink
      for (const char* a : {"-vf", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a",
                            "-loop", "0", "-f", "gif"})
        args.emplace_back(a);
    } else {
      for (const char* a : {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
                            "18", "-movflags", "+faststart", "-f", "mp4"})
        args.emplace_back(a);
    }
    args.push_back(part_);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    const int rc = posix_spawn(&pid_, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[0]);
    if (rc != 0) {
      close(fds[1]);
      throw std::runtime_error("cannot start " + ffmpeg + ": " + std::strerror(rc));
    }
    fd_ = fds[1];
    std::signal(SIGPIPE, SIG_IGN);  // a dying ffmpeg makes write() fail instead of killing us
  }
  ~Encoder() {
    if (fd_ >= 0) close(fd_);
    if (pid_ > 0) waitpid(pid_, nullptr, 0);
    if (!part_.empty()) fs::remove(part_);
  }
  void write(const Image& img) {
    const std::uint8_t* p = img.rgba.data();
    size_t left = img.rgba.size();
    while (left > 0) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error("ffmpeg stopped reading frames (see its message above)");
      p += n, left -= size_t(n);
    }
  }
  void finish(const fs::path& out) {
    close(fd_);
    fd_ = -1;
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      throw std::runtime_error("ffmpeg failed writing " + out.string() + " (see its message above)");
    fs::rename(part_, out);
    part_.clear();
  }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string part_;
};

// "[#######.......]  42/120 frames  3.1 fps  25 s left", redrawn in place.
void show_progress(int done, int total, double seconds, bool final) {
  const int width = 28, filled = total ? done * width / total : width;
  const double fps = seconds > 0 ? done / seconds : 0;
  std::string bar(size_t(filled), '#');
  bar.append(size_t(width - filled), '.');
  std::fprintf(stderr, "\r[%s] %4d/%d frames  %5.1f fps  %4.0f s left", bar.c_str(), done, total, fps,
               fps > 0 ? (total - done) / fps : 0.0);
  if (final) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace

int animate(const RenderRequest& req, const AnimateRequest& anim) {
  Timeline timeline = load_timeline(anim.timeline);
  SceneRequest scene = req.scene;
  if (!anim.preset_given && !timeline.preset.empty()) scene.preset = timeline.preset;
  if (!anim.glass_given && !timeline.glass.empty()) {
    // A scene that places its own glasses takes none from the timeline.
    if (!load_preset(find_preset(scene.preset, "drink")).objects.empty())
      throw InputError(timeline.file + ": field 'glass': the scene '" + scene.preset +
                       "' places its own glasses; leave out the timeline's glass");
    scene.glass = timeline.glass;
  }
  const double fps = anim.fps > 0 ? anim.fps : (timeline.fps > 0 ? timeline.fps : 30.0);
  const double duration = anim.duration > 0 ? anim.duration : timeline.duration;
  const int frames = std::max(1, int(std::floor(duration * fps + 1e-9)));

  fs::path out = anim.output.empty() ? fs::path("out") / (timeline.name.empty() ? "animation" : timeline.name) / ""
                                     : fs::path(anim.output);
  const std::string ext = out.extension().string();
  const bool video = ext == ".mp4" || ext == ".gif";
  if (!video && !ext.empty())
    throw InputError("-o " + out.string() + ": with --timeline, expected a folder for PNG frames (e.g. frames/), "
                     "or a file ending in .mp4 or .gif");

  std::string log;
  const Scene base = resolve_scene_objects(scene, &log);
  bind_timeline(timeline, base);  // the objects its actions address are in this scene
  if (req.verbose) std::fprintf(stderr, "%stimeline: %s (%d frames at %g fps)\n", log.c_str(), timeline.file.c_str(), frames, fps);
  auto ctx = gpu::HeadlessContext::create();
  if (req.verbose) std::fprintf(stderr, "renderer: %s (%s)\n", ctx->renderer().c_str(), ctx->platform().c_str());
  gpu::Renderer renderer(req.shader_dir);

  SceneSimulation sim(timeline.scene_at(0, base));
  sim.settle_bubbles(4.0);  // drinks that have been standing (a pour clears them)
  std::vector<TimelineDriver> drivers = timeline_drivers(timeline, sim);  // one per object
  std::unique_ptr<Encoder> encoder;
  if (video) {
    if (out.has_parent_path()) fs::create_directories(out.parent_path());
    encoder = std::make_unique<Encoder>(out, req.width, req.height, fps);
  } else {
    fs::create_directories(out);
  }
  const bool progress = anim.progress || isatty(STDERR_FILENO);
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) {
    play_timeline(sim, drivers, timeline, base, i / fps);
    const Image img = renderer.render(sim.frame(), req.width, req.height);
    if (encoder) {
      encoder->write(img);
    } else {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", i);
      write_png(out / name, img);
    }
    if (progress)
      show_progress(i + 1, frames, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                    i + 1 == frames);
  }
  if (encoder) encoder->finish(out);
  double spilled = 0;  // the most any glass spilled
  for (int i = 0; i < int(base.objects.size()); ++i)
    if (const Simulation* v = sim.vessel(i)) spilled = std::max(spilled, v->spilled());
  std::printf("wrote %s (%d frame%s, %g fps, %.2f s; spilled %.1f %% of the glass%s)\n", out.string().c_str(), frames,
              frames == 1 ? "" : "s", fps, frames / fps, 100.0 * spilled,
              base.objects.size() > 1 ? " that spilled most" : "");
  return 0;
}

}  // namespace draught::cli
