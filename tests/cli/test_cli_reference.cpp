// End-to-end tests of `draught render --reference`: it writes the picture through the
// same output as the GPU, reports its rate with --verbose, and refuses flags that do not
// apply (exit 1, the flag named, nothing written).
#include "cli_helpers.hpp"

#include "core/io/hdr_image.hpp"

#include <cmath>

namespace draught_cli_test {
namespace {

using Reference = CliTest;

TEST_F(Reference, WritesAPngAndSaysHowFast) {
  const fs::path png = out() / "ref.png";
  auto r = render({"--reference", "--spp", "2", "--threads", "2", "-o", png.string(), "--verbose"}, "24x16");
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "wrote " + png.string())) << r.describe();
  EXPECT_TRUE(contains(r.err, "reference: 24x16 at 2 paths per pixel")) << r.describe();
  EXPECT_TRUE(contains(r.err, "paths per second")) << r.describe();
  const PngInfo info = png_info(png);
  EXPECT_EQ(info.error, "");
  EXPECT_EQ(info.width, 24u);
  EXPECT_EQ(info.height, 16u);
}

// -o NAME.exr: the radiance before exposure and the tone map, as 32-bit floats, for
// comparing in linear light; the GPU's picture has no such output.
TEST_F(Reference, WritesTheLinearRadianceToAnExr) {
  const std::string gpu_exr = (out() / "gpu.exr").string();
  expect_failure(render({"-o", gpu_exr}), {"gpu.exr", "add --reference, or name a .png"});
  expect_failure(render({"--reference", "-o", (out() / "ref.tiff").string()}), {"ref.tiff", ".png (or .exr with --reference)"});
  const fs::path exr = out() / "ref.exr";
  auto r = render({"--reference", "--spp", "2", "-o", exr.string()}, "24x16");
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "wrote " + exr.string() + " (scene-linear radiance)")) << r.describe();
  const draught::HdrImage img = draught::read_hdr_image(exr);
  EXPECT_EQ(img.width, 24);
  EXPECT_EQ(img.height, 16);
  float brightest = 0;
  for (const glm::vec3& p : img.rgb) {
    ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
    brightest = std::max({brightest, p.r, p.g, p.b});
  }
  EXPECT_GT(brightest, 0.05f);  // a lit scene, in linear light
}

TEST_F(Reference, AScenePresetRendersToo) {
  const fs::path png = out() / "flight.png";
  auto r = render({"--preset", "flight", "--reference", "--spp", "1", "-o", png.string()}, "20x12");
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(png).error, "");
}

TEST_F(Reference, FlagsThatDoNotApplyAreRefused) {
  const std::string png = (out() / "x.png").string();
  expect_failure(render({"--reference", "--debug", "depth", "-o", png}), {"--reference", "--debug"});
  expect_failure(render({"--reference", "--transparent", "-o", png}), {"--reference", "--transparent"});
  expect_failure(render({"--reference", "--timeline", "pour", "-o", png}), {"--reference", "--timeline"});
  expect_failure(render({"--spp", "4", "-o", png}), {"--spp needs --reference"});
  expect_failure(render({"--threads", "4", "-o", png}), {"--threads needs --reference"});
  expect_failure(render({"--reference", "--spp", "0", "-o", png}), {"--spp 0", "1 to 100000"});
  expect_failure(render({"--reference", "--spp", "many", "-o", png}), {"--spp many"});
  expect_failure(render({"--progress", "-o", png}), {"--progress needs --timeline or --reference"});
  EXPECT_FALSE(fs::exists(png));
}

}  // namespace
}  // namespace draught_cli_test
