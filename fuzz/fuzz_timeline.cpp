// libFuzzer target: the timeline loader (parse_timeline), then sampling what it
// accepted over its duration, as a render would.
#include "fuzz_common.hpp"

#include "core/params/timeline.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace draught;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Timeline t = parse_timeline(text, fuzz::kFile);
    const Params base = default_params();
    for (int i = 0; i <= 4; ++i) {
      const double at = t.duration * i / 4;
      (void)t.lean_at(at);
      (void)t.params_at(at, base);
    }
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  return 0;
}
