// End-to-end tests of the MatCap tier on the command line (docs/MATCAP.md): a render with
// --set render.tier=matcap (baked MatCap, and one from a PNG); a bad MatCap image
// (missing, not an image, cut short, a folder) is refused where it is given (exit 1, the
// flag, the field, the file and what was expected; nothing written).
#include "cli_helpers.hpp"

#include "core/io/image.hpp"

#include <fstream>

namespace draught_cli_test {
namespace {

class MatCap : public CliTest {
 protected:
  fs::path in() {
    fs::create_directories(dir_ / "in");
    return dir_ / "in";
  }
};

TEST_F(MatCap, RendersTheTierBakedAndFromAPng) {
  fs::create_directories(out());
  const fs::path png = out() / "pint.png";
  auto r = draught({"render", "--size", "48x48", "--set", "render.tier=matcap", "-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const draught::Image baked = draught::read_png(png);
  EXPECT_EQ(baked.width, 48);
  const fs::path sphere = in() / "sphere.png";
  draught::Image img{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 255)};
  for (int y = 0; y < 8; ++y)  // a red top half
    for (int x = 0; x < 16; ++x) img.px(x, y)[1] = img.px(x, y)[2] = 0;
  draught::write_png(sphere, img);
  r = draught({"render", "--size", "48x48", "--set", "render.tier=matcap", "--set", "matcap.file=" + sphere.string(), "-o",
               png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const draught::Image from_file = draught::read_png(png);
  EXPECT_NE(from_file.rgba, baked.rgba);
}

TEST_F(MatCap, BadImagesAreRefusedNamingTheFile) {
  fs::create_directories(out());
  const std::string png = (out() / "never.png").string();
  const std::string missing = (in() / "missing.png").string();
  expect_failure(draught({"render", "--set", "render.tier=matcap", "--set", "matcap.file=" + missing, "-o", png}),
                 {"--set matcap.file=", "field 'matcap.file'", missing, "no such file"});
  const fs::path text = in() / "notes.png";
  std::ofstream(text) << "just some text";
  expect_failure(draught({"render", "--set", "matcap.file=" + text.string(), "-o", png}),
                 {"matcap.file", text.string(), "expected a PNG image"});
  const std::string good = draught::encode_png(draught::Image{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 90)});
  const fs::path cut = in() / "cut.png";
  std::ofstream(cut, std::ios::binary) << good.substr(0, good.size() - 20);
  expect_failure(draught({"render", "--set", "matcap.file=" + cut.string(), "-o", png}), {cut.string(), "damaged PNG"});
  expect_failure(draught({"render", "--set", "matcap.file=" + in().string(), "-o", png}), {in().string(), "a directory"});
  expect_failure(draught({"render", "--set", "render.tier=glass", "-o", png}), {"render.tier", "full", "matcap"});
  EXPECT_FALSE(fs::exists(png));
}

}  // namespace
}  // namespace draught_cli_test
