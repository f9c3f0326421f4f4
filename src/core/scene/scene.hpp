// A scene: the surroundings (SceneParams) and a list of objects, each placed in the world.
// Today's one kind of object is a vessel: a glass with its drink. A new kind (a field of
// metaball droplets, a point cloud) is a struct of its own in its own core folder, added
// to ObjectKind below; nothing else in the scene or the vessel code changes (see
// docs/ARCHITECTURE.md, "How to add an object kind").
#pragma once

#include "core/droplets/droplets.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/params/params.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace draught {

// Where an object stands: on the floor (world y = 0) at (x, z), turned by yaw about the
// world's up axis. Motion (tilt, slosh, a shake) is added by the object's simulation.
struct Placement {
  glm::vec3 position{0.0f};  // metres; y is the height of the foot above the floor
  float yaw = 0;             // degrees, counter-clockwise seen from above
};

// A glass and its drink.
struct VesselObject {
  VesselParams params;
};

// A trail of water droplets following a pointer (core/droplets, docs/DROPLETS.md). At most
// one per scene (its spheres travel in the Frame block).
struct DropletsObject {
  DropletParams params;
};

// A cloud of metaballs: molten glass, a stream, points from files (core/pointcloud,
// docs/POINT_CLOUDS.md). Up to contract::kMaxClouds per scene (they share the data textures).
struct PointCloudObject {
  PointCloudParams params;
};

// Every kind an object can be (one registration per kind).
using ObjectKind = std::variant<VesselObject, DropletsObject, PointCloudObject>;

struct SceneObject {
  std::string name;  // from the scene file ("pilsner"); unique within the scene
  Placement placement;
  ObjectKind kind;
};

// The most objects one scene may hold (src/interface/constants.def). Object data reaches
// the GPU in data textures (one row per object), so this is not the 16 KB uniform-block
// limit of GLES 3.0; it bounds the per-pixel object loop and the simulation's cost.
// Tested at the limit (tests/gpu).
inline constexpr int kMaxSceneObjects = contract::kMaxSceneObjects;

struct Scene {
  SceneParams params;
  std::vector<SceneObject> objects;
  int selected = 0;  // the object that input drives (viewer, web page)
};

// The scene of a single-glass document: one vessel at the origin.
Scene single_glass_scene(const Params&);
// The document of one vessel in its scene (what a single-glass UI or the old API edits).
Params vessel_document(const Scene&, int object);

// A parameter path that may name one object: "objects[2].liquid.fill" (object 2),
// "liquid.fill" (every vessel object; object = -1), "env.floor" (the scene).
struct ParamRef {
  int object = -1;
  const ParamDesc* desc = nullptr;
};
// The two parts of a path: "objects[2].liquid.fill" -> {2, "liquid.fill"}; a path without
// the prefix -> {-1, path}. Throws ParamError for a malformed prefix ("objects[x].a",
// "objects[2]"); the index is not checked against a scene here.
struct ObjectPath {
  int object = -1;
  std::string_view param;
};
ObjectPath split_object_path(std::string_view path);
// "an object index from 0 to 3 (the scene has 4 objects)": what an objects[N] prefix of
// this scene may be, for error messages.
std::string object_range_text(const Scene&);
// Throws ParamError for an unknown path (the message suggests the nearest), an object
// index out of range, or an object prefix on a scene parameter.
ParamRef parse_param_ref(const Scene&, std::string_view path);
// Reads a value (object -1 on a vessel parameter reads the selected object).
ParamValue get_param(const Scene&, const ParamRef&);
// Checks and sets (object -1 on a vessel parameter sets every vessel object); nothing is
// written unless the value is valid.
void set_param(Scene&, const ParamRef&, const ParamValue&);

// The vessel of an object, or nullptr for another kind.
inline VesselObject* as_vessel(SceneObject& o) { return std::get_if<VesselObject>(&o.kind); }
inline const VesselObject* as_vessel(const SceneObject& o) { return std::get_if<VesselObject>(&o.kind); }
inline DropletsObject* as_droplets(SceneObject& o) { return std::get_if<DropletsObject>(&o.kind); }
inline const DropletsObject* as_droplets(const SceneObject& o) { return std::get_if<DropletsObject>(&o.kind); }
inline PointCloudObject* as_cloud(SceneObject& o) { return std::get_if<PointCloudObject>(&o.kind); }
inline const PointCloudObject* as_cloud(const SceneObject& o) { return std::get_if<PointCloudObject>(&o.kind); }

}  // namespace draught
