// The `draught` CLI's commands. main.cpp only parses flags; each command lives here.
#pragma once

#include "core/params.hpp"

#include <string>
#include <vector>

namespace draught::cli {

// What a render asks for: presets first, then --camera, then --set, later wins.
struct SceneRequest {
  std::string preset = "lager";
  std::string glass;  // empty: the drink's suggested glass, else "pint"
  std::vector<std::string> sets;     // "path=value"
  std::vector<std::string> camera;   // "eye=x,y,z" "target=x,y,z" "vfov=deg"
};

// Loads and validates everything before applying anything; throws InputError.
Params resolve_params(const SceneRequest&, bool verbose);

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
