// The parameter table: every tunable of draught is declared once, in param_table().
// JSON presets, the CLI's --set, `draught params` and (later) the UI panels all go
// through these descriptors; code reads the typed struct `Params`.
#pragma once

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace draught {

// A designer's profile: control points (r, y) in metres, y strictly increasing from 0.
using Curve = std::vector<glm::vec2>;

struct GlassParams {
  Curve profile;
  float wall_thickness;
  float base_thickness;
  float rim_radius;
  float ior;
  float roughness;
  glm::vec3 absorption;  // per metre
};

struct LiquidParams {
  float fill;  // fraction of the cavity volume
  float ior;
  float srm;   // > 0: absorption derived from the beer colour (SRM); 0: use `absorption`
  glm::vec3 absorption;  // per metre
  float haze;            // scattering per metre
  glm::vec3 haze_color;  // single-scattering albedo
  float roughness;
  float slosh_stiffness;  // multiplies the physical first-mode frequency squared
  float slosh_damping;    // damping ratio of the surface's tilt
  float wave_amplitude;   // how strongly motion raises waves
  float wave_speed;       // multiplies the waves' natural frequencies
};

struct FoamParams {
  float height;        // head thickness when settled after the pour, metres
  float density;       // extinction per metre (micro bubbles scatter light)
  glm::vec3 color;     // single-scattering albedo (white lager foam, tan stout head)
  float anisotropy;    // Henyey-Greenstein g
  float multiscatter;  // 0: single scattering only; 1: the full multi-scatter terms
  float age;           // seconds since the pour, for a still picture
  float rise_time;     // seconds for the head to build during a pour
  float half_life;     // seconds for the head to halve as it collapses
  float dome;          // > 0 domed (thicker in the middle), < 0 concave
  float bubble_size;   // metres: the scale of the micro-bubble detail
  float detail;        // 0..1: how much the micro bubbles modulate the density
  int big_bubbles;     // large bubbles on top at any time
  float lacing;        // 0..1: foam rings left on the glass as the level drops
  int seed;
};

struct BubbleParams {
  float carbonation;  // 0 still wine .. 1 champagne: how many bubbles, how big
  int sites;          // nucleation sites on the inner wall and the floor
  bool etched_base;   // a ring of sites etched into the floor (a flute's fine stream)
  float size;         // radius at birth, metres, at full carbonation
  int max_bubbles;    // alive at once
  int seed;
};

enum class EnvMode { Studio = 0, Constant = 1 };
enum class Tonemap { None = 0, Aces = 1 };

struct EnvParams {
  int mode;  // EnvMode
  glm::vec3 color;  // constant mode radiance
  glm::vec3 sky_top;
  glm::vec3 sky_horizon;
  glm::vec3 ground;
  float strip_intensity;
  float backdrop_glow;
  bool floor;
  float checker_size;
  glm::vec3 floor_a;
  glm::vec3 floor_b;
};

struct LightParams {
  glm::vec3 direction;  // towards the light
  glm::vec3 color;
  float intensity;
  float size;  // angular radius, degrees
};

struct CameraParams {
  bool auto_frame;  // place the camera to frame the glass; eye/target then only give the direction
  glm::vec3 eye;
  glm::vec3 target;
  float vfov;  // degrees
};

struct ClipParams {
  bool enabled;      // show a cross-section
  glm::vec3 normal;  // glass frame; the side the normal points to is cut away
  float offset;      // metres along the normal from the glass's axis foot
};

struct RenderParams {
  int tonemap;  // Tonemap
  float exposure;
  bool transparent;
  int supersample;
  int max_events;
};

// The groups that belong to one vessel object of a scene: its glass and its drink.
struct VesselParams {
  GlassParams glass;
  LiquidParams liquid;
  FoamParams foam;
  BubbleParams bubbles;
  ClipParams clip;
};

// The groups that belong to the scene as a whole: surroundings, light, camera, output.
struct SceneParams {
  EnvParams env;
  LightParams light;
  CameraParams camera;
  RenderParams render;
};

// One glass in its scene: what a single-glass preset describes and what `--set glass.ior`
// edits. A Scene (core/scene/scene.hpp) holds SceneParams and one VesselParams per vessel.
struct Params : VesselParams, SceneParams {};

// Which struct a parameter lives in: the scene's, or each vessel object's.
enum class ParamScope { Scene, Vessel };

enum class ParamType { Float, Int, Bool, Vec3, Color, Enum, Curve };
std::string_view type_name(ParamType);

// Enums are held as their index in the struct and as their name in JSON/CLI.
using ParamValue = std::variant<float, int, bool, glm::vec3, std::string, Curve>;

struct ParamDesc {
  std::string path;  // "group.name"
  ParamType type;
  ParamValue def;
  float min = 0, max = 0;  // per component for Vec3/Color; r and y bounds for Curve
  std::string unit;
  std::string doc;
  std::vector<std::string> choices;  // Enum only
  void* (*field)(Params&);           // where the value lives in Params
  ParamScope scope = ParamScope::Scene;  // whose struct holds it: the scene's or each vessel's
};

// An error in a parameter value. `field` is the parameter path, `expected` says what
// was wanted. The caller adds the file.
struct ParamError : std::runtime_error {
  ParamError(std::string field, std::string expected)
      : std::runtime_error(field + ": expected " + expected), field(std::move(field)),
        expected(std::move(expected)) {}
  std::string field, expected;
};

const std::vector<ParamDesc>& param_table();
const ParamDesc* find_param(std::string_view path);
Params default_params();

ParamValue get_param(const Params&, const ParamDesc&);
// Checks type and range; throws ParamError. Nothing is written unless the value is valid.
void set_param(Params&, const ParamDesc&, const ParamValue&);
void validate_value(const ParamDesc&, const ParamValue&);
std::string expected_text(const ParamDesc&);
// "unknown parameter 'x' (did you mean 'y'?)" for a path not in the table.
std::string unknown_param_message(const std::string& path);

// Text forms used by --set and `draught params`: "0.8", "true", "1,0.5,0", "aces",
// "0.03,0;0.035,0.15" for curves.
ParamValue parse_param_text(const ParamDesc&, std::string_view text);
std::string format_param(const ParamDesc&, const ParamValue&);

}  // namespace draught
