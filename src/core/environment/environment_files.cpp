#include "core/environment/environment_files.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/text/echo.hpp"

#include <list>
#include <mutex>
#include <system_error>

namespace draught {

namespace {

// A shipped name is a bare word: no folder, no extension.
bool is_shipped_name(const std::string& name) {
  return !name.empty() && name.find_first_of("/\\.") == std::string::npos;
}

struct Entry {
  std::string name;  // as given
  std::filesystem::path file;
  std::filesystem::file_time_type written;
  std::uintmax_t bytes = 0;
  std::shared_ptr<const EnvironmentMap> map;
};

// The few maps last used: a viewer flipping between environments does not reread them,
// and an 8k chain (about 0.5 GB as doubles would be; 400 MB as floats) is not kept forever.
constexpr size_t kKeptMaps = 3;

std::mutex g_mutex;
std::list<Entry> g_kept;  // most recently used first

}  // namespace

std::filesystem::path resolve_environment(const std::string& name) {
  if (name.empty()) throw InputError("env.image: expected a file or the name of a shipped environment, got \"\"");
  if (is_shipped_name(name)) {
    std::string tried;
    for (const auto& dir : preset_dirs()) {
      for (const char* ext : {".hdr", ".exr"}) {
        const auto p = dir / "environments" / (name + ext);
        std::error_code ec;
        if (std::filesystem::is_regular_file(p, ec)) return p;
        tried += (tried.empty() ? "" : ", ") + p.string();
      }
    }
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
    std::lock_guard lock(g_mutex);
    for (const Entry& e : g_kept)
      if (e.name == name) return e.map;
    throw;
  }
  std::error_code ec;
  const auto written = std::filesystem::last_write_time(file, ec);
  const auto bytes = std::filesystem::file_size(file, ec);
  {
    std::lock_guard lock(g_mutex);
    for (auto it = g_kept.begin(); it != g_kept.end(); ++it) {
      if (it->file == file && it->written == written && it->bytes == bytes) {
        g_kept.splice(g_kept.begin(), g_kept, it);
        return g_kept.front().map;
      }
    }
  }
  // Read outside the lock: a big file takes a while, and another thread may want another.
  auto map = std::make_shared<const EnvironmentMap>(read_environment_map(file));
  std::lock_guard lock(g_mutex);
  g_kept.push_front({name, file, written, bytes, map});
  if (g_kept.size() > kKeptMaps) g_kept.pop_back();
  return map;
}

void check_environment_image(const std::string& name) { load_environment(name); }

}  // namespace draught
