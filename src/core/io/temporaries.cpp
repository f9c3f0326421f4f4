#include "core/io/temporaries.hpp"

#include <atomic>
#include <charconv>
#include <cstdio>
#include <random>
#include <string>
#include <unistd.h>

namespace draught {

namespace {

constexpr std::string_view kPrefix = ".draught-tmp-";
TemporaryObserver g_observer;

// s as a positive number, if it is all digits and fits.
std::optional<long> digits(std::string_view s) {
  long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v <= 0) return std::nullopt;
  return v;
}

}  // namespace

std::filesystem::path temporary_path_beside(const std::filesystem::path& target) {
  // The token tells apart runs that happen to get the same PID (e.g. one killed, then a
  // new one in a fresh container).
  static const unsigned token = std::random_device{}() & 0xFFFFFFu;
  static std::atomic<unsigned> counter{0};
  char name[64];
  std::snprintf(name, sizeof name, "%.*s%ld-%u-%06x", int(kPrefix.size()), kPrefix.data(), long(::getpid()), counter++,
                token);
  return target.parent_path() / name;
}

std::optional<long> temporary_owner(std::string_view name) {
  if (name.starts_with(kPrefix)) {
    name.remove_prefix(kPrefix.size());
    return digits(name.substr(0, name.find('-')));
  }
  // NAME.png.tmp-PID or NAME.json.tmp-PID, as written before this scheme; only those, so
  // a user's "notes.tmp-2024" is never taken for one.
  const auto legacy = name.rfind(".tmp-");
  if (legacy == std::string_view::npos) return std::nullopt;
  const std::string_view stem = name.substr(0, legacy);
  if (!(stem.size() > 4 && stem.ends_with(".png")) && !(stem.size() > 5 && stem.ends_with(".json")))
    return std::nullopt;
  return digits(name.substr(legacy + 5));
}

void set_temporary_observer(TemporaryObserver o) { g_observer = o; }
void temporary_created(const std::filesystem::path& p, bool is_folder) {
  if (g_observer.created) g_observer.created(p, is_folder);
}
void temporary_gone(const std::filesystem::path& p) {
  if (g_observer.gone) g_observer.gone(p);
}

}  // namespace draught
