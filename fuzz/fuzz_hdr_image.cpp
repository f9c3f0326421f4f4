// libFuzzer target: the HDR image decoder (Radiance and OpenEXR), then, for what it
// accepts in an environment's shape, the level chain and a lookup at every level.
#include "fuzz_common.hpp"

#include "core/environment/environment_map.hpp"
#include "core/io/hdr_image.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace draught;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    HdrImage img = decode_hdr_image(bytes, fuzz::kFile);
    for (const glm::vec3& c : img.rgb)
      if (!(c.r >= 0 && c.g >= 0 && c.b >= 0 && c.r <= kMaxHdrValue && c.g <= kMaxHdrValue && c.b <= kMaxHdrValue))
        fuzz::finding("a decoded texel is out of range", "");
    if (img.width == 2 * img.height && img.width >= kMinEnvironmentWidth) {
      const EnvironmentMap map = make_environment_map(std::move(img), fuzz::kFile);
      for (size_t l = 0; l < map.levels.size(); ++l) {
        const glm::dvec3 c = map.radiance(glm::normalize(glm::dvec3(0.3, -0.2, 0.9)), double(l));
        if (!std::isfinite(c.r + c.g + c.b)) fuzz::finding("a lookup is not finite", "");
      }
    }
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  return 0;
}
