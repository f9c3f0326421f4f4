// The std140 uniform block of shaders/common.glsl, as a C++ struct. The asserts pin
// size and offsets so the two cannot drift apart silently.
#pragma once

#include "core/vessel/vessel.hpp"

#include <glm/glm.hpp>

#include <cstddef>

namespace draught::gpu {

struct FrameUniforms {
  glm::vec4 cam_eye, cam_right, cam_up, cam_forward;
  glm::vec4 viewport;
  glm::vec4 vessel, rim, glass, glass_absorb;
  glm::vec4 liquid_plane, liquid, liquid_absorb, haze_color;
  glm::vec4 light_dir, light_color;
  glm::vec4 env, env_color, sky_top, sky_horizon, ground, floor_a, floor_b;
  glm::vec4 output;
  glm::ivec4 limits;
  glm::vec4 pose_x, pose_y, pose_z, pose_pos;
  glm::vec4 waves;
  glm::vec4 foam, foam_color, foam_detail, lacing_info;
  glm::vec4 lacing[2];
  glm::vec4 bubbles[12];
  glm::vec4 clip;
  glm::vec4 knots[Vessel::kSegments + 1];
};

static_assert(sizeof(glm::vec4) == 16 && sizeof(glm::ivec4) == 16);
static_assert(offsetof(FrameUniforms, viewport) == 64);
static_assert(offsetof(FrameUniforms, vessel) == 80);
static_assert(offsetof(FrameUniforms, liquid_plane) == 144);
static_assert(offsetof(FrameUniforms, light_dir) == 208);
static_assert(offsetof(FrameUniforms, env) == 240);
static_assert(offsetof(FrameUniforms, output) == 352);
static_assert(offsetof(FrameUniforms, limits) == 368);
static_assert(offsetof(FrameUniforms, pose_x) == 384);
static_assert(offsetof(FrameUniforms, waves) == 448);
static_assert(offsetof(FrameUniforms, foam) == 464);
static_assert(offsetof(FrameUniforms, lacing) == 528);
static_assert(offsetof(FrameUniforms, bubbles) == 560);
static_assert(offsetof(FrameUniforms, clip) == 752);
static_assert(offsetof(FrameUniforms, knots) == 768);
static_assert(sizeof(FrameUniforms) == 768 + 16 * (Vessel::kSegments + 1));

}  // namespace draught::gpu
