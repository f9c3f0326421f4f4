#include "core/params/params.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace draught {

namespace {

// One row per tunable. The macro keeps the path string and the struct field in step.
#define DRAUGHT_FIELD(member) [](Params& p) -> void* { return &p.member; }
#define ROW(member, type, def, lo, hi, unit, doc) \
  ParamDesc{#member, ParamType::type, ParamValue(def), lo, hi, unit, doc, {}, DRAUGHT_FIELD(member)}
#define ENUM_ROW(member, def, choices, doc) \
  ParamDesc{#member, ParamType::Enum, ParamValue(std::string(def)), 0, 0, "", doc, choices, DRAUGHT_FIELD(member)}

using glm::vec3;

std::vector<ParamDesc> make_table() {
  const Curve pint = {{0.0295f, 0.0f}, {0.0345f, 0.05f}, {0.0395f, 0.10f}, {0.0435f, 0.15f}};
  return {
      // glass
      ROW(glass.profile, Curve, pint, 0.0005f, 0.6f, "m",
          "Outer profile: control points (r, y) of a smooth curve, y from 0 (the foot) up to the rim"),
      ROW(glass.wall_thickness, Float, 0.003f, 0.0005f, 0.02f, "m", "Wall thickness, measured horizontally"),
      ROW(glass.base_thickness, Float, 0.012f, 0.001f, 0.3f, "m",
          "Height of solid glass under the cavity (the base, or foot and stem)"),
      ROW(glass.rim_radius, Float, 0.0015f, 0.0002f, 0.02f, "m",
          "Radius of the torus bead at the rim (kept between half and twice the wall thickness)"),
      ROW(glass.ior, Float, 1.52f, 1.0f, 2.5f, "", "Index of refraction of the glass"),
      ROW(glass.roughness, Float, 0.03f, 0.005f, 1.0f, "", "GGX roughness of the glass surfaces (highlights)"),
      ROW(glass.absorption, Vec3, vec3(0.9f, 0.25f, 0.7f), 0.0f, 1000.0f, "1/m",
          "Beer-Lambert absorption of the glass (soda-lime is slightly green)"),
      // liquid
      ROW(liquid.fill, Float, 0.85f, 0.0f, 0.98f, "", "Fill level as a fraction of the cavity volume"),
      ROW(liquid.ior, Float, 1.34f, 1.0f, 2.0f, "", "Index of refraction of the liquid"),
      ROW(liquid.srm, Float, 4.0f, 0.0f, 100.0f, "SRM",
          "Beer colour (Standard Reference Method); > 0 derives the absorption, 0 uses liquid.absorption"),
      ROW(liquid.absorption, Vec3, vec3(1.0f, 4.0f, 20.0f), 0.0f, 20000.0f, "1/m",
          "Beer-Lambert absorption per metre (used when liquid.srm is 0)"),
      ROW(liquid.haze, Float, 0.0f, 0.0f, 2000.0f, "1/m", "Cloudiness: scattering coefficient per metre"),
      ROW(liquid.haze_color, Color, vec3(0.95f, 0.85f, 0.6f), 0.0f, 1.0f, "",
          "Single-scattering albedo of the haze"),
      ROW(liquid.roughness, Float, 0.02f, 0.005f, 1.0f, "", "GGX roughness of the liquid surface"),
      ROW(liquid.slosh_stiffness, Float, 1.0f, 0.25f, 4.0f, "",
          "Scales the sloshing frequency squared (1: a real drink in this glass)"),
      ROW(liquid.slosh_damping, Float, 0.06f, 0.005f, 1.0f, "",
          "Damping ratio of the sloshing surface (a few percent for water-like drinks, more for thick ones)"),
      ROW(liquid.wave_amplitude, Float, 1.0f, 0.0f, 5.0f, "", "How strongly shaking raises waves on the surface"),
      ROW(liquid.wave_speed, Float, 1.0f, 0.25f, 4.0f, "", "Scales the frequency of the surface waves"),
      // foam head
      ROW(foam.height, Float, 0.015f, 0.0f, 0.08f, "m", "Head thickness once poured and settled (0: no head)"),
      ROW(foam.density, Float, 1500.0f, 50.0f, 20000.0f, "1/m", "Extinction of the foam: how opaque the head is"),
      ROW(foam.color, Color, vec3(0.97f, 0.95f, 0.9f), 0.0f, 1.0f, "",
          "Single-scattering albedo of the foam (white for lager, tan for stout)"),
      ROW(foam.anisotropy, Float, 0.0f, -0.9f, 0.9f, "", "Henyey-Greenstein anisotropy of the foam's scattering"),
      ROW(foam.multiscatter, Float, 0.7f, 0.0f, 1.0f, "",
          "Weight of the multiple-scattering terms (brightens the inside of the head)"),
      ROW(foam.age, Float, 45.0f, 0.0f, 36000.0f, "s", "Seconds since the pour, for a still picture"),
      ROW(foam.rise_time, Float, 2.0f, 0.1f, 30.0f, "s", "How long the head takes to build during a pour"),
      ROW(foam.half_life, Float, 150.0f, 1.0f, 36000.0f, "s", "Time for the head to halve as it collapses"),
      ROW(foam.dome, Float, 0.2f, -0.5f, 0.5f, "", "Shape of the head: > 0 domed, < 0 concave"),
      ROW(foam.bubble_size, Float, 0.0012f, 0.0002f, 0.01f, "m", "Size of the micro bubbles in the head"),
      ROW(foam.detail, Float, 0.5f, 0.0f, 1.0f, "", "How much the micro bubbles break up the foam's density"),
      ROW(foam.big_bubbles, Int, 6, 0.0f, 12.0f, "", "Large shiny bubbles on top of the head that grow and pop"),
      ROW(foam.lacing, Float, 0.6f, 0.0f, 1.0f, "", "Foam rings left on the glass each time the level drops"),
      ROW(foam.seed, Int, 1, 0.0f, 1000000.0f, "", "Seed of the foam's randomness (big bubbles, lacing)"),
      // rising bubbles
      ROW(bubbles.carbonation, Float, 0.6f, 0.0f, 1.0f, "",
          "Dissolved CO2, 0 (still wine) to 1 (champagne): how many bubbles rise and how big"),
      ROW(bubbles.sites, Int, 40, 0.0f, 400.0f, "", "Nucleation sites on the inner wall and the floor"),
      ROW(bubbles.etched_base, Bool, false, 0.0f, 1.0f, "",
          "A ring of sites etched into the floor, as in many flutes: one fine, fast stream"),
      ROW(bubbles.size, Float, 0.0002f, 0.00002f, 0.001f, "m", "Bubble radius at birth (at full carbonation)"),
      ROW(bubbles.max_bubbles, Int, 500, 0.0f, 2000.0f, "", "Most bubbles alive at once"),
      ROW(bubbles.seed, Int, 1, 0.0f, 1000000.0f, "", "Seed of the nucleation sites and bubble jitter"),
      // environment
      ENUM_ROW(env.mode, "studio", (std::vector<std::string>{"studio", "constant"}),
               "studio: gradient sky, softbox and strip lights; constant: env.color everywhere"),
      ROW(env.color, Color, vec3(0.8f), 0.0f, 100.0f, "", "Radiance of the constant environment"),
      ROW(env.sky_top, Color, vec3(0.10f, 0.105f, 0.115f), 0.0f, 100.0f, "", "Studio sky colour at the zenith"),
      ROW(env.sky_horizon, Color, vec3(0.30f, 0.29f, 0.27f), 0.0f, 100.0f, "", "Studio sky colour at the horizon"),
      ROW(env.ground, Color, vec3(0.16f, 0.15f, 0.14f), 0.0f, 100.0f, "", "Studio colour below the horizon"),
      ROW(env.strip_intensity, Float, 3.0f, 0.0f, 100.0f, "", "Brightness of the two vertical strip lights"),
      ROW(env.backdrop_glow, Float, 2.0f, 0.0f, 100.0f, "", "Brightness of the glow behind the glass"),
      ROW(env.floor, Bool, true, 0.0f, 1.0f, "", "Show a checker floor at y = 0 with the glass's shadow"),
      ROW(env.checker_size, Float, 0.04f, 0.001f, 10.0f, "m", "Edge length of one floor checker square"),
      ROW(env.floor_a, Color, vec3(0.58f, 0.56f, 0.53f), 0.0f, 1.0f, "", "Floor albedo, light squares"),
      ROW(env.floor_b, Color, vec3(0.44f, 0.42f, 0.40f), 0.0f, 1.0f, "", "Floor albedo, dark squares"),
      // key light
      ROW(light.direction, Vec3, vec3(-0.55f, 0.75f, 0.45f), -1.0f, 1.0f, "",
          "Direction towards the key light (normalised)"),
      ROW(light.color, Color, vec3(1.0f, 0.97f, 0.92f), 0.0f, 1.0f, "", "Key light colour"),
      ROW(light.intensity, Float, 2.5f, 0.0f, 100.0f, "", "Key light intensity"),
      ROW(light.size, Float, 12.0f, 0.5f, 60.0f, "deg", "Angular radius of the key softbox"),
      // camera
      ROW(camera.auto_frame, Bool, true, 0.0f, 1.0f, "",
          "Frame the whole glass automatically, looking from the direction of eye - target"),
      ROW(camera.eye, Vec3, vec3(0.0f, 0.13f, 0.42f), -10.0f, 10.0f, "m", "Camera position"),
      ROW(camera.target, Vec3, vec3(0.0f, 0.075f, 0.0f), -10.0f, 10.0f, "m", "Point the camera looks at"),
      ROW(camera.vfov, Float, 28.0f, 5.0f, 120.0f, "deg", "Vertical field of view"),
      // cross-section
      ROW(clip.enabled, Bool, false, 0.0f, 1.0f, "", "Cut the glass and its contents open along a plane (capped cuts)"),
      ROW(clip.normal, Vec3, vec3(0.0f, 0.0f, 1.0f), -1.0f, 1.0f, "",
          "Normal of the cut, in the glass's frame: the side it points to is removed"),
      ROW(clip.offset, Float, 0.0f, -0.3f, 0.3f, "m", "Where the cut lies along its normal, from the glass's axis"),
      // output
      ENUM_ROW(render.tonemap, "aces", (std::vector<std::string>{"none", "aces"}),
               "none: clamp then sRGB; aces: filmic tone map then sRGB"),
      ROW(render.exposure, Float, 1.0f, 0.01f, 100.0f, "", "Linear exposure multiplier before tone mapping"),
      ROW(render.transparent, Bool, false, 0.0f, 1.0f, "",
          "Transparent background, premultiplied alpha (the floor is left out)"),
      ROW(render.supersample, Int, 2, 1.0f, 4.0f, "", "Supersampling factor per axis (anti-aliasing)"),
      ROW(render.max_events, Int, 12, 2.0f, 32.0f, "", "Most surface interactions followed per pixel"),
  };
}
#undef ROW
#undef ENUM_ROW
#undef DRAUGHT_FIELD

// The shortest decimal text that reads back as the same float.
std::string fmt(float v) {
  char buf[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, double(v));
    if (std::strtof(buf, nullptr) == v) break;
  }
  return buf;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (;;) {
    size_t p = s.find(sep, start);
    out.push_back(trim(s.substr(start, p == std::string_view::npos ? std::string_view::npos : p - start)));
    if (p == std::string_view::npos) break;
    start = p + 1;
  }
  return out;
}

bool parse_float(std::string_view s, float& out) {
  std::string str(trim(s));
  if (str.empty()) return false;
  char* end = nullptr;
  double v = std::strtod(str.c_str(), &end);
  if (end != str.c_str() + str.size() || !std::isfinite(v)) return false;
  out = float(v);
  return true;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t prev = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t cur = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, prev + (a[i - 1] != b[j - 1])});
      prev = cur;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string unknown_param_message(const std::string& path) {
  const ParamDesc* best = nullptr;
  size_t best_d = 4;
  for (auto& d : param_table()) {
    size_t e = edit_distance(path, d.path);
    if (e < best_d) best_d = e, best = &d;
  }
  return "unknown parameter '" + path + "'" + (best ? " (did you mean '" + best->path + "'?)" : "") +
         "; `draught params` lists them";
}



std::string_view type_name(ParamType t) {
  switch (t) {
    case ParamType::Float: return "float";
    case ParamType::Int: return "int";
    case ParamType::Bool: return "bool";
    case ParamType::Vec3: return "vec3";
    case ParamType::Color: return "color";
    case ParamType::Enum: return "enum";
    case ParamType::Curve: return "curve";
  }
  return "?";
}

const std::vector<ParamDesc>& param_table() {
  static const std::vector<ParamDesc> table = make_table();
  return table;
}

const ParamDesc* find_param(std::string_view path) {
  for (const auto& d : param_table())
    if (d.path == path) return &d;
  return nullptr;
}

std::string expected_text(const ParamDesc& d) {
  const std::string range = "[" + fmt(d.min) + ", " + fmt(d.max) + "]";
  switch (d.type) {
    case ParamType::Float: return "a number in " + range;
    case ParamType::Int: return "a whole number in " + range;
    case ParamType::Bool: return "true or false";
    case ParamType::Vec3: return "three numbers, each in " + range;
    case ParamType::Color: return "an RGB colour: three numbers, each in " + range;
    case ParamType::Enum: {
      std::string s = "one of";
      for (size_t i = 0; i < d.choices.size(); ++i) s += (i ? ", \"" : " \"") + d.choices[i] + "\"";
      return s;
    }
    case ParamType::Curve:
      return "2 to 32 points [r, y] with r in [" + fmt(d.min) + ", " + fmt(d.max) +
             "], y starting at 0 and strictly increasing up to at most " + fmt(d.max) + " (a glass at least 0.02 m tall)";
  }
  return "?";
}

void validate_value(const ParamDesc& d, const ParamValue& v) {
  auto fail = [&] { throw ParamError(d.path, expected_text(d)); };
  auto in = [&](float x) { return std::isfinite(x) && x >= d.min && x <= d.max; };
  switch (d.type) {
    case ParamType::Float:
      if (!std::holds_alternative<float>(v) || !in(std::get<float>(v))) fail();
      break;
    case ParamType::Int:
      if (!std::holds_alternative<int>(v) || !in(float(std::get<int>(v)))) fail();
      break;
    case ParamType::Bool:
      if (!std::holds_alternative<bool>(v)) fail();
      break;
    case ParamType::Vec3:
    case ParamType::Color: {
      if (!std::holds_alternative<glm::vec3>(v)) fail();
      auto c = std::get<glm::vec3>(v);
      if (!in(c.x) || !in(c.y) || !in(c.z)) fail();
      break;
    }
    case ParamType::Enum: {
      if (!std::holds_alternative<std::string>(v)) fail();
      bool ok = false;
      for (auto& c : d.choices) ok |= c == std::get<std::string>(v);
      if (!ok) fail();
      break;
    }
    case ParamType::Curve: {
      if (!std::holds_alternative<Curve>(v)) fail();
      const Curve& c = std::get<Curve>(v);
      if (c.size() < 2 || c.size() > 32 || c.front().y != 0.0f) fail();
      for (size_t i = 0; i < c.size(); ++i) {
        if (!in(c[i].x) || !std::isfinite(c[i].y) || c[i].y < 0 || c[i].y > d.max) fail();
        if (i > 0 && !(c[i].y > c[i - 1].y)) fail();
      }
      if (c.back().y < 0.02f) throw ParamError(d.path, "a glass at least 0.02 m tall");
      break;
    }
  }
}

ParamValue get_param(const Params& p, const ParamDesc& d) {
  void* f = d.field(const_cast<Params&>(p));
  switch (d.type) {
    case ParamType::Float: return *static_cast<float*>(f);
    case ParamType::Int: return *static_cast<int*>(f);
    case ParamType::Bool: return *static_cast<bool*>(f);
    case ParamType::Vec3:
    case ParamType::Color: return *static_cast<glm::vec3*>(f);
    case ParamType::Enum: return d.choices.at(size_t(*static_cast<int*>(f)));
    case ParamType::Curve: return *static_cast<Curve*>(f);
  }
  return 0.0f;
}

void set_param(Params& p, const ParamDesc& d, const ParamValue& v) {
  validate_value(d, v);
  void* f = d.field(p);
  switch (d.type) {
    case ParamType::Float: *static_cast<float*>(f) = std::get<float>(v); break;
    case ParamType::Int: *static_cast<int*>(f) = std::get<int>(v); break;
    case ParamType::Bool: *static_cast<bool*>(f) = std::get<bool>(v); break;
    case ParamType::Vec3:
    case ParamType::Color: *static_cast<glm::vec3*>(f) = std::get<glm::vec3>(v); break;
    case ParamType::Enum:
      for (size_t i = 0; i < d.choices.size(); ++i)
        if (d.choices[i] == std::get<std::string>(v)) *static_cast<int*>(f) = int(i);
      break;
    case ParamType::Curve: *static_cast<Curve*>(f) = std::get<Curve>(v); break;
  }
}

Params default_params() {
  Params p{};
  for (const auto& d : param_table()) set_param(p, d, d.def);
  return p;
}

ParamValue parse_param_text(const ParamDesc& d, std::string_view text) {
  auto fail = [&]() -> ParamValue {
    throw ParamError(d.path, expected_text(d) + ", got \"" + std::string(text) + "\"");
  };
  ParamValue v;
  switch (d.type) {
    case ParamType::Float: {
      float x;
      if (!parse_float(text, x)) return fail();
      v = x;
      break;
    }
    case ParamType::Int: {
      float x;
      if (!parse_float(text, x) || x != std::floor(x) || x < d.min || x > d.max) return fail();
      v = int(x);
      break;
    }
    case ParamType::Bool: {
      auto t = trim(text);
      if (t == "true" || t == "1" || t == "on") v = true;
      else if (t == "false" || t == "0" || t == "off") v = false;
      else return fail();
      break;
    }
    case ParamType::Vec3:
    case ParamType::Color: {
      auto parts = split(text, ',');
      glm::vec3 c;
      if (parts.size() != 3) return fail();
      for (int i = 0; i < 3; ++i)
        if (!parse_float(parts[size_t(i)], c[i])) return fail();
      v = c;
      break;
    }
    case ParamType::Enum: v = std::string(trim(text)); break;
    case ParamType::Curve: {
      Curve c;
      for (auto pt : split(text, ';')) {
        auto xy = split(pt, ',');
        glm::vec2 q;
        if (xy.size() != 2 || !parse_float(xy[0], q.x) || !parse_float(xy[1], q.y)) return fail();
        c.push_back(q);
      }
      v = c;
      break;
    }
  }
  try {
    validate_value(d, v);
  } catch (const ParamError&) {
    return fail();
  }
  return v;
}

std::string format_param(const ParamDesc& d, const ParamValue& v) {
  switch (d.type) {
    case ParamType::Float: return fmt(std::get<float>(v));
    case ParamType::Int: return std::to_string(std::get<int>(v));
    case ParamType::Bool: return std::get<bool>(v) ? "true" : "false";
    case ParamType::Vec3:
    case ParamType::Color: {
      auto c = std::get<glm::vec3>(v);
      return fmt(c.x) + "," + fmt(c.y) + "," + fmt(c.z);
    }
    case ParamType::Enum: return std::get<std::string>(v);
    case ParamType::Curve: {
      std::string s;
      for (auto& q : std::get<Curve>(v)) s += (s.empty() ? "" : ";") + fmt(q.x) + "," + fmt(q.y);
      return s;
    }
  }
  return "";
}

}  // namespace draught
