// Shipped files named by a bare word: `env.image studio`, a decal `wordmark`, a screen's
// `draught-loop` are looked up in the preset folders' environments/, decals/ and videos/;
// anything else is a path.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

namespace draught {

// A shipped name is a bare word: not empty, no folder, no extension (and none of `also`).
bool is_shipped_name(const std::string& name, const char* also = "");

// The first of the preset folders' `folder`/`name``ext`, for each ext in turn, that exists:
// a regular file, or a folder where ext is "". Else nullopt, with `tried` listing every
// path looked at (a folder ending in /).
std::optional<std::filesystem::path> find_shipped(const char* folder, const std::string& name,
                                                  std::initializer_list<const char*> exts, std::string& tried);

}  // namespace draught
