#include "commands.hpp"

#include "core/files.hpp"
#include "core/frame.hpp"
#include "core/preset.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

namespace draught::cli {

namespace {

std::pair<const ParamDesc*, ParamValue> parse_assignment(const std::string& flag, const std::string& text) {
  auto eq = text.find('=');
  if (eq == std::string::npos)
    throw InputError(flag + " " + text + ": expected path=value, e.g. " + flag + " liquid.fill=0.8");
  const std::string path = text.substr(0, eq);
  const ParamDesc* d = find_param(path);
  if (!d) throw InputError(flag + " " + text + ": " + unknown_param_message(path));
  try {
    return {d, parse_param_text(*d, text.substr(eq + 1))};
  } catch (const ParamError& e) {
    throw InputError(flag + " " + text + ": field '" + e.field + "': expected " + e.expected);
  }
}

}  // namespace

void parse_size(const std::string& text, int& w, int& h) {
  char x;
  if (std::sscanf(text.c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 1 || h < 1 || w > 8192 ||
      h > 8192)
    throw InputError("--size " + text + ": expected WIDTHxHEIGHT, each from 1 to 8192, e.g. 512x512");
}

Params resolve_params(const SceneRequest& req, bool verbose) {
  const Preset drink = load_preset(find_preset(req.preset, "drink"));
  std::string glass_name = !req.glass.empty() ? req.glass
                           : !drink.suggested_glass.empty() ? drink.suggested_glass
                                                            : "pint";
  const bool scene_sets_glass = drink.kind == "scene" && req.glass.empty() && drink.suggested_glass.empty();
  Preset glass;
  if (!scene_sets_glass) glass = load_preset(find_preset(glass_name, "glass"));
  std::vector<std::pair<const ParamDesc*, ParamValue>> overrides;
  for (const auto& c : req.camera) {
    auto eq = c.find('=');
    const std::string key = c.substr(0, eq);
    if (eq == std::string::npos || (key != "eye" && key != "target" && key != "vfov"))
      throw InputError("--camera " + c + ": expected eye=x,y,z, target=x,y,z or vfov=degrees");
    overrides.push_back(parse_assignment("--camera", "camera." + c));
    if (key != "vfov") overrides.push_back(parse_assignment("--camera", "camera.auto_frame=false"));
  }
  for (const auto& s : req.sets) overrides.push_back(parse_assignment("--set", s));
  // Everything is valid: now apply, in order.
  Params p = default_params();
  if (!scene_sets_glass) apply_preset(glass, p);
  apply_preset(drink, p);
  for (auto& [d, v] : overrides) set_param(p, *d, v);
  if (verbose)
    std::fprintf(stderr, "preset: %s (%s)%s%s\n", drink.name.c_str(), drink.file.c_str(),
                 scene_sets_glass ? "" : ", glass: ", scene_sets_glass ? "" : glass.file.c_str());
  return p;
}

int render(const RenderRequest& req) {
  std::filesystem::path out(req.output);
  if (out.extension() != ".png") throw InputError("-o " + req.output + ": expected a file name ending in .png");
  gpu::DebugView view = gpu::DebugView::None;
  if (req.debug == "depth") view = gpu::DebugView::Depth;
  else if (req.debug == "normal") view = gpu::DebugView::Normal;
  else if (req.debug == "material") view = gpu::DebugView::Material;
  else if (!req.debug.empty()) throw InputError("--debug " + req.debug + ": expected depth, normal or material");

  const Params params = resolve_params(req.scene, req.verbose);
  const FrameState frame = make_frame(params);
  auto ctx = gpu::HeadlessContext::create();
  if (req.verbose) std::fprintf(stderr, "renderer: %s (%s)\n", ctx->renderer().c_str(), ctx->platform().c_str());
  gpu::Renderer renderer(req.shader_dir);
  auto t0 = std::chrono::steady_clock::now();
  Image img = view == gpu::DebugView::None
                  ? renderer.render(frame, req.width, req.height)
                  : gpu::visualize_debug(renderer.render_debug(frame, req.width, req.height, view), view);
  auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  write_png(out, img);
  if (req.verbose)
    std::fprintf(stderr, "rendered %dx%d (supersample %d) in %.1f ms\n", req.width, req.height,
                 view == gpu::DebugView::None ? params.render.supersample : 1, ms);
  std::printf("wrote %s\n", out.string().c_str());
  return 0;
}

int list_presets() {
  std::printf("%-6s %-16s %-10s %s\n", "kind", "name", "glass", "description");
  for (const Preset& p : draught::list_presets())
    std::printf("%-6s %-16s %-10s %s\n", p.kind.c_str(), p.name.c_str(),
                p.suggested_glass.empty() ? "-" : p.suggested_glass.c_str(), p.description.c_str());
  return 0;
}

int validate(const std::vector<std::string>& files) {
  int bad = 0;
  for (const auto& f : files) {
    try {
      Preset p = load_preset(f);
      std::printf("%s: ok (%s '%s', %zu parameters)\n", f.c_str(), p.kind.c_str(), p.name.c_str(), p.values.size());
    } catch (const InputError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      ++bad;
    }
  }
  return bad ? 1 : 0;
}

int print_params(bool markdown) {
  if (markdown) {
    std::printf("| parameter | type | default | range | unit | description |\n|---|---|---|---|---|---|\n");
  } else {
    std::printf("%-24s %-6s %-28s %-18s %-5s %s\n", "path", "type", "default", "range", "unit", "doc");
  }
  for (const auto& d : param_table()) {
    std::string range;
    if (d.type == ParamType::Enum) {
      for (auto& c : d.choices) range += (range.empty() ? "" : "|") + c;
    } else if (d.type != ParamType::Bool) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "[%g, %g]", double(d.min), double(d.max));
      range = buf;
    }
    std::string def = format_param(d, d.def);
    if (markdown)
      std::printf("| `%s` | %s | `%s` | %s | %s | %s |\n", d.path.c_str(), std::string(type_name(d.type)).c_str(),
                  def.c_str(), range.c_str(), d.unit.c_str(), d.doc.c_str());
    else
      std::printf("%-24s %-6s %-28s %-18s %-5s %s\n", d.path.c_str(), std::string(type_name(d.type)).c_str(),
                  def.size() > 28 ? (def.substr(0, 25) + "...").c_str() : def.c_str(), range.c_str(),
                  d.unit.c_str(), d.doc.c_str());
  }
  return 0;
}

}  // namespace draught::cli
