#include "core/environment/environment_files.hpp"

#include "core/io/file_cache.hpp"
#include "core/io/files.hpp"
#include "core/params/shipped_files.hpp"
#include "core/text/echo.hpp"

#include <system_error>

namespace draught {

namespace {

// The few maps last used: a viewer flipping between environments does not reread them,
// and an 8k chain (about 0.5 GB as doubles would be; 400 MB as floats) is not kept forever.
FileCache<const EnvironmentMap> g_maps(3);

}  // namespace

std::filesystem::path resolve_environment(const std::string& name) {
  if (name.empty()) throw InputError("env.image: expected a file or the name of a shipped environment, got \"\"");
  if (is_shipped_name(name)) {
    std::string tried;
    if (auto p = find_shipped("environments", name, {".hdr", ".exr"}, tried)) return *p;
    throw InputError("no shipped environment named '" + shorten(name) + "' (looked for " + tried + ")");
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(name, ec))
    throw InputError(shorten(name, kEchoPathBytes) + ": no such environment file");
  return name;
}

std::shared_ptr<const EnvironmentMap> load_environment(const std::string& name) {
  std::filesystem::path file;
  try {
    file = resolve_environment(name);
  } catch (const InputError&) {
    // A file read before and gone since (deleted while a viewer shows it): the frames go on
    // with what was read; a name never read is an error.
    if (auto kept = g_maps.last_read(name)) return kept;
    throw;
  }
  return g_maps.get(name, file, [](const std::filesystem::path& f) {
    return std::make_shared<const EnvironmentMap>(read_environment_map(f));
  });
}

void check_environment_image(const std::string& name) { load_environment(name); }

}  // namespace draught
