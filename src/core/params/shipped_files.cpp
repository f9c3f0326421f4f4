#include "core/params/shipped_files.hpp"

#include "core/params/preset.hpp"

#include <system_error>

namespace draught {

bool is_shipped_name(const std::string& name, const char* also) {
  return !name.empty() && name.find_first_of(std::string("/\\.") + also) == std::string::npos;
}

std::optional<std::filesystem::path> find_shipped(const char* folder, const std::string& name,
                                                  std::initializer_list<const char*> exts, std::string& tried) {
  tried.clear();
  for (const auto& dir : preset_dirs()) {
    for (const char* ext : exts) {
      const auto p = dir / folder / (name + ext);
      std::error_code ec;
      if (*ext ? std::filesystem::is_regular_file(p, ec) : std::filesystem::is_directory(p, ec)) return p;
      tried += (tried.empty() ? "" : ", ") + p.string() + (*ext ? "" : "/");
    }
  }
  return std::nullopt;
}

}  // namespace draught
