// Counter-based randomness for deterministic simulations: a splitmix64 mix of a seed
// and three counters (which object, which event, which channel) into [0, 1). The same
// inputs give the same number on every machine, in any order of calls.
#pragma once

#include <cstdint>
#include <initializer_list>

namespace draught {

inline double hash01(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull;
  for (std::uint64_t v : {a, b, c}) {
    z += v + 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
  }
  return double(z >> 11) * 0x1.0p-53;
}

}  // namespace draught
