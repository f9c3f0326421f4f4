// The parameter panel, generated from the parameter table: a collapsing header per group
// (the path's prefix), a widget per type, the unit in the label and the doc as the tooltip.
// There is no list of parameters here: a new row in param_table() shows up by itself.
#pragma once

#include "core/params/params.hpp"

#include <string>

namespace draught::viewer {

struct ParamsPanelState {
  std::string error;  // the last rejected value, shown in red until the next good change
};

// Draws the widgets (inside the current ImGui window) for `p`. Every edit is clamped to the
// table's range and goes through set_param; returns true when `p` changed.
bool params_panel(Params& p, ParamsPanelState& state);

}  // namespace draught::viewer
