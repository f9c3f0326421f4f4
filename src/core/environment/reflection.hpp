// What the surroundings give the renderer beyond its own per-pixel look-ups: estimates
// that are physics of the environment, computed once per frame on the CPU.
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

namespace draught {

struct EnvironmentFrame {
  // The radiance a small mirror-like sphere (a rising bubble) reflects on average: the
  // studio around it, whose lights (strip lights, backdrop glow) are several times its
  // sky. The bubble pass scales it by each bubble's Fresnel reflectance.
  glm::vec3 reflected{0.0f};
};

EnvironmentFrame environment_frame(const EnvParams&);

}  // namespace draught
