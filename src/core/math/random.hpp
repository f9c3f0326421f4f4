// A small, fast random stream for Monte Carlo sampling (PCG32, O'Neill 2014), seeded from
// counters so each pixel's samples are the same on every run and with any number of
// threads.
#pragma once

#include "core/math/hash.hpp"

#include <cstdint>

namespace draught {

class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
    state_ = std::uint64_t(hash01(seed, a, b, 0) * 0x1.0p53) * 2048u + 1u;
    inc_ = (std::uint64_t(hash01(seed, a, b, 1) * 0x1.0p53) << 1) | 1u;
    next();
  }
  std::uint32_t next() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = std::uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  // Uniform in [0, 1).
  double uniform() { return double(next()) * 0x1.0p-32; }

 private:
  std::uint64_t state_ = 0, inc_ = 1;
};

}  // namespace draught
