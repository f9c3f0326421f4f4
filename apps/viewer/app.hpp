// The viewer's loop: events to the input rig and the shortcuts, the panel, the simulation in
// real time, the renderer into the window, the overlay, and the screenshot mode.
#pragma once

#include <string>

namespace draught::viewer {

struct ViewerOptions {
  std::string preset = "lager";
  std::string glass;            // empty: the drink's suggested glass
  int width = 1280, height = 800;
  std::string screenshot;       // non-empty: render `frames` frames, write this PNG, exit
  std::string picture;          // non-empty: after `frames` frames, save the picture (F12) here, exit
  int frames = 30;
  std::string timeline;         // non-empty: play this timeline instead of interactive input
  bool preset_given = false, glass_given = false;  // flags win over the timeline's scene
  bool hide_panel = false;
  int quality = 2;  // 0 low, 1 medium, 2 high, 3 MatCap
};

// Returns the process exit code; throws InputError or std::runtime_error for main to report.
int run_viewer(const ViewerOptions&);

}  // namespace draught::viewer
