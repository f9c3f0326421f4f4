// The point-cloud object: its parameters as a scene preset gives them (every mistake named
// with the file, the field and what was expected), its sources on the scene's clock (the
// gob with its blowpipe, files placed by position, yaw and scale, sequences played at a
// rate), deterministic; and the frame's trees kept, refit or rebuilt as the points move.
#include "core/pointcloud/cloud_object.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/pointcloud/cloud_scene.hpp"
#include "core/scene/frame.hpp"
#include "core/sim/scene_simulation.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace draught {
namespace {

using test::has;

std::string parse_error(const std::string& text) {
  return test::input_error_of([&] { parse_point_cloud_params(nlohmann::json::parse(text), "gob.json", "objects[1].pointcloud"); });
}

TEST(PointCloudObject, EveryMistakeIsNamedWithItsFieldAndWhatWasExpected) {
  EXPECT_TRUE(has(parse_error(R"({"glwo": 2})"), {"gob.json", "objects[1].pointcloud.glwo", "unknown", "glow"}));
  EXPECT_TRUE(has(parse_error(R"({"source": "bucket"})"), {"objects[1].pointcloud.source", "\"gob\"", "\"file\""}));
  EXPECT_TRUE(has(parse_error(R"({"source": "file"})"), {"objects[1].pointcloud.file", "missing"}));
  EXPECT_TRUE(has(parse_error(R"({"file": "a.ply"})"), {"objects[1].pointcloud.file", "only a \"file\" source"}));
  EXPECT_TRUE(has(parse_error(R"({"count": 12.5})"), {"objects[1].pointcloud.count", "whole number", "[500, 50000]"}));
  EXPECT_TRUE(has(parse_error(R"({"glow": -1})"), {"objects[1].pointcloud.glow", "[0, 100]", "-1"}));
  EXPECT_TRUE(has(parse_error(R"({"absorption": [1, 2]})"), {"objects[1].pointcloud.absorption", "[r, g, b]"}));
  EXPECT_TRUE(has(parse_error(R"({"material": "lava"})"), {"objects[1].pointcloud.material", "\"molten_glass\""}));
  EXPECT_TRUE(has(parse_error(R"({"loop": 1})"), {"objects[1].pointcloud.loop", "true or false"}));
  EXPECT_TRUE(has(parse_error(R"([1])"), {"objects[1].pointcloud", "expected an object"}));
  EXPECT_EQ(parse_error(R"({"source": "file", "file": "frames/frame_0001.ply", "rate": 12})"), "no error");
}

TEST(PointCloudObject, ParametersSurviveTheirJson) {
  PointCloudParams p = parse_point_cloud_params(
      nlohmann::json::parse(R"({"source": "gob", "count": 900, "turn": -1.5, "temperature": 1200, "glow": 2,
                                "glow_depth": 0.05, "absorption": [1, 2, 3], "age": 0.25})"),
      "gob.json", "pointcloud");
  const PointCloudParams q = parse_point_cloud_params(point_cloud_params_json(p), "again.json", "pointcloud");
  EXPECT_EQ(point_cloud_params_json(p), point_cloud_params_json(q));
  EXPECT_EQ(q.count, 900);
  EXPECT_FLOAT_EQ(q.turn, -1.5f);
  EXPECT_FLOAT_EQ(q.absorption.z, 3.0f);
  EXPECT_FLOAT_EQ(q.age, 0.25f);
}

TEST(PointCloudObject, ARelativeFileIsTakenFromTheSceneFilesFolder) {
  const PointCloudParams p = parse_point_cloud_params(nlohmann::json::parse(R"({"source": "file", "file": "pts/a.ply"})"),
                                                      "scene.json", "pointcloud", "shots/scenes");
  EXPECT_EQ(std::filesystem::path(p.file), std::filesystem::path("shots/scenes/pts/a.ply"));
}

PointCloudParams small_gob() {
  PointCloudParams p;
  p.count = 600;
  p.gob_radius = 0.02f;
  p.age = 0.1f;
  return p;
}

TEST(PointCloudObject, TheGobTurnsOnItsBlowpipeTheSameEveryTime) {
  CloudSource a(small_gob(), {0.1f, 0.2f, 0.0f}, 30.0f), b(small_gob(), {0.1f, 0.2f, 0.0f}, 30.0f);
  const std::vector<CloudFrame> start = a.frames();
  ASSERT_EQ(start.size(), 2u);  // the gob and its blowpipe
  EXPECT_GT(start[0].points->size(), 400u);
  EXPECT_GT(start[0].glow, 0.0f);
  EXPECT_EQ(start[1].glow, 0.0f);  // the pipe: cold
  // The pipe lies along the gob's -x, turned by the yaw about +y, from the placement.
  const glm::vec3 far = start[1].points->position.back();
  const float c = std::cos(glm::radians(30.0f)), s = std::sin(glm::radians(30.0f));
  const glm::vec3 along = glm::normalize(far - glm::vec3(0.1f, 0.2f, 0.0f));
  EXPECT_NEAR(glm::dot(along, glm::vec3(-c, 0.0f, s)), 1.0f, 1e-4f);
  a.advance_to(0.5);
  b.advance_to(0.5);
  const std::vector<CloudFrame> fa = a.frames(), fb = b.frames();
  EXPECT_NE(fa[0].version, start[0].version);        // it moved
  EXPECT_EQ(fa[1].version, start[1].version);        // the pipe did not
  ASSERT_EQ(fa[0].points->size(), fb[0].points->size());
  for (std::size_t i = 0; i < fa[0].points->size(); ++i) ASSERT_EQ(fa[0].points->position[i], fb[0].points->position[i]);
  EXPECT_EQ(a.frames()[0].version, fa[0].version);  // asked again at the same time: the same points
}

// What the table accepts, the gob's model takes: each of the gob's parameters at either
// end of its range (the others at their defaults) makes a gob, not an error from inside.
TEST(PointCloudObject, EveryValueTheTableAcceptsMakesAGob) {
  for (const char* key : {"count", "gob_radius", "turn", "temperature", "blob_radius"})
    for (bool high : {false, true}) {
      const ObjectParamInfo* info = nullptr;
      for (const ObjectParamInfo& row : point_cloud_param_table())
        if (std::string(row.name) == key) info = &row;
      ASSERT_NE(info, nullptr) << key;
      nlohmann::json j = {{"age", 0}};
      j[key] = high ? info->max : info->min;
      if (std::string(key) == "count") j[key] = int(high ? info->max : info->min);
      const PointCloudParams p = parse_point_cloud_params(j, "gob.json", "objects[0].pointcloud");
      EXPECT_NO_THROW(CloudSource(p, {}, 0)) << key << " = " << j[key];
    }
}

class PointCloudFiles : public test::TempDirTest {
 protected:
  PointCloudFiles() : TempDirTest("draught-cloud-object") {}
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
};

TEST_F(PointCloudFiles, AFileIsScaledTurnedAndPlaced) {
  write("two.xyz", "x y z radius\n1 0 0 2\n0 0 1 4\n");
  PointCloudParams p;
  p.source = int(CloudSourceKind::File);
  p.file = (dir_ / "two.xyz").string();
  p.scale = 0.01f;
  p.cooling = 0;
  p.temperature = 1000;
  CloudSource src(p, {0.5f, 0.1f, 0.0f}, 90.0f);
  const std::vector<CloudFrame> f = src.frames();
  ASSERT_EQ(f.size(), 1u);
  const PointCloud& c = *f[0].points;
  // +x turned 90 degrees counter-clockwise seen from above is -z.
  EXPECT_NEAR(glm::distance(c.position[0], glm::vec3(0.5f, 0.1f, -0.01f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(c.position[1], glm::vec3(0.51f, 0.1f, 0.0f)), 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(c.radius[0], 0.02f);
  EXPECT_FLOAT_EQ(c.radius[1], 0.04f);
  EXPECT_FLOAT_EQ(c.temperature[0], 1000.0f);  // points without their own take the object's
}

TEST_F(PointCloudFiles, AMissingFileIsNamed) {
  PointCloudParams p;
  p.source = int(CloudSourceKind::File);
  p.file = (dir_ / "gone.ply").string();
  try {
    CloudSource src(p, {}, 0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.what(), {"gone.ply"}));
  }
}

TEST_F(PointCloudFiles, ASequencePlaysAtItsRate) {
  for (int i = 1; i <= 3; ++i) write("frame_000" + std::to_string(i) + ".xyz", "0 0 0\n" + std::to_string(i) + " 0 0\n");
  PointCloudParams p;
  p.source = int(CloudSourceKind::File);
  p.file = (dir_ / "frame_0001.xyz").string();
  p.rate = 4;
  p.loop = false;
  CloudSource src(p, {}, 0);
  auto x_of_second = [&] { return src.frames()[0].points->position[1].x; };
  EXPECT_FLOAT_EQ(x_of_second(), 1.0f);
  src.advance_to(0.3);  // frame floor(0.3 x 4) = 1
  EXPECT_FLOAT_EQ(x_of_second(), 2.0f);
  src.advance_to(5.0);  // held at the last
  EXPECT_FLOAT_EQ(x_of_second(), 3.0f);
}

TEST(PointCloudScene, TreesAreKeptWhileThePointsHoldStillAndRefitWhenTheyMove) {
  CloudSource gob(small_gob(), {0.0f, 0.2f, 0.0f}, 0.0f);
  CloudScene scene;
  EXPECT_TRUE(scene.update(gob.frames()));
  EXPECT_EQ(scene.built(), 2);
  ASSERT_EQ(scene.ranges().size(), 2u);
  EXPECT_EQ(scene.texels().point_count(), int(gob.frames()[0].points->size() + gob.frames()[1].points->size()));
  EXPECT_FALSE(scene.update(gob.frames()));  // nothing moved: no tree, no upload
  EXPECT_EQ(scene.built() + scene.refit(), 0);
  gob.advance_to(0.05);
  EXPECT_TRUE(scene.update(gob.frames()));
  EXPECT_EQ(scene.built() + scene.refit(), 1);  // the gob's tree; the pipe's is kept
  EXPECT_TRUE(scene.update({}));
  EXPECT_TRUE(scene.ranges().empty());
}

// The arrays flattened afresh from these clouds and the scene's trees of them (what every
// update, in place or not, must equal).
CloudTexels flattened_afresh(const CloudScene& scene, const std::vector<CloudFrame>& clouds) {
  CloudTexels tx;
  for (std::size_t i = 0; i < clouds.size(); ++i) tx.append(*clouds[i].points, scene.tree(i));
  return tx;
}

void expect_same_texels(const CloudTexels& a, const CloudTexels& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.attrs, b.attrs);
  EXPECT_EQ(a.nodes, b.nodes);
  ASSERT_EQ(a.clouds.size(), b.clouds.size());
  for (std::size_t i = 0; i < a.clouds.size(); ++i) {
    EXPECT_EQ(a.clouds[i].first_point, b.clouds[i].first_point);
    EXPECT_EQ(a.clouds[i].first_node, b.clouds[i].first_node);
    EXPECT_EQ(a.clouds[i].root, b.clouds[i].root);
    EXPECT_EQ(a.clouds[i].lo, b.clouds[i].lo);
    EXPECT_EQ(a.clouds[i].hi, b.clouds[i].hi);
  }
}

TEST(PointCloudScene, OnlyTheTexelsOfCloudsThatChangedAreWrittenAgain) {
  // A gob moving in front of its still blowpipe, then a stream after them that grows.
  CloudSource gob(small_gob(), {0.0f, 0.2f, 0.0f}, 0.0f);
  auto stream = [](int n, std::uint64_t version) {
    PointCloud p;
    for (int i = 0; i < n; ++i) p.position.push_back({0.3f, 0.01f * float(i), 0.0f});
    CloudFrame f;
    f.points = std::make_shared<const PointCloud>(std::move(p));
    f.version = version;
    return f;
  };
  CloudScene scene;
  std::vector<CloudFrame> frames = gob.frames();
  frames.push_back(stream(40, 1));
  ASSERT_TRUE(scene.update(frames));
  const CloudTexels first = scene.texels();
  EXPECT_EQ(scene.changed().points_first, 0u);
  EXPECT_EQ(scene.changed().points_end, std::size_t(first.point_count()));

  // The gob moves (the same count: its tree refit): its texels only, in place.
  gob.advance_to(0.05);
  frames = gob.frames();
  frames.push_back(stream(40, 1));
  ASSERT_TRUE(scene.update(frames));
  const CloudRange& g = scene.ranges()[0];
  EXPECT_EQ(scene.changed().points_first, std::size_t(g.first_point));
  EXPECT_EQ(scene.changed().points_end, std::size_t(g.first_point + g.point_count));
  EXPECT_EQ(scene.changed().nodes_first, 2 * std::size_t(g.first_node));
  EXPECT_EQ(scene.changed().nodes_end, 2 * std::size_t(g.first_node + g.node_count));
  EXPECT_NE(scene.texels().points, first.points);
  expect_same_texels(scene.texels(), flattened_afresh(scene, frames));

  // The stream grows: from its first texel on, the gob and the pipe untouched.
  frames.back() = stream(55, 2);
  ASSERT_TRUE(scene.update(frames));
  const CloudRange& s = scene.ranges()[2];
  EXPECT_EQ(scene.changed().points_first, std::size_t(s.first_point));
  EXPECT_EQ(scene.changed().points_end, std::size_t(s.first_point + 55));
  EXPECT_EQ(scene.changed().nodes_first, 2 * std::size_t(s.first_node));
  expect_same_texels(scene.texels(), flattened_afresh(scene, frames));

  // Gone again: the ranges shrink, nothing to write.
  frames.pop_back();
  ASSERT_TRUE(scene.update(frames));
  EXPECT_TRUE(scene.changed().empty());
  expect_same_texels(scene.texels(), flattened_afresh(scene, frames));
  EXPECT_FALSE(scene.update(frames));
}

TEST(PointCloudScene, ARewriteOfOtherCountsIsRefusedAndChangesNothing) {
  CloudSource gob(small_gob(), {0.0f, 0.2f, 0.0f}, 0.0f);
  CloudScene scene;
  scene.update(gob.frames());
  CloudTexels tx = scene.texels();
  const CloudTexels before = tx;
  PointCloud fewer = *gob.frames()[0].points;
  fewer.position.pop_back();
  const CloudBvh tree = build_cloud_bvh(fewer, 1.0f);
  std::string e = "no error";
  try {
    tx.rewrite(0, fewer, tree);
  } catch (const std::invalid_argument& x) {
    e = x.what();
  }
  EXPECT_TRUE(has(e, {"cloud 0", "points", "nodes"}));
  expect_same_texels(tx, before);
}

TEST(PointCloudScene, AScenePresetPlacesAGobBesideAGlass) {
  const std::string text = R"({"draught_preset": 1, "kind": "scene", "name": "bench",
    "objects": [{"name": "pint", "glass": "pint", "drink": "lager"},
                {"name": "gob", "kind": "pointcloud", "position": [0.2, 0.15, 0], "pointcloud": {"count": 500}}]})";
  const Preset preset = parse_preset(text, "bench.json");
  const Scene scene = scene_from_preset(preset);
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_NE(as_cloud(scene.objects[1]), nullptr);
  SceneSimulation sim(scene);
  const FrameState f = sim.frame();
  EXPECT_EQ(f.vessels.size(), 1u);
  EXPECT_EQ(f.clouds.size(), 2u);
  // A cloud's keys are its own; a vessel's are not.
  auto error = [&](const std::string& obj) {
    try {
      parse_preset(R"({"draught_preset": 1, "kind": "scene", "name": "x", "objects": [)" + obj + "]}", "x.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_TRUE(has(error(R"({"name": "g", "kind": "pointcloud", "glass": "pint"})"), {"objects[0].glass", "pointcloud"}));
  EXPECT_TRUE(has(error(R"({"name": "g", "pointcloud": {}})"), {"objects[0].pointcloud", "only an object"}));
  EXPECT_TRUE(has(error(R"({"name": "g", "kind": "cloud"})"), {"objects[0].kind", "\"pointcloud\""}));
  std::string five;
  for (int i = 0; i < 5; ++i)
    five += std::string(i ? "," : "") + R"({"name": "g)" + std::to_string(i) + R"(", "kind": "pointcloud", "position": [)" +
            std::to_string(0.2 * i) + ", 0.1, 0]}";
  EXPECT_TRUE(has(error(five), {"objects[4].kind", "at most 4 point clouds"}));
}

}  // namespace
}  // namespace draught
