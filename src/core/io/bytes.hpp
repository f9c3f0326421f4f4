// Integers read from a file's bytes (the PNG and video containers' headers).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace draught {

// The big-endian 32-bit integer at byte `at` of b (the caller checks that four bytes are there).
inline std::uint32_t be32(std::string_view b, std::size_t at) {
  return std::uint32_t(static_cast<unsigned char>(b[at])) << 24 | std::uint32_t(static_cast<unsigned char>(b[at + 1])) << 16 |
         std::uint32_t(static_cast<unsigned char>(b[at + 2])) << 8 | std::uint32_t(static_cast<unsigned char>(b[at + 3]));
}

}  // namespace draught
