// File input/output with the error discipline of the project: every failure names the
// file; writes are atomic (temporary file, then rename) so nothing half-written is left.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace draught {

// Bad input from a user: the message is complete ("file: field: expected ...").
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The largest file read as text (presets, timelines, shaders): far above any real one,
// and small enough that a mistaken path (a video, a disk image) fails at once.
inline constexpr std::uintmax_t kMaxTextFileBytes = 16u << 20;

// The whole of a regular file of at most kMaxTextFileBytes. Anything else (a folder, a
// FIFO, which would block, a device such as /dev/zero, which never ends) is refused
// with an InputError naming the file, before a byte is read.
std::string read_text_file(const std::filesystem::path&);

// The same for any input with its own limit (images: kMaxImageFileBytes); `what` names
// the kind of input in the error ("an image").
std::string read_whole_file(const std::filesystem::path&, std::uintmax_t max_bytes, const std::string& what);

// The largest image file read (HDR environments): an uncompressed 8192 x 4096 RGBA
// float EXR is 512 MiB.
inline constexpr std::uintmax_t kMaxImageFileBytes = 600u << 20;

// Where a write to `path` lands: `path` itself, or, when it is a symbolic link, the file
// the chain of links ends at (created if missing). Writes follow links, like a shell's
// `>`: the link stays a link, and its target gets the new content.
std::filesystem::path write_destination(const std::filesystem::path&);

// Writes through a temporary beside the destination (see temporaries.hpp), then renames
// it onto write_destination(path).
void write_file_atomic(const std::filesystem::path&, const std::string& bytes);

}  // namespace draught
