// Nothing left behind when the CLI is interrupted: on SIGINT, SIGTERM or SIGHUP the
// handler kills the encoder child, removes every temporary this process has open (files,
// and the folder a PNG sequence is written into), then dies of the signal as it would
// have. Temporaries of runs that died without a chance to clean (SIGKILL, a crash) are
// swept by the next run that writes into the same folder.
#pragma once

#include <chrono>
#include <filesystem>
#include <sys/types.h>

namespace draught::cli {

// Installs the signal handlers and the observer that keeps the table of temporaries
// (core/io/temporaries.hpp). Call once, early in main.
void install_cleanup_on_signals();

// The encoder process the handler kills (0: none).
void set_child_process(pid_t);

// Removes the temporaries in `folder` (not below it) whose owning process is no longer
// alive; returns how many.
int sweep_stale_temporaries(const std::filesystem::path& folder);

// Versions before the PID-named temporaries wrote a video as "X.mp4.part" / "X.gif.part",
// names that say nothing of their owner. A run writing the video X removes X's own such
// part when nothing has written it for kLegacyPartAge (a run of an older version still
// encoding it writes every frame); parts of other names are left alone (a browser's
// download in progress is "X.mp4.part" too). Returns whether it removed one.
inline constexpr auto kLegacyPartAge = std::chrono::minutes(10);
bool sweep_legacy_part(const std::filesystem::path& video);

}  // namespace draught::cli
