#include "core/environment/environment_bake.hpp"

#include "core/environment/backdrop.hpp"
#include "core/environment/environment_map.hpp"
#include "core/environment/lights.hpp"
#include "core/environment/sky_irradiance.hpp"
#include "core/environment/studio.hpp"
#include "core/io/files.hpp"
#include "core/text/echo.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace draught {

namespace {

double smooth(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// The studio as the scene's centre sees it, with no glass: the rig's lights, in front of
// the backdrop (the sweep lit by the rig and the sky, where env.floor is on), in front of
// the sky. The centre stands kBakeCentreHeight above the floor, as a glass's middle does.
constexpr double kBakeCentreHeight = 0.08;

struct StudioView {
  Studio studio;
  glm::dvec3 centre{0.0, kBakeCentreHeight, 0.0};
  LightRig rig;
  BackdropSurface backdrop;
  SkyIrradiance sky;
  explicit StudioView(const SceneParams& p)
      : studio(p), rig(light_rig(p, centre)), backdrop(backdrop_surface(p.env, centre)), sky(sky_irradiance(studio)) {}

  glm::dvec3 radiance(const glm::dvec3& d) const {
    double nearest = INFINITY, t;
    glm::dvec3 n, c = studio.sky(d);
    if (backdrop.present && backdrop.intersect(centre, d, 0.0, t, n)) {
      nearest = t;
      const glm::dvec3 p = centre + t * d;
      c = backdrop.albedo(p) / kPi * (rig.irradiance(p, n) + sky.at(n));
    }
    for (const AreaLight& l : rig.lights)
      if (l.intersect(centre, d, 0.0, t) && t < nearest) {
        nearest = t;
        c = l.radiance;
      }
    return c;
  }
};

// A warm bar at night, seen from a stool: dark wood, a back bar of lit bottles behind the
// glass, four pendant lamps of 2700 K, and a dim blue window to the right. Radiance in
// the same units as the studio's (W / (sr m^2); its key softbox is about 3).
glm::dvec3 bar_radiance(const glm::dvec3& d) {
  const double elev = std::asin(std::clamp(d.y, -1.0, 1.0));  // radians above the horizon
  const double az = std::atan2(d.x, -d.z);                      // 0 behind the glass, + to the right
  const glm::dvec3 warm(1.0, 0.62, 0.32), wood(0.022, 0.011, 0.005), wall(0.045, 0.026, 0.014);
  glm::dvec3 c = d.y < 0 ? wood * (0.5 + 0.5 * smooth(-0.5, 0.0, d.y))          // the counter and floor
                         : glm::mix(wall, glm::dvec3(0.006, 0.005, 0.004), smooth(0.15, 0.7, d.y));  // walls, ceiling
  // The back bar behind the glass: a warm-lit mirror wall with three shelves of bottles,
  // each bottle its own height and colour, lit from below.
  const double span = smooth(1.2, 1.0, std::abs(az));
  const double wall_band = smooth(glm::radians(-4.0), glm::radians(-3.0), elev) * (1 - smooth(glm::radians(25.0), glm::radians(27.0), elev));
  c += span * wall_band * warm * 0.08;
  for (int shelf = 0; shelf < 3; ++shelf) {
    const double lo = glm::radians(-3.0 + 9.0 * shelf);
    const double slot = az * 13.0 + 0.37 * shelf;
    const double k = std::floor(slot), f = slot - k;
    const double hash = std::fmod(std::abs(std::sin(k * 12.9898 + shelf * 78.233) * 43758.5453), 1.0);
    const double height = glm::radians(4.0 + 2.5 * hash);
    const double t = (elev - lo) / height;  // 0 at the shelf, 1 at the bottle's cap
    if (t < 0 || t > 1) continue;
    const double half_width = t < 0.65 ? 0.3 : 0.3 - 0.22 * smooth(0.65, 0.8, t);  // body, shoulder, neck
    const double bottle = smooth(half_width, half_width - 0.05, std::abs(f - 0.5));
    const int kind = int(hash * 97) % 4;
    const glm::dvec3 tint = kind == 0 ? glm::dvec3(1.0, 0.5, 0.12) : kind == 1 ? glm::dvec3(0.3, 0.65, 0.25)
                          : kind == 2 ? glm::dvec3(0.95, 0.9, 0.8) : glm::dvec3(0.7, 0.25, 0.1);
    c += span * bottle * tint * (0.5 + 1.8 * (1 - t));
  }
  // Pendant lamps: small bright discs up and around, each with a faint halo.
  const double lamps[4][2] = {{-0.55, 0.62}, {0.15, 0.75}, {0.85, 0.58}, {2.6, 0.7}};  // azimuth, elevation
  for (const auto& l : lamps) {
    const glm::dvec3 ld{std::cos(l[1]) * std::sin(l[0]), std::sin(l[1]), -std::cos(l[1]) * std::cos(l[0])};
    const double cos_a = glm::dot(d, ld);
    c += warm * 60.0 * smooth(std::cos(glm::radians(2.2)), std::cos(glm::radians(1.6)), cos_a);
    c += warm * 0.15 * std::pow(std::max(cos_a, 0.0), 400.0);
  }
  // A window to the right, dusk outside, in four panes.
  const double a0 = 1.45, a1 = 2.05, e0 = 0.06, e1 = 0.62;
  const double win = smooth(a0, a0 + 0.01, az) * (1 - smooth(a1 - 0.01, a1, az)) * smooth(e0, e0 + 0.01, elev) *
                     (1 - smooth(e1 - 0.01, e1, elev));
  const double bars = smooth(0.006, 0.012, std::abs(az - 0.5 * (a0 + a1))) * smooth(0.006, 0.012, std::abs(elev - 0.5 * (e0 + e1)));
  c += win * bars * glm::mix(glm::dvec3(0.45, 0.35, 0.4), glm::dvec3(0.15, 0.22, 0.45), (elev - e0) / (e1 - e0));
  return c;
}

}  // namespace

const std::vector<std::string>& baked_environment_names() {
  static const std::vector<std::string> names{"studio", "bar"};
  return names;
}

HdrImage bake_environment(const std::string& name, const SceneParams& scene, int width) {
  if (width < 8 || width > kMaxHdrImageWidth || width % 2 != 0)
    throw InputError("environment width " + std::to_string(width) + ": expected an even number from 8 to " +
                     std::to_string(kMaxHdrImageWidth));
  std::function<glm::dvec3(const glm::dvec3&)> radiance;
  SceneParams studio_scene = scene;
  if (studio_scene.env.mode == int(EnvMode::Image)) studio_scene.env.mode = int(EnvMode::Studio);  // not itself
  const StudioView studio(studio_scene);
  if (name == "studio")
    radiance = [&](const glm::dvec3& d) { return studio.radiance(d); };
  else if (name == "bar")
    radiance = bar_radiance;
  else
    throw InputError("unknown environment " + quote_input(name) + "; expected studio or bar");
  const int height = width / 2;
  HdrImage img{width, height, std::vector<glm::vec3>(size_t(width) * size_t(height))};
  constexpr int kGrid = 4;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // Directions weighted by the solid angle each covers (sin theta), so the texel holds
      // the mean radiance over its patch of sky.
      glm::dvec3 sum(0);
      double weight = 0;
      for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
          const double u = (x + (i + 0.5) / kGrid) / width, v = (y + (j + 0.5) / kGrid) / height;
          const double w = std::sin(v * kPi);
          sum += w * radiance(equirect_direction({u, v}));
          weight += w;
        }
      img.rgb[size_t(y) * size_t(width) + size_t(x)] = glm::vec3(weight > 0 ? sum / weight : glm::dvec3(0));
    }
  return img;
}

}  // namespace draught
