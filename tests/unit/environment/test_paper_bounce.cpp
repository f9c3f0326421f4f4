// The paper's own light where each point of it is (core/environment/paper_bounce): a
// floor that sees only the sky takes the sky's light exactly; under the key alone the
// paper far from the light takes less than the paper beside it (the light round the
// scene's centre, taken everywhere before, did not); the coarse map agrees with a fine
// gather of the exact lights at its texels; and the surroundings are made of it.
#include "core/environment/backdrop_light.hpp"
#include "core/environment/paper_bounce.hpp"
#include "core/environment/reflection.hpp"
#include "core/environment/sphere_grid.hpp"
#include "core/params/params.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {
namespace {

// The sweep under the key alone and a black sky.
SceneParams key_alone() {
  SceneParams p = default_params();
  p.env.mode = int(EnvMode::Constant);
  p.env.color = glm::vec3(0.0f);
  p.strips.power = p.backlight.power = 0;
  return p;
}

struct Studio3 {
  LightRig rig;
  BackdropSurface backdrop;
  SkyIrradiance sky;
  PaperBounceMap map;
  explicit Studio3(const SceneParams& p) {
    rig = light_rig(p, {0, 0.08, 0});
    backdrop = backdrop_surface(p.env, rig.aim);
    const Studio studio(p);
    sky = sky_irradiance(studio);
    map = paper_bounce_map(rig, backdrop, sky, rig.aim);
  }
  glm::dvec3 at(const glm::dvec2& xs) const {
    glm::dvec3 n;
    const glm::dvec3 p = backdrop_point(backdrop, xs, n);
    return map.at(backdrop, p);
  }
};

TEST(PaperBounce, AFloorUnderTheSkyAloneTakesTheSkysLight) {
  SceneParams p = default_params();
  p.env.mode = int(EnvMode::Constant);
  p.env.color = {0.3f, 0.5f, 0.7f};
  p.env.backdrop = int(Backdrop::Checker);
  const Studio3 s(p);
  ASSERT_FALSE(s.map.empty());
  for (const glm::dvec2 xs : {glm::dvec2(0, 0), glm::dvec2(1.2, -0.8), glm::dvec2(-2.5, 2.0)})
    EXPECT_NEAR(s.at(xs).b, std::numbers::pi * 0.7, 1e-3) << xs.x << ", " << xs.y;
}

TEST(PaperBounce, PaperFarFromTheLightTakesLessThanPaperBesideIt) {
  const Studio3 s(key_alone());
  const double z = s.backdrop.z_curve;
  const glm::dvec3 beside = s.at({0, z - 0.1}), far = s.at({0, z - 2.8}), far_across = s.at({2.8, z - 0.3});
  std::printf("key alone, facing up: beside the aim %.3f, 2.7 m in front %.3f, 2.8 m across %.3f\n", beside.g, far.g,
              far_across.g);
  EXPECT_LT(far.g, 0.5 * beside.g);
  EXPECT_LT(far_across.g, 0.5 * beside.g);
  for (const glm::dvec3& e : s.map.bounce) EXPECT_TRUE(e.x >= 0 && e.y >= 0 && e.z >= 0 && std::isfinite(e.x + e.y + e.z));
}

// At a texel, a fine gather (32 x 64 directions, each light's exact light where a
// direction meets the paper, the map's bounce there) is the map's own value: three rounds
// of a 6 x 12 grid round each texel's normal have settled.
TEST(PaperBounce, TheMapAgreesWithAFineGatherOfTheExactLights) {
  const Studio3 s(key_alone());
  const double z = s.backdrop.z_curve, wall = s.backdrop.radius * std::numbers::pi / 2;
  // The texels nearest the floor beside the aim, the curve, the wall half a metre up and
  // the floor a metre across.
  for (const glm::dvec2 xs : {glm::dvec2(0, z), glm::dvec2(0, 0.2), glm::dvec2(0, wall + 0.5), glm::dvec2(1.0, z)}) {
    const glm::dvec2 uv = (xs - s.map.origin) / s.map.size * glm::dvec2(s.map.width, s.map.height);
    const int i = std::clamp(int(uv.x), 0, s.map.width - 1), j = std::clamp(int(uv.y), 0, s.map.height - 1);
    glm::dvec3 n;
    const glm::dvec3 p = backdrop_point(s.backdrop, s.map.texel_centre(i, j), n), from = p + 1e-6 * n;
    glm::dvec3 fine = s.sky.at(n);
    for_each_sphere_cell(32, 64, [&](const glm::dvec3& d, double weight) {
      const double c = glm::dot(d, n);
      double t;
      glm::dvec3 m;
      if (c <= 0 || !s.backdrop.intersect(from, d, 0.0, t, m)) return;
      const glm::dvec3 q = from + t * d;
      const glm::dvec3 lit = s.rig.irradiance(q, m) + s.map.at(s.backdrop, q);
      fine += (s.backdrop.albedo(q) / std::numbers::pi * lit - s.sky.radiance(d)) * (c * weight);
    });
    const glm::dvec3 got = s.map.bounce[size_t(j) * size_t(s.map.width) + size_t(i)];
    std::printf("texel (%d, %d) at (%.2f, %.2f, %.2f): map %.4f, fine gather %.4f\n", i, j, p.x, p.y, p.z, got.g, fine.g);
    EXPECT_NEAR(got.g, fine.g, 0.12 * fine.g + 1e-3);
  }
}

TEST(PaperBounce, TheSurroundIsMadeOfTheMap) {
  const SceneParams p = key_alone();
  const LightRig rig = light_rig(p, {0, 0.08, 0});
  const BackdropSurface backdrop = backdrop_surface(p.env, rig.aim);
  const EnvironmentFrame f = environment_frame(p, rig, backdrop);
  ASSERT_TRUE(f.paper_bounce);
  // The same surround from the frame's map; without the paper's bounce (an empty map) the
  // paper the centre sees is darker.
  const SkyIrradiance again = surround_irradiance(Studio(p), f.sky, rig, backdrop, *f.paper_bounce, rig.aim);
  for (size_t k = 0; k < 9; ++k) EXPECT_EQ(again.coef[k], f.surround.coef[k]);
  const SkyIrradiance unlit = surround_irradiance(Studio(p), f.sky, rig, backdrop, PaperBounceMap{}, rig.aim);
  EXPECT_GT(f.surround.at({1, 0, 0}).g, unlit.at({1, 0, 0}).g);
  EXPECT_GT(f.surround.at({0, 1, 0}).g, unlit.at({0, 1, 0}).g);
}

}  // namespace
}  // namespace draught
