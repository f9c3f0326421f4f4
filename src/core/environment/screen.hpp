// The screen: a moving picture in the scene, seen refracted through the glasses and the
// drinks (issue 12). Two ways (screen.mode):
//   card:       an emissive rectangle placed around the scene's centre as the studio's
//               lights are (screen.direction, distance, width, height), facing it; seen
//               from the front only, like a softbox, and like the lights an emitter only
//               (it casts no shadow and lights only what sees it).
//   background: the AR view (a phone's camera seen through the beer): a ray that leaves
//               the scene looks the picture up where its direction crosses the camera's
//               picture plane, so around the glass the picture is seen as it was taken
//               (the output's tone map undone) and through the glass refracted. The floor
//               is then left out: the picture is the surroundings.
// What it shows at scene time t is the source's frame at screen.start + t while
// screen.playing (a timeline starts, seeks and stops it: core/params/timeline), at
// screen.fps or the source's own rate, looping or holding its last frame: a function of t
// only. GLSL twin: shaders/lib/environment/screen.glsl.
#pragma once

#include "core/io/image.hpp"
#include "core/io/video_source.hpp"
#include "core/params/params.hpp"
#include "core/scene/camera.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace draught {

// A PNG sequence's rate when screen.fps does not give one (it has none of its own).
inline constexpr double kSequenceFps = 25.0;

struct ScreenFrame {
  ScreenMode mode = ScreenMode::Off;
  // The card: centre, the side it faces (unit), half its width (the picture's rightwards
  // as seen from the front) and half its height (the picture's upwards), in the world.
  glm::dvec3 center{0.0}, normal{0, 0, 1}, half_u{0.0}, half_v{0.0};
  double brightness = 1;
  // The frame shown (8-bit sRGB RGBA, rows top-down); the same object while the frame is
  // the same, so the GPU uploads it only when another one comes. nullptr with `external`:
  // the app streams the picture into the texture itself (the web page's video or camera).
  std::shared_ptr<const Image> picture;
  bool external = false;
  std::string app_file;   // a video the app plays itself (screen_source_played_by_app), resolved
  int index = 0;          // which frame of the source
  double position = 0;    // seconds into the source
  std::string source;     // screen.source

  bool on() const { return mode != ScreenMode::Off; }
  int picture_width() const { return picture ? picture->width : external_width; }
  int picture_height() const { return picture ? picture->height : external_height; }
  // The size of a picture the app streams (external): the card's aspect when
  // screen.height is 0. set_external_size sets it and shapes the card.
  int external_width = 16, external_height = 9;
  void set_external_size(int width, int height, const SceneParams&);

  // Where the ray o + t d (d unit) meets the card's front nearest after tmin, and where in
  // the picture (u right, v down, 0..1). Twin of screen_card_seen in screen.glsl.
  bool intersect(const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t, glm::dvec2& uv) const;
  // The picture at uv (clamped to its edges), in linear light: bilinear between texel
  // centres after decoding sRGB, as the GPU filters its sRGB texture. Black without one.
  glm::dvec3 texel(const glm::dvec2& uv) const;
  // The card's radiance at uv: brightness x the picture.
  glm::dvec3 card_radiance(const glm::dvec2& uv) const { return brightness * texel(uv); }
  // Background: where direction d (unit, world) looks in the picture through the camera
  // `cam` (its picture plane; directions behind it mirrored to the front, beyond the
  // picture's edge mirrored once back into it, then clamped), the picture covering the
  // view without distortion (cropped to the view's aspect). Twin of screen_background_uv.
  glm::dvec2 background_uv(const glm::dvec3& d, const CameraBasis& cam) const;
  // The radiance seen along d: the picture with the output transform of `render` undone
  // (so seen directly it comes out as it went in), times brightness.
  glm::dvec3 background_radiance(const glm::dvec3& d, const CameraBasis& cam, const RenderParams& render) const;
};

// The screen of a scene at time t (seconds of the scene), the card placed around `aim`
// (the scene's centre). Reads the source's frame (kept open: screen_source).
ScreenFrame screen_frame(const SceneParams&, const glm::dvec3& aim, double time);

// The frame index shown at `position` seconds into a source of `frames` frames (-1:
// unknown) at `fps`: floor(position x fps), wrapped when looping, else held at the last.
int screen_frame_index(double position, double fps, int frames, bool loop);

// The file or pattern `name` stands for: a shipped name (a bare word: presets/videos/NAME
// .mp4, .webm, .mkv or the folder NAME of PNG frames) or a path. Throws InputError.
std::filesystem::path resolve_screen_source(const std::string& name);

// The source of `name`, opened once and kept (the last three; one changed since is opened
// again). Throws InputError naming the file and what was expected.
std::shared_ptr<VideoSource> screen_source(const std::string& name);

// Whether the app plays the video `name` itself instead of the core decoding it: in a build
// that runs no programs (the web page, where the browser plays it in a <video> element and
// streams its frames in) a video file is the app's; a PNG sequence never is. Throws
// InputError for a name that resolves to nothing.
bool screen_source_played_by_app(const std::string& name);

// The parameter table's check of screen.source: "" (the app streams the picture), a video
// the app plays (its file exists), or a source that opens.
void check_screen_source(const std::string& name);

}  // namespace draught
