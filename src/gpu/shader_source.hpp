// Shader sources: small GLSL files joined by `#include "file.glsl"`. Each file gets a
// source-string number through `#line`, so a compile log's "3:42" maps back to
// "lib/vessel/intersect.glsl:42". Files come embedded in the binary, or from a folder
// (for shader work without rebuilding: --shader-dir / DRAUGHT_SHADER_DIR). Files under generated/
// (the GLSL side of src/interface/*.def) are always the embedded ones.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace draught::gpu {

struct EmbeddedShader {
  const char* name;
  const char* text;
};
const std::vector<EmbeddedShader>& embedded_shaders();  // generated at build time

struct ShaderSource {
  std::string text;
  std::vector<std::string> files;  // index = source-string number in #line
};

struct ShaderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Resolves includes starting at `entry`; reads from `dir` when it is not empty.
ShaderSource assemble_shader(const std::string& entry, const std::filesystem::path& dir = {});

// Rewrites driver log locations (Mesa "0:12(5):", NVIDIA "0(12) :", ANGLE "0:12:")
// into "file.glsl:12:".
std::string map_shader_log(const std::string& log, const ShaderSource&);

}  // namespace draught::gpu
