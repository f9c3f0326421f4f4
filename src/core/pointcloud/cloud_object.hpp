// The point-cloud object: a cloud of metaballs in the scene (issue 14), from a built-in
// source (a molten-glass gob turning on a blowpipe, a falling stream) or from files (one
// PLY/XYZ/CSV cloud, or a numbered sequence played at a rate). Its parameters, how a
// scene preset gives them, the source that animates it, and its state in a frame.
// docs/POINT_CLOUDS.md.
#pragma once

#include "core/params/object_params.hpp"
#include "core/pointcloud/cloud.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace draught {

// Point-cloud objects one scene may hold: each takes at most two of the frame's
// contract::kMaxClouds clouds (a gob and its blowpipe).
inline constexpr int kMaxCloudObjects = contract::kMaxClouds / 2;

enum class CloudSourceKind : int { Gob = 0, Stream = 1, File = 2 };
// What the blob is made of (src/interface/constants.def): hot glass, or a drink.
using contract::CloudMaterial;

// The picture's radiance per cd/m^2 of a blackbody's glow at glow = 1: the studio's
// lights are of order 1-10 in the picture's units, and glass at 1100 C shines at about
// 10^4 cd/m^2, so one unit per 1000 cd/m^2 shows a gob at working heat bright and
// yellow-orange, and at 700 C a dull red, as photographs of a glassblower's bench do.
inline constexpr double kGlowPerNit = 1e-3;

struct PointCloudParams {
  int source = 0;                  // CloudSourceKind
  std::string file;                // File: a cloud, or one frame of a numbered sequence (frame_0001.ply)
  float rate = 24.0f;              // File sequences: frames per second
  bool loop = true;                // File sequences: loop (or hold the last frame)
  float scale = 1.0f;              // File: metres per unit of the file's coordinates
  float blob_radius = 0;           // m: a lone point's radius (points without their own; the gob's);
                                   // 0: automatic (files 2 mm, the gob 1.7 x its particles' spacing)
  float threshold = 0.5f;          // the summed field's level that is the surface
  int material = 0;                // CloudMaterial
  float temperature = 1373.15f;    // K: the gob's start; file points without their own
  float cooling = 40.0f;           // s: time constant of the cooling towards the room (0: none)
  float glow = 1.0f;               // multiplies the blackbody emission (an exposure of its own)
  float glow_depth = 0.02f;        // m: hot glass's visible extinction is 1 / glow_depth at 1100 K
  float ior = 1.5f;                // index of refraction (soda-lime glass; a drink's ~1.34)
  float roughness = 0.02f;         // GGX roughness of the surface
  glm::vec3 absorption{0.9f, 0.35f, 0.6f};  // 1/m: Beer-Lambert (glass: a little green)
  int count = 6000;                // Gob: particles
  float gob_radius = 0.035f;       // Gob: m
  float turn = 2.0f;               // Gob: rad/s the blowpipe turns
  float flow = 1.5e-4f;            // Stream: m^3/s
  float height = 0.25f;            // Stream: m the spout stands above the placement
  float age = 1.5f;                // s the source has run before the scene's time 0 (a still shows a gob that
                                   // has turned and sagged, a stream that has landed)
};

// The parameters of a point-cloud object, for parsing, errors and docs/POINT_CLOUDS.md.
const std::vector<ObjectParamInfo>& point_cloud_param_table();

// The "pointcloud" object of a scene preset's object, every field checked (InputError
// "FILE: field 'AT.glow': expected a number in [0, 100], got ..."). A relative `file` is
// taken from `base_dir` (the scene file's folder); the file is not read here.
PointCloudParams parse_point_cloud_params(const nlohmann::json&, const std::string& file, const std::string& at,
                                          const std::string& base_dir = "");
nlohmann::json point_cloud_params_json(const PointCloudParams&);

// One cloud in a frame (a scene holds at most contract::kMaxClouds: they share the data
// textures, each with its own root): its points in the world and how to draw them. The points are
// shared, not copied, from frame to frame; `version` changes whenever they do, so the
// renderer uploads a cloud only when it moved.
struct CloudFrame {
  std::shared_ptr<const PointCloud> points;  // world positions, blob radii, temperatures
  std::uint64_t version = 0;
  int material = 0;          // CloudMaterial
  float threshold = 0.5f;
  float glow = 0;            // 0: no emission (a drink)
  float glow_depth = 0;      // m: 1 / the visible extinction of the hot body (0: none)
  float ior = 1.5f, roughness = 0.02f;
  glm::vec3 absorption{0.0f};
  glm::vec3 color{1.0f};     // the colour of points without their own (the drink's tint)
  float temperature = 293.15f;  // K of points without their own
  glm::vec3 placement{0.0f};    // its object's position (the scene's centre is taken from it)
};

// The runtime of one point-cloud object: its source advanced on the scene's clock, its
// points placed in the world. Deterministic (the same times give the same points).
class CloudSource {
 public:
  // Throws InputError when a file source cannot be read (named).
  CloudSource(const PointCloudParams&, glm::vec3 position, float yaw);
  ~CloudSource();
  CloudSource(CloudSource&&) noexcept;
  CloudSource& operator=(CloudSource&&) noexcept;

  // Steps the source to time t (seconds since the scene began; earlier times are ignored).
  void advance_to(double t);
  double time() const { return time_; }
  // Its clouds in this frame: the source's, and for a gob its blowpipe (a cloud of its
  // own, so that neither field nor colour blends into the glass).
  std::vector<CloudFrame> frames() const;
  const PointCloudParams& params() const { return params_; }

 private:
  struct State;
  PointCloudParams params_;
  glm::vec3 position_{0.0f};
  float yaw_ = 0;
  double time_ = 0;
  std::unique_ptr<State> state_;
};

}  // namespace draught
