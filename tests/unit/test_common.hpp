// Helpers shared by the unit tests (header only; tests/CMakeLists.txt globs *.cpp).
#pragma once

#include "core/io/files.hpp"
#include "core/params/params.hpp"
#include "core/params/preset.hpp"
#include "core/vessel/vessel.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <unistd.h>

namespace draught::test {

inline std::filesystem::path preset_source_dir() { return DRAUGHT_PRESET_SOURCE_DIR; }

// Default parameters with a shipped glass preset applied.
inline Params params_with_glass(const std::string& name) {
  Params p = default_params();
  apply_preset(load_preset(preset_source_dir() / "glasses" / (name + ".json")), p);
  return p;
}

inline Vessel preset_vessel(const std::string& name) { return build_vessel(params_with_glass(name).glass); }

// A glass with the given outer profile; thickness etc. as given.
inline GlassParams simple_glass(Curve profile, float wall, float base, float rim) {
  GlassParams g = default_params().glass;
  g.profile = std::move(profile);
  g.wall_thickness = wall;
  g.base_thickness = base;
  g.rim_radius = rim;
  return g;
}

// Does an error message contain every part? (names the missing one)
inline ::testing::AssertionResult has(const std::string& message, std::initializer_list<std::string> parts) {
  for (const auto& p : parts)
    if (message.find(p) == std::string::npos)
      return ::testing::AssertionFailure() << "message \"" << message << "\" lacks \"" << p << "\"";
  return ::testing::AssertionSuccess();
}

// The message of the InputError that `f` throws; "no error" where it throws none.
inline std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A fresh, empty folder per test (dir_), named after the suite's prefix, the process and
// the test, removed afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  explicit TempDirTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + "-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace draught::test
