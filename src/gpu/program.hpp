// Compiling and linking GLSL ES programs; failures throw ShaderError naming the file
// and line of the problem.
#pragma once

#include "gpu/shader_source.hpp"

#include <GLES3/gl3.h>

namespace draught::gpu {

class Program {
 public:
  Program(const ShaderSource& vertex, const ShaderSource& fragment);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace draught::gpu
