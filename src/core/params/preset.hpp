// Presets: JSON files that set some parameters of the table. A preset is parsed and
// validated completely before anything is applied, so a bad file never half-applies.
//
//   { "draught_preset": 1, "kind": "drink", "name": "lager",
//     "description": "...", "suggested_glass": "pint",
//     "params": { "liquid": { "srm": 4, "ior": 1.34 } } }
//
// kind "glass" may set only glass.*, "drink" only liquid.*, foam.* and bubbles.*, "scene" anything.
//
// A scene may instead place several objects, each a glass with its drink; its own
// `params` then hold only the scene's groups (env, light, camera, render), and each
// object's `params` only vessel groups (glass, liquid, foam, bubbles, clip):
//
//   { "draught_preset": 1, "kind": "scene", "name": "flight",
//     "params": { "camera": { "vfov": 24 } },
//     "objects": [ { "name": "pilsner", "glass": "pilsner", "drink": "pilsner",
//                    "position": [-0.17, 0, 0], "yaw": 0,
//                    "params": { "liquid": { "fill": 0.8 } } }, ... ] }
//
// An object's glass and drink are preset names (or paths relative to the scene file);
// without a glass it takes its drink's suggested glass, else "pint"; without a drink, the
// table's defaults. Each object is: defaults, its glass, its drink, its params.
#pragma once

#include "core/droplets/droplets.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/params/params.hpp"
#include "core/scene/scene.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace draught {

using PresetValues = std::vector<std::pair<const ParamDesc*, ParamValue>>;

// One object of a scene preset: a glass with its drink, standing on the floor.
struct PresetObject {
  std::string name;         // unique within the scene
  std::string glass, drink;  // preset names or paths (relative to the scene file); may be empty
  Placement placement;
  PresetValues values;  // vessel parameters, applied after the glass and the drink
  // "kind": "droplets": a trail of droplets (core/droplets) with these parameters; no
  // glass, drink or params then.
  std::optional<DropletParams> droplets;
  // "kind": "pointcloud": a cloud of metaballs (core/pointcloud) with these parameters.
  std::optional<PointCloudParams> cloud;
};

struct Preset {
  std::string file, kind, name, description, suggested_glass;
  PresetValues values;
  std::vector<PresetObject> objects;  // kind "scene" only; empty: a single-glass preset
};

inline constexpr int kPresetFormat = 1;

// Checks everything inside the file (types, ranges, which groups each part may set, and
// for objects: names unique and present, at most kMaxSceneObjects, positions); throws
// InputError "FILE: field 'objects[2].params.env.floor': ...".
Preset parse_preset(const std::string& text, const std::string& file);
Preset load_preset(const std::filesystem::path&);
// Applies the preset's own values (for a scene with objects: the scene's groups only).
void apply_preset(const Preset&, Params&);
// The scene a preset with objects describes (`preset.objects` not empty): each object's
// glass and drink presets are found and loaded (names must exist and be of their kind:
// "FILE: field 'objects[2].drink': expected one of ..., got "stuot" (did you mean
// "stout"?)"), and no two glasses may overlap on the floor. Nothing is returned unless
// all of it is valid; `log` (optional) receives the files used.
Scene scene_from_preset(const Preset&, std::string* log = nullptr);
// Throws InputError "WHERE: objects[1] 'amber-ale' and objects[2] 'stout' overlap: ..."
// when two vessels' footprints (their widest radius around their foot) overlap.
void check_footprints(const Scene&, const std::string& where);
// The names of the presets of a kind ("glass", "drink", "scene") in the preset
// directories, sorted.
std::vector<std::string> preset_names(const std::string& kind);

// Where named presets are looked up: $DRAUGHT_PRESET_DIR, then the source tree's presets/.
std::vector<std::filesystem::path> preset_dirs();
// A name ("lager") is looked up in the preset directories under <kind>s/; anything with
// a '/' or ending in .json is a path.
std::filesystem::path find_preset(const std::string& name_or_path, const std::string& kind);
// Every preset in the first preset directory that has any. A file that does not load is
// left out of the list and its error appended to `broken` (when given), so one bad file
// does not hide the others.
std::vector<Preset> list_presets(std::vector<std::string>* broken = nullptr);

// Serialises the given parameter groups ("glass", "liquid", ...; empty = all) of p.
std::string preset_json(const Params& p, const std::string& kind, const std::string& name,
                        const std::string& description, const std::vector<std::string>& groups);
// A scene preset of the whole scene: its own groups and every object with its placement
// and all its vessel values (a scene of one glass is written as a single-glass scene
// preset, as before). Loads back into the same scene.
std::string scene_preset_json(const Scene&, const std::string& name, const std::string& description);
void save_preset(const std::filesystem::path&, const std::string& json_text);  // validates, atomic

// What a render asks for: a glass preset, a drink (or scene) preset, then camera and
// parameter overrides; later wins. `glass` must be empty for a scene that places its own
// objects (an InputError says so: change one glass with --set objects[N].glass.*).
struct SceneRequest {
  std::string preset = "lager";
  std::string glass;                // empty: the drink's suggested glass, else "pint"
  std::vector<std::string> sets;    // "path=value", as --set
  std::vector<std::string> camera;  // "eye=x,y,z" "target=x,y,z" "vfov=deg", as --camera
};

// Loads and validates everything before applying anything; throws InputError whose
// message names the file or flag, the field and what was expected. `log` (optional)
// receives which files were used. --set and --camera paths may address one object
// (`objects[2].liquid.fill=0.5`, checked against the scene's objects); a vessel path
// without the prefix sets every object.
Scene resolve_scene_objects(const SceneRequest&, std::string* log = nullptr);
// The document of the request's first object in its scene (for a single-glass preset,
// the one glass): what single-glass callers (the viewer, the web page) edit.
Params resolve_scene(const SceneRequest&, std::string* log = nullptr);

}  // namespace draught
