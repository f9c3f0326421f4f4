// A test fixture for scenes under an environment image (env.mode image): writes small
// Radiance HDR images of an even sky with a few bright texels into the test's own folder.
#pragma once

#include "core/io/hdr_image.hpp"
#include "core/params/preset.hpp"

#include "test_common.hpp"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace draught::test {

class ImageSceneTest : public TempDirTest {
 protected:
  using TempDirTest::TempDirTest;

  static constexpr int kWidth = 64, kHeight = 32;

  // A kWidth x kHeight image of `base` with `value` at the texels (x, y) listed, written
  // as `name`; returns its path.
  std::string write_image(const std::string& name, glm::vec3 base, const std::vector<glm::ivec2>& bright = {},
                          glm::vec3 value = glm::vec3(0)) {
    HdrImage img{kWidth, kHeight, std::vector<glm::vec3>(size_t(kWidth) * kHeight, base)};
    for (glm::ivec2 t : bright) img.rgb[size_t(t.y) * kWidth + size_t(t.x)] = value;
    const auto path = dir_ / name;
    write_radiance_hdr(path, img);
    return path.string();
  }

  // The default scene under the image `file`.
  static SceneParams image_scene(const std::string& file) {
    SceneParams p = default_params();
    set_param(p, *find_param("env.mode"), std::string("image"));
    set_param(p, *find_param("env.image"), file);
    return p;
  }
};

}  // namespace draught::test
