#include "core/io/files.hpp"

#include "core/io/temporaries.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace draught {

namespace {

std::string mib(std::uintmax_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / (1 << 20));
  return buf;
}

const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_text_file(const std::filesystem::path& path) { return read_whole_file(path, kMaxTextFileBytes, "a text input"); }

std::string read_whole_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& what) {
  const std::string limit = "the limit of " + std::to_string(max_bytes >> 20) + " MiB for " + what;
  // O_NONBLOCK: opening a FIFO must not wait for a writer before we can refuse it.
  Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0) throw InputError(path.string() + ": cannot open file: " + std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw InputError(path.string() + ": cannot read: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw InputError(path.string() + ": is " + kind_of(st.st_mode) + ", expected a regular file");
  if (std::uintmax_t(st.st_size) > max_bytes)
    throw InputError(path.string() + ": " + mib(std::uintmax_t(st.st_size)) + ", larger than " + limit);
  std::string text;
  text.resize(std::size_t(st.st_size));
  std::size_t have = 0;
  for (;;) {  // to the end, which may differ from st_size (a growing file, /proc)
    if (have == text.size()) {
      if (have > max_bytes) throw InputError(path.string() + ": larger than " + limit);
      text.resize(std::max<std::size_t>(4096, std::min<std::size_t>(2 * have, max_bytes + 1)));
    }
    const ssize_t n = ::read(f.fd, text.data() + have, text.size() - have);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path.string() + ": cannot read: " + std::strerror(errno));
    if (n == 0) break;
    have += std::size_t(n);
  }
  text.resize(have);
  return text;
}

std::filesystem::path write_destination(const std::filesystem::path& path) {
  std::filesystem::path p = path;
  for (int hops = 0; hops < 40; ++hops) {  // 40: the kernel's own limit on a chain of links
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) return p;
    const std::filesystem::path next = std::filesystem::read_symlink(p, ec);
    if (ec) throw InputError(path.string() + ": cannot read the symbolic link: " + ec.message());
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  throw InputError(path.string() + ": too many levels of symbolic links");
}

void write_file_atomic(const std::filesystem::path& path, const std::string& bytes) {
  const std::filesystem::path dest = write_destination(path);
  const std::filesystem::path tmp = temporary_path_beside(dest);
  temporary_created(tmp, false);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    const int err = errno;
    temporary_gone(tmp);
    throw InputError(path.string() + ": cannot write: " + std::strerror(err));
  }
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = std::fflush(f) == 0 && ok;
  ok = ::fsync(::fileno(f)) == 0 && ok;
  ok = std::fclose(f) == 0 && ok;
  int err = errno;
  std::error_code ec;
  if (ok) std::filesystem::rename(tmp, dest, ec);
  if (!ok || ec) {
    if (ec) err = ec.value();
    std::filesystem::remove(tmp, ec);
    temporary_gone(tmp);
    throw InputError(path.string() + ": cannot write: " + std::strerror(err));
  }
  temporary_gone(tmp);
}

}  // namespace draught
