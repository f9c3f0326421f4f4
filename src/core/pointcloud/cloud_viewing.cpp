#include "core/pointcloud/cloud_viewing.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>

namespace draught {

CloudFit fit_cloud_to_view(const PointCloud& cloud) {
  if (cloud.size() == 0) throw std::invalid_argument("the cloud has no points");
  glm::vec3 lo = cloud.position[0], hi = lo;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    // A file's radii are in its own units, like its positions; points without one get
    // a blob of 2 mm in the world, after the scale, so they do not enter the box.
    const float r = cloud.radius.empty() ? 0.0f : cloud.radius[i];
    lo = glm::min(lo, cloud.position[i] - r);
    hi = glm::max(hi, cloud.position[i] + r);
  }
  const glm::vec3 size = hi - lo;
  const float extent = std::max({size.x, size.y, size.z});
  CloudFit fit;
  // pointcloud.scale's range (core/pointcloud/cloud_object.cpp): 1e-6 to 1000.
  if (extent > 0.0f) fit.scale = std::clamp(kCloudViewingExtent / extent, 1e-6f, 1e3f);
  fit.position = kCloudViewingCentre - 0.5f * (lo + hi) * fit.scale;
  return fit;
}

std::string cloud_viewing_preset(const std::string& name, const std::string& file_name, const CloudFit& fit) {
  using nlohmann::json;
  const glm::vec3 t = kCloudViewingCentre;
  // The molten-gob preset's view and hot shop: a dark sweep, a dimmed key, no backlight.
  const json scene = {
      {"draught_preset", 1},
      {"kind", "scene"},
      {"name", name},
      {"description", "The point cloud " + file_name + ", fitted to the view (" + std::to_string(fit.scale) +
                          " m per unit of the file)"},
      {"params",
       {{"camera",
         {{"auto_frame", false},
          {"eye", {t.x + 0.035, t.y + 0.05, t.z + 0.34}},
          {"target", {t.x, t.y, t.z}},
          {"vfov", 24.0}}},
        {"env", {{"sweep_color", {0.05, 0.05, 0.055}}}},
        {"light", {{"power", 2.0}}},
        {"backlight", {{"power", 0.0}}},
        {"render", {{"exposure", 0.6}}}}},
      {"objects",
       json::array({{{"name", "cloud"},
                     {"kind", "pointcloud"},
                     {"position", {fit.position.x, fit.position.y, fit.position.z}},
                                          // The file's temperatures held (cooling 0): data to look at, and a
                     // cloud that does not change is not refit, uploaded or shadowed again
                     // every frame (1M points: seconds a frame in a browser).
                     {"pointcloud", {{"source", "file"}, {"file", file_name}, {"scale", fit.scale}, {"cooling", 0}}}}})}};
  return scene.dump(2) + "\n";
}

}  // namespace draught
