// Decal files (core/vessel/decal_files) and the decal parameters: a shipped name or a path
// is read and checked where it is given; a bad one is refused with the file and what was
// expected, and the parameters keep what they had.
#include "core/io/files.hpp"
#include "core/params/params.hpp"
#include "core/params/preset.hpp"
#include "core/vessel/decal_files.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace draught {
namespace {

namespace fs = std::filesystem;

class DecalFiles : public test::TempDirTest {
 protected:
  DecalFiles() : TempDirTest("draught-decal") {}
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  static Image square(int n, std::uint8_t grey) {
    Image img{n, n, {}};
    for (int i = 0; i < n * n; ++i) img.rgba.insert(img.rgba.end(), {grey, grey, grey, 255});
    return img;
  }
  // The error of setting decal_outer.file to `value`, "" if it was taken.
  static std::string set_error(Params& p, const std::string& value) {
    try {
      set_param(p, *find_param("decal_outer.file"), ParamValue(value));
    } catch (const ParamError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(DecalFiles, ShippedDecalsAreFoundByName) {
  const std::vector<std::string> names = shipped_decal_names();
  for (const char* want : {"crest", "gold-band", "wordmark"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  for (const std::string& name : names) {
    const auto img = load_decal(name);
    EXPECT_GT(img->width, 0) << name;
    EXPECT_LE(std::max(img->width, img->height), kMaxPngSide) << name;
  }
  EXPECT_EQ(resolve_decal("crest").filename(), "crest.png");
}

TEST_F(DecalFiles, AnUnknownNameSuggestsTheNearest) {
  try {
    resolve_decal("crst");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::has(e.what(), {"no shipped decal named 'crst'", "did you mean 'crest'", "wordmark"}));
  }
}

TEST_F(DecalFiles, AFileIsReadAndKeptUntilItChanges) {
  const fs::path p = write("logo.png", encode_png(square(4, 10)));
  const auto first = load_decal(p.string());
  EXPECT_EQ(first->width, 4);
  EXPECT_EQ(load_decal(p.string()), first) << "read again although unchanged";
  write("logo.png", encode_png(square(6, 10)));
  EXPECT_EQ(load_decal(p.string())->width, 6) << "a changed file must be read again";
}

TEST_F(DecalFiles, BadFilesAreRefusedNamingThem) {
  auto error = [](const std::string& name) {
    try {
      load_decal(name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string missing = (dir_ / "missing.png").string();
  EXPECT_TRUE(test::has(error(missing), {missing, "no such file", "PNG"}));
  const fs::path text = write("notes.png", "not a picture");
  EXPECT_TRUE(test::has(error(text.string()), {text.string(), "expected a PNG image"}));
  const fs::path empty = write("empty.png", "");
  EXPECT_TRUE(test::has(error(empty.string()), {empty.string(), "an empty file"}));
  const std::string good = encode_png(square(8, 200));
  const fs::path cut = write("cut.png", good.substr(0, good.size() / 2));
  EXPECT_TRUE(test::has(error(cut.string()), {cut.string(), "damaged", "cut short"}));
  EXPECT_TRUE(test::has(error(dir_.string()), {dir_.string(), "a directory"}));
  // Too large: 5000 x 1 claims too many pixels (stb's encoder makes a real one cheaply).
  Image wide{5000, 1, std::vector<std::uint8_t>(5000 * 4, 255)};
  const fs::path huge = write("huge.png", encode_png(wide));
  EXPECT_TRUE(test::has(error(huge.string()), {huge.string(), "5000 x 1 pixels", "4096 x 4096"}));
}

TEST_F(DecalFiles, TheParameterRefusesABadFileAndKeepsItsValue) {
  Params p;
  EXPECT_EQ(p.decal_outer.file, "") << "decals are off by default";
  EXPECT_EQ(set_error(p, "crest"), "");
  EXPECT_EQ(p.decal_outer.file, "crest");
  const fs::path bad = write("bad.png", "GIF89a");
  const std::string e = set_error(p, bad.string());
  EXPECT_TRUE(test::has(e, {"decal_outer.file", bad.string(), "a GIF image"})) << e;
  EXPECT_EQ(p.decal_outer.file, "crest") << "a refused file changed the parameter";
  EXPECT_TRUE(test::has(set_error(p, "wordmrk"), {"did you mean 'wordmark'"}));
  EXPECT_EQ(set_error(p, ""), "") << "\"\" turns the decal off";
  EXPECT_EQ(p.decal_outer.file, "");
  // The other rows of a layer validate their ranges like any parameter.
  EXPECT_THROW(set_param(p, *find_param("decal_inner.repeat"), ParamValue(0)), ParamError);
  EXPECT_THROW(set_param(p, *find_param("decal_inner.kind"), ParamValue(std::string("chrome"))), ParamError);
  EXPECT_THROW(set_param(p, *find_param("decal_inner.width"), ParamValue(-0.01f)), ParamError);
}

TEST_F(DecalFiles, APresetWithABadDecalChangesNothing) {
  const fs::path bad = write("bad.png", "");
  const fs::path preset = write("branded.json", R"({"draught_preset": 1, "kind": "scene", "name": "b",
    "params": {"decal_outer": {"file": ")" + bad.string() + R"(", "width": 0.06}}})");
  try {
    load_preset(preset);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::has(e.what(), {preset.string(), "decal_outer.file", bad.string(), "an empty file"}));
  }
}

}  // namespace
}  // namespace draught
