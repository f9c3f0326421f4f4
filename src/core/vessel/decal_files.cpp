#include "core/vessel/decal_files.hpp"

#include "core/io/file_cache.hpp"
#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/params/shipped_files.hpp"
#include "core/text/echo.hpp"
#include "core/text/suggest.hpp"

#include <algorithm>
#include <set>
#include <system_error>

namespace draught {

namespace {

// The images last used: a scene's few decals and a viewer flipping between some (a
// 4096 x 4096 image is 64 MiB, so not every one ever read is kept).
FileCache<const Image> g_images(8);

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
    if (auto p = find_shipped("decals", name, {".png"}, tried)) return *p;
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
  // read_whole_file refuses folders, FIFOs, devices and files over the limit before reading.
  return g_images.get(name, file, [](const std::filesystem::path& f) {
    return std::make_shared<const Image>(
        decode_png(read_whole_file(f, kMaxPngFileBytes, "a PNG image"), shorten(f.string(), kEchoPathBytes)));
  });
}

void check_decal_image(const std::string& name) {
  if (!name.empty()) load_decal(name);
}

}  // namespace draught
