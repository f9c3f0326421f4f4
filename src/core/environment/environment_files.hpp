// Which file `env.image` names and the environment maps read from them, kept while they
// are in use: a shipped name ("studio", "bar") is looked up in the preset folders'
// environments/, anything else is a path. The parameter table asks here before it takes
// a new value, so a file that cannot be read is refused where it was given (a preset, a
// --set, a panel) and the scene keeps what it had; the renderer then finds the map here
// already read.
#pragma once

#include "core/environment/environment_map.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace draught {

// The file `name` stands for; throws InputError for an unknown shipped name or a path
// that is no file.
std::filesystem::path resolve_environment(const std::string& name);

// The map of `name`, read once and kept (a file changed since is read again; one deleted
// since gives what was read). Throws InputError naming the file and what was expected.
std::shared_ptr<const EnvironmentMap> load_environment(const std::string& name);

// load_environment, for the parameter table's check of env.image.
void check_environment_image(const std::string& name);

}  // namespace draught
