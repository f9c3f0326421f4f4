#include "cleanup.hpp"

#include "core/io/temporaries.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>

namespace draught::cli {

namespace {

// The signal handler may only use async-signal-safe calls: no allocation, no locks, no
// stdio. So temporaries live in a fixed table of plain character arrays; a slot is
// filled completely before it is marked in use.
enum SlotState : int { Free = 0, Busy = 1, File = 2, Folder = 3 };
struct Slot {
  std::atomic<int> state{Free};
  char path[PATH_MAX];
};
Slot g_slots[64];
std::atomic<pid_t> g_child{0};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free);

void on_created(const std::filesystem::path& p, bool folder) {
  const std::string& s = p.native();
  if (s.size() >= PATH_MAX) return;  // cannot exist anyway
  for (Slot& slot : g_slots) {
    int expected = Free;
    if (!slot.state.compare_exchange_strong(expected, Busy)) continue;
    std::memcpy(slot.path, s.c_str(), s.size() + 1);
    slot.state.store(folder ? Folder : File, std::memory_order_release);
    return;
  }
  // More than 64 at once never happens (the CLI holds at most four); such a temporary
  // is then only swept by a later run.
}

void on_gone(const std::filesystem::path& p) {
  for (Slot& slot : g_slots) {
    const int s = slot.state.load(std::memory_order_acquire);
    if ((s == File || s == Folder) && p.native() == slot.path) {
      slot.state.store(Free, std::memory_order_release);
      return;
    }
  }
}

// Removes a folder of plain files: getdents64, unlinkat and rmdir are system calls, safe
// in a handler (opendir/readdir allocate). Passes repeat because removing entries while
// reading a directory may skip some.
void remove_folder(const char* path) {
  for (int pass = 0; pass < 16; ++pass) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) break;
    bool removed = false;
    alignas(8) char buf[8192];
    for (;;) {
      const ssize_t n = ::getdents64(fd, buf, sizeof buf);
      if (n <= 0) break;
      for (ssize_t at = 0; at < n;) {
        const auto* e = reinterpret_cast<const dirent64*>(buf + at);
        at += e->d_reclen;
        if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
        removed |= ::unlinkat(fd, e->d_name, 0) == 0;
      }
    }
    ::close(fd);
    if (!removed) break;
  }
  ::rmdir(path);
}

void on_signal(int sig) {
  const int saved = errno;
  if (const pid_t child = g_child.exchange(0); child > 0) {
    ::kill(child, SIGKILL);  // before removing its output, so it cannot write it again
    ::waitpid(child, nullptr, 0);
  }
  for (Slot& slot : g_slots) {
    const int s = slot.state.load(std::memory_order_acquire);
    if (s == File)
      ::unlink(slot.path);
    else if (s == Folder)
      remove_folder(slot.path);
  }
  errno = saved;
  // Die of the signal (exit status 128 + sig, as the shell expects): the raised signal
  // is blocked while we are in the handler and delivered as we return.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void install_cleanup_on_signals() {
  set_temporary_observer({on_created, on_gone});
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, s);  // one cleanup at a time
  for (int s : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    sigaction(s, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. started with nohup: keep ignoring it
    sigaction(s, &sa, nullptr);
  }
}

void set_child_process(pid_t pid) { g_child.store(pid); }

int sweep_stale_temporaries(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  int removed = 0;
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder.empty() ? fs::path(".") : folder, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const auto owner = temporary_owner(it->path().filename().native());
    if (!owner || *owner == long(::getpid())) continue;
    // ESRCH: no such process. EPERM means it is alive (another user's): leave it.
    if (::kill(pid_t(*owner), 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    if (fs::remove_all(it->path(), rm) > 0 && !rm) ++removed;
  }
  return removed;
}

bool sweep_legacy_part(const std::filesystem::path& video) {
  namespace fs = std::filesystem;
  const std::string ext = video.extension().string();
  if (ext != ".mp4" && ext != ".gif") return false;
  fs::path part = video;
  part += ".part";
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(part, ec);
  if (ec || !fs::is_regular_file(st)) return false;  // no such part, or a link or folder: not ours
  const auto written = fs::last_write_time(part, ec);
  if (ec || fs::file_time_type::clock::now() - written < kLegacyPartAge) return false;
  return fs::remove(part, ec) && !ec;
}

}  // namespace draught::cli
