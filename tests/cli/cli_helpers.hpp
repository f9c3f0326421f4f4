// Helpers for the end-to-end tests of the `draught` binary: run it as a user would
// (separate stdout/stderr, exit code), fresh temporary folders, PNG header checks.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace draught_cli_test {

namespace fs = std::filesystem;

inline const fs::path kExe = DRAUGHT_EXE;
inline const fs::path kSourceDir = DRAUGHT_SOURCE_DIR;

// ECMAScript regular expressions (std::regex), compiled in cli_regex.cpp alone: <regex>
// took about 4 s of every test file that included it.
bool matches(const std::string& text, const std::string& pattern);
// The first group of the first match of `pattern` in `text`; "" when nothing matches.
std::string first_group(const std::string& text, const std::string& pattern);
// A pattern that matches `literal` as it is (a path with dots, brackets, ...).
std::string literal_pattern(const std::string& literal);

struct RunResult {
  int exit_code = -1;  // 128 + signal when killed by a signal
  std::string out, err;
  bool timed_out = false;
  std::string describe() const {
    return "exit code " + std::to_string(exit_code) + (timed_out ? " (timed out)" : "") + "\n--- stdout ---\n" +
           out + "--- stderr ---\n" + err + "--------------";
  }
};

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// Runs `draught args...` with stdin from /dev/null; stdout and stderr go to files in
// `capture_dir` (never the output folder the test inspects). `env` overrides (value) or
// removes (nullopt) environment variables for the child only.
inline RunResult run_draught(const std::vector<std::string>& args, const fs::path& capture_dir,
                             const std::map<std::string, std::optional<std::string>>& env = {},
                             std::chrono::seconds timeout = std::chrono::seconds(60)) {
  static std::atomic<int> counter{0};
  fs::create_directories(capture_dir);
  const int n = counter++;
  const fs::path out_path = capture_dir / ("stdout-" + std::to_string(n));
  const fs::path err_path = capture_dir / ("stderr-" + std::to_string(n));

  std::vector<std::string> argv_s = {kExe.string()};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);

  // The suite pins Mesa's software rasterizer and the source tree's presets unless the
  // test says otherwise.
  std::map<std::string, std::optional<std::string>> overrides = {{"DRAUGHT_DEVICE", "software"},
                                                                 {"DRAUGHT_PRESET_DIR", std::nullopt}};
  if (const char* d = std::getenv("DRAUGHT_DEVICE"); d && *d) overrides["DRAUGHT_DEVICE"] = std::string(d);
  for (auto& [k, v] : env) overrides[k] = v;
  std::vector<std::string> env_s;
  for (char** e = environ; *e; ++e) {
    std::string entry = *e;
    if (!overrides.count(entry.substr(0, entry.find('=')))) env_s.push_back(entry);
  }
  for (auto& [k, v] : overrides)
    if (v) env_s.push_back(k + "=" + *v);
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  RunResult r;
  int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    r.err = "posix_spawn of " + kExe.string() + " failed: " + std::to_string(rc);
    return r;
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0) return r;
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  r.out = read_file(out_path);
  r.err = read_file(err_path);
  fs::remove(out_path);
  fs::remove(err_path);
  return r;
}

// Everything (recursively) under `dir`, relative, sorted; empty when dir does not exist.
inline std::vector<std::string> list_tree(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return out;
  // Lexically relative and with error codes: a file that a run renames away between the
  // listing and the look (a frame's temporary) must not throw (fs::relative asks the file
  // system for the canonical path, which a vanished file has not).
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    out.push_back(it->path().lexically_relative(dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

inline std::string join(const std::vector<std::string>& v, const std::string& sep = ", ") {
  std::string s;
  for (auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

// `s` with the first `from` replaced by `to` (a test fails when `from` is not there).
inline std::string replace(std::string s, const std::string& from, const std::string& to) {
  auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

// What the header of a PNG file says; `error` is empty when the file is a well-formed
// PNG (signature, IHDR first, IEND last).
struct PngInfo {
  std::string error;
  uint32_t width = 0, height = 0;
  int bit_depth = 0, color_type = -1;
};

inline uint32_t be32(const std::string& s, size_t at) {
  return (uint32_t(uint8_t(s[at])) << 24) | (uint32_t(uint8_t(s[at + 1])) << 16) |
         (uint32_t(uint8_t(s[at + 2])) << 8) | uint32_t(uint8_t(s[at + 3]));
}

inline PngInfo png_info(const fs::path& p) {
  PngInfo info;
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) {
    info.error = p.string() + ": no such file";
    return info;
  }
  const std::string b = read_file(p);
  static const std::string sig("\x89PNG\r\n\x1a\n", 8);
  static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  if (b.size() < 8 + 25 + 12 || b.compare(0, 8, sig) != 0) {
    info.error = p.string() + ": no PNG signature (" + std::to_string(b.size()) + " bytes)";
    return info;
  }
  if (be32(b, 8) != 13 || b.compare(12, 4, "IHDR") != 0) {
    info.error = p.string() + ": first chunk is not a 13-byte IHDR";
    return info;
  }
  if (b.compare(b.size() - 12, 12, iend) != 0) {
    info.error = p.string() + ": does not end with an IEND chunk (truncated?)";
    return info;
  }
  info.width = be32(b, 16);
  info.height = be32(b, 20);
  info.bit_depth = uint8_t(b[24]);
  info.color_type = uint8_t(b[25]);
  return info;
}

// A fresh, empty folder per test (removed afterwards): in/ for inputs the test writes,
// out/ for images, cap/ for the captured stdout and stderr of runs.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "-" + info->name();
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
    dir_ = fs::temp_directory_path() /
           ("draught-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + name);
    fs::remove_all(dir_);
    fs::create_directories(in());
    fs::create_directories(out());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  fs::path in() const { return dir_ / "in"; }
  fs::path out() const { return dir_ / "out"; }

  // `draught <args...>`. A render traces the floor's light map from 20,000 photons unless
  // the args set the budget: a still's 500,000 were 1.3 of a 32x32 render's 2.3 s of CPU,
  // and an animation traces it again for every frame whose pose moved. The full budget is
  // the GPU suite's and the goldens'.
  RunResult draught(std::vector<std::string> args, const std::map<std::string, std::optional<std::string>>& env = {}) {
    const bool sets_budget = std::any_of(args.begin(), args.end(),
                                         [](const std::string& a) { return a.rfind("render.floor_photons=", 0) == 0; });
    if (!args.empty() && args[0] == "render" && !sets_budget)
      args.insert(args.begin() + 1, {"--set", "render.floor_photons=20000"});
    return run_draught(args, dir_ / "cap", env);
  }

  // A small, fast render: `size` and 1 sample per pixel unless the args say otherwise.
  RunResult render(std::vector<std::string> args, const std::string& size = "32x32",
                   const std::map<std::string, std::optional<std::string>>& env = {}) {
    auto has = [&](const char* opt) { return std::find(args.begin(), args.end(), opt) != args.end(); };
    std::vector<std::string> a = {"render"};
    if (!has("--size") && !has("-s")) a.insert(a.end(), {"--size", size});
    if (!has("--supersample")) a.insert(a.end(), {"--supersample", "1"});
    a.insert(a.end(), args.begin(), args.end());
    return draught(a, env);
  }

  // A failed command: non-zero exit, nothing claimed on stdout, every needle in stderr,
  // and nothing at all (no image, no temporary file) left in out/.
  void expect_failure(const RunResult& r, const std::vector<std::string>& needles) {
    EXPECT_NE(r.exit_code, 0) << r.describe();
    EXPECT_FALSE(r.timed_out) << r.describe();
    EXPECT_LT(r.exit_code, 128) << "crashed instead of reporting an error\n" << r.describe();
    EXPECT_FALSE(contains(r.out, "wrote")) << r.describe();
    EXPECT_FALSE(r.err.empty()) << "no error message\n" << r.describe();
    for (auto& n : needles) EXPECT_TRUE(contains(r.err, n)) << "stderr lacks \"" << n << "\"\n" << r.describe();
    EXPECT_EQ(join(list_tree(out())), "") << "files left in the output folder";
  }

  fs::path dir_;
};

}  // namespace draught_cli_test
