// File input/output with the error discipline of the project: every failure names the
// file; writes are atomic (temporary file, then rename) so nothing half-written is left.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace draught {

// Bad input from a user: the message is complete ("file: field: expected ...").
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string read_text_file(const std::filesystem::path&);
void write_file_atomic(const std::filesystem::path&, const std::string& bytes);

}  // namespace draught
