#include "stored_reference.hpp"

#include "core/io/hdr_image.hpp"
#include "core/io/files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

RadianceImage to_radiance(const HdrImage& img) {
  RadianceImage r;
  r.width = img.width;
  r.height = img.height;
  r.pixels.reserve(img.rgb.size());
  for (const glm::vec3& p : img.rgb) r.pixels.emplace_back(p);
  return r;
}

std::string text(const glm::vec3& v) {
  char s[96];
  std::snprintf(s, sizeof s, "%.9g %.9g %.9g", double(v.r), double(v.g), double(v.b));
  return s;
}

// Where `now` (path-traced in this run, stored as the file stores it) differs from
// `stored`, beyond the last bits a different CPU's maths library may round otherwise.
std::string first_difference(const HdrImage& stored, const RadianceImage& now) {
  for (int y = 0; y < now.height; ++y)
    for (int x = 0; x < now.width; ++x) {
      const glm::vec3 a = stored.at(x, y), b = glm::min(glm::vec3(now.at(x, y)), glm::vec3(kMaxHdrValue));
      for (int c = 0; c < 3; ++c)
        if (std::abs(a[c] - b[c]) > 1e-5f * std::max(std::abs(a[c]), std::abs(b[c])) + 1e-12f)
          return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " + text(b) + " now, " + text(a) +
                 " stored";
    }
  return "";
}

}  // namespace

StoredReference stored_reference(const std::filesystem::path& dir, const std::string& name, const FrameState& f,
                                 int width, int height, const ReferenceSettings& settings, bool bless) {
  const std::filesystem::path full = dir / (name + ".exr"), check = dir / (name + ".check.exr");
  // Named in messages from the folder's own name on (no machine's paths in logs).
  const std::string shown = (dir.filename() / (name + ".exr")).string();
  const std::string again = "scripts/bless-references.sh " + name;
  ReferenceSettings check_settings = settings;
  check_settings.samples = kCheckPaths;
  StoredReference out;
  if (bless) {
    out.radiance = render_reference(f, width, height, settings);
    std::filesystem::create_directories(dir);
    write_exr(full, radiance_hdr_image(out.radiance));
    write_exr(check, radiance_hdr_image(render_reference(f, width, height, check_settings)));
    char how[160];
    std::snprintf(how, sizeof how, "path-traced in %.1f s and stored", out.radiance.seconds);
    out.how = how + std::string(" in ") + shown;
    return out;
  }
  if (!std::filesystem::exists(full) || !std::filesystem::exists(check)) {
    out.error = shown + " or its check is missing: path-trace it with " + again;
    return out;
  }
  try {
    const HdrImage stored = read_hdr_image(full), stored_check = read_hdr_image(check);
    if (stored.width != width || stored.height != height || stored_check.width != width ||
        stored_check.height != height) {
      out.error = shown + " is " + std::to_string(stored.width) + " x " + std::to_string(stored.height) +
                  ", the case " + std::to_string(width) + " x " + std::to_string(height) + ": " + again;
      return out;
    }
    const RadianceImage now = render_reference(f, width, height, check_settings);
    if (const std::string d = first_difference(stored_check, now); !d.empty()) {
      out.error = shown + " was path-traced from another scene or other code: its first " +
                  std::to_string(kCheckPaths) + " paths differ (" + d + "). If the change is meant, run " + again +
                  " and look at the figures";
      return out;
    }
    out.radiance = to_radiance(stored);
    char how[200];
    std::snprintf(how, sizeof how, "stored, its %d-path check path-traced in %.2f s and equal", kCheckPaths,
                  now.seconds);
    out.how = how;
  } catch (const InputError& e) {
    out.error = std::string(e.what()) + ": " + again;
  }
  return out;
}

}  // namespace draught::test
