#include "core/vessel/decal_files.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/text/echo.hpp"
#include "core/text/suggest.hpp"

#include <algorithm>
#include <list>
#include <mutex>
#include <set>
#include <system_error>

namespace draught {

namespace {

// A shipped name is a bare word: no folder, no extension.
bool is_shipped_name(const std::string& name) {
  return !name.empty() && name.find_first_of("/\\.") == std::string::npos;
}

struct Entry {
  std::filesystem::path file;
  std::filesystem::file_time_type written;
  std::uintmax_t bytes = 0;
  std::shared_ptr<const Image> image;
};

// The images last used: a scene's few decals and a viewer flipping between some (a
// 4096 x 4096 image is 64 MiB, so not every one ever read is kept).
constexpr size_t kKeptImages = 8;

std::mutex g_mutex;
std::list<Entry> g_kept;  // most recently used first

}  // namespace

std::vector<std::string> shipped_decal_names() {
  std::set<std::string> names;
  for (const auto& dir : preset_dirs()) {
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir / "decals", ec))
      if (e.path().extension() == ".png") names.insert(e.path().stem().string());
  }
  return {names.begin(), names.end()};
}

std::filesystem::path resolve_decal(const std::string& name) {
  if (name.empty()) throw InputError("expected a PNG file or the name of a shipped decal, got \"\"");
  if (is_shipped_name(name)) {
    std::string tried;
    for (const auto& dir : preset_dirs()) {
      const auto p = dir / "decals" / (name + ".png");
      std::error_code ec;
      if (std::filesystem::is_regular_file(p, ec)) return p;
      tried += (tried.empty() ? "" : ", ") + p.string();
    }
    const std::vector<std::string> shipped = shipped_decal_names();
    std::string list;
    for (const std::string& s : shipped) list += (list.empty() ? "" : ", ") + s;
    if (name.size() > kEchoBytes) tried = "the preset folders' decals/";
    throw InputError("no shipped decal named '" + shorten(name) + "'" + did_you_mean(name, shipped) + " (looked for " +
                     tried + "); expected a PNG file's path or one of: " + (list.empty() ? "(none)" : list));
  }
  std::error_code ec;
  if (!std::filesystem::exists(name, ec))
    throw InputError(shorten(name, kEchoPathBytes) + ": no such file (expected a PNG image for a decal)");
  return name;
}

std::shared_ptr<const Image> load_decal(const std::string& name) {
  const std::filesystem::path file = resolve_decal(name);
  std::error_code ec;
  const auto written = std::filesystem::last_write_time(file, ec);
  const auto bytes = std::filesystem::file_size(file, ec);
  {
    std::lock_guard lock(g_mutex);
    for (auto it = g_kept.begin(); it != g_kept.end(); ++it) {
      if (it->file == file && it->written == written && it->bytes == bytes) {
        g_kept.splice(g_kept.begin(), g_kept, it);
        return g_kept.front().image;
      }
    }
  }
  // Read and decoded outside the lock (read_whole_file refuses folders, FIFOs, devices and
  // files over the limit before reading).
  const std::string name_in_errors = shorten(file.string(), kEchoPathBytes);
  auto image = std::make_shared<const Image>(
      decode_png(read_whole_file(file, kMaxPngFileBytes, "a PNG image"), name_in_errors));
  std::lock_guard lock(g_mutex);
  g_kept.push_front({file, written, bytes, image});
  if (g_kept.size() > kKeptImages) g_kept.pop_back();
  return image;
}

void check_decal_image(const std::string& name) {
  if (!name.empty()) load_decal(name);
}

}  // namespace draught
