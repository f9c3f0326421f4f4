#include "gpu/shader_source.hpp"

#include "core/io/files.hpp"

#include <regex>
#include <sstream>

namespace draught::gpu {

namespace {

std::string load(const std::string& name, const std::filesystem::path& dir) {
  // Generated files ("generated/frame.glsl") always come from this binary: they must
  // match its C++ side, and a shader folder has none.
  if (!dir.empty() && name.rfind("generated/", 0) != 0) {
    try {
      return read_text_file(dir / name);
    } catch (const InputError& e) {
      throw ShaderError(e.what());
    }
  }
  for (auto& s : embedded_shaders())
    if (name == s.name) return s.text;
  throw ShaderError("shader file '" + name + "' is not embedded in this build");
}

void append(const std::string& name, const std::filesystem::path& dir, ShaderSource& out,
            std::vector<std::string>& stack) {
  for (auto& s : stack)
    if (s == name) throw ShaderError(name + ": included recursively");
  stack.push_back(name);
  const int index = int(out.files.size());
  out.files.push_back(name);
  std::istringstream in(load(name, dir));
  std::string line;
  int lineno = 0;
  static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
  // An include in a disabled #if block has its restoring #line skipped too: say it again
  // where a block ends or turns.
  static const std::regex branch_re(R"(^\s*#\s*(else|elif|endif)\b.*$)");
  while (std::getline(in, line)) {
    ++lineno;
    std::smatch m;
    if (std::regex_match(line, m, include_re)) {
      out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
      append(m[1], dir, out, stack);
      out.text += "#line " + std::to_string(lineno + 1) + " " + std::to_string(index) + "\n";
    } else {
      out.text += line + "\n";
      if (std::regex_match(line, branch_re))
        out.text += "#line " + std::to_string(lineno + 1) + " " + std::to_string(index) + "\n";
    }
  }
  stack.pop_back();
}

}  // namespace

ShaderSource assemble_shader(const std::string& entry, const std::filesystem::path& dir) {
  ShaderSource out;
  std::vector<std::string> stack;
  append(entry, dir, out, stack);
  return out;
}

std::string map_shader_log(const std::string& log, const ShaderSource& src) {
  static const std::regex loc_re(R"((?:ERROR: |WARNING: )?(\d+)(?::(\d+)\((\d+)\)|\((\d+)\)\s*|:(\d+)):)");
  std::string out;
  auto begin = log.cbegin();
  std::smatch m;
  while (std::regex_search(begin, log.cend(), m, loc_re)) {
    out.append(begin, m[0].first);
    size_t file = std::stoul(m[1]);
    std::string line = m[2].matched ? m[2].str() : m[4].matched ? m[4].str() : m[5].str();
    std::string name = file < src.files.size() ? src.files[file] : "source " + m[1].str();
    out += name + ":" + line + (m[3].matched ? ":" + m[3].str() : "") + ":";
    begin = m[0].second;
  }
  out.append(begin, log.cend());
  return out;
}

}  // namespace draught::gpu
