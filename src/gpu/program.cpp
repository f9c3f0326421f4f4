#include "gpu/program.hpp"

#include <vector>

namespace draught::gpu {

namespace {

GLuint compile(GLenum type, const ShaderSource& src) {
  GLuint s = glCreateShader(type);
  const char* text = src.text.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(size_t(len) + 1);
    glGetShaderInfoLog(s, len, nullptr, log.data());
    glDeleteShader(s);
    throw ShaderError("shader " + src.files.front() + " failed to compile:\n" + map_shader_log(log.data(), src));
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
    GLint len = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(size_t(len) + 1);
    glGetProgramInfoLog(id_, len, nullptr, log.data());
    glDeleteProgram(id_);
    throw ShaderError("program " + vertex.files.front() + " + " + fragment.files.front() +
                      " failed to link:\n" + map_shader_log(log.data(), fragment));
  }
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace draught::gpu
