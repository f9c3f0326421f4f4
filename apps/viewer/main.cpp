// draught-viewer: the drink in a desktop window, with a parameter panel and live input.
#include "app.hpp"

#include "core/io/files.hpp"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

namespace {

// "WIDTHxHEIGHT", each 16..8192.
void parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0, end = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &w, &h, &end) != 2 || end != int(text.size()) || w < 16 || h < 16 ||
      w > 8192 || h > 8192)
    throw draught::InputError("--size " + text + ": expected WIDTHxHEIGHT, each from 16 to 8192, e.g. 1280x800");
  width = w;
  height = h;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"draught-viewer: raymarched drinks in glassware in a window (SDL2, OpenGL ES 3.0, Dear ImGui)"};
  app.set_version_flag("--version", std::string("draught-viewer ") + DRAUGHT_VERSION);
  draught::viewer::ViewerOptions o;
  std::string size = "1280x800";
  app.add_option("-p,--preset", o.preset, "Drink or scene preset: a name or a JSON file")->capture_default_str();
  app.add_option("-g,--glass", o.glass, "Glass preset: a name or a JSON file (default: the drink's)");
  app.add_option("-s,--size", size, "Window size WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--screenshot", o.screenshot,
                 "Render --frames frames (1/30 s apart), write the window as this PNG and exit");
  app.add_option("--picture", o.picture,
                 "Render --frames frames (1/30 s apart), save the picture as F12 does (the scene alone, drawn as "
                 "the CLI draws a still) as this PNG and exit");
  app.add_option("--frames", o.frames, "Frames to render before the screenshot or the picture")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  app.add_option("-t,--timeline", o.timeline, "Play this timeline (a name or a JSON file) in a loop instead of "
                                              "interactive input");
  app.add_flag("--hide-panel", o.hide_panel, "Start with the panel hidden (F1 shows it)");
  app.add_option("--quality", o.quality,
                 "Quality tier: 0 low (50 % resolution), 1 medium (75 %), 2 high, 3 the MatCap tier (docs/MATCAP.md)")
      ->check(CLI::Range(0, 3));
  CLI11_PARSE(app, argc, argv);
  try {
    parse_size(size, o.width, o.height);
    // Checked before a window opens: the screenshot and the picture are PNG data, so their
    // names say so.
    for (const auto& [flag, file] : {std::pair{"--screenshot", o.screenshot}, std::pair{"--picture", o.picture}}) {
      if (file.empty()) continue;
      std::string ext = std::filesystem::path(file).extension().string();
      for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (ext != ".png") throw std::runtime_error(std::string(flag) + " " + file + ": expected a file name ending in .png");
    }
    o.preset_given = app.get_option("--preset")->count() > 0;
    o.glass_given = app.get_option("--glass")->count() > 0;
    return draught::viewer::run_viewer(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "draught-viewer: error: %s\n", e.what());
    return 1;
  }
}
