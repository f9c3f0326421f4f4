// The environment estimate handed to the renderer: what a rising bubble mirrors is the
// sky's mean (as the path pass's ambient light) twice over plus the studio's lights; in
// constant mode the constant colour.
#include "core/environment/reflection.hpp"
#include "core/params/params.hpp"

#include <gtest/gtest.h>

namespace draught {
namespace {

TEST(Environment, BubblesMirrorTheStudioAndItsLights) {
  EnvParams env = default_params().env;
  env.mode = int(EnvMode::Studio);
  env.sky_top = {0.2f, 0.3f, 0.4f};
  env.sky_horizon = {0.6f, 0.5f, 0.4f};
  env.strip_intensity = 2.0f;
  env.backdrop_glow = 1.0f;
  const glm::vec3 r = environment_frame(env).reflected;
  const glm::vec3 expected = 0.5f * (env.sky_top + env.sky_horizon) * 2.0f + glm::vec3(0.15f * 2.0f + 0.1f * 1.0f);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(r[c], expected[c]);
  env.strip_intensity = env.backdrop_glow = 0;
  env.mode = int(EnvMode::Constant);
  env.color = {0.5f, 0.5f, 0.5f};
  EXPECT_FLOAT_EQ(environment_frame(env).reflected.g, 1.0f);
}

}  // namespace
}  // namespace draught
