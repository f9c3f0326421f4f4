#include "gpu/shader_source.hpp"

#include "core/io/files.hpp"

#include <algorithm>
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

// What the joining knows of the preprocessor: how deep in #if blocks a line is, not
// counting include guards, and which guarded files it has joined there in full. Such a
// file joined again is empty to the preprocessor (its guard is defined), so it is left out:
// the library's diamond of includes otherwise repeated generated/frame.glsl 119 times and
// made the path pass 4.9 MB of text for every compiler to read.
struct Joining {
  std::vector<std::string> stack;  // the files being joined, the outermost first
  int depth = 0;                   // open #if blocks that are not guards, in all of them
  std::vector<std::string> whole;  // guarded files joined at depth 0
};

// The line of a file's include guard: its first directive `#ifndef G`, when the second is
// `#define G`; 0 when it has none.
int include_guard_line(const std::string& text) {
  static const std::regex directive_re(R"(^\s*#\s*(\w+)\s*(\w*).*$)");
  std::istringstream in(text);
  std::string line, guard;
  int lineno = 0, guard_line = 0;
  std::smatch m;
  while (std::getline(in, line)) {
    ++lineno;
    if (!std::regex_match(line, m, directive_re)) continue;
    if (guard_line == 0) {
      if (m[1] != "ifndef") return 0;
      guard = m[2];
      guard_line = lineno;
    } else {
      return m[1] == "define" && m[2] == guard ? guard_line : 0;
    }
  }
  return 0;
}

// Joins `name` (and what it includes) to out; returns whether it has an include guard.
bool append(const std::string& name, const std::filesystem::path& dir, ShaderSource& out, Joining& j) {
  for (auto& s : j.stack)
    if (s == name) throw ShaderError(name + ": included recursively");
  const std::string text = load(name, dir);
  const int guard_line = include_guard_line(text);
  j.stack.push_back(name);
  const int index = int(out.files.size());
  out.files.push_back(name);
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
  static const std::regex open_re(R"(^\s*#\s*if(n?def)?\b.*$)");
  // An include in a disabled #if block has its restoring #line skipped too: say it again
  // where a block ends or turns.
  static const std::regex branch_re(R"(^\s*#\s*(else|elif|endif)\b.*$)");
  std::vector<bool> blocks;  // this file's open #if blocks, true for its guard
  while (std::getline(in, line)) {
    ++lineno;
    std::smatch m;
    if (std::regex_match(line, m, include_re)) {
      const std::string file = m[1];
      if (std::find(j.whole.begin(), j.whole.end(), file) != j.whole.end()) {
        out.text += "\n";  // joined whole before: nothing to the preprocessor now
        continue;
      }
      out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
      if (append(file, dir, out, j) && j.depth == 0) j.whole.push_back(file);
      out.text += "#line " + std::to_string(lineno + 1) + " " + std::to_string(index) + "\n";
      continue;
    }
    out.text += line + "\n";
    if (std::regex_match(line, m, open_re)) {
      blocks.push_back(lineno == guard_line);
      if (!blocks.back()) ++j.depth;
    } else if (std::regex_match(line, m, branch_re)) {
      out.text += "#line " + std::to_string(lineno + 1) + " " + std::to_string(index) + "\n";
      if (m[1] == "endif" && !blocks.empty()) {
        if (!blocks.back()) --j.depth;
        blocks.pop_back();
      }
    }
  }
  if (!blocks.empty()) throw ShaderError(name + ": an #if block is not closed");
  j.stack.pop_back();
  return guard_line > 0;
}

}  // namespace

ShaderSource assemble_shader(const std::string& entry, const std::filesystem::path& dir) {
  ShaderSource out;
  Joining j;
  append(entry, dir, out, j);
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
