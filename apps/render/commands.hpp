// The `draught` CLI's commands. main.cpp only parses flags; each command lives here.
#pragma once

#include "core/preset.hpp"

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
};

int render(const RenderRequest&);
int list_presets();
int validate(const std::vector<std::string>& files);
int print_params(bool markdown);
int bench(int frames, const std::vector<int>& sizes, bool verbose);

// "512x256" -> 512, 256; throws InputError.
void parse_size(const std::string& text, int& w, int& h);

}  // namespace draught::cli
