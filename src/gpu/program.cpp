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

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace draught::gpu
