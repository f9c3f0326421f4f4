// `draught render --timeline`: plays a timeline through the simulation and writes a PNG
// sequence (built in a temporary folder, moved into place whole: output.hpp), or streams
// the frames to ffmpeg for MP4 / GIF (encoder.hpp). Deterministic: fixed steps, and
// frame i is the state at exactly i / fps seconds.
#include "commands.hpp"

#include "cleanup.hpp"
#include "encoder.hpp"
#include "names.hpp"
#include "output.hpp"

#include "core/io/files.hpp"
#include "core/output/cutout.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/sim/scene_simulation.hpp"
#include "core/text/echo.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace draught::cli {

namespace {

namespace fs = std::filesystem;

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

// The scene a timeline plays in (flags win over the timeline's own preset and glass),
// with every file it reads added to `inputs`, so that the output cannot replace one.
SceneRequest timeline_scene(const RenderRequest& req, const AnimateRequest& anim, const Timeline& timeline,
                            std::vector<InputFile>& inputs) {
  SceneRequest scene = req.scene;
  const std::string field = timeline.file + ": field '";
  if (!anim.preset_given && !timeline.preset.empty()) {
    scene.preset = timeline.preset;
    inputs.push_back({"timeline's preset", preset_file(scene.preset, "drink", field + "preset':")});
  } else {
    inputs.push_back({"--preset", preset_file(scene.preset, "drink", "--preset")});
  }
  if (!anim.glass_given && !timeline.glass.empty()) {
    // A scene that places its own glasses takes none from the timeline.
    if (!load_preset(find_preset(scene.preset, "drink")).objects.empty())
      throw InputError(timeline.file + ": field 'glass': the scene '" + scene.preset +
                       "' places its own glasses; leave out the timeline's glass");
    scene.glass = timeline.glass;
    inputs.push_back({"timeline's glass", preset_file(scene.glass, "glass", field + "glass':")});
  } else if (!scene.glass.empty()) {
    inputs.push_back({"--glass", preset_file(scene.glass, "glass", "--glass")});
  }
  if (!req.shader_dir.empty()) inputs.push_back({"--shader-dir", req.shader_dir});
  return scene;
}

// A timeline read, the scene it plays in and the rate it is played at; `inputs`: every
// file it reads (the output may replace none).
struct TimelineToPlay {
  Timeline timeline;
  std::vector<InputFile> inputs;
  SceneRequest scene;
  double fps = 30;
};

TimelineToPlay read_timeline(const RenderRequest& req, const AnimateRequest& anim) {
  TimelineToPlay t;
  const fs::path path = timeline_file(anim.timeline);
  t.timeline = load_timeline(path.string());
  t.inputs = {{"--timeline", path}};
  t.scene = timeline_scene(req, anim, t.timeline, t.inputs);
  t.fps = anim.fps > 0 ? anim.fps : (t.timeline.fps > 0 ? t.timeline.fps : 30.0);
  return t;
}

// The timeline's scene resolved and its camera checked, the timeline bound to it (the
// objects its actions address are in this scene); what was resolved goes to `log`.
Scene bind_scene(const RenderRequest& req, TimelineToPlay& t, std::string& log) {
  Scene base = resolve_scene_objects(t.scene, &log);
  check_camera(base.params, req.camera_given);
  bind_timeline(t.timeline, base);
  return base;
}

// The timeline played from its start through the simulation, frame by frame: drinks that
// have been standing (a pour clears them), one driver per object.
class Playback {
 public:
  Playback(const Timeline& tl, const Scene& base) : tl_(tl), base_(base), sim_(tl.scene_at(0, base)) {
    sim_.settle_bubbles(4.0);
    drivers_ = timeline_drivers(tl, sim_);
  }
  // On to time t (a parameter the timeline moves takes the value at t for the steps up to
  // the next call).
  void to(double t) { play_timeline(sim_, drivers_, tl_, base_, t); }
  const SceneSimulation& sim() const { return sim_; }

 private:
  const Timeline& tl_;
  const Scene& base_;
  SceneSimulation sim_;
  std::vector<TimelineDriver> drivers_;
};

// Whether a frame of the timeline is transparent: from the start, or from a set action
// that makes the picture transparent (a WebM then keeps alpha; its opaque frames have 1).
bool any_frame_transparent(const Timeline& timeline, const Scene& base) {
  return base.params.render.transparent ||
         std::any_of(timeline.actions.begin(), timeline.actions.end(), [](const TimelineAction& a) {
           const bool* on = a.param && a.param->path == "render.transparent" ? std::get_if<bool>(&a.value) : nullptr;
           return a.kind == TimelineAction::Kind::Set && on && *on;
         });
}

}  // namespace

int render_timeline_still(const RenderRequest& req, const AnimateRequest& anim, double at) {
  TimelineToPlay t = read_timeline(req, anim);
  const fs::path dest = still_destination(req);
  refuse_overwriting_inputs(dest, req.output, t.inputs, false);
  std::string log;
  const Scene base = bind_scene(req, t, log);
  if (req.verbose)
    std::fprintf(stderr, "%stimeline: %s at %g s (played at %g fps)\n", log.c_str(), t.timeline.file.c_str(), at,
                 t.fps);
  // Frame by frame as animate plays it, then on to `at`: the animation's frame there.
  Playback play(t.timeline, base);
  for (int i = 0; i / t.fps < at - 1e-9; ++i) play.to(i / t.fps);
  play.to(at);
  return render_still(req, play.sim().frame(), dest);
}

int animate(const RenderRequest& req, const AnimateRequest& anim) {
  TimelineToPlay t = read_timeline(req, anim);
  const Timeline& timeline = t.timeline;
  const double fps = t.fps;
  const double duration = anim.duration > 0 ? anim.duration : timeline.duration;
  const int frames = std::max(1, int(std::floor(duration * fps + 1e-9)));

  const std::string shown =
      anim.output.empty() ? (fs::path("out") / (timeline.name.empty() ? "animation" : timeline.name) / "").string()
                          : anim.output;
  const std::string ext = fs::path(shown).extension().string();
  const bool video = ext == ".mp4" || ext == ".webm" || ext == ".gif";
  if (!video && !ext.empty())
    throw InputError("-o " + shorten(shown, kEchoPathBytes) +
                     ": with --timeline, expected a folder for PNG frames (e.g. frames/), or a file ending in .mp4, "
                     ".webm or .gif");
  // Links are followed: the file or folder they point to is what gets replaced.
  const fs::path dest = video ? write_destination(shown) : SequenceFolder::destination(shown);
  refuse_overwriting_inputs(dest, shown, t.inputs, !video);

  std::string log;
  const Scene base = bind_scene(req, t, log);
  if (req.verbose)
    std::fprintf(stderr, "%stimeline: %s (%d frames at %g fps)\n", log.c_str(), timeline.file.c_str(), frames, fps);

  // The output is set up (and a folder that may not be replaced refused) before the
  // costly part; ffmpeg starts before the GL driver's threads do.
  if (dest.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(dest.parent_path(), ec);
    if (ec) throw InputError("-o " + shown + ": cannot create " + dest.parent_path().string() + ": " + ec.message());
  }
  sweep_stale_temporaries(dest.parent_path());  // of runs killed before they could clean up
  if (video) sweep_legacy_part(dest);             // and this video's part from older versions
  std::optional<Encoder> encoder;
  std::optional<SequenceFolder> sequence;
  if (video) encoder.emplace(dest, shown, req.width, req.height, fps, any_frame_transparent(timeline, base));
  else sequence.emplace(dest, shown, anim.overwrite);

  auto ctx = gpu::HeadlessContext::create();
  if (req.verbose) std::fprintf(stderr, "renderer: %s (%s)\n", ctx->renderer().c_str(), ctx->platform().c_str());
  gpu::Renderer renderer(req.shader_dir);
  Playback play(timeline, base);
  const bool progress = anim.progress || isatty(STDERR_FILENO);
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) {
    play.to(i / fps);
    const FrameState frame = play.sim().frame();
    Image img;
    try {
      img = renderer.render(frame, req.width, req.height);
    } catch (const std::runtime_error& e) {
      explain_size_error(e, req, base.params.render.supersample);
    }
    if (encoder) encoder->write(img);
    else write_png(sequence->folder() / SequenceFolder::frame_name(i), png_picture(img, frame.params.render.transparent));
    if (progress)
      show_progress(i + 1, frames, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                    i + 1 == frames);
  }
  if (encoder) encoder->finish();
  else sequence->publish();

  fs::path given(shown);
  if (!given.has_filename()) given = given.parent_path();  // frames/ -> frames
  std::error_code ec;
  const std::string through =
      fs::is_symlink(fs::symlink_status(given, ec)) ? "through the symbolic link, to " + dest.string() + "; " : "";
  double spilled = 0;  // the most any glass spilled
  for (int i = 0; i < int(base.objects.size()); ++i)
    if (const Simulation* v = play.sim().vessel(i)) spilled = std::max(spilled, v->spilled());
  std::printf("wrote %s (%s%d frame%s, %g fps, %.2f s; spilled %.1f %% of the glass%s)\n", shown.c_str(),
              through.c_str(), frames, frames == 1 ? "" : "s", fps, frames / fps, 100.0 * spilled,
              base.objects.size() > 1 ? " that spilled most" : "");
  return 0;
}

}  // namespace draught::cli
