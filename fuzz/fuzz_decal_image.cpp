// libFuzzer target: the strict PNG decoder of decal images (core/io/image decode_png),
// then, for what it accepts, the GPU's layer texels at a small size and a lookup of the
// reference's sampler (core/vessel/decal).
#include "fuzz_common.hpp"

#include "core/io/image.hpp"
#include "core/vessel/decal.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace draught;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    // A smaller side than a user's limit keeps each run quick; the checks are the same.
    const Image img = decode_png(bytes, fuzz::kFile, 512);
    if (img.width < 1 || img.height < 1 || img.width > 512 || img.height > 512)
      fuzz::finding("a decoded image has a size outside the limits", "");
    if (img.rgba.size() != size_t(img.width) * size_t(img.height) * 4) fuzz::finding("a decoded image's pixels do not fill it", "");
    const std::vector<std::uint8_t> texels = decal_layer_texels(img, 16);
    if (texels.size() != 16 * 16 * 4) fuzz::finding("a layer has the wrong size", "");
    const glm::dvec4 c = sample_decal_image(img, {0.3, 0.7});
    if (!(c.a >= 0 && c.a <= 1 && c.r >= 0 && c.r <= c.a + 1e-9)) fuzz::finding("a sample is not premultiplied colour", "");
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  return 0;
}
