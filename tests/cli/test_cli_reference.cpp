// End-to-end tests of `draught render --reference`: it writes the picture through the
// same output as the GPU, reports its rate with --verbose, and refuses flags that do not
// apply (exit 1, the flag named, nothing written).
#include "cli_helpers.hpp"

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
