#include "gpu/program.hpp"

#include <string>
#include <vector>

namespace draught::gpu {

namespace {

// The info log of a shader or program object (the two share one shape of API).
template <class GetIv, class GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint len = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &len);
  std::vector<char> log(size_t(len) + 1);
  get_log(object, len, nullptr, log.data());
  return log.data();
}

GLuint compile(GLenum type, const ShaderSource& src) {
  GLuint s = glCreateShader(type);
  const char* text = src.text.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(s, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(s);
    throw ShaderError("shader " + src.files.front() + " failed to compile:\n" + map_shader_log(log, src));
  }
  return s;
}

}  // namespace

Program::Program(const ShaderSource& vertex, const ShaderSource& fragment) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertex);
  GLuint fs;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(id_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(id_);
    throw ShaderError("program " + vertex.files.front() + " + " + fragment.files.front() +
                      " failed to link:\n" + map_shader_log(log, fragment));
  }
}

void check_uniform_block(GLuint program, const char* block, std::span<const contract::UniformMember> members,
                         std::size_t used, std::size_t size, unsigned binding, const std::string& what) {
  const std::string where = what + ": uniform block '" + block + "'";
  const std::string twin = " (generated from src/interface/*.def; was the shader's block edited by hand?)";
  const GLuint index = glGetUniformBlockIndex(program, block);
  if (index == GL_INVALID_INDEX) throw ShaderError(where + " is missing");
  GLint active = 0, data_size = 0;
  glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS, &active);
  glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &data_size);
  for (const contract::UniformMember& m : members) {
    GLuint member = GL_INVALID_INDEX;
    glGetUniformIndices(program, 1, &m.name, &member);
    if (member == GL_INVALID_INDEX)
      throw ShaderError(where + ": member " + m.name + " (" + m.glsl_type + ", byte " + std::to_string(m.offset) +
                        " in C++) is not in the shader" + twin);
    GLint offset = -1;
    glGetActiveUniformsiv(program, 1, &member, GL_UNIFORM_OFFSET, &offset);
    if (offset != GLint(m.offset))
      throw ShaderError(where + ": member " + m.name + " is at byte " + std::to_string(offset) +
                        " for the driver but at byte " + std::to_string(m.offset) + " in C++" + twin);
  }
  if (size_t(active) != members.size())
    throw ShaderError(where + " has " + std::to_string(active) + " members but C++ knows " +
                      std::to_string(members.size()) + twin);
  if (size_t(data_size) < used || size_t(data_size) > size)
    throw ShaderError(where + " is " + std::to_string(data_size) + " bytes but its C++ struct holds " +
                      std::to_string(used) + " (" + std::to_string(size) + " with padding)" + twin);
  glUniformBlockBinding(program, index, binding);
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace draught::gpu
