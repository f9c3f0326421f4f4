// Helpers shared by the unit tests (header only; tests/CMakeLists.txt globs *.cpp).
#pragma once

#include "core/params/params.hpp"
#include "core/params/preset.hpp"
#include "core/vessel/vessel.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>

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

}  // namespace draught::test
