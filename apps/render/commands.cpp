#include "commands.hpp"

#include "cleanup.hpp"
#include "names.hpp"
#include "output.hpp"

#include "core/environment/environment_bake.hpp"
#include "core/io/files.hpp"
#include "core/output/cutout.hpp"
#include "core/io/hdr_image.hpp"
#include "core/params/json_input.hpp"
#include "core/text/echo.hpp"
#include "core/scene/frame.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/reference/path_tracer.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <tuple>

#include <unistd.h>

namespace draught::cli {


void parse_size(const std::string& text, int& w, int& h) {
  auto x = text.find('x');
  auto whole_number = [](std::string_view s, int& out) {
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
  };
  if (x == std::string::npos || !whole_number(std::string_view(text).substr(0, x), w) ||
      !whole_number(std::string_view(text).substr(x + 1), h) || w < 1 || h < 1 || w > 8192 || h > 8192)
    throw InputError("--size " + shorten(text) + ": expected WIDTHxHEIGHT, each from 1 to 8192, e.g. 512x512");
}

void explain_size_error(const std::runtime_error& e, const RenderRequest& req, int supersample) {
  const std::string what = e.what();
  if (what.find("offscreen framebuffer") == std::string::npos) throw;
  throw InputError("--size " + std::to_string(req.width) + "x" + std::to_string(req.height) +
                   (supersample > 1 ? " at --supersample " + std::to_string(supersample) + " (rendered at " +
                                          std::to_string(req.width * supersample) + "x" +
                                          std::to_string(req.height * supersample) + ", then averaged down)"
                                    : std::string()) +
                   ": " + what + "; choose a smaller size or supersampling");
}

void check_camera(const SceneParams& p, bool camera_given) {
  const glm::vec3 e = p.camera.eye;
  if (glm::length(p.camera.target - e) > 1e-6f) return;
  char at[96];
  std::snprintf(at, sizeof at, "(%g, %g, %g)", double(e.x), double(e.y), double(e.z));
  throw InputError(std::string(camera_given ? "--camera: " : "") + "camera.eye and camera.target are the same point " +
                   at + ": the camera needs a direction to look in; move the eye or the target");
}

namespace {

// Writes a still to `dest` (the file `out` names, a symbolic link followed) atomically
// by `write(dest)`, its folder made and stale temporaries there swept, and says where it
// went (and `what`, when given).
template <class Write>
void write_still_file(const std::filesystem::path& dest, const std::filesystem::path& out, Write write,
                      const std::string& what = "") {
  if (dest.has_parent_path()) std::filesystem::create_directories(dest.parent_path());
  sweep_stale_temporaries(dest.parent_path());
  write(dest);
  std::string note = dest != out ? "through the symbolic link, to " + dest.string() : "";
  if (!what.empty()) note = what + (note.empty() ? "" : "; " + note);
  if (!note.empty()) std::printf("wrote %s (%s)\n", out.c_str(), note.c_str());
  else std::printf("wrote %s\n", out.string().c_str());
}

void write_still(const std::filesystem::path& dest, const std::filesystem::path& out, const Image& img) {
  write_still_file(dest, out, [&](const std::filesystem::path& p) { write_png(p, img); });
}

// A still from the reference path tracer: the same frame, camera and output transform
// as the GPU's picture; progress on stderr.
int render_reference_still(const RenderRequest& req, const FrameState& frame, const std::filesystem::path& dest,
                           const std::filesystem::path& out) {
  ReferenceSettings settings;
  settings.samples = req.samples;
  settings.threads = req.threads;
  const bool progress = req.progress || isatty(STDERR_FILENO);
  const auto t0 = std::chrono::steady_clock::now();
  if (progress)
    settings.progress = [&](int done, int rows) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const int width = 28, filled = done * width / rows;
      std::fprintf(stderr, "\r[%s%s] %3d %%  %4.0f s left", std::string(size_t(filled), '#').c_str(),
                   std::string(size_t(width - filled), '.').c_str(), done * 100 / rows,
                   done > 0 ? s * (rows - done) / done : 0.0);
      if (done == rows) std::fprintf(stderr, "\n");
      std::fflush(stderr);
    };
  const RadianceImage radiance = render_reference(frame, req.width, req.height, settings);
  if (req.verbose)
    std::fprintf(stderr, "reference: %dx%d at %d paths per pixel in %.1f s (%.0f paths per second)\n", req.width,
                 req.height, req.samples, radiance.seconds,
                 double(req.width) * req.height * req.samples / std::max(radiance.seconds, 1e-9));
  if (dest.extension() == ".exr")  // the radiance itself, before exposure and the tone map
    write_still_file(
        dest, out, [&](const std::filesystem::path& p) { write_exr(p, radiance_hdr_image(radiance)); },
        "scene-linear radiance");
  else
    write_still(dest, out, display_image(radiance, frame.params.render));
  return 0;
}

// --debug's view (None for the picture); throws InputError for another name.
gpu::DebugView debug_view(const std::string& debug) {
  if (debug.empty()) return gpu::DebugView::None;
  if (debug == "depth") return gpu::DebugView::Depth;
  if (debug == "normal") return gpu::DebugView::Normal;
  if (debug == "material") return gpu::DebugView::Material;
  if (debug == "cost") return gpu::DebugView::Cost;
  throw InputError("--debug " + debug + ": expected depth, normal, material or cost");
}

}  // namespace

// The PNG -o names for a still (or with --reference an OpenEXR file of the radiance): its
// destination (a symbolic link followed). Throws InputError for another extension.
std::filesystem::path still_destination(const RenderRequest& req) {
  const std::filesystem::path out(req.output);
  const std::string shown = "-o " + shorten(req.output, kEchoPathBytes);
  if (out.extension() == ".exr" && !req.reference)
    throw InputError(shown + ": an OpenEXR file holds the reference's scene-linear radiance: add --reference, or "
                             "name a .png");
  if (out.extension() != ".png" && out.extension() != ".exr")
    throw InputError(shown + ": expected a file name ending in .png (or .exr with --reference)");
  return write_destination(out);
}

int render_still(const RenderRequest& req, const FrameState& frame, const std::filesystem::path& dest) {
  const std::filesystem::path out(req.output);
  const gpu::DebugView view = debug_view(req.debug);
  if (req.reference) return render_reference_still(req, frame, dest, out);
  auto ctx = gpu::HeadlessContext::create();
  if (req.verbose) std::fprintf(stderr, "renderer: %s (%s)\n", ctx->renderer().c_str(), ctx->platform().c_str());
  gpu::Renderer renderer(req.shader_dir);
  auto t0 = std::chrono::steady_clock::now();
  const int supersample = view == gpu::DebugView::None ? frame.params.render.supersample : 1;
  Image img;
  try {
    img = view == gpu::DebugView::None
              ? renderer.render(frame, req.width, req.height)
              : gpu::visualize_debug(renderer.render_debug(frame, req.width, req.height, view), view,
                                    depth_range(frame, req.width, req.height));
  } catch (const std::runtime_error& e) {
    explain_size_error(e, req, supersample);
  }
  auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (req.verbose)
  {
    std::fprintf(stderr, "rendered %dx%d (supersample %d) in %.1f ms\n", req.width, req.height, supersample, ms);
    if (const gpu::Renderer::Refined r = renderer.last_refined(); r.pixels > 0)
      std::fprintf(stderr, "  of which %ld pixels (%.1f %%) drawn again at %d x %d samples: %.1f ms\n", r.pixels,
                   100.0 * double(r.pixels) / (double(req.width) * req.height), r.samples, r.samples, r.ms);
  }
  write_still(dest, out, png_picture(img, frame.params.render.transparent));
  return 0;
}

int render(const RenderRequest& req) {
  debug_view(req.debug);  // (its error before any file is looked at)
  const std::filesystem::path dest = still_destination(req);
  // Names resolved first, so a typo gets its "did you mean"; what is read is never written.
  std::vector<InputFile> inputs = {{"--preset", preset_file(req.scene.preset, "drink", "--preset")}};
  if (!req.scene.glass.empty()) inputs.push_back({"--glass", preset_file(req.scene.glass, "glass", "--glass")});
  if (!req.shader_dir.empty()) inputs.push_back({"--shader-dir", req.shader_dir});
  refuse_overwriting_inputs(dest, req.output, inputs, false);
  std::string log;
  const Scene scene = resolve_scene_objects(req.scene, &log);
  check_camera(scene.params, req.camera_given);
  if (req.verbose) std::fprintf(stderr, "%s", log.c_str());
  return render_still(req, make_frame(scene), dest);
}

int list_presets() {
  // objects: how many glasses a scene places (one for a scene without objects).
  std::printf("%-6s %-16s %-10s %-7s %s\n", "kind", "name", "glass", "objects", "description");
  std::vector<std::string> broken;
  for (const Preset& p : draught::list_presets(&broken)) {
    const std::string objects =
        p.kind != "scene" ? "-" : std::to_string(p.objects.empty() ? size_t(1) : p.objects.size());
    std::printf("%-6s %-16s %-10s %-7s %s\n", p.kind.c_str(), p.name.c_str(),
                p.suggested_glass.empty() ? "-" : p.suggested_glass.c_str(), objects.c_str(), p.description.c_str());
  }
  // The others are listed; each broken file is named with its error, and the exit says so.
  for (const std::string& e : broken) std::fprintf(stderr, "draught: error: %s\n", e.c_str());
  return broken.empty() ? 0 : 1;
}

namespace {
// A timeline's own scene (its preset and glass) must exist, and the objects its actions
// address must be in it.
void check_timeline_scene(Timeline& t, const std::string& f) {
  for (auto [field, name, kind] : {std::tuple{"preset", t.preset, "drink"}, {"glass", t.glass, "glass"}})
    if (!name.empty()) preset_file(name, kind, f + ": field '" + field + "':");  // the scene it names must exist
  if (t.preset.empty()) return;  // objects are checked against the scene it is played in
  Scene scene;
  try {
    SceneRequest req;
    req.preset = t.preset;
    const Preset preset = load_preset(find_preset(t.preset, "drink"));
    if (!preset.objects.empty() && !t.glass.empty())
      throw InputError("the scene '" + preset.name + "' places its own glasses: leave out the timeline's glass");
    req.glass = t.glass;
    scene = resolve_scene_objects(req);
  } catch (const InputError& e) {
    throw InputError(f + ": field '" + (t.glass.empty() ? "preset" : "glass") + "': " + e.what());
  }
  bind_timeline(t, scene);
}
}  // namespace

int validate(const std::vector<std::string>& files) {
  int bad = 0;
  for (const auto& f : files) {
    try {
      const std::string text = read_text_file(f);
      // Timelines are told apart by their top-level format key, or their actions (a
      // preset may well be named "actions").
      const nlohmann::json top = parse_json_file_text(text, f);
      if (top.is_object() && (top.contains("draught_timeline") || top.contains("actions"))) {
        Timeline t = parse_timeline(text, f);
        check_timeline_scene(t, f);
        std::printf("%s: ok (timeline '%s', %zu actions, %g s)\n", f.c_str(), t.name.c_str(), t.actions.size(),
                    t.duration);
        continue;
      }
      Preset p = parse_preset(text, f);
      if (!p.objects.empty()) {
        const Scene scene = scene_from_preset(p);  // glasses and drinks exist, no two glasses overlap
        size_t values = p.values.size();
        for (auto& o : p.objects) values += o.values.size();
        std::printf("%s: ok (%s '%s', %zu objects, %zu parameters)\n", f.c_str(), p.kind.c_str(), p.name.c_str(),
                    scene.objects.size(), values);
        continue;
      }
      if (!p.suggested_glass.empty())  // what a render would take as its glass must exist
        preset_file(p.suggested_glass, "glass", f + ": field 'suggested_glass':");
      std::printf("%s: ok (%s '%s', %zu parameters)\n", f.c_str(), p.kind.c_str(), p.name.c_str(), p.values.size());
    } catch (const InputError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      ++bad;
    }
  }
  return bad ? 1 : 0;
}

int bake_environment(const std::string& name, int width, const std::string& output) {
  const HdrImage img = draught::bake_environment(name, default_params(), width);
  write_radiance_hdr(output, img);
  std::printf("wrote %s (%d x %d, %s)\n", output.c_str(), img.width, img.height, name.c_str());
  return 0;
}

int print_params(bool markdown) {
  // scope: "scene" parameters belong to the whole scene; "object" ones to each glass
  // (objects[N].path sets one object's, the bare path every object's).
  if (markdown) {
    std::printf("| parameter | type | default | range | unit | scope | description |\n|---|---|---|---|---|---|---|\n");
  } else {
    std::printf("%-24s %-6s %-28s %-18s %-5s %-6s %s\n", "path", "type", "default", "range", "unit", "scope", "doc");
  }
  for (const auto& d : param_table()) {
    std::string range;
    if (d.type == ParamType::Enum) {
      for (auto& c : d.choices) range += (range.empty() ? "" : "|") + c;
    } else if (d.type != ParamType::Bool && d.type != ParamType::File) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "[%g, %g]", double(d.min), double(d.max));
      range = buf;
    }
    std::string def = format_param(d, d.def);
    const std::string scope(scope_name(d.scope));
    if (markdown)
      std::printf("| `%s` | %s | `%s` | %s | %s | %s | %s |\n", d.path.c_str(), std::string(type_name(d.type)).c_str(),
                  def.c_str(), range.c_str(), d.unit.c_str(), d.scope == ParamScope::Scene ? "scene" : "per object",
                  d.doc.c_str());
    else
      std::printf("%-24s %-6s %-28s %-18s %-5s %-6s %s\n", d.path.c_str(), std::string(type_name(d.type)).c_str(),
                  def.size() > 28 ? (def.substr(0, 25) + "...").c_str() : def.c_str(), range.c_str(),
                  d.unit.c_str(), scope.c_str(), d.doc.c_str());
  }
  return 0;
}

}  // namespace draught::cli
