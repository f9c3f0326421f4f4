#include "core/environment/screen.hpp"

#include "core/environment/lights.hpp"
#include "core/io/file_cache.hpp"
#include "core/io/files.hpp"
#include "core/io/process.hpp"
#include "core/output/tonemap.hpp"
#include "core/params/preset.hpp"
#include "core/params/shipped_files.hpp"
#include "core/text/echo.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <system_error>

namespace draught {

namespace fs = std::filesystem;

namespace {

// The card's rectangle: placed as a light of the rig is (place_light), facing the scene.
void place_card(ScreenFrame& s, const ScreenParams& p, const glm::dvec3& aim, double aspect) {
  LightParams l;
  l.direction = p.direction;
  l.distance = p.distance;
  l.width = p.width;
  l.height = p.height > 0 ? p.height : float(p.width / std::max(aspect, 1e-3));
  const AreaLight rect = place_light(l, aim);
  s.center = rect.center;
  s.normal = rect.normal;
  s.half_u = rect.half_u;
  s.half_v = rect.half_v;
}

// One mirror back into [-1, 1] beyond an edge, then clamped (twin: screen_fold).
double fold(double s) {
  if (std::fabs(s) > 1) s = std::copysign(2 - std::fabs(s), s);
  return std::clamp(s, -1.0, 1.0);
}

// The few sources last used: a viewer flipping between clips does not reopen them (each
// video holds an ffmpeg process and a few decoded frames).
FileCache<VideoSource> g_sources(3);
std::recursive_mutex g_decoding;  // every source's decoding, one frame at a time

}  // namespace

void ScreenFrame::set_external_size(int width, int height, const SceneParams& p) {
  external_width = std::max(width, 1);
  external_height = std::max(height, 1);
  // The card keeps its centre and width; its height follows the picture's aspect.
  const double len = glm::length(half_v);
  if (mode == ScreenMode::Card && !picture && p.screen.height <= 0 && len > 0)
    half_v *= 0.5 * double(p.screen.width) * external_height / external_width / len;
}

bool ScreenFrame::intersect(const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t, glm::dvec2& uv) const {
  if (mode != ScreenMode::Card) return false;
  const double denom = glm::dot(d, normal);
  if (denom >= 0) return false;  // parallel, or its back
  t = glm::dot(center - o, normal) / denom;
  if (!(t > tmin)) return false;
  const glm::dvec3 q = o + t * d - center;
  const double su = glm::dot(q, half_u) / glm::dot(half_u, half_u), sv = glm::dot(q, half_v) / glm::dot(half_v, half_v);
  if (std::fabs(su) > 1 || std::fabs(sv) > 1) return false;
  uv = {0.5 + 0.5 * su, 0.5 - 0.5 * sv};
  return true;
}

glm::dvec3 ScreenFrame::texel(const glm::dvec2& uv) const {
  if (!picture || picture->width < 1 || picture->height < 1) return glm::dvec3(0.0);
  const int w = picture->width, h = picture->height;
  // Texel centres at (i + 0.5) / w; clamped to the edge texels.
  const double x = std::clamp(uv.x, 0.0, 1.0) * w - 0.5, y = std::clamp(uv.y, 0.0, 1.0) * h - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto at = [&](int i, int j) {
    const std::uint8_t* px = picture->px(std::clamp(i, 0, w - 1), std::clamp(j, 0, h - 1));
    // (sRGB bytes to linear, as the GPU decodes an SRGB8_ALPHA8 texel)
    return glm::dvec3(srgb8_to_linear(px[0]), srgb8_to_linear(px[1]), srgb8_to_linear(px[2]));
  };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

glm::dvec2 ScreenFrame::background_uv(const glm::dvec3& d, const CameraBasis& cam) const {
  const double z = std::max(std::fabs(glm::dot(d, glm::dvec3(cam.forward))), 0.05);
  const double tan_half = cam.tan_half_vfov, aspect = cam.aspect;
  // Where the direction crosses the picture plane, -1..1 across the whole picture.
  const double sx = glm::dot(d, glm::dvec3(cam.right)) / (z * aspect * tan_half) + cam.shift.x;
  const double sy = glm::dot(d, glm::dvec3(cam.up)) / (z * tan_half) + cam.shift.y;
  // The picture covers the view: the part of its width (or height) the view's aspect keeps.
  const double pa = double(picture_width()) / std::max(picture_height(), 1);
  const double cover_x = std::min(1.0, aspect / pa), cover_y = std::min(1.0, pa / aspect);
  return {0.5 + 0.5 * fold(sx) * cover_x, 0.5 - 0.5 * fold(sy) * cover_y};
}

glm::dvec3 ScreenFrame::background_radiance(const glm::dvec3& d, const CameraBasis& cam, const RenderParams& r) const {
  glm::dvec3 c = texel(background_uv(d, cam));
  if (r.tonemap == int(Tonemap::Aces))
    for (int k = 0; k < 3; ++k) c[k] = aces_filmic_inverse(c[k]);
  return brightness * c / double(r.exposure);
}

int screen_frame_index(double position, double fps, int frames, bool loop) {
  const double at = std::floor(std::max(position, 0.0) * fps + 1e-6);
  int index = int(std::min(at, 2.0e9));
  if (frames > 0) index = loop ? index % frames : std::min(index, frames - 1);
  return index;
}

fs::path resolve_screen_source(const std::string& name) {
  if (is_shipped_name(name, "%")) {
    std::string tried;
    if (auto p = find_shipped("videos", name, {".mp4", ".webm", ".mkv", ""}, tried)) return *p;
    throw InputError("no shipped video named '" + shorten(name) + "' (looked for " + tried + ")");
  }
  return name;
}

std::shared_ptr<VideoSource> screen_source(const std::string& name) {
  return g_sources.get(name, resolve_screen_source(name), [](const fs::path& f) { return open_video_source(f); });
}

bool screen_source_played_by_app(const std::string& name) {
  if (name.empty() || can_start_processes() || name.find('%') != std::string::npos) return false;
  const fs::path file = resolve_screen_source(name);
  std::error_code ec;
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return !fs::is_directory(file, ec) && ext != ".png";
}

void check_screen_source(const std::string& name) {
  if (name.empty()) return;
  if (screen_source_played_by_app(name)) {
    std::error_code ec;
    const fs::path file = resolve_screen_source(name);
    if (!fs::is_regular_file(file, ec))
      throw InputError(shorten(name, kEchoPathBytes) + ": no such video file");
    return;
  }
  screen_source(name);
}

ScreenFrame screen_frame(const SceneParams& p, const glm::dvec3& aim, double time) {
  ScreenFrame s;
  const ScreenParams& sp = p.screen;
  s.mode = ScreenMode(sp.mode);
  s.source = sp.source;
  s.brightness = sp.brightness;
  if (!s.on()) return s;
  s.position = sp.timeline_position >= 0 ? sp.timeline_position
                                        : double(sp.start) + (sp.playing ? std::max(time, 0.0) : 0.0);
  if (sp.source.empty()) {
    s.external = true;
  } else if (screen_source_played_by_app(sp.source)) {
    s.external = true;
    s.app_file = resolve_screen_source(sp.source).string();
  } else {
    std::lock_guard lock(g_decoding);
    const std::shared_ptr<VideoSource> src = screen_source(sp.source);
    const VideoInfo& info = src->info();
    const double fps = sp.fps > 0 ? double(sp.fps) : (info.fps > 0 ? info.fps : kSequenceFps);
    s.index = screen_frame_index(s.position, fps, info.frames, sp.loop);
    s.picture = src->frame(s.index);
    if (!s.picture) {  // past the end of a video whose length was unknown until now
      s.index = screen_frame_index(s.position, fps, src->info().frames, sp.loop);
      s.picture = src->frame(s.index);
    }
  }
  const double aspect = double(s.picture_width()) / std::max(s.picture_height(), 1);
  place_card(s, sp, aim, aspect);
  return s;
}

}  // namespace draught
