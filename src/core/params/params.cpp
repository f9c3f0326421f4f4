#include "core/params/params.hpp"

#include "core/environment/environment_files.hpp"
#include "core/environment/matcap.hpp"
#include "core/environment/screen.hpp"
#include "core/vessel/decal_files.hpp"
#include "core/io/files.hpp"
#include "core/params/param_row.hpp"
#include "core/text/echo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace draught {

namespace {

// One row per tunable: the field (by member pointers, so a row of the wrong type does not
// compile), the range, unit and doc. Defaults come from the structs' initializers.
#define ROW DRAUGHT_PARAM_ROW

std::vector<ParamDesc> make_object_and_env_rows();

// A File row that reads what it names before taking it (ParamDesc::check_file).
ParamDesc with_file_check(ParamDesc d, void (*check)(const std::string&)) {
  d.check_file = check;
  return d;
}
std::vector<ParamDesc> make_camera_and_render_rows();

// The rows of one area light's group (light, strips, backlight): the same fields.
template <auto Group>
void add_light_rows(std::vector<ParamDesc>& rows, const std::string& g, const std::string& what) {
  using L = LightParams;
  rows.push_back(param_row<ParamType::Enum, Group, &L::shape>(g + ".shape", 0, 0, "",
      "rect: a rectangular softbox facing the scene; sphere: a round lamp (diameter " + g + ".width)",
      std::vector<std::string>{"rect", "sphere"}));
  rows.push_back(param_row<ParamType::Enum, Group, &L::facing>(g + ".facing", 0, 0, "",
      "scene: " + what + " shines at the scene; away: it shines at the backdrop behind it (a rect seen from behind is not seen)",
      std::vector<std::string>{"scene", "away"}));
  rows.push_back(param_row<ParamType::Vec3, Group, &L::direction>(g + ".direction", -1.0f, 1.0f, "",
      "Direction from the scene's centre towards " + what + " (normalised)"));
  rows.push_back(param_row<ParamType::Float, Group, &L::distance>(g + ".distance", 0.05f, 20.0f, "m",
      "Distance of " + what + " from the scene's centre"));
  rows.push_back(param_row<ParamType::Float, Group, &L::width>(g + ".width", 0.005f, 10.0f, "m", "Width of " + what));
  rows.push_back(param_row<ParamType::Float, Group, &L::height>(g + ".height", 0.005f, 10.0f, "m",
      "Height of " + what + " (rect)"));
  rows.push_back(param_row<ParamType::Color, Group, &L::color>(g + ".color", 0.0f, 1.0f, "", "Colour of " + what));
  rows.push_back(param_row<ParamType::Float, Group, &L::power>(g + ".power", 0.0f, 1000.0f, "W",
      "Power of " + what + ": radiant flux of a Lambertian emitter (0: off)"));
  rows.push_back(param_row<ParamType::Bool, Group, &L::camera_visible>(g + ".camera_visible", 0.0f, 1.0f, "",
      "Whether the camera sees " + what + " straight (false: kept out of the shot, as a photographer places a "
      "softbox, wherever the camera looks from; its reflections, what the glass bends of it and its light stay)"));
}

// The rows of one decal layer (decal_outer, decal_inner): the same fields on either wall.
template <auto Group>
void add_decal_rows(std::vector<ParamDesc>& rows, const std::string& g, const std::string& wall) {
  using D = DecalParams;
  rows.push_back(with_file_check(param_row<ParamType::File, Group, &D::file>(g + ".file", 0, 0, "",
      "A decal on " + wall + ": a PNG with alpha (at most 4096 x 4096), or the name of a shipped decal "
      "(presets/decals: crest, gold-band, wordmark); \"\": none"), &check_decal_image));
  rows.push_back(param_row<ParamType::Enum, Group, &D::kind>(g + ".kind", 0, 0, "",
      "enamel: printed paint, opaque, lit like a matte surface; etched: frosted glass that scatters the light "
      "behind it; metallic: a metal leaf (gilding) that mirrors the studio in its colour",
      std::vector<std::string>{"enamel", "etched", "metallic"}));
  rows.push_back(param_row<ParamType::Float, Group, &D::angle>(g + ".angle", -180.0f, 180.0f, "deg",
      "Where the decal's centre faces, about the glass's axis from its front (+z, the camera's side), "
      "counter-clockwise seen from above"));
  rows.push_back(param_row<ParamType::Float, Group, &D::height>(g + ".height", 0.0f, 0.6f, "m",
      "Height of the decal's centre above the glass's foot"));
  rows.push_back(param_row<ParamType::Float, Group, &D::width>(g + ".width", 0.0f, 1.0f, "m",
      "Width of the decal around the wall (its height along the profile follows from the image's aspect); "
      "0: each copy fills its share of the turn, so the copies join into a band"));
  rows.push_back(param_row<ParamType::Int, Group, &D::repeat>(g + ".repeat", 1.0f, 64.0f, "",
      "Copies of the decal spaced evenly around the glass"));
  rows.push_back(param_row<ParamType::Color, Group, &D::color>(g + ".color", 0.0f, 1.0f, "",
      "Multiplies the image's colour: the paint's colour, the frost's tint, or the metal's reflectance (gold: 1, 0.77, 0.34)"));
  rows.push_back(param_row<ParamType::Float, Group, &D::opacity>(g + ".opacity", 0.0f, 1.0f, "",
      "Multiplies the image's alpha (0: the decal is not there)"));
  rows.push_back(param_row<ParamType::Float, Group, &D::roughness>(g + ".roughness", 0.005f, 1.0f, "",
      "Roughness of a metallic decal: how much it blurs the lights it mirrors (polished gold 0.05, satin gold 0.3)"));
}

// Condensation on a cold glass (core/condensation).
void add_condensation_rows(std::vector<ParamDesc>& rows) {
  const std::vector<ParamDesc> c = {
      ROW(VesselParams, condensation, enabled, Bool, 0.0f, 1.0f, "",
          "Water beads and a fog of micro-droplets on the outside of the glass, where the cold drink cools it"),
      ROW(VesselParams, condensation, seed, Int, 0.0f, 1000000.0f, "", "Which random pattern of beads (the same seed, the same glass)"),
      ROW(VesselParams, condensation, count, Int, 0.0f, 8000.0f, "", "Beads seeded on the cold part of the wall (fewer where they would overlap)"),
      ROW(VesselParams, condensation, size, Float, 0.0002f, 0.004f, "m", "The beads' median base radius"),
      ROW(VesselParams, condensation, spread, Float, 0.0f, 1.2f, "",
          "How varied the beads' sizes are: the spread of their log-normal radii (0: all alike)"),
      ROW(VesselParams, condensation, coverage, Float, 0.0f, 1.0f, "",
          "How much of the wall between the beads the fog of micro-droplets covers (0: clear, 1: frosted)"),
      ROW(VesselParams, condensation, contact_angle, Float, 20.0f, 90.0f, "deg",
          "How domed a bead is: its contact angle with the glass (clean glass 30-70)"),
      ROW(VesselParams, condensation, slide_radius, Float, 0.001f, 0.006f, "m",
          "A bead this wide is too heavy to cling and runs down, taking the beads in its way and leaving a clear trail"),
      ROW(VesselParams, condensation, growth, Float, 0.0f, 1e-4f, "m/s",
          "How fast the beads' radii grow from the humid air (0: they do not)"),
      ROW(VesselParams, condensation, age, Float, 0.0f, 600.0f, "s",
          "How long the cold glass has been standing before the scene's time 0 (older: bigger beads, more trails)"),
      ROW(VesselParams, condensation, margin, Float, -0.05f, 0.05f, "m",
          "The top of the beaded band above the drink's level (the wall above the drink is warmer)"),
      ROW(VesselParams, condensation, hand, Bool, 0.0f, 1.0f, "", "A clear print where a hand held the glass"),
      ROW(VesselParams, condensation, hand_angle, Float, -180.0f, 180.0f, "deg",
          "Where the hand's print faces, about the glass's axis from its front (+z), counter-clockwise seen from above"),
      ROW(VesselParams, condensation, hand_height, Float, 0.0f, 0.6f, "m", "Height of the palm's centre above the foot"),
  };
  rows.insert(rows.end(), c.begin(), c.end());
}

// The screen (core/environment/screen.hpp): a moving picture behind and through the glass.
void add_screen_rows(std::vector<ParamDesc>& rows) {
  const std::vector<ParamDesc> screen = {
      ROW(SceneParams, screen, mode, Enum, 0, 0, "",
          "off: no screen; card: a screen showing screen.source in the scene, placed like a light (screen.direction, "
          "distance, width, height) and seen through the drinks; background: screen.source is the whole background "
          "(the AR view: a phone's camera seen through the beer; no floor)",
          (std::vector<std::string>{"off", "card", "background"})),
      with_file_check(ROW(SceneParams, screen, source, File, 0, 0, "",
                          "What the screen shows: a video file (decoded by ffmpeg), a folder of PNG frames, a pattern "
                          "such as clip/frame_%04d.png, a PNG file, or a shipped clip (draught-loop); \"\": the app "
                          "streams it (the web page's video or camera)"),
                      &check_screen_source),
      ROW(SceneParams, screen, fps, Float, 0.0f, 240.0f, "1/s",
          "Frames per second the source plays at (0: the video's own rate; 25 for a PNG sequence)"),
      ROW(SceneParams, screen, loop, Bool, 0.0f, 1.0f, "", "Play the source from its start again after its last frame (else hold the last)"),
      ROW(SceneParams, screen, start, Float, 0.0f, 36000.0f, "s", "Where in the source the scene's time 0 is (a still shows this moment)"),
      ROW(SceneParams, screen, playing, Bool, 0.0f, 1.0f, "",
          "Play as the scene's time runs (else hold screen.start); timelines start, seek and stop it with play, seek and stop"),
      ROW(SceneParams, screen, direction, Vec3, -1.0f, 1.0f, "", "Direction from the scene's centre towards the card (normalised)"),
      ROW(SceneParams, screen, distance, Float, 0.05f, 20.0f, "m", "Distance of the card from the scene's centre"),
      ROW(SceneParams, screen, width, Float, 0.01f, 20.0f, "m", "Width of the card"),
      ROW(SceneParams, screen, height, Float, 0.0f, 20.0f, "m", "Height of the card (0: from the picture's aspect)"),
      ROW(SceneParams, screen, brightness, Float, 0.0f, 100.0f, "",
          "Card: the radiance of a white pixel (1 is about as bright as the lit paper); background: 1 shows the picture "
          "as it was taken"),
  };
  rows.insert(rows.end(), screen.begin(), screen.end());
}

std::vector<ParamDesc> make_table() {
  std::vector<ParamDesc> rows = make_object_and_env_rows();
  // The decals after the glass's other per-object groups (before env).
  std::vector<ParamDesc> decals;
  add_decal_rows<&VesselParams::decal_outer>(decals, "decal_outer", "the outer wall");
  add_decal_rows<&VesselParams::decal_inner>(decals, "decal_inner",
                                             "the inner wall (the cavity's side: seen through the glass)");
  add_condensation_rows(decals);
  const auto env = std::find_if(rows.begin(), rows.end(), [](const ParamDesc& d) { return d.path.starts_with("env."); });
  rows.insert(env, decals.begin(), decals.end());
  add_light_rows<&SceneParams::light>(rows, "light", "the key light");
  rows.push_back(ROW(SceneParams, light, intensity, Float, 0.0f, 100.0f, "",
                     "Deprecated, has no effect: the key light's power is light.power (W)"));
  rows.push_back(ROW(SceneParams, light, size, Float, 0.5f, 60.0f, "deg",
                     "Deprecated, has no effect: the key light's size is light.width and light.height (m)"));
  add_light_rows<&SceneParams::strips>(rows, "strips", "each strip softbox (the right one mirrors the left)");
  add_light_rows<&SceneParams::backlight>(rows, "backlight", "the backlight");
  add_screen_rows(rows);
  const std::vector<ParamDesc> rest = make_camera_and_render_rows();
  rows.insert(rows.end(), rest.begin(), rest.end());
  return rows;
}

std::vector<ParamDesc> make_object_and_env_rows() {
  return {
      // glass
      ROW(VesselParams, glass, profile, Curve, 0.0005f, 0.6f, "m",
          "Outer profile: control points (r, y) of a smooth curve, y from 0 (the foot) up to the rim"),
      ROW(VesselParams, glass, wall_thickness, Float, 0.0005f, 0.02f, "m", "Wall thickness, measured horizontally"),
      ROW(VesselParams, glass, base_thickness, Float, 0.001f, 0.3f, "m",
          "Height of solid glass under the cavity (the base, or foot and stem)"),
      ROW(VesselParams, glass, rim_radius, Float, 0.0002f, 0.02f, "m",
          "Radius of the torus bead at the rim (kept between half and twice the wall thickness)"),
      ROW(VesselParams, glass, ior, Float, 1.0f, 2.5f, "", "Index of refraction of the glass"),
      ROW(VesselParams, glass, roughness, Float, 0.005f, 1.0f, "", "Roughness of the glass surfaces: how much they blur the key softbox's reflection"),
      ROW(VesselParams, glass, absorption, Vec3, 0.0f, 1000.0f, "1/m",
          "Beer-Lambert absorption of the glass (soda-lime is slightly green)"),
      // liquid
      ROW(VesselParams, liquid, fill, Float, 0.0f, 0.98f, "", "Fill level as a fraction of the cavity volume"),
      ROW(VesselParams, liquid, ior, Float, 1.0f, 2.0f, "", "Index of refraction of the liquid"),
      ROW(VesselParams, liquid, srm, Float, 0.0f, 100.0f, "SRM",
          "Beer colour (Standard Reference Method, 12.7 x A430 of 1 cm); > 0 derives the absorption"),
      ROW(VesselParams, liquid, ebc, Float, 0.0f, 197.0f, "EBC",
          "Beer colour in EBC (1.97 x SRM); > 0 takes precedence over liquid.srm"),
      ROW(VesselParams, liquid, wine, Vec3, 0.0f, 50.0f, "A/cm",
          "Wine colour: absorbance of 1 cm at 420, 520, 620 nm (used when liquid.ebc and liquid.srm are 0)"),
      ROW(VesselParams, liquid, absorption, Vec3, 0.0f, 20000.0f, "1/m",
          "Beer-Lambert absorption per metre (used when no beer or wine colour is given)"),
      ROW(VesselParams, liquid, haze, Float, 0.0f, 2000.0f, "1/m", "Cloudiness: scattering coefficient per metre"),
      ROW(VesselParams, liquid, haze_color, Color, 0.0f, 1.0f, "",
          "Single-scattering albedo of the haze"),
      ROW(VesselParams, liquid, roughness, Float, 0.005f, 1.0f, "", "Roughness of the liquid surface: how much it blurs the key softbox's reflection"),
      ROW(VesselParams, liquid, slosh_stiffness, Float, 0.25f, 4.0f, "",
          "Scales the sloshing frequency squared (1: a real drink in this glass)"),
      ROW(VesselParams, liquid, slosh_damping, Float, 0.005f, 1.0f, "",
          "Damping ratio of the sloshing surface (a few percent for water-like drinks, more for thick ones)"),
      ROW(VesselParams, liquid, wave_amplitude, Float, 0.0f, 5.0f, "", "How strongly shaking raises waves on the surface"),
      ROW(VesselParams, liquid, wave_speed, Float, 0.25f, 4.0f, "", "Scales the frequency of the surface waves"),
      // foam head
      ROW(VesselParams, foam, height, Float, 0.0f, 0.08f, "m", "Head thickness once poured and settled (0: no head)"),
      ROW(VesselParams, foam, density, Float, 50.0f, 20000.0f, "1/m", "Extinction of the foam at its top, where the bubbles are finest: how opaque the head is"),
      ROW(VesselParams, foam, color, Color, 0.0f, 1.0f, "",
          "Colour of a deep head under even light: its diffuse reflectance (white for lager, tan for stout)"),
      ROW(VesselParams, foam, anisotropy, Float, -0.9f, 0.9f, "", "Henyey-Greenstein anisotropy of the foam's scattering"),
      ROW(VesselParams, foam, multiscatter, Float, 0.0f, 1.0f, "",
          "Deprecated, has no effect: the head's multiple scattering is derived from foam.color"),
      ROW(VesselParams, foam, age, Float, 0.0f, 36000.0f, "s", "Seconds since the pour, for a still picture"),
      ROW(VesselParams, foam, rise_time, Float, 0.1f, 30.0f, "s", "How long the head takes to build during a pour"),
      ROW(VesselParams, foam, half_life, Float, 1.0f, 36000.0f, "s", "Time for the head to halve as it collapses"),
      ROW(VesselParams, foam, dome, Float, -0.5f, 0.5f, "", "Shape of the head: > 0 domed, < 0 concave"),
      ROW(VesselParams, foam, bubble_size, Float, 0.0002f, 0.01f, "m", "Size of the micro bubbles in the head"),
      ROW(VesselParams, foam, detail, Float, 0.0f, 1.0f, "", "How much the micro bubbles break up the foam's density"),
      ROW(VesselParams, foam, big_bubbles, Int, 0.0f, 12.0f, "", "Large shiny bubbles on top of the head that grow and pop"),
      ROW(VesselParams, foam, lacing, Float, 0.0f, 1.0f, "", "Foam rings left on the glass each time the level drops"),
      ROW(VesselParams, foam, seed, Int, 0.0f, 1000000.0f, "", "Seed of the foam's randomness (big bubbles, lacing)"),
      // rising bubbles
      ROW(VesselParams, bubbles, carbonation, Float, 0.0f, 1.0f, "",
          "Dissolved CO2, 0 (still wine) to 1 (champagne): how many bubbles rise and how big"),
      ROW(VesselParams, bubbles, sites, Int, 0.0f, 400.0f, "", "Nucleation sites on the inner wall and the floor"),
      ROW(VesselParams, bubbles, etched_base, Bool, 0.0f, 1.0f, "",
          "A ring of sites etched into the floor, as in many flutes: one fine, fast stream"),
      ROW(VesselParams, bubbles, size, Float, 0.00002f, 0.001f, "m", "Bubble radius at birth (at full carbonation)"),
      ROW(VesselParams, bubbles, max_bubbles, Int, 0.0f, 2000.0f, "", "Most bubbles alive at once"),
      ROW(VesselParams, bubbles, seed, Int, 0.0f, 1000000.0f, "", "Seed of the nucleation sites and bubble jitter"),
      // environment
      ROW(SceneParams, env, mode, Enum, 0, 0, "",
          "studio: a gradient sky (with strips and a glow painted in where env.strip_intensity, env.backdrop_glow) "
          "and the rig's lights; constant: env.color everywhere; image: the equirectangular HDR environment env.image, "
          "whose light replaces the rig's",
          (std::vector<std::string>{"studio", "constant", "image"})),
      with_file_check(ROW(SceneParams, env, image, File, 0, 0, "",
                          "An HDR environment, for env.mode image: a Radiance .hdr or OpenEXR .exr file "
                          "(equirectangular, 2:1), or the name of a shipped one (studio, bar)"),
                      &check_environment_image),
      ROW(SceneParams, env, rotation, Float, -180.0f, 180.0f, "deg",
          "Turns env.image about the vertical axis (positive: counter-clockwise seen from above)"),
      ROW(SceneParams, env, intensity, Float, 0.0f, 100.0f, "", "Multiplies env.image's radiance"),
      ROW(SceneParams, env, blur, Float, 0.0f, 45.0f, "deg",
          "Blurs env.image as seen directly and in sharp reflections (the angle of the blur)"),
      ROW(SceneParams, env, reflections, Bool, 0.0f, 1.0f, "",
          "Glasses reflect the scene around them: each glass's surroundings (the other objects, the floor, the "
          "lights, the sky) rendered from its middle into a panorama its outer reflections look up"),
      ROW(SceneParams, env, reflections_size, Int, 32.0f, 1024.0f, "px",
          "env.reflections: the panoramas' width (their height is half): sharper reflections for more time"),
      ROW(SceneParams, env, reflections_rate, Float, 0.0f, 240.0f, "1/s",
          "env.reflections: how often the panoramas are rendered again, per second of scene time (0: every frame)"),
      ROW(SceneParams, env, color, Color, 0.0f, 100.0f, "", "Radiance of the constant environment"),
      ROW(SceneParams, env, sky_top, Color, 0.0f, 100.0f, "", "Studio sky colour at the zenith"),
      ROW(SceneParams, env, sky_horizon, Color, 0.0f, 100.0f, "", "Studio sky colour at the horizon"),
      ROW(SceneParams, env, ground, Color, 0.0f, 100.0f, "", "Studio colour below the horizon"),
      ROW(SceneParams, env, strip_intensity, Float, 0.0f, 100.0f, "", "Radiance of two strips painted into the sky (the checker test environment; the studio's strips are strips.*)"),
      ROW(SceneParams, env, backdrop_glow, Float, 0.0f, 100.0f, "", "Radiance of a glow painted into the sky behind the glass (the checker test environment)"),
      ROW(SceneParams, env, floor, Bool, 0.0f, 1.0f, "", "A floor at y = 0 (env.backdrop) with the glasses' shadows"),
      ROW(SceneParams, env, backdrop, Enum, 0, 0, "",
          "sweep: a seamless paper sweep curving up into a wall behind the scene (the packshot studio); "
          "checker: a checker floor to the horizon (a test environment)",
          (std::vector<std::string>{"sweep", "checker"})),
      ROW(SceneParams, env, sweep_color, Color, 0.0f, 1.0f, "", "Albedo of the sweep's paper"),
      ROW(SceneParams, env, sweep_distance, Float, 0.05f, 10.0f, "m",
          "How far behind the scene's centre the sweep's floor starts to curve up into its wall"),
      ROW(SceneParams, env, sweep_radius, Float, 0.01f, 5.0f, "m", "Radius of the sweep's curve from floor to wall"),
      ROW(SceneParams, env, checker_size, Float, 0.001f, 10.0f, "m", "Edge length of one floor checker square"),
      ROW(SceneParams, env, floor_a, Color, 0.0f, 1.0f, "", "Floor albedo, light squares"),
      ROW(SceneParams, env, floor_b, Color, 0.0f, 1.0f, "", "Floor albedo, dark squares"),
  };
}

std::vector<ParamDesc> make_camera_and_render_rows() {
  return {
      // camera
      ROW(SceneParams, camera, auto_frame, Bool, 0.0f, 1.0f, "",
          "Frame the whole glass automatically, looking from the direction of eye - target"),
      ROW(SceneParams, camera, eye, Vec3, -10.0f, 10.0f, "m", "Camera position"),
      ROW(SceneParams, camera, target, Vec3, -10.0f, 10.0f, "m", "Point the camera looks at"),
      ROW(SceneParams, camera, vfov, Float, 5.0f, 120.0f, "deg", "Vertical field of view"),
      // cross-section
      ROW(VesselParams, clip, enabled, Bool, 0.0f, 1.0f, "", "Cut the glass and its contents open along a plane (capped cuts)"),
      ROW(VesselParams, clip, normal, Vec3, -1.0f, 1.0f, "",
          "Normal of the cut, in the glass's frame: the side it points to is removed"),
      ROW(VesselParams, clip, offset, Float, -0.3f, 0.3f, "m", "Where the cut lies along its normal, from the glass's axis"),
      // output
      ROW(SceneParams, render, tier, Enum, 0, 0, "",
          "full: the path pass (refraction, absorption, foam marched per pixel); matcap: the low-cost glass for "
          "weak devices, the outer wall lit by a MatCap with a thickness mask (docs/MATCAP.md)",
          (std::vector<std::string>{"full", "matcap"})),
      ROW(SceneParams, render, tonemap, Enum, 0, 0, "",
          "none: clamp then sRGB; aces: filmic tone map then sRGB", (std::vector<std::string>{"none", "aces"})),
      ROW(SceneParams, render, exposure, Float, 0.01f, 100.0f, "", "Linear exposure multiplier before tone mapping"),
      ROW(SceneParams, render, transparent, Bool, 0.0f, 1.0f, "",
          "Transparent background: the objects cut out (PNG: straight alpha; the floor is left out)"),
      ROW(SceneParams, render, supersample, Int, 1.0f, 4.0f, "", "Supersampling factor per axis (anti-aliasing)"),
      ROW(SceneParams, render, adaptive_supersample, Int, 1.0f, 4.0f, "",
          "Samples per axis at pixels whose supersamples disagree (fine detail, edges); not above supersample: off"),
      ROW(SceneParams, render, adaptive_threshold, Float, 0.0f, 255.0f, "levels",
          "How far a pixel's supersamples may differ (8-bit display levels) before it takes adaptive_supersample"),
      ROW(SceneParams, render, max_events, Int, 2.0f, 32.0f, "", "Most surface interactions followed per pixel"),
      ROW(SceneParams, render, floor_photons, Int, 0.0f, 5000000.0f, "",
          "Photons traced for the floor's shadows and caustics in a still or an animation frame; 0: the app's own "
          "(the CLI's 500,000; fewer render an animation whose objects move faster, noisier)"),
      // the MatCap tier
      with_file_check(ROW(SceneParams, matcap, file, File, 0, 0, "",
                          "render.tier matcap: a MatCap PNG (a lit sphere seen straight on, at most 4096 x 4096); "
                          "\"\": baked from the current environment and lights"),
                      &check_matcap_image),
      ROW(SceneParams, matcap, edge_range, Float, -1.0f, 1.0f, "",
          "render.tier matcap: the Fresnel edge begins where the surface turns this far from the view (n.v below it)"),
      ROW(SceneParams, matcap, edge_intensity, Float, 0.0f, 10.0f, "",
          "render.tier matcap: how sharply the Fresnel edge fades towards the glass's middle"),
      ROW(SceneParams, matcap, refraction, Float, 0.0f, 1.0f, "",
          "render.tier matcap: the refraction's look-up offset where the glass is thickest, in MatCap widths"),
      ROW(SceneParams, matcap, frost, Float, 0.0f, 1.0f, "",
          "render.tier matcap: 0 clear glass, 1 frosted (the MatCap blurred to its coarsest level)"),
      ROW(SceneParams, matcap, tint, Color, 0.0f, 1.0f, "", "render.tier matcap: the colour of the glass body"),
      ROW(SceneParams, matcap, thickness, Float, 0.0005f, 0.1f, "m",
          "render.tier matcap: glass along the view that makes the refraction mask 63 % opaque"),
  };
}
#undef ROW

// The shortest decimal text that reads back as the same float.
std::string fmt(float v) {
  char buf[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, double(v));
    if (std::strtof(buf, nullptr) == v) break;
  }
  return buf;
}

// Spaces and tabs off a value typed or pasted on one line (core/text/trim.hpp takes a
// file's line endings too).
std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (;;) {
    size_t p = s.find(sep, start);
    out.push_back(trim_blanks(s.substr(start, p == std::string_view::npos ? std::string_view::npos : p - start)));
    if (p == std::string_view::npos) break;
    start = p + 1;
  }
  return out;
}

bool parse_float(std::string_view s, float& out) {
  std::string str(trim_blanks(s));
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

double shortest_double(float v) { return std::strtod(fmt(v).c_str(), nullptr); }

std::string nearest_choice(const std::string& text, const std::vector<std::string>& choices) {
  const std::string* best = nullptr;
  size_t best_d = 4;
  for (const auto& c : choices) {
    const size_t e = edit_distance(text, c);
    if (e < best_d) best_d = e, best = &c;
  }
  return best ? *best : std::string();
}

std::string unknown_param_message(const std::string& path) {
  std::vector<std::string> paths;
  for (auto& d : param_table()) paths.push_back(d.path);
  const std::string best = nearest_choice(path, paths);
  return "unknown parameter '" + path + "'" + (best.empty() ? "" : " (did you mean '" + best + "'?)") +
         "; `draught params` lists them";
}

std::string_view scope_name(ParamScope s) { return s == ParamScope::Scene ? "scene" : "object"; }

std::string_view type_name(ParamType t) {
  switch (t) {
    case ParamType::Float: return "float";
    case ParamType::Int: return "int";
    case ParamType::Bool: return "bool";
    case ParamType::Vec3: return "vec3";
    case ParamType::Color: return "color";
    case ParamType::Enum: return "enum";
    case ParamType::Curve: return "curve";
    case ParamType::File: return "file";
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
    case ParamType::File:
      return "a file's path or a shipped name, at most " + std::to_string(kMaxFileParamBytes) +
             " bytes with no control characters";
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
    case ParamType::File: {
      if (!std::holds_alternative<std::string>(v)) fail();
      const std::string& f = std::get<std::string>(v);
      if (f.size() > kMaxFileParamBytes) fail();
      for (unsigned char c : f)
        if (c < 0x20 || c == 0x7f) fail();
      if (d.check_file) {
        try {
          d.check_file(f);
        } catch (const InputError& e) {
          throw ParamError(d.path, std::string("a file that can be used: ") + e.what());
        }
      }
      break;
    }
  }
}

namespace {
[[noreturn]] void wrong_scope(const ParamDesc& d, const char* given) {
  throw std::logic_error(d.path + " is a " + std::string(scope_name(d.scope)) + " parameter, not one of " + given);
}
}  // namespace

ParamValue get_param(const VesselParams& p, const ParamDesc& d) {
  if (!d.vessel.get) wrong_scope(d, "VesselParams");
  return d.vessel.get(d, p);
}

ParamValue get_param(const SceneParams& p, const ParamDesc& d) {
  if (!d.scene.get) wrong_scope(d, "SceneParams");
  return d.scene.get(d, p);
}

ParamValue get_param(const Params& p, const ParamDesc& d) {
  return d.scope == ParamScope::Vessel ? get_param(static_cast<const VesselParams&>(p), d)
                                       : get_param(static_cast<const SceneParams&>(p), d);
}

void set_param(VesselParams& p, const ParamDesc& d, const ParamValue& v) {
  if (!d.vessel.set) wrong_scope(d, "VesselParams");
  validate_value(d, v);
  d.vessel.set(d, p, v);
}

void set_param(SceneParams& p, const ParamDesc& d, const ParamValue& v) {
  if (!d.scene.set) wrong_scope(d, "SceneParams");
  validate_value(d, v);
  d.scene.set(d, p, v);
}

void set_param(Params& p, const ParamDesc& d, const ParamValue& v) {
  if (d.scope == ParamScope::Vessel) set_param(static_cast<VesselParams&>(p), d, v);
  else set_param(static_cast<SceneParams&>(p), d, v);
}

Params default_params() { return Params{}; }

ParamValue parse_param_text(const ParamDesc& d, std::string_view text) {
  auto fail = [&]() -> ParamValue {
    throw ParamError(d.path, expected_text(d) + ", got " + quote_input(text));  // capped: a pasted page is not echoed
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
      auto t = trim_blanks(text);
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
    case ParamType::Enum: v = std::string(trim_blanks(text)); break;
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
    case ParamType::File: v = std::string(trim_blanks(text)); break;
  }
  try {
    validate_value(d, v);
  } catch (const ParamError&) {
    if (d.type == ParamType::File) throw;  // it says what is wrong with the file
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
    case ParamType::File: return std::get<std::string>(v);
  }
  return "";
}

}  // namespace draught
