#include "core/io/process.hpp"

#include "core/io/files.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#ifndef __EMSCRIPTEN__
#include <csignal>
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace draught {

namespace fs = std::filesystem;

#ifdef __EMSCRIPTEN__

bool can_start_processes() { return false; }
std::string find_executable(const std::string&) { return ""; }
std::string find_ffmpeg(const std::string&) { return ""; }
pid_t spawn_process(const std::vector<std::string>& args, int, int, int) {
  throw std::runtime_error("cannot start " + (args.empty() ? std::string("a program") : args[0]) +
                           ": the web page runs no programs");
}
int wait_process(pid_t) { return 0; }
void kill_process(pid_t) {}
void make_pipe(int[2]) { throw std::runtime_error("pipe: the web page has no pipes"); }
size_t read_fully(int, void*, size_t) { return 0; }

#else

bool can_start_processes() { return true; }

std::string find_executable(const std::string& name) {
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  for (size_t start = 0; start <= dirs.size();) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return "";
}

std::string find_ffmpeg(const std::string& who) {
  const char* pinned = std::getenv("DRAUGHT_FFMPEG");
  if (pinned && *pinned) {
    if (access(pinned, X_OK) != 0) throw InputError(who + ": DRAUGHT_FFMPEG=" + pinned + " is not an executable ffmpeg");
    return pinned;
  }
  return find_executable("ffmpeg");
}

void make_pipe(int fds[2]) {
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
}

pid_t spawn_process(const std::vector<std::string>& args, int in, int out, int err) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  int status_pipe[2];  // carries exec's errno; closed by a successful exec (O_CLOEXEC)
  make_pipe(status_pipe);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {  // the child: async-signal-safe calls only until exec
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);  // the parent died before prctl
    setpgid(0, 0);
    const int fd = in >= 0 ? in : open("/dev/null", O_RDONLY);
    if (fd < 0 || dup2(fd, 0) < 0) _exit(127);
    if (out >= 0 && dup2(out, 1) < 0) _exit(127);
    if (err >= 0 && dup2(err, 2) < 0) _exit(127);
    execv(argv[0], argv.data());
    const int e = errno;
    (void)!write(status_pipe[1], &e, sizeof e);
    _exit(127);
  }
  close(status_pipe[1]);
  if (pid < 0) {
    close(status_pipe[0]);
    throw std::runtime_error("cannot start " + args[0] + ": fork: " + std::strerror(errno));
  }
  int e = 0;
  ssize_t n;
  while ((n = read(status_pipe[0], &e, sizeof e)) < 0 && errno == EINTR) {
  }
  close(status_pipe[0]);
  if (n > 0) {
    waitpid(pid, nullptr, 0);
    throw std::runtime_error("cannot start " + args[0] + ": " + std::strerror(e));
  }
  return pid;
}

int wait_process(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

void kill_process(pid_t pid) {
  if (pid <= 0) return;
  kill(pid, SIGKILL);
  wait_process(pid);
}

size_t read_fully(int fd, void* data, size_t size) {
  auto* p = static_cast<unsigned char*>(data);
  size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, p + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("read: ") + std::strerror(errno));
    if (n == 0) break;
    got += size_t(n);
  }
  return got;
}

#endif

}  // namespace draught
