// The few values last read from files (environment maps, decal images, videos), kept while
// they are in use: keyed by the file, its modification time and its size, so a file
// changed since is read again; most recently used first, the least recently used dropped
// past `keep`. The value last read under a name stays reachable when its file is deleted
// (a viewer showing it goes on with what was read).
#pragma once

#include <cstdint>
#include <filesystem>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <system_error>

namespace draught {

template <class T>
class FileCache {
 public:
  explicit FileCache(size_t keep) : keep_(keep) {}

  // The value of `file` (named `name` by its user), read by `read(file)` when not kept.
  // The read happens outside the lock: a big file takes a while, and another thread may
  // want another one.
  template <class Read>
  std::shared_ptr<T> get(const std::string& name, const std::filesystem::path& file, Read&& read) {
    std::error_code ec;
    const auto written = std::filesystem::last_write_time(file, ec);
    const auto bytes = std::filesystem::is_regular_file(file, ec) ? std::filesystem::file_size(file, ec) : 0;
    {
      std::lock_guard lock(mutex_);
      for (auto it = kept_.begin(); it != kept_.end(); ++it) {
        if (it->file == file && it->written == written && it->bytes == bytes) {
          kept_.splice(kept_.begin(), kept_, it);
          return kept_.front().value;
        }
      }
    }
    std::shared_ptr<T> value = read(file);
    std::lock_guard lock(mutex_);
    kept_.push_front({name, file, written, bytes, value});
    if (kept_.size() > keep_) kept_.pop_back();
    return value;
  }

  // The value last read under `name`, or null.
  std::shared_ptr<T> last_read(const std::string& name) {
    std::lock_guard lock(mutex_);
    for (const Entry& e : kept_)
      if (e.name == name) return e.value;
    return nullptr;
  }

 private:
  struct Entry {
    std::string name;  // as given
    std::filesystem::path file;
    std::filesystem::file_time_type written;
    std::uintmax_t bytes = 0;
    std::shared_ptr<T> value;
  };
  size_t keep_;
  std::mutex mutex_;
  std::list<Entry> kept_;
};

}  // namespace draught
