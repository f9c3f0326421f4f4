// Presets: JSON files that set some parameters of the table. A preset is parsed and
// validated completely before anything is applied, so a bad file never half-applies.
//
//   { "draught_preset": 1, "kind": "drink", "name": "lager",
//     "description": "...", "suggested_glass": "pint",
//     "params": { "liquid": { "srm": 4, "ior": 1.34 } } }
//
// kind "glass" may set only glass.*, "drink" only liquid.*, foam.* and bubbles.*, "scene" anything.
#pragma once

#include "core/params/params.hpp"
#include "core/scene/scene.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace draught {

struct Preset {
  std::string file, kind, name, description, suggested_glass;
  std::vector<std::pair<const ParamDesc*, ParamValue>> values;
};

inline constexpr int kPresetFormat = 1;

Preset parse_preset(const std::string& text, const std::string& file);  // throws InputError
Preset load_preset(const std::filesystem::path&);
void apply_preset(const Preset&, Params&);

// Where named presets are looked up: $DRAUGHT_PRESET_DIR, then the source tree's presets/.
std::vector<std::filesystem::path> preset_dirs();
// A name ("lager") is looked up in the preset directories under <kind>s/; anything with
// a '/' or ending in .json is a path.
std::filesystem::path find_preset(const std::string& name_or_path, const std::string& kind);
std::vector<Preset> list_presets();

// Serialises the given parameter groups ("glass", "liquid", ...; empty = all) of p.
std::string preset_json(const Params& p, const std::string& kind, const std::string& name,
                        const std::string& description, const std::vector<std::string>& groups);
void save_preset(const std::filesystem::path&, const std::string& json_text);  // validates, atomic

// What a render asks for: a glass preset, a drink (or scene) preset, then camera and
// parameter overrides; later wins.
struct SceneRequest {
  std::string preset = "lager";
  std::string glass;                // empty: the drink's suggested glass, else "pint"
  std::vector<std::string> sets;    // "path=value", as --set
  std::vector<std::string> camera;  // "eye=x,y,z" "target=x,y,z" "vfov=deg", as --camera
};

// Loads and validates everything before applying anything; throws InputError whose
// message names the file or flag, the field and what was expected. `log` (optional)
// receives which files were used.
Params resolve_scene(const SceneRequest&, std::string* log = nullptr);
// The same request as a scene of objects: a scene preset with "objects" places several
// glasses; any other preset gives a scene of one glass. --set paths may address one
// object (`objects[2].liquid.fill=0.5`); a vessel path without a prefix sets every object.
Scene resolve_scene_objects(const SceneRequest&, std::string* log = nullptr);

}  // namespace draught
