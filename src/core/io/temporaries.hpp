// Temporary files and folders written next to an output and renamed onto it when
// complete (atomic writes). Their names are short and fixed in length, so an output name
// of up to NAME_MAX bytes still gets a temporary beside it, and carry the PID of the
// process that owns them, so a later run can sweep those whose process died (killed by
// SIGKILL, or by a crash) without touching those of a process still writing.
//
// Core has no signal handling: an app that wants temporaries removed when it is
// interrupted installs an observer (the CLI does, apps/render/cleanup.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace draught {

// folder/.draught-tmp-PID-N-TOKEN: beside `target` (same folder, so the final rename
// stays on one file system), unique within this process and across runs.
std::filesystem::path temporary_path_beside(const std::filesystem::path& target);

// The PID that owns a temporary, from its file name: this scheme's names and the older
// "NAME.png.tmp-PID" / "NAME.json.tmp-PID" ones. nullopt for any other name.
std::optional<long> temporary_owner(std::string_view file_name);

// Told about every temporary before it is created (`created`) and after it has been
// renamed into place or removed (`gone`). The callbacks must not throw.
struct TemporaryObserver {
  void (*created)(const std::filesystem::path&, bool is_folder) = nullptr;
  void (*gone)(const std::filesystem::path&) = nullptr;
};
void set_temporary_observer(TemporaryObserver);
void temporary_created(const std::filesystem::path&, bool is_folder);
void temporary_gone(const std::filesystem::path&);

}  // namespace draught
