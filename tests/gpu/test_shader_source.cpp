// Joining shader files (gpu/shader_source): a guarded file included again where the first
// inclusion was whole is left out (it is empty to the preprocessor), but not when the first
// one sat in an #if block; an unguarded file is joined every time; compile errors still
// name the file and line they are in.
#include "gpu/program.hpp"
#include "gpu/shader_source.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace draught::test {
namespace {

namespace fs = std::filesystem;

struct ShaderDir {
  fs::path dir = fs::temp_directory_path() / ("draught-shader-source-" + std::to_string(::getpid()));
  ShaderDir() { fs::create_directories(dir); }
  ~ShaderDir() { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir / name) << text; }
};

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ShaderSource, AGuardedFileJoinedWholeIsNotJoinedAgain) {
  ShaderDir d;
  d.write("guarded.glsl", "// a comment first\n#ifndef GUARDED_GLSL\n#define GUARDED_GLSL\nfloat guarded_marker;\n#endif\n");
  d.write("plain.glsl", "float plain_marker;\n");
  d.write("middle.glsl", "#ifndef MIDDLE_GLSL\n#define MIDDLE_GLSL\n#include \"guarded.glsl\"\n#endif\n");
  d.write("entry.glsl",
          "#if defined(NEVER)\n"
          "#include \"guarded.glsl\"\n"  // in a block: the preprocessor may skip it
          "#endif\n"
          "#include \"middle.glsl\"\n"   // whole, through another guarded file
          "#include \"guarded.glsl\"\n"  // left out
          "#include \"plain.glsl\"\n"
          "#include \"plain.glsl\"\n"    // no guard: joined again
          "float entry_marker;\n");
  const gpu::ShaderSource s = gpu::assemble_shader("entry.glsl", d.dir);
  EXPECT_EQ(count(s.text, "guarded_marker"), 2) << s.text;
  EXPECT_EQ(count(s.text, "plain_marker"), 2) << s.text;
  EXPECT_EQ(count(s.text, "entry_marker"), 1);
  EXPECT_EQ(s.files.size(), 6u);  // entry, guarded (in the block), middle, guarded (whole), plain, plain
}

TEST(ShaderSource, ACompileErrorAfterALeftOutIncludeNamesItsLine) {
  gpu_instance();  // the GL context the shader is compiled in
  ShaderDir d;
  d.write("lib.glsl", "#ifndef LIB_GLSL\n#define LIB_GLSL\nfloat lib_value() { return 1.0; }\n#endif\n");
  d.write("entry.glsl",
          "#version 300 es\n"
          "precision highp float;\n"
          "#include \"lib.glsl\"\n"
          "#include \"lib.glsl\"\n"
          "out vec4 c;\n"
          "void main() { c = vec4(lib_value()) + undefined_name; }\n");  // line 6
  const gpu::ShaderSource frag = gpu::assemble_shader("entry.glsl", d.dir);
  const gpu::ShaderSource vert{"#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n", {"test.vert"}};
  try {
    gpu::Program p(vert, frag);
    ADD_FAILURE() << "a shader with an undefined name compiled";
  } catch (const gpu::ShaderError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("entry.glsl:6"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace draught::test
