// Child processes for the tools draught drives (ffmpeg: the CLI's MP4/GIF encoder, the
// screen's video decoder). One place starts them, so each gets the same guarantees: it
// dies with us (PR_SET_PDEATHSIG, so no decoder outlives a crashed or killed draught),
// sits in its own process group (a Ctrl+C on the terminal reaches only draught, which
// cleans up), and a failed exec is an error here, not a silent child exiting 127.
//
// Note: PR_SET_PDEATHSIG follows the thread that forked, so start long-lived children
// from a thread that lives as long as they do (the main thread).
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace draught {

// Whether this build can start processes (the web build cannot).
bool can_start_processes();

// The first executable `name` on $PATH (or /usr/bin:/bin without one); "" when none.
std::string find_executable(const std::string& name);

// The ffmpeg to run: $DRAUGHT_FFMPEG when set (throws InputError when that is no
// executable; `who` begins the message), else the one on $PATH, else "".
std::string find_ffmpeg(const std::string& who);

// Starts args[0] (a path) with args. stdin from `in`, stdout to `out`, stderr to `err`
// (each -1: /dev/null for stdin, inherited for stdout and stderr). Throws
// std::runtime_error when it cannot start (naming the program and why).
pid_t spawn_process(const std::vector<std::string>& args, int in = -1, int out = -1, int err = -1);

// Waits for the child (retrying on EINTR); its wait status.
int wait_process(pid_t);

// Ends a child that is still running: SIGKILL, then waits for it.
void kill_process(pid_t);

// A pipe whose ends close on exec (O_CLOEXEC); fds[0] reads, fds[1] writes. Throws.
void make_pipe(int fds[2]);

// Reads exactly `size` bytes (retrying on EINTR and short reads); the bytes read, fewer
// only at the end of the stream. Throws std::runtime_error on a read error.
size_t read_fully(int fd, void* data, size_t size);

}  // namespace draught
