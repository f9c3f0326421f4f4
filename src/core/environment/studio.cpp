#include "core/environment/studio.hpp"

#include "core/environment/environment_files.hpp"
#include "core/math/smoothstep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
glm::dvec3 mix(const glm::dvec3& a, const glm::dvec3& b, double t) { return a + (b - a) * t; }
}  // namespace

Studio::Studio(const SceneParams& p) : env(p.env) {
  if (env.mode != int(EnvMode::Image)) return;
  image = load_environment(env.image);  // env.image was checked when it was set
  const double a = glm::radians(double(env.rotation));
  rotation_cos = std::cos(a);
  rotation_sin = std::sin(a);
  blur_lod = environment_lod(*image, glm::radians(double(env.blur)));
}

glm::dvec3 Studio::image_direction(const glm::dvec3& d) const {
  // The image turned by +rotation about +y (counter-clockwise seen from above) shows at d
  // what it showed at d turned by -rotation.
  return {rotation_cos * d.x - rotation_sin * d.z, d.y, rotation_sin * d.x + rotation_cos * d.z};
}

glm::dvec3 Studio::world_direction(const glm::dvec3& e) const {
  return {rotation_cos * e.x + rotation_sin * e.z, e.y, -rotation_sin * e.x + rotation_cos * e.z};
}

glm::dvec3 Studio::sky(const glm::dvec3& d, double roughness) const {
  if (!image) return sky(d);
  const double lobe = 2 * roughness * roughness;  // radians: the GGX lobe's width, as lights.glsl spreads highlights
  return double(env.intensity) *
         image->radiance(image_direction(d), std::max(blur_lod, environment_lod(*image, lobe)));
}

glm::dvec3 Studio::sky(const glm::dvec3& d) const {
  if (env.mode == int(EnvMode::Constant)) return glm::dvec3(env.color);
  if (image) return double(env.intensity) * image->radiance(image_direction(d), blur_lod);
  const glm::dvec3 top(env.sky_top), horizon(env.sky_horizon), ground(env.ground);
  glm::dvec3 s = d.y >= 0 ? mix(horizon, top, std::pow(d.y, 0.6)) : mix(horizon, ground, smoothstep(0.0, 0.25, -d.y));
  // Strip lights, left and right and a little behind the scene, tall and narrow.
  for (int i = 0; i < 2; ++i) {
    const double az = glm::radians(i == 0 ? 105.0 : -105.0);
    const double horiz = std::hypot(d.x, d.z);
    const double c = horiz > 1e-4 ? (d.x * std::sin(az) + d.z * std::cos(az)) / horiz : 0.0;
    const double across = smoothstep(0.985, 0.996, c);
    const double along = smoothstep(-0.15, 0.0, d.y) * (1 - smoothstep(0.55, 0.75, d.y));
    s += glm::dvec3(env.strip_intensity * across * along);
  }
  // The glow on the backdrop behind the scene.
  const glm::dvec3 g = glm::normalize(glm::dvec3(0.0, 0.12, -1.0));
  s += double(env.backdrop_glow) * glm::dvec3(1.0, 0.97, 0.92) * std::pow(std::max(glm::dot(d, g), 0.0), 200.0);
  return s;
}

double Studio::floor_visibility(double dist) { return std::exp(-dist / 2.0); }

std::string studio_params_key(const SceneParams& p) {
  std::string key;
  for (const ParamDesc& d : param_table()) {
    if (d.scope != ParamScope::Scene) continue;
    const std::string group = d.path.substr(0, d.path.find('.'));
    if (group == "env" || group == "light" || group == "strips" || group == "backlight")
      key += format_param(d, get_param(p, d)) + ";";
  }
  return key;
}

}  // namespace draught
