#include "names.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/text/echo.hpp"
#include "core/text/suggest.hpp"

#include <algorithm>
#include <vector>

namespace draught::cli {

namespace fs = std::filesystem;

namespace {

bool is_path(const std::string& name) { return name.find('/') != std::string::npos || name.ends_with(".json"); }

// The names of the .json files in `sub` of every preset folder.
std::vector<std::string> names_in(std::initializer_list<const char*> subs) {
  std::vector<std::string> names;
  for (auto& dir : preset_dirs())
    for (const char* sub : subs) {
      std::error_code ec;
      for (auto& e : fs::directory_iterator(dir / sub, ec))
        if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
    }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

// "dir/drinks/NAME.json, dir/scenes/NAME.json" for each preset folder.
std::string looked_for(const std::string& name, std::initializer_list<const char*> subs) {
  std::string s;
  for (auto& dir : preset_dirs())
    for (const char* sub : subs) s += (s.empty() ? "" : ", ") + (dir / sub / (shorten(name) + ".json")).string();
  return s;
}

}  // namespace

fs::path preset_file(const std::string& name, const std::string& kind, const std::string& what) {
  try {
    return find_preset(name, kind);
  } catch (const InputError& e) {
    if (is_path(name)) throw InputError(what + " " + e.what());
    const char* sub = kind == "glass" ? "glasses" : "drinks";
    throw InputError(what + " " + shorten(name) + ": no " + kind + " preset named " + quote_input(name) +
                     did_you_mean(name, names_in({sub, "scenes"})) + " (looked for " +
                     looked_for(name, {sub, "scenes"}) + "); `draught presets` lists them");
  }
}

fs::path timeline_file(const std::string& name) {
  if (is_path(name)) {
    std::error_code ec;
    if (!fs::exists(name, ec))
      throw InputError("--timeline " + shorten(name, kEchoPathBytes) + ": no such timeline file");
    return name;
  }
  for (auto& dir : preset_dirs()) {
    std::error_code ec;
    const fs::path p = dir / "timelines" / (name + ".json");
    if (fs::exists(p, ec)) return p;
  }
  throw InputError("--timeline " + shorten(name) + ": no timeline named " + quote_input(name) +
                   did_you_mean(name, names_in({"timelines"})) + " (looked for " + looked_for(name, {"timelines"}) +
                   ")");
}

}  // namespace draught::cli
