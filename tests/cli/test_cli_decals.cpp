// End-to-end tests of decals on the command line: a shipped decal and a PNG of the user's
// render; a bad decal image (missing, not an image, cut short, a folder) is refused where
// it is given (exit 1, the flag, the field, the file and what was expected; nothing
// written), from --set and from a preset alike.
#include "cli_helpers.hpp"

#include "core/io/image.hpp"

#include <fstream>

namespace draught_cli_test {
namespace {

class Decals : public CliTest {
 protected:
  // Inputs live beside the output folder, which a refused run must leave empty.
  fs::path in() {
    fs::create_directories(dir_ / "in");
    return dir_ / "in";
  }
};

TEST_F(Decals, AShippedDecalAndAUsersPngRender) {
  fs::create_directories(out());
  const fs::path logo = in() / "logo.png";
  draught::Image img{8, 4, std::vector<std::uint8_t>(8 * 4 * 4, 200)};
  draught::write_png(logo, img);
  const fs::path png = out() / "pint.png";
  auto r = draught({"render", "--size", "48x48", "--set", "decal_outer.file=wordmark", "--set",
                    "decal_inner.file=" + logo.string(), "-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(fs::exists(png));
  r = draught({"render", "--size", "48x48", "--preset", "branded-pint", "-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
}

TEST_F(Decals, BadImagesAreRefusedNamingTheFile) {
  fs::create_directories(out());
  const std::string png = (out() / "never.png").string();
  const std::string missing = (in() / "missing.png").string();
  expect_failure(draught({"render", "--set", "decal_outer.file=" + missing, "-o", png}),
                 {"--set decal_outer.file=", "field 'decal_outer.file'", missing, "no such file"});
  const fs::path text = in() / "notes.png";
  std::ofstream(text) << "just some text";
  expect_failure(draught({"render", "--set", "decal_inner.file=" + text.string(), "-o", png}),
                 {"decal_inner.file", text.string(), "expected a PNG image"});
  const std::string good = draught::encode_png(draught::Image{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 90)});
  const fs::path cut = in() / "cut.png";
  std::ofstream(cut, std::ios::binary) << good.substr(0, good.size() - 20);
  expect_failure(draught({"render", "--set", "decal_outer.file=" + cut.string(), "-o", png}),
                 {cut.string(), "damaged PNG"});
  expect_failure(draught({"render", "--set", "decal_outer.file=" + in().string(), "-o", png}),
                 {in().string(), "a directory"});
  expect_failure(draught({"render", "--set", "decal_outer.file=wordmrk", "-o", png}),
                 {"no shipped decal named 'wordmrk'", "did you mean 'wordmark'"});
  EXPECT_FALSE(fs::exists(png));
}

TEST_F(Decals, APresetWithABadDecalIsRefused) {
  fs::create_directories(out());
  const fs::path preset = in() / "branded.json";
  std::ofstream(preset) << R"({"draught_preset": 1, "kind": "scene", "name": "branded",
    "params": {"decal_outer": {"file": "no-such-decal.png"}}})";
  expect_failure(draught({"validate", preset.string()}), {preset.string(), "decal_outer.file", "no-such-decal.png"});
  auto r = draught({"validate", (fs::path(DRAUGHT_SOURCE_DIR) / "presets/scenes/branded-glassware.json").string()});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
}

}  // namespace
}  // namespace draught_cli_test
