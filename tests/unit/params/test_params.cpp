// The parameter table: descriptors, validation, text forms, and the preset round trip.
#include "core/io/files.hpp"
#include "core/params/param_row.hpp"
#include "core/params/params.hpp"
#include "core/params/preset.hpp"
#include "core/vessel/decal_files.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>

namespace draught {
namespace {

std::string show(const ParamDesc& d, const ParamValue& v) {
  try {
    return format_param(d, v);
  } catch (...) {
    return "<" + std::to_string(v.index()) + ">";
  }
}

// Params are compared field by field through the table (the struct has no ==).
::testing::AssertionResult params_equal(const Params& a, const Params& b) {
  for (const auto& d : param_table()) {
    const ParamValue va = get_param(a, d), vb = get_param(b, d);
    if (!(va == vb))
      return ::testing::AssertionFailure() << d.path << ": " << show(d, va) << " != " << show(d, vb);
  }
  return ::testing::AssertionSuccess();
}

// A valid value different from the default.
ParamValue other_value(const ParamDesc& d) {
  switch (d.type) {
    case ParamType::Float: {
      const float x = std::get<float>(d.def);
      return x != d.max ? d.max : d.min;
    }
    case ParamType::Int: {
      const int x = std::get<int>(d.def);
      return x != int(d.max) ? int(d.max) : int(d.min);
    }
    case ParamType::Bool: return !std::get<bool>(d.def);
    case ParamType::Vec3:
    case ParamType::Color: {
      const glm::vec3 x = std::get<glm::vec3>(d.def);
      glm::vec3 o;
      for (int i = 0; i < 3; ++i) o[i] = x[i] != d.max ? d.max : d.min;
      return o;
    }
    case ParamType::Enum:
      for (auto& c : d.choices)
        if (c != std::get<std::string>(d.def)) return c;
      return std::string();
    case ParamType::Curve: return Curve{{0.02f, 0.0f}, {0.025f, 0.03f}, {0.03f, 0.09f}};
    case ParamType::File:  // shipped: an environment, a decal, or the screen's clip
      if (d.path.starts_with("decal_")) return std::string(std::get<std::string>(d.def) == "crest" ? "wordmark" : "crest");
      if (d.path == "screen.source") return std::string("draught-loop");
      if (d.path == "matcap.file") return resolve_decal("crest").string();  // any PNG's path
      return std::string(std::get<std::string>(d.def) == "bar" ? "studio" : "bar");
  }
  return 0.0f;
}

// A value of the wrong type for each kind of parameter.
ParamValue wrong_type(const ParamDesc& d) {
  switch (d.type) {
    case ParamType::Float: return std::string("0.5");
    case ParamType::Int: return 2.0f;
    case ParamType::Bool: return 1;
    case ParamType::Vec3:
    case ParamType::Color: return 0.5f;
    case ParamType::Enum: return 0;
    case ParamType::Curve: return glm::vec3(0.03f, 0.0f, 0.1f);
    case ParamType::File: return 1.0f;
  }
  return 0.0f;
}

// Values of the right type but out of range (empty for Bool).
std::vector<ParamValue> out_of_range(const ParamDesc& d) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float above = d.max + std::max(1.0f, std::fabs(d.max)), below = d.min - std::max(1.0f, std::fabs(d.min));
  switch (d.type) {
    case ParamType::Float: return {above, below, nan, inf, -inf, std::nextafter(d.max, inf)};
    case ParamType::Int: return {int(d.max) + 1, int(d.min) - 1, -1000000};
    case ParamType::Bool: return {};
    case ParamType::Vec3:
    case ParamType::Color: {
      const glm::vec3 ok = std::get<glm::vec3>(d.def);
      std::vector<ParamValue> v;
      for (int i = 0; i < 3; ++i)
        for (float bad : {above, below, nan}) {
          glm::vec3 c = ok;
          c[i] = bad;
          v.emplace_back(std::in_place_type<glm::vec3>, c);
        }
      return v;
    }
    case ParamType::Enum: return {std::string("bogus"), std::string(""), std::string("Studio ")};
    case ParamType::Curve:
      return {
          Curve{},                                               // empty
          Curve{{0.03f, 0.0f}},                                  // one point
          Curve{{0.03f, 0.01f}, {0.04f, 0.1f}},                  // does not start at y = 0
          Curve{{0.03f, 0.0f}, {0.04f, 0.1f}, {0.05f, 0.1f}},    // y not strictly increasing
          Curve{{0.03f, 0.0f}, {0.04f, 0.1f}, {0.05f, 0.05f}},   // y going down
          Curve{{0.03f, 0.0f}, {0.0f, 0.1f}},                    // r below the minimum
          Curve{{0.03f, 0.0f}, {0.7f, 0.1f}},                    // r above the maximum
          Curve{{0.03f, 0.0f}, {0.04f, 0.7f}},                   // taller than the maximum
          Curve{{0.03f, 0.0f}, {0.04f, 0.01f}},                  // shorter than 2 cm
          Curve{{0.03f, 0.0f}, {nan, 0.1f}},                     // not a number
          Curve{{0.03f, 0.0f}, {0.04f, inf}},                    // infinite
          Curve(40, glm::vec2(0.03f, 0.0f)),                     // too many points (and flat)
      };
    case ParamType::File:
      return {std::string("a\nb.png"), std::string("tab\there"), std::string(1, '\0'),
              std::string(kMaxFileParamBytes + 1, 'x')};
  }
  return {};
}

TEST(ParamTable, PathsAreUniqueAndGrouped) {
  std::set<std::string> seen;
  const std::set<std::string> groups = {"glass", "liquid", "foam", "bubbles", "env", "light", "strips", "backlight", "screen", "camera", "clip", "decal_outer", "decal_inner", "condensation", "render", "matcap"};
  for (const auto& d : param_table()) {
    EXPECT_TRUE(seen.insert(d.path).second) << "duplicate path " << d.path;
    const auto dot = d.path.find('.');
    ASSERT_NE(dot, std::string::npos) << d.path;
    EXPECT_EQ(d.path.find('.', dot + 1), std::string::npos) << d.path << " has more than one dot";
    EXPECT_TRUE(groups.count(d.path.substr(0, dot))) << d.path;
    EXPECT_FALSE(d.doc.empty()) << d.path << " is undocumented";
    EXPECT_EQ(find_param(d.path), &d);
    if (d.type == ParamType::Enum) { EXPECT_GE(d.choices.size(), 2u) << d.path; }
    if (d.type != ParamType::Bool && d.type != ParamType::Enum && d.type != ParamType::File) {
      EXPECT_LT(d.min, d.max) << d.path;
    }
  }
  EXPECT_GE(seen.size(), 30u);
  EXPECT_EQ(find_param("liquid.nonexistent"), nullptr);
  EXPECT_EQ(find_param("liquid"), nullptr);
}

TEST(ParamTable, FieldsDoNotAlias) {
  // Every descriptor writes its own field: setting one parameter changes no other.
  for (const auto& d : param_table()) {
    Params p = default_params();
    set_param(p, d, other_value(d));
    for (const auto& e : param_table()) {
      if (&e == &d) { EXPECT_FALSE(get_param(p, e) == e.def) << d.path << " was not written"; }
      else { EXPECT_TRUE(get_param(p, e) == e.def) << "setting " << d.path << " changed " << e.path; }
    }
  }
}

// ------------------------------------------------------ typed rows, defaults --

// Whether the table's row builder accepts this row (it is constrained, so a mismatch is
// a compile error in the table; here it is asked without failing the build).
template <ParamType T, auto Group, auto Field>
constexpr bool row_compiles =
    requires { param_row<T, Group, Field>(std::string("g.f"), 0.0f, 1.0f, std::string(), std::string()); };

static_assert(row_compiles<ParamType::Float, &VesselParams::glass, &GlassParams::ior>);
static_assert(row_compiles<ParamType::Int, &VesselParams::foam, &FoamParams::seed>);
static_assert(row_compiles<ParamType::Bool, &SceneParams::env, &EnvParams::floor>);
static_assert(row_compiles<ParamType::Vec3, &SceneParams::light, &LightParams::direction>);
static_assert(row_compiles<ParamType::Color, &SceneParams::light, &LightParams::color>);
static_assert(row_compiles<ParamType::Enum, &SceneParams::env, &EnvParams::mode>);
static_assert(row_compiles<ParamType::Curve, &VesselParams::glass, &GlassParams::profile>);
// The wrong ParamType for the field's C++ type does not compile.
static_assert(!row_compiles<ParamType::Int, &VesselParams::glass, &GlassParams::ior>);
static_assert(!row_compiles<ParamType::Float, &VesselParams::foam, &FoamParams::seed>);
static_assert(!row_compiles<ParamType::Enum, &SceneParams::env, &EnvParams::floor>);
static_assert(!row_compiles<ParamType::Bool, &SceneParams::render, &RenderParams::supersample>);
static_assert(!row_compiles<ParamType::Vec3, &SceneParams::light, &LightParams::intensity>);
static_assert(!row_compiles<ParamType::Curve, &VesselParams::glass, &GlassParams::absorption>);
// A field of another group, or a group of neither VesselParams nor SceneParams.
static_assert(!row_compiles<ParamType::Float, &VesselParams::glass, &LiquidParams::ior>);
static_assert(!row_compiles<ParamType::Float, &VesselParams::liquid, &GlassParams::ior>);
static_assert(!row_compiles<ParamType::Float, &LiquidParams::fill, &LiquidParams::fill>);

TEST(ParamTable, DefaultConstructedParamsAreTheDefaults) {
  // Defaults live in the structs' initializers; the table reads them from there.
  const Params value_initialized{};
  Params default_initialized;
  EXPECT_TRUE(params_equal(value_initialized, default_params()));
  EXPECT_TRUE(params_equal(default_initialized, default_params()));
  for (const auto& d : param_table()) EXPECT_TRUE(get_param(value_initialized, d) == d.def) << d.path;
  // A few spelled out, so a changed initializer is noticed (docs/PRESETS.md lists all).
  EXPECT_EQ(default_initialized.liquid.fill, 0.85f);
  EXPECT_EQ(default_initialized.glass.ior, 1.52f);
  EXPECT_EQ(default_initialized.glass.profile,
            (Curve{{0.0295f, 0.0f}, {0.0345f, 0.05f}, {0.0395f, 0.10f}, {0.0435f, 0.15f}}));
  EXPECT_EQ(default_initialized.foam.big_bubbles, 6);
  EXPECT_EQ(default_initialized.bubbles.etched_base, false);
  EXPECT_EQ(default_initialized.env.mode, int(EnvMode::Studio));
  EXPECT_EQ(default_initialized.render.tonemap, int(Tonemap::Aces));
  EXPECT_EQ(default_initialized.light.direction, glm::vec3(-0.6f, 0.6f, 0.55f));
  EXPECT_EQ(default_initialized.camera.auto_frame, true);
  EXPECT_EQ(default_initialized.render.supersample, 2);
  EXPECT_TRUE(find_param("env.mode")->def == ParamValue(std::string("studio")));
  EXPECT_TRUE(find_param("render.tonemap")->def == ParamValue(std::string("aces")));
}

TEST(ParamTable, EveryDefaultIsWithinItsRange) {
  for (const auto& d : param_table()) {
    auto in = [&](float x) { return x >= d.min && x <= d.max; };
    switch (d.type) {
      case ParamType::Float: EXPECT_TRUE(in(std::get<float>(d.def))) << d.path; break;
      case ParamType::Int: EXPECT_TRUE(in(float(std::get<int>(d.def)))) << d.path; break;
      case ParamType::Vec3:
      case ParamType::Color: {
        const glm::vec3 v = std::get<glm::vec3>(d.def);
        EXPECT_TRUE(in(v.x) && in(v.y) && in(v.z)) << d.path;
        break;
      }
      case ParamType::Enum: {
        const auto& c = d.choices;
        EXPECT_NE(std::find(c.begin(), c.end(), std::get<std::string>(d.def)), c.end()) << d.path;
        break;
      }
      case ParamType::Curve:
        for (const glm::vec2& q : std::get<Curve>(d.def)) EXPECT_TRUE(in(q.x) && q.y >= 0 && q.y <= d.max) << d.path;
        break;
      case ParamType::Bool:
      case ParamType::File: break;
    }
    EXPECT_NO_THROW(validate_value(d, d.def)) << d.path;
  }
}

TEST(ParamTable, ScopeComesFromTheStructThatHoldsTheRow) {
  const std::set<std::string> vessel_groups = {"glass", "liquid", "foam", "bubbles", "clip", "decal_outer", "decal_inner", "condensation"};
  int vessel = 0, scene = 0;
  for (const auto& d : param_table()) {
    const bool is_vessel = vessel_groups.count(d.path.substr(0, d.path.find('.'))) > 0;
    EXPECT_EQ(d.scope, is_vessel ? ParamScope::Vessel : ParamScope::Scene) << d.path;
    // Exactly the accessors of its scope.
    EXPECT_EQ(d.vessel.get != nullptr, is_vessel) << d.path;
    EXPECT_EQ(d.vessel.set != nullptr, is_vessel) << d.path;
    EXPECT_EQ(d.scene.get != nullptr, !is_vessel) << d.path;
    EXPECT_EQ(d.scene.set != nullptr, !is_vessel) << d.path;
    (is_vessel ? vessel : scene)++;
  }
  EXPECT_EQ(scope_name(ParamScope::Scene), "scene");
  EXPECT_EQ(scope_name(ParamScope::Vessel), "object");
  EXPECT_GT(vessel, 30);
  EXPECT_GT(scene, 20);
}

TEST(ParamTable, VesselAndSceneStructsAreReachedDirectly) {
  VesselParams v;
  SceneParams s;
  set_param(v, *find_param("liquid.fill"), 0.5f);
  set_param(s, *find_param("env.mode"), std::string("constant"));
  EXPECT_EQ(v.liquid.fill, 0.5f);
  EXPECT_EQ(s.env.mode, int(EnvMode::Constant));
  EXPECT_TRUE(get_param(v, *find_param("liquid.fill")) == ParamValue(0.5f));
  EXPECT_TRUE(get_param(s, *find_param("env.mode")) == ParamValue(std::string("constant")));
  // A row of the other scope is a programming error, not a silent write elsewhere.
  EXPECT_THROW(get_param(v, *find_param("env.floor")), std::logic_error);
  EXPECT_THROW(set_param(s, *find_param("liquid.fill"), 0.5f), std::logic_error);
  // Validation still applies.
  EXPECT_THROW(set_param(v, *find_param("liquid.fill"), 2.0f), ParamError);
  EXPECT_EQ(v.liquid.fill, 0.5f);
}

TEST(ParamTable, EveryDefaultValidates) {
  const Params p = default_params();
  for (const auto& d : param_table()) {
    EXPECT_NO_THROW(validate_value(d, d.def)) << d.path;
    EXPECT_TRUE(get_param(p, d) == d.def) << d.path;
    EXPECT_NO_THROW(validate_value(d, other_value(d))) << d.path;
  }
}

TEST(ParamTable, DefaultsRoundTripThroughText) {
  for (const auto& d : param_table()) {
    const std::string text = format_param(d, d.def);
    ParamValue back;
    ASSERT_NO_THROW(back = parse_param_text(d, text)) << d.path << " = " << text;
    EXPECT_TRUE(back == d.def) << d.path << ": \"" << text << "\" parsed back as " << show(d, back);
    const ParamValue other = other_value(d);
    EXPECT_TRUE(parse_param_text(d, format_param(d, other)) == other) << d.path;
  }
}

TEST(ParamTable, TextFormsAsDocumented) {
  auto parse = [](const char* path, const char* text) { return parse_param_text(*find_param(path), text); };
  EXPECT_TRUE(parse("liquid.fill", "0.8") == ParamValue(0.8f));
  EXPECT_TRUE(parse("liquid.fill", " 0.5 ") == ParamValue(0.5f));
  EXPECT_TRUE(parse("env.floor", "true") == ParamValue(true));
  EXPECT_TRUE(parse("env.floor", "off") == ParamValue(false));
  EXPECT_TRUE(parse("env.floor", "0") == ParamValue(false));
  EXPECT_TRUE(parse("light.color", "1,0.5,0") == ParamValue(glm::vec3(1.0f, 0.5f, 0.0f)));
  EXPECT_TRUE(parse("light.color", "1, 0.5, 0") == ParamValue(glm::vec3(1.0f, 0.5f, 0.0f)));
  EXPECT_TRUE(parse("render.tonemap", "aces") == ParamValue(std::string("aces")));
  EXPECT_TRUE(parse("render.supersample", "3") == ParamValue(3));
  EXPECT_TRUE(parse("glass.profile", "0.03,0;0.035,0.15") == ParamValue(Curve{{0.03f, 0.0f}, {0.035f, 0.15f}}));
}

TEST(ParamTable, BadTextIsRejectedWithTheField) {
  const std::vector<std::pair<const char*, const char*>> bad = {
      {"liquid.fill", "abc"},        {"liquid.fill", ""},         {"liquid.fill", "0.5x"},
      {"liquid.fill", "1.5"},        {"liquid.fill", "nan"},      {"liquid.fill", "inf"},
      {"render.supersample", "2.5"}, {"render.supersample", "9"}, {"render.supersample", "two"},
      {"env.floor", "yes"},          {"env.floor", ""},           {"light.color", "1,0.5"},
      {"light.color", "1,0.5,0,1"},  {"light.color", "1,x,0"},    {"light.color", "2,0,0"},
      {"render.tonemap", "filmic"},  {"glass.profile", "0.03,0"}, {"glass.profile", "0.03,0;0.04"},
      {"glass.profile", "0.03,0.01;0.04,0.1"},
  };
  for (const auto& [path, text] : bad) {
    const ParamDesc& d = *find_param(path);
    try {
      parse_param_text(d, text);
      ADD_FAILURE() << path << " accepted \"" << text << "\"";
    } catch (const ParamError& e) {
      EXPECT_EQ(e.field, path);
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("expected"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("\"" + std::string(text) + "\""), std::string::npos)
          << "the message should quote the bad text: " << e.what();
    }
  }
}

TEST(ParamTable, HugeIntegerTextIsRejected) {
  // Whole numbers far outside int must be rejected, not wrapped or converted with
  // undefined behaviour into range.
  const ParamDesc& d = *find_param("render.supersample");
  for (const char* text : {"1e10", "4294967298", "-4294967294", "3e38", "-1e30"})
    EXPECT_THROW(parse_param_text(d, text), ParamError) << text;
}

TEST(ParamTable, SetParamRejectsBadValuesAndChangesNothing) {
  const Params base = default_params();
  int rejected = 0;
  for (const auto& d : param_table()) {
    std::vector<ParamValue> bad = out_of_range(d);
    bad.push_back(wrong_type(d));
    for (const ParamValue& v : bad) {
      Params p = base;
      try {
        set_param(p, d, v);
        ADD_FAILURE() << d.path << " accepted a bad value (" << show(d, v) << ")";
      } catch (const ParamError& e) {
        ++rejected;
        EXPECT_EQ(e.field, d.path);
        EXPECT_FALSE(e.expected.empty());
        EXPECT_EQ(std::string(e.what()), d.path + ": expected " + e.expected);
      }
      EXPECT_TRUE(params_equal(p, base)) << "after rejecting a value for " << d.path;
    }
  }
  EXPECT_GT(rejected, 150);
}

TEST(ParamTable, RangesAreInclusive) {
  for (const auto& d : param_table()) {
    if (d.type == ParamType::Float) {
      EXPECT_NO_THROW(validate_value(d, d.min)) << d.path;
      EXPECT_NO_THROW(validate_value(d, d.max)) << d.path;
    } else if (d.type == ParamType::Int) {
      EXPECT_NO_THROW(validate_value(d, int(d.min))) << d.path;
      EXPECT_NO_THROW(validate_value(d, int(d.max))) << d.path;
    }
  }
}

TEST(ParamTable, ExpectedTextNamesTheRange) {
  EXPECT_EQ(expected_text(*find_param("liquid.fill")), "a number in [0, 0.98]");
  EXPECT_EQ(expected_text(*find_param("render.supersample")), "a whole number in [1, 4]");
  EXPECT_EQ(expected_text(*find_param("env.floor")), "true or false");
  EXPECT_EQ(expected_text(*find_param("render.tonemap")), "one of \"none\", \"aces\"");
}

TEST(ParamTable, UnknownParameterSuggestsTheNearest) {
  EXPECT_NE(unknown_param_message("liquid.srn").find("did you mean 'liquid.srm'"), std::string::npos);
  EXPECT_NE(unknown_param_message("glass.ior_").find("did you mean 'glass.ior'"), std::string::npos);
  EXPECT_NE(unknown_param_message("camera.fov").find("did you mean 'camera.vfov'"), std::string::npos);
  const std::string far = unknown_param_message("completely.different");
  EXPECT_NE(far.find("unknown parameter 'completely.different'"), std::string::npos);
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
}

// --------------------------------------------------------------- presets --

Params all_other_values() {
  Params p = default_params();
  for (const auto& d : param_table()) set_param(p, d, other_value(d));
  return p;
}

TEST(PresetRoundTrip, DefaultsSurviveJsonAndApply) {
  const Params defaults = default_params();
  const std::string json = preset_json(defaults, "scene", "everything", "all parameters", {});
  const Preset preset = parse_preset(json, "roundtrip.json");
  EXPECT_EQ(preset.kind, "scene");
  EXPECT_EQ(preset.name, "everything");
  EXPECT_EQ(preset.description, "all parameters");
  EXPECT_EQ(preset.values.size(), param_table().size());
  Params p = all_other_values();
  for (const auto& d : param_table()) ASSERT_FALSE(get_param(p, d) == d.def) << d.path;
  apply_preset(preset, p);
  EXPECT_TRUE(params_equal(p, defaults));
}

TEST(PresetRoundTrip, OtherValuesSurviveToo) {
  const Params src = all_other_values();
  Params p = default_params();
  apply_preset(parse_preset(preset_json(src, "scene", "other", "", {}), "other.json"), p);
  EXPECT_TRUE(params_equal(p, src));
}

TEST(PresetRoundTrip, GroupsSelectWhatIsWritten) {
  const Params src = all_other_values();
  const Preset glass = parse_preset(preset_json(src, "glass", "g", "", {"glass"}), "g.json");
  EXPECT_EQ(glass.kind, "glass");
  Params p = default_params();
  apply_preset(glass, p);
  for (const auto& d : param_table()) {
    if (d.path.starts_with("glass.")) { EXPECT_TRUE(get_param(p, d) == get_param(src, d)) << d.path; }
    else { EXPECT_TRUE(get_param(p, d) == d.def) << d.path; }
  }
  const Preset drink = parse_preset(preset_json(src, "drink", "d", "", {"liquid"}), "d.json");
  for (auto& [d, v] : drink.values) EXPECT_TRUE(d->path.starts_with("liquid.")) << d->path;
}

// ------------------------------------------------------- shipped presets --

std::vector<std::filesystem::path> preset_files(const char* sub) {
  std::vector<std::filesystem::path> files;
  for (auto& e : std::filesystem::directory_iterator(test::preset_source_dir() / sub))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedPresets, AtLeastFiveGlassesAndFiveDrinks) {
  EXPECT_GE(preset_files("glasses").size(), 5u);
  EXPECT_GE(preset_files("drinks").size(), 5u);
}

TEST(ShippedPresets, GlassesLoadAndMakeSensibleVessels) {
  for (const auto& f : preset_files("glasses")) {
    Preset p;
    ASSERT_NO_THROW(p = load_preset(f)) << f;
    EXPECT_EQ(p.kind, "glass") << f;
    EXPECT_EQ(p.name, f.stem().string()) << f;
    EXPECT_FALSE(p.description.empty()) << f;
    Params params = default_params();
    apply_preset(p, params);
    const Vessel v = build_vessel(params.glass);
    // Between a shot glass and a litre, taller than wide, with room for the liquid.
    EXPECT_GT(v.cavity_volume(), 100e-6) << f;
    EXPECT_LT(v.cavity_volume(), 1000e-6) << f;
    EXPECT_GT(v.height, 0.1) << f;
    EXPECT_LT(v.base, v.height - 0.02) << f;
    EXPECT_GT(v.inner_radius(v.base + 0.5 * (v.height - v.base)), 0.0) << f;
    // The designer's base thickness is what the vessel uses (no clamping needed).
    EXPECT_NEAR(v.base, double(params.glass.base_thickness), 1e-12) << f;
  }
}

TEST(ShippedPresets, DrinksLoadAndSuggestExistingGlasses) {
  for (const auto& f : preset_files("drinks")) {
    Preset p;
    ASSERT_NO_THROW(p = load_preset(f)) << f;
    EXPECT_EQ(p.kind, "drink") << f;
    EXPECT_EQ(p.name, f.stem().string()) << f;
    EXPECT_FALSE(p.values.empty()) << f;
    for (auto& [d, v] : p.values) EXPECT_TRUE(d->path.starts_with("liquid.") || d->path.starts_with("foam.") || d->path.starts_with("bubbles.")) << f << ": " << d->path;
    if (!p.suggested_glass.empty()) {
      EXPECT_TRUE(std::filesystem::exists(test::preset_source_dir() / "glasses" / (p.suggested_glass + ".json")))
          << f << " suggests a missing glass " << p.suggested_glass;
    }
  }
}

TEST(ShippedPresets, FindPresetLooksInKindFolders) {
  EXPECT_EQ(std::filesystem::canonical(find_preset("pint", "glass")),
            std::filesystem::canonical(test::preset_source_dir() / "glasses" / "pint.json"));
  EXPECT_EQ(std::filesystem::canonical(find_preset("stout", "drink")),
            std::filesystem::canonical(test::preset_source_dir() / "drinks" / "stout.json"));
  try {
    find_preset("no-such-glass", "glass");
    ADD_FAILURE() << "found a missing preset";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-glass"), std::string::npos) << e.what();
  }
  EXPECT_THROW(find_preset("/nonexistent/dir/x.json", "glass"), InputError);
}

}  // namespace
}  // namespace draught
