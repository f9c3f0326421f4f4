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

// Every field has its default here, once: a default-constructed Params is the table's
// defaults (param_table() reads them from Params{}), and it is valid.
struct GlassParams {
  Curve profile = {{0.0295f, 0.0f}, {0.0345f, 0.05f}, {0.0395f, 0.10f}, {0.0435f, 0.15f}};  // a shaker pint
  float wall_thickness = 0.003f;
  float base_thickness = 0.012f;
  float rim_radius = 0.0015f;
  float ior = 1.52f;
  float roughness = 0.03f;
  glm::vec3 absorption{0.9f, 0.25f, 0.7f};  // per metre
};

struct LiquidParams {
  float fill = 0.85f;  // fraction of the cavity volume
  float ior = 1.34f;
  float srm = 4.0f;    // > 0: absorption derived from the beer colour (SRM); 0: use the next
  float ebc = 0.0f;    // > 0: beer colour in EBC (1.97 x SRM), takes precedence over srm
  glm::vec3 wine{0.0f};  // wine colour: absorbance of 1 cm at 420, 520, 620 nm (when srm and ebc are 0)
  glm::vec3 absorption{1.0f, 4.0f, 20.0f};  // per metre, when no colour above is given
  float haze = 0.0f;                         // scattering per metre
  glm::vec3 haze_color{0.95f, 0.85f, 0.6f};  // single-scattering albedo
  float roughness = 0.02f;
  float slosh_stiffness = 1.0f;  // multiplies the physical first-mode frequency squared
  float slosh_damping = 0.06f;   // damping ratio of the surface's tilt
  float wave_amplitude = 1.0f;   // how strongly motion raises waves
  float wave_speed = 1.0f;       // multiplies the waves' natural frequencies
};

struct FoamParams {
  float height = 0.015f;                // head thickness when settled after the pour, metres
  float density = 1500.0f;              // extinction per metre at the top (lower down it falls as bubbles grow)
  glm::vec3 color{0.97f, 0.95f, 0.9f};  // diffuse reflectance of a deep head (white lager foam, tan stout head)
  float anisotropy = 0.0f;              // Henyey-Greenstein g
  float multiscatter = 0.7f;            // deprecated, accepted, no effect (the head's light is derived)
  float age = 45.0f;                    // seconds since the pour, for a still picture
  float rise_time = 2.0f;               // seconds for the head to build during a pour
  float half_life = 150.0f;             // seconds for the head to halve as it collapses
  float dome = 0.2f;                    // > 0 domed (thicker in the middle), < 0 concave
  float bubble_size = 0.0012f;          // metres: the scale of the micro-bubble detail
  float detail = 0.5f;                  // 0..1: how much the micro bubbles modulate the density
  int big_bubbles = 6;                  // large bubbles on top at any time
  float lacing = 0.6f;                  // 0..1: foam rings left on the glass as the level drops
  int seed = 1;
};

struct BubbleParams {
  float carbonation = 0.6f;  // 0 still wine .. 1 champagne: how many bubbles, how big
  int sites = 40;            // nucleation sites on the inner wall and the floor
  bool etched_base = false;  // a ring of sites etched into the floor (a flute's fine stream)
  float size = 0.0002f;      // radius at birth, metres, at full carbonation
  int max_bubbles = 500;     // alive at once
  int seed = 1;
};

enum class EnvMode { Studio = 0, Constant = 1, Image = 2 };
enum class Backdrop { Sweep = 0, Checker = 1 };
enum class LightShape { Rect = 0, Sphere = 1 };
// Which way a rect light emits: at the scene, or away from it (a background light behind
// the glasses, aimed at the backdrop: its glow shows through the drinks, and the light
// itself, seen from behind, is not seen).
enum class LightFacing { Scene = 0, Away = 1 };
enum class Tonemap { None = 0, Aces = 1 };
// The screen (core/environment/screen.hpp): none, a card in the scene, or the whole
// background (the AR view).
enum class ScreenMode { Off = 0, Card = 1, Background = 2 };

struct EnvParams {
  int mode = int(EnvMode::Studio);  // EnvMode
  glm::vec3 color{0.8f};            // constant mode radiance
  std::string image = "studio";     // image mode: a file, or a shipped environment's name
  float rotation = 0.0f;            // degrees about +y
  float intensity = 1.0f;
  float blur = 0.0f;                // degrees
  // Scene reflections: each glass's surroundings rendered from its middle into a panorama
  // its outer reflections look up (gpu/reflection_panoramas; docs/ENVIRONMENTS.md).
  bool reflections = false;
  int reflections_size = 256;    // the panoramas' width in texels (height half)
  float reflections_rate = 0.0f;  // renders per second of scene time; 0: every frame
  // The studio's sky is dim: the rig's lights light the picture, the sky only fills.
  glm::vec3 sky_top{0.02f, 0.021f, 0.023f};
  glm::vec3 sky_horizon{0.03f, 0.03f, 0.03f};
  glm::vec3 ground{0.02f, 0.02f, 0.02f};
  float strip_intensity = 0.0f;  // strips painted in the sky (the checker test environment)
  float backdrop_glow = 0.0f;    // a glow painted in the sky (the checker test environment)
  bool floor = true;
  int backdrop = int(Backdrop::Sweep);  // Backdrop: what the floor is
  glm::vec3 sweep_color{0.80f, 0.79f, 0.77f};  // the sweep's paper albedo
  float sweep_distance = 0.35f;  // m behind the scene's centre where the floor starts to curve up
  float sweep_radius = 0.30f;    // m: radius of the curve into the wall
  float checker_size = 0.04f;
  glm::vec3 floor_a{0.58f, 0.56f, 0.53f};
  glm::vec3 floor_b{0.44f, 0.42f, 0.40f};
};

// One area light of the studio (core/environment/lights.hpp): placed `distance` metres
// from the scene's centre in `direction`, facing it, emitting `power` watts.
struct LightParams {
  int shape = int(LightShape::Rect);          // LightShape
  int facing = int(LightFacing::Scene);       // LightFacing (rect)
  glm::vec3 direction{-0.6f, 0.6f, 0.55f};  // from the scene's centre towards the light
  float distance = 1.0f;                    // m from the scene's centre
  float width = 0.6f;                       // m (a sphere's diameter)
  float height = 0.6f;                      // m (rect only)
  glm::vec3 color{1.0f, 0.97f, 0.92f};
  float power = 6.0f;  // W, radiant flux of a Lambertian emitter
  float intensity = 2.5f;  // deprecated, accepted, no effect (light.power)
  float size = 12.0f;      // deprecated, accepted, no effect (light.width, light.height)
  // Seen by the camera's own rays: off, a softbox is out of the shot, as a photographer
  // places it, wherever the camera looks from (still in reflections, through the glass
  // and in the light it gives).
  bool camera_visible = false;
};

// The studio's strip softboxes: a pair, the right one the left one mirrored across x = 0,
// behind the glass to the sides, so the glass's flanks mirror them at grazing angles
// (where Fresnel is strong): the two vertical lines of a packshot. Narrow, so they are
// bright in the glass and spill little on the sweep.
inline LightParams default_strips() {
  LightParams l;
  l.direction = {-0.64f, 0.05f, -0.77f};
  l.distance = 0.55f;
  l.width = 0.05f;
  l.height = 0.9f;
  l.color = {1.0f, 1.0f, 1.0f};
  l.power = 1.5f;
  return l;
}

// The backlight: a panel just behind the drinks' middle, turned away from them to the
// sweep: the glow it throws on the paper behind is what the drinks are seen against (a
// backlit beer glows), and the panel, seen from behind, is not seen at all, not even
// beside a wine glass's bowl. presets/scenes/flight.json lights its row otherwise.
inline LightParams default_backlight() {
  LightParams l;
  l.facing = int(LightFacing::Away);  // lights the sweep behind the drinks; never seen itself
  l.direction = {0.0f, 0.4f, -1.0f};  // raised: its lower edge clear of the paper, so no line
  l.distance = 0.14f;
  l.width = 0.2f;
  l.height = 0.12f;
  l.color = {1.0f, 0.98f, 0.95f};
  l.power = 2.0f;
  return l;
}

// A moving picture seen through the drinks (core/environment/screen.hpp): a screen card
// placed like a light, or the whole background; its source a video or a PNG sequence.
struct ScreenParams {
  int mode = int(ScreenMode::Off);  // ScreenMode
  std::string source;               // a video, a PNG sequence or a shipped clip; "": the app streams it (web page)
  float fps = 0.0f;                 // frames per second; 0: the video's own (kSequenceFps for a PNG sequence)
  bool loop = true;                 // from the start again after the last frame; else it holds the last
  float start = 0.0f;               // seconds into the source shown at the scene's time 0
  bool playing = true;              // plays as the scene's time runs; false: holds screen.start
  glm::vec3 direction{0.0f, 0.3f, -1.0f};  // from the scene's centre towards the card (behind the glasses)
  float distance = 0.25f;           // m from the scene's centre
  float width = 0.32f;              // m
  float height = 0.0f;              // m; 0: from the picture's aspect
  float brightness = 1.0f;          // card: radiance of a white texel; background: 1 shows the picture as it is
  // Not a parameter: where a timeline's play, seek and stop actions put the source at the
  // frame's time (s, resolved by Timeline::scene_at in double precision, so frame i of a
  // clip is exactly i / fps); < 0: none, screen.start and screen.playing apply.
  double timeline_position = -1;
};

struct CameraParams {
  bool auto_frame = true;  // place the camera to frame the scene; eye/target then only give the direction
  glm::vec3 eye{0.0f, 0.13f, 0.42f};
  glm::vec3 target{0.0f, 0.075f, 0.0f};
  float vfov = 28.0f;  // degrees
};

struct ClipParams {
  bool enabled = false;              // show a cross-section
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // glass frame; the side the normal points to is cut away
  float offset = 0.0f;               // metres along the normal from the glass's axis foot
};

// What a decal is made of (docs/DECALS.md): printed enamel (opaque paint, lit like a
// matte painted surface), etched or frosted glass (rough glass that scatters what lies
// behind it) or metal (gilding: a gold rim band).
enum class DecalKind { Enamel = 0, Etched = 1, Metallic = 2 };

// One decal layer on a wall (core/vessel/decal.hpp): an image with alpha placed by its
// centre's angle around the axis and height, and its width around the wall; its extent
// along the profile follows from the image's aspect, measured by arc length, so it is not
// stretched on a curved bowl.
struct DecalParams {
  std::string file;  // a PNG, or the name of a shipped decal (presets/decals/); "": none
  int kind = int(DecalKind::Enamel);  // DecalKind
  float angle = 0.0f;   // degrees about the axis from the glass's front (+z), counter-clockwise seen from above
  float height = 0.07f;  // m: the centre's height above the foot
  float width = 0.05f;   // m around the wall at the centre; 0: each copy fills its share of the turn (a band)
  int repeat = 1;        // copies spaced evenly around the axis
  glm::vec3 color{1.0f};  // multiplies the image: paint colour, frost tint, or the metal's reflectance
  float opacity = 1.0f;   // multiplies the image's alpha
  float roughness = 0.3f;  // a metallic decal's: 0 a mirror, more a satin metal
};

// Condensation on a cold glass (core/condensation, docs/CONDENSATION.md): water beads of
// varied size on the outer wall where the drink cools it, a fog of micro-droplets between
// them, beads that grow, merge and run down leaving clear trails. Deterministic per seed.
struct CondensationParams {
  bool enabled = false;
  int seed = 1;
  int count = 4000;             // beads seeded on the cold part of the wall (fewer where they would overlap)
  float size = 0.0011f;         // m: the beads' median base radius
  float spread = 0.55f;         // the log-normal spread of their radii (sigma of ln r)
  float coverage = 0.55f;       // how much of the wall between the beads the fog covers (0..1)
  float contact_angle = 60.0f;  // deg: how domed a bead is (water on clean glass 30-70)
  float slide_radius = 0.0024f; // m: a bead this wide runs down
  float growth = 2.5e-6f;       // m/s: how fast the beads' radii grow (humid air grows them faster)
  float age = 30.0f;            // s the glass has been standing before the scene's time 0
  float margin = 0.004f;        // m: the cold band's top above the drink's level
  bool hand = false;            // a clear print where a hand held the glass
  float hand_angle = 150.0f;    // deg about the axis from the glass's front (+z), as decals
  float hand_height = 0.07f;    // m: the palm's centre above the foot
  bool operator==(const CondensationParams&) const = default;
};

// Which pass draws the picture: the full path pass, or the low-cost MatCap glass
// (docs/MATCAP.md) for weak devices.
enum class RenderTier { Full = 0, MatCap = 1 };

// The MatCap tier's glass (docs/MATCAP.md, shaders/passes/matcap.frag.glsl): the outer
// wall lit by a MatCap (baked from the environment, or a PNG), a thickness mask from the
// analytic profile, a Fresnel edge, refraction as an offset look-up, frost, a tint.
struct MatCapParams {
  std::string file;             // a MatCap PNG; "": baked from the current environment
  float edge_range = 0.1f;      // the Fresnel edge: n.v below which the edge begins
  float edge_intensity = 4.0f;  // how fast the edge fades towards the middle
  float refraction = 0.4f;      // the look-up's offset where the glass is thickest (MatCap widths)
  float frost = 0.0f;           // 0 clear, 1 frosted (the MatCap's blurriest level)
  glm::vec3 tint{0.93f, 0.97f, 0.96f};  // the glass body's colour
  float thickness = 0.02f;      // m of glass along the view that makes the mask 63 % opaque
};

struct RenderParams {
  int tier = int(RenderTier::Full);  // RenderTier
  int tonemap = int(Tonemap::Aces);  // Tonemap
  float exposure = 1.15f;
  bool transparent = false;
  int supersample = 2;
  // Adaptive supersampling (core/output/refine): a pixel whose supersamples differ by more
  // than adaptive_threshold levels of 8-bit display code is drawn again at
  // adaptive_supersample samples per axis; not above supersample: off.
  int adaptive_supersample = 4;
  float adaptive_threshold = 6.0f;
  int max_events = 12;
  int floor_photons = 0;  // the floor's light map's budget for a still; 0: the app's own
};

// The groups that belong to one vessel object of a scene: its glass and its drink.
struct VesselParams {
  GlassParams glass;
  LiquidParams liquid;
  FoamParams foam;
  BubbleParams bubbles;
  ClipParams clip;
  DecalParams decal_outer;  // printed on the outside of the glass
  DecalParams decal_inner;  // on the cavity's side: seen through the glass, and through the drink from behind
  CondensationParams condensation;  // beads and fog on the outside of a cold glass
};

// The groups that belong to the scene as a whole: surroundings, light, camera, output.
struct SceneParams {
  EnvParams env;
  LightParams light;  // the key light
  LightParams strips = default_strips();
  LightParams backlight = default_backlight();
  ScreenParams screen;
  CameraParams camera;
  RenderParams render;
  MatCapParams matcap;
};

// One glass in its scene: what a single-glass preset describes and what `--set glass.ior`
// edits. A Scene (core/scene/scene.hpp) holds SceneParams and one VesselParams per vessel.
struct Params : VesselParams, SceneParams {};

// Which struct a parameter lives in: the scene's, or each vessel object's.
enum class ParamScope { Scene, Vessel };

// File: a file's path or the name of a shipped asset, "" for none; what it names is read
// (and refused with a clear error) where it is used, not by the table.
enum class ParamType { Float, Int, Bool, Vec3, Color, Enum, Curve, File };
inline constexpr size_t kMaxFileParamBytes = 1024;
std::string_view type_name(ParamType);

// Enums are held as their index in the struct and as their name in JSON/CLI; files as
// their text.
using ParamValue = std::variant<float, int, bool, glm::vec3, std::string, Curve>;

struct ParamDesc;

// Typed access to the field of one table row in the struct that holds it (`Root` is
// VesselParams or SceneParams). Made only by the row builder (param_row.hpp), which
// does not compile when the row's ParamType does not match the field's C++ type.
template <class Root>
struct ParamAccess {
  ParamValue (*get)(const ParamDesc&, const Root&) = nullptr;
  void (*set)(const ParamDesc&, Root&, const ParamValue&) = nullptr;  // the value already validated
};

struct ParamDesc {
  std::string path;  // "group.name"
  ParamType type;
  ParamValue def;          // from a default-constructed Params
  float min = 0, max = 0;  // per component for Vec3/Color; r and y bounds for Curve
  std::string unit;
  std::string doc;
  std::vector<std::string> choices;      // Enum only
  ParamScope scope = ParamScope::Scene;  // whose struct holds it: the scene's or each vessel's
  ParamAccess<VesselParams> vessel;      // set for ParamScope::Vessel rows
  ParamAccess<SceneParams> scene;        // set for ParamScope::Scene rows
  // File rows: reads what a value names and throws InputError when it cannot be used, so a
  // bad file is refused like an out-of-range number (validate_value calls it).
  void (*check_file)(const std::string&) = nullptr;
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
// The same as Params{}: every default of the table.
Params default_params();
std::string_view scope_name(ParamScope);  // "scene", "object"

ParamValue get_param(const Params&, const ParamDesc&);
// A vessel-scope row of one vessel's parameters, or a scene-scope row of the scene's;
// the other scope throws std::logic_error (a programming error).
ParamValue get_param(const VesselParams&, const ParamDesc&);
ParamValue get_param(const SceneParams&, const ParamDesc&);
// Checks type and range; throws ParamError. Nothing is written unless the value is valid.
void set_param(Params&, const ParamDesc&, const ParamValue&);
void set_param(VesselParams&, const ParamDesc&, const ParamValue&);
void set_param(SceneParams&, const ParamDesc&, const ParamValue&);
void validate_value(const ParamDesc&, const ParamValue&);
std::string expected_text(const ParamDesc&);
// "unknown parameter 'x' (did you mean 'y'?)" for a path not in the table.
std::string unknown_param_message(const std::string& path);
// The choice nearest to `text` (a few edits away at most), or "" when none is near.
std::string nearest_choice(const std::string& text, const std::vector<std::string>& choices);

// Text forms used by --set and `draught params`: "0.8", "true", "1,0.5,0", "aces",
// "0.03,0;0.035,0.15" for curves.
// The double whose shortest text is the float's shortest text (0.65f -> 0.65, not
// 0.6499999761581421): what JSON writers store, so saved files carry no float noise and
// read back the same float.
double shortest_double(float);

ParamValue parse_param_text(const ParamDesc&, std::string_view text);
std::string format_param(const ParamDesc&, const ParamValue&);

}  // namespace draught
