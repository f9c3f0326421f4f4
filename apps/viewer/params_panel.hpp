// The parameter panel, generated from the parameter table: which object it edits (a combo
// when the scene has several), then a collapsing header per group (the path's prefix), the
// selected object's groups (glass, liquid, ...) apart from the scene's (env, light, camera,
// render); a widget per type, the unit in the label and the doc as the tooltip. There is
// no list of parameters here: a new row in param_table() shows up by itself.
#pragma once

#include "core/scene/scene.hpp"

#include <string>

namespace draught::viewer {

struct ParamsPanelState {
  std::string error;  // the last rejected value, shown in red until the next good change
};

// Draws the widgets (inside the current ImGui window) for the selected object of `s` and
// for the scene. Every edit is clamped to the table's range and goes through set_param
// (objects[N].path for the object's rows); returns true when a parameter changed. The
// object combo writes s.selected (not a parameter change: the caller compares).
bool params_panel(Scene& s, ParamsPanelState& state);

}  // namespace draught::viewer
