// Preset and timeline names given on the command line (or in a timeline) resolved to
// files, with "did you mean" for a typo: `--preset lagr` -> "(did you mean 'lager'?)".
#pragma once

#include <filesystem>
#include <string>

namespace draught::cli {

// The file of a preset name or path (as find_preset), for `what` ("--preset", or
// "TIMELINE: field 'preset'"); kind is "drink" or "glass". Throws InputError.
std::filesystem::path preset_file(const std::string& name, const std::string& kind, const std::string& what);

// The file of a timeline name or path (as load_timeline finds it). Throws InputError.
std::filesystem::path timeline_file(const std::string& name);

}  // namespace draught::cli
