// draught: headless renderer of drinks in glassware.
#include "args.hpp"
#include "cleanup.hpp"
#include "commands.hpp"

#include "core/io/files.hpp"
#include "core/text/echo.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace draught;

int main(int argc, char** argv) {
  cli::install_cleanup_on_signals();
  CLI::App app{"draught: raymarched drinks in glassware, rendered headless (OpenGL ES 3.0 via EGL)"};
  app.set_version_flag("--version", std::string("draught ") + DRAUGHT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // global flags (--verbose) also after the subcommand
  app.allow_extras();  // unknown words are kept, for a message that names them (args.hpp)
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Say which renderer and presets are used, and how long it took");

  // Values are taken as text and checked by cli::*_flag, so every bad value gets the
  // same kind of message (flag, value, what was expected) and exit code 1.
  cli::RenderRequest rr;
  std::string size = "512x512", tonemap, debug, supersample, adaptive, fps, duration, at;
  bool transparent = false;
  auto* render = app.add_subcommand("render", "Render a preset to a PNG");
  render->add_option("-p,--preset", rr.scene.preset, "Drink or scene preset: a name or a JSON file")
      ->capture_default_str();
  render->add_option("-g,--glass", rr.scene.glass, "Glass preset: a name or a JSON file (default: the drink's)");
  render->add_option("-s,--size", size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_option("-o,--output", rr.output,
                     "Output PNG (written atomically; a symbolic link is followed and its target replaced); "
                     "with --reference, a .exr gets the scene-linear radiance")
      ->capture_default_str();
  render->add_option("--set", rr.scene.sets, "Set a parameter: path=value (see `draught params`); repeatable")
      ->allow_extra_args(false);
  render->add_option("--camera", rr.scene.camera, "Camera: eye=x,y,z target=x,y,z vfov=degrees")->expected(1, 3);
  render->add_option("--debug", debug,
                     "Write a debug view instead: depth, normal, material, or cost (intersection tests per pixel)");
  render->add_option("--tonemap", tonemap, "Output transform: none or aces");
  render->add_flag("--transparent", transparent, "Transparent background: the objects cut out (PNG: straight alpha; the floor is left out)");
  render->add_option("--supersample", supersample, "Anti-aliasing: samples per axis (1-4)");
  render->add_option("--adaptive", adaptive,
                     "Adaptive anti-aliasing: samples per axis where a pixel's samples disagree, fine detail and "
                     "edges (1-4; default 4; not above --supersample: off)");
  render->add_option("--shader-dir", rr.shader_dir, "Load shaders from this folder instead of the built-in ones");
  std::string spp, threads;
  render->add_flag("--reference", rr.reference,
                   "Render with the reference path tracer on the CPU (slow, the ground truth) instead of the GPU");
  render->add_option("--spp", spp, "Reference: paths per pixel, 1-100000 (default 64)");
  render->add_option("--threads", threads, "Reference: worker threads, 1-256 (default: one per CPU)");
  cli::AnimateRequest anim;
  render->add_option("-t,--timeline", anim.timeline,
                     "Animate: play this timeline (a name or a JSON file); -o is then a folder for PNG frames or a "
                     ".mp4/.webm/.gif file (a .webm keeps --transparent's alpha)");
  render->add_option("--fps", fps, "Frames per second of the animation, 1-120 (default: the timeline's, else 30)");
  render->add_option("--duration", duration, "Seconds to render, 0.01-600 (default: the timeline's)");
  render->add_option("--at", at,
                     "With --timeline: render the timeline's frame at this time, 0-600 seconds, as a still PNG "
                     "(the picture, --debug or --reference; played at --fps)");
  render->add_flag("--progress", anim.progress, "Show the progress bar even when stderr is not a terminal");
  render->add_flag("--overwrite", anim.overwrite,
                   "Let a PNG sequence replace a folder that holds other files (all of them are removed)");

  auto* presets = app.add_subcommand("presets", "List the presets");
  std::vector<std::string> files;
  auto* validate = app.add_subcommand("validate", "Check preset and timeline files; exit 1 if any is invalid");
  validate->add_option("files", files, "Preset or timeline JSON files")->required();
  bool markdown = false;
  auto* params = app.add_subcommand("params", "Print the parameter table (path, type, default, range, unit, doc)");
  params->add_flag("--markdown", markdown, "As a Markdown table");
  auto* environment = app.add_subcommand("environment", "Environments draught makes itself");
  auto* bake = environment->add_subcommand("bake", "Write an environment as an equirectangular Radiance .hdr");
  std::string env_name, env_width = "1024", env_output;
  bake->add_option("name", env_name, "studio (the procedural studio with its key softbox) or bar (a warm bar at night)")
      ->required();
  bake->add_option("--width", env_width, "Width in pixels, even, 8-8192 (the height is half)")->capture_default_str();
  bake->add_option("-o,--output", env_output, "The .hdr file to write")->required();
  environment->require_subcommand(1);
  std::string frames = "20", sizes = "256,512";
  auto* bench = app.add_subcommand("bench", "Render fixed scenes for N frames and print median frame times");
  bench->add_option("-n,--frames", frames, "Frames per scene and size (1-10000)")->capture_default_str();
  bench->add_option("--sizes", sizes, "Square image sizes, comma-separated")->capture_default_str();
  std::vector<std::string> bench_scenes;
  bench->add_option("--scenes", bench_scenes, "Only these scenes (names as printed)")->delimiter(',');

  try {
    cli::check_verb(app, argc, argv);
    try {
      app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      throw InputError(cli::explain_parse_error(app, e));
    }
    if (app.remaining_size(true) > 0) throw InputError(cli::explain_extras(app));
    if (*render) {
      cli::check_device_environment();
      cli::parse_size(size, rr.width, rr.height);
      if (render->count("--debug"))
        rr.debug = cli::choice_flag("--debug", debug, {"depth", "normal", "material", "cost"});
      if (render->count("--tonemap"))
        rr.scene.sets.push_back("render.tonemap=" + cli::choice_flag("--tonemap", tonemap, {"none", "aces"}));
      if (transparent) rr.scene.sets.push_back("render.transparent=true");
      if (render->count("--supersample"))
        rr.scene.sets.push_back("render.supersample=" +
                                std::to_string(cli::integer_flag("--supersample", supersample, 1, 4)));
      if (render->count("--adaptive"))
        rr.scene.sets.push_back("render.adaptive_supersample=" +
                                std::to_string(cli::integer_flag("--adaptive", adaptive, 1, 4)));
      if (render->count("--fps")) anim.fps = cli::number_flag("--fps", fps, 1, 120, "frames per second");
      if (render->count("--duration")) anim.duration = cli::number_flag("--duration", duration, 0.01, 600, "seconds");
      rr.verbose = verbose;
      rr.output_given = render->count("--output") > 0;
      rr.camera_given = render->count("--camera") > 0;
      if (render->count("--spp")) rr.samples = cli::integer_flag("--spp", spp, 1, 100000);
      if (render->count("--threads")) rr.threads = cli::integer_flag("--threads", threads, 1, 256);
      const bool still_of_timeline = render->count("--at") > 0;
      if (still_of_timeline) {
        if (anim.timeline.empty()) throw InputError("--at needs --timeline (it is a time in a timeline)");
        for (const char* flag : {"--duration", "--overwrite"})
          if (render->count(flag)) throw InputError(std::string(flag) + " is about animations: --at renders a still");
      }
      if (rr.reference) {
        if (!anim.timeline.empty() && !still_of_timeline)
          throw InputError("--reference renders a still: leave out --timeline, or give --at");
        if (!rr.debug.empty()) throw InputError("--reference renders the picture: leave out --debug");
        if (transparent) throw InputError("--reference renders an opaque picture: leave out --transparent");
        if (!rr.shader_dir.empty()) throw InputError("--reference uses no shaders: leave out --shader-dir");
        rr.progress = anim.progress;
      } else {
        for (const char* flag : {"--spp", "--threads"})
          if (render->count(flag)) throw InputError(std::string(flag) + " needs --reference (it is about the path tracer)");
      }
      if (still_of_timeline) {
        anim.preset_given = render->count("--preset") > 0;
        anim.glass_given = render->count("--glass") > 0;
        return cli::render_timeline_still(rr, anim, cli::number_flag("--at", at, 0, 600, "seconds"));
      }
      if (!anim.timeline.empty()) {
        if (!rr.debug.empty()) throw InputError("--debug renders a still: leave out --timeline, or give --at");
        anim.output = rr.output_given ? rr.output : "";
        anim.preset_given = render->count("--preset") > 0;
        anim.glass_given = render->count("--glass") > 0;
        return cli::animate(rr, anim);
      }
      for (const char* flag : {"--fps", "--duration", "--overwrite"})
        if (render->count(flag)) throw InputError(std::string(flag) + " needs --timeline (it is about animations)");
      if (!rr.reference && render->count("--progress"))
        throw InputError("--progress needs --timeline or --reference (it is about long renders)");
      return cli::render(rr);
    }
    if (*presets) return cli::list_presets();
    if (*validate) return cli::validate(files);
    if (*params) return cli::print_params(markdown);
    if (*bake) return cli::bake_environment(env_name, cli::integer_flag("--width", env_width, 8, 8192), env_output);
    if (*bench) {
      cli::check_device_environment();
      return cli::bench(cli::integer_flag("--frames", frames, 1, 10000),
                        cli::integer_list_flag("--sizes", sizes, 1, 8192), bench_scenes, verbose);
    }
  } catch (const std::exception& e) {
    // Capped: a message is never a flood, and never ends inside a UTF-8 character.
    std::fprintf(stderr, "draught: error: %s\n", shorten(e.what(), 4 * kEchoPathBytes).c_str());
    return 1;
  }
  return 0;
}
