// End-to-end tests of `draught environment bake`: it writes a Radiance file the decoder
// reads back at the asked size, and refuses unknown names and bad widths (exit 1, the
// flag or name said, nothing written).
#include "cli_helpers.hpp"

#include "core/io/hdr_image.hpp"

namespace draught_cli_test {
namespace {

using Environment = CliTest;

TEST_F(Environment, BakesARadianceFile) {
  const fs::path hdr = out() / "bar.hdr";
  auto r = draught({"environment", "bake", "bar", "--width", "64", "-o", hdr.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "wrote " + hdr.string() + " (64 x 32, bar)")) << r.describe();
  const draught::HdrImage img = draught::read_hdr_image(hdr);
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 32);
}

TEST_F(Environment, BadNamesAndWidthsAreRefused) {
  const std::string hdr = (out() / "x.hdr").string();
  expect_failure(draught({"environment", "bake", "disco", "-o", hdr}), {"\"disco\"", "studio or bar"});
  expect_failure(draught({"environment", "bake", "bar", "--width", "63", "-o", hdr}), {"63", "even number"});
  expect_failure(draught({"environment", "bake", "bar", "--width", "wide", "-o", hdr}), {"--width wide"});
  expect_failure(draught({"environment", "bake", "studio"}), {"--output"});
}

}  // namespace
}  // namespace draught_cli_test
