// The droplets object: a trail of water spheres that follows a pointer (the seed's
// demo: metaballs by ray marching), an object kind of the scene beside the vessels.
// Its parameters, how a scene preset gives them, and its state in a frame.
// docs/DROPLETS.md.
#pragma once

#include "core/droplets/field.hpp"
#include "core/params/object_params.hpp"

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace draught {

struct DropletParams {
  int count = 16;                  // spheres in the trail (1 .. kMaxDroplets)
  float radius = 0.018f;           // m: the head's radius
  float taper = 0.6f;              // the tail's radius is radius (1 - taper)
  float blend = 0.02f;             // m: blend width of the smooth minimum
  int kernel = 0;                  // BlendKernel: 0 polynomial, 1 exponential
  float noise_amplitude = 0.0012f; // m
  float noise_frequency = 80.0f;   // 1/m
  float ior = 1.33f;               // water
  float roughness = 0.03f;         // GGX roughness of the surface
  glm::vec3 absorption{2.5f, 0.7f, 0.45f};  // 1/m: a little, water's red first
  float stiffness = 900.0f;        // 1/s^2: each sphere's spring to the one before it
  float damping = 16.0f;           // 1/s: the head's (the followers' at least sqrt(2 stiffness))
};

// One droplets field in a frame: its parameters, where it stands and its spheres (world).
struct DropletsFrame {
  DropletParams params;
  glm::vec3 position{0.0f};  // the placement: the trail's plane passes through it
  float yaw = 0;
  DropletField field;
};

// The parameters of a droplets object, for parsing, errors and docs/DROPLETS.md.
const std::vector<ObjectParamInfo>& droplet_param_table();

// The "droplets" object of a scene preset's object ({"count": 16, "blend": 0.02, ...}),
// every field checked: InputError "FILE: field 'AT.blend': expected a number in [0, 0.1]
// (m), got ...". Fields left out keep their defaults.
DropletParams parse_droplet_params(const nlohmann::json&, const std::string& file, const std::string& at);
nlohmann::json droplet_params_json(const DropletParams&);

// The field of a frame's spheres with these parameters.
DropletField droplet_field_of(const DropletParams&, std::vector<DropletSphere> spheres);

}  // namespace draught
