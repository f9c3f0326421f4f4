// Compiling and linking GLSL ES programs; failures throw ShaderError naming the file
// and line of the problem.
#pragma once

#include "generated/frame.hpp"
#include "gpu/shader_source.hpp"

#include <GLES3/gl3.h>

#include <cstddef>
#include <span>
#include <string>

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

// Checks a linked program's uniform block against its generated C++ twin, member by
// member: each member's byte offset from the driver (GL_UNIFORM_OFFSET) against the
// offset the generator computed, the member count and the block's size (between the
// end of the last member, `used`, and the C++ struct's size: drivers differ in rounding
// it up); then binds the block to `binding`. A mismatch throws ShaderError naming the
// member. `what` names the shader for the message.
void check_uniform_block(GLuint program, const char* block, std::span<const contract::UniformMember> members,
                         std::size_t used, std::size_t size, unsigned binding, const std::string& what);

}  // namespace draught::gpu
