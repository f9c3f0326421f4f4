// The `draught` CLI's commands. main.cpp only parses flags; each command lives here.
#pragma once

#include "core/params/preset.hpp"
#include "core/scene/frame.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace draught::cli {

struct RenderRequest {
  SceneRequest scene;
  int width = 512, height = 512;
  std::string output = "out/draught.png";
  std::string debug;  // "", depth, normal, material
  std::string shader_dir;
  bool verbose = false;
  // The reference path tracer (core/reference/path_tracer) instead of the GPU.
  bool reference = false;
  int samples = 64;  // --spp: paths per pixel
  int threads = 0;   // 0: one per hardware thread
  bool progress = false;  // draw the progress bar even when stderr is not a terminal
  bool output_given = false, camera_given = false;  // -o and --camera were on the command line
};

// An animation: a timeline played through the simulation.
struct AnimateRequest {
  std::string timeline;   // a name (presets/timelines/) or a JSON file
  std::string output;     // a folder for PNG frames, or .mp4 / .gif (ffmpeg); empty: out/<name>/
  double fps = 0;         // 0: the timeline's, else 30
  double duration = 0;    // 0: the timeline's
  bool preset_given = false, glass_given = false;  // flags win over the timeline's scene
  bool progress = false;  // draw the progress bar even when stderr is not a terminal
  bool overwrite = false;  // a PNG sequence may replace a folder holding other files
};

int render(const RenderRequest&);
int animate(const RenderRequest&, const AnimateRequest&);
// The timeline's frame at `at` seconds as a still (the picture, a debug view or the
// reference), played as an animation is, frame by frame at its rate, so that it is the
// animation's frame there.
int render_timeline_still(const RenderRequest&, const AnimateRequest&, double at);
// The destination of the still -o names (a .png; a symbolic link followed); throws InputError.
std::filesystem::path still_destination(const RenderRequest&);
// Renders `frame` as RenderRequest asks (the GPU's picture or debug view, or the reference)
// and writes it to `dest` atomically.
int render_still(const RenderRequest&, const FrameState& frame, const std::filesystem::path& dest);
int list_presets();
int validate(const std::vector<std::string>& files);
int print_params(bool markdown);
// Writes environment `name` (studio, bar) as a `width` x width/2 Radiance .hdr.
int bake_environment(const std::string& name, int width, const std::string& output);
// `only`: scene names to run (empty: all).
int bench(int frames, const std::vector<int>& sizes, const std::vector<std::string>& only, bool verbose);

// "512x256" -> 512, 256; throws InputError.
void parse_size(const std::string& text, int& w, int& h);

// Rethrows a render error that comes from the image's size as an InputError naming
// --size and --supersample; any other error as it is. Call from a catch block.
[[noreturn]] void explain_size_error(const std::runtime_error&, const RenderRequest&, int supersample);

// Refuses a camera that looks nowhere (eye == target), naming --camera when it was given.
void check_camera(const SceneParams&, bool camera_given);

}  // namespace draught::cli
