// End-to-end tests of `draught render --shader-dir`: shaders loaded from a folder, and
// compile errors reported as "file.glsl:LINE" (paths under shaders/, as included).
#include "cli_helpers.hpp"


namespace draught_cli_test {
namespace {

std::vector<std::string> read_lines(const fs::path& p) {
  std::vector<std::string> out;
  std::istringstream in(read_file(p));
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

void write_lines(const fs::path& p, const std::vector<std::string>& lines) {
  std::string text;
  for (auto& l : lines) text += l + "\n";
  write_file(p, text);
}

// A library file included by the path pass, and the pass's entry file.
const std::string kLibFile = "lib/vessel/intersect.glsl";
const std::string kEntryFile = "passes/path.frag.glsl";

class Shaders : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    fs::create_directories(shaders());
    fs::copy(kSourceDir / "shaders", shaders(), fs::copy_options::recursive);
    ASSERT_TRUE(fs::exists(shaders() / kLibFile));
    ASSERT_TRUE(fs::exists(shaders() / kEntryFile));
  }
  fs::path shaders() const { return in() / "shaders"; }
  fs::path png() const { return out() / "x.png"; }

  // Inserts a line that is not GLSL into `file` so that it becomes line `line` (1-based).
  void break_line(const std::string& file, size_t line) {
    auto lines = read_lines(shaders() / file);
    ASSERT_GT(lines.size(), line) << file;
    lines.insert(lines.begin() + long(line - 1), "this is not glsl;");
    write_lines(shaders() / file, lines);
  }

  RunResult render_with_shaders() {
    return render({"--shader-dir", shaders().string(), "-o", png().string()}, "16x16");
  }

  // stderr names `file` and the broken line (drivers may blame the line after it).
  void expect_blames(const RunResult& r, const std::string& file, size_t line) {
    expect_failure(r, {file + ":"});
    const std::string re = "(^|[^A-Za-z0-9_.])" + literal_pattern(file) + ":(" + std::to_string(line) + "|" +
                           std::to_string(line + 1) + ")[^0-9]";
    EXPECT_TRUE(matches(r.err, re)) << "expected " << file << ":" << line << " (or " << line + 1
                                              << ")\n" << r.describe();
  }
};

TEST_F(Shaders, CopiedShadersRenderLikeTheBuiltInOnes) {
  auto r = render_with_shaders();
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  auto r2 = render({"-o", (out() / "builtin.png").string()}, "16x16");
  ASSERT_EQ(r2.exit_code, 0) << r2.describe();
  EXPECT_EQ(png_info(png()).error, "");
  EXPECT_EQ(read_file(png()), read_file(out() / "builtin.png"))
      << "shaders/ differs from the copies embedded in the binary (rebuild?)";
}

// The first blank line at or after line 10 of a library file: a top-level spot in it.
size_t spot_in(const std::vector<std::string>& lines) {
  for (size_t i = 9; i < lines.size(); ++i)
    if (lines[i].find_first_not_of(" \t") == std::string::npos) return i + 1;
  return 10;
}

TEST_F(Shaders, SyntaxErrorInIncludedFileGivesItsLine) {
  const size_t line = spot_in(read_lines(shaders() / kLibFile));
  ASSERT_GT(line, 1u);
  break_line(kLibFile, line);
  expect_blames(render_with_shaders(), kLibFile, line);
}

TEST_F(Shaders, SyntaxErrorAfterIncludesGivesTheEntryFileLine) {
  // Just after the last #include of the entry file, outside any #if (an include may sit in
  // a variant's block): the line numbers must have been restored after the included files.
  auto lines = read_lines(shaders() / kEntryFile);
  const std::string include = R"(^\s*#\s*include\s)", open_if = R"(^\s*#\s*if)", end_if = R"(^\s*#\s*endif)";
  size_t last_include = 0;
  for (size_t i = 0; i < lines.size(); ++i)
    if (matches(lines[i], include)) last_include = i + 1;
  ASSERT_GT(last_include, 0u) << kEntryFile << " includes nothing?";
  int depth = 0;
  size_t spot = 0;
  for (size_t i = 0; i < lines.size() && spot == 0; ++i) {
    if (matches(lines[i], open_if)) ++depth;
    else if (matches(lines[i], end_if)) --depth;
    else if (i + 1 > last_include && depth == 0) spot = i + 1;
  }
  ASSERT_GT(spot, 0u) << kEntryFile << " has no top-level line after its includes";
  break_line(kEntryFile, spot);
  expect_blames(render_with_shaders(), kEntryFile, spot);
}

TEST_F(Shaders, MissingShaderFileIsNamed) {
  fs::remove(shaders() / "lib/common/math.glsl");
  expect_failure(render_with_shaders(), {"lib/common/math.glsl"});
}

TEST_F(Shaders, MissingShaderDirIsNamed) {
  const fs::path none = in() / "no-such-dir";
  expect_failure(render({"--shader-dir", none.string(), "-o", png().string()}, "16x16"), {none.string()});
}

TEST_F(Shaders, FailedCompileKeepsExistingImage) {
  write_file(png(), "previous image");
  break_line(kLibFile, spot_in(read_lines(shaders() / kLibFile)));
  auto r = render_with_shaders();
  EXPECT_NE(r.exit_code, 0) << r.describe();
  EXPECT_EQ(read_file(png()), "previous image");
  EXPECT_EQ(join(list_tree(out())), "x.png") << "a temporary file was left behind";
}

}  // namespace
}  // namespace draught_cli_test
