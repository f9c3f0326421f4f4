// A scene that shows one point cloud file on its own: the web page's "Point cloud…"
// button. The points are fitted to the view whatever the file's units (a simulation in
// millimetres, a scan in metres): scaled so the cloud's largest extent is
// kCloudViewingExtent and centred at kCloudViewingCentre, in the molten-gob preset's dark
// hot shop, so that hot glass glows as it does there. docs/POINT_CLOUDS.md.
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace draught {

inline constexpr float kCloudViewingExtent = 0.08f;              // m
inline constexpr glm::vec3 kCloudViewingCentre{0.0f, 0.12f, 0.0f};  // m, world

struct CloudFit {
  float scale = 1.0f;           // metres per unit of the file (the object's pointcloud.scale)
  glm::vec3 position{0.0f};     // the object's position: the file's centre lands at kCloudViewingCentre
};

// The fit of a cloud (its points' box, each grown by its radius; the radius in file units
// when the file gives radii). Throws std::invalid_argument for an empty cloud. The scale is
// clamped to pointcloud.scale's range; a cloud of one point (or all at one place) keeps
// scale 1.
CloudFit fit_cloud_to_view(const PointCloud&);

// The scene preset's text: one "pointcloud" object with source "file" and `file_name`
// (relative to where the preset is written, so the preset goes beside the file), placed
// by `fit`, its temperatures held (cooling 0), and the hot shop's camera, light and
// exposure. `name` is the preset's name.
std::string cloud_viewing_preset(const std::string& name, const std::string& file_name, const CloudFit& fit);

}  // namespace draught
