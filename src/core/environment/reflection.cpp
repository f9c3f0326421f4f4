#include "core/environment/reflection.hpp"

namespace draught {

EnvironmentFrame environment_frame(const EnvParams& env) {
  EnvironmentFrame f;
  // The sky's mean (as the shader's ambient_light), twice over for the bright studio
  // around a bubble, plus the lights it mirrors.
  const glm::vec3 sky = env.mode == int(EnvMode::Constant) ? env.color : 0.5f * (env.sky_top + env.sky_horizon);
  f.reflected = sky * 2.0f + glm::vec3(0.15f * env.strip_intensity + 0.1f * env.backdrop_glow);
  return f;
}

}  // namespace draught
