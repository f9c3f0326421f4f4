// Which file a decal's `file` names and the images read from them, kept while they are in
// use: a shipped name ("wordmark", "crest") is looked up in the preset folders' decals/
// (NAME.png), anything else is a path. The parameter table asks here before it takes a
// new value (check_decal_image), so a file that cannot be used (missing, not a PNG, too
// large, without pixels, damaged or cut short) is refused where it was given (a preset, a
// --set, a panel, the web page) and the scene keeps what it had; the renderer and the
// reference then find the image here already read.
#pragma once

#include "core/io/image.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace draught {

// The shipped decals' names (presets/decals/*.png), sorted.
std::vector<std::string> shipped_decal_names();

// The file `name` stands for; throws InputError for an unknown shipped name (with the
// nearest one) or a path that is no file.
std::filesystem::path resolve_decal(const std::string& name);

// The image of `name` (8-bit sRGB RGBA, alpha not premultiplied), read once and kept (a
// file changed since is read again). Throws InputError naming the file and what was
// expected.
std::shared_ptr<const Image> load_decal(const std::string& name);

// load_decal, for the parameter table's check of decal_*.file; "" (no decal) is fine.
void check_decal_image(const std::string& name);

}  // namespace draught
