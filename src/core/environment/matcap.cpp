#include "core/environment/matcap.hpp"

#include "core/environment/sky_irradiance.hpp"
#include "core/environment/studio.hpp"
#include "core/io/files.hpp"
#include "core/output/tonemap.hpp"
#include "core/text/echo.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <numbers>

namespace draught {

MatCapView matcap_view() {
  const CameraParams c;
  const glm::dvec3 back = glm::normalize(glm::dvec3(c.eye) - glm::dvec3(c.target));
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), back));
  return {right, glm::cross(back, right), back};
}

glm::dvec3 matcap_normal(double u, double v) {
  glm::dvec2 xy(2 * u - 1, 1 - 2 * v);
  const double r2 = glm::dot(xy, xy);
  if (r2 >= 1) return {xy / std::sqrt(r2), 0.0};
  return {xy, std::sqrt(1 - r2)};
}

glm::dvec2 matcap_uv(const glm::dvec3& n) { return {0.5 + 0.5 * n.x, 0.5 - 0.5 * n.y}; }

MatCap bake_matcap(const SceneParams& p, const LightRig& rig, const BackdropSurface& backdrop, const glm::dvec3& centre,
                   int size) {
  const Studio studio(p);
  const SkyIrradiance sky = sky_irradiance(studio);
  const MatCapView view = matcap_view();
  MatCap m{size, std::vector<glm::vec3>(size_t(size) * size_t(size))};
  const glm::dvec3 o = centre;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 nv = matcap_normal((x + 0.5) / size, (y + 0.5) / size);
      const glm::dvec3 n = nv.x * view.right + nv.y * view.up + nv.z * view.back;
      const glm::dvec3 r = glm::normalize(2 * glm::dot(n, view.back) * n - view.back);  // the view mirrored
      double tb = INFINITY, tl = INFINITY;
      glm::dvec3 nb(0.0);
      if (backdrop.present && !backdrop.intersect(o, r, 0.0, tb, nb)) tb = INFINITY;
      glm::dvec3 c(0.0);
      const AreaLight* seen = nullptr;
      for (const AreaLight& l : rig.lights) {
        double t;
        if (l.intersect(o, r, 0.0, t) && t < tl && t < tb) {
          tl = t;
          seen = &l;
        }
      }
      if (seen) {
        c = seen->radiance;
      } else if (std::isfinite(tb)) {  // the lit paper: the rig's light and the sky's, diffusely
        const glm::dvec3 q = o + tb * r;
        c = backdrop.albedo(q) / kPi * (rig.irradiance(q, nb) + sky.at(nb));
        if (backdrop.plane) c = glm::mix(studio.sky(r, 0.0), c, Studio::floor_visibility(tb));
      } else {
        c = studio.sky(r, 0.0);
      }
      m.rgb[size_t(y) * size_t(size) + size_t(x)] = glm::vec3(glm::min(c, glm::dvec3(6.0e4)));
    }
  return m;
}

MatCap matcap_from_image(const Image& img) {
  // Linear light first, then a box filter (or nearest sample up) to the MatCap's size.
  const int n = kMatCapSize;
  MatCap m{n, std::vector<glm::vec3>(size_t(n) * size_t(n))};
  auto lin = [&](int x, int y) {
    const std::uint8_t* q = img.px(x, y);
    return glm::vec3(float(srgb_to_linear(q[0] / 255.0)), float(srgb_to_linear(q[1] / 255.0)),
                     float(srgb_to_linear(q[2] / 255.0)));
  };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int x0 = x * img.width / n, x1 = std::max(x0 + 1, (x + 1) * img.width / n);
      const int y0 = y * img.height / n, y1 = std::max(y0 + 1, (y + 1) * img.height / n);
      glm::vec3 sum(0.0f);
      for (int j = y0; j < y1; ++j)
        for (int i = x0; i < x1; ++i) sum += lin(i, j);
      m.rgb[size_t(y) * size_t(n) + size_t(x)] = sum / float((x1 - x0) * (y1 - y0));
    }
  return m;
}

namespace {

std::mutex g_mutex;
struct FileEntry {
  std::filesystem::path file;
  std::filesystem::file_time_type written;
  std::uintmax_t bytes = 0;
  std::shared_ptr<const MatCap> matcap;
} g_file;
struct BakeEntry {
  std::string key;
  std::shared_ptr<const MatCap> matcap;
} g_bake;

// What a bake depends on, as text: every env.*, light.*, strips.*, backlight.* value,
// where the rig stands and where the bake looks from.
std::string bake_key(const SceneParams& p, const LightRig& rig, const BackdropSurface& b, const glm::dvec3& centre) {
  const std::string key = studio_params_key(p);
  char buf[240];
  std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g;%.9g;%.9g,%.9g,%.9g", rig.aim.x, rig.aim.y, rig.aim.z, b.z_curve,
                centre.x, centre.y, centre.z);
  return key + buf;
}

}  // namespace

std::shared_ptr<const MatCap> load_matcap_file(const std::string& name) {
  const std::string shown = shorten(name, kEchoPathBytes);
  if (name.empty()) throw InputError("expected a MatCap PNG file, got \"\"");
  std::error_code ec;
  if (!std::filesystem::exists(name, ec))
    throw InputError(shown + ": no such file (expected a MatCap PNG image)");
  const auto written = std::filesystem::last_write_time(name, ec);
  const auto bytes = std::filesystem::file_size(name, ec);
  {
    std::lock_guard lock(g_mutex);
    if (g_file.matcap && g_file.file == name && g_file.written == written && g_file.bytes == bytes) return g_file.matcap;
  }
  auto matcap = std::make_shared<const MatCap>(
      matcap_from_image(decode_png(read_whole_file(name, kMaxPngFileBytes, "a MatCap PNG image"), shown)));
  std::lock_guard lock(g_mutex);
  g_file = {name, written, bytes, matcap};
  return matcap;
}

void check_matcap_image(const std::string& name) {
  if (!name.empty()) load_matcap_file(name);
}

std::shared_ptr<const MatCap> matcap_for(const SceneParams& p, const LightRig& rig, const BackdropSurface& b,
                                         const glm::dvec3& centre) {
  if (!p.matcap.file.empty()) return load_matcap_file(p.matcap.file);
  std::string key = bake_key(p, rig, b, centre);
  {
    std::lock_guard lock(g_mutex);
    if (g_bake.matcap && g_bake.key == key) return g_bake.matcap;
  }
  auto matcap = std::make_shared<const MatCap>(bake_matcap(p, rig, b, centre));
  std::lock_guard lock(g_mutex);
  g_bake = {std::move(key), matcap};
  return matcap;
}

}  // namespace draught
