// A cloud file shown on its own (the web page's "Point cloud…"): whatever its units, the
// points land in the view, kCloudViewingExtent across, centred at kCloudViewingCentre; the
// preset written beside the file resolves as the CLI resolves any scene preset.
#include "core/pointcloud/cloud_viewing.hpp"

#include "core/params/preset.hpp"
#include "core/pointcloud/cloud_files.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/scene/frame.hpp"
#include "core/sim/scene_simulation.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

namespace draught {
namespace {

PointCloud cloud_of(std::vector<glm::vec3> points) {
  PointCloud c;
  c.position = std::move(points);
  return c;
}

TEST(CloudViewing, ACloudInMillimetresIsScaledToTheViewAndCentred) {
  const CloudFit fit = fit_cloud_to_view(cloud_of({{0, 0, 0}, {800, 100, 0}, {400, 0, 200}}));
  EXPECT_FLOAT_EQ(fit.scale, kCloudViewingExtent / 800.0f);
  // The box's centre (400, 50, 100) lands on the view's centre.
  const glm::vec3 centre = fit.position + glm::vec3(400, 50, 100) * fit.scale;
  EXPECT_NEAR(glm::distance(centre, kCloudViewingCentre), 0.0f, 1e-6f);
}

TEST(CloudViewing, AFilesRadiiGrowTheBox) {
  PointCloud c = cloud_of({{0, 0, 0}, {6, 0, 0}});
  c.radius = {1, 1};  // the box is 8 units across, not 6
  EXPECT_FLOAT_EQ(fit_cloud_to_view(c).scale, kCloudViewingExtent / 8.0f);
}

TEST(CloudViewing, OnePointKeepsItsScaleAndAnEmptyCloudIsRefused) {
  const CloudFit one = fit_cloud_to_view(cloud_of({{3, 4, 5}}));
  EXPECT_FLOAT_EQ(one.scale, 1.0f);
  EXPECT_NEAR(glm::distance(one.position + glm::vec3(3, 4, 5), kCloudViewingCentre), 0.0f, 1e-6f);
  EXPECT_THROW(fit_cloud_to_view(PointCloud{}), std::invalid_argument);
  // Kilometres of points are held to pointcloud.scale's smallest value, 1e-6.
  EXPECT_FLOAT_EQ(fit_cloud_to_view(cloud_of({{0, 0, 0}, {1e9f, 0, 0}})).scale, 1e-6f);
}

class CloudViewingFiles : public test::TempDirTest {
 protected:
  CloudViewingFiles() : TempDirTest("draught-cloud-viewing") {}
};

TEST_F(CloudViewingFiles, ThePresetBesideTheFileShowsThePointsFitted) {
  std::ofstream(dir_ / "scan.xyz") << "0 0 0\n2000 0 0\n1000 500 0\n1000 0 300\n";
  const CloudFit fit = fit_cloud_to_view(load_point_cloud(dir_ / "scan.xyz"));
  std::ofstream(dir_ / "scan.json") << cloud_viewing_preset("scan", "scan.xyz", fit);
  SceneRequest req;
  req.preset = (dir_ / "scan.json").string();
  const Scene scene = resolve_scene_objects(req);
  ASSERT_EQ(scene.objects.size(), 1u);
  ASSERT_NE(as_cloud(scene.objects[0]), nullptr);
  const FrameState f = SceneSimulation(scene).frame();
  ASSERT_EQ(f.clouds.size(), 1u);
  const PointCloud& c = *f.clouds[0].points;
  ASSERT_EQ(c.size(), 4u);
  glm::vec3 lo = c.position[0], hi = lo;
  for (const glm::vec3& p : c.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  EXPECT_NEAR(hi.x - lo.x, kCloudViewingExtent, 1e-6f);  // 2000 units across: the largest extent
  EXPECT_NEAR(glm::distance(0.5f * (lo + hi), kCloudViewingCentre), 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(as_cloud(scene.objects[0])->params.cooling, 0.0f);  // held: the data as it is
  EXPECT_FALSE(f.camera.auto_frame);
  EXPECT_NEAR(glm::distance(f.camera.target, kCloudViewingCentre), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace draught
