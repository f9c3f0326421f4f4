// The preset part of the panel: the shipped presets in two combos (drinks and scenes,
// glasses), a file to load or save, undo, and what the last action said.
#pragma once

#include "editor.hpp"

#include "core/params/preset.hpp"

#include <string>
#include <vector>

namespace draught::viewer {

struct PresetPanelState {
  std::vector<Preset> drinks, glasses;  // drinks holds scenes too: both go in --preset
  std::string list_error;               // a shipped preset that does not load
  char path[512] = "my-drink.json";
  int save_kind = 0;                    // index into the kinds: scene, drink, glass
};

// Reads the preset directories once (list_presets()).
PresetPanelState make_preset_panel_state();
void preset_panel(Editor&, PresetPanelState&);

}  // namespace draught::viewer
