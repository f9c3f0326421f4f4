// draught: headless renderer of drinks in glassware.
#include "commands.hpp"

#include "core/io/files.hpp"
#include "gpu/shader_source.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace draught;

int main(int argc, char** argv) {
  CLI::App app{"draught: raymarched drinks in glassware, rendered headless (OpenGL ES 3.0 via EGL)"};
  app.set_version_flag("--version", std::string("draught ") + DRAUGHT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // global flags (--verbose) also after the subcommand
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Say which renderer and presets are used, and how long it took");

  cli::RenderRequest rr;
  std::string size = "512x512", tonemap;
  bool transparent = false;
  int supersample = 0;
  auto* render = app.add_subcommand("render", "Render a preset to a PNG");
  render->add_option("-p,--preset", rr.scene.preset, "Drink or scene preset: a name or a JSON file")
      ->capture_default_str();
  render->add_option("-g,--glass", rr.scene.glass, "Glass preset: a name or a JSON file (default: the drink's)");
  render->add_option("-s,--size", size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_option("-o,--output", rr.output, "Output PNG (written atomically)")->capture_default_str();
  render->add_option("--set", rr.scene.sets, "Set a parameter: path=value (see `draught params`); repeatable")
      ->allow_extra_args(false);
  render->add_option("--camera", rr.scene.camera, "Camera: eye=x,y,z target=x,y,z vfov=degrees")->expected(1, 3);
  render->add_option("--debug", rr.debug,
                     "Write a debug view instead: depth, normal, material, or cost (intersection tests per pixel)")
      ->check(CLI::IsMember({"depth", "normal", "material", "cost"}));
  render->add_option("--tonemap", tonemap, "Output transform: none or aces")->check(CLI::IsMember({"none", "aces"}));
  render->add_flag("--transparent", transparent, "Transparent background, premultiplied alpha");
  render->add_option("--supersample", supersample, "Anti-aliasing: samples per axis (1-4)")
      ->check(CLI::Range(1, 4));
  render->add_option("--shader-dir", rr.shader_dir, "Load shaders from this folder instead of the built-in ones");
  cli::AnimateRequest anim;
  render->add_option("-t,--timeline", anim.timeline,
                     "Animate: play this timeline (a name or a JSON file); -o is then a folder for PNG frames or a "
                     ".mp4/.gif file");
  render->add_option("--fps", anim.fps, "Frames per second of the animation (default: the timeline's, else 30)")
      ->check(CLI::Range(1.0, 120.0));
  render->add_option("--duration", anim.duration, "Seconds to render (default: the timeline's)")
      ->check(CLI::Range(0.01, 600.0));
  render->add_flag("--progress", anim.progress, "Show the progress bar even when stderr is not a terminal");

  auto* presets = app.add_subcommand("presets", "List the presets");
  std::vector<std::string> files;
  auto* validate = app.add_subcommand("validate", "Check preset and timeline files; exit 1 if any is invalid");
  validate->add_option("files", files, "Preset or timeline JSON files")->required();
  bool markdown = false;
  auto* params = app.add_subcommand("params", "Print the parameter table (path, type, default, range, unit, doc)");
  params->add_flag("--markdown", markdown, "As a Markdown table");
  int frames = 20;
  std::vector<int> sizes = {256, 512};
  auto* bench = app.add_subcommand("bench", "Render fixed scenes for N frames and print median frame times");
  bench->add_option("-n,--frames", frames, "Frames per scene and size")->check(CLI::Range(1, 10000))->capture_default_str();
  bench->add_option("--sizes", sizes, "Square image sizes")->delimiter(',')->capture_default_str();
  std::vector<std::string> bench_scenes;
  bench->add_option("--scenes", bench_scenes, "Only these scenes (names as printed)")->delimiter(',');

  CLI11_PARSE(app, argc, argv);
  try {
    if (*render) {
      cli::parse_size(size, rr.width, rr.height);
      if (!tonemap.empty()) rr.scene.sets.push_back("render.tonemap=" + tonemap);
      if (transparent) rr.scene.sets.push_back("render.transparent=true");
      if (supersample) rr.scene.sets.push_back("render.supersample=" + std::to_string(supersample));
      rr.verbose = verbose;
      if (!anim.timeline.empty()) {
        if (!rr.debug.empty()) throw InputError("--debug renders a still: leave out --timeline");
        anim.output = render->get_option("--output")->count() ? rr.output : "";
        anim.preset_given = render->get_option("--preset")->count() > 0;
        anim.glass_given = render->get_option("--glass")->count() > 0;
        return cli::animate(rr, anim);
      }
      if (anim.fps > 0 || anim.duration > 0 || anim.progress)
        throw InputError("--fps, --duration and --progress need --timeline");
      return cli::render(rr);
    }
    if (*presets) return cli::list_presets();
    if (*validate) return cli::validate(files);
    if (*params) return cli::print_params(markdown);
    if (*bench) return cli::bench(frames, sizes, bench_scenes, verbose);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "draught: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
