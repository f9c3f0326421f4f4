// libFuzzer target: the preset loader (parse_preset), then applying what it accepted.
#include "fuzz_common.hpp"

#include "core/params/preset.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace draught;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Preset p = parse_preset(text, fuzz::kFile);
    Params params = default_params();
    apply_preset(p, params);  // every accepted value must pass validation again
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  return 0;  // any other exception escapes: libFuzzer reports it as a crash
}
